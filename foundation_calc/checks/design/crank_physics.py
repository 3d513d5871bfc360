"""The physics of a batch of crank-foundation candidates: each candidate block's mass, springs and
dashpots, its natural frequencies, the resonance rule and the steady-state amplitudes, in array
operations over the batch (what :mod:`.crank` judges per chunk and :mod:`.crank_range` over the
soil's modulus range)."""

from __future__ import annotations

from dataclasses import replace

import numpy as np

from foundation_calc.checks.design.candidates import FAIL, PASS, WARN

#: The scene keys a candidate may vary, by their short names.
VARIED = ("length", "width", "height")

_UNSTABLE = "the block tips over: rocking stiffness K_φ - K_xφ²/K_x <= P h (fcalc check: invalid scene)"


class CandidateDesigns:
    """The scene's design for each block (L, B, H) of a batch: ``at(soil_frequency)`` is a
    :class:`~foundation_calc.solvers.crank.mechanism.CrankDesign` whose block and support fields
    are arrays over the batch (``soil_frequency`` [rad/s] a scalar or one per candidate).

    The machine and the positions given from C move with the block as a candidate's scene moves
    them (:func:`~foundation_calc.checks.design.apply.moved`): the machine's centre of mass, the
    crank axis (``a``) and the points (``points_u``, ``points_H``: (points, N) [m] from the new C).

    What carries each block is the scene's support (:meth:`~foundation_calc.scenes.crank.CrankScene.support`)
    under its base L × B and the plane's body (M_tot, I_0 = I_c + M_tot h²), at the support's own
    ``sizes`` (key -> (N,), :meth:`~foundation_calc.solvers.supports.base.Sizing.sized`; the scene's
    where left out) and on the soil's stiffness data times ``factor`` (a scalar or one per candidate,
    :meth:`~foundation_calc.scenes.soil.OnSoil.with_modulus_factor`); read in the plane
    (:func:`~foundation_calc.solvers.supports.plane_footing.plane`: a pile group's
    sway-rocking K_xφ, C_xφ taken, any other coupling of the plane's motions a PhysicsError naming it).
    """

    def __init__(self, scene, L, B, H, factor=1.0, sizes=None):
        from foundation_calc.checks.design.apply import moved, sizing_of
        from foundation_calc.solvers.crank.block import block_with_machine
        from foundation_calc.solvers.supports.plane_footing import plane_masses

        f, machine = scene.foundation, scene.foundation.machine
        self.scene, self.base = scene, scene.design()
        self.L, self.B, self.H, self.factor = L, B, H, factor
        old, new = tuple(getattr(f.block, k) for k in VARIED), (L, B, H)

        def at_base(u, height):  # a position given from C: (x, z) from the base's centre, moved
            position = moved([u, 0.0, height + f.cog_height], old, new)
            return position[..., 0], position[..., 2]

        self.machine_height = None if machine is None else moved([0.0, 0.0, machine.cog_height], old, new)[..., 2]
        self.props = p = block_with_machine(L, B, H, f.block.density, *(
            (0.0, 0.0, 0.0) if machine is None else (machine.mass, self.machine_height, machine.moment_of_inertia)))
        self.S, self.I1 = L * B, B * L**3 / 12.0
        self.M_tot = p.M + self.base.rod.m
        self.a = at_base(0.0, scene.mechanism.crank_axis_to_cog)[1] - p.h
        moved_points = [at_base(q.horizontal, q.height) for q in scene.points]
        shape = (len(moved_points), *np.shape(L))
        self.points_u = np.array([np.broadcast_to(u, np.shape(L)) for u, _ in moved_points]).reshape(shape)
        self.points_H = np.array([z - p.h for _, z in moved_points]).reshape(shape)
        on = sizing_of(scene).sized(scene, sizes) if sizes else scene
        if np.ndim(factor) or factor != 1.0:
            on = on.with_modulus_factor(factor)
        self.support = on.support((L, B), plane_masses(self.M_tot, p.I_c + self.M_tot * p.h**2))
        self._last = None  # (frequency, springs at O): :meth:`in_plane`'s last

    def in_plane(self, soil_frequency=0.0) -> tuple:
        """((K_x, K_z, K_φ), (C_x, C_z, C_φ), (K_xφ, C_xφ)) at O of every candidate's support at
        ``soil_frequency`` [rad/s] (class docstring), (N,) each: the plane's springs and dashpots and
        the support's sway-rocking coupling (a pile group's; 0 on an uncoupled support), as
        ``fcalc check`` reads them (:meth:`~foundation_calc.scenes.crank.CrankScene.design`). The
        last frequency's are kept: the designs and the stability at one frequency ask the support
        once."""
        from foundation_calc.solvers.supports.plane_footing import plane

        asked = np.array(soil_frequency, dtype=float)
        if self._last is None or self._last[0].shape != asked.shape or not np.array_equal(self._last[0], asked):
            self._last = asked, plane(self.support.impedance(soil_frequency), self.support.label)
        return self._last[1]

    def at(self, soil_frequency=0.0):
        """The candidates' designs on the support at ``soil_frequency`` [rad/s], its springs as
        c = K_z/S, c1 = K_x/S, c_φ = K_φ/I1 of each candidate's base (as ``scene.design``), with the
        support's K_xφ, C_xφ (:attr:`~foundation_calc.solvers.crank.mechanism.CrankDesign.coupled`
        when it couples sway with rocking)."""
        (K_x, K_z, K_phi), (C_x, C_z, C_phi), (K_xphi, C_xphi) = self.in_plane(soil_frequency)
        p, ones = self.props, np.ones_like(self.L)
        return replace(self.base, M=p.M, I_c=p.I_c, h=p.h, S=self.S, I1=self.I1, c=K_z / self.S * ones,
                       c1=K_x / self.S * ones, c_phi=K_phi / self.I1 * ones, C_x=C_x * ones, C_z=C_z * ones,
                       C_phi=C_phi * ones, a=self.a, K_xphi=K_xphi * ones, C_xphi=C_xphi * ones,
                       soil_frequency=soil_frequency)

    def rocking_stable(self, soil_frequency=0.0) -> np.ndarray:
        """The candidates whose rocking stiffness at O on the support's springs at ``soil_frequency``
        [rad/s], net of its sway-rocking coupling, K_φ - K_xφ²/K_x
        (:func:`~foundation_calc.solvers.crank.frequencies.coupled_rocking_stiffness`; K_φ
        uncoupled), exceeds the weight's overturning moment P h (paper (3.4))."""
        from foundation_calc.solvers.constants import GRAVITY
        from foundation_calc.solvers.crank.frequencies import coupled_rocking_stiffness

        (K_x, _, K_phi), _, (K_xphi, _) = self.in_plane(soil_frequency)
        return coupled_rocking_stiffness(K_phi, K_x, K_xphi) > self.M_tot * GRAVITY * self.props.h

    def stable(self) -> np.ndarray:
        """The candidates ``fcalc check`` does not refuse as tipping over: those that stand
        (:meth:`rocking_stable`) on the support's springs at rest (ω = 0), as the scene judges them
        (:meth:`~foundation_calc.scenes.crank.CrankScene.in_plane`). Stability is a statement about
        the static equilibrium: a frequency-dependent support's springs at a harmonic or at a mode's
        own frequency are the real part of an impedance (a pile group's K_x(ω) may dip near zero,
        making K_xφ²/K_x explode), on which the steady state is solved and the modes are found, but
        no stability judged."""
        return self.rocking_stable(0.0)


