"""A batch of candidate designs and the verdicts of the checks on it, held as arrays.

A candidate assigns a value to each varied scene key (a dotted path of the scene file, such as
``block.length`` or ``foundation.block.height``); a batch of N candidates is a mapping
``key -> (N,) array`` of values in the scene's SI units. A kind's evaluator,
``evaluate(scene, batch) -> CandidateVerdicts``, judges every candidate of the batch by the checks
``fcalc check`` runs on the kind (:data:`~foundation_calc.checks.registry.CHECKS`, same names), with
array operations over the batch (no Python loop per candidate), so that a search can afford
10⁵ candidates a second.

Utilisation is the demand over the capacity of a check: 1 at its limit, above 1 where it fails
(an amplitude: peak / limit; a resonance: the required detuning over the margin of the governing
condition; an office rule: value / allowed value). The worst margin of a candidate is
1 - max(utilisation) over its checks.
"""

from __future__ import annotations

from collections.abc import Callable, Mapping, Sequence
from dataclasses import dataclass

import numpy as np

#: Outcome codes of :attr:`CandidateVerdicts.outcome`, in rising severity.
PASS, WARN, FAIL = 0, 1, 2

#: scene kind -> module whose ``evaluate(scene, batch)`` returns :class:`CandidateVerdicts`.
EVALUATORS: dict[str, str] = {
    "block_foundation": "foundation_calc.checks.design.block",
    "crank_foundation": "foundation_calc.checks.design.crank",
}

#: Threads that judge the pieces of a batch (:func:`in_pieces`).
WORKERS = 2

#: A batch: varied scene key -> (N,) values [SI].
Batch = Mapping[str, np.ndarray]


@dataclass(frozen=True)
class CandidateVerdicts:
    """Every check's verdict on every candidate of a batch of N.

    Attributes
    ----------
    volume : (N,) concrete volume of the block [m³] (the objective)
    mass : (N,) mass of the block [kg]
    outcome : check name -> (N,) int8 of :data:`PASS`, :data:`WARN`, :data:`FAIL`
    utilisation : check name -> (N,) demand / capacity [-]; NaN where the check judges no number
    governing : check name -> (N,) int index into ``reasons[check]``: what governs the check there
    reasons : check name -> the texts ``governing`` indexes (e.g. ``"3ω = p1"``,
        ``"displacement at crankshaft bearing, z"``)
    deferred : the checks the evaluator does not evaluate (reported PASS, utilisation NaN), left
        to the full path (``fcalc check``'s): a search confirms its candidates by that path
    """

    volume: np.ndarray
    mass: np.ndarray
    outcome: dict[str, np.ndarray]
    utilisation: dict[str, np.ndarray]
    governing: dict[str, np.ndarray]
    reasons: dict[str, tuple[str, ...]]
    deferred: tuple[str, ...] = ()

    @property
    def worst_outcome(self) -> np.ndarray:
        """(N,) the most severe outcome over the checks."""
        return np.max(np.stack(list(self.outcome.values())), axis=0)

    @property
    def worst_margin(self) -> np.ndarray:
        """(N,) 1 - the largest utilisation over the checks [-] (negative: the candidate fails)."""
        return 1.0 - np.nanmax(np.stack(list(self.utilisation.values())), axis=0)


def ordered(volume, mass, outcome, utilisation, governing, reasons, order, deferred=()) -> CandidateVerdicts:
    """:class:`CandidateVerdicts` of the checks ``order`` names, in that order (``outcome``,
    ``utilisation``, ``governing``: check -> (N,); ``reasons``: check -> its texts)."""
    return CandidateVerdicts(volume=volume, mass=mass, outcome={c: outcome[c] for c in order},
                             utilisation={c: utilisation[c] for c in order}, governing={c: governing[c] for c in order},
                             reasons={c: tuple(reasons[c]) for c in order}, deferred=tuple(deferred))


def not_evaluated(n: int, reason: str) -> tuple:
    """(outcome, utilisation, governing, reasons) of a check a batch of ``n`` does not evaluate and
    leaves to the full path (its re-check of the chosen designs): PASS, NaN, ``reason``."""
    return np.full(n, PASS, dtype=np.int8), np.full(n, np.nan), np.zeros(n, dtype=np.intp), (reason,)


def largest_ratio(ratios: Sequence[np.ndarray], n: int) -> tuple[np.ndarray, np.ndarray]:
    """(utilisation, governing) of ``n`` candidates from the ``ratios`` of a check's rows ((N,) or
    (N, rows) each, in the order of the check's reasons): the largest ratio [-] and the index of its
    row (the first of equals); NaN and 0 for a check with no row."""
    if not ratios:
        return np.full(n, np.nan), np.zeros(n, dtype=int)
    ratio = np.concatenate([r if np.ndim(r) == 2 else np.reshape(r, (-1, 1)) for r in ratios], axis=-1)
    return ratio.max(axis=-1), np.argmax(ratio, axis=-1)


def failing(mask, outcome, utilisation, governing, reason) -> tuple:
    """A check's (outcome, utilisation, governing) of every candidate with those in ``mask`` (N,)
    failing it: outcome :data:`FAIL`, utilisation inf, governing ``reason`` (an index of the check's
    reasons, or one per candidate); the others' verdicts kept."""
    return (np.where(mask, FAIL, outcome).astype(np.int8), np.where(mask, np.inf, utilisation),
            np.where(mask, reason, governing))


def in_pieces(
    judge: Callable[[int, int], CandidateVerdicts], count: int, size: int, workers: int = WORKERS
) -> CandidateVerdicts:
    """``judge(start, stop)`` over the consecutive pieces of at most ``size`` of a batch of ``count``
    candidates, put together in order. More than one piece runs on ``workers`` threads: numpy's
    array arithmetic and linear algebra run outside Python's lock, so the cores share the work."""
    starts = range(0, count, size)
    if len(starts) <= 1:
        return judge(0, count)
    from concurrent.futures import ThreadPoolExecutor

    with ThreadPoolExecutor(workers) as pool:
        parts = list(pool.map(lambda start: judge(start, start + size), starts))
    return concatenated(parts)


def concatenated(parts: Sequence[CandidateVerdicts]) -> CandidateVerdicts:
    """The verdicts of consecutive pieces of one batch as one (their reasons and deferred checks
    depend on the scene alone: the first piece's)."""
    first = parts[0]
    return CandidateVerdicts(
        volume=np.concatenate([p.volume for p in parts]),
        mass=np.concatenate([p.mass for p in parts]),
        outcome={c: np.concatenate([p.outcome[c] for p in parts]) for c in first.outcome},
        utilisation={c: np.concatenate([p.utilisation[c] for p in parts]) for c in first.utilisation},
        governing={c: np.concatenate([p.governing[c] for p in parts]) for c in first.governing},
        reasons=first.reasons,
        deferred=first.deferred,
    )
