"""Sweep of a crank foundation's speed or soil stiffness: closed-form amplitudes, resonances, limits,
as the one report of every kind's sweep (:class:`~foundation_calc.checks.sweep.report.SweepReport`;
its columns ``omega``, ``peaks``, ``points``, ``harmonics``, its setup ``damped``, ``coupled``,
``not_applicable``), the motion from the crank's engine (:mod:`foundation_calc.solvers.crank.sweep`).

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
forms do not apply ("not applicable", :data:`~foundation_calc.checks.amplitudes.approximations.FIRST_NOT_APPLICABLE`):
the peaks are the plane's one model's, the averaged operator with the exact forcing as ``fcalc
amplitudes`` solves it there, each harmonic n at n ω on the support's springs and dashpots at n ω,
for every speed at once (:func:`~foundation_calc.solvers.crank.sweep.coupled_motion`: the mechanism's part, a polynomial of degree 2
in ω, :class:`~foundation_calc.solvers.crank.batch.MechanismOperator`; one batched 3 × 3 solve per
harmonic over the chunk of speeds); the critical speeds and margins are to the modes ``fcalc
resonance`` reports, the one model's eigen-solve, each at its own frequency. A soil sweep there
recomputes the group from the factored soil data, as a frequency-dependent soil's.
"""

from __future__ import annotations

from dataclasses import dataclass, replace

import numpy as np

from foundation_calc.checks.limits import QUANTITIES, limited_quantities
from foundation_calc.checks.resonance.report import judge_conditions
from foundation_calc.checks.resonance.rule import judge, required_detuning
from foundation_calc.checks.sweep.report import SweepReport, joined
from foundation_calc.checks.sweep.status import over_limits, row_verdicts
from foundation_calc.solvers.crank import sweep as engine
from foundation_calc.solvers.crank.loads import block_frequencies
from foundation_calc.solvers.crank.mechanism import CrankDesign
from foundation_calc.solvers.crank.natural import design_frequencies
from foundation_calc.solvers.crank.machine_conditions import machine_conditions
from foundation_calc.solvers.crank.resonance import critical_speed

#: What a sweep can vary: the crank speed [rad/s] or a factor [-] on both soil coefficients.
VARIABLES = ("omega", "soil_factor")

