"""A crank mechanism's section of the amplitude check (``fcalc amplitudes`` of a crank scene): the
approximations of its foundation's periodic steady state, judged by the rules of every kind
(:func:`~foundation_calc.checks.amplitudes.report.judge`).

Three approximations of the same periodic steady state are computed for one design:

- ``first_approximation``: the paper's corrected first approximation (always reported);
- ``averaged_operator``: the closed form with the mechanism's time-averaged operator and the
  exact zero-order forcing;
- ``exact``: harmonic balance of the exact equations (only when asked; it is the reference for
  the closed forms' errors).

The limits are checked with the best approximation computed (exact, else averaged operator),
for the centre of mass C and every point of the scene, horizontally and vertically. With base
dashpots every approximation is finite at and through every resonance and is judged on its
amplitudes; an undamped speed within a hair of a resonance of the checked approximation fails as
"resonant" with its margin. The resonance verdict itself (which condition governs, its margin)
is the rule's (:mod:`~foundation_calc.checks.resonance.rule`), reported beside the amplitudes.
"""

from __future__ import annotations

from dataclasses import dataclass, field, replace

import numpy as np

from foundation_calc.checks.amplitudes.report import AmplitudeVerdict, Judgement, judge
from foundation_calc.checks.limits import QUANTITIES, AmplitudeWording
from foundation_calc.checks.resonance.report import ResonanceReport, check_block_resonances, check_resonances
from foundation_calc.errors import NotApplicable
from foundation_calc.solvers.crank.averaged import averaged_response
from foundation_calc.solvers.crank.closed_form import COUPLED_SUPPORT, design_first_approximation
from foundation_calc.solvers.crank.first_approximation import RESONANT_MARGIN
from foundation_calc.solvers.crank.loads import HarmonicLoads, RigidBlock, load_conditions, loads_response
from foundation_calc.solvers.crank.mechanism import CrankDesign
from foundation_calc.solvers.crank.natural import design_frequencies
from foundation_calc.solvers.crank.response import (
    DIRECTIONS,
    DOFS,
    PeriodicMotion,
    Peaks,
    located,
    motion_peaks,
    relative_error,
    splice_harmonics,
    superpose,
)

#: The detuning band of a check called without a scene's [limits] (the scene's default) [-].
DEFAULT_DETUNING = 0.2

#: Harmonics whose coefficients are reported and compared (dof, n).
HARMONICS = (("y", 1), ("y", 2), ("y", 3), ("y", 4), ("x", 1), ("x", 2), ("x", 3), ("theta", 1), ("theta", 2), ("theta", 3))

TITLES = {
    "first_approximation": "paper's first approximation, corrected (Eqs. 4.11-4.14)",
    "averaged_operator": "closed form: averaged operator, exact forcing",
    "exact": "exact periodic solution (harmonic balance)",
    "loads": "vendor loads: linear steady state of the block (K - n²ω²M + i nωC) Z = F",
}

#: Why the paper's first approximation is left out of a design on a support coupling sway with rocking.
FIRST_NOT_APPLICABLE = f"not applicable: {COUPLED_SUPPORT}"

#: Appended to the title of a mechanism's approximation when the scene's [[loads]] are added to it.
WITH_LOADS = " + vendor loads (linear)"


@dataclass(frozen=True)
class Approximation:
    """One approximation of the steady state.

    ``motion`` is None when ``resonant``; ``peaks`` has x, y, θ on its arrays' last axis;
    ``points`` maps "C" and each scene point to its (horizontal, vertical) peaks, ``rms`` to its
    (horizontal, vertical) RMS values.
    """

    key: str
    motion: PeriodicMotion | None
    resonant: bool
    margin: float
    nearest: str
    peaks: Peaks | None
    points: dict
    rms: dict
    with_loads: bool = False

    @property
    def title(self) -> str:
        return TITLES[self.key] + (WITH_LOADS if self.with_loads and self.key != "loads" else "")

    def harmonic(self, dof: str, n: int) -> complex:
        """Complex coefficient cos - i sin of harmonic n of ``dof`` (0 when absent)."""
        c, s = self.motion.coefficient(dof, n)
        return complex(c) - 1j * complex(s)

    def phase(self, dof: str, n: int) -> float:
        """Phase lag φ [rad] of harmonic n of ``dof``: the harmonic is A cos(nωt - φ), φ in (-π, π]."""
        c, s = self.motion.coefficient(dof, n)
        return float(np.arctan2(float(s), float(c)))


