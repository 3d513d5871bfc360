"""The one modulus-range checker of ``fcalc design`` (checks/design/modulus_range.py) on verdicts
written out by hand: the worst element per candidate (outcome first, then utilisation, the later
of equals), the candidates a further factor can still make worse, and the merge with the soil as
given in both of the kinds' forms (the range's own reasons, or one summary). Exact comparisons:
nothing is computed but choices among the given numbers."""

from __future__ import annotations

import numpy as np

from foundation_calc.checks.design.modulus_range import OVER_RANGE, Worst

REASONS = ("a", "b", "c")


def _given():
    """Three candidates on the soil as given: PASS, WARN, FAIL."""
    return {"resonance": (np.array([0, 1, 2], np.int8), np.array([0.5, 1.1, 2.0]), np.array([0, 1, 2]), REASONS)}


def _worst():
    worst = Worst(3, ("resonance",))
    # candidate 0: a WARN at 0.9 then a FAIL at 0.3 (the outcome governs, not the utilisation);
    # candidate 1: two WARNs at 1.2 and 1.2 (the later governs: reason c); candidate 2: none
    worst.add("resonance", np.array([0, 1]), np.array([1, 1], np.int8), np.array([0.9, 1.2]), np.array([0, 1]), REASONS)
    worst.add("resonance", np.array([0, 1]), np.array([2, 1], np.int8), np.array([0.3, 1.2]), np.array([1, 2]), REASONS)
    return worst


def test_the_worst_element_of_each_candidate():
    worst = _worst()
    assert worst.outcome["resonance"].tolist() == [2, 1, -1]
    assert worst.governing["resonance"].tolist() == [1, 2, 0]
    np.testing.assert_array_equal(worst.utilisation["resonance"], [0.3, 1.2, np.nan])


def test_a_candidate_that_fails_already_is_not_open():
    assert _worst().open(_given(), ("resonance",)).tolist() == [1]
    assert Worst(3, ("resonance",)).open(_given(), ("resonance",)).tolist() == [0, 1]


def test_the_merge_names_the_ranges_reason_or_a_summary():
    worst = _worst()
    outcome, utilisation, governing, reasons = worst.merged(_given())["resonance"]
    assert outcome.tolist() == [2, 1, 2]  # candidate 0 fails over the range only
    np.testing.assert_array_equal(utilisation, [0.5, 1.1, 2.0])  # the soil as given's, as the full path reads it
    assert reasons == (*REASONS, *(r + OVER_RANGE for r in REASONS))
    assert governing.tolist() == [len(REASONS) + 1, 1, 2]  # where worse: the range's "b"; elsewhere unchanged
    _, _, governing, reasons = worst.merged(_given(), "over the range")["resonance"]
    assert reasons == (*REASONS, "over the range") and governing.tolist() == [3, 1, 2]
