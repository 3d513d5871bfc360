"""``fcalc amplitudes`` through typer's CliRunner on every crank_foundation scene in configs/."""

from __future__ import annotations

import json
import tomllib
from pathlib import Path

import pytest
import tomli_w
from typer.testing import CliRunner

from foundation_calc.cli.app import app
from tests.conftest import ROOT, mechanism_configs, only_input_warnings

CONFIGS = mechanism_configs()  # a machine given by its loads only: tests/test_crank_loads.py


BASE = Path(__file__).parent.parent / "configs" / "frame_saw_extra_resonance.toml"


def run(*args):
    return CliRunner().invoke(app, ["amplitudes", *map(str, args)])


@pytest.mark.parametrize("scene", CONFIGS, ids=lambda p: p.name)
@pytest.mark.parametrize("exact", [False, True])
def test_config_json(scene, exact):
    result = run(scene, "--json", *(["--exact"] if exact else []))
    assert result.exit_code in (0, 1), result.output
    assert only_input_warnings(result.stderr, scene)
    doc = json.loads(result.stdout)
    assert result.exit_code == (1 if doc["verdict"] == "fail" else 0)
    approx = doc["approximations"]
    closed_forms = "not_applicable" not in doc  # a pile group couples the plane: (4.14) does not apply
    if closed_forms:
        assert set(approx["first_approximation"]["coefficients"]) == {"y1", "y2", "x1", "x3", "theta1", "theta3"}
    else:
        assert "first_approximation" not in approx and set(doc["not_applicable"]) == {"first_approximation"}
    assert doc["checked_with"] == ("exact" if exact else "averaged_operator")
    if exact:
        assert set(doc["errors"]) == {"first_approximation", "averaged_operator"} if closed_forms else {"averaged_operator"}
        assert doc["exact_solver"]["harmonic_change"] < 1e-10


@pytest.mark.parametrize("scene", CONFIGS, ids=lambda p: p.name)
def test_config_tables(scene):
    result = run(scene, "--exact")
    assert result.exit_code in (0, 1)
    assert only_input_warnings(result.stderr, scene)
    assert "first approximation" in result.stdout and "exact" in result.stdout


def _scene(tmp_path, **changes):
    data = tomllib.loads(BASE.read_text("utf-8"))
    for section, values in changes.items():
        if isinstance(values, dict):
            data.setdefault(section, {}).update(values)
        else:
            data[section] = values
    path = tmp_path / "scene.toml"
    path.write_text(tomli_w.dumps(data), "utf-8")
    return path


def test_points_and_limits_pass(tmp_path):
    path = _scene(
        tmp_path,
        limits={"amplitude": 1.0e-2, "velocity": 1.0, "acceleration": 10.0},
        points=[{"name": "top edge", "horizontal": 2.5, "height": 1.3}],
    )
    result = run(path, "--json")
    assert result.exit_code == 0, result.output
    doc = json.loads(result.stdout)
    assert len(doc["limits"]) == 2 * 2 * 3
    assert "top edge" in doc["approximations"]["averaged_operator"]["points"]


def test_resonant_speed_fails_with_its_margin(tmp_path):
    # k0 = sqrt(c S / M_tot) of the frame saw
    data = tomllib.loads(BASE.read_text("utf-8"))
    f, s, m = data["foundation"], data["soil"], data["mechanism"]
    k0 = (s["c_z"] * f["base_area"] / (f["mass"] + m["rod_mass"] + m.get("slider_mass", 0.0))) ** 0.5
    mech = {k: v for k, v in m.items() if k not in ("omega", "frequency_hz", "speed_rpm")}
    data["mechanism"] = {**mech, "omega": k0}
    path = tmp_path / "resonant.toml"
    path.write_text(tomli_w.dumps(data), "utf-8")
    result = run(path, "--json", "--exact")
    assert result.exit_code == 1, result.output
    doc = json.loads(result.stdout)
    assert doc["approximations"]["averaged_operator"]["resonant"] is True
    assert doc["approximations"]["first_approximation"]["resonance_margin"] < 1e-6
    assert doc["verdict"] == "fail"
    tables = run(path)
    assert tables.exit_code == 1 and "resonant" in tables.stdout


