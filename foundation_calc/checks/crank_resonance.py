"""Resonance check of a crank-mechanism foundation against the scene's required detuning.

Each condition n·ω = p of :data:`~foundation_calc.solvers.crank.resonance.CONDITIONS` has two
estimates of its critical speed: from the paper's zero-order operator and from the operator with
the mechanism's time-averaged inertia. The margin is measured to the nearer of the two, so the
verdict holds whichever estimate is used. Which conditions are judged and how is the rule shared
by every scene kind (:mod:`~foundation_calc.checks.resonance_rule`): the paper's six, and every
other harmonic n ω = k0, p1, p2 of the machine's forcing whose forcing share reaches 1 %.
This module gives the plane model's conditions, frequencies and forcing shares; the rows, the
report and its words are every kind's (:mod:`~foundation_calc.checks.resonance`).
"""

from __future__ import annotations

import math
from dataclasses import replace

import numpy as np

from foundation_calc.checks.resonance import ResonanceReport, judged_rows
from foundation_calc.checks.resonance_rule import INFORMATION, judge, required_detuning
from foundation_calc.solvers.crank.frequencies import (
    NaturalFrequencies,
    averaged_inertia_frequencies,
    rocking_stability_margin,
    stability_arguments,
    zero_order_frequencies,
)
from foundation_calc.solvers.crank.mechanism import CrankDesign
from foundation_calc.solvers.crank.resonance import (
    CONDITIONS,
    ResonanceCondition,
    condition_margin,
    critical_speed,
)


def design_frequencies(design: CrankDesign) -> tuple[NaturalFrequencies, NaturalFrequencies]:
    """Zero-order and averaged-inertia natural frequencies of a design (fields may be arrays); on a
    frequency-dependent support's springs at ω ≠ 0 (its ``soil_frequency``) no stability is judged
    and a mode the springs there leave without a positive frequency is 0 (the scene judged the
    springs at rest, :meth:`~foundation_calc.scenes.crank.CrankScene.in_plane`). On a
    support coupling u_x with θ_y (a pile group) the closed forms do not apply: both are the one
    model's eigen-solve in the plane (:func:`~foundation_calc.solvers.crank.averaged.plane_frequencies`,
    one design)."""
    at_rest = not np.any(np.asarray(design.soil_frequency) != 0.0)  # stability is judged on static springs only
    if design.coupled:
        from foundation_calc.solvers.crank.averaged import plane_frequencies

        found = plane_frequencies(design, at_rest)
        return found, found
    d, rod = design, design.rod
    soil_args = (d.M_tot, d.I_c, d.h, d.S, d.I1, d.c, d.c1, d.c_phi, d.g)
    zero = zero_order_frequencies(*soil_args, at_rest=at_rest)
    averaged = averaged_inertia_frequencies(*soil_args, rod.m, d.a, d.r, d.l, rod.l1, rod.rho, at_rest=at_rest)
    return zero, averaged


def paper_margin(design: CrankDesign):
    """Smallest margin [-] of the speed from the paper's six conditions; arrays of designs welcome.

    This is the batch path: one call for a million designs, numpy arrays in and out.
    """
    zero, averaged = design_frequencies(design)
    margins = [condition_margin(design.omega, zero, averaged, c) for c in CONDITIONS if c.source == "paper"]
    smallest = margins[0]
    for m in margins[1:]:
        smallest = (smallest + m - abs(smallest - m)) / 2.0
    return smallest


#: Conditions listed as information beside the judged ones (the nearest first).
SHOWN_INFORMATION = 3

#: The crank foundation's modes in the plane, by name: vertical k0, sliding-rocking p1 < p2.
MODES = ("k0", "p1", "p2")


def _label(n: int, mode: str) -> str:
    return f"{n if n > 1 else ''}ω = {mode}"


def forcing_shares(M, K, forces) -> np.ndarray:
    """Forcing share [-] of each harmonic on each mode: the modal weights
    (:func:`~foundation_calc.solvers.numerics.modal_forcing.modal_forcing_weights`) of ``forces``
    (H, 3) on (K, M), modes in the order k0, p1, p2, over the largest weight; shape (..., H, 3)
    for stacks (..., 3, 3) of operators."""
    from foundation_calc.solvers.crank.averaged import mode_order
    from foundation_calc.solvers.numerics.modal_forcing import modal_forcing_weights

    _, shapes, weights = modal_forcing_weights(M, K, forces)
    weights = np.take_along_axis(weights, mode_order(M, shapes)[..., None, :], axis=-1)
    largest = weights.max(axis=(-2, -1), keepdims=True)
    return np.where(largest > 0.0, weights / np.where(largest > 0.0, largest, 1.0), 0.0)


