"""Sweep of a crank foundation's speed or soil stiffness: closed-form amplitudes, resonances, limits.

One call of the corrected first approximation on arrays (no Python object per point) gives the
peaks of x, y and θ at every point; the margins of every resonance condition come from the same
arithmetic as ``fcalc resonance`` (nearer of the zero-order and the averaged-inertia critical
speed). With base dashpots every point has a finite amplitude and a phase, at and through each
resonance; without them a point whose margin is below the first approximation's resonant margin
has no periodic solution: it is reported as resonant, never as an infinite amplitude.

On a frequency-dependent soil (Gazetas', Pais & Kausel's impedance) a speed sweep is
frequency-consistent, as ``fcalc amplitudes`` at each speed: every harmonic n ≥ 1 of every speed
is solved with the soil's springs and dashpots at n ω (one batched first approximation and loads
solve per harmonic over the whole chunk of speeds, harmonics spliced as
:func:`~foundation_calc.solvers.crank.response.splice_harmonics` does; the mean on the static
springs), and the resonance margins are to the natural frequencies that solve ω = p(K(ω)), which
do not depend on the speed (:class:`DynamicSoil`). A soil sweep on such a soil multiplies the soil's
stiffness data (G, or V_s by the square root) by the factor and recomputes everything from them
at each factor: the springs and dashpots at each harmonic's n ω and the natural frequencies each at
its own, at the scene's speed (:func:`factored_soil_chunks`): each point is ``fcalc amplitudes``
and ``fcalc resonance`` of the scene with that soil. On a frequency-independent soil a soil sweep
multiplies the springs by the factor and the dashpots by its square root.

On a support that couples sway with rocking (a pile group's K_xφ, C_xφ at O) the paper's closed
forms do not apply ("not applicable", :data:`~foundation_calc.checks.approximations.FIRST_NOT_APPLICABLE`):
the peaks are the plane's one model's, the averaged operator with the exact forcing as ``fcalc
amplitudes`` solves it there, each harmonic n at n ω on the support's springs and dashpots at n ω,
for every speed at once (:func:`coupled_motion`: the mechanism's part, a polynomial of degree 2
in ω, :class:`~foundation_calc.solvers.crank.batch.MechanismOperator`; one batched 3 × 3 solve per
harmonic over the chunk of speeds); the critical speeds and margins are to the modes ``fcalc
resonance`` reports, the one model's eigen-solve, each at its own frequency. A soil sweep there
recomputes the group from the factored soil data, as a frequency-dependent soil's.
"""

from __future__ import annotations

from dataclasses import dataclass, field, replace

import numpy as np

from foundation_calc.checks.crank_resonance import design_frequencies, judge_conditions, machine_conditions
from foundation_calc.checks.limits import QUANTITIES, limited_quantities
from foundation_calc.checks.resonance_rule import judge, required_detuning
from foundation_calc.checks.sweep_status import STATUSES, RowVerdicts, over_limits, row_verdicts
from foundation_calc.solvers.crank.closed_form import first_approximation_motion, soft_at_harmonic, varied
from foundation_calc.solvers.crank.loads import block_frequencies, loads_response
from foundation_calc.solvers.crank.mechanism import CrankDesign
from foundation_calc.solvers.crank.resonance import CONDITIONS, critical_speed
from foundation_calc.solvers.crank.response import PeriodicMotion, point_series, superpose
from foundation_calc.solvers.numerics.trig_series import derivative, peak, rms

#: What a sweep can vary: the crank speed [rad/s] or a factor [-] on both soil coefficients.
VARIABLES = ("omega", "soil_factor")

#: Points whose peaks are found together: peak() holds ~64 × 4 × 8 bytes per series and sample.
CHUNK = 4096

#: Harmonics of the first approximation reported per point (dof, n).
HARMONICS = (("y", 1), ("y", 2), ("x", 1), ("x", 3), ("theta", 1), ("theta", 3))

