"""``fcalc sweep``: options, outputs, and that one vectorised call equals point-by-point calls."""

from __future__ import annotations

import csv
import io
import json

import numpy as np
import pytest

from foundation_calc.checks.sweep.crank import sweep
from foundation_calc.cli.app import app
from foundation_calc.scenes import load_scene
from foundation_calc.solvers.crank.closed_form import design_first_approximation, varied
from foundation_calc.units import omega_from_rpm
from tests.conftest import configs_of_kind, crank_on_piles, only_input_warnings

CRANKS = [p for p in configs_of_kind("crank_foundation") if not crank_on_piles(p)]  # sweeps by the closed forms


@pytest.mark.parametrize("path", configs_of_kind("crank_foundation"), ids=lambda p: p.stem)
def test_every_crank_config_sweeps_to_json(runner, path):
    result = runner.invoke(app, ["sweep", str(path), "--speed", "50:900:40", "--json"])
    assert result.exit_code == 0, result.output
    assert only_input_warnings(result.stderr, path)
    doc = json.loads(result.stdout)
    assert len(doc["points"]) == 40
    assert doc["points"][0]["omega"] == pytest.approx(omega_from_rpm(50.0), rel=1e-15)


def test_vectorised_sweep_equals_scalar_calls():
    """The batch path is the same arithmetic: each point equals its own scalar evaluation."""
    design = load_scene(CRANKS[0]).design()
    omegas = np.geomspace(1.0, 500.0, 37)
    report = sweep(design, "omega", omegas, None, 0.2)
    factors = np.linspace(0.5, 1.5, 9)
    soil = sweep(design, "soil_factor", factors, None, 0.2)
    for i, w in enumerate(omegas):
        one = design_first_approximation(varied(design, omega=float(w)))
        assert abs(report.columns["peaks"][i, 1]) >= abs(one.y1) - abs(one.y2) - 1e-30  # peak bounds the harmonics
        assert report.columns["peaks"][i, 1] <= abs(one.y1) + abs(one.y2) + 1e-30
    for i, f in enumerate(factors):
        one = sweep(varied(design, soil_factor=float(f)), "omega", [design.omega], None, 0.2)
        assert soil.columns["peaks"][i] == pytest.approx(one.columns["peaks"][0], rel=1e-13)
        assert soil.rows.status[i] == one.rows.status[0]


def test_table_csv_and_units(runner, tmp_path):
    out = tmp_path / "s.csv"
    result = runner.invoke(app, ["sweep", str(CRANKS[0]), "--soil", "0.5:1.5:5", "--csv", str(out), "--units", "mm"])
    assert result.exit_code == 0, result.output
    assert "[mm]" in result.stdout and "soil" in result.stdout
    rows = list(csv.DictReader(io.StringIO(out.read_text(encoding="utf-8"))))
    assert [float(r["soil_factor"]) for r in rows] == [0.5, 0.75, 1.0, 1.25, 1.5]
    assert all(float(r["x_peak_m"]) > 0 for r in rows)


@pytest.mark.parametrize(
    "spec, unit, first",
    [("100:600:3", "rpm", omega_from_rpm(100.0)), ("10:60:3rad/s", "rad/s", 10.0), ("2:8:3 hz", "Hz", 2 * np.pi * 2)],
)
def test_speed_units(runner, spec, unit, first):
    result = runner.invoke(app, ["sweep", str(CRANKS[0]), "--speed", spec, "--json"])
    assert result.exit_code == 0, result.output
    assert json.loads(result.stdout)["points"][0]["omega"] == pytest.approx(first, rel=1e-15)
    table = runner.invoke(app, ["sweep", str(CRANKS[0]), "--speed", spec])
    assert f"[{unit}]" in table.stdout


@pytest.mark.parametrize(
    "args",
    [[], ["--speed", "1:2", "--soil", "1:2"], ["--speed", "600:100"], ["--speed", "1:2:1"], ["--speed", "1:2furlong"],
     ["--soil", "0:1"], ["--soil", "0.5:1.5m"], ["--speed", "a:b"], ["--speed", "nan:2"], ["--speed", "1:inf"]],
)
def test_bad_options_are_usage_errors(runner, args):
    result = runner.invoke(app, ["sweep", str(CRANKS[0]), *args])
    assert result.exit_code == 2, result.output


def test_plot(runner, tmp_path, monkeypatch):
    png = tmp_path / "s.png"
    pytest.importorskip("matplotlib")
    result = runner.invoke(app, ["sweep", str(CRANKS[0]), "--speed", "100:700:60", "--plot", str(png)])
    assert result.exit_code == 0, result.output
    assert png.read_bytes()[:4] == b"\x89PNG"
    monkeypatch.setattr("foundation_calc.output.plots.plotting_available", lambda: False)
    result = runner.invoke(app, ["sweep", str(CRANKS[0]), "--speed", "100:700", "--plot", str(tmp_path / "t.png")])
    assert result.exit_code == 2 and "foundation_calc[plot]" in result.output


def test_points_match_fcalc_amplitudes(runner, tmp_path, frame_saw):
    """A sweep point at the scene's speed reports the same point peaks as ``fcalc amplitudes``."""
    import tomli_w

    frame_saw["points"] = [{"name": "edge", "horizontal": 2.5, "height": -1.5}]
    path = tmp_path / "p.toml"
    path.write_text(tomli_w.dumps(frame_saw), encoding="utf-8")
    swept = runner.invoke(app, ["sweep", str(path), "--speed", "300:400:2", "--json"])
    amps = runner.invoke(app, ["amplitudes", str(path), "--json"])
    edge = json.loads(swept.stdout)["points"][0]["points"]["edge"]
    want = json.loads(amps.stdout)["approximations"]["first_approximation"]["points"]["edge"]
    for direction in ("horizontal", "vertical"):
        assert edge[direction] == pytest.approx(want[direction]["displacement"], rel=1e-12)
    assert json.loads(swept.stdout)["points"][0]["over_limit"]


@pytest.mark.parametrize("quantity", ["velocity", "acceleration"])
def test_sweep_applies_the_limits_that_amplitudes_applies(runner, tmp_path, quantity):
    """A scene that fails on velocity (or acceleration) in ``fcalc amplitudes`` fails on it in
    ``fcalc sweep`` at the same speed: one limit check for every command."""
    import tomli_w

    from tests.conftest import CONFIGS
    from foundation_calc.scenes import read_toml

    scene = read_toml(CONFIGS / "frame_saw.toml")
    amps = json.loads(runner.invoke(app, ["amplitudes", str(CONFIGS / "frame_saw.toml"), "--json"]).stdout)
    peak = amps["approximations"]["first_approximation"]["peaks"]["y"][quantity]
    scene["limits"] = {"amplitude": 1.0, quantity: 0.9 * peak, "detuning": 0.2}
    path = tmp_path / "tight.toml"
    path.write_text(tomli_w.dumps(scene), encoding="utf-8")
    assert runner.invoke(app, ["amplitudes", str(path)]).exit_code == 1
    rpm = scene["mechanism"]["speed_rpm"]
    speeds = f"{rpm}:{rpm + 2}:3"  # the scene's speed is the first point
    swept = json.loads(runner.invoke(app, ["sweep", str(path), "--speed", speeds, "--json"]).stdout)
    row = swept["points"][0]
    assert row["status"] == "fail" and row["over_limits"] == [quantity]
    assert swept["limits"][quantity] == pytest.approx(0.9 * peak)
    table = runner.invoke(app, ["sweep", str(path), "--speed", speeds]).stdout
    assert f"over {quantity} limit" in table
