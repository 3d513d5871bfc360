"""``fcalc design``: the cheapest passing block against a brute-force grid checked by ``fcalc check``'s
path, the written design, the chunked walk, and the bad input."""

from __future__ import annotations

import json

import numpy as np
import pytest

from foundation_calc.checks.batch import run_checks
from foundation_calc.checks.design.apply import apply
from foundation_calc.checks.design.candidates import FAIL, PASS, CandidateVerdicts
from foundation_calc.checks.design.grid import Range, grid
from foundation_calc.checks.design.search import search
from foundation_calc.cli.app import app
from foundation_calc.scenes import read_toml

from tests.conftest import CONFIGS

FAN = CONFIGS / "block_fan_torsion_near_speed.toml"
COMPRESSOR = CONFIGS / "compressor_medium_sand_lysmer.toml"

#: A 3 × 3 × 3 grid on which the fan passes only on the larger blocks (its torsion and rocking
#: modes must fall 20 % below the running speed).
FAN_RANGES = ["block.length=5:8", "block.width=5:7", "block.height=3:4"]


def _brute_force_cheapest(document) -> float:
    """Volume of the cheapest grid candidate whose every check passes ``run_checks``, one by one."""
    volumes = []
    for length in (5.0, 6.5, 8.0):
        for width in (5.0, 6.0, 7.0):
            for height in (3.0, 3.5, 4.0):
                scene = apply(document, {"block.length": length, "block.width": width, "block.height": height})
                if all(run.verdict in ("pass", "warn") for run in run_checks(scene)):
                    volumes.append(length * width * height)
    return min(volumes)


@pytest.fixture(scope="module")
def fan_design(tmp_path_factory, runner_module):
    written = tmp_path_factory.mktemp("design") / "best.toml"
    args = ["design", str(FAN), *[a for r in FAN_RANGES for a in ("--vary", r)], "--points", "3", "--json", "--write", str(written)]
    result = runner_module.invoke(app, args)
    return result, written


@pytest.fixture(scope="module")
def runner_module():
    from typer.testing import CliRunner

    return CliRunner()


def test_no_grid_design_is_cheaper_and_passes(fan_design):
    """Brute force: every candidate of the same grid through run_checks; the design the search
    picks (refined, so possibly off the grid) is no dearer than the cheapest that passes there,
    and passes itself."""
    result, _ = fan_design
    assert result.exit_code == 0, result.output
    document = json.loads(result.stdout)
    cheapest = _brute_force_cheapest(read_toml(FAN))
    assert document["best"]["volume"] <= cheapest + 1e-9
    assert document["best"]["outcome"] in ("pass", "warn")
    assert document["recheck"]["agree"] and not document["recheck"]["disagreements"]


def test_written_design_passes_fcalc_check(fan_design, runner_module):
    result, written = fan_design
    best = json.loads(result.stdout)["best"]["values"]
    assert runner_module.invoke(app, ["check", str(written)]).exit_code == 0
    block = read_toml(written)["block"]
    assert [block["length"], block["width"], block["height"]] == pytest.approx(list(best.values()), abs=0)


def test_cheaper_failures_are_tallied_by_governing_check(fan_design):
    document = json.loads(fan_design[0].stdout)
    assert sum(row["count"] for row in document["cheaper_failures"]) == document["cheaper_candidates"] > 0
    assert {row["check"] for row in document["cheaper_failures"]} == {"resonance"}


def _synthetic(batch) -> CandidateVerdicts:
    """Verdicts of a made-up rule (a block passes when L + 2B - H > 9), to test the walk alone."""
    L, B, H = batch["block.length"], batch["block.width"], batch["block.height"]
    util = 9.0 / (L + 2 * B - H)
    office = H / 4.0
    return CandidateVerdicts(
        L * B * H, 2400 * L * B * H,
        {"resonance": np.where(util > 1, FAIL, PASS).astype(np.int8), "office": np.where(office > 1, FAIL, PASS).astype(np.int8)},
        {"resonance": util, "office": office},
        {"resonance": (L > 6).astype(int), "office": np.zeros(L.shape, int)},
        {"resonance": ("short", "long"), "office": ("height",)},
    )