@dataclass(frozen=True)
class ExactInfo:
    """How the exact solution was reached; ``capped``: the solver's message when the harmonic cap
    left ``harmonic_change`` above its tolerance (the solution is then good to about that)."""

    harmonics: int
    newton_iterations: int
    harmonic_change: float
    residual: float
    seconds: float
    capped: str | None = None


@dataclass(frozen=True)
class VendorLoads:
    """A scene's ``[[loads]]`` with the block they act on and the speed ω [rad/s]."""

    block: RigidBlock
    loads: HarmonicLoads
    omega: float


@dataclass(frozen=True)
class Damping:
    """The base dashpots of a design and the modal damping ratios they give.

    ``dashpots``: C_x [N s/m], C_z [N s/m], C_phi [N m s/rad] and, on a support coupling sway with
    rocking, C_xphi [N s/rad]; ``natural``: natural frequencies of
    the averaged operator [rad/s], ascending; ``modal_ratios``: each mode's damping ratio [-].
    """

    dashpots: dict
    natural: tuple[float, ...]
    modal_ratios: tuple[float, ...]


@dataclass(frozen=True)
class AmplitudeReport(AmplitudeVerdict):
    """A crank scene's amplitude report: the common part (:mod:`~foundation_calc.checks.amplitudes.report`)
    judged on the ``checked`` approximation, and the approximations themselves. ``design`` is None
    for a machine given by its loads only (``vendor`` then holds them)."""

    design: CrankDesign | None
    approximations: dict
    checked: str
    exact_info: ExactInfo | None
    errors: dict | None
    damping: Damping | None = None
    vendor: VendorLoads | None = None
    #: approximation key -> why it is not computed for this design (:data:`FIRST_NOT_APPLICABLE`; a
    #: harmonic's soil where the first approximation does not apply,
    #: :func:`~foundation_calc.solvers.crank.closed_form.require_first_approximation`)
    not_applicable: dict = field(default_factory=dict)

    @property
    def omega(self) -> float:
        """The speed [rad/s]."""
        return self.design.omega if self.design is not None else self.vendor.omega

    @property
    def damped(self) -> bool:
        """The design has base dashpots: its response is finite at every resonance."""
        return self.damping is not None

    @property
    def resonant(self) -> bool:
        return self.approximations[self.checked].resonant

    @property
    def no_steady_state(self) -> str:
        """Why there is no steady state to judge (when ``resonant``): the checked approximation's nearest resonance."""
        return f"resonant ({self.approximations[self.checked].nearest}): no steady state"

    @property
    def wording(self) -> AmplitudeWording:
        """How ``fcalc check`` states this report (:class:`~foundation_calc.checks.limits.AmplitudeWording`):
        the speed first, resonant with the checked approximation's nearest resonance and its margin,
        the resonance rule's statement after the limits, itemised."""
        approx = self.approximations[self.checked]
        speed = ("speed", self.omega)
        return AmplitudeWording(
            resonant=("speed ", speed, f" is resonant ({approx.nearest}, margin {approx.margin:.2%}): no steady state"),
            values={"speed": speed}, statement=None if self.resonance is None else self.resonance.statement, itemised=True,
        )


@dataclass(frozen=True)
class _LoadsPart:
    """The loads' steady state, added to each approximation of a mechanism (linear superposition)."""

    motion: PeriodicMotion
    resonant: bool
    margin: float
    nearest: str


def _loads_part(vendor: VendorLoads) -> _LoadsPart:
    res = loads_response(vendor.block, vendor.omega, vendor.loads)
    n, mode, _ = load_conditions(vendor.loads)[int(res.nearest)]
    label = f"{n if n > 1 else ''}ω = {mode} (loads)"
    return _LoadsPart(res.motion, bool(res.resonant), float(res.margin), label)


def _approximation(key, motion, resonant, margin, nearest, points, loads: _LoadsPart | None = None) -> Approximation:
    if loads is not None:
        if loads.margin < margin:
            margin, nearest = loads.margin, loads.nearest
        resonant = resonant or loads.resonant
        if not resonant:
            motion = loads.motion if motion is None else superpose(motion, loads.motion)
    with_loads = loads is not None
    if resonant:
        return Approximation(key, None, True, margin, nearest, None, {}, {}, with_loads)
    return Approximation(key, motion, False, margin, nearest, motion_peaks(motion), *located(motion, points), with_loads)


