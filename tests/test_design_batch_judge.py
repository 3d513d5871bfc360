"""The one array judge of a batch's amplitudes (checks/amplitudes/batch.py) and the resonance
verdict at the governing condition (checks/resonance/batch.py) that both engines of ``fcalc
design`` hand their values to, on values written here.

The zone boundaries are ISO 10816-3:2009, Annex A, Table A.2 (group 2, rigid): r.m.s. velocity
1.4 / 2.8 / 4.5 mm/s and r.m.s. displacement 22 / 45 / 71 µm between zones A/B, B/C and C/D.
The expected utilisations are quotients of those numbers, exact to round-off: compared at 1e-12.
"""

from __future__ import annotations

from types import SimpleNamespace

import numpy as np
import pytest

from foundation_calc.checks.amplitudes.batch import judge_batch
from foundation_calc.checks.design.candidates import FAIL, PASS, WARN
from foundation_calc.checks.resonance.batch import governing_verdicts
from foundation_calc.checks.resonance.rule import judge

#: 1500 rpm [rad/s]: inside the code's 120 ... 15 000 rpm
SPEED = 1500.0 * 2.0 * np.pi / 60.0


def _limits(**changes):
    """``[limits]``: a 20 µm peak displacement and ISO 10816-3, group 2, rigid, on a 100 kW machine."""
    limits = dict(amplitude=20e-6, velocity=None, acceleration=None, amplitude_rms=None, velocity_rms=None,
                  acceleration_rms=None, code="ISO 10816-3", machine_group=2, foundation="rigid",
                  acceptable_zone=None, machine_power=100e3)
    return SimpleNamespace(**(limits | changes))


#: quantity -> (2 candidates, points G and bearing, directions x and z) [m, m/s]: candidate 0's
#: bearing moves 30 µm vertically (over the 20 µm limit), its velocities in zone A, its 30 µm r.m.s.
#: displacement in zone B; candidate 1's peaks stay under the limit (its largest alone at its row,
#: as a block's exact peak is given, the other rows -inf) while G's horizontal r.m.s. velocity,
#: 3.5 mm/s, lies in zone C.
VALUES = {
    "displacement": np.array([[[5e-6, 8e-6], [12e-6, 30e-6]],
                              [[-np.inf, -np.inf], [10e-6, -np.inf]]]),
    "velocity_rms": np.array([[[0.7e-3, 1.0e-3], [0.9e-3, 0.5e-3]],
                              [[3.5e-3, 1.1e-3], [2.0e-3, 0.4e-3]]]),
    "displacement_rms": np.array([[[3e-6, 4e-6], [8e-6, 30e-6]],
                                  [[5e-6, 2e-6], [6e-6, 1e-6]]]),
}

STEADY = [(np.array([False, False]), "no steady state")]


def _judged(limits, unsteady=STEADY):
    return judge_batch(["G", "bearing"], ["x", "z"], VALUES.__getitem__, limits, [("fan", SPEED)], unsteady)


def test_a_row_over_its_limit_fails_and_a_point_in_zone_c_fails():
    outcome, utilisation, governing, reasons = _judged(_limits())
    assert reasons == ("displacement at G (x)", "displacement at G (z)", "displacement at bearing (x)",
                       "displacement at bearing (z)", "ISO 10816-3, group 2, rigid zone at G",
                       "ISO 10816-3, group 2, rigid zone at bearing", "no steady state")
    assert outcome.tolist() == [FAIL, FAIL]
    assert [reasons[g] for g in governing] == ["displacement at bearing (z)", "ISO 10816-3, group 2, rigid zone at G"]
    # 30 µm over 20 µm; 3.5 mm/s over zone B's upper 2.8 mm/s (the velocity's zone C worse than the displacement's A)
    assert utilisation == pytest.approx([30.0 / 20.0, 3.5 / 2.8], rel=1e-12)


@pytest.mark.parametrize(("acceptable", "outcome", "utilisation"), [
    (None, [WARN, FAIL], [30.0 / 45.0, 3.5 / 2.8]),  # zone B warns, C fails; over zone B's upper boundaries
    ("C", [PASS, PASS], [30.0 / 71.0, 3.5 / 4.5]),  # over zone C's
])
def test_a_point_s_zone_is_its_worse_quantity_s_and_the_acceptable_zone_judges_it(acceptable, outcome, utilisation):
    found, ratio, governing, _ = _judged(_limits(acceptable_zone=acceptable, amplitude=None))
    assert found.tolist() == outcome
    # candidate 0: the bearing, its displacement's zone B worse than its velocity's A (G is in zone A by both);
    # candidate 1: G
    assert governing.tolist() == [1, 0]
    assert ratio == pytest.approx(utilisation, rel=1e-12)


def test_a_machine_outside_the_codes_group_warns_and_a_candidate_without_a_steady_state_fails():
    outside = _limits(amplitude=None, acceptable_zone="C", machine_power=500e3)  # 500 kW: outside group 2's 15 ... 300 kW
    outcome, utilisation, governing, reasons = _judged(
        outside, [(np.array([False, True]), "resonant"), (np.array([True, True]), "tips over"), (np.array([False, True]), "last")])
    assert outcome.tolist() == [FAIL, FAIL]
    assert utilisation.tolist() == [np.inf, np.inf]
    assert [reasons[g] for g in governing] == ["tips over", "last"]  # a later one governs where several hold
    outcome, _, _, _ = _judged(outside)
    assert outcome.tolist() == [WARN, WARN]  # both in an acceptable zone, warned by the code's group


def test_no_limit_and_no_code_judge_no_number():
    outcome, utilisation, governing, reasons = _judged(_limits(amplitude=None, code=None))
    assert outcome.tolist() == [PASS, PASS]
    assert np.isnan(utilisation).all() and governing.tolist() == [0, 0] and reasons == ("no steady state",)


def test_the_resonance_verdict_is_read_at_the_governing_condition():
    """Three candidates, conditions (ω = p1 order 1 judged, 2ω = p2 order 2 with a share of 0.5 %
    that the rule never lets decide) in a band of 20 %: 10 % from p1 fails at 0.2/0.1; 25 % from
    p1 passes at 0.2/0.25; a margin of 0 is inf."""
    margin = np.array([[0.10, 0.01], [0.25, 0.01], [0.0, 0.5]])
    verdict = judge(margin, [1, 2], [1.0, 0.005], [0.2, 0.2], [False, False])
    outcome, utilisation = governing_verdicts(verdict, margin)
    assert outcome.tolist() == [FAIL, PASS, FAIL]
    assert utilisation == pytest.approx([2.0, 0.8, np.inf], rel=1e-12)
    # no condition can decide (an order 2 the forcing does not drive): no number, a pass
    lone = np.array([[0.01]])
    outcome, utilisation = governing_verdicts(judge(lone, [2], [0.0], [0.2], [False]), lone)
    assert outcome.tolist() == [PASS] and np.isnan(utilisation).all()
