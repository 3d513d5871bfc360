"""A candidate design put into a scene (checks/design/apply.py) and the reference evaluator that
checks every candidate by ``fcalc check``'s own path (checks/design/reference.py)."""

from __future__ import annotations

import math

import numpy as np
import pytest

from foundation_calc.checks.batch import run_checks
from foundation_calc.checks.design.apply import VaryError, applied_document, apply, moved, variable
from foundation_calc.checks.design.candidates import FAIL, PASS
from foundation_calc.checks.design.reference import evaluate
from foundation_calc.scenes import parse_scene, read_toml

from tests.conftest import CONFIGS

FAN = CONFIGS / "block_fan_torsion_near_speed.toml"
COMPRESSOR = CONFIGS / "compressor_medium_sand_lysmer.toml"


def test_misspelt_key_names_the_nearest_and_the_keys_that_can_vary():
    with pytest.raises(VaryError) as caught:
        variable("block_foundation", "block.lenght")
    assert "did you mean block.length?" in str(caught.value)
    assert "block.width" in str(caught.value)


def test_crank_shorthand_and_bounds_from_the_plausible_ranges():
    found = variable("crank_foundation", "block.height")
    assert found.key == "foundation.block.height" and found.unit == "m"
    assert 0 < found.low < 1 < 10 < found.high


def test_platform_scene_cannot_vary():
    with pytest.raises(VaryError, match="sizes"):
        variable("platform", "block.length")


def test_positions_on_the_top_and_on_the_faces_follow_the_block():
    """A corner stays a corner, a machine on the top rises with it, a point inside stays put:
    the values are the geometry of the rule, by hand."""
    old, new = (5.0, 3.0, 1.6), (6.0, 4.0, 2.0)
    corner, inside, below = moved([[2.5, 1.5, 1.6], [1.0, 0.5, 2.6], [-2.5, 0.2, 0.8]], old, new)
    assert corner.tolist() == pytest.approx([3.0, 2.0, 2.0])
    assert inside.tolist() == pytest.approx([1.0, 0.5, 3.0])
    assert below.tolist() == pytest.approx([-3.0, 0.2, 0.8])


def test_moved_broadcasts_over_candidates():
    heights = np.array([1.0, 1.6, 2.4])
    out = moved([0.0, 0.0, 2.6], (5.0, 3.0, 1.6), (5.0, 3.0, heights))
    assert out.shape == (3, 3)
    assert out[:, 2].tolist() == pytest.approx([2.0, 2.6, 3.4])


def test_block_candidate_is_validated_with_the_new_dimensions():
    document = read_toml(FAN)
    scene = apply(document, {"block.length": 6.0, "block.height": 2.0})
    assert (scene.block.length, scene.block.width, scene.block.height) == (6.0, 3.0, 2.0)
    fan = next(m for m in scene.machines if m.name == "fan")
    assert fan.cog[2] == pytest.approx(3.0)  # stood 1.0 m above the top, still does
    assert document["block"]["length"] == 5.0  # the user's document is left as it was


def test_crank_keys_computed_from_the_block_are_dropped_and_recomputed():
    """Mass and base given beside [foundation.block] would disagree with a new block; they are left
    out and computed again: the mass is then the new block's plus the machine's, by hand."""
    document = read_toml(COMPRESSOR)
    document["foundation"] |= {"mass": 6.0 * 4.0 * 1.6 * 2400.0 + 14.0e3, "base_area": 24.0}
    parse_scene(document)  # the scene as given is valid
    scene = apply(document, {"block.height": 2.0})
    assert scene.foundation.mass == pytest.approx(6.0 * 4.0 * 2.0 * 2400.0 + 14.0e3)
    assert scene.foundation.base_area == pytest.approx(24.0)


def test_crank_axis_rises_with_the_machine_on_the_top():
    """The crank axis stands on the machine: its height above the base (h + a) rises with the
    block's top, whatever the new centre of mass C."""
    document = read_toml(COMPRESSOR)
    before = parse_scene(document)
    after = apply(document, {"block.height": 2.3})
    axis = lambda s: s.foundation.cog_height + s.mechanism.crank_axis_to_cog  # noqa: E731
    assert axis(after) == pytest.approx(axis(before) + 0.7)
    assert applied_document(document, {"block.height": 2.3})["foundation"]["machine"]["cog_height"] == pytest.approx(3.6)