def test_chunks_give_the_result_of_one_chunk():
    searched = grid("block_foundation", [Range("block.length", 3, 9), Range("block.width", 1, 4), Range("block.height", 0.5, 3)],
                    step=0.25)
    given = {"block.length": 5.0, "block.width": 3.0, "block.height": 1.6}
    whole = search(searched, _synthetic, given, chunk=searched.size)
    parts = search(searched, _synthetic, given, chunk=97)
    assert parts.chunks == 37 and whole.chunks == 1  # 25 × 13 × 11 = 3575 candidates
    assert parts.best.design(0) == whole.best.design(0)
    assert np.array_equal(parts.pareto.volume, whole.pareto.volume)
    assert np.array_equal(parts.pareto.margin, whole.pareto.margin)
    assert parts.cheaper_failures == whole.cheaper_failures and parts.fail_counts == whole.fail_counts


def test_synthetic_cheapest_is_the_rules_boundary():
    """Against the made-up rule enumerated in plain Python over the same grid: the search's design
    (refined, so possibly between grid points) passes the rule and is no dearer."""
    searched = grid("block_foundation", [Range("block.length", 3, 9), Range("block.width", 1, 4), Range("block.height", 0.5, 3)],
                    step=0.25)
    found = search(searched, _synthetic, {"block.length": 5.0, "block.width": 3.0, "block.height": 1.6})
    best = found.best.design(0)
    L, B, H = best["block.length"], best["block.width"], best["block.height"]
    assert 9.0 / (L + 2 * B - H) <= 1
    volumes = [l * b * h for l in np.arange(3, 9.01, 0.25) for b in np.arange(1, 4.01, 0.25) for h in np.arange(0.5, 3.01, 0.25)
               if 9.0 / (l + 2 * b - h) <= 1]
    assert L * B * H <= min(volumes) + 1e-9


@pytest.mark.parametrize(("args", "message"), [
    (["--vary", "block.lenght=4:8"], "did you mean block.length?"),
    (["--vary", "block.length=8:4"], "low end is above the high end"),
    (["--vary", "block.length=4:8", "--step", "0"], "must be > 0"),
    (["--vary", "block.length=4:8", "--step", "-0.1"], "must be > 0"),
    (["--vary", "block.length=0.3:60", "--vary", "block.width=0.3:60", "--vary", "block.height=0.2:15", "--step", "0.01"],
     "more than the"),
    (["--vary", "block.length=4:600"], "outside the bounds"),
    (["--vary", "block.length=4-8"], "KEY=LOW:HIGH"),
    (["--vary", "block.length=4:8", "--vary", "block.length=5:6"], "more than once"),
])
def test_bad_options_are_usage_errors(runner_module, args, message):
    result = runner_module.invoke(app, ["design", str(FAN), *args])
    assert result.exit_code == 2, result.output
    assert message in " ".join(result.output.split())


def test_crank_scene_without_a_block_cannot_vary(runner_module):
    result = runner_module.invoke(app, ["design", str(CONFIGS / "frame_saw.toml"), "--vary", "block.length=4:8"])
    assert result.exit_code == 2 and "[foundation.block]" in result.output


def test_invalid_scene_exits_3(runner_module, tmp_path):
    bad = tmp_path / "bad.toml"
    bad.write_text(FAN.read_text().replace("length = 5.0", "length = -5.0"))
    assert runner_module.invoke(app, ["design", str(bad), "--vary", "block.height=1:2"]).exit_code == 3


def test_nothing_passes_names_the_check_and_the_closest(runner_module):
    """On blocks near the given one the fan's torsion stays in its band: every candidate fails
    the resonance rule; the closest one's worst utilisation is over 1."""
    result = runner_module.invoke(app, ["design", str(FAN), "--vary", "block.length=4.5:5.5", "--points", "2", "--json"])
    assert result.exit_code == 1, result.output
    document = json.loads(result.stdout)
    assert not document["passed"] and document["best"] is None
    assert document["fails_everywhere"] == ["resonance"]
    assert document["closest"]["worst_margin"] < 0
    text = runner_module.invoke(app, ["design", str(FAN), "--vary", "block.length=4.5:5.5", "--points", "2"]).output
    assert "no candidate passes" in text and "resonance" in text and "worst utilisation" in text