def _first(design: CrankDesign, points, loads=None) -> Approximation:
    fa = design_first_approximation(design)
    label = min(fa.margins, key=lambda k: fa.margins[k])
    return _approximation(
        "first_approximation", fa.motion(design.omega), bool(fa.resonant), float(fa.margins[label]), label, points,
        loads,
    )


def _averaged(design: CrankDesign, points, loads=None) -> tuple[Approximation, Damping | None]:
    res = averaged_response(design)
    n, mode = res.nearest
    w = float(res.natural[mode])
    zero, _ = design_frequencies(design)  # name the averaged mode after the nearest k0, p1, p2
    name = min(("k0", "p1", "p2"), key=lambda k: abs(float(getattr(zero, k)) - w))
    label = f"{n if n > 1 else ''}ω = {name} ({w:.6g} rad/s with the averaged operator)"
    damping = None
    dashpots = {"C_x": float(design.C_x), "C_z": float(design.C_z), "C_phi": float(design.C_phi)}
    if design.C_xphi != 0.0:  # a support coupling sway with rocking (a pile group) damps that pair too
        dashpots["C_xphi"] = float(design.C_xphi)
    if any(value > 0.0 for value in dashpots.values()):
        damping = Damping(dashpots, tuple(map(float, res.natural)), tuple(map(float, res.damping_ratios)))
    return _approximation("averaged_operator", res.motion, res.resonant, res.margin, label, points, loads), damping


def _errors(approx: Approximation, exact: Approximation) -> dict | None:
    """Relative errors of ``approx`` against ``exact``: per harmonic and per peak."""
    if approx.resonant:
        return None
    harmonics = {
        f"{dof}{n}": float(relative_error(approx.harmonic(dof, n), exact.harmonic(dof, n))) for dof, n in HARMONICS
    }
    peaks = {
        q: {dof: float(relative_error(getattr(approx.peaks, q)[i], getattr(exact.peaks, q)[i])) for i, dof in enumerate(DOFS)}
        for q in QUANTITIES
    }
    points = {name: {} for name in approx.points}
    for q in QUANTITIES:  # every point at once: (points, directions) arrays
        errors = relative_error(_stacked(approx.points, q), _stacked(exact.points, q)).tolist()
        for row, name in zip(errors, points):
            points[name][q] = dict(zip(DIRECTIONS, row))
    return {"harmonics": harmonics, "peaks": peaks, "points": points}


def _stacked(by_point: dict, quantity: str) -> np.ndarray:
    """``quantity`` of C and every point (peaks or RMS values), shape (points, directions)."""
    return np.array([getattr(values, quantity) for values in by_point.values()])


def _judged(approx: Approximation, limits, omega: float, supports=None) -> Judgement:
    """The limit rows, zone rows and code warnings of C and every point of ``approx``
    (:func:`~foundation_calc.checks.amplitudes.report.judge`; ``supports``: point name -> (horizontal,
    vertical) :class:`~foundation_calc.checks.support.SupportClass`, as :func:`scene_supports` gives
    them; None: the scene's ``limits.foundation`` everywhere)."""

    def values(quantity):
        return _stacked(approx.rms, quantity[:-4]) if quantity.endswith("_rms") else _stacked(approx.points, quantity)

    return judge(list(approx.points), DIRECTIONS, None if approx.resonant else values, limits, [(None, omega)], supports)


def scene_supports(scene):
    """The support class of every point and direction of a ``crank_foundation`` scene with a
    vibration code (:func:`~foundation_calc.checks.support.crank_supports`, from the block's modes
    k0, p1, p2, each at its own frequency on a frequency-dependent soil; on a support coupling sway
    with rocking, a pile group, the one model's modes as the resonance check reports them); None
    without a code."""
    if getattr(scene.limits, "code", None) is None:
        return None
    from foundation_calc.checks.support import crank_supports

    design = None if scene.mechanism is None else scene.design()
    if design is not None and design.coupled:
        from foundation_calc.checks.resonance.frequencies import scene_design_frequencies
        from foundation_calc.solvers.crank.natural import design_frequencies

        consistent = scene_design_frequencies(scene)
        return crank_supports(scene, design_frequencies(design)[1] if consistent is None else consistent[1])
    from foundation_calc.checks.resonance.frequencies import scene_block_frequencies
    from foundation_calc.solvers.crank.loads import block_frequencies

    consistent = scene_block_frequencies(scene)
    return crank_supports(scene, block_frequencies(scene.block()) if consistent is None else consistent[0])


