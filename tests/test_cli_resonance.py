"""`fcalc resonance` on every shipped crank_foundation scene: exit codes, JSON, tables, stderr."""

from __future__ import annotations

import json
import math

import pytest

from foundation_calc.cli.app import app
from foundation_calc.scenes import read_toml
from tests.conftest import configs_of_kind, only_input_warnings

EXPECTED_EXIT = {
    "compressor_near_resonance.toml": 1,
    "compressor_damped_near_resonance.toml": 1,
}


@pytest.mark.parametrize("config", configs_of_kind("crank_foundation"), ids=lambda p: p.name)
def test_json_on_every_config(runner, config):
    result = runner.invoke(app, ["resonance", str(config), "--json"])
    assert result.exit_code == EXPECTED_EXIT.get(config.name, 0), result.stderr
    assert only_input_warnings(result.stderr, config)
    doc = json.loads(result.stdout)
    assert doc["command"] == "resonance" and doc["schema_version"] == 1
    assert doc["verdict"] in {"pass", "warn", "fail"}

    def finite(node):
        if isinstance(node, dict):
            return all(finite(v) for v in node.values())
        if isinstance(node, list):
            return all(finite(v) for v in node)
        return not isinstance(node, float) or math.isfinite(node)

    assert finite(doc)


@pytest.mark.parametrize("config", configs_of_kind("crank_foundation"), ids=lambda p: p.name)
def test_tables_on_every_config(runner, config):
    result = runner.invoke(app, ["resonance", str(config)])
    assert result.exit_code == EXPECTED_EXIT.get(config.name, 0)
    assert only_input_warnings(result.stderr, config)
    condition = "3ω = p2" if "mechanism" in read_toml(config) else "2ω = p2 (loads)"
    for text in ("Natural frequencies", "Resonances", "rpm", condition):
        assert text in result.stdout
    assert result.stdout.strip().splitlines()[-1].split(":")[0] in {"PASS", "WARN", "FAIL"}


def test_help_documents_exit_codes(runner):
    for args in (["--help"], ["resonance", "--help"]):
        result = runner.invoke(app, args)
        assert result.exit_code == 0
        assert "Exit codes" in result.stdout and "3 invalid scene" in result.stdout


def test_usage_error_exits_2(runner):
    result = runner.invoke(app, ["resonance"])
    assert result.exit_code == 2
    result = runner.invoke(app, ["resonance", "configs/frame_saw_extra_resonance.toml", "--no-such-flag"])
    assert result.exit_code == 2


def test_wrong_kind_exits_3(runner, tmp_path):
    path = tmp_path / "p.toml"
    path.write_text('kind = "platform"\n', encoding="utf-8")
    result = runner.invoke(app, ["resonance", str(path)])
    assert result.exit_code == 3
    assert "kind" in result.stderr


def test_internal_error_exits_4_without_traceback(runner, monkeypatch):
    import foundation_calc.checks.resonance as mod

    def boom(*args, **kwargs):
        raise ZeroDivisionError("simulated")

    monkeypatch.setattr(mod, "check_resonances", boom)
    result = runner.invoke(app, ["resonance", "configs/frame_saw_extra_resonance.toml"])
    assert result.exit_code == 4
    assert "internal error" in result.stderr and "Traceback" not in result.stderr


def test_closed_pipe_ends_quietly_with_141(runner, monkeypatch):
    import foundation_calc.output.resonance as out

    def closed(*args, **kwargs):
        raise BrokenPipeError(32, "Broken pipe")

    monkeypatch.setattr(out, "resonance_document", closed)
    result = runner.invoke(app, ["resonance", "configs/frame_saw_extra_resonance.toml", "--json"])
    assert result.exit_code == 141
    assert "internal error" not in result.stderr
