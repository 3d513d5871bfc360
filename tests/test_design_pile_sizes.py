"""A pile group's sizes in ``fcalc design``: each candidate's piles are judged as ``fcalc check``
judges the design written with them.

The batch (:func:`~foundation_calc.checks.design.block.evaluate`) must give every check of every
candidate the outcome that ``fcalc check``'s own path gives the candidate's scene
(:func:`~foundation_calc.checks.design.reference.evaluate`: the candidate put into the document,
then every check), and the utilisations within the re-check's agreement (1e-6,
:data:`~foundation_calc.checks.design.recheck.UTILISATION_AGREEMENT`). The candidates cross the
thresholds of the piles' plausibility warnings (Randolph & Wroth's L/d range 10-100, the spacing
2 d of Dobry & Gazetas' factors) that the scene as given does not, and the other way round (a batch
that took the scene's warnings as given said "pass", or "warn", where fcalc check says otherwise);
one's piles overlap, a scene fcalc check refuses; and stiff or closely spaced groups, whose modes
the batch took for a block that tips over (a dynamic spring negative at a high mode's frequency)
where fcalc check judges them.
"""

from __future__ import annotations

import tomllib

import numpy as np
import pytest

import foundation_calc as fc
from foundation_calc.checks.design.block import evaluate
from foundation_calc.checks.design.recheck import recheck
from foundation_calc.scenes import parse_scene
from tests.conftest import CONFIGS

PILED = CONFIGS / "block_on_piles.toml"

#: Candidates of the shipped piled block (d = 0.6 m, L = 16 m, heads 2.4 m apart along x on a 6 m
#: base, 3.0 m along y on a 4 m one): its own piles; L/d = 5/0.6 = 8.3 < 10; L/d = 70/0.6 = 117 >
#: 100; d = 1.3 m, the heads 2.4 m < 2 d = 2.6 m apart; a base 1.5 m wide, the heads 3.0 × 1.5/4 =
#: 1.125 m < 1.2 m apart; one 1.7 m wide, 1.275 m apart; d = 2.5 m, the piles overlap (2.4 m < d
#: apart): fcalc check refuses the scene.
CANDIDATES = {"piles.length": np.array([16.0, 5.0, 70.0, 16.0, 16.0, 16.0, 16.0]),
              "piles.diameter": np.array([0.6, 0.6, 0.6, 1.3, 0.6, 0.6, 2.5]),
              "block.width": np.array([4.0, 4.0, 4.0, 4.0, 1.5, 1.7, 4.0])}


def _document(**piles):
    with open(PILED, "rb") as fh:
        document = tomllib.load(fh)
    document["piles"] |= piles
    return document


@pytest.mark.parametrize("piles", [{}, {"length": 5.0}], ids=["scene's piles plausible", "scene's piles too short"])
def test_each_candidates_piles_are_judged_as_fcalc_check_judges_its_scene(piles):
    document = _document(**piles)
    searched = evaluate(parse_scene(document, "piles.toml"), CANDIDATES)
    full, found = recheck(document, CANDIDATES, searched, "piles.toml")
    assert full.outcome["inputs"].tolist() == [0, 1, 1, 1, 1, 0, 0]  # fcalc check: the crossings warn, whatever the scene's own
    assert full.outcome["scene"].tolist() == searched.outcome["scene"].tolist() == [0, 0, 0, 0, 0, 0, 2]  # the overlap
    assert [d.text for d in found] == []


def test_a_written_design_with_short_piles_is_the_one_fcalc_check_judges(tmp_path):
    """The cheapest design takes piles too short for Randolph & Wroth's range (L/d < 10): the
    search warns of it, as fcalc check does on the written scene (a batch that took the scene's
    own L/d = 26.7 said "pass": the re-check disagreed, exit 4)."""
    scene = tmp_path / "piled.toml"
    scene.write_text(PILED.read_text(encoding="utf-8"), encoding="utf-8")
    written = tmp_path / "written.toml"
    result = fc.design(scene, vary=["piles.length=5:9"], points=2, write=written)
    assert result.exit_code == 0, result.to_dict()
    best = result.to_dict()["best"]
    assert best["values"] == {"piles.length": 5.0} and best["checks"]["inputs"]["outcome"] == "warn"
    checked = fc.check(written).to_dict()
    with open(written, "rb") as fh:
        assert tomllib.load(fh)["piles"]["length"] == 5.0
    assert {c["check"]: c["verdict"] for c in checked["checks"]}["inputs"] == "warn"


@pytest.mark.parametrize("config", ["block_two_machines.toml", "compressor_medium_sand_lysmer.toml"])
def test_a_pile_size_in_a_scene_without_piles_is_a_usage_error(config):
    """A support's size that the scene's support does not have: exit 2 naming what has it, before any search."""
    from foundation_calc.errors import UsageError

    with pytest.raises(UsageError, match=r"piles.length varies only in a scene with \[piles\]"):
        fc.design(CONFIGS / config, vary=["piles.length=10:20"])
