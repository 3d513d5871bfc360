"""Resonance check of a crank-mechanism foundation against the scene's required detuning.

Each condition n·ω = p of :data:`~foundation_calc.solvers.crank.resonance.CONDITIONS` has two
estimates of its critical speed: from the paper's zero-order operator and from the operator with
the mechanism's time-averaged inertia. The margin is measured to the nearer of the two, so the
verdict holds whichever estimate is used. The verdict follows the rule shared by every scene kind
(:func:`~foundation_calc.checks.outcomes.resonance_outcome`): a paper condition (the mechanism
drives it at first order) fails inside the band; an extra one warns there and fails within 5 %.
"""

from __future__ import annotations

from dataclasses import dataclass

from foundation_calc.checks.outcomes import Outcome, resonance_outcome, worst
from foundation_calc.solvers.crank.frequencies import (
    NaturalFrequencies,
    averaged_inertia_frequencies,
    rocking_stability_margin,
    zero_order_frequencies,
)
from foundation_calc.solvers.crank.mechanism import CrankDesign
from foundation_calc.solvers.crank.resonance import (
    CONDITIONS,
    ResonanceCondition,
    condition_margin,
    critical_speed,
)


@dataclass(frozen=True)
class ResonanceRow:
    """One resonance condition checked at the operating speed (speeds in rad/s)."""

    condition: ResonanceCondition
    critical_zero_order: float
    critical_averaged: float
    margin: float
    required: float
    outcome: Outcome


@dataclass(frozen=True)
class ResonanceReport:
    """Natural frequencies of a design and its resonance rows.

    ``design`` is None for a machine given by its loads only; ``averaged`` is then the same as
    ``zero_order`` (there is no mechanism whose inertia could be averaged). On a
    frequency-dependent soil each frequency solves ω = p(K(ω)) with the springs taken at that
    mode's own frequency, and ``static`` holds the zero-order frequencies on the static springs
    (None on a frequency-independent soil, where they are the same).
    """

    design: CrankDesign | None
    zero_order: NaturalFrequencies
    averaged: NaturalFrequencies
    stability_margin: float
    rows: tuple[ResonanceRow, ...]
    omega: float
    static: NaturalFrequencies | None = None
    #: the check over the soil's ``modulus_range`` (:mod:`foundation_calc.checks.soil_range`), if given
    modulus_range: object = None

    @property
    def outcome(self) -> Outcome:
        ranged = () if self.modulus_range is None else (self.modulus_range.outcome,)
        return worst((*(row.outcome for row in self.rows), *ranged))

    @property
    def nearest(self) -> ResonanceRow:
        """The row with the smallest margin."""
        return min(self.rows, key=lambda row: row.margin)


def design_frequencies(design: CrankDesign) -> tuple[NaturalFrequencies, NaturalFrequencies]:
    """Zero-order and averaged-inertia natural frequencies of a design (fields may be arrays)."""
    d, rod = design, design.rod
    soil_args = (d.M_tot, d.I_c, d.h, d.S, d.I1, d.c, d.c1, d.c_phi, d.g)
    zero = zero_order_frequencies(*soil_args)
    averaged = averaged_inertia_frequencies(*soil_args, rod.m, d.a, d.r, d.l, rod.l1, rod.rho)
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


def _row(omega, zero, averaged, cond: ResonanceCondition, detuning: float) -> ResonanceRow:
    w0 = critical_speed(getattr(zero, cond.mode), cond.harmonic)
    w1 = critical_speed(getattr(averaged, cond.mode), cond.harmonic)
    margin = condition_margin(omega, zero, averaged, cond)
    outcome = resonance_outcome(margin, detuning, driven=cond.source == "paper" or cond.driven)
    return ResonanceRow(cond, w0, w1, margin, detuning, outcome)


def check_resonances(design: CrankDesign, detuning: float, loads=None, frequencies=None) -> ResonanceReport:
    """Natural frequencies of ``design`` and the margin of its speed from every resonance; with
    ``loads`` (:class:`~foundation_calc.solvers.crank.loads.HarmonicLoads`) also from n ω of
    every order n of the loads (:func:`load_resonance_conditions`). ``frequencies`` =
    (zero-order, averaged, static) replaces the design's own (a frequency-dependent soil)."""
    d = design
    zero, averaged = design_frequencies(design)
    static = None
    if frequencies is not None:
        zero, averaged, static = frequencies
    conditions = CONDITIONS + (() if loads is None else load_resonance_conditions(loads))
    return ResonanceReport(
        design=design,
        zero_order=zero,
        averaged=averaged,
        stability_margin=rocking_stability_margin(d.c_phi, d.I1, d.M_tot * d.g, d.h),
        rows=tuple(_row(d.omega, zero, averaged, cond, detuning) for cond in conditions),
        omega=d.omega,
        static=static,
    )


