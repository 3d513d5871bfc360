"""Forced amplitudes of a crank-mechanism foundation and their check against the scene's limits.

Three approximations of the same periodic steady state are computed for one design:

- ``first_approximation``: the paper's corrected first approximation (always reported);
- ``averaged_operator``: the closed form with the mechanism's time-averaged operator and the
  exact zero-order forcing;
- ``exact``: harmonic balance of the exact equations (only when asked; it is the reference for
  the closed forms' errors).

The limits are checked with the best approximation computed (exact, else averaged operator),
for the centre of mass C and every point of the scene, horizontally and vertically. A speed
within a hair of a resonance of the checked approximation fails as "resonant" with its margin.
"""

from __future__ import annotations

from dataclasses import dataclass, fields

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
class AmplitudeReport:
    design: CrankDesign
    approximations: dict
    checked: str
    rows: tuple[LimitRow, ...]
    exact_info: ExactInfo | None
    errors: dict | None

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
    chunks = [point_peaks(motion, horizontal[i : i + POINT_CHUNK], height[i : i + POINT_CHUNK])
              for i in range(0, len(names), POINT_CHUNK)]
    arrays = {f.name: np.concatenate([getattr(pk, f.name) for pk in chunks]) for f in fields(Peaks)}
    return {name: Peaks(**{q: values[i] for q, values in arrays.items()}) for i, name in enumerate(names)}


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


def _averaged(design: CrankDesign, points) -> Approximation:
    res = averaged_response(design)
    n, mode = res.nearest
    w = float(res.natural[mode])
    zero, _ = design_frequencies(design)  # name the averaged mode after the nearest k0, p1, p2
    name = min(("k0", "p1", "p2"), key=lambda k: abs(float(getattr(zero, k)) - w))
    label = f"{n if n > 1 else ''}ω = {name} ({w:.6g} rad/s with the averaged operator)"
    return _approximation("averaged_operator", res.motion, res.resonant, res.margin, label, points)


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
        errors = relative_error(_stacked(approx, q), _stacked(exact, q)).tolist()
        for row, name in zip(errors, points):
            points[name][q] = dict(zip(DIRECTIONS, row))
    return {"harmonics": harmonics, "peaks": peaks, "points": points}


def _stacked(approx: Approximation, quantity: str) -> np.ndarray:
    """Peaks of ``quantity`` of C and every point, shape (points, directions)."""
    return np.array([getattr(pk, quantity) for pk in approx.points.values()])


def _rows(approx: Approximation, limits) -> tuple[LimitRow, ...]:
    if approx.resonant:
        return ()
    rows = []
    for quantity, limit in limited_quantities(limits).items():
        values = _stacked(approx, quantity)
        over = exceeds(values, limit).tolist()
        for name, value, fails in zip(approx.points, values.tolist(), over):
            rows += [
                LimitRow(name, direction, quantity, v, limit, Outcome.FAIL if f else Outcome.PASS)
                for direction, v, f in zip(DIRECTIONS, value, fails)
            ]
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
    approximations = {"first_approximation": _first(design, points), "averaged_operator": _averaged(design, points)}
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
    )


__all__ = ["RESONANT_MARGIN", "AmplitudeReport", "Approximation", "LimitRow", "check_amplitudes"]
