"""``fcalc design --margin M``: a candidate passes only when every utilisation is at most 1 - M; the
search's answer against a plain enumeration of a made-up rule, a deferred check confirmed against
the reserve, the note that the answer sits on a limit, and the option's range."""

from __future__ import annotations

import itertools
import json

import numpy as np
import pytest
from typer.testing import CliRunner

from foundation_calc.checks.design.candidates import FAIL, PASS, WARN, CandidateVerdicts
from foundation_calc.checks.design.grid import Range, grid
from foundation_calc.checks.design.reserve import on_limit
from foundation_calc.checks.design.search import passing, search
from foundation_calc.cli.app import app

from tests.conftest import CONFIGS

FAN = CONFIGS / "block_fan_torsion_near_speed.toml"

#: The made-up rule's grid: 13 × 7 × 6 candidates.
RANGES = [Range("block.length", 3, 9), Range("block.width", 1, 4), Range("block.height", 0.5, 3)]
GIVEN = {"block.length": 5.0, "block.width": 3.0, "block.height": 1.6}


def _rule(L, B, H):
    """Utilisations of the made-up rule: a resonance 9/(L + 2B - H), an office check H/4 and a
    rule of thumb 40/(L B H) that only warns beyond 1 (as the mass ratio does)."""
    return {"resonance": 9.0 / (L + 2 * B - H), "office": H / 4.0, "thumb": 40.0 / (L * B * H)}


def _verdicts(batch, deferred: bool = False) -> CandidateVerdicts:
    L, B, H = batch["block.length"], batch["block.width"], batch["block.height"]
    util = _rule(L, B, H)
    outcome = {"resonance": np.where(util["resonance"] > 1, FAIL, PASS), "office": np.where(util["office"] > 1, FAIL, PASS),
               "thumb": np.where(util["thumb"] > 1, WARN, PASS)}
    if deferred:  # the thumb left to a slower path, as a batch leaves the run-up
        outcome["thumb"], util = np.full(L.shape, PASS), {**util, "thumb": np.full(L.shape, np.nan)}
    return CandidateVerdicts(L * B * H, 2400 * L * B * H, {k: v.astype(np.int8) for k, v in outcome.items()}, util,
                             {k: np.zeros(L.shape, int) for k in outcome}, {k: (k,) for k in outcome},
                             ("thumb",) if deferred else ())


def _enumerated(margin: float | None, strict: bool = False) -> float:
    """The least volume over the grid, by the rule written out candidate by candidate: no check
    fails (a warning passes unless strict), and with a reserve every utilisation <= 1 - margin."""
    axes = [np.linspace(r.low, r.high, n) for r, n in zip(RANGES, (13, 7, 6))]
    volumes = []
    for L, B, H in itertools.product(*axes):
        util = _rule(L, B, H)
        fails = util["resonance"] > 1 or util["office"] > 1 or (strict and util["thumb"] > 1)
        short = margin is not None and max(util.values()) > 1 - margin
        if not fails and not short:
            volumes.append(L * B * H)
    return min(volumes)


def _grid():
    return grid("block_foundation", RANGES, step=0.5)


@pytest.mark.parametrize("margin", [None, 0.0, 0.1, 0.3])
def test_the_cheapest_with_a_reserve_is_the_enumerations(margin):
    """On the grid alone (no refinement): the search's answer has the least volume of the
    candidates that keep the reserve, and keeps it."""
    found = search(_grid(), _verdicts, GIVEN, refine=0, margin=margin)
    assert found.best.volume[0] == pytest.approx(_enumerated(margin), rel=1e-12)
    utilisation = _rule(*found.best.design(0).values())
    assert max(utilisation.values()) <= 1 - (margin or 0.0) or margin is None


def test_a_reserve_is_asked_of_a_warning_too():
    """Without a reserve a warning beyond its limit passes (fcalc check's rule); --margin 0 asks
    every utilisation to be at most 1, and the answer moves to a block the warning clears."""
    free, held = (search(_grid(), _verdicts, GIVEN, refine=0, margin=m) for m in (None, 0.0))
    assert max(_rule(*free.best.design(0).values()).values()) > 1  # the scene tests what it should
    assert held.best.volume[0] > free.best.volume[0]
    assert held.best.volume[0] == pytest.approx(_enumerated(None, strict=True), rel=1e-12)


def test_candidates_short_of_the_reserve_are_tallied():
    """Every cheaper candidate is counted under the check that keeps it from passing, those that
    only lack the reserve too."""
    found = search(_grid(), _verdicts, GIVEN, refine=0, margin=0.2)
    assert sum(found.cheaper_failures.values()) == found.cheaper_count > 0
    plain = search(_grid(), _verdicts, GIVEN, refine=0)
    assert found.cheaper_count > plain.cheaper_count


