"""``fcalc design`` with candidates that cannot be evaluated (an error of their physics, as the former
ω = p(K(ω)) iteration raised on 0.8 % of plausible blocks on Gazetas' soil): each is counted,
named with an example and left out; the search goes on and finds what it finds without them."""

from __future__ import annotations

import json

import numpy as np
import pytest

from foundation_calc.checks.design.grid import Range, grid
from foundation_calc.checks.design.search import search
from foundation_calc.cli.app import app
from foundation_calc.errors import PhysicsError
from tests.conftest import CONFIGS
from tests.test_design_search import _synthetic

GIVEN = {"block.length": 5.0, "block.width": 3.0, "block.height": 1.6}
CHEAP = {"block.length": 3.0, "block.width": 1.0, "block.height": 0.5}  # fails the made-up rule, cheaper than the answer
DEAR = {"block.length": 6.0, "block.width": 2.0, "block.height": 1.0}  # passes it, dearer than the answer


def _grid():
    return grid("block_foundation", [Range("block.length", 3, 9), Range("block.width", 1, 4), Range("block.height", 0.5, 3)],
                step=0.25)


def _raising(batch, errors):
    """:func:`_synthetic`, raising ``errors[i]`` on a batch that holds candidate i of (CHEAP, DEAR)."""
    for design, error in zip((CHEAP, DEAR), errors):
        if error is not None and np.any(np.logical_and.reduce([batch[k] == v for k, v in design.items()])):
            raise error
    return _synthetic(batch)


def test_candidates_that_raise_are_counted_named_and_left_out():
    """Two candidates raise (an ArithmeticError, a PhysicsError) inside chunks of 97: the search
    counts each once under its error with its values and message, judges the other 3573, and its
    answer, Pareto set and tally of the cheaper candidates are those of the search without the two
    (the cheaper one, a failing candidate, missing from the tally)."""
    whole = search(_grid(), _synthetic, GIVEN, chunk=97)
    found = search(_grid(), lambda b: _raising(b, (ArithmeticError("did not converge"), PhysicsError("tips over"))), GIVEN,
                   chunk=97)
    assert found.unevaluated == {"ArithmeticError": (1, CHEAP, "did not converge"), "PhysicsError": (1, DEAR, "tips over")}
    assert found.unevaluated_count == 2 and found.evaluated == whole.evaluated - 2
    assert found.best.design(0) == whole.best.design(0)
    assert np.array_equal(found.pareto.volume, whole.pareto.volume)
    assert found.cheaper_count == whole.cheaper_count - 1
    assert sum(found.cheaper_failures.values()) == sum(whole.cheaper_failures.values()) - 1


def test_a_bug_is_not_hidden_and_nothing_evaluated_is_an_error():
    """An error that is no design's (a RuntimeError: a bug) ends the search; so does the first
    error when no candidate at all can be evaluated (there is nothing to report)."""
    with pytest.raises(RuntimeError):
        search(_grid(), lambda b: _raising(b, (RuntimeError("bug"), None)), GIVEN, chunk=97)
    with pytest.raises(ArithmeticError, match="nowhere"):
        search(_grid(), lambda b: (_ for _ in ()).throw(ArithmeticError("nowhere")), GIVEN, chunk=1000)


def test_fcalc_design_reports_a_candidate_it_cannot_evaluate(monkeypatch):
    """``fcalc design`` on the fan block with its evaluator raising on one grid candidate (5 × 5 ×
    3 m): exit 0 with the design it finds without it, the candidate counted in the JSON document and
    named in the text."""
    from typer.testing import CliRunner

    import foundation_calc.checks.design.block as block

    evaluate = block.evaluate

    def raising(scene, batch):
        if np.any((batch["block.length"] == 5.0) & (batch["block.width"] == 5.0) & (batch["block.height"] == 3.0)):
            raise ArithmeticError("ω = p(K(ω)) did not converge")
        return evaluate(scene, batch)

    monkeypatch.setattr(block, "evaluate", raising)
    args = ["design", str(CONFIGS / "block_fan_torsion_near_speed.toml"), "--vary", "block.length=5:8", "--vary",
            "block.width=5:7", "--vary", "block.height=3:4", "--points", "3"]
    result = CliRunner().invoke(app, [*args, "--json"])
    assert result.exit_code == 0, result.output
    document = json.loads(result.stdout)
    assert document["passed"] and document["unevaluated"] == {"count": 1, "errors": [
        {"error": "ArithmeticError", "count": 1, "example": {"block.length": 5.0, "block.width": 5.0, "block.height": 3.0},
         "message": "ω = p(K(ω)) did not converge"}]}
    text = " ".join(CliRunner().invoke(app, args, env={"COLUMNS": "80"}).output.split())
    assert "1 candidate could not be evaluated" in text and "ArithmeticError (1), e.g. 5.000 × 5.000 × 3.000 m" in text
