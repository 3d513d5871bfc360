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


#: Relative distance of the operating speed from any natural frequency inside which a design
#: fails whatever the mode [-]: within 5 % the smallest build tolerance (a 1 % stiffness error
#: moves a frequency by 0.5 %) or a few percent of speed drift reaches the resonance.
RESONANCE_FAIL_MARGIN = 0.05


def exit_code(outcome: Outcome, strict: bool = False, warned: bool = False) -> ExitCode:
    """Exit code of a run whose worst outcome is ``outcome``; ``warned``: the scene has
    plausibility warnings, which fail like a warning with ``strict``."""
    if outcome is Outcome.FAIL or (strict and (outcome is Outcome.WARN or warned)):
        return ExitCode.CHECK_FAILED
    return ExitCode.OK