def check_amplitudes(
    design: CrankDesign | None, limits, points, exact: bool = False, vendor: VendorLoads | None = None, supports=None,
    resonance: ResonanceReport | None = None,
) -> AmplitudeReport:
    """Amplitudes of ``design`` by every approximation asked for, and the limit rows.

    ``limits``: the scene's ``[limits]`` (peak and RMS limits [m, m/s, m/s²], a code) or None;
    ``points``: objects with ``name``, ``horizontal``, ``height`` [m]. ``vendor``: the scene's
    ``[[loads]]``, whose linear steady state is added to every approximation of the mechanism,
    or is the only one (``"loads"``) when ``design`` is None. ``supports``: the code's support
    class of every point and direction (:func:`scene_supports`), None for ``limits.foundation``.
    ``resonance``: the resonance report to give, None for the design's own (a design on a
    frequency-dependent support's springs at a harmonic is given its scene's, every mode at its own
    frequency, :func:`~foundation_calc.checks.resonance.scene_resonances_as_given`).
    The first approximation steps aside where it does not apply
    (:func:`~foundation_calc.solvers.crank.closed_form.require_first_approximation`: a support
    coupling sway with rocking, a harmonic's soil whose rocking spring does not exceed P h), the
    report saying why (``not_applicable``); the averaged operator, which is judged, applies.

    Raises
    ------
    PhysicsError
        unstable rocking.
    ConvergenceError
        ``exact`` and the harmonic balance fails (away from the averaged operator's resonances).
    """
    loads = None if vendor is None else _loads_part(vendor)
    info = errors = None
    damping = None
    not_applicable = {}
    if design is None:
        approximations = {"loads": _approximation("loads", None, False, loads.margin, loads.nearest, points, loads)}
        checked = "loads"
        omega = vendor.omega
    else:
        omega = design.omega
        averaged, damping = _averaged(design, points, loads)
        try:
            approximations = {"first_approximation": _first(design, points, loads), "averaged_operator": averaged}
        except NotApplicable as why:  # a coupled support, a harmonic's soil: the closed form steps aside
            approximations, not_applicable = {"averaged_operator": averaged}, {"first_approximation": f"not applicable: {why.message}"}
        checked = "averaged_operator"
    if design is not None and exact and not approximations["averaged_operator"].resonant:
        import time

        from foundation_calc.solvers.crank.exact import HarmonicCapReached, exact_periodic_solution

        start = time.perf_counter()
        capped = None
        try:
            sol = exact_periodic_solution(design)
        except HarmonicCapReached as cap:
            sol, capped = cap.solution, str(cap)
        seconds = time.perf_counter() - start
        info = ExactInfo(sol.harmonics, sol.newton_iterations, sol.harmonic_change, sol.residual, seconds, capped)
        averaged = approximations["averaged_operator"]
        approximations["exact"] = _approximation("exact", sol.motion, False, averaged.margin, averaged.nearest, points, loads)
        checked = "exact"
        errors = {
            key: _errors(approximations[key], approximations["exact"])
            for key in ("first_approximation", "averaged_operator") if key in approximations
        }
    detuning = getattr(limits, "detuning", DEFAULT_DETUNING)
    if resonance is None:
        resonance = (check_block_resonances(vendor.block, vendor.omega, vendor.loads, detuning) if design is None else
                     check_resonances(design, detuning, None if vendor is None else vendor.loads))
    return AmplitudeReport(
        design=design,
        approximations=approximations,
        checked=checked,
        exact_info=info,
        errors=errors,
        damping=damping,
        vendor=vendor,
        resonance=resonance,
        not_applicable=not_applicable,
        judgement=_judged(approximations[checked], limits, omega, supports),
    )