def test_damped_scene_at_exact_resonance_gives_finite_amplitudes_and_phases(tmp_path):
    """The resonant scene above with soil.damping: every method (--exact too) answers, the limits
    judge the amplitudes, and the JSON carries the phases and the damping."""
    data = tomllib.loads(BASE.read_text("utf-8"))
    f, s, m = data["foundation"], data["soil"], data["mechanism"]
    k0 = (s["c_z"] * f["base_area"] / (f["mass"] + m["rod_mass"] + m.get("slider_mass", 0.0))) ** 0.5
    mech = {k: v for k, v in m.items() if k not in ("omega", "frequency_hz", "speed_rpm")}
    data["mechanism"] = {**mech, "omega": k0}
    data["soil"]["damping"] = [0.1, 0.1, 0.05]
    data["limits"]["amplitude"] = 1.0
    path = tmp_path / "damped.toml"
    path.write_text(tomli_w.dumps(data), "utf-8")
    result = run(path, "--json", "--exact")
    assert result.exit_code == 0, result.output
    doc = json.loads(result.stdout)
    assert doc["damping"]["dashpots"]["C_z"] > 0 and len(doc["damping"]["modal_damping_ratios"]) == 3
    for approx in doc["approximations"].values():
        assert approx["resonant"] is False
        y1 = approx["harmonics"]["y1"]
        assert 0 < y1["magnitude"] < 1.0
        # ω = k0: the vertical harmonic lags the crank-pin force by 90°
        assert abs(abs(y1["phase"]) - 1.5707963) < 0.01, y1
    tables = run(path, "--exact")
    assert tables.exit_code == 0 and "phase lag" in tables.stdout and "resonant" not in tables.stdout


def test_duplicate_point_names_are_an_invalid_scene(tmp_path):
    path = _scene(tmp_path, points=[{"name": "a", "horizontal": 1.0, "height": 0.0}] * 2)
    result = run(path)
    assert result.exit_code == 3
    assert "points" in result.stderr


def test_units_convert_the_tables_but_not_the_json(runner):
    from foundation_calc.cli.app import app

    si = runner.invoke(app, ["amplitudes", "configs/vertical_compressor.toml"])
    mm = runner.invoke(app, ["amplitudes", "configs/vertical_compressor.toml", "--units", "mm,mm/s"])
    assert si.exit_code == mm.exit_code == 0
    assert "y1 [m]" in si.stdout and "y1 [mm]" in mm.stdout
    row = next(line for line in mm.stdout.splitlines() if "│ horizontal │ displacement [mm] │" in line)
    assert row.split("│")[5].strip() == "0.15"  # the limit, in the unit beside its quantity
    js = runner.invoke(app, ["amplitudes", "configs/vertical_compressor.toml", "--units", "mm", "--json"])
    assert '"amplitude": 0.00015' in js.stdout or "0.00015" in js.stdout
    bad = runner.invoke(app, ["amplitudes", "configs/vertical_compressor.toml", "--units", "furlong"])
    assert bad.exit_code == 2


def test_exact_solution_at_the_harmonic_cap_is_given_with_its_error_estimate(runner, tmp_path, monkeypatch):
    """A rod barely longer than the crank (λ = 0.999) needs more harmonics than the cap: the
    solution at the cap is shown with its change from half the harmonics, not refused (exit 3).
    The cap is lowered to 32 here so that the test stays cheap; the shipped cap is 256."""
    import foundation_calc.solvers.crank.exact as exact
    from foundation_calc.cli.app import app

    monkeypatch.setattr(exact, "MAX_HARMONICS", 32)
    text = (ROOT / "configs" / "frame_saw.toml").read_text()
    scene = tmp_path / "short_rod.toml"
    scene.write_text(text.replace("rod_length = 1.2", "rod_length = 0.3003").replace("rod_cog_to_crank_pin = 1.0", "rod_cog_to_crank_pin = 0.15"))
    result = runner.invoke(app, ["amplitudes", str(scene), "--exact", "--json"])
    assert result.exit_code in (0, 1), result.output
    solver = json.loads(result.stdout)["exact_solver"]
    assert solver["harmonics"] == 32 and not solver["converged"] and solver["harmonic_change"] > 1e-10
    assert "λ = r/l = 0.999" in solver["note"] and "32 harmonics (the cap)" in solver["note"]