def harmonic_conditions(orders, load_orders=(), mechanism: bool = True) -> tuple[ResonanceCondition, ...]:
    """The conditions n ω = k0, p1, p2 of every order n of ``orders``, in that order: the paper's
    own where it names them, else one of the mechanism's harmonics, of the loads' orders or of the
    speed itself (a machine given by its loads)."""
    known = {(c.harmonic, c.mode): c for c in CONDITIONS} if mechanism else {}
    conditions = []
    for n in orders:
        for mode in MODES:
            condition = known.get((n, mode))
            if condition is None:
                source = "loads" if n in load_orders else "harmonic" if mechanism else "speed"
                excitation = {
                    "loads": f"loads of order {n}",
                    "harmonic": f"harmonic {n} of the mechanism's forcing",
                    "speed": "the speed itself (no load of order 1)",
                }[source]
                condition = ResonanceCondition(_label(n, mode), n, mode, source, excitation)
            conditions.append(condition)
    return tuple(conditions)


def machine_conditions(design: CrankDesign | None, loads=None, block=None) -> tuple[tuple[ResonanceCondition, ...], np.ndarray]:
    """Every condition n ω = k0, p1, p2 of the machine's forcing and its forcing share [-].

    The mechanism's harmonics 1 ... :data:`~foundation_calc.solvers.crank.averaged.FORCING_HARMONICS`
    come from its exact forcing on the averaged operator; the loads' orders (and order 1, the
    speed itself) from ``loads`` on the averaged operator, or on ``block`` for a machine given by
    its loads only. A harmonic of both adds the two forces (their phases included).
    """
    from foundation_calc.solvers.crank.averaged import averaged_operator
    from foundation_calc.solvers.crank.loads import matrices

    forces: dict[int, np.ndarray] = {1: np.zeros(3, dtype=complex)}
    if design is not None:
        M, _, K, fc, fs = averaged_operator(design)
        for n, force in enumerate((fc - 1j * fs).T[1:], start=1):
            forces[n] = force
    else:
        M, K, _ = matrices(block)
    load_orders = set()
    if loads is not None:
        generalized = loads.generalized()
        for n in sorted({int(k) for k in loads.order}):
            load_orders.add(n)
            forces[n] = forces.get(n, 0.0) + generalized[np.asarray(loads.order) == n].sum(axis=0)
    orders = sorted(forces)
    shares = forcing_shares(M, K, np.array([forces[n] for n in orders]))
    return harmonic_conditions(orders, load_orders, design is not None), shares.ravel()


def judge_conditions(omega, zero, averaged, conditions, share, detuning):
    """The rule (:func:`~foundation_calc.checks.resonance_rule.judge`) on ``conditions`` at the
    speeds ``omega`` [rad/s] (a scalar or an array (S,)): margins (..., C), judgement, bands."""
    margins = np.stack(
        np.broadcast_arrays(*(np.asarray(condition_margin(omega, zero, averaged, c), dtype=float) for c in conditions)),
        axis=-1,
    )
    orders = np.array([c.harmonic for c in conditions])
    required = required_detuning(detuning, orders)
    source = np.array([c.source == "paper" for c in conditions])
    return margins, judge(margins, orders, share, required, source), required


def _report(design, zero, averaged, stability, omega, conditions, share, detuning) -> ResonanceReport:
    margins, verdict, required = judge_conditions(omega, zero, averaged, conditions, share, detuning)
    critical = [critical_speed(getattr(zero, c.mode), c.harmonic) for c in conditions]
    averaged_critical = [critical_speed(getattr(averaged, c.mode), c.harmonic) for c in conditions]
    rows, governing = judged_rows(conditions, critical, averaged_critical, margins, share, required, verdict)
    information = sorted((row for row in rows if row.information and row.condition.source == "harmonic"), key=lambda r: r.margin)
    listed = {id(row) for row in information[:SHOWN_INFORMATION]}
    shown = tuple(
        row for row in rows
        if row.condition.source != "harmonic" or row.judged or row.status > INFORMATION or id(row) in listed
    )
    return ResonanceReport(
        rows=shown, governing=governing, speeds={"": omega}, detuning=detuning, conditions_checked=len(rows),
        design=design, zero_order=zero, averaged=averaged, stability_margin=stability,
    )