def test_a_deferred_check_is_confirmed_against_the_reserve():
    """The batch leaves the thumb to the full path (NaN, no reserve asked there); the full path
    judges it against 1 - M: the answer is the enumeration's with every check held to the reserve."""
    found = search(_grid(), lambda b: _verdicts(b, deferred=True), GIVEN, refine=0, margin=0.1,
                   confirm=_verdicts, bound=10_000)
    assert found.deferred == ("thumb",) and found.deferred_failed > 0
    assert found.best.volume[0] == pytest.approx(_enumerated(0.1), rel=1e-12)
    assert passing(_verdicts(found.best.values), False, 0.1)[0]


def test_on_limit_names_the_check_within_one_percent_of_its_bound():
    design = {"block.length": np.array([6.0]), "block.width": np.array([3.35]), "block.height": np.array([2.0])}
    verdicts = _verdicts(design)  # resonance 9/10.7 = 0.84, office 0.5, thumb 40/40.2 = 0.995
    found = on_limit(verdicts, 0, None)
    assert found.check == "thumb" and found.limit == 1.0 and found.utilisation == pytest.approx(40 / 40.2)
    assert on_limit(verdicts, 0, 0.01).check == "thumb"  # within 1 % of 0.99
    assert on_limit(verdicts, 0, 0.5).check == "office"  # 0.5 at its bound; the thumb, far beyond it, is no note
    assert on_limit(verdicts, 0, 0.1) is None


@pytest.fixture(scope="module")
def fan_runs():
    """The fan block on a fine grid around its answer, without and with a 5 % reserve (JSON)."""
    runner = CliRunner()
    args = ["design", str(FAN), "--vary", "block.length=5:5.4", "--vary", "block.width=5.5:5.8", "--vary",
            "block.height=4:4", "--step", "0.02", "--json"]
    return [runner.invoke(app, args + extra) for extra in ([], ["--margin", "0.05"])]


def test_the_fan_without_a_reserve_sits_on_a_limit(fan_runs):
    result = fan_runs[0]
    assert result.exit_code == 0, result.output
    document = json.loads(result.stdout)
    assert document["margin"] is None and document["best"]["worst_margin"] < 0.01
    assert document["on_limit"]["check"] == "resonance" and document["on_limit"]["limit"] == 1.0
    assert document["on_limit"]["governing"] == document["best"]["checks"]["resonance"]["governing"]


def test_the_fan_with_a_reserve_keeps_it_by_fcalc_checks_path(fan_runs):
    """The answer's utilisations, as fcalc check's path judges them (the re-check), are at most
    0.95 (within the re-check's agreement, 1e-6); it is dearer than the answer without a reserve."""
    plain, reserved = (json.loads(r.stdout) for r in fan_runs)
    assert fan_runs[1].exit_code == 0, fan_runs[1].output
    assert reserved["margin"] == 0.05 and reserved["recheck"]["agree"]
    utilisations = [c["utilisation"] for c in reserved["best"]["checks"].values() if c["utilisation"] is not None]
    assert max(utilisations) <= 0.95 * (1 + 1e-6)
    assert reserved["best"]["volume"] > plain["best"]["volume"]
    assert all(d["worst_margin"] >= 0.05 - 1e-6 for d in reserved["pareto"])
    assert reserved["on_limit"]["limit"] == pytest.approx(0.95)


def test_the_text_says_the_reserve_and_the_limit(tmp_path):
    args = ["design", str(FAN), "--vary", "block.length=5.2:5.4", "--vary", "block.width=5.6:5.8", "--vary",
            "block.height=4:4", "--step", "0.02", "--margin", "0.05"]
    result = CliRunner().invoke(app, args, env={"COLUMNS": "200"})
    assert result.exit_code == 0, result.output
    assert "reserve: every utilisation at most 0.95 (--margin 0.05)" in result.stdout
    assert "on a limit: resonance (fan: ω = mode 6" in result.stdout


@pytest.mark.parametrize("value", ["1", "-0.1", "nan", "1.5"])
def test_a_margin_outside_its_range_is_a_usage_error(value):
    result = CliRunner().invoke(app, ["design", str(FAN), "--vary", "block.length=5:6", "--margin", value])
    assert result.exit_code == 2, result.output
    assert "'--margin'" in result.output and "0 <= M < 1" in " ".join(result.output.split())
