"""The designs a search picks, judged again by ``fcalc check``'s own path, and every place where
that judgement and the search's differ.

The search's evaluator and the reference evaluator (:mod:`.reference`, one
:func:`~foundation_calc.checks.batch.run_checks` a candidate) must give each check the same
outcome on the same design, and the same utilisation within :data:`UTILISATION_AGREEMENT`; any
difference is a :class:`Disagreement`, which the command reports as the internal error it is.
A check the search's evaluator defers (``CandidateVerdicts.deferred``: it did not evaluate it) is
no disagreement: the full path's verdict on it stands.
"""

from __future__ import annotations

import math
from collections.abc import Mapping
from dataclasses import dataclass
from typing import Any

import numpy as np

from foundation_calc.checks.design.candidates import PASS, CandidateVerdicts

#: Relative difference within which two evaluators' utilisations agree [-]: the same closed
#: forms computed in another order differ by rounding (1e-12); an eigen-solve in a batch and
#: alone by its tolerance (1e-9); 1e-6 leaves room and still catches a wrong term.
UTILISATION_AGREEMENT = 1e-6

OUTCOME_NAMES = ("pass", "warn", "fail")


@dataclass(frozen=True)
class Disagreement:
    """One check on one design judged differently by the search and by the full path."""

    design: dict[str, float]
    check: str
    search: str
    full: str

    @property
    def text(self) -> str:
        values = ", ".join(f"{k} = {v:.4g} m" for k, v in self.design.items())
        return f"{values}: check {self.check}: the search says {self.search}, fcalc check says {self.full}"


def _said(verdicts: CandidateVerdicts, check: str, i: int) -> tuple[int, float]:
    if check not in verdicts.outcome:
        return PASS, math.nan
    return int(verdicts.outcome[check][i]), float(verdicts.utilisation[check][i])


def _agree(a: float, b: float) -> bool:
    if math.isnan(a) or math.isnan(b):
        return True  # one evaluator judges no number there: the outcome decides
    if math.isinf(a) or math.isinf(b):
        return a == b
    return abs(a - b) <= UTILISATION_AGREEMENT * max(abs(a), abs(b))


def disagreements(designs: Mapping[str, np.ndarray], searched: CandidateVerdicts, full: CandidateVerdicts) -> list[Disagreement]:
    """Every check of every design (key -> (n,) values) whose outcome differs between the two
    verdicts, or whose utilisations differ by more than :data:`UTILISATION_AGREEMENT`; the checks
    ``searched`` defers are left out."""
    found = []
    count = len(full.volume)
    for i in range(count):
        design = {k: float(v[i]) for k, v in designs.items()}
        for check in dict.fromkeys([*full.outcome, *searched.outcome]):
            if check in searched.deferred:
                continue
            (o1, u1), (o2, u2) = _said(searched, check, i), _said(full, check, i)
            if o1 != o2 or not _agree(u1, u2):
                found.append(Disagreement(design, check, f"{OUTCOME_NAMES[o1]} ({u1:.6g})", f"{OUTCOME_NAMES[o2]} ({u2:.6g})"))
    return found


def recheck(document: Mapping[str, Any], designs: Mapping[str, np.ndarray], searched: CandidateVerdicts,
            source: str = "<design>") -> tuple[CandidateVerdicts, list[Disagreement]]:
    """The full path's verdicts on ``designs`` (:func:`.reference.evaluate`) and where they differ
    from ``searched``, the search's verdicts on the same designs."""
    from foundation_calc.checks.design.reference import evaluate

    full = evaluate(document, designs, source)
    return full, disagreements(designs, searched, full)


__all__ = ["Disagreement", "UTILISATION_AGREEMENT", "disagreements", "recheck"]