def check_resonances(design: CrankDesign, detuning, loads=None, frequencies=None) -> ResonanceReport:
    """Natural frequencies of ``design`` and every resonance condition of its forcing (and of
    ``loads``, :class:`~foundation_calc.solvers.crank.loads.HarmonicLoads`), judged by the rule
    (:mod:`~foundation_calc.checks.resonance_rule`). ``detuning``: a band [-] or order -> band.
    ``frequencies`` = (zero-order, averaged, static) replaces the design's own (a
    frequency-dependent soil, :func:`scene_design_frequencies`)."""
    d = design
    zero, averaged = design_frequencies(design)
    static = None
    if frequencies is not None:
        zero, averaged, static = frequencies
    stability = rocking_stability_margin(*stability_arguments(d))
    conditions, share = machine_conditions(design, loads)
    return replace(_report(design, zero, averaged, stability, d.omega, conditions, share, detuning), static=static)


def check_block_resonances(block, omega: float, loads, detuning, frequencies=None) -> ResonanceReport:
    """Resonances of a machine given by its loads only: n ω of every order n of ``loads`` (and
    ω itself) against the natural frequencies of the block (``RigidBlock``) at ``omega`` [rad/s];
    ``frequencies`` = (frequencies, static) replaces the block's own (a frequency-dependent soil)."""
    from foundation_calc.solvers.crank.loads import block_frequencies

    freqs, static = block_frequencies(block), None
    if frequencies is not None:
        freqs, static = frequencies
    stability = rocking_stability_margin(block.K_phi, 1.0, block.M_tot * block.g, block.h)
    conditions, share = machine_conditions(None, loads, block)
    return replace(_report(None, freqs, freqs, stability, omega, conditions, share, detuning), static=static)


def check_scene_resonances(scene) -> ResonanceReport:
    """The resonance report of a ``crank_foundation`` scene: its mechanism, its loads or both; with
    ``soil.modulus_range``, also over that range (the verdict is the worse of the two); the soil
    model's validity at its modes and judged orders (:func:`~foundation_calc.checks.soil_validity.crank_validity`)."""
    from foundation_calc.checks.soil_validity import crank_validity

    report = scene_resonances_as_given(scene)
    report = replace(report, soil_validity=crank_validity(scene, report))
    if scene.soil.modulus_range is None:
        return report
    from foundation_calc.checks.soil_range import resonances_over_range

    return replace(report, modulus_range=resonances_over_range(scene, scene_resonances_as_given))


def scene_resonances_as_given(scene) -> ResonanceReport:
    """The resonance report of a scene with its soil data as given (no ``modulus_range``); on a
    frequency-dependent soil every mode at its own frequency."""
    loads = scene.harmonic_loads()
    if scene.mechanism is None:
        return check_block_resonances(scene.block(), scene.speed.omega_rad_s, loads, scene.limits.detuning,
                                      scene_block_frequencies(scene))
    several = {}
    report = check_resonances(scene.design(), scene.limits.detuning, loads, scene_design_frequencies(scene, several))
    return replace(report, several_roots=several_roots_warnings(report, several))


def several_roots_warnings(report: ResonanceReport, several: dict) -> tuple[str, ...]:
    """``WARN`` a line per mode of ``several`` (mode -> every root [rad/s] of ω = p(K(ω))): the
    roots in rad/s and Hz and the one the check took; and a line per judged condition n ω on that
    mode that the resonance rule would fail or warn against another root (its margin
    :func:`~foundation_calc.solvers.crank.resonance.condition_margin` with that root for the mode's
    frequency, against the condition's band): a speed near the other root is as resonant. The
    verdict stays the root taken's."""
    from foundation_calc.solvers.crank.resonance import condition_margin

    lines = []
    for mode, roots in several.items():
        taken = float(getattr(report.averaged, mode))
        listed = ", ".join(f"{w:.4g} rad/s ({w / (2.0 * math.pi):.4g} Hz)" for w in roots)
        lines.append(f"WARN mode {mode} has {len(roots)} natural frequencies on the support's springs at frequency"
                     f" (roots of ω = p(K(ω))): {listed}; the check takes {taken:.4g} rad/s, the root its search brackets")
        for row in (r for r in report.rows if r.judged and r.condition.mode == mode and r.required > 0.0):
            for root in (w for w in roots if abs(w - taken) > 1e-9 * taken):
                other = replace(report.averaged, **{mode: root})
                margin = float(condition_margin(report.omega, replace(report.zero_order, **{mode: root}), other, row.condition))
                if margin < row.required:
                    lines.append(f"WARN {row.label} at the other root {root:.4g} rad/s: margin {margin:.1%} (needs"
                                 f" {row.required:.0%}): a speed near it is as resonant")
    return tuple(lines)