def candidate_frequencies(designs: CandidateDesigns, mechanism):
    """(zero-order, averaged) of every candidate: k0, p1, p2, each mode at its own frequency on a
    frequency-dependent soil (as :func:`~foundation_calc.checks.crank_resonance.scene_design_frequencies`;
    the stability is judged at rest, :meth:`CandidateDesigns.stable`).
    ``mechanism``: the mechanism's M̄, C̄, K̄ (..., 3, 3) at the candidates' distances ``a``
    (:meth:`~foundation_calc.solvers.crank.batch.MechanismOperator.at`).

    On a support coupling sway with rocking (a pile group) the closed forms do not apply: both are
    the one model's, the eigen-solve of the averaged operator M̄, K̄ (mechanism and
    :func:`~foundation_calc.solvers.crank.averaged.block_matrices`) stacked over the candidates, each mode named by its dominant motion
    (:func:`~foundation_calc.solvers.crank.averaged.mode_order`) on the static springs and followed
    by its rank at frequency (:func:`~foundation_calc.checks.crank_resonance.by_static_rank`), as
    ``fcalc resonance`` takes them."""
    from foundation_calc.solvers.crank.natural import by_static_rank, consistent_frequencies, design_frequencies
    from foundation_calc.solvers.crank.averaged import block_matrices, mode_order, natural_modes
    from foundation_calc.solvers.crank.frequencies import NaturalFrequencies

    static_design = designs.at(0.0)
    if not static_design.coupled:
        static = design_frequencies(static_design)
        if not designs.support.frequency_dependent:
            return static
        return tuple(consistent_frequencies(static[which], lambda w, which=which: design_frequencies(designs.at(w))[which],
                                            "nan") for which in (0, 1))
    M_m, _, K_m = mechanism[:3]

    def modes(design, at_rest=True):
        M, _, K = block_matrices(design)
        return M_m + M, natural_modes(M_m + M, K_m + K, at_rest)

    M, (natural, shapes) = modes(static_design)
    static = NaturalFrequencies(*np.moveaxis(np.take_along_axis(natural, mode_order(M, shapes), -1), -1, 0))
    if designs.support.frequency_dependent:
        ranked = by_static_rank(static)

        def at(w):  # the springs at ω: a mode with p² < 0 there is 0, no root (natural_modes)
            return ranked(NaturalFrequencies(*np.moveaxis(modes(designs.at(w), at_rest=False)[1][0], -1, 0)))

        static = consistent_frequencies(static, at, "nan")
    return static, static


