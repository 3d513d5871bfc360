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


def resonance_outcome(margin: float, detuning: float, driven: bool) -> Outcome:
    """The verdict rule of every scene kind for one resonance (README, "Verdicts").

    A mode the design drives (platform: the two translations; crank foundation: the paper's
    conditions ω = k0, 2ω = k0, ω = p1,2, 3ω = p1,2) fails inside the detuning band; any mode
    fails within :data:`RESONANCE_FAIL_MARGIN`; any other mode inside the band warns.

    Parameters
    ----------
    margin : relative distance of the speed from the resonance, |ω - ω_c|/ω_c [-]
    detuning : required relative distance, the scene's ``[limits] detuning`` [-]
    driven : whether the design's own excitation drives this mode

    >>> [resonance_outcome(m, 0.2, d).value for m, d in ((0.15, True), (0.15, False), (0.04, False), (0.3, True))]
    ['fail', 'warn', 'fail', 'pass']
    """
    fails, inside = resonance_masks(margin, detuning, driven)
    if fails:
        return Outcome.FAIL
    return Outcome.WARN if inside else Outcome.PASS


def resonance_masks(margin, detuning, driven):
    """``(fails, inside)`` of :func:`resonance_outcome` for arrays of margins (numpy bool arrays
    for ``driven``) or scalars: a resonance fails, or warns where ``inside & ~fails``."""
    inside = margin < detuning
    return (margin < RESONANCE_FAIL_MARGIN) | (driven & inside), inside


def exit_code(outcome: Outcome, strict: bool = False, warned: bool = False) -> ExitCode:
    """Exit code of a run whose worst outcome is ``outcome``; ``warned``: the scene has
    plausibility warnings, which fail like a warning with ``strict``."""
    if outcome is Outcome.FAIL or (strict and (outcome is Outcome.WARN or warned)):
        return ExitCode.CHECK_FAILED
    return ExitCode.OK
