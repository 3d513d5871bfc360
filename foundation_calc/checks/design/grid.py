"""The grid of candidate designs a sizing search walks: ``--vary KEY=LO:HI`` ranges, each cut by
a step or a number of points, their Cartesian product handed out in chunks.

A range from LO to HI with step s holds n = ceil((HI - LO)/s) + 1 evenly spaced values, both ends
included, so the grid's step is at most s (:attr:`Axis.step` says the one it has). A grid is never
held whole: :meth:`Grid.chunk` gives the candidates ``start`` to ``stop`` of the product, so a
search's memory is bounded by its chunk, not by the grid.
"""

from __future__ import annotations

import math
from collections.abc import Sequence
from dataclasses import dataclass

import numpy as np

from foundation_calc.checks.design.apply import Variable, VaryError, variable

#: Largest grid searched [candidates]: 2·10⁶ take about 40 s at the vectorised evaluators' speed.
MAX_CANDIDATES = 2_000_000

#: Largest grid of a kind without a vectorised evaluator (each candidate through fcalc check's
#: path, 5-30 ms, far more with a soil's modulus_range): at most this many candidates, and at
#: most :data:`MAX_REFERENCE_SECONDS` of them at the cost of the scene's own block.
MAX_REFERENCE_CANDIDATES = 5_000
MAX_REFERENCE_SECONDS = 120.0

#: Decimals a grid value is rounded to [m]: a micrometre, so that values print and write as typed (4.3, not 4.300000000000001).
DECIMALS = 6

#: Step of a range when neither a step nor a number of points is given [m].
DEFAULT_STEP = 0.1


@dataclass(frozen=True)
class Range:
    """One ``--vary KEY=LO:HI``: a scene key and its bounds [the key's unit]."""

    key: str
    low: float
    high: float


def parse_range(text: str) -> Range:
    """``"block.length=4:10"`` -> Range; raises :class:`VaryError` saying what the form is."""
    key, equals, bounds = text.partition("=")
    low, colon, high = bounds.partition(":")
    try:
        values = float(low), float(high)
    except ValueError:
        values = None
    if not equals or not colon or not key.strip() or values is None or not all(map(math.isfinite, values)):
        raise VaryError(f"{text!r} is not KEY=LOW:HIGH with two finite numbers, e.g. block.length=4:10 (metres)")
    return Range(key.strip(), *values)


@dataclass(frozen=True)
class Axis:
    """One varied key and its grid values [the key's unit]."""

    variable: Variable
    values: np.ndarray

    @property
    def step(self) -> float:
        """The grid's step [unit]; 0 for a single value."""
        span = float(self.values[-1] - self.values[0])
        return round(span / (len(self.values) - 1), 9) if len(self.values) > 1 else 0.0


def axis(kind: str, given: Range, step: float | None = None, points: int | None = None) -> Axis:
    """The grid values of one range: ``points`` values, or the step at most ``step`` (module
    docstring; :data:`DEFAULT_STEP` without either). Raises :class:`VaryError` for a key that
    cannot vary, LO > HI, a bound outside the key's physical bounds or a step <= 0."""
    found = variable(kind, given.key)
    if given.low > given.high:
        raise VaryError(f"{found.key}={given.low:g}:{given.high:g}: the low end is above the high end")
    for end in (given.low, given.high):
        if not found.low <= end <= found.high:
            raise VaryError(f"{found.key} = {end:g} {found.unit} is outside the bounds of a {found.text},"
                            f" {found.low:g} to {found.high:g} {found.unit}")
    if step is not None and not step > 0:
        raise VaryError(f"--step must be > 0 {found.unit} (got {step:g})")
    if points is not None and points < 2:
        raise VaryError(f"--points must be at least 2 (got {points})")
    span = given.high - given.low
    if span == 0:
        count = 1
    elif points is not None:
        count = points
    else:
        count = math.ceil(span / (step or DEFAULT_STEP) - 1e-9) + 1
        if count > MAX_CANDIDATES:
            raise VaryError(f"{found.key}: a step of {step:g} {found.unit} over {span:g} {found.unit} gives {count}"
                            f" values, more than a whole grid may hold ({MAX_CANDIDATES})")
    return Axis(found, np.round(np.linspace(given.low, given.high, count), DECIMALS))


@dataclass(frozen=True)
class Grid:
    """The Cartesian product of the axes; the scene's other dimensions stay as given."""

    axes: tuple[Axis, ...]

    @property
    def keys(self) -> list[str]:
        return [a.variable.key for a in self.axes]

    @property
    def shape(self) -> tuple[int, ...]:
        return tuple(len(a.values) for a in self.axes)

    @property
    def size(self) -> int:
        return math.prod(self.shape)

    def chunk(self, start: int, stop: int) -> dict[str, np.ndarray]:
        """The candidates ``start`` to ``stop`` (exclusive) of the product: key -> (n,) values."""
        index = np.unravel_index(np.arange(start, min(stop, self.size)), self.shape)
        return {a.variable.key: a.values[i] for a, i in zip(self.axes, index)}


def grid(kind: str, ranges: Sequence[Range], step: float | None = None, points: int | None = None,
         maximum: int = MAX_CANDIDATES, evaluator: str = "") -> Grid:
    """The grid of ``ranges`` (:func:`axis` each); raises :class:`VaryError` for no range, a key
    given twice, or more than ``maximum`` candidates (naming the size of each axis, and
    ``evaluator``, what judges them, when it sets the maximum)."""
    if not ranges:
        raise VaryError("give at least one --vary KEY=LOW:HIGH, e.g. --vary block.length=4:10")
    axes = tuple(axis(kind, r, step, points) for r in ranges)
    keys = [a.variable.key for a in axes]
    twice = sorted({k for k in keys if keys.count(k) > 1})
    if twice:
        raise VaryError(f"{', '.join(twice)} is given more than once")
    found = Grid(axes)
    if found.size > maximum:
        sizes = " × ".join(f"{len(a.values)} ({a.variable.key})" for a in axes)
        why = f" ({evaluator})" if maximum < MAX_CANDIDATES and evaluator else ""
        raise VaryError(f"the grid has {found.size} candidates ({sizes}), more than the {maximum} searched at once{why};"
                        " use a coarser --step or fewer --points (the search refines near the cheapest design)")
    return found


__all__ = ["Axis", "DECIMALS", "DEFAULT_STEP", "Grid", "MAX_CANDIDATES", "MAX_REFERENCE_CANDIDATES", "MAX_REFERENCE_SECONDS", "Range", "axis", "grid",
           "parse_range"]