#: What drives a mode, for the rows of the loads.
_LOAD_EXCITATION = {"k0": "vertical force", "p1": "horizontal force or moment about C", "p2": "horizontal force or moment about C"}


def load_resonance_conditions(loads) -> tuple[ResonanceCondition, ...]:
    """n ω = k0, p1, p2 for every order n of the loads; driven where a load of order n has a
    component that drives the mode (:func:`~foundation_calc.solvers.crank.loads.load_conditions`)."""
    from foundation_calc.solvers.crank.loads import load_conditions

    return tuple(
        ResonanceCondition(
            f"{n if n > 1 else ''}ω = {mode}", n, mode, "loads",
            f"loads of order {n}: {_LOAD_EXCITATION[mode]}" + ("" if driven else " (none given)"), driven,
        )
        for n, mode, driven in load_conditions(loads)
    )


def check_block_resonances(block, omega: float, loads, detuning: float, frequencies=None) -> ResonanceReport:
    """Resonances of a machine given by its loads only: n ω of every order n of ``loads``
    against the natural frequencies of the block (``RigidBlock``) at the speed ``omega`` [rad/s];
    ``frequencies`` = (frequencies, static) replaces the block's own (a frequency-dependent soil)."""
    from foundation_calc.solvers.crank.loads import block_frequencies

    freqs, static = block_frequencies(block), None
    if frequencies is not None:
        freqs, static = frequencies
    return ResonanceReport(
        design=None,
        zero_order=freqs,
        averaged=freqs,
        stability_margin=rocking_stability_margin(block.K_phi, 1.0, block.M_tot * block.g, block.h),
        rows=tuple(_row(omega, freqs, freqs, cond, detuning) for cond in load_resonance_conditions(loads)),
        omega=omega,
        static=static,
    )


def check_scene_resonances(scene) -> ResonanceReport:
    """The resonance report of a ``crank_foundation`` scene: its mechanism, its loads or both; with
    ``soil.modulus_range``, also over that range (the verdict is the worse of the two)."""
    report = _scene_resonances(scene)
    if scene.soil.modulus_range is None:
        return report
    from dataclasses import replace

    from foundation_calc.checks.soil_range import resonances_over_range

    return replace(report, modulus_range=resonances_over_range(scene, _scene_resonances))


def _scene_resonances(scene) -> ResonanceReport:
    loads = scene.harmonic_loads()
    if scene.mechanism is None:
        return check_block_resonances(scene.block(), scene.speed.omega_rad_s, loads, scene.limits.detuning,
                                      scene_block_frequencies(scene))
    return check_resonances(scene.design(), scene.limits.detuning, loads, scene_design_frequencies(scene))


_MODES = ("k0", "p1", "p2")


def _consistent(static: NaturalFrequencies, frequencies_at) -> NaturalFrequencies:
    """Each mode of ``static`` re-solved as ω = p(K(ω)), ``frequencies_at(ω)`` giving the
    NaturalFrequencies on the springs taken at ω."""
    from foundation_calc.solvers.soil.impedance import consistent_frequency

    return NaturalFrequencies(**{
        mode: consistent_frequency(lambda w, mode=mode: getattr(frequencies_at(w), mode), getattr(static, mode))
        for mode in _MODES
    })


def scene_design_frequencies(scene):
    """(zero-order, averaged, static) frequencies of a scene's mechanism on a frequency-dependent
    soil, each mode at its own frequency (ω = p(K(ω))); None on a frequency-independent soil."""
    if not scene.soil.frequency_dependent:
        return None
    static, _ = design_frequencies(scene.design())
    zero = _consistent(static, lambda w: design_frequencies(scene.design(w))[0])
    averaged = _consistent(design_frequencies(scene.design())[1], lambda w: design_frequencies(scene.design(w))[1])
    return zero, averaged, static


def scene_block_frequencies(scene):
    """(frequencies, static) of a machine given by its loads on a frequency-dependent soil, each
    mode at its own frequency; None on a frequency-independent soil."""
    if not scene.soil.frequency_dependent:
        return None
    from foundation_calc.solvers.crank.loads import block_frequencies

    static = block_frequencies(scene.block())
    return _consistent(static, lambda w: block_frequencies(scene.block(w))), static
