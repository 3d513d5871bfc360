"""Forced amplitudes of a crank-mechanism foundation and their check against the scene's limits.

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
"resonant" with its margin.
"""

from __future__ import annotations

from dataclasses import dataclass

import numpy as np

from foundation_calc.checks.crank_resonance import design_frequencies
from foundation_calc.checks.limits import QUANTITIES, exceeds, limited_quantities
from foundation_calc.checks.outcomes import Outcome, worst
from foundation_calc.solvers.crank.averaged import averaged_response
from foundation_calc.solvers.crank.closed_form import design_first_approximation
from foundation_calc.solvers.crank.first_approximation import RESONANT_MARGIN
from foundation_calc.solvers.crank.mechanism import CrankDesign
from foundation_calc.solvers.crank.response import (
    DIRECTIONS,
    DOFS,
    PeriodicMotion,
    Peaks,
    motion_peaks,
    point_peaks,
    relative_error,
)

#: Harmonics whose coefficients are reported and compared (dof, n).
HARMONICS = (("y", 1), ("y", 2), ("y", 3), ("y", 4), ("x", 1), ("x", 2), ("x", 3), ("theta", 1), ("theta", 2), ("theta", 3))

TITLES = {
    "first_approximation": "paper's first approximation, corrected (Eqs. 4.11-4.14)",
    "averaged_operator": "closed form: averaged operator, exact forcing",
    "exact": "exact periodic solution (harmonic balance)",
}


@dataclass(frozen=True)
class Approximation:
    """One approximation of the steady state.

    ``motion`` is None when ``resonant``; ``peaks`` has x, y, θ on its arrays' last axis;
    ``points`` maps "C" and each scene point to its (horizontal, vertical) peaks.
    """

    key: str
    motion: PeriodicMotion | None
    resonant: bool
    margin: float
    nearest: str
    peaks: Peaks | None
    points: dict

    @property
    def title(self) -> str:
        return TITLES[self.key]

    def harmonic(self, dof: str, n: int) -> complex:
        """Complex coefficient cos - i sin of harmonic n of ``dof`` (0 when absent)."""
        c, s = self.motion.coefficient(dof, n)
        return complex(c) - 1j * complex(s)

    def phase(self, dof: str, n: int) -> float:
        """Phase lag φ [rad] of harmonic n of ``dof``: the harmonic is A cos(nωt - φ), φ in (-π, π]."""
        c, s = self.motion.coefficient(dof, n)
        return float(np.arctan2(float(s), float(c)))


@dataclass(frozen=True)
class LimitRow:
    """A peak of one point, direction and quantity against its limit (SI units)."""

    point: str
    direction: str
    quantity: str
    value: float
    limit: float
    outcome: Outcome

    @property
    def ratio(self) -> float:
        return self.value / self.limit


@dataclass(frozen=True)
class ExactInfo:
    """How the exact solution was reached."""

    harmonics: int
    newton_iterations: int
    harmonic_change: float
    residual: float
    seconds: float


@dataclass(frozen=True)
class Damping:
    """The base dashpots of a design and the modal damping ratios they give.

    ``dashpots``: C_x [N s/m], C_z [N s/m], C_phi [N m s/rad]; ``natural``: natural frequencies of
    the averaged operator [rad/s], ascending; ``modal_ratios``: each mode's damping ratio [-].
    """

    dashpots: dict
    natural: tuple[float, ...]
    modal_ratios: tuple[float, ...]


@dataclass(frozen=True)
class AmplitudeReport:
    design: CrankDesign
    approximations: dict
    checked: str
    rows: tuple[LimitRow, ...]
    exact_info: ExactInfo | None
    errors: dict | None
    damping: Damping | None

    @property
    def damped(self) -> bool:
        """The design has base dashpots: its response is finite at every resonance."""
        return self.damping is not None

    @property
    def resonant(self) -> bool:
        return self.approximations[self.checked].resonant

    @property
    def outcome(self) -> Outcome:
        if self.resonant:
            return Outcome.FAIL
        return worst(row.outcome for row in self.rows)


#: Points evaluated in one array operation; bounds the memory of a scene with many points.
POINT_CHUNK = 1024