class Verdicts:
    """Outcome, utilisation and governing index of each check over a chunk, filled check by check."""

    def __init__(self):
        self.outcome, self.utilisation, self.governing, self.reasons = {}, {}, {}, {}

    def put(self, check, outcome, utilisation, governing, reasons):
        self.outcome[check], self.utilisation[check] = outcome.astype(np.int8), utilisation
        self.governing[check], self.reasons[check] = governing.astype(np.intp), tuple(reasons)


def _resonance(out: Verdicts, scene, d0, M, K, mech, harmonics, frequencies, stable):
    """The resonance rule on every candidate, as :func:`~foundation_calc.checks.crank_resonance.check_resonances`
    judges one design; returns (zero-order frequencies, margins, judgement, conditions), the
    arrays over every condition n ω = k0, p1, p2 of harmonics 1 ... ``harmonics``; ``frequencies``:
    the candidates' (zero-order, averaged) k0, p1, p2 (:func:`candidate_frequencies`).

    Only the conditions that can decide somewhere in the batch are judged (a source's, order 1,
    or a forcing share of at least 1 % on some candidate); every other one is information at most,
    never the verdict: its margin is inf, its status clear."""
    from foundation_calc.checks.resonance import judge_conditions
    from foundation_calc.solvers.crank.resonance import forcing_shares, harmonic_conditions
    from foundation_calc.checks.resonance_rule import FAIL as RULE_FAIL, FORCING_SHARE, WARN as RULE_WARN, Judgement

    _, _, _, fc, fs = mech
    conditions = harmonic_conditions(range(1, harmonics + 1))
    forces = np.swapaxes(fc - 1j * fs, -1, -2)[:, 1 : harmonics + 1]  # (N, harmonics, 3)
    shares = forcing_shares(M, K, forces).reshape(len(d0.S), -1)
    deciding = np.array([c.source == "paper" or c.harmonic == 1 for c in conditions]) | (shares >= FORCING_SHARE).any(0)
    kept = np.nonzero(deciding)[0]
    zero, averaged = frequencies
    margins, verdict, _ = judge_conditions(d0.omega, zero, averaged, [conditions[i] for i in kept], shares[:, kept],
                                           scene.limits.detuning)
    worst = verdict.worst
    outcome = np.select([worst >= RULE_FAIL, worst == RULE_WARN], [FAIL, WARN], PASS)
    g = np.maximum(verdict.governing, 0)[:, None]
    margin = np.take_along_axis(margins, g, -1)[:, 0]
    needed = np.take_along_axis(verdict.needed, g, -1)[:, 0]
    utilisation = np.where(margin > 0.0, needed / np.where(margin > 0.0, margin, 1.0), np.inf)
    utilisation = np.where(verdict.governing >= 0, utilisation, np.nan)
    unstable = len(conditions)
    out.put("resonance", np.where(stable, outcome, FAIL), np.where(stable, utilisation, np.inf),
            np.where(stable, kept[g[:, 0]], unstable), [c.label for c in conditions] + [_UNSTABLE])

    def widened(values, fill):  # the kept conditions' columns among every condition's
        full = np.full(values.shape[:-1] + (len(conditions),), fill, dtype=values.dtype)
        full[..., kept] = values
        return full

    judgement = Judgement(judged=widened(verdict.judged, False), status=widened(verdict.status, 0),
                          needed=widened(verdict.needed, np.inf), governing=kept[g[:, 0]])
    return zero, widened(margins, np.inf), judgement, conditions