def scene_vendor_loads(scene, soil_frequency: float = 0.0) -> VendorLoads | None:
    """The scene's ``[[loads]]`` as a :class:`VendorLoads`, None without loads; a
    frequency-dependent soil takes its springs at ``soil_frequency`` [rad/s]."""
    loads = scene.harmonic_loads()
    return None if loads is None else VendorLoads(scene.block(soil_frequency), loads, scene.speed.omega_rad_s)


def _at_soil_frequency(scene, soil_frequency: float, exact: bool, supports=None, resonance=None) -> AmplitudeReport:
    design = None if scene.mechanism is None else scene.design(soil_frequency)
    return check_amplitudes(design, scene.limits, scene.points, exact=exact,
                            vendor=scene_vendor_loads(scene, soil_frequency), supports=supports, resonance=resonance)


def check_scene_amplitudes(scene, exact: bool = False) -> AmplitudeReport:
    """:func:`check_amplitudes` of a ``crank_foundation`` scene: its mechanism, its loads or both;
    with ``soil.modulus_range`` also over that range (:func:`~foundation_calc.checks.soil_range.amplitudes_over_range`;
    the verdict is the worse of the two); the soil model's validity at the modes and judged orders
    (:func:`~foundation_calc.checks.soil_validity.crank_validity`).
    """
    from foundation_calc.checks.soil_validity import crank_validity

    report = _scene_amplitudes(scene, exact)
    report = replace(report, soil_validity=crank_validity(scene, report.resonance))
    if scene.soil.modulus_range is None:
        return report
    from foundation_calc.checks.resonance import check_scene_resonances
    from foundation_calc.checks.soil_range import amplitudes_over_range

    crossings = check_scene_resonances(scene).modulus_range.crossings
    return replace(report, amplitude_range=amplitudes_over_range(scene, _scene_amplitudes, crossings))


def _scene_amplitudes(scene, exact: bool = False) -> AmplitudeReport:
    """The amplitudes of ``scene`` with its soil data as given.

    On a frequency-dependent support (its ``frequency_dependent``) every harmonic n of the closed
    forms (first approximation, averaged operator, loads) is solved with the springs and dashpots
    at its own frequency n ω (:func:`splice_harmonics`; the mean, n = 0, on the static springs);
    the exact harmonic balance, which couples the harmonics, takes them at the speed ω. Where the
    first approximation does not apply at a harmonic n it has (n <= 3: its rocking spring K_φ(nω)
    does not exceed P h there), it is left out with the reason (``not_applicable``), the others kept.
    """
    omega = scene.speed.omega_rad_s
    supports, dependent = scene_supports(scene), scene.support().frequency_dependent
    if not dependent:
        return _at_soil_frequency(scene, 0.0, exact, supports)
    from foundation_calc.checks.resonance import scene_resonances_as_given

    resonance = scene_resonances_as_given(scene)  # every mode at its own frequency, not at a harmonic's
    base = _at_soil_frequency(scene, omega, exact, supports, resonance)
    live = {key: a for key, a in base.approximations.items() if key != "exact" and not a.resonant}
    width = max((a.motion.cos.shape[-1] for a in live.values()), default=0)
    by_n = [base if n == 1 else _at_soil_frequency(scene, n * omega, False, supports, resonance) for n in range(width)]
    approximations, not_applicable = dict(base.approximations), dict(base.not_applicable)
    for key, a in live.items():
        used = by_n[: a.motion.cos.shape[-1]]  # the harmonics the approximation has
        why = next((r.not_applicable[key] for r in used if key in r.not_applicable), None)
        if why is not None:
            del approximations[key]
            not_applicable[key] = why
            continue
        if any(r.approximations[key].resonant for r in by_n if key in r.approximations):
            continue
        motion = splice_harmonics([r.approximations[key].motion for r in used])
        approximations[key] = _approximation(key, motion, False, a.margin, a.nearest, scene.points)
    return replace(base, approximations=approximations, not_applicable=not_applicable,
                   judgement=_judged(approximations[base.checked], scene.limits, omega, supports))


__all__ = [
    "FIRST_NOT_APPLICABLE",
    "RESONANT_MARGIN",
    "AmplitudeReport",
    "Approximation",
    "Damping",
    "VendorLoads",
    "check_amplitudes",
    "check_scene_amplitudes",
    "scene_supports",
    "scene_vendor_loads",
]
