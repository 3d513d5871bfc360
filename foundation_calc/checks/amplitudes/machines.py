"""Checks of a block foundation: resonance margins of every machine's orders from every mode,
the damped steady state against [limits] and a vibration code, and the office checks.

Resonances: each order n of each machine against each of the six modes, margin
|n ω - p_j| / p_j, judged by the resonance rule of every kind
(:func:`~foundation_calc.checks.resonance.rule.judge`) with the forcing share of the order on the
mode (|φ_jᵀ Q_n| / p_j over its largest value for the machine); no condition is the source's own.

Soil's modulus range (``[soil] modulus_range``): both checks also over the range, by the machinery
of the crank foundation's (:mod:`~foundation_calc.checks.soil_range`): the resonances at every
factor of its grid and where a critical speed p_j / n crosses a machine's speed, the amplitudes on
its coarser grid and at those crossings; each verdict is the worse of the soil as given and the
range, and the range names its governing factor.

On a frequency-dependent soil (Gazetas' impedance) every mode is taken at its own frequency and
every order n of every machine is solved with the springs and dashpots at n ω
(:mod:`~foundation_calc.solvers.block.response`).

Amplitudes: the peak of the displacement, of the velocity and of the acceleration over time, and
their RMS values, of the centre of mass G and of every point, along x, y and z;
several machines combine as :mod:`~foundation_calc.solvers.block.response` says (peaks add, RMS
values add as root-sum-square). A code zone judges each point's largest RMS velocity.
"""

from __future__ import annotations

from dataclasses import dataclass, replace

import numpy as np

from foundation_calc.checks.amplitudes.report import AmplitudeVerdict, judge
from foundation_calc.checks.limits import AmplitudeWording
from foundation_calc.checks.office import OfficeRow, office_rows
from foundation_calc.checks.outcomes import Outcome, worst
from foundation_calc.checks.resonance.report import ResonanceRow, condition_label, modes_resonances
from foundation_calc.solvers.block.response import (
    BlockModes,
    PointMotion,
    block_modes,
    consistent_modes,
    point_motion,
    resonances,
    resonant,
)

DIRECTIONS = ("x", "y", "z")

#: Why a block has no steady state to judge.
NO_STEADY_STATE = "an order is resonant with an undamped mode: no steady state"


@dataclass(frozen=True)
class BlockReport(AmplitudeVerdict):
    """Everything ``fcalc resonance``, ``amplitudes`` and ``check`` say about a block scene: its
    amplitudes' common part (:mod:`~foundation_calc.checks.amplitudes.report`) judged on the machines'
    combined motion, and its modes, resonances and office checks."""

    modes: BlockModes
    speeds: dict
    resonant: bool
    motion: PointMotion | None
    office: tuple[OfficeRow, ...]
    total_mass: float
    cog: np.ndarray
    #: per machine with periodic inertia (cranks), the exact periodic solution's peaks and the first
    #: approximation's error (:class:`~foundation_calc.solvers.block.periodic_inertia.FirstApproximationError`)
    periodic: tuple = ()
    #: the solution that ``motion`` holds and the limits judge, by the crank report's names:
    #: ``"first_approximation"``, or ``"exact"`` (``fcalc amplitudes --exact``: every machine with
    #: periodic inertia by its exact periodic solution)
    checked: str = "first_approximation"

    @property
    def office_outcome(self) -> Outcome:
        return worst(r.outcome for r in self.office)

    @property
    def wording(self) -> AmplitudeWording:
        """How ``fcalc check`` states this report (:class:`~foundation_calc.checks.limits.AmplitudeWording`):
        no steady state when an order is resonant, no speed of its own (each machine has one)."""
        return AmplitudeWording(resonant=(NO_STEADY_STATE,))

    @property
    def no_steady_state(self) -> str:
        """Why there is no steady state to judge (when ``resonant``)."""
        return NO_STEADY_STATE

    @property
    def nearest(self) -> ResonanceRow:
        """The governing resonance row (the rule's governing condition)."""
        return self.resonance.governing


#: Limited quantity -> the :class:`~foundation_calc.solvers.block.response.PointMotion` field that holds it.
LIMITED_VALUES = {
    "displacement": "peak",
    "velocity": "velocity_peak",
    "displacement_rms": "displacement_rms",
    "velocity_rms": "velocity_rms",
    "acceleration": "acceleration_peak",
    "acceleration_rms": "acceleration_rms",
}


#: [scene, its report, the report with the machines' periodic solution, the report judged with it
#: (None until asked)] of the last scene :func:`check_block` judged: ``fcalc check`` asks for the
#: same scene's report three times (resonance, amplitudes, office findings), and a scene is frozen.
_LAST: list = []


def check_block(scene, periodic: bool = False, exact: bool = False) -> BlockReport:
    """Modes, resonance margins, steady state, limits, code zones and office checks of a
    ``block_foundation`` scene; with ``soil.modulus_range`` the resonances and amplitudes also over
    that range (module docstring); with ``periodic`` the exact periodic solution of the machines with
    periodic inertia and the first approximation's error (:mod:`~foundation_calc.checks.amplitudes.periodic`);
    with ``exact`` also the limits, the code's zones and the verdict judged with that solution in
    place of those machines' first approximation (the soil's modulus range keeps the first
    approximation, as a crank scene's does). The same scene object asked again gets the same report."""
    if not _LAST or _LAST[0] is not scene:
        _LAST[:] = [scene, _check_block(scene), None, None]
    if not (periodic or exact):
        return _LAST[1]
    if _LAST[2] is None:
        _LAST[2:] = _with_periodic(scene, _LAST[1])
    return _LAST[3] if exact else _LAST[2]