def _motion(scene, designs, d0, block, mech, harmonics, decoupled):
    """The averaged-operator steady state of every candidate (harmonics 0 ... ``harmonics``) and
    its resonant mask; ``block``: M, C, K of the blocks on the static springs; ``decoupled``: y
    apart from x and θ (:attr:`~foundation_calc.solvers.crank.batch.MechanismOperator.decoupled`); a
    frequency-dependent soil takes harmonic n on the springs at n ω."""
    from foundation_calc.solvers.crank.averaged import block_matrices
    from foundation_calc.solvers.crank.batch import harmonic_response, resonant_blocks
    from foundation_calc.solvers.crank.response import PeriodicMotion

    M_m, C_m, K_m, fc, fs = mech
    omega = d0.omega
    if designs.support.frequency_dependent:
        parts = [block_matrices(designs.at(n * omega)) for n in range(harmonics + 1)]
        M, C, K = (np.stack([p[i] for p in parts], axis=-3) for i in range(3))
        resonant, _ = resonant_blocks(M_m + M[:, 1], C[:, 1], K_m + K[:, 1], omega)
        M_m, C_m, K_m = (x[:, None] for x in (M_m, C_m, K_m))
        Z = harmonic_response(M_m + M, C_m + C, K_m + K, omega, fc, fs, harmonics, per_harmonic=True, decoupled=decoupled)
    else:
        M, C, K = block
        resonant, _ = resonant_blocks(M_m + M, C, K_m + K, omega)
        Z = harmonic_response(M_m + M, C_m + C, K_m + K, omega, fc, fs, harmonics, decoupled=decoupled)
    Z = np.where(resonant[:, None, None], 0.0, Z)
    return PeriodicMotion(omega=omega, cos=Z.real, sin=-Z.imag), resonant


