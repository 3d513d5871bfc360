"""A check over the soil's modulus range: it passes only if it passes at every stiffness in between.

ACI 351.3R-18 (4.2, 4.5) asks that the dynamic analysis bracket the soil's uncertain modulus
(commonly 0.5-1.5 × the best estimate, or the range of the site investigation) rather than trust
one value. A scene gives ``[soil] modulus_range = [low, high]``: factors on the soil's stiffness
data (:meth:`~foundation_calc.scenes.soil.Soil.factored`), from which every spring and dashpot is
recomputed. Two ends are not enough: a natural frequency moves through n ω somewhere inside the
range, and the verdict there is the worst. The check is evaluated on a geometric grid of
:data:`GRID_POINTS` factors (and the data as given, factor 1, when it lies inside) plus, for each
resonance condition whose critical speed crosses the operating speed between two grid points, the
factor at the crossing itself (found by Brent's method, where the margin is 0) when the resonance
rule judges that condition there (a harmonic with a negligible forcing share is information,
not a crossing). The verdict is the worst over all of them; the governing factor is the one that
gives it. The amplitude checks
(a steady-state solve per factor) take a coarser grid of :data:`AMPLITUDE_GRID_POINTS` factors
plus the resonance crossings, where the steady state peaks.
"""

from __future__ import annotations

import math
from dataclasses import dataclass

from foundation_calc.checks.outcomes import Outcome, worst

#: Factors of the grid over [low, high] (geometric: the frequencies go as sqrt(factor)).
GRID_POINTS = 41

#: Factors of the amplitude checks' grid (each a full steady-state solve), besides the crossings.
AMPLITUDE_GRID_POINTS = 17

_RANK = {Outcome.PASS: 0, Outcome.WARN: 1, Outcome.FAIL: 2}


@dataclass(frozen=True)
class RangePoint:
    """The check at one factor: its outcome, what decides it (``text``) and how close it comes to
    failing (``severity``, larger is worse: the limit ratio of an amplitude, required/margin of a
    resonance)."""

    factor: float
    outcome: Outcome
    text: str
    severity: float


@dataclass(frozen=True)
class ModulusRangeResult:
    """The check over ``[low, high]``: every factor evaluated and the governing one.

    ``crossings``: (factor, condition) where a critical speed equals the operating speed.
    """

    low: float
    high: float
    points: tuple[RangePoint, ...]
    crossings: tuple[tuple[float, str], ...]

    @property
    def outcome(self) -> Outcome:
        return worst(p.outcome for p in self.points)

    @property
    def governing(self) -> RangePoint:
        """The factor with the worst outcome and, among those, the highest severity."""
        return max(self.points, key=lambda p: (_RANK[p.outcome], p.severity))

    @property
    def text(self) -> str:
        """One line: the range, the verdict and the governing factor."""
        g = self.governing
        crossed = "; ".join(f"{label} crossed at factor {f:.4g}" for f, label in self.crossings)
        return (
            f"over the soil's modulus range [{self.low:g}, {self.high:g}] ({len(self.points)} factors): "
            f"{self.outcome.value.upper()}, governing factor {g.factor:.4g} ({g.text})" + (f"; {crossed}" if crossed else "")
        )

    def details(self) -> tuple[str, ...]:
        """One line per factor evaluated: ``"FAIL modulus factor 0.5: ..."``."""
        return tuple(f"{p.outcome.value.upper()} modulus factor {p.factor:.4g}: {p.text}" for p in self.points)

    def document(self) -> dict:
        """The JSON form (SI): every factor, the crossings and the governing factor."""
        g = self.governing
        return {
            "low": self.low, "high": self.high, "verdict": self.outcome.value,
            "governing_factor": g.factor, "governing": g.text,
            "crossings": [{"factor": f, "condition": label} for f, label in self.crossings],
            "factors": [{"factor": p.factor, "verdict": p.outcome.value, "governing": p.text} for p in self.points],
        }


def modulus_factors(low: float, high: float, n: int = GRID_POINTS) -> list[float]:
    """``n`` factors spaced geometrically over [low, high], with 1 added when it lies inside.

    >>> modulus_factors(0.5, 2.0, 3)
    [0.5, 1.0, 2.0]
    """
    if high == low:
        return [low]
    ratio = (high / low) ** (1.0 / (n - 1))
    grid = [low * ratio**i for i in range(n - 1)] + [high]
    if low < 1.0 < high and not any(math.isclose(f, 1.0) for f in grid):
        grid.append(1.0)
    return sorted(grid)


