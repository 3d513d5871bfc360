"""`fcalc sweep` files and edges: CSV streamed in chunks (true/false, never -0.0), clear usage
errors for --csv and --plot paths, a single-speed sweep, the JSON document's command and verdict,
and a plot that marks the operating speed and the detuning bands."""

from __future__ import annotations

import csv
import io
import json

import pytest

from foundation_calc.checks.sweep import crank as crank_sweep
from foundation_calc.solvers.crank import sweep as crank_engine
from foundation_calc.cli.app import app
from tests.conftest import CONFIGS

SAW = CONFIGS / "frame_saw.toml"


def _csv(path):
    return list(csv.DictReader(io.StringIO(path.read_text(encoding="utf-8"))))


def test_csv_writes_true_false_and_never_minus_zero(runner, tmp_path):
    out = tmp_path / "s.csv"
    result = runner.invoke(app, ["sweep", str(SAW), "--speed", "100:600:41", "--csv", str(out)])
    assert result.exit_code == 0, result.output
    rows = _csv(out)
    assert {r["resonant"] for r in rows} <= {"true", "false"} and {r["over_limit"] for r in rows} == {"true", "false"}
    cells = [c for r in rows for c in r.values()]
    assert "-0.0" not in cells and "True" not in cells and "False" not in cells
    assert any(c == "0.0" for c in cells)  # undamped phases of 0 (once written -0.0)


def test_long_csv_streams_chunk_by_chunk_and_matches_one_piece(runner, tmp_path, monkeypatch):
    """A sweep longer than the table limit, written to CSV, is computed and written a chunk at a
    time (here 97 points a chunk): the file equals the one-chunk file, and stdout has a summary,
    not 1500 rows."""
    whole = tmp_path / "whole.csv"
    assert runner.invoke(app, ["sweep", str(SAW), "--speed", "100:600:1500", "--csv", str(whole)]).exit_code == 0
    sizes = []
    chunk = crank_sweep._chunk

    def recording(design, variable, values, *args):
        sizes.append(len(values))
        return chunk(design, variable, values, *args)

    monkeypatch.setattr(crank_engine, "CHUNK", 97)
    monkeypatch.setattr(crank_sweep, "_chunk", recording)
    parts = tmp_path / "parts.csv"
    result = runner.invoke(app, ["sweep", str(SAW), "--speed", "100:600:1500", "--csv", str(parts)])
    assert result.exit_code == 0, result.output
    assert max(sizes) == 97 and sum(sizes) == 1500
    assert parts.read_text(encoding="utf-8") == whole.read_text(encoding="utf-8")
    assert "1500 points written to" in result.stdout and len(result.stdout.splitlines()) < 30


@pytest.mark.parametrize(
    ("option", "target", "words"),
    [
        ("--csv", "missing/out.csv", ["--csv", "does not exist"]),
        ("--csv", ".", ["--csv", "is a folder"]),
        ("--plot", "out.txt", ["--plot", "unsupported plot format '.txt'", ".png, .svg, .pdf"]),
        ("--plot", "missing/out.png", ["--plot", "does not exist"]),
    ],
)
def test_bad_output_paths_are_usage_errors(runner, tmp_path, option, target, words):
    result = runner.invoke(app, ["sweep", str(SAW), "--speed", "100:600:5", option, str(tmp_path / target)])
    assert result.exit_code == 2, result.output
    text = " ".join(result.output.split())
    assert all(w in text for w in words), text
    assert "Traceback" not in result.output


