"""The crank engine's verdicts on a batch of crank-foundation candidates: the resonance rule, the
amplitudes against the limits and the code's zones, the plausibility warnings and the bearing
pressure, in array operations over the batch (what :mod:`.crank` judges per piece and
:mod:`.crank_range` over the soil's modulus range). The candidates' mass, springs, steady state and
statistics are computed by :mod:`~foundation_calc.solvers.crank.batch_design`; their natural
frequencies here, by the closed forms of :mod:`~foundation_calc.solvers.crank.natural` that
``fcalc check`` takes."""

from __future__ import annotations

import numpy as np

from foundation_calc.checks.design.candidates import FAIL, PASS, WARN, failing

#: The scene keys a candidate may vary, by their short names.
VARIED = ("length", "width", "height")

_UNSTABLE = "the block tips over: rocking stiffness K_φ - K_xφ²/K_x <= P h (fcalc check: invalid scene)"


def candidate_designs(scene, L, B, H, factor=1.0, sizes=None):
    """The scene's design for each block (L, B, H) of a batch
    (:class:`~foundation_calc.solvers.crank.batch_design.CandidateDesigns`), on the soil's stiffness
    data times ``factor`` (a scalar or one per candidate,
    :meth:`~foundation_calc.scenes.soil.OnSoil.with_modulus_factor`).

    The machine and the positions given from C move with the block as a candidate's scene moves
    them (:func:`~foundation_calc.checks.design.apply.moved`): the machine's centre of mass, the
    crank axis and the points. What carries each block is the scene's support
    (:meth:`~foundation_calc.scenes.crank.CrankScene.support`) under its base L × B at the
    support's own ``sizes`` (key -> (N,), :meth:`~foundation_calc.solvers.supports.base.Sizing.sized`;
    the scene's where left out)."""
    from foundation_calc.checks.design.apply import moved, sizing_of
    from foundation_calc.solvers.crank.batch_design import CandidateDesigns

    f, machine = scene.foundation, scene.foundation.machine
    old, new = tuple(getattr(f.block, k) for k in VARIED), (L, B, H)

    def at_base(u, height):  # a position given from C: (x, z) from the base's centre, moved
        position = moved([u, 0.0, height + f.cog_height], old, new)
        return position[..., 0], position[..., 2]

    carried = None if machine is None else (
        machine.mass, moved([0.0, 0.0, machine.cog_height], old, new)[..., 2], machine.moment_of_inertia)
    on = sizing_of(scene).sized(scene, sizes) if sizes else scene
    if np.ndim(factor) or factor != 1.0:
        on = on.with_modulus_factor(factor)
    return CandidateDesigns(scene.design(), L, B, H, f.block.density, carried,
                            at_base(0.0, scene.mechanism.crank_axis_to_cog)[1],
                            [at_base(q.horizontal, q.height) for q in scene.points],
                            lambda masses: on.support((L, B), masses))


