"""`fcalc platform`: the acceptance commands, every shipped platform scene, flags and errors."""

from __future__ import annotations

import copy
import json
import math

import pytest
import tomli_w

from foundation_calc.cli.app import app
from foundation_calc.scenes import read_toml
from tests.conftest import CONFIGS, configs_of_kind

ACCEPT = ["platform", "--omega", "157.07963267948966", "--amp", "1e-3", "--json"]


def _finite(node):
    if isinstance(node, dict):
        return all(_finite(v) for v in node.values())
    if isinstance(node, list):
        return all(_finite(v) for v in node)
    return not isinstance(node, float) or math.isfinite(node)


#: Shipped scenes that fail on purpose, one per failure mode (docs/examples.md).
DELIBERATELY_FAILING = {"platform_thin_regime_margin.toml", "platform_translation_mode_near_speed.toml"}


def _run_json(runner, args, exit_code=0):
    result = runner.invoke(app, args)
    assert result.exit_code == exit_code, result.stderr
    assert result.stderr == ""
    doc = json.loads(result.stdout)
    assert doc["command"] == "platform" and _finite(doc)
    return doc


@pytest.mark.parametrize(
    "omega,expected",
    [
        (157.07963267948966, {"c0": 3.7073e8, "c11+c21": 1.2399e8, "c31+c41": 2.4674e8, "c": 2.6127}),
        (50.0, {"c0": 3.75625e7, "c11+c21": 1.25625e7, "c31+c41": 2.5e7, "c": 2.6091}),
    ],
    ids=["omega-50pi", "omega-50"],
)
def test_acceptance_commands_reproduce_the_corrected_example(runner, omega, expected):
    doc = _run_json(runner, ["platform", "--omega", repr(omega), "--amp", "1e-3", "--json"])
    d, w2, M, m = doc["design"], omega**2, 2e4, 25.0
    # closed forms of the note (3.14), (3.19)-(3.21), (3.15) to 1e-9
    assert d["c0"] == pytest.approx((M + m) * w2 - m * 0.2 * w2 / 1e-3, rel=1e-9)
    assert d["c31+c41"] == pytest.approx(M * w2 / 2, rel=1e-9)
    assert d["c22+c32"] == pytest.approx(M * w2 / 2, rel=1e-9)
    assert d["c11+c21"] == pytest.approx(w2 * ((M + 2 * m) / 2 - m * 0.2 / 1e-3), rel=1e-9)
    assert d["c12+c42"] == pytest.approx(d["c11+c21"], rel=1e-12)
    assert d["c13"] == pytest.approx(1.005e8, rel=1e-12) and d["c3"] == pytest.approx(4.005e8, rel=1e-12)
    assert d["static_deflection"] == pytest.approx(-4.905e-4, rel=1e-12)
    assert d["c"] == pytest.approx((m * 9.81 * 0.2 - M * 1e-3 * 0.65 * w2) / (m * w2 * (1e-3 - 0.2)), rel=1e-9)
    for key, value in expected.items():  # the note's table, printed precision
        assert d[key] == pytest.approx(value, rel=6e-5), key
    assert doc["speed"]["omega"] == omega and doc["speed"]["given_as"].startswith("--omega")
    assert doc["verification"]["rocking_percent"] < 1e-10
    assert len(d["stiffness_table"]) == 4 and len(d["stiffness_table"][0]) == 3


@pytest.mark.parametrize("config", configs_of_kind("platform"), ids=lambda p: p.name)
def test_every_platform_config(runner, config):
    failing = config.name in DELIBERATELY_FAILING
    doc = _run_json(runner, ["platform", str(config), "--json"], 1 if failing else 0)
    assert doc["verdict"] == "fail" if failing else doc["verdict"] in {"pass", "warn"}
    if not read_toml(config)["isolators"].get("loss_factor"):
        assert doc["verification"]["rocking_percent"] < 1e-9
        (rocking,) = (c for c in doc["checks"] if c["name"] == "rocking")  # its round-off said as the table says it
        assert rocking["message"].startswith("rocking 0 % of u"), rocking["message"]
    table = runner.invoke(app, ["platform", str(config)])
    assert table.exit_code == (1 if failing else 0) and table.stderr == ""
    for text in ("rad/s", "Hz", "rpm", "N/m", "% of u", "Sensitivity"):
        assert text in table.stdout


