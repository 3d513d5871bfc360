"""The validation record as a whole: every case, in the order ``fcalc validate`` prints them."""

from __future__ import annotations

from collections.abc import Sequence

from foundation_calc.validation import independent, published
from foundation_calc.validation.record import Case, CaseResult, evaluate


def all_cases() -> tuple[Case, ...]:
    """Every case of the record: published values first, then independent methods."""
    return (*published.CASES, *independent.CASES)


def run_record(cases: Sequence[Case] | None = None) -> list[CaseResult]:
    """Evaluate ``cases`` (all of them by default), in order."""
    return [evaluate(case) for case in (all_cases() if cases is None else cases)]


__all__ = ["all_cases", "run_record"]