def consistent_frequencies(static: NaturalFrequencies, frequencies_at, rootless: str = "raise",
                           several: dict | None = None) -> NaturalFrequencies:
    """Each mode of ``static`` re-solved as ω = p(K(ω)), ``frequencies_at(ω)`` giving the
    NaturalFrequencies on the springs taken at ω; a mode without a root raises the PhysicsError
    naming it, or with ``rootless="nan"`` (a batch of candidates) is NaN
    (:func:`~foundation_calc.solvers.soil.impedance.consistent_frequency`). ``several`` (one
    design): receives mode -> every root [rad/s] of a mode whose scan found more than one."""
    from foundation_calc.solvers.soil.impedance import consistent_frequency

    found = {}
    for mode in MODES:
        every = [] if several is not None else None
        found[mode] = consistent_frequency(lambda w, mode=mode: getattr(frequencies_at(w), mode), getattr(static, mode),
                                           mode=mode, rootless=rootless, every=every)
        if every is not None and len(every) > 1:
            several[mode] = tuple(every)
    return NaturalFrequencies(**found)


def scene_design_frequencies(scene, several: dict | None = None):
    """(zero-order, averaged, static) frequencies of a scene's mechanism on a frequency-dependent
    soil, each mode at its own frequency (ω = p(K(ω))); None on a frequency-independent soil.
    ``several``: receives mode -> every root of a mode with more than one (:func:`consistent_frequencies`;
    the averaged operator's, which the rule judges)."""
    if not scene.support().frequency_dependent:
        return None
    design = scene.design()
    static, static_averaged = design_frequencies(design)
    if design.coupled:  # the one model's modes, by rank as the block's are: one root of each
        ranked = by_static_rank(static)
        found = consistent_frequencies(static, lambda w: ranked(design_frequencies(scene.design(w))[1]),
                                       several=several)
        return found, found, static
    zero = consistent_frequencies(static, lambda w: design_frequencies(scene.design(w))[0])
    averaged = consistent_frequencies(static_averaged, lambda w: design_frequencies(scene.design(w))[1],
                                      several=several)
    return zero, averaged, static


def by_static_rank(static: NaturalFrequencies):
    """A function giving k0, p1, p2 at a frequency named by their rank in ``static``: the j-th
    lowest there takes the name of the j-th lowest at rest. A mode then follows its rank, as
    :func:`~foundation_calc.solvers.soil.impedance.consistent_frequency` needs it (its root exists
    and is bracketed), not its dominant motion, which a pile group's springs at frequency reorder.
    Fields may be arrays (a batch of designs): each design's modes by their own ranks."""
    rank = np.argsort(np.argsort(_stacked(static), axis=-1, kind="stable"), axis=-1)

    def ranked(found: NaturalFrequencies) -> NaturalFrequencies:
        values = np.take_along_axis(np.sort(_stacked(found), axis=-1), np.broadcast_to(rank, np.shape(_stacked(found))), -1)
        return NaturalFrequencies(*(values[..., j] for j in range(len(MODES))))

    return ranked


def _stacked(found: NaturalFrequencies) -> np.ndarray:
    """k0, p1, p2 of ``found`` stacked on a last axis, (..., 3)."""
    return np.stack(np.broadcast_arrays(*(np.asarray(getattr(found, mode), dtype=float) for mode in MODES)), axis=-1)


def scene_frequencies(scene) -> NaturalFrequencies:
    """k0, p1, p2 [rad/s] of a ``crank_foundation`` scene's operator with the mechanism's inertia
    averaged, as its resonance check reports them (a machine given by its loads: its block's), on
    a frequency-dependent soil each at its own frequency: the modes its start-up passes."""
    if scene.mechanism is None:
        from foundation_calc.solvers.crank.loads import block_frequencies

        found = scene_block_frequencies(scene)
        return block_frequencies(scene.block()) if found is None else found[0]
    found = scene_design_frequencies(scene)
    return design_frequencies(scene.design())[1] if found is None else found[1]


def scene_block_frequencies(scene):
    """(frequencies, static) of a machine given by its loads on a frequency-dependent soil, each
    mode at its own frequency; None on a frequency-independent soil."""
    if not scene.support().frequency_dependent:
        return None
    from foundation_calc.solvers.crank.loads import block_frequencies

    static = block_frequencies(scene.block())
    return consistent_frequencies(static, lambda w: block_frequencies(scene.block(w))), static