def _located(motion, points) -> dict[str, Peaks]:
    """Peaks of C and of every point, all points of a chunk in one array operation."""
    names = ["C", *(p.name for p in points)]
    horizontal = np.array([0.0, *(p.horizontal for p in points)])
    height = np.array([0.0, *(p.height for p in points)])
    located = {}
    for start in range(0, len(names), POINT_CHUNK):
        chunk = slice(start, start + POINT_CHUNK)
        pk = point_peaks(motion, horizontal[chunk], height[chunk])
        for i, name in enumerate(names[chunk]):
            located[name] = Peaks(pk.displacement[i], pk.velocity[i], pk.acceleration[i])
    return located


def _approximation(key, motion, resonant, margin, nearest, points) -> Approximation:
    if resonant:
        return Approximation(key, None, True, margin, nearest, None, {})
    return Approximation(key, motion, False, margin, nearest, motion_peaks(motion), _located(motion, points))


def _first(design: CrankDesign, points) -> Approximation:
    fa = design_first_approximation(design)
    label = min(fa.margins, key=lambda k: fa.margins[k])
    return _approximation(
        "first_approximation", fa.motion(design.omega), bool(fa.resonant), float(fa.margins[label]), label, points
    )


def _averaged(design: CrankDesign, points) -> tuple[Approximation, Damping | None]:
    res = averaged_response(design)
    n, mode = res.nearest
    w = float(res.natural[mode])
    zero, _ = design_frequencies(design)  # name the averaged mode after the nearest k0, p1, p2
    name = min(("k0", "p1", "p2"), key=lambda k: abs(float(getattr(zero, k)) - w))
    label = f"{n if n > 1 else ''}ω = {name} ({w:.6g} rad/s with the averaged operator)"
    damping = None
    dashpots = {"C_x": float(design.C_x), "C_z": float(design.C_z), "C_phi": float(design.C_phi)}
    if any(value > 0.0 for value in dashpots.values()):
        damping = Damping(dashpots, tuple(map(float, res.natural)), tuple(map(float, res.damping_ratios)))
    return _approximation("averaged_operator", res.motion, res.resonant, res.margin, label, points), damping


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
    points = {
        name: {
            q: {
                d: float(relative_error(getattr(pk, q)[i], getattr(exact.points[name], q)[i]))
                for i, d in enumerate(DIRECTIONS)
            }
            for q in QUANTITIES
        }
        for name, pk in approx.points.items()
    }
    return {"harmonics": harmonics, "peaks": peaks, "points": points}


def _rows(approx: Approximation, limits) -> tuple[LimitRow, ...]:
    rows = []
    if approx.resonant:
        return ()
    for quantity, limit in limited_quantities(limits).items():
        for name, pk in approx.points.items():
            for i, direction in enumerate(DIRECTIONS):
                value = float(getattr(pk, quantity)[i])
                outcome = Outcome.FAIL if exceeds(value, limit) else Outcome.PASS
                rows.append(LimitRow(name, direction, quantity, value, limit, outcome))
    return tuple(rows)


def check_amplitudes(design: CrankDesign, limits, points, exact: bool = False) -> AmplitudeReport:
    """Amplitudes of ``design`` by every approximation asked for, and the limit rows.

    ``limits``: an object with ``amplitude``, ``velocity``, ``acceleration`` [m, m/s, m/s²] or
    None; ``points``: objects with ``name``, ``horizontal``, ``height`` [m].

    Raises
    ------
    PhysicsError
        unstable rocking.
    ConvergenceError
        ``exact`` and the harmonic balance fails (away from the averaged operator's resonances).
    """
    averaged, damping = _averaged(design, points)
    approximations = {"first_approximation": _first(design, points), "averaged_operator": averaged}
    checked = "averaged_operator"
    info = errors = None
    if exact and not approximations["averaged_operator"].resonant:
        import time

        from foundation_calc.solvers.crank.exact import exact_periodic_solution

        start = time.perf_counter()
        sol = exact_periodic_solution(design)
        seconds = time.perf_counter() - start
        info = ExactInfo(sol.harmonics, sol.newton_iterations, sol.harmonic_change, sol.residual, seconds)
        averaged = approximations["averaged_operator"]
        approximations["exact"] = _approximation("exact", sol.motion, False, averaged.margin, averaged.nearest, points)
        checked = "exact"
        errors = {
            key: _errors(approximations[key], approximations["exact"])
            for key in ("first_approximation", "averaged_operator")
        }
    return AmplitudeReport(
        design=design,
        approximations=approximations,
        checked=checked,
        rows=_rows(approximations[checked], limits),
        exact_info=info,
        errors=errors,
        damping=damping,
    )


__all__ = ["RESONANT_MARGIN", "AmplitudeReport", "Approximation", "Damping", "LimitRow", "check_amplitudes"]