def _amplitudes(out: Verdicts, scene, designs, motion, resonant, stable):
    """Peaks and RMS values of C and every point against [limits] and the code's zones, as
    :func:`~foundation_calc.checks.approximations.check_amplitudes` judges them."""
    from foundation_calc.checks.codes import TABLES, ZONES, application_warnings, code_zone_index
    from foundation_calc.checks.limits import limited_quantities
    from foundation_calc.solvers.crank.response import DIRECTIONS, point_series
    from foundation_calc.units import rpm_from_omega

    limits, points = scene.limits, scene.points
    names = ["C", *(p.name for p in points)]
    limited = limited_quantities(limits)
    wanted = set(limited) | ({"velocity_rms", "displacement_rms"} if limits.code is not None else set())
    series = [(motion.cos[:, None, :2, :], motion.sin[:, None, :2, :])]  # C: x and y themselves
    if points:
        cos, sin = point_series(motion, designs.points_u, designs.points_H)  # (points, N, 2, 2K + 1)
        series.append((np.moveaxis(cos, 0, 1), np.moveaxis(sin, 0, 1)))
    statistic = _statistics(wanted, limited, series, motion.omega)
    ratios, fails, reasons = [], [], []
    for quantity, limit in limited.items():
        values = statistic[quantity]  # (N, points, 2)
        for i, name in enumerate(names):
            for j, direction in enumerate(DIRECTIONS):
                ratios.append(values[:, i, j] / limit)
                fails.append(np.where(values[:, i, j] > limit, FAIL, PASS))
                reasons.append(f"{quantity} at {name} ({direction})")
    warned = False
    if limits.code is not None:
        table = TABLES[limits.code, limits.machine_group, limits.foundation]
        power = None if limits.machine_power is None else limits.machine_power / 1e3
        warned = bool(application_warnings(table, rpm_from_omega(motion.omega), power))
        highest = ZONES.index(limits.acceptable_zone or "B")
        velocity = statistic["velocity_rms"].max(axis=-1).T  # (points, N): the larger direction governs
        displacement = statistic["displacement_rms"].max(axis=-1).T
        zone, by_displacement = code_zone_index(velocity, displacement, table)  # the more restrictive decides
        acceptable = limits.acceptable_zone
        by_zone = np.array([PASS, WARN, FAIL, FAIL] if acceptable is None else
                           [PASS if z <= ZONES.index(acceptable) else FAIL for z in range(4)])
        ratio = np.where(by_displacement, displacement / table.displacement_boundaries[highest],
                         velocity / table.boundaries[highest])
        for i, name in enumerate(names):
            ratios.append(ratio[i])
            fails.append(by_zone[zone[i]])
            reasons.append(f"{table.title} zone at {name}")
    n = len(resonant)
    if ratios:
        ratio = np.stack(ratios)
        outcome = np.stack(fails).max(axis=0)
        governing = np.argmax(ratio, axis=0)
        utilisation = ratio.max(axis=0)
    else:
        outcome, governing, utilisation = np.zeros(n, int), np.zeros(n, int), np.full(n, np.nan)
    if warned:
        outcome = np.maximum(outcome, WARN)
    k = len(reasons)
    reasons += ["resonant with an undamped mode: no steady state", _UNSTABLE]
    outcome = np.where(resonant | ~stable, FAIL, outcome)
    utilisation = np.where(resonant | ~stable, np.inf, utilisation)
    governing = np.where(~stable, k + 1, np.where(resonant, k, governing))
    out.put("amplitudes", outcome, utilisation, governing, reasons)


#: The time derivative of each limited quantity.
_ORDER = {"displacement": 0, "velocity": 1, "acceleration": 2}

#: Phases a revolution at which a series is sampled for a lower bound of its peak.
_BOUND_PHASES = 16


def _statistics(wanted, limited, series, omega) -> dict[str, np.ndarray]:
    """quantity -> (N, points, 2) values of each wanted statistic of the ``series`` (C's, the
    points'): RMS values by Parseval; peaks to round-off (:func:`~foundation_calc.solvers.numerics.trig_series.peak`)
    where they can decide the check, elsewhere their upper bound Σ|c_n|.

    A peak decides nothing when its upper bound over its limit is below the largest lower bound
    (the series sampled at :data:`_BOUND_PHASES` phases) over its limit of any row of the same
    candidate: it is not the largest ratio, and if it exceeds its limit so does that row. The
    largest ratio, every row's pass or fail that can change the verdict, and what governs are
    then those of the exact peaks."""
    from foundation_calc.solvers.numerics.trig_series import basis, derivative, peak, rms

    parts = {q: [derivative(c, s, omega, _ORDER[q.removesuffix("_rms")]) for c, s in series] for q in wanted}
    found = {q: np.concatenate([rms(c, s) for c, s in parts[q]], axis=1) for q in wanted if q.endswith("_rms")}
    bounds = {}
    for q in wanted - set(found):
        low, up = [], []
        for c, s in parts[q]:
            cb, sb = basis(c.shape[-1] - 1, 2.0 * np.pi * np.arange(_BOUND_PHASES) / _BOUND_PHASES)
            low.append(np.abs(c @ cb.T + s @ sb.T).max(axis=-1))
            up.append(np.hypot(c, s).sum(axis=-1))
        bounds[q] = (np.concatenate(low, axis=1), np.concatenate(up, axis=1))
    best = np.zeros(next(iter(parts.values()))[0][0].shape[0])
    for q, limit in limited.items():
        best = np.maximum(best, (found[q] if q in found else bounds[q][0]).max(axis=(1, 2)) / limit)
    for q, (_, up) in bounds.items():
        need = up / limited[q] >= best[:, None, None]
        values, start = up.copy(), 0
        for c, s in parts[q]:
            part = need[:, start : start + c.shape[1]]
            values[:, start : start + c.shape[1]][part] = peak(c[part], s[part]) if part.any() else []
            start += c.shape[1]
        found[q] = values
    return found