#: The highest harmonic of the first approximation's series (4.11)-(4.14).
FIRST_APPROXIMATION_HARMONICS = 3


@dataclass(frozen=True)
class CriticalSpeed:
    """A resonance condition's critical speeds [rad/s] (zero-order and averaged-inertia operator),
    whether the rule judges it, and the detuning band of its order [-] (0: the scene gives that
    order none, or the condition is not judged)."""

    label: str
    source: str
    zero_order: float
    averaged: float
    band: float = 0.0
    judged: bool = True


@dataclass(frozen=True)
class DynamicSoil:
    """A frequency-dependent soil along a speed sweep.

    ``at(soil_frequency)``: (design, vendor loads) with the springs and dashpots taken at the
    frequencies ``soil_frequency`` [rad/s] (an array, one per point; either part None when the
    scene has none); ``zero``, ``averaged``: the natural frequencies that solve ω = p(K(ω))
    (:func:`~foundation_calc.checks.crank_resonance.scene_design_frequencies`); ``blocks``: the
    block's M, C, K on the support at an array of frequencies (:func:`plane_blocks`) for the
    averaged operator: the whole sweep on a support that couples sway with rocking, the speeds where
    the first approximation steps aside on the others (None for a machine given by its loads)."""

    at: object
    zero: object
    averaged: object
    blocks: object = None


@dataclass(frozen=True)
class SweepReport:
    """Amplitudes and verdicts along a sweep (arrays of length n).

    Attributes
    ----------
    variable : ``"omega"`` or ``"soil_factor"``
    values : the swept values [rad/s or -]
    omega : crank speed at each point [rad/s]
    peaks : (n, 3) peak |x| [m], |y| [m], |θ| [rad]; 0 where ``resonant``
    resonant : no periodic solution of the first approximation (margin < 1e-6)
    margin : margin of the governing condition [-]
    governing : index into ``conditions`` of the condition that governs each point's resonance
        verdict (:mod:`~foundation_calc.checks.resonance_rule`); ``margin`` is its margin and
        ``needed`` the margin it needs [-]; ``resonance_status`` the rule's verdict per point
        (``clear``, ``information``, ``warn``, ``fail``)
    conditions : the resonance conditions checked: the mechanism's
        (:data:`~foundation_calc.solvers.crank.resonance.CONDITIONS`), then those of the loads
    points : scene point name -> (n, 2) peak horizontal and vertical displacement [m]
    over_quantities : limited quantity -> where a peak or RMS value of C (x, y) or of a point
        exceeds its limit (:mod:`~foundation_calc.checks.limits`; ``over_limit``: any of them)
    status : one of :data:`STATUSES` per point
    harmonics : "y1", "x1", ... (:data:`HARMONICS`) -> complex coefficient cos - i sin per point
        [m or rad]: amplitude ``abs``, phase lag φ = -``angle`` of q_n = A cos(nωt - φ)
    damped : the design has base dashpots
    critical : critical speeds inside the swept range (speed sweeps; empty for soil sweeps)
    coupled : the support couples sway with rocking: the peaks are the averaged operator's, the
        paper's first approximation does not apply
    not_applicable : approximation key -> why it is left out, as ``fcalc amplitudes`` words it:
        the first approximation on a coupled support (every point), or at the points of a
        frequency-dependent soil whose rocking spring at one of its harmonics does not exceed P h
        (:func:`frequency_consistent_motion`: the averaged operator there); empty otherwise
    """

    variable: str
    values: np.ndarray
    omega: np.ndarray
    peaks: np.ndarray
    resonant: np.ndarray
    margin: np.ndarray
    governing: np.ndarray
    needed: np.ndarray
    resonance_status: np.ndarray
    points: dict
    over_quantities: dict
    status: np.ndarray
    harmonics: dict
    damped: bool
    critical: tuple[CriticalSpeed, ...]
    limits: dict
    detuning: float | dict
    conditions: tuple = CONDITIONS
    coupled: bool = False
    not_applicable: dict = field(default_factory=dict)

    @property
    def amplitude_limit(self) -> float | None:
        """The displacement limit [m], or None."""
        return self.limits.get("displacement")

    @property
    def over_limit(self) -> np.ndarray:
        """Where a point exceeds any limit (bool (n,))."""
        return self.rows.over_limit

    @property
    def rows(self) -> RowVerdicts:
        """The rows' verdicts as every kind's sweep gives them."""
        return RowVerdicts(governing=self.governing, margin=self.margin, needed=self.needed,
                           resonance_status=self.resonance_status, over_quantities=self.over_quantities, status=self.status)


