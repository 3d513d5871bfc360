"""What decides a row of ``fcalc sweep``, for every scene kind: the governing resonance condition
by the resonance rule (docs/resonance-rule.md), its margin and the margin it needs, every
limit the row exceeds, the row's status, and the words that say why.

A kind's sweep gives the margins of its conditions at every row and the rule's
:class:`~foundation_calc.checks.resonance.rule.Judgement` of them, and which limited quantities
exceed their limits; :func:`row_verdicts` reads the rest and :func:`status_text` names it. A
condition the rule does not judge (a harmonic whose forcing share is under 1 %) never governs a
row, however near its critical speed lies.
"""

from __future__ import annotations

from dataclasses import dataclass

import numpy as np

from foundation_calc.checks.resonance.rule import FAIL, STATUS_NAMES, WARN, Judgement, condition_phrase

#: Status of a row, worst last ("resonant": no steady state there).
STATUSES = ("pass", "warn", "fail", "resonant")


@dataclass(frozen=True)
class RowVerdicts:
    """The verdict of every row of a sweep (arrays of length n).

    Attributes
    ----------
    governing : index of the condition that governs each row's resonance verdict (-1: none can decide)
    margin : that condition's margin [-] (0 where none governs)
    needed : the margin it needs [-]: its band, at least the rule's floor
    resonance_status : the rule's verdict per row (``clear``, ``information``, ``warn``, ``fail``)
    over_quantities : limited quantity -> where it exceeds its limit (bool (n,))
    status : one of :data:`STATUSES` per row
    """

    governing: np.ndarray
    margin: np.ndarray
    needed: np.ndarray
    resonance_status: np.ndarray
    over_quantities: dict
    status: np.ndarray

    @property
    def over_limit(self) -> np.ndarray:
        """Whether a row exceeds any limit."""
        over = np.zeros(self.status.shape, dtype=bool)
        for mask in self.over_quantities.values():
            over = over | mask
        return over

    def condition(self, i: int, conditions) -> str | None:
        """The label of the condition that governs row ``i`` (one of ``conditions``, each with a
        ``label``; None: none can decide)."""
        g = int(self.governing[i])
        return None if g < 0 else conditions[g].label

    def over_limits(self, i: int) -> list[str]:
        """The limited quantities row ``i`` exceeds."""
        return [q for q, mask in self.over_quantities.items() if mask[i]]


def over_limits(largest: dict, limits: dict) -> dict:
    """Limited quantity -> where a row exceeds its limit (bool (n,)), for every kind's sweep:
    ``largest``: quantity -> the row's values (n,) or (n, directions), over every point [SI];
    ``limits``: quantity -> limit (:func:`~foundation_calc.checks.limits.limited_quantities`).

    >>> over_limits({"displacement": np.array([[1.0, 3.0], [1.0, 1.0]])}, {"displacement": 2.0})["displacement"].tolist()
    [True, False]
    """
    from foundation_calc.checks.limits import exceeds

    found = {}
    for quantity, limit in limits.items():
        over = np.asarray(exceeds(largest[quantity], limit), dtype=bool)
        found[quantity] = over.reshape(over.shape[0], -1).any(axis=-1)
    return found