def resonance_point(factor: float, report) -> RangePoint:
    """A :class:`~foundation_calc.checks.resonance.report.ResonanceReport` at one factor: its governing
    condition, severity needed/margin."""
    g = report.governing
    if g is None:
        return RangePoint(factor, report.outcome, "no resonance condition to judge", 0.0)
    return RangePoint(factor, report.outcome, g.phrase, math.inf if g.margin <= 0.0 else g.needed / g.margin)


def resonance_offsets(report) -> dict[str, tuple[float, bool]]:
    """Condition -> (its critical speed less its machine's speed [rad/s], judged by the rule) of a
    :class:`~foundation_calc.checks.resonance.report.ResonanceReport`."""
    return report.offsets()


def worst_row_point(factor: float, outcome: Outcome, rows) -> RangePoint:
    """The amplitude check at one factor from its rows (limit rows, code-zone rows): the worst
    outcome and, among those, the highest ratio to its limit names it."""
    if not rows:
        return RangePoint(factor, outcome, "nothing judged", 0.0)
    row = max(rows, key=lambda r: (_RANK[r.outcome], r.ratio))
    name = getattr(row, "quantity", "r.m.s. velocity")
    return RangePoint(factor, outcome, f"{name} at {row.point} is {row.ratio:.0%} of its limit", float(row.ratio))


def amplitude_point(factor: float, report) -> RangePoint:
    """An amplitude report of any kind (:mod:`~foundation_calc.checks.amplitudes`) at one factor:
    without a steady state a failure that says why, else its governing limit or zone row."""
    if report.resonant:
        return RangePoint(factor, Outcome.FAIL, report.no_steady_state, math.inf)
    return worst_row_point(factor, report.amplitude_outcome, [*report.limit_rows, *report.zone_rows])


def amplitudes_over_range(scene, check, crossings=(), point=amplitude_point) -> ModulusRangeResult:
    """``check(scene)`` at :data:`AMPLITUDE_GRID_POINTS` factors of the scene's
    ``soil.modulus_range`` and at the resonance ``crossings`` [(factor, condition)], where the
    steady state peaks; ``point(factor, report)`` reads each report (default: an amplitude report of
    any kind, :func:`amplitude_point`)."""
    low, high = scene.soil.modulus_range
    factors = sorted({*modulus_factors(low, high, AMPLITUDE_GRID_POINTS), *(f for f, _ in crossings)})
    return ModulusRangeResult(
        low=low, high=high,
        points=tuple(point(f, check(scene.with_modulus_factor(f))) for f in factors),
        crossings=tuple(crossings),
    )


def resonances_over_range(scene, check, point=resonance_point, offsets=resonance_offsets) -> ModulusRangeResult:
    """``check(scene)`` at every factor of the scene's ``soil.modulus_range`` and at the factors
    where a critical speed crosses the operating speed (module docstring). ``point(factor,
    report)`` reads a report's verdict, ``offsets(report)`` its conditions (condition ->
    (critical speed less operating speed [rad/s], judged)); the defaults read a
    :class:`~foundation_calc.checks.resonance.report.ResonanceReport`."""
    from scipy.optimize import brentq

    low, high = scene.soil.modulus_range
    reports = {f: check(scene.with_modulus_factor(f)) for f in modulus_factors(low, high)}
    factors = sorted(reports)

    def offset(f, label):
        """Critical speed of ``label`` less the speed at factor ``f``; None where it is not listed."""
        report = reports[f] if f in reports else check(scene.with_modulus_factor(f))
        found = offsets(report).get(label)
        return None if found is None else found[0]

    labels = dict.fromkeys(label for f in factors for label in offsets(reports[f]))
    crossings = []
    for label in labels:
        for a, b in zip(factors, factors[1:]):
            at_a, at_b = offset(a, label), offset(b, label)
            if at_a is not None and at_b is not None and at_a * at_b < 0.0:
                f = brentq(lambda x, label=label: offset(x, label) or 0.0, a, b, xtol=1e-12, rtol=1e-10)
                report = check(scene.with_modulus_factor(f))
                if offsets(report).get(label, (0.0, False))[1]:  # the rule judges it there
                    reports[f] = report
                    crossings.append((f, label))
    return ModulusRangeResult(
        low=low, high=high,
        points=tuple(point(f, reports[f]) for f in sorted(reports)),
        crossings=tuple(crossings),
    )


__all__ = ["AMPLITUDE_GRID_POINTS", "GRID_POINTS", "ModulusRangeResult", "RangePoint", "amplitude_point",
           "amplitudes_over_range", "modulus_factors", "resonance_offsets", "resonance_point", "resonances_over_range",
           "worst_row_point"]