def _peaks(cos, sin):
    """:func:`peak` over the first axis in chunks of :data:`CHUNK`, so memory stays bounded."""
    return np.concatenate([peak(cos[i : i + CHUNK], sin[i : i + CHUNK]) for i in range(0, len(cos), CHUNK)])


def _located(motion, omega, points, limits: dict):
    """Peak displacements of every point, name -> (n, 2) [m], and, per limited quantity (peak or
    RMS), whether a value of C (x, y) or of a point exceeds the limit (bool (n,)).

    The points go through :func:`point_series` and :func:`peak` together, as many at a time as
    make :data:`CHUNK` sweep points' worth of series.
    """
    w = omega[:, None]
    orders = {}  # every quantity a limit may bound -> (order of the time derivative, a peak or not)
    for order, quantity in enumerate(QUANTITIES):
        orders[quantity], orders[f"{quantity}_rms"] = (order, True), (order, False)
    largest = {}
    for key in limits:  # C: x and y
        order, is_peak = orders[key]
        cos, sin = derivative(motion.cos[..., :2, :], motion.sin[..., :2, :], w, order)
        largest[key] = (_peaks(cos, sin) if is_peak else rms(cos, sin)).max(axis=1)
    located = {}
    names = [name for name, _, _ in points]
    horizontal = np.array([u for _, u, _ in points], dtype=float)[:, None]
    height = np.array([H for _, _, H in points], dtype=float)[:, None]
    step = max(1, CHUNK // max(len(omega), 1))
    for i in range(0, len(names), step):
        cos, sin = point_series(motion, horizontal[i : i + step], height[i : i + step])  # (points, n, 2, K + 1)
        for key in {"displacement", *limits}:
            order, is_peak = orders[key]
            found = (peak if is_peak else rms)(*derivative(cos, sin, w, order))  # (points, n, 2)
            if key == "displacement":
                located.update(zip(names[i : i + step], found))
            if key in limits:
                largest[key] = np.maximum(largest[key], found.max(axis=(0, 2)))
    return located, over_limits(largest, limits)


def _complex(coefficient):
    """cos - i sin of a (cos, sin) pair of arrays."""
    c, s = coefficient
    return c - 1j * s


def _varied_block(block, variable: str, values):
    """The loads' block at each point of the sweep: soil springs × factor, dashpots × sqrt(factor)
    (C = 2 ξ sqrt(K m) at fixed damping ratios); unchanged for a speed sweep."""
    if variable != "soil_factor":
        return block
    f = np.asarray(values, dtype=float)
    r = np.sqrt(f)
    return replace(block, K_x=block.K_x * f, K_z=block.K_z * f, K_phi=block.K_phi * f,
                   C_x=block.C_x * r, C_z=block.C_z * r, C_phi=block.C_phi * r)


def _at_harmonics(static, width: int, solve):
    """The motion whose harmonic n ≥ 1 is that of ``solve(n)`` (a (motion, resonant) pair on the
    springs at n ω) and whose mean is ``static``'s; and where any of them is resonant."""
    from foundation_calc.solvers.crank.response import splice_harmonics

    motions, resonant = [static[0]], np.asarray(static[1], dtype=bool)
    for n in range(1, width):
        motion, stuck = solve(n)
        motions.append(motion)
        resonant = resonant | np.asarray(stuck, dtype=bool)
    return splice_harmonics(motions), resonant


def _chunk(design, variable: str, values, limits, detuning, points, vendor, conditions, share, dynamic=None) -> SweepReport:
    """One chunk of :func:`sweep_chunks` (``critical`` left empty: the caller sets it)."""
    motion = resonant = None
    not_applicable = {}
    coupled = design is not None and design.coupled
    if coupled:
        from foundation_calc.checks.approximations import FIRST_NOT_APPLICABLE

        motion, resonant = coupled_motion(design, values, _static_blocks(design) if dynamic is None else dynamic.blocks)
        zero, averaged = design_frequencies(design) if dynamic is None else (dynamic.zero, dynamic.averaged)
        omega = values
        not_applicable = {"first_approximation": FIRST_NOT_APPLICABLE}
    elif design is not None:
        batch = varied(design, **{variable: values})
        if dynamic is None:
            motion, resonant = first_approximation_motion(batch)
        else:
            motion, resonant, not_applicable = frequency_consistent_motion(design, values, dynamic)
        resonant = np.asarray(resonant, dtype=bool)
        zero, averaged = design_frequencies(batch) if dynamic is None else (dynamic.zero, dynamic.averaged)
        omega = np.broadcast_to(np.asarray(batch.omega, dtype=float), values.shape)
    if vendor is not None:
        block = _varied_block(vendor.block, variable, values)
        omega = values if variable == "omega" else np.full(values.shape, vendor.omega)
        res = loads_response(block, omega, vendor.loads)
        loads_motion, stuck = res.motion, res.resonant
        if dynamic is not None:
            def solve(n):
                found = loads_response(dynamic.at(n * values)[1].block, omega, vendor.loads)
                return found.motion, found.resonant

            loads_motion, stuck = _at_harmonics((loads_motion, stuck), loads_motion.cos.shape[-1], solve)
        if design is None:
            zero = averaged = block_frequencies(block) if dynamic is None else dynamic.zero
        loads_motion = PeriodicMotion(omega, np.nan_to_num(loads_motion.cos), np.nan_to_num(loads_motion.sin))
        motion = loads_motion if motion is None else superpose(motion, loads_motion)
        resonant = stuck if resonant is None else resonant | stuck
    dashpotted = [d for d in (design, None if vendor is None else vendor.block) if d is not None]
    peaks = _peaks(motion.cos, motion.sin)  # displacement only: (n, 3)
    margins, verdict, required = judge_conditions(omega, zero, averaged, conditions, share, detuning)
    margins = np.broadcast_to(margins, values.shape + (len(conditions),))
    limited = limited_quantities(limits)
    located, over_quantities = _located(motion, omega, points, limited)
    rows = row_verdicts(margins, verdict, over_quantities, resonant)
    return SweepReport(
        variable=variable,
        values=values,
        omega=omega,
        peaks=peaks,
        resonant=np.asarray(resonant, dtype=bool),
        margin=rows.margin,
        governing=rows.governing,
        resonance_status=rows.resonance_status,
        needed=rows.needed,
        points=located,
        over_quantities=over_quantities,
        status=rows.status,
        harmonics={f"{dof}{n}": _complex(motion.coefficient(dof, n)) for dof, n in HARMONICS},
        damped=any(float(np.max(getattr(d, key))) > 0.0 for d in dashpotted for key in ("C_x", "C_z", "C_phi")),
        critical=(),
        limits=limited,
        detuning=detuning,
        conditions=tuple(conditions),
        coupled=coupled,
        not_applicable=not_applicable,
    )


def frequency_consistent_motion(design: CrankDesign, omega, dynamic: DynamicSoil):
    """The mechanism's steady state at each speed of ``omega`` [rad/s] (n,) on a frequency-dependent
    soil that does not couple sway with rocking, where it has none (bool (n,)), and why the first
    approximation is left out ({} where it is not), as ``fcalc amplitudes`` solves each speed:

    - the corrected first approximation, each harmonic n = 1 ... 3 on the springs and dashpots at
      n ω (:func:`_at_harmonics`), the mean on the static springs;
    - at the speeds where it steps aside, the rocking spring at one of its harmonics' soil not
      exceeding P h (:func:`~foundation_calc.solvers.crank.closed_form.soft_at_harmonic`; the
      block stands at rest), the averaged operator with the exact forcing, each harmonic n at n ω
      (:func:`coupled_motion` on ``dynamic.blocks``), which ``fcalc amplitudes`` judges there;
      ``not_applicable`` then holds the first approximation's refusal at the first such speed
      (:func:`~foundation_calc.solvers.crank.closed_form.require_first_approximation`, in
      amplitudes' words).

    The two series are laid side by side (:func:`side_by_side`)."""
    from foundation_calc.errors import NotApplicable
    from foundation_calc.solvers.crank.closed_form import require_first_approximation

    omega = np.asarray(omega, dtype=float)
    aside, why = np.zeros(omega.shape, dtype=bool), {}
    for n in range(1, FIRST_APPROXIMATION_HARMONICS + 1):
        soft = soft_at_harmonic(dynamic.at(n * omega)[0])
        if soft.any() and not why:
            try:
                first = omega[soft][:1]
                require_first_approximation(varied(dynamic.at(n * first)[0], omega=first))
            except NotApplicable as refused:
                why = {"first_approximation": f"not applicable: {refused.message}"}
        aside |= soft
    parts = []
    if not aside.all():
        w = omega[~aside]
        static = first_approximation_motion(varied(design, omega=w))
        parts.append((~aside, *_at_harmonics(static, static[0].cos.shape[-1], lambda n: first_approximation_motion(
            varied(dynamic.at(n * w)[0], omega=w)))))
    if aside.any():
        parts.append((aside, *coupled_motion(design, omega[aside], dynamic.blocks)))
    return (*side_by_side(omega, parts), why)


def side_by_side(omega, parts) -> tuple[PeriodicMotion, np.ndarray]:
    """One motion at the speeds ``omega`` [rad/s] (n,) of ``parts``, each (where: bool (n,), the
    motion of those points, their ``resonant``), the series of the shorter padded with zero
    harmonics; and where it is resonant (bool (n,))."""
    width = max(motion.cos.shape[-1] for _, motion, _ in parts)
    cos, sin = np.zeros(omega.shape + (3, width)), np.zeros(omega.shape + (3, width))
    resonant = np.zeros(omega.shape, dtype=bool)
    for where, motion, stuck in parts:
        K = motion.cos.shape[-1]
        cos[where, :, :K], sin[where, :, :K], resonant[where] = motion.cos, motion.sin, stuck
    return PeriodicMotion(omega, cos, sin), resonant


def coupled_motion(design: CrankDesign, omega, blocks):
    """The averaged operator's steady state of ``design`` at each speed of ``omega`` [rad/s] (n,),
    and where it has none (bool (n,)): the mechanism's M̄, C̄, K̄ and forcing at each speed
    (:class:`~foundation_calc.solvers.crank.batch.MechanismOperator` about ω, exact), the block's
    on the support at each harmonic's frequency n ω, n = 0 ... K (``blocks(frequencies)``: M, C, K
    (..., 3, 3) at an array of frequencies [rad/s], :func:`plane_blocks`; one call per harmonic, so
    that a pile group's impedance holds one chunk of frequencies at a time), and per harmonic

        (K̄(nω) + i nω C̄(nω) - n²ω² M̄) Z_n = F_n

    solved for every speed at once (:func:`~foundation_calc.solvers.crank.batch.harmonic_response`);
    resonant where a mode of the operator at ω that the dashpots leave undamped lies within the
    resonant margin of a harmonic (:func:`~foundation_calc.solvers.crank.batch.resonant_blocks`)."""
    from foundation_calc.solvers.crank.batch import MechanismOperator, harmonic_response, resonant_blocks

    omega = np.asarray(omega, dtype=float)
    mech = MechanismOperator.of(design, "omega")
    M_m, C_m, K_m, fc, fs = mech.at(omega)
    parts = [blocks(n * omega) for n in range(mech.harmonics + 1)]  # one harmonic at a time: the support's memory
    M, C, K = (np.stack([part[i] for part in parts], axis=1) for i in range(3))  # (n, K + 1, 3, 3)
    resonant, _ = resonant_blocks(M_m + M[:, 1], C[:, 1], K_m + K[:, 1], omega[:, None])
    Z = harmonic_response(M_m[:, None] + M, C_m[:, None] + C, K_m[:, None] + K, omega[:, None], fc, fs, mech.harmonics,
                          per_harmonic=True, decoupled=mech.decoupled)
    Z = np.where(resonant[:, None, None], 0.0, Z)
    return PeriodicMotion(omega, Z.real, -Z.imag), resonant


def _static_blocks(design: CrankDesign):
    """``blocks`` of :func:`coupled_motion` on a frequency-independent support: the design's own at every frequency."""
    from foundation_calc.solvers.crank.averaged import block_matrices

    found = block_matrices(design)
    return lambda frequencies: tuple(np.broadcast_to(A, np.shape(frequencies) + (3, 3)) for A in found)


def plane_blocks(scene, design: CrankDesign):
    """M, C, K (..., 3, 3) of ``design``'s block (:func:`~foundation_calc.solvers.crank.averaged.block_matrices`)
    on the ``crank_foundation`` scene's support at the frequencies given (an array [rad/s]), its
    sway-rocking coupling included (:func:`~foundation_calc.solvers.supports.plane_footing.plane`):
    the springs and dashpots ``scene.design(frequency)`` takes, read for every
    frequency at once. The static stability in rocking is the scene's (its design at rest); a
    pile group's rocking spring at a frequency past its interaction peaks may fall below P h there
    without making the steady state any less defined."""
    from foundation_calc.solvers.crank.averaged import block_matrices
    from foundation_calc.solvers.supports.plane_footing import plane

    support = scene.support()
    f = scene.foundation

    def at(frequencies):
        shape = np.shape(frequencies)
        (K_x, K_z, K_phi), (C_x, C_z, C_phi), (K_xphi, C_xphi) = (
            tuple(np.broadcast_to(v, (np.size(frequencies),)).reshape(shape) for v in part)
            for part in plane(support.impedance(np.ravel(frequencies)), support.label))
        return block_matrices(replace(design, c=K_z / f.base_area, c1=K_x / f.base_area, c_phi=K_phi / f.base_second_moment,
                                      C_x=C_x, C_z=C_z, C_phi=C_phi, K_xphi=K_xphi, C_xphi=C_xphi))

    return at


def _critical_speeds(design, vendor, conditions, share, detuning, lo: float, hi: float, dynamic=None) -> tuple[CriticalSpeed, ...]:
    """Critical speeds [rad/s] inside [lo, hi] of the conditions that are judged or named (the
    paper's, the extra ones, the loads'), with the band of each one's order."""
    zero, averaged = design_frequencies(design) if design is not None else (block_frequencies(vendor.block),) * 2
    if dynamic is not None:
        zero, averaged = dynamic.zero, dynamic.averaged
    orders = np.array([c.harmonic for c in conditions])
    required = required_detuning(detuning, orders)
    judged = judge(np.ones(len(conditions)), orders, share, required, [c.source == "paper" for c in conditions]).judged
    found = []
    for c, band, j in zip(conditions, required, judged):
        w0 = float(critical_speed(getattr(zero, c.mode), c.harmonic))
        w1 = float(critical_speed(getattr(averaged, c.mode), c.harmonic))
        if (j or c.source != "harmonic") and lo <= max(w0, w1) and min(w0, w1) <= hi:
            found.append(CriticalSpeed(c.label, c.source, w0, w1, float(band) if j else 0.0, bool(j)))
    return tuple(found)


def sweep_chunks(
    design: CrankDesign | None, variable: str, values, limits, detuning, points=(), vendor=None, chunk: int | None = None,
    dynamic: DynamicSoil | None = None,
):
    """:func:`sweep` in chunks of ``chunk`` points, one :class:`SweepReport` each, so that a long
    sweep's memory is bounded by a chunk (the conditions' margins are (points × conditions)
    arrays). The conditions and their forcing shares are the scene's, at its own speed and soil
    (:func:`~foundation_calc.checks.crank_resonance.machine_conditions`): which conditions are
    judged does not change along a sweep, and the row at the scene's speed is ``fcalc check``'s.
    ``dynamic``: a frequency-dependent soil, for a speed sweep (module docstring)."""
    if dynamic is not None and variable != "omega":
        raise ValueError("a frequency-dependent soil is swept frequency-consistently by speed only")
    if design is not None and design.coupled and variable != "omega":
        raise ValueError("a support coupling sway with rocking is swept by soil from its scene (factored_soil_chunks)")
    if variable not in VARIABLES:
        raise ValueError(f"variable must be one of {VARIABLES}, not {variable!r}")
    values = np.asarray(values, dtype=float)
    conditions, share = machine_conditions(design, None if vendor is None else vendor.loads,
                                           None if vendor is None else vendor.block)
    critical = ()
    if variable == "omega" and values.size:
        critical = _critical_speeds(design, vendor, conditions, share, detuning, float(values.min()), float(values.max()),
                                    dynamic)
    chunk = CHUNK if chunk is None else chunk
    for i in range(0, len(values), chunk):
        part = _chunk(design, variable, values[i : i + chunk], limits, detuning, points, vendor, conditions, share, dynamic)
        yield replace(part, critical=critical)


def factored_soil_chunks(scene, values, limits, detuning, points=()):
    """A soil sweep of a ``crank_foundation`` scene on a frequency-dependent soil (module
    docstring), one :class:`SweepReport` of one point per factor of ``values`` [-]: the scene with
    its soil's stiffness data × factor (:meth:`~foundation_calc.scenes.soil.OnSoil.with_modulus_factor`)
    at its own speed, on the springs and dashpots at n ω and the natural frequencies that solve
    ω = p(K(ω)) (:func:`scene_dynamic_soil`). ``limits``, ``detuning``, ``points`` as
    :func:`sweep` takes them; the conditions and their forcing shares are the scene's as given,
    as :func:`sweep_chunks` takes them."""
    from foundation_calc.checks.approximations import scene_vendor_loads

    vendor = scene_vendor_loads(scene)
    conditions, share = machine_conditions(None if scene.mechanism is None else scene.design(),
                                           None if vendor is None else vendor.loads, None if vendor is None else vendor.block)
    omega = np.array([scene.speed.omega_rad_s])
    for factor in np.asarray(values, dtype=float):
        at = scene.with_modulus_factor(float(factor))
        design = None if at.mechanism is None else at.design()
        part = _chunk(design, "omega", omega, limits, detuning, points, scene_vendor_loads(at), conditions, share,
                      scene_dynamic_soil(at))
        yield replace(part, variable="soil_factor", values=np.array([factor]))


def scene_sweep_chunks(scene, variable: str, values):
    """The chunks of a sweep of a ``crank_foundation`` scene (:func:`sweep_chunks`) of ``variable``
    over ``values``, with its [limits], [[points]] and [[loads]]: frequency-consistent on a
    frequency-dependent soil (module docstring)."""
    from foundation_calc.checks.approximations import scene_vendor_loads

    points = [(p.name, p.horizontal, p.height) for p in scene.points]
    limits, detuning = scene.limits, scene.limits.detuning
    design = None if scene.mechanism is None else scene.design()
    coupled = design is not None and design.coupled  # its K_xφ is recomputed from the soil, not scaled
    if variable == "soil_factor" and (coupled or scene.support().frequency_dependent):
        return factored_soil_chunks(scene, values, limits, detuning, points)
    dynamic = scene_dynamic_soil(scene) if variable == "omega" else None
    return sweep_chunks(design, variable, values, limits, detuning, points, scene_vendor_loads(scene), dynamic=dynamic)


def joined(parts: list[SweepReport]) -> SweepReport:
    """One report of the chunks ``parts`` (their point arrays joined end to end)."""
    first = parts[0]
    if len(parts) == 1:
        return first
    join = np.concatenate
    return replace(
        first,
        **{name: join([getattr(p, name) for p in parts]) for name in _POINT_ARRAYS},
        points={k: join([p.points[k] for p in parts]) for k in first.points},
        over_quantities={k: join([p.over_quantities[k] for p in parts]) for k in first.over_quantities},
        harmonics={k: join([p.harmonics[k] for p in parts]) for k in first.harmonics},
        not_applicable=next((p.not_applicable for p in parts if p.not_applicable), {}),
    )


#: The fields of :class:`SweepReport` that hold one value per point.
_POINT_ARRAYS = ("values", "omega", "peaks", "resonant", "margin", "governing", "needed", "resonance_status", "status")


def sweep(
    design: CrankDesign | None, variable: str, values, limits, detuning, points=(), vendor=None, dynamic=None
) -> SweepReport:
    """Sweep ``variable`` (``"omega"`` [rad/s] or ``"soil_factor"`` [-]) over ``values``.

    ``limits``: the scene's ``[limits]`` (peak and RMS limits [m, m/s, m/s²] or None), checked as
    ``fcalc amplitudes`` checks them; ``detuning``: its band or bands per order;
    ``points``: (name, horizontal, height) [m] of body points relative to C, as the scene's
    ``[[points]]``; their peaks come from the same series (rigid-body motion, exact in θ).
    ``vendor``: the scene's ``[[loads]]``
    (:class:`~foundation_calc.checks.approximations.VendorLoads`), whose linear steady state
    is added to the mechanism's, or is the whole motion when ``design`` is None; their
    conditions n ω = k0, p1, p2 join the mechanism's. ``dynamic``: a frequency-dependent soil
    (:class:`DynamicSoil`, :func:`scene_dynamic_soil`). Computed in chunks (:func:`sweep_chunks`).

    Raises
    ------
    PhysicsError
        when a point of the sweep is unstable in rocking (a soil factor too small).
    """
    return joined(list(sweep_chunks(design, variable, values, limits, detuning, points, vendor, dynamic=dynamic)))


def scene_dynamic_soil(scene) -> DynamicSoil | None:
    """The :class:`DynamicSoil` of a ``crank_foundation`` scene on a frequency-dependent soil; None
    on the others."""
    if not scene.support().frequency_dependent:
        return None
    from foundation_calc.checks.approximations import scene_vendor_loads
    from foundation_calc.checks.crank_resonance import scene_block_frequencies, scene_design_frequencies

    def at(soil_frequency):
        return (None if scene.mechanism is None else scene.design(soil_frequency)), scene_vendor_loads(scene, soil_frequency)

    if scene.mechanism is None:
        frequencies, _ = scene_block_frequencies(scene)
        return DynamicSoil(at, frequencies, frequencies)
    zero, averaged, _ = scene_design_frequencies(scene)
    design = scene.design()
    return DynamicSoil(at, zero, averaged, plane_blocks(scene, design))


__all__ = ["HARMONICS", "STATUSES", "VARIABLES", "CriticalSpeed", "DynamicSoil", "SweepReport", "coupled_motion",
           "factored_soil_chunks", "frequency_consistent_motion", "joined", "plane_blocks", "scene_dynamic_soil",
           "scene_sweep_chunks", "side_by_side", "sweep", "sweep_chunks"]