def row_verdicts(margins, verdict: Judgement, over_quantities: dict, resonant=None) -> RowVerdicts:
    """Each row's governing condition and status from the ``margins`` of its conditions (n, C) [-]
    and the rule's ``verdict`` of them (:func:`~foundation_calc.checks.resonance.rule.judge`, rows
    on the leading axis); ``over_quantities``: limited quantity -> bool (n,); ``resonant``: rows
    with no steady state (bool (n,), default none). A row fails where the rule fails or a limit is
    exceeded, warns where the rule warns.

    >>> from foundation_calc.checks.resonance.rule import judge
    >>> m = np.array([[0.05, 0.3], [0.5, 0.3]])  # the order-2 condition's share is 0.001: not judged
    >>> v = row_verdicts(m, judge(m, [2, 1], [0.001, 1.0], [0.2, 0.2], [False, False]), {"displacement": np.array([False, True])})
    >>> v.governing.tolist(), v.status.tolist(), v.resonance_status.tolist()
    ([1, 1], ['pass', 'fail'], ['information', 'clear'])
    """
    margins = np.asarray(margins, dtype=float)
    n = margins.shape[0]
    governing = np.broadcast_to(verdict.governing, (n,))
    at = np.maximum(governing, 0)[:, None]
    none = governing < 0
    margin = np.where(none, 0.0, np.take_along_axis(margins, at, axis=-1)[:, 0])
    needed = np.where(none, 0.0, np.take_along_axis(np.broadcast_to(verdict.needed, margins.shape), at, axis=-1)[:, 0])
    rule = np.broadcast_to(verdict.worst, (n,))
    over = np.zeros(n, dtype=bool)
    for mask in over_quantities.values():
        over = over | np.asarray(mask, dtype=bool)
    status = np.where((rule == FAIL) | over, "fail", np.where(rule == WARN, "warn", "pass"))
    if resonant is not None:
        status = np.where(np.asarray(resonant, dtype=bool), "resonant", status)
    return RowVerdicts(governing=governing, margin=margin, needed=needed, resonance_status=np.asarray(STATUS_NAMES)[rule],
                       over_quantities=over_quantities, status=status)


#: The symbol of each limited quantity in a compact status: u, v, a and their RMS u_rms, v_rms, a_rms.
SYMBOLS = {"displacement": "u", "velocity": "v", "acceleration": "a"}


def symbol(quantity: str) -> str:
    """A limited quantity's symbol (:data:`SYMBOLS`), peak or RMS.

    >>> symbol("displacement"), symbol("acceleration_rms")
    ('u', 'a_rms')
    """
    peak = quantity.removesuffix("_rms")
    return SYMBOLS[peak] + quantity[len(peak):]


def status_text(status: str, condition: str | None, margin: float, needed: float, resonance_status: str,
                over_limits, compact: bool = False) -> str:
    """Why a row has its status, the failing causes first: the governing condition when the rule
    fails or warns there, every limit the row exceeds; then, when the rule is satisfied, the
    governing condition and its margin. ``condition``: the governing condition's label (None: no
    condition can decide); ``over_limits``: the limited quantities exceeded.

    ``compact``: the same causes for a narrow terminal, without the words that a legend says once
    under the table: the verdict, the limits exceeded by their symbols (:data:`SYMBOLS`), the
    governing condition with no spaces about its "=" and its margin / the margin it needs (inside
    its band when the first is the smaller; docs/sweep.md).

    >>> status_text("fail", "3ω = p1", 0.157, 0.2, "fail", ["displacement"])
    'fail: inside 3ω = p1 at 15.7% (needs 20%); over displacement limit'
    >>> status_text("fail", "motor: ω = mode 1 (y)", 0.309, 0.2, "clear", ["displacement", "velocity_rms"])
    'fail: over displacement, velocity_rms limit; resonances clear, governing motor: ω = mode 1 (y) at 30.9% (needs 20%)'
    >>> status_text("fail", "3ω = p1", 0.309, 0.2, "clear", ["displacement", "velocity_rms"], compact=True)
    'fail over u, v_rms; 3ω=p1 30.9%/20%'
    >>> status_text("pass", "3ω = p1", 0.724, 0.2, "clear", [], compact=True)
    'pass 3ω=p1 72.4%/20%'
    """
    if compact:
        causes = [f"over {', '.join(symbol(q) for q in over_limits)}"] if over_limits else []
        causes += [] if condition is None else [f"{condition.replace(' = ', '=')} {margin:.1%}/{needed:.0%}"]
        return " ".join([status, "; ".join(causes)]) if causes else status
    phrase = None if condition is None else condition_phrase(condition, margin, needed)
    causes = []
    if phrase is not None and resonance_status in ("warn", "fail"):
        causes.append(f"inside {phrase}")
    if over_limits:
        causes.append(f"over {', '.join(over_limits)} limit")
    if phrase is not None and resonance_status not in ("warn", "fail"):
        causes.append(f"resonances clear, governing {phrase}")
    return f"{status}: " + "; ".join(causes) if causes else status


__all__ = ["STATUSES", "SYMBOLS", "RowVerdicts", "over_limits", "row_verdicts", "status_text", "symbol"]