def judge_office(out: Verdicts, scene, designs):
    from foundation_calc.solvers.constants import GRAVITY

    allowed = scene.limits.bearing_pressure
    q = designs.M_tot * GRAVITY / designs.S
    out.put("office", np.where(q > allowed, FAIL, PASS), q / allowed, np.zeros(len(q)), ["bearing pressure q = W/S"])


def judge_inputs(out: Verdicts, scene, designs, warned, sizes):
    """The plausibility warnings (the ``inputs`` check) of every candidate: the scene's own that
    do not depend on the candidate, and the block's dimensions, the lengths against the size
    sqrt(S) of its base, the block-to-machine mass ratio and a stratum shallower than twice the
    base's equivalent radius (:func:`~foundation_calc.scenes.stratum.shallow`), as the scene
    model judges them; the support's ``sizes`` (key -> (N,)) against their plausible ranges and
    the support's own warnings of them (``warned``, its
    :meth:`~foundation_calc.solvers.supports.base.Sizing.size_warnings`: governing 1 + its index)."""
    from foundation_calc.checks.design.supported import sizes_outside
    from foundation_calc.scenes.common import LENGTH_SCALE_FACTOR
    from foundation_calc.scenes.plausibility import RANGES
    from foundation_calc.scenes.stratum import shallow, stratum_remarks

    f, mech = scene.foundation, scene.mechanism
    on_base = {str(x) for x in stratum_remarks(scene.soil, *f.dimensions)}  # the scene's own base's
    judged = {*sizes, *warned.keys}  # findings under these keys are each candidate's
    fixed = [x for x in scene.plausibility_findings()
             if not _block_dependent(x.key) and x.key not in judged and str(x) not in on_base]

    def outside(values, name):
        return RANGES[name].outside(values)

    block = outside(designs.L, "block_length") | outside(designs.B, "block_length") | outside(designs.H, "block_height")
    block |= outside(np.full(len(designs.L), f.block.density), "block_density")
    foundation = block | any(x.key.startswith("foundation.") for x in fixed)
    # the lengths the candidate's scene gives, each against ten times the size sqrt(S) of its base
    size = LENGTH_SCALE_FACTOR * np.sqrt(designs.S)
    too_long_foundation = np.zeros(len(size), bool) if designs.machine_height is None else np.abs(designs.machine_height) > size
    lengths = [np.abs(designs.a), np.abs(designs.points_u).max(axis=0, initial=0.0), np.abs(designs.points_H).max(axis=0, initial=0.0)]
    too_long = too_long_foundation | (np.maximum.reduce(lengths) > size)
    too_long |= max(abs(mech.crank_radius), abs(mech.rod_length)) > size
    warn = block | too_long | bool(fixed) | shallow(scene.soil, designs.L, designs.B)
    if f.machine is not None:
        machine = f.machine.mass + (0.0 if mech is None else mech.rod_mass + mech.slider_mass)
        name = "mass_ratio_rotating" if mech is None else "mass_ratio_reciprocating"
        ratio = f.block.density * designs.L * designs.B * designs.H / machine
        warn |= ~(foundation | too_long_foundation) & outside(ratio, name)
    warn |= sizes_outside(sizes, warn.shape)
    governing = np.where(warn, 0, warned.which)
    out.put("inputs", np.where(warn | (governing > 0), WARN, PASS), np.full(len(warn), np.nan), governing,
            ["input values outside the plausible ranges", *warned.reasons])