#: Harmonics of the first approximation reported per point (dof, n).
HARMONICS = (("y", 1), ("y", 2), ("x", 1), ("x", 3), ("theta", 1), ("theta", 3))


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
    (:func:`~foundation_calc.checks.resonance.frequencies.scene_design_frequencies`); ``blocks``: the
    block's M, C, K on the support at an array of frequencies (:func:`~foundation_calc.solvers.crank.sweep.plane_blocks`) for the
    averaged operator: the whole sweep on a support that couples sway with rocking, the speeds where
    the first approximation steps aside on the others (None for a machine given by its loads)."""

    at: object
    zero: object
    averaged: object
    blocks: object = None


def _located(motion, omega, points, limits: dict):
    """Peak displacements of every point, name -> (n, 2) [m], and, per limited quantity (peak or
    RMS), whether a value of C (x, y) or of a point exceeds the limit (bool (n,))
    (:func:`~foundation_calc.solvers.crank.sweep.located`)."""
    orders = {}  # every quantity a limit may bound -> (order of the time derivative, a peak or not)
    for order, quantity in enumerate(QUANTITIES):
        orders[quantity], orders[f"{quantity}_rms"] = (order, True), (order, False)
    found_at, largest = engine.located(motion, omega, points, orders, limits)
    return found_at, over_limits(largest, limits)


def _complex(cos, sin):
    """cos - i sin of a pair of arrays."""
    return cos - 1j * sin


def _chunk(design, variable: str, values, limits, detuning, points, vendor, conditions, share, dynamic=None) -> SweepReport:
    """One chunk of :func:`sweep_chunks` (``critical`` left empty: the caller sets it)."""
    coupled = design is not None and design.coupled
    found = engine.sweep_motion(design, variable, values, vendor, None if dynamic is None else dynamic.at,
                                None if dynamic is None else dynamic.blocks)
    motion, resonant, omega, not_applicable = found.motion, found.resonant, found.omega, found.why
    if coupled:
        from foundation_calc.checks.amplitudes.approximations import FIRST_NOT_APPLICABLE

        not_applicable = {"first_approximation": FIRST_NOT_APPLICABLE}
    if dynamic is not None:
        zero, averaged = dynamic.zero, dynamic.averaged
    elif design is None:
        zero = averaged = block_frequencies(found.block)
    else:
        zero, averaged = design_frequencies(design if coupled else found.batch)
    dashpotted = [d for d in (design, None if vendor is None else vendor.block) if d is not None]
    peaks = engine.chunked_peaks(motion.cos, motion.sin)  # displacement only: (n, 3)
    margins, verdict, required = judge_conditions(omega, zero, averaged, conditions, share, detuning)
    margins = np.broadcast_to(margins, values.shape + (len(conditions),))
    limited = limited_quantities(limits)
    located, over_quantities = _located(motion, omega, points, limited)
    return SweepReport(
        variable=variable,
        values=values,
        resonant=resonant,
        rows=row_verdicts(margins, verdict, over_quantities, resonant),
        conditions=tuple(conditions),
        limits=limited,
        detuning=detuning,
        columns={"omega": omega, "peaks": peaks, "points": located,
                 "harmonics": {f"{dof}{n}": _complex(*motion.coefficient(dof, n)) for dof, n in HARMONICS}},
        setup={"damped": any(float(np.max(getattr(d, key))) > 0.0 for d in dashpotted for key in ("C_x", "C_z", "C_phi")),
               "coupled": coupled, "not_applicable": not_applicable},
    )


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
    (:func:`~foundation_calc.solvers.crank.machine_conditions.machine_conditions`): which conditions are
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
    chunk = engine.CHUNK if chunk is None else chunk
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
    from foundation_calc.checks.amplitudes.approximations import scene_vendor_loads

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
    from foundation_calc.checks.amplitudes.approximations import scene_vendor_loads

    points = [(p.name, p.horizontal, p.height) for p in scene.points]
    limits, detuning = scene.limits, scene.limits.detuning
    design = None if scene.mechanism is None else scene.design()
    coupled = design is not None and design.coupled  # its K_xφ is recomputed from the soil, not scaled
    if variable == "soil_factor" and (coupled or scene.support().frequency_dependent):
        return factored_soil_chunks(scene, values, limits, detuning, points)
    dynamic = scene_dynamic_soil(scene) if variable == "omega" else None
    return sweep_chunks(design, variable, values, limits, detuning, points, scene_vendor_loads(scene), dynamic=dynamic)


def sweep(
    design: CrankDesign | None, variable: str, values, limits, detuning, points=(), vendor=None, dynamic=None
) -> SweepReport:
    """Sweep ``variable`` (``"omega"`` [rad/s] or ``"soil_factor"`` [-]) over ``values``.

    ``limits``: the scene's ``[limits]`` (peak and RMS limits [m, m/s, m/s²] or None), checked as
    ``fcalc amplitudes`` checks them; ``detuning``: its band or bands per order;
    ``points``: (name, horizontal, height) [m] of body points relative to C, as the scene's
    ``[[points]]``; their peaks come from the same series (rigid-body motion, exact in θ).
    ``vendor``: the scene's ``[[loads]]``
    (:class:`~foundation_calc.checks.amplitudes.approximations.VendorLoads`), whose linear steady state
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
    from foundation_calc.checks.amplitudes.approximations import scene_vendor_loads
    from foundation_calc.checks.resonance.frequencies import scene_block_frequencies, scene_design_frequencies

    def at(soil_frequency):
        return (None if scene.mechanism is None else scene.design(soil_frequency)), scene_vendor_loads(scene, soil_frequency)

    if scene.mechanism is None:
        frequencies, _ = scene_block_frequencies(scene)
        return DynamicSoil(at, frequencies, frequencies)
    zero, averaged, _ = scene_design_frequencies(scene)
    design = scene.design()
    return DynamicSoil(at, zero, averaged, engine.plane_blocks(scene.support(), scene.foundation.base_area,
                                                            scene.foundation.base_second_moment, design))


__all__ = ["HARMONICS", "VARIABLES", "CriticalSpeed", "DynamicSoil", "factored_soil_chunks", "scene_dynamic_soil",
           "scene_sweep_chunks", "sweep", "sweep_chunks"]
