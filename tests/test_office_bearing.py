"""The office check's bearing pressure under a base that does not bear on the soil.

A pile cap without ``piles.cap_contact`` rests on its piles: the soil under it carries nothing, so
``[limits] bearing_pressure`` has no pressure to judge there (checks/office.py, its module
docstring). ``fcalc check`` reports the row as not applicable, with its reason and no number, for a
piled block and a piled crank alike, and the design batch (checks/design/block.py) judges each
candidate as ``fcalc check`` judges its scene; a cap that bears (``cap_contact = true``) is judged
on q as a footing is. The allowable, 10 kPa, is far below the caps' own q (the block's W/(L B) =
117.7 t g/24 m² = 48 kPa before its eccentricity term, the crank's W/S = 106.4 t g/24 m² = 43 kPa),
so that a computed q fails.
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

ALLOWABLE = 1.0e4  # [Pa]


def _document(config: str, cap_contact: bool) -> dict:
    with open(CONFIGS / config, "rb") as fh:
        document = tomllib.load(fh)
    document["piles"]["cap_contact"] = cap_contact
    document["limits"]["bearing_pressure"] = ALLOWABLE
    return document


def _bearing(document) -> dict:
    found = fc.check(document).to_dict()["checks"]
    office = next(c for c in found if c["check"] == "office")
    return next(row for row in office["result"]["office"] if row["check"] == "bearing pressure"), office


@pytest.mark.parametrize("config", ["block_on_piles.toml", "crank_on_piles.toml"])
def test_a_cap_on_its_piles_has_no_bearing_pressure(config):
    row, office = _bearing(_document(config, cap_contact=False))
    assert row["value"] is None and row["verdict"] == "pass"
    assert row["text"].startswith("not applicable: the base does not bear on the soil") and "kPa" not in row["text"]
    assert office["verdict"] == "pass"
    row, office = _bearing(_document(config, cap_contact=True))
    assert row["value"] > 4.0 * ALLOWABLE and row["verdict"] == office["verdict"] == "fail"


@pytest.mark.parametrize("cap_contact", [False, True])
def test_the_design_batch_judges_the_bearing_pressure_as_fcalc_check(cap_contact):
    """The batch's office outcome of two candidate caps is the one fcalc check gives each candidate's
    scene (the re-check finds no disagreement): pass on the piles alone, fail on a cap that bears."""
    document = _document("block_on_piles.toml", cap_contact)
    candidates = {"block.length": np.array([6.0, 7.0])}
    searched = evaluate(parse_scene(document, "piles.toml"), candidates)
    full, found = recheck(document, candidates, searched, "piles.toml")
    expected = [2, 2] if cap_contact else [0, 0]
    assert searched.outcome["office"].tolist() == full.outcome["office"].tolist() == expected
    assert [d.text for d in found] == []