def _block_dependent(key: str) -> bool:
    """Whether a plausibility finding's key is one the block's dimensions enter (re-judged per
    candidate): the block, the keys a candidate's scene computes from it, the lengths judged
    against the base's size and the block-to-machine mass ratio."""
    from foundation_calc.checks.design.apply import CRANK_DERIVED

    derived = tuple(f"foundation.{k}" for k in CRANK_DERIVED)
    return key.startswith(("foundation.block.", "block-to-machine", "points[", *derived)) or key in (
        "foundation.machine.cog_height", "mechanism.crank_radius", "mechanism.rod_length", "mechanism.crank_axis_to_cog")


def judge_physics(out: Verdicts, scene, L, B, H, mech, harmonics, factor=1.0, resonance=True, amplitudes=True, sizes=None):
    """The resonance and amplitude checks of blocks (L, B, H) on their support at ``sizes`` (key ->
    (N,); None: the scene's) on the soil × ``factor`` into ``out``; returns the blocks' designs and
    the resonance judgement (zero-order frequencies, margins,
    :class:`~foundation_calc.checks.resonance_rule.Judgement`, conditions)."""
    from foundation_calc.solvers.crank.averaged import block_matrices

    given = CandidateDesigns(scene, L, B, H, factor, sizes)
    stable = given.stable()
    designs = given
    if not stable.all():  # a tipping candidate is solved as a stable stand-in, its verdicts overwritten
        if stable.any():
            keep = int(np.argmax(stable))
            stand_in = [np.where(stable, v, v[keep]) for v in (L, B, H, np.broadcast_to(factor, L.shape))]
            own = {key: np.where(stable, v, v[keep]) for key, v in (sizes or {}).items()}
        else:
            stand_in = [np.full_like(L, getattr(scene.foundation.block, k)) for k in VARIED] + [np.ones_like(L)]
            own = None
        designs = CandidateDesigns(scene, *stand_in, own)
    d0 = designs.at(0.0)
    block = block_matrices(d0)
    decoupled, mech = mech.decoupled, mech.at(designs.a)
    judgement, rootless = None, None
    if resonance:
        frequencies = candidate_frequencies(designs, mech)
        rootless = _rootless(frequencies)
        judgement = _resonance(out, scene, d0, mech[0] + block[0], mech[2] + block[2], mech, harmonics, frequencies, stable)
    if amplitudes:  # fcalc amplitudes judges the resonances too, and takes every harmonic's springs
        motion, resonant = _motion(scene, designs, d0, block, mech, harmonics, decoupled)
        _amplitudes(out, scene, designs, motion, resonant, stable)
    if rootless is not None:
        _fail_rootless(out, rootless & stable[:, None])
    return given, judgement


def _rootless(frequencies) -> np.ndarray:
    """(N, 3) the candidates' modes k0, p1, p2 without a natural frequency (ω = p(K(ω)) has no
    root: NaN in either the zero-order or the averaged frequencies, :func:`candidate_frequencies`)."""
    from foundation_calc.solvers.crank.natural import MODES

    zero, averaged = frequencies
    return np.stack(np.broadcast_arrays(*(np.isnan(getattr(zero, mode)) | np.isnan(getattr(averaged, mode))
                                          for mode in MODES)), axis=-1)


def _fail_rootless(out: Verdicts, rootless: np.ndarray) -> None:
    """Fail the resonance and amplitude checks of the candidates with a mode in ``rootless`` (N, 3)
    (its first such mode governing, named as ``fcalc check`` names it: an invalid scene there),
    the other candidates' verdicts kept; each check's reasons gain one text per mode."""
    from foundation_calc.solvers.crank.natural import MODES
    from foundation_calc.solvers.soil.impedance import rootless_reason

    failing = rootless.any(axis=-1)
    first = np.argmax(rootless, axis=-1)
    texts = [f"{rootless_reason(mode)} (fcalc check: invalid scene)" for mode in MODES]
    for check in [c for c in ("resonance", "amplitudes") if c in out.outcome]:
        k = len(out.reasons[check])
        out.put(check, np.where(failing, FAIL, out.outcome[check]), np.where(failing, np.inf, out.utilisation[check]),
                np.where(failing, k + first, out.governing[check]), out.reasons[check] + tuple(texts))