def candidate_frequencies(designs, mechanism):
    """(zero-order, averaged) of every candidate: k0, p1, p2, each mode at its own frequency on a
    frequency-dependent soil (as :func:`~foundation_calc.checks.resonance.frequencies.scene_design_frequencies`;
    the stability is judged at rest, :meth:`~foundation_calc.solvers.crank.batch_design.CandidateDesigns.stable`;
    ``designs``: :func:`candidate_designs`).
    ``mechanism``: the mechanism's M̄, C̄, K̄ (..., 3, 3) at the candidates' distances ``a``
    (:meth:`~foundation_calc.solvers.crank.batch.MechanismOperator.at`).

    On a support coupling sway with rocking (a pile group) the closed forms do not apply: both are
    the one model's, the eigen-solve of the averaged operator M̄, K̄ (mechanism and
    :func:`~foundation_calc.solvers.crank.averaged.block_matrices`) stacked over the candidates, each mode named by its dominant motion
    (:func:`~foundation_calc.solvers.crank.averaged.mode_order`) on the static springs and followed
    by its rank at frequency (:func:`~foundation_calc.solvers.crank.natural.by_static_rank`), as
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
    """The resonance rule on every candidate, as :func:`~foundation_calc.checks.resonance.report.check_resonances`
    judges one design; returns (zero-order frequencies, margins, judgement, conditions), the
    arrays over every condition n ω = k0, p1, p2 of harmonics 1 ... ``harmonics``; ``frequencies``:
    the candidates' (zero-order, averaged) k0, p1, p2 (:func:`candidate_frequencies`).

    Only the conditions that can decide somewhere in the batch are judged (a source's, order 1,
    or a forcing share of at least 1 % on some candidate); every other one is information at most,
    never the verdict: its margin is inf, its status clear."""
    from foundation_calc.checks.resonance.batch import governing_verdicts
    from foundation_calc.checks.resonance.report import judge_conditions
    from foundation_calc.solvers.crank.machine_conditions import forcing_shares, harmonic_conditions
    from foundation_calc.checks.resonance.rule import FORCING_SHARE, Judgement

    _, _, _, fc, fs = mech
    conditions = harmonic_conditions(range(1, harmonics + 1))
    forces = np.swapaxes(fc - 1j * fs, -1, -2)[:, 1 : harmonics + 1]  # (N, harmonics, 3)
    shares = forcing_shares(M, K, forces).reshape(len(d0.S), -1)
    deciding = np.array([c.source == "paper" or c.harmonic == 1 for c in conditions]) | (shares >= FORCING_SHARE).any(0)
    kept = np.nonzero(deciding)[0]
    zero, averaged = frequencies
    margins, verdict, _ = judge_conditions(d0.omega, zero, averaged, [conditions[i] for i in kept], shares[:, kept],
                                           scene.limits.detuning)
    governing = kept[np.maximum(verdict.governing, 0)]
    out.put("resonance", *failing(~stable, *governing_verdicts(verdict, margins), governing, len(conditions)),
            [c.label for c in conditions] + [_UNSTABLE])

    def widened(values, fill):  # the kept conditions' columns among every condition's
        full = np.full(values.shape[:-1] + (len(conditions),), fill, dtype=values.dtype)
        full[..., kept] = values
        return full

    judgement = Judgement(judged=widened(verdict.judged, False), status=widened(verdict.status, 0),
                          needed=widened(verdict.needed, np.inf), governing=governing)
    return zero, widened(margins, np.inf), judgement, conditions


def _amplitudes(out: Verdicts, scene, designs, motion, resonant, stable):
    """Peaks and RMS values of C and every point against [limits] and the code's zones, as
    :func:`~foundation_calc.checks.amplitudes.approximations.check_amplitudes` judges them (by the
    one batch judge, :func:`~foundation_calc.checks.amplitudes.batch.judge_batch`)."""
    from foundation_calc.checks.amplitudes.batch import judge_batch
    from foundation_calc.checks.limits import limited_quantities
    from foundation_calc.solvers.crank.batch_design import statistics
    from foundation_calc.solvers.crank.response import DIRECTIONS, point_series

    limits, points = scene.limits, scene.points
    limited = limited_quantities(limits)
    wanted = set(limited) | ({"velocity_rms", "displacement_rms"} if limits.code is not None else set())
    series = [(motion.cos[:, None, :2, :], motion.sin[:, None, :2, :])]  # C: x and y themselves
    if points:
        cos, sin = point_series(motion, designs.points_u, designs.points_H)  # (points, N, 2, 2K + 1)
        series.append((np.moveaxis(cos, 0, 1), np.moveaxis(sin, 0, 1)))
    statistic = statistics(wanted, limited, series, motion.omega)  # quantity -> (N, points, 2)
    out.put("amplitudes", *judge_batch(["C", *(p.name for p in points)], DIRECTIONS, statistic.__getitem__, limits,
                                       [(None, motion.omega)],
                                       [(resonant, "resonant with an undamped mode: no steady state"), (~stable, _UNSTABLE)]))


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
    from foundation_calc.checks.design.supported import fixed_findings, sizes_outside
    from foundation_calc.scenes.common import LENGTH_SCALE_FACTOR
    from foundation_calc.scenes.plausibility import RANGES
    from foundation_calc.scenes.stratum import shallow

    f, mech = scene.foundation, scene.mechanism
    fixed = fixed_findings(scene, f.dimensions, _block_dependent, sizes, warned)

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
    :class:`~foundation_calc.checks.resonance.rule.Judgement`, conditions)."""
    from foundation_calc.solvers.crank.averaged import block_matrices
    from foundation_calc.solvers.crank.batch_design import steady_state

    given = candidate_designs(scene, L, B, H, factor, sizes)
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
        designs = candidate_designs(scene, *stand_in, own)
    d0 = designs.at(0.0)
    block = block_matrices(d0)
    decoupled, mech = mech.decoupled, mech.at(designs.a)
    judgement, rootless = None, None
    if resonance:
        frequencies = candidate_frequencies(designs, mech)
        rootless = _rootless(frequencies)
        judgement = _resonance(out, scene, d0, mech[0] + block[0], mech[2] + block[2], mech, harmonics, frequencies, stable)
    if amplitudes:  # fcalc amplitudes judges the resonances too, and takes every harmonic's springs
        motion, resonant = steady_state(designs, d0, block, mech, harmonics, decoupled)
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

    first = np.argmax(rootless, axis=-1)
    texts = [f"{rootless_reason(mode)} (fcalc check: invalid scene)" for mode in MODES]
    for check in [c for c in ("resonance", "amplitudes") if c in out.outcome]:
        k = len(out.reasons[check])
        out.put(check, *failing(rootless.any(axis=-1), out.outcome[check], out.utilisation[check], out.governing[check],
                                k + first), out.reasons[check] + tuple(texts))