def test_reference_evaluator_agrees_with_fcalc_check_row_by_row():
    """Each candidate's outcome is the verdict run_checks gives its scene; an amplitude's
    utilisation is the reported peak over its limit."""
    document = read_toml(COMPRESSOR)
    batch = {"block.length": np.array([6.0, 4.0]), "block.height": np.array([1.6, 1.0])}
    verdicts = evaluate(document, batch)
    for i in range(2):
        runs = {run.check: run for run in run_checks(apply(document, {k: v[i] for k, v in batch.items()}))}
        for name, run in runs.items():
            assert verdicts.outcome[name][i] == {"pass": PASS, "warn": 1, "fail": FAIL}[run.verdict]
        peak, limit = runs["amplitudes"].values["peak"][1], runs["amplitudes"].values["limit"][1]
        assert verdicts.utilisation["amplitudes"][i] == pytest.approx(peak / limit, rel=1e-12)
    assert verdicts.volume.tolist() == pytest.approx([6 * 4 * 1.6, 4 * 4 * 1.0])
    assert verdicts.mass.tolist() == pytest.approx([6 * 4 * 1.6 * 2400, 4 * 4 * 1.0 * 2400])


def test_a_candidate_that_cannot_be_built_fails_with_its_reason():
    """A 0.3 m square column 15 m tall topples on the soil's rocking spring (an invalid design in
    ``fcalc check``): every check fails there, infinitely utilised, and says why."""
    document = read_toml(COMPRESSOR)
    batch = {"block.length": np.array([0.3]), "block.width": np.array([0.3]), "block.height": np.array([15.0])}
    verdicts = evaluate(document, batch)
    assert verdicts.outcome["resonance"][0] == FAIL and verdicts.utilisation["resonance"][0] == math.inf
    assert "unstable in rocking" in verdicts.reasons["resonance"][verdicts.governing["resonance"][0]]
    assert verdicts.worst_margin[0] == -math.inf


def test_crank_helpers_on_arrays_match_the_document_rule():
    """The array helpers a vectorised crank evaluator uses give, candidate by candidate, what the
    candidate's scene holds (two heights in one call)."""
    from foundation_calc.checks.design.apply import moved_from_c, moved_machine_height

    document = read_toml(COMPRESSOR)
    before = parse_scene(document)
    heights = np.array([1.2, 2.3])
    after = [apply(document, {"block.height": h}) for h in heights]
    old, new = (6.0, 4.0, 1.6), (6.0, 4.0, heights)
    machine = moved_machine_height(before.foundation.machine.cog_height, old, new)
    assert machine.tolist() == pytest.approx([s.foundation.machine.cog_height for s in after], rel=1e-12)
    h_new = np.array([s.foundation.cog_height for s in after])
    _, a = moved_from_c(0.0, before.mechanism.crank_axis_to_cog, before.foundation.cog_height, h_new, old, new)
    assert a.tolist() == pytest.approx([s.mechanism.crank_axis_to_cog for s in after], rel=1e-12)


def test_a_crank_centre_moves_with_its_machine_where_its_own_place_would_not():
    """A crank centre on the block's end face (x = L/2) of a machine whose centre of mass lies
    inside: a longer block moves the face, not the machine. The centre goes with its machine (the
    model gives the mechanism at the machine's centre of mass), in the written scene and in the
    search's batch alike: the two evaluators agree (a centre moved by its own place, with the face,
    would put the mechanism 0.5 m from where the batch judged it)."""
    from foundation_calc.checks.design.block import evaluate as batch_evaluate
    from foundation_calc.checks.design.recheck import disagreements

    document = read_toml(CONFIGS / "block_two_throw_compressor.toml")
    document["machines"][0]["cranks"][0]["crank_centre"] = [3.0, -0.4, 3.0]  # on the end face, L/2 = 3 m
    batch = {"block.length": np.array([6.0, 7.0]), "block.height": np.array([2.0, 2.5])}
    written = applied_document(document, {"block.length": 7.0, "block.height": 2.5})
    assert written["machines"][0]["cog"] == pytest.approx([0.0, 0.0, 3.4])
    assert written["machines"][0]["cranks"][0]["crank_centre"] == pytest.approx([3.0, -0.4, 3.5])
    assert written["points"][1]["at"] == pytest.approx([3.5, 2.0, 2.5])  # a point on the corner follows the faces
    searched = batch_evaluate(parse_scene(document, "face"), batch)
    assert [d.text for d in disagreements(batch, searched, evaluate(document, batch))] == []
