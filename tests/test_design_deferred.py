"""``fcalc design`` on a scene whose run-up is judged: the batch defers the run-up, the search
confirms the candidates passing the other checks by ``fcalc check``'s path, cheapest first, and
picks the first that passes it; checked against a brute force over the grid with ``run_checks``."""

from __future__ import annotations

import json

import numpy as np
import pytest
import tomli_w

from foundation_calc.checks.batch import run_checks
from foundation_calc.checks.design import reference
from foundation_calc.checks.design.apply import apply, given_dimensions
from foundation_calc.checks.design.candidates import FAIL, PASS, CandidateVerdicts
from foundation_calc.checks.design.grid import grid, parse_range
from foundation_calc.checks.design.recheck import disagreements
from foundation_calc.checks.design.search import search
from foundation_calc.cli.app import app
from foundation_calc.scenes import parse_scene, read_toml

from tests.conftest import CONFIGS

#: The block's heights of the grid [m]: 0.8 to 1.6 in steps of 0.2 (length 6 m, width 5 m).
HEIGHTS = (0.8, 1.0, 1.2, 1.4, 1.6)


def _saw_on_a_block() -> dict:
    """The sawmill frame of frame_saw_soft_soil_runup.toml on a 6 × 5 m concrete block (instead of
    its given mass), its start-up limit 16 mm: the steady checks pass from a 1.2 m high block up,
    the start-up (15.5 mm at 1.4 m, more on a lighter block) from 1.4 m up."""
    document = read_toml(CONFIGS / "frame_saw_soft_soil_runup.toml")
    document["foundation"] = {"base_length": 6.0, "base_width": 5.0,
                              "block": {"length": 6.0, "width": 5.0, "height": 1.4, "density": 2400.0}}
    document["limits"]["transient_amplitude"] = 1.6e-2
    return document


def _passes_fcalc_check(document, height: float) -> bool:
    scene = apply(document, {"foundation.block.height": height})
    return all(run.verdict in ("pass", "warn") for run in run_checks(scene))


@pytest.fixture(scope="module")
def saw():
    document = _saw_on_a_block()
    scene = parse_scene(document, "<saw>")
    from foundation_calc.checks.design import crank

    searched = grid(scene.kind, [parse_range(f"block.height={HEIGHTS[0]}:{HEIGHTS[-1]}")], None, len(HEIGHTS))
    return document, scene, searched, lambda batch: crank.evaluate(scene, batch)


def test_the_first_candidate_passing_the_full_path_is_chosen_as_brute_force_finds(saw):
    """Brute force: every grid height through run_checks; the cheapest that passes is the search's
    choice (the grid alone, no refinement), and the cheaper one the batch passes fails the run-up."""
    document, _, searched, evaluate = saw
    confirm = lambda batch: reference.evaluate(document, batch)  # noqa: E731
    found = search(searched, evaluate, given_dimensions(document), refine=0, confirm=confirm)
    brute = [h for h in HEIGHTS if _passes_fcalc_check(document, h)]
    batch_passing = [h for h in HEIGHTS if evaluate({"foundation.block.height": np.array([h])}).worst_outcome[0] < FAIL]
    assert batch_passing[0] < brute[0]  # the scene tests what it should: the batch alone would pick a failing block
    assert found.found and found.best.design(0)["foundation.block.height"] == brute[0] == 1.4
    assert found.deferred == ("runup",)
    assert found.confirmations == 2 and found.deferred_failed == 1
    assert list(found.deferred_failures) == ["runup: C, start-up"]
    assert sum(found.cheaper_failures.values()) == found.cheaper_count == 3
    assert found.pareto.design(0) == found.best.design(0)  # the Pareto set starts at the confirmed design


def test_a_bound_reached_finds_no_design_and_says_how_many_were_not_judged(saw):
    document, _, searched, evaluate = saw
    found = search(searched, evaluate, given_dimensions(document), refine=0, bound=1,
                   confirm=lambda batch: reference.evaluate(document, batch))
    assert not found.found
    assert found.confirmations == 1 and found.unconfirmed == 2  # 1.4 and 1.6 pass the batch, unjudged
    assert found.closest.design(0) == {"foundation.block.height": 1.2}


def test_a_deferred_check_is_no_disagreement_but_an_evaluated_one_is():
    def verdicts(runup, amplitudes, deferred):
        return CandidateVerdicts(np.ones(1), np.ones(1), {"amplitudes": np.array([amplitudes]), "runup": np.array([runup])},
                                 {"amplitudes": np.array([0.5]), "runup": np.array([np.nan if deferred else 1.2])},
                                 {"amplitudes": np.zeros(1, int), "runup": np.zeros(1, int)},
                                 {"amplitudes": ("C",), "runup": ("C, start-up",)}, ("runup",) if deferred else ())

    design = {"block.height": np.array([1.0])}
    assert not disagreements(design, verdicts(PASS, PASS, True), verdicts(FAIL, PASS, False))
    assert [d.check for d in disagreements(design, verdicts(PASS, PASS, False), verdicts(FAIL, PASS, False))] == ["runup"]
    assert [d.check for d in disagreements(design, verdicts(PASS, FAIL, True), verdicts(FAIL, PASS, False))] == ["amplitudes"]


def test_design_command_confirms_past_the_run_up_and_says_so(tmp_path):
    """The command (refined): its design passes fcalc check, is no dearer than the brute force's
    cheapest grid design (1.4 m), and the output says what was deferred and how many full-path
    checks it took; exit 0, not the internal error of a disagreement."""
    from typer.testing import CliRunner

    scene = tmp_path / "saw.toml"
    scene.write_text(tomli_w.dumps(_saw_on_a_block()))
    args = ["design", str(scene), "--vary", "block.height=0.8:1.6", "--points", "5", "--json"]
    result = CliRunner().invoke(app, args)
    assert result.exit_code == 0, result.output
    document = json.loads(result.stdout)
    best = document["best"]
    assert best["outcome"] in ("pass", "warn") and best["checks"]["runup"]["outcome"] == "pass"
    assert best["volume"] <= 6.0 * 5.0 * 1.4 + 1e-9
    assert 1.2 < best["values"]["foundation.block.height"] <= 1.4
    deferred = document["deferred"]
    assert deferred["checks"] == ["runup"] and deferred["full_path_checks"] >= 2 and deferred["failed"] >= 1
    assert all(d["outcome"] in ("pass", "warn") for d in document["pareto"])
    assert document["recheck"]["agree"]