#: A shipped scene of each kind fcalc design sizes.
KIND_SCENES = {"block_foundation": FAN, "crank_foundation": COMPRESSOR}


@pytest.mark.parametrize("kind", sorted(KIND_SCENES))
def test_vectorised_evaluator_agrees_with_fcalc_check(kind):
    """Each kind's vectorised evaluator against fcalc check's path on the same candidates (blocks
    0.6 to 1.6 times the scene's in each dimension, machines moved with them): every check's
    outcome equal, utilisation within the re-check's 1e-6."""
    import importlib

    from foundation_calc.checks.design.apply import given_dimensions
    from foundation_calc.checks.design.candidates import EVALUATORS
    from foundation_calc.checks.design.recheck import recheck
    from foundation_calc.scenes import parse_scene

    if kind not in EVALUATORS:
        pytest.skip(f"no vectorised evaluator for {kind}: fcalc design judges it by fcalc check's path")
    document = read_toml(KIND_SCENES[kind])
    rng = np.random.default_rng(3)
    batch = {key: value * rng.uniform(0.6, 1.6, 12) for key, value in given_dimensions(document).items()}
    searched = importlib.import_module(EVALUATORS[kind]).evaluate(parse_scene(document), batch)
    _, found = recheck(document, batch, searched)
    rule = ("the candidate's scene is checks/design/apply.py's: machines, loads and points on the block's top rise"
            " with it, those on an end face follow it (a crank's C-relative heights re-measured from the new C)")
    assert not found, (rule, [d.text for d in found])


def test_block_evaluator_judges_a_modulus_range_as_fcalc_checks_path():
    """A scene with a soil modulus_range: the vectorised block evaluator judges the range (its grid
    factors and crossings) and agrees with fcalc check's path, check by check."""
    from foundation_calc.checks.design import reference
    from foundation_calc.checks.design.block import evaluate
    from foundation_calc.scenes import parse_scene

    document = read_toml(FAN)
    document["soil"]["modulus_range"] = [0.7, 1.5]
    batch = {"block.height": np.array([1.2, 2.4])}
    fast, slow = evaluate(parse_scene(document), batch), reference.evaluate(document, batch, source="range")
    for check in ("resonance", "amplitudes", "office"):
        assert fast.outcome[check].tolist() == slow.outcome[check].tolist(), check


def test_strict_crank_sizing_against_brute_force(runner_module):
    """The compressor's crank foundation with --strict (the mass-ratio warning fails): on a
    3 × 3 × 3 grid checked one by one through run_checks, no candidate that passes without a
    warning is cheaper than the design the search picks, which itself passes so."""
    args = ["design", str(COMPRESSOR), "--vary", "block.length=3:8", "--vary", "block.width=2:5",
            "--vary", "block.height=0.8:2.4", "--points", "3", "--strict", "--json"]
    result = runner_module.invoke(app, args)
    assert result.exit_code == 0, result.output
    best = json.loads(result.stdout)["best"]
    document = read_toml(COMPRESSOR)
    volumes = [
        length * width * height
        for length in (3.0, 5.5, 8.0) for width in (2.0, 3.5, 5.0) for height in (0.8, 1.6, 2.4)
        if all(run.verdict == "pass" for run in run_checks(apply(document, {"block.length": length, "block.width": width,
                                                                          "block.height": height})))
    ]
    assert best["volume"] <= min(volumes) + 1e-9
    assert best["outcome"] == "pass"


def test_nothing_written_when_nothing_passes(runner_module, tmp_path):
    written = tmp_path / "best.toml"
    result = runner_module.invoke(app, ["design", str(FAN), "--vary", "block.length=4.5:5.5", "--points", "2",
                                        "--write", str(written)])
    assert result.exit_code == 1 and not written.exists()
    assert "not written: no candidate passes" in result.output
