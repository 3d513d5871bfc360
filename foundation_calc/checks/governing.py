"""Which points and limit rows govern a design with many points, and how many rows fail.

A scene may list hundreds of points; an engineer signing the foundation wants the worst of them
and the number that fail, not every row. These functions pick them from a computed
approximation (``checks/amplitudes/approximations.py``); the tables show the selection, JSON every row.
"""

from __future__ import annotations

from collections.abc import Iterable, Mapping, Sequence
from dataclasses import dataclass, fields

import numpy as np

from foundation_calc.checks.outcomes import Outcome
from foundation_calc.solvers.crank.response import Peaks


def governing_points(points: Mapping[str, Peaks], exclude: Iterable[str] = ("C",)) -> list[str]:
    """Names of the points (other than ``exclude``) that hold the largest peak of some quantity
    (displacement, velocity, acceleration) in some direction, in the order of ``points``.

    ``points`` maps a name to its peaks, each an array over the directions (horizontal,
    vertical); a tie goes to the point listed first.

    >>> import numpy as np
    >>> pk = lambda d, v, a: Peaks(np.array(d), np.array(v), np.array(a))
    >>> governing_points({"C": pk([9, 9], [9, 9], [9, 9]), "a": pk([1, 5], [1, 5], [1, 5]),
    ...                   "b": pk([2, 1], [2, 1], [2, 1]), "c": pk([0, 0], [0, 0], [0, 0])})
    ['a', 'b']
    """
    skip = set(exclude)
    names = [name for name in points if name not in skip]
    if not names:
        return []
    chosen = set()
    for quantity in (f.name for f in fields(Peaks)):
        values = np.array([getattr(points[name], quantity) for name in names])  # (points, directions)
        chosen.update(np.argmax(values, axis=0).tolist())
    return [names[i] for i in sorted(chosen)]


def worst_rows(rows: Sequence, count: int) -> list:
    """The ``count`` limit rows with the largest value/limit ratio, and the largest of each quantity
    besides, by ratio from the largest (a row has ``quantity`` and ``ratio``).

    >>> from types import SimpleNamespace as Row
    >>> rows = [Row(quantity="d", ratio=r) for r in (0.2, 0.9, 0.5)] + [Row(quantity="v", ratio=0.1)]
    >>> [(r.quantity, r.ratio) for r in worst_rows(rows, 2)]
    [('d', 0.9), ('d', 0.5), ('v', 0.1)]
    """
    order = sorted(range(len(rows)), key=lambda i: -rows[i].ratio)
    shown = set(order[:count])
    seen = set()
    for i in order:
        if rows[i].quantity not in seen:
            seen.add(rows[i].quantity)
            shown.add(i)
    return [rows[i] for i in order if i in shown]


@dataclass(frozen=True)
class LimitTally:
    """How many limit rows (a point, a direction, a quantity) and points there are, and fail."""

    rows: int
    failed_rows: int
    points: int
    failed_points: int


def tally(rows: Iterable) -> LimitTally:
    """Count the limit rows and their points (a row has ``point`` and ``outcome``), failed or not.

    >>> from types import SimpleNamespace as Row
    >>> tally([Row(point="C", outcome=Outcome.PASS), Row(point="a", outcome=Outcome.FAIL),
    ...        Row(point="a", outcome=Outcome.FAIL)])
    LimitTally(rows=3, failed_rows=2, points=2, failed_points=1)
    """
    rows = list(rows)
    failed = [row for row in rows if row.outcome is Outcome.FAIL]
    return LimitTally(len(rows), len(failed), len({row.point for row in rows}), len({row.point for row in failed}))


__all__ = ["LimitTally", "governing_points", "tally", "worst_rows"]
