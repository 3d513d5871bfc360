"""The reserve a sizing search may ask of every check (``fcalc design --margin M``), and whether a
design sits on a limit.

``fcalc check`` passes a design when no check fails (a warning passes; with ``strict`` it fails).
A reserve M (0 ≤ M < 1) asks more of a candidate: every utilisation (demand over capacity,
:mod:`.candidates`) at most 1 − M, a check that judges no number (NaN) excepted. A warning's
utilisation is held to it too: a check's utilisation is its most utilised row, and a rule of
thumb beyond its limit (the mass ratio below 3, utilisation above 1) leaves no reserve, whether
the rows that can fail behind it have one or not.

The cheapest design lies on the boundary of the passing region by construction: some check's
utilisation sits at its bound (1, or 1 − M with a reserve). :func:`on_limit` names that check
when it lies within :data:`ON_LIMIT` of the bound, so that the output can say so.
"""

from __future__ import annotations

from dataclasses import dataclass

import numpy as np

from foundation_calc.checks.design.candidates import FAIL, WARN, CandidateVerdicts

#: A design whose largest utilisation lies within this of its bound sits on a limit [-]: a 1 %
#: change of a demand or a capacity (a soil's stiffness is known to ±20 %, ACI 351.3R) moves it
#: across.
ON_LIMIT = 0.01


def bound(margin: float | None) -> float:
    """The largest utilisation a check may have with the reserve ``margin`` [-] (1 without one)."""
    return 1.0 - (margin or 0.0)


def failing_checks(verdicts: CandidateVerdicts, strict: bool, margin: float | None) -> dict[str, np.ndarray]:
    """check -> (N,) True where it keeps the candidate from passing: its outcome fails (or warns,
    with ``strict``), or, with a reserve ``margin``, its utilisation exceeds 1 − ``margin``."""
    worst = WARN if strict else FAIL
    found = {}
    for name, outcome in verdicts.outcome.items():
        fails = outcome >= worst
        if margin is not None:
            fails = fails | (verdicts.utilisation[name] > bound(margin))  # NaN: no number, no reserve asked
        found[name] = fails
    return found


@dataclass(frozen=True)
class OnLimit:
    """The check whose utilisation sits within :data:`ON_LIMIT` of ``limit`` (its bound)."""

    check: str
    governing: str
    utilisation: float
    limit: float


def on_limit(verdicts: CandidateVerdicts, i: int, margin: float | None) -> OnLimit | None:
    """The most utilised check of candidate ``i`` whose utilisation lies within :data:`ON_LIMIT` of
    ``bound(margin)`` and at most 1 (beyond 1 a check warns or fails, which its outcome says), or None."""
    limit = bound(margin)
    found = None
    for name, column in verdicts.utilisation.items():
        value = float(column[i])
        near = abs(value - limit) <= ON_LIMIT and value <= 1.0  # NaN: never near
        if near and (found is None or value > found.utilisation):
            found = OnLimit(name, verdicts.reasons[name][verdicts.governing[name][i]], value, limit)
    return found


__all__ = ["ON_LIMIT", "OnLimit", "bound", "failing_checks", "on_limit"]
