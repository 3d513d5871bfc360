"""Sources as data: where the soil's values, a machine's loads and each limit come from, printed
beside them on the sheet; a limit without one says so."""

from __future__ import annotations

import pytest

from foundation_calc.cli.app import app
from tests.conftest import CONFIGS

pytest.importorskip("matplotlib")


def _edited(tmp_path, config: str, *edits: tuple[str, str]):
    text = (CONFIGS / config).read_text(encoding="utf-8")
    for old, new in edits:
        assert old in text, old
        text = text.replace(old, new, 1)
    scene = tmp_path / config
    scene.write_text(text, encoding="utf-8")
    return scene


def _sheet(runner, scene, tmp_path) -> str:
    out = tmp_path / "sheet.md"
    result = runner.invoke(app, ["report", str(scene), "-o", str(out)])
    assert result.exit_code in (0, 1), result.output
    return out.read_text(encoding="utf-8").replace("\\", "")


def test_block_sources_are_printed_beside_their_values(runner, tmp_path):
    scene = _edited(
        tmp_path, "block_two_machines.toml",
        ("[[machines]]\n", '[[machines]]\nsource = "vendor data sheet DS-7, rev. 2"\n'),
        ("[soil]\n", '[soil]\nsource = "soil report GR-12, table 3"\n'),
        ("[limits]\n", '[limits]\nsources = { amplitude = "client spec. S-123, 4.2" }\n'),
    )
    text = _sheet(runner, scene, tmp_path)
    assert "| source | - | vendor data sheet DS-7, rev. 2 |" in text
    assert "| source | - | soil report GR-12, table 3 |" in text
    assert "source: client spec. S-123, 4.2" in text  # beside the limit in [limits]
    rows = [line for line in text.splitlines() if line.startswith("| amplitudes |")]
    assert any("| [limits] amplitude: client spec. S-123, 4.2 |" in r for r in rows)
    assert any("| [limits] velocity_rms: scene value, no source given |" in r for r in rows)  # given, not sourced


def test_crank_load_source_and_a_defaulted_limit(runner, tmp_path):
    scene = _edited(tmp_path, "compressor_vendor_loads.toml", ("[[loads]]\n", '[[loads]]\nsource = "vendor DS-3"\n'),
                    ("detuning = 0.2", ""))
    text = _sheet(runner, scene, tmp_path)
    assert "| vendor DS-3 |" in text  # the loads table's source column
    assert "[limits] detuning: fcalc's default, no source given" in text


def test_a_source_for_no_limit_is_an_invalid_scene(runner, tmp_path):
    scene = _edited(tmp_path, "frame_saw.toml", ("[limits]\n", '[limits]\nsources = { amplitud = "spec" }\n'))
    result = runner.invoke(app, ["check", str(scene)])
    assert result.exit_code == 3
    assert "sources names amplitud, not a limit of this scene kind" in " ".join(result.output.split())