def _with_periodic(scene, report: BlockReport) -> tuple[BlockReport, BlockReport]:
    """``report`` with its machines' exact periodic solution (:func:`check_block`'s ``periodic``),
    and that report judged with it (``exact``; the same report without a machine with periodic
    inertia or without a steady state)."""
    if report.motion is None or not any(m.periodic_parts for m in scene.machines):
        return report, report
    from foundation_calc.checks.amplitudes.periodic import exact_motion, periodic_errors, periodic_solutions

    model, impedance = scene.stable_model(), scene_impedance(scene)
    solutions = periodic_solutions(scene, model, impedance)
    shown = replace(report, periodic=periodic_errors(scene, model, impedance, solutions))
    motion = exact_motion(scene, model, impedance, solutions)
    judged = _judged(scene, report.modes, model.cog, scene.excitations(), motion)
    return shown, replace(shown, motion=motion, judgement=judged, checked="exact")


def _check_block(scene) -> BlockReport:
    """:func:`check_block` without the periodic solution, evaluated."""
    from dataclasses import replace

    from foundation_calc.checks.soil_validity import block_validity

    report = check_block_as_given(scene)
    validity = block_validity(scene, report)
    report = replace(report, soil_validity=validity, resonance=replace(report.resonance, soil_validity=validity))
    if getattr(scene.soil, "modulus_range", None) is None:  # none on isolators
        return report
    from foundation_calc.checks.soil_range import amplitudes_over_range, resonance_point, resonances_over_range

    # the resonance and amplitude grids share factors (the ends, 1, the crossings): each soil once
    reports: dict = {}

    def at_factor(factored):
        key = factored.soil.model_dump_json()
        if key not in reports:
            reports[key] = check_block_as_given(factored)
        return reports[key]

    resonance = resonances_over_range(scene, at_factor, lambda f, r: resonance_point(f, r.resonance),
                                      lambda r: r.resonance.offsets())
    amplitude = amplitudes_over_range(scene, at_factor, resonance.crossings)
    return replace(report, resonance=replace(report.resonance, modulus_range=resonance), amplitude_range=amplitude)


def scene_modes(scene, model) -> tuple[BlockModes, object]:
    """The modes of a block scene's ``model`` and its soil's impedance (None on a
    frequency-independent soil): on a frequency-dependent soil each mode at its own frequency
    (:func:`~foundation_calc.solvers.block.response.consistent_modes`). Every command takes the
    scene's modes from here (resonance, amplitudes, sweep, run-up), so they are one set."""
    impedance = scene_impedance(scene)
    return (block_modes(model) if impedance is None else consistent_modes(model, impedance)), impedance


def scene_impedance(scene):
    """A block scene's support's impedance ω -> springs and dashpots at O (:meth:`soil_impedance` of
    the scene), None when its springs do not depend on frequency."""
    return scene.soil_impedance if scene.support().frequency_dependent else None


def check_block_as_given(scene) -> BlockReport:
    """:func:`check_block` with the soil data as given (no ``modulus_range``)."""
    model = scene.stable_model()
    excitations = scene.excitations()
    modes, impedance = scene_modes(scene, model)
    resonance = replace(modes_resonances(modes, excitations, scene.limits.detuning), total_mass=model.mass, cog=model.cog)
    stuck = any(resonant(modes, resonances(modes, exc)) for exc in excitations)
    motion = None if stuck else point_motion(model, excitations, [p.name for p in scene.points], [p.at for p in scene.points],
                                             impedance=impedance)
    return BlockReport(
        modes=modes,
        speeds={exc.name: exc.omega for exc in excitations},
        resonance=resonance,
        resonant=stuck,
        motion=motion,
        judgement=_judged(scene, modes, model.cog, excitations, motion),
        office=office_rows(scene, model),
        total_mass=model.mass,
        cog=model.cog,
    )


def _judged(scene, modes: BlockModes, cog, excitations, motion: PointMotion | None):
    """The limit rows, the code's zone rows and warnings of ``motion`` (None: no steady state) of a
    block scene with its ``modes`` and centre of mass ``cog`` [m]
    (:func:`~foundation_calc.checks.amplitudes.report.judge`)."""
    limits = scene.limits
    supports = None
    if limits.code is not None:
        from foundation_calc.checks.support import block_supports

        supports = block_supports(scene, modes, cog)
    values = None if motion is None else (lambda quantity: getattr(motion, LIMITED_VALUES[quantity]))
    return judge(None if motion is None else motion.names, DIRECTIONS, values, limits,
                 [(exc.name, exc.omega) for exc in excitations], supports)


__all__ = ["LIMITED_VALUES", "BlockReport", "ResonanceRow", "check_block",
           "check_block_as_given", "condition_label", "scene_impedance", "scene_modes"]
