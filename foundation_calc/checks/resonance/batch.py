"""The resonance check's verdict on a batch of N candidate designs at once (``fcalc design``), for
every scene kind: the resonance rule's judgement (:func:`~foundation_calc.checks.resonance.rule.judge`)
of each candidate's conditions, read at its governing condition as the batch's verdicts
(:class:`~foundation_calc.checks.design.candidates.CandidateVerdicts`). Which conditions a kind
has, their margins and how it names the governing one are the kind's engine's."""

from __future__ import annotations

import numpy as np

from foundation_calc.checks.design.candidates import FAIL, PASS, WARN

#: Outcome code of each status of :mod:`~foundation_calc.checks.resonance.rule` (clear, information,
#: warn, fail), as ``fcalc check`` reports a resonance: information passes.
RULE_OUTCOME = np.array([PASS, PASS, WARN, FAIL], dtype=np.int8)


def governing_verdicts(judgement, margin) -> tuple[np.ndarray, np.ndarray]:
    """(outcome int8, utilisation [-]) of N candidates from the rule's ``judgement`` of their
    conditions and the conditions' ``margin`` |ω - ω_c|/ω_c (N, C) [-]: the outcome of the worst
    status (:data:`RULE_OUTCOME`); the utilisation needed/margin of the governing condition (the
    margin it needs over the margin it has: above 1 it fails, or warns for an order-1 condition the
    forcing does not drive), inf at a margin of 0, NaN where no condition can decide.

    >>> from foundation_calc.checks.resonance.rule import judge
    >>> j = judge([[0.1, 0.5], [0.3, 0.0]], [1, 2], [1.0, 1.0], [0.2, 0.2], [True, True])
    >>> outcome, utilisation = governing_verdicts(j, [[0.1, 0.5], [0.3, 0.0]])
    >>> outcome.tolist(), utilisation.tolist()
    ([2, 2], [2.0, inf])
    """
    margin = np.asarray(margin, dtype=float)
    g = np.maximum(judgement.governing, 0)[..., None]
    at = np.take_along_axis(margin, g, -1)[..., 0]
    needed = np.take_along_axis(judgement.needed, g, -1)[..., 0]
    utilisation = np.where(at > 0.0, needed / np.where(at > 0.0, at, 1.0), np.inf)
    return RULE_OUTCOME[judgement.worst], np.where(judgement.governing >= 0, utilisation, np.nan)


__all__ = ["RULE_OUTCOME", "governing_verdicts"]
