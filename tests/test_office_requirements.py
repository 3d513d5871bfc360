"""Office rules in fcalc.toml [require]: soil bracketing (ACI 351.3R-18 asks for a range of soil properties)."""

from __future__ import annotations

import json

import pytest

from foundation_calc.cli.app import app
from tests.conftest import CONFIGS

REQUIRE = "[require]\nsoil_bracketing = true\n"


def _office(tmp_path, config: str, extra: str = "", office: str = REQUIRE):
    (tmp_path / "fcalc.toml").write_text(office, encoding="utf-8")
    scene = tmp_path / "job" / config
    scene.parent.mkdir(exist_ok=True)
    scene.write_text((CONFIGS / config).read_text(encoding="utf-8") + extra, encoding="utf-8")
    return scene


def _checks(runner, scene) -> tuple[int, dict]:
    result = runner.invoke(app, ["check", str(scene), "--json"])
    document = json.loads(result.stdout)
    entry = document["scenes"][0] if "scenes" in document else document
    return result.exit_code, {c["check"]: c for c in entry["checks"]}


@pytest.mark.parametrize("config", ["frame_saw.toml", "block_two_machines.toml"])
def test_required_bracketing_fails_a_scene_without_a_modulus_range(runner, tmp_path, config):
    code, checks = _checks(runner, _office(tmp_path, config))
    assert code == 1
    assert checks["requirements"]["verdict"] == "fail"
    assert "[require] soil_bracketing" in json.dumps(checks["requirements"], ensure_ascii=False)


def test_required_bracketing_passes_with_a_modulus_range_and_is_absent_without_the_rule(runner, tmp_path):
    ranged = _office(tmp_path, "frame_saw.toml").read_text(encoding="utf-8").replace("[soil]\n", "[soil]\nmodulus_range = [0.7, 1.3]\n", 1)
    (tmp_path / "job" / "frame_saw.toml").write_text(ranged, encoding="utf-8")
    code, checks = _checks(runner, tmp_path / "job" / "frame_saw.toml")
    assert checks["requirements"]["verdict"] == "pass"
    (tmp_path / "fcalc.toml").write_text("[project]\njob = \"J-1\"\n", encoding="utf-8")
    assert "requirements" not in _checks(runner, tmp_path / "job" / "frame_saw.toml")[1]


def test_a_scene_cannot_lift_the_office_rule(runner, tmp_path):
    scene = _office(tmp_path, "frame_saw.toml", "\n[require]\nsoil_bracketing = false\n")
    assert _checks(runner, scene)[1]["requirements"]["verdict"] == "fail"


def test_office_rule_with_unknown_key_is_an_error(runner, tmp_path):
    scene = _office(tmp_path, "frame_saw.toml", office="[require]\nsoil_bracket = true\n")
    result = runner.invoke(app, ["check", str(scene)])
    assert result.exit_code == 3 and "require.soil_bracket" in result.output


def test_sheet_fails_with_check_and_says_when_the_soil_is_not_bracketed(runner, tmp_path):
    pytest.importorskip("matplotlib")
    scene = _office(tmp_path, "frame_saw.toml")
    out = tmp_path / "sheet.md"
    assert runner.invoke(app, ["report", str(scene), "-o", str(out)]).exit_code == 1  # as fcalc check
    text = out.read_text(encoding="utf-8").replace("\\", "")
    assert "| requirements | [require] soil_bracketing | [soil] modulus_range not given |" in text
    plain = tmp_path / "plain.md"
    assert runner.invoke(app, ["report", str(CONFIGS / "frame_saw.toml"), "-o", str(plain)]).exit_code == 0
    assert "The soil was not bracketed" in plain.read_text(encoding="utf-8").replace("\\", "")


def test_design_refuses_a_scene_that_fails_an_office_rule(runner, tmp_path):
    scene = _office(tmp_path, "block_two_machines.toml")
    result = runner.invoke(app, ["design", str(scene), "--vary", "block.height=1.5:2.5", "--step", "0.5"])
    assert result.exit_code == 1 and "soil_bracketing" in result.output