@pytest.mark.parametrize("config", ["frame_saw.toml", "compressor_vendor_loads.toml"])
def test_the_sweep_names_the_governing_condition_as_every_command_does(runner, config):
    """At the scene's own speed the sweep's row names the governing condition in the words of
    resonance, amplitudes and check (docs/resonance-rule.md): a condition of the [[loads]]
    too, which the row once called "ω = p2 (loads)" where the others say "ω = p2"."""
    scene = str(CONFIGS / config)
    rpm = {"frame_saw.toml": "250", "compressor_vendor_loads.toml": "1500"}[config]
    resonance = json.loads(runner.invoke(app, ["resonance", scene, "--json"]).stdout)["rule"]["governing"]
    amplitudes = json.loads(runner.invoke(app, ["amplitudes", scene, "--json"]).stdout)["resonance_rule"]["governing"]
    (row,) = json.loads(runner.invoke(app, ["sweep", scene, "--speed", rpm, "--json"]).stdout)["points"]
    assert row["governing_condition"] == resonance["condition"] == amplitudes["condition"]
    checked = runner.invoke(app, ["check", scene, "--json", "--jobs", "1"]).stdout
    reason = next(c["reason"] for c in json.loads(checked)["scenes"][0]["checks"] if c["check"] == "resonance")
    phrase = reason.split("governing resonance ")[1]  # e.g. "ω = p2 at 50.5% (needs 20%)"
    table = runner.invoke(app, ["sweep", scene, "--speed", rpm], env={"COLUMNS": "400"}).stdout
    assert f"governing {phrase}" in table, table


@pytest.mark.parametrize("spec", ["250", "250rpm", "250:250", "250:250:1"])
def test_a_single_speed_sweep_is_the_scenes_check(runner, spec):
    result = runner.invoke(app, ["sweep", str(SAW), "--speed", spec, "--json"])
    assert result.exit_code == 0, result.output
    doc = json.loads(result.stdout)
    (row,) = doc["points"]
    resonance = json.loads(runner.invoke(app, ["resonance", str(SAW), "--json"]).stdout)
    assert row["governing_condition"] == resonance["rule"]["governing"]["condition"]
    assert row["margin"] == pytest.approx(resonance["rule"]["governing"]["margin"], rel=1e-12)


def test_a_single_point_with_more_than_one_n_is_a_usage_error(runner):
    result = runner.invoke(app, ["sweep", str(SAW), "--speed", "250:250:3"])
    assert result.exit_code == 2 and "N must be 1" in " ".join(result.output.split())


def test_json_names_the_command_and_a_verdict(runner):
    doc = json.loads(runner.invoke(app, ["sweep", str(SAW), "--speed", "100:600:11", "--json"]).stdout)
    assert doc["command"] == "sweep" and doc["verdict"] == "fail"  # 300 rpm and up exceed 0.2 mm
    doc = json.loads(runner.invoke(app, ["sweep", str(SAW), "--speed", "100:250:4", "--json"]).stdout)
    assert doc["verdict"] == "pass"


def test_plot_marks_the_operating_speed_and_the_bands(runner, tmp_path, monkeypatch):
    pytest.importorskip("matplotlib")
    from foundation_calc.output import plots

    figures = []
    save = plots.save
    monkeypatch.setattr(plots, "save", lambda fig, path: (figures.append(fig), save(fig, path)))
    out = tmp_path / "s.png"
    result = runner.invoke(app, ["sweep", str(SAW), "--speed", "100:600:41", "--plot", str(out)])
    assert result.exit_code == 0, result.output
    assert out.read_bytes()[:8] == b"\x89PNG\r\n\x1a\n"
    (ax,) = figures[0].axes
    operating = [line for line in ax.lines if line.get_label() == "operating speed"]
    assert len(operating) == 1 and operating[0].get_xdata()[0] == pytest.approx(250.0)
    doc = json.loads(runner.invoke(app, ["sweep", str(SAW), "--speed", "100:600:41", "--json"]).stdout)
    spans = [p for p in ax.patches if p.get_width() > 0]
    judged = [c for c in doc["critical_speeds"] if c["judged"]]
    assert len(spans) == len(judged) >= 1 and len(doc["critical_speeds"]) >= 3  # 3ω = p1; 4ω = k0, 2ω = p1 not judged
    for crit in judged:  # each band is ±band around its critical speed (rpm)
        centre = crit["zero_order"] * 30 / 3.141592653589793
        assert any(p.get_x() == pytest.approx(centre * (1 - crit["band"])) for p in spans)