def test_explicit_vertical_scene_gives_a_b_from_3_9_3_10(runner):
    doc = _run_json(runner, ["platform", str(CONFIGS / "platform_explicit_vertical.toml"), "--json"])
    d, i = doc["design"], doc["inputs"]
    c13, c23, c33, c43 = 5.25e7, 5.39e7, 5.0e7, 4.36e7
    c3, Ms = c13 + c23 + c33 + c43, i["M"] + i["m"]
    assert d["c3"] == pytest.approx(c3, rel=1e-15)
    assert d["a"] == pytest.approx((c23 + c33) * i["A"] * Ms / (c3 * i["m"]) - i["M"] * i["xi"] / i["m"], rel=1e-9)
    assert d["b"] == pytest.approx((c33 + c43) * i["B"] * Ms / (c3 * i["m"]) - i["M"] * i["eta"] / i["m"], rel=1e-9)
    assert d["static_deflection"] == pytest.approx(-Ms * 9.81 / c3, rel=1e-12)


def test_default_is_the_paper_example_and_flags_override(runner):
    base = _run_json(runner, ["platform", "--json"])
    assert base["design"]["c0"] == pytest.approx(3.7073e8, rel=2e-5)
    hz = _run_json(runner, ["platform", "--hz", "25", "--json"])
    rpm = _run_json(runner, ["platform", "--rpm", "1500", "--json"])
    assert hz["design"]["c0"] == pytest.approx(base["design"]["c0"], rel=1e-12)
    assert rpm["design"]["c0"] == pytest.approx(base["design"]["c0"], rel=1e-12)
    assert rpm["speed"]["given_as"] == "--rpm on the command line"


def test_two_speed_flags_are_a_usage_error(runner):
    result = runner.invoke(app, ["platform", "--omega", "50", "--hz", "8"])
    assert result.exit_code == 2


@pytest.mark.parametrize(
    "args,fragment",
    [
        (["--amp", "4e-4"], "c11+c21"),
        (["--amp", "1e-4"], "c0 = c1 = c2"),
        (["--amp", "0.2"], "c0 = M ω²"),
        (["--omega", "-5"], "operation.omega"),
        (["--amp", "nan"], "operation.amplitude"),
    ],
)
def test_impossible_or_invalid_exits_3_naming_the_cause(runner, args, fragment):
    result = runner.invoke(app, ["platform", *args, "--json"])
    assert result.exit_code == 3
    assert json.loads(result.stdout)["exit_code"] == 3 and fragment in result.stderr


def test_scene_rules(runner, tmp_path):
    doc = read_toml(CONFIGS / "platform_paper_example.toml")
    both = copy.deepcopy(doc)
    both["isolators"]["vertical"] = [1e8, 1e8, 1e8, 1e8]
    contradicts = copy.deepcopy(doc)
    del contradicts["isolators"]["vertical_reference"]
    contradicts["isolators"]["vertical"] = [1e8, 1e8, 1e8, 1e8]  # puts the exciter at a = 6 m
    neither = copy.deepcopy(doc)
    del neither["isolators"]["vertical_reference"]
    typo = copy.deepcopy(doc)
    typo["exciter"]["rotor_mas"] = 1.0
    cases = ((both, "not both"), (neither, "vertical_reference"), (typo, "rotor_mas"), (contradicts, "contradicts"))
    for case, text in cases:
        path = tmp_path / "s.toml"
        path.write_text(tomli_w.dumps(case), encoding="utf-8")
        result = runner.invoke(app, ["platform", str(path)])
        assert result.exit_code == 3 and text in result.stderr


def test_position_consistent_with_vertical_is_accepted(runner, tmp_path):
    doc = read_toml(CONFIGS / "platform_paper_example.toml")
    del doc["isolators"]["vertical_reference"]
    doc["isolators"]["vertical"] = [1.005e8, 1.0e8, 1.0e8, 1.0e8]  # and position = [0, 0] kept
    path = tmp_path / "s.toml"
    path.write_text(tomli_w.dumps(doc), encoding="utf-8")
    result = _run_json(runner, ["platform", str(path), "--json"])
    assert abs(result["design"]["a"]) < 1e-9 and result["design"]["c13"] == 1.005e8


def test_rocking_limit_fails_with_exit_1(runner, tmp_path):
    doc = read_toml(CONFIGS / "platform_damped.toml")
    doc["limits"] = {"rocking_percent": 0.1}
    path = tmp_path / "s.toml"
    path.write_text(tomli_w.dumps(doc), encoding="utf-8")
    result = runner.invoke(app, ["platform", str(path), "--json"])
    assert result.exit_code == 1
    assert json.loads(result.stdout)["verdict"] == "fail"
