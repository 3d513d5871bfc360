"""Outcomes of checks and how they combine into an exit code."""

from __future__ import annotations

from collections.abc import Iterable
from enum import Enum

from foundation_calc.errors import ExitCode


class Outcome(str, Enum):
    """Result of one check. ``WARN`` is reported but fails the run only with ``--strict``."""

    PASS = "pass"
    WARN = "warn"
    FAIL = "fail"


_RANK = {Outcome.PASS: 0, Outcome.WARN: 1, Outcome.FAIL: 2}


def worst(outcomes: Iterable[Outcome]) -> Outcome:
    """The most severe outcome (``PASS`` for none).

    >>> worst([Outcome.PASS, Outcome.WARN]).value
    'warn'
    """
    return max(outcomes, key=_RANK.__getitem__, default=Outcome.PASS)


def exit_code(outcome: Outcome, strict: bool = False) -> ExitCode:
    """Exit code of a run whose worst outcome is ``outcome``."""
    if outcome is Outcome.FAIL or (strict and outcome is Outcome.WARN):
        return ExitCode.CHECK_FAILED
    return ExitCode.OK
