"""`fcalc resonance`, `amplitudes` and `check` on the shipped block_foundation scenes, and the
parts of a block scene that turn user input into loads (the unbalance of a balance grade)."""

from __future__ import annotations

import json
import math
from pathlib import Path

import numpy as np
import pytest

from foundation_calc.cli.app import app
from foundation_calc.scenes import load_scene
from tests.conftest import configs_of_kind

#: Shipped block scenes and the exit code of `fcalc check` on each (docs/examples.md).
EXPECTED_EXIT = {"block_two_machines.toml": 0, "block_fan_torsion_near_speed.toml": 1, "block_on_piles.toml": 1,
                 "block_two_throw_compressor.toml": 0, "block_opposed_compressor.toml": 0, "block_on_isolators.toml": 0,
                 "block_vibrating_table.toml": 0}


def test_every_shipped_block_scene_is_listed():
    assert sorted(p.name for p in configs_of_kind("block_foundation")) == sorted(EXPECTED_EXIT)


@pytest.mark.parametrize("config", configs_of_kind("block_foundation"), ids=lambda p: p.name)
@pytest.mark.parametrize("command", ["resonance", "amplitudes"])
def test_json_is_one_finite_document(runner, config, command):
    result = runner.invoke(app, [command, str(config), "--json"])
    assert result.stderr == ""
    doc = json.loads(result.stdout)
    assert doc["command"] == command and doc["scene"]["kind"] == "block_foundation"
    assert len(doc["modes"]) == 6
    assert result.exit_code == (1 if doc["verdict"] == "fail" else 0)

    def finite(node):
        if isinstance(node, dict):
            return all(finite(v) for v in node.values())
        if isinstance(node, list):
            return all(finite(v) for v in node)
        return not isinstance(node, float) or math.isfinite(node)

    assert finite(doc)


@pytest.mark.parametrize("config", configs_of_kind("block_foundation"), ids=lambda p: p.name)
def test_check_exit_code(runner, config):
    result = runner.invoke(app, ["check", str(config), "--json"])
    assert result.exit_code == EXPECTED_EXIT[config.name], result.stdout + result.stderr
    checks = json.loads(result.stdout)["scenes"][0]["checks"]
    assert [c["check"] for c in checks] == ["resonance", "amplitudes", "office"]


def test_the_torsional_mode_near_the_fan_speed_is_reported(runner):
    result = runner.invoke(app, ["resonance", "configs/block_fan_torsion_near_speed.toml", "--json"])
    doc = json.loads(result.stdout)
    failing = [r for r in doc["resonances"] if r["verdict"] == "fail"]
    assert any(r["dominant"] == "rz" and r["machine"] == "fan" and r["judged"] for r in failing)
    table = runner.invoke(app, ["resonance", "configs/block_fan_torsion_near_speed.toml"]).stdout
    assert "torsion about z" in table and "FAIL" in table


def test_a_command_without_blocks_names_the_block_commands(runner, tmp_path):
    result = runner.invoke(app, ["platform", "configs/block_two_machines.toml"])
    assert result.exit_code == 3
    assert "fcalc resonance" in result.stderr and "fcalc runup" in result.stderr


def test_soil_lists_six_springs(runner):
    result = runner.invoke(app, ["soil", "configs/block_fan_torsion_near_speed.toml", "--json"])
    assert result.exit_code == 0, result.stderr
    springs = json.loads(result.stdout)["springs"]
    assert [s["motion"] for s in springs] == ["x", "y", "z", "rx", "ry", "rz"]
    assert springs[0]["K"] == springs[1]["K"]  # Lysmer's sliding analog is the same along x and y


def test_unbalance_is_the_rotating_force_of_its_balance_grade():
    """ISO 21940-11: e ω = G, so F = m_r G ω, turning about the axis (right-handed) at the speed:
    the load at t and a quarter period later are perpendicular, equal and normal to the axis."""
    scene = load_scene("configs/block_fan_torsion_near_speed.toml")
    fan = scene.machines[0]
    rows = fan.load_rows()
    F = sum(np.asarray(f) * math.cos(phase) for _, f, _, phase, *_ in rows)  # at t = 0
    F_later = sum(np.asarray(f) * math.cos(math.pi / 2 + phase) for _, f, _, phase, *_ in rows)  # ω t = π/2
    expected = 2.5e3 * 6.3e-3 * 990.0 * math.pi / 30.0
    assert np.linalg.norm(F) == pytest.approx(expected, rel=1e-12)
    assert np.linalg.norm(F_later) == pytest.approx(expected, rel=1e-12)
    assert abs(F @ F_later) < 1e-9 * expected**2
    axis = np.array([1.0, 0.0, 0.0])
    assert abs(F @ axis) < 1e-12 * expected
    assert np.cross(F, F_later) @ axis > 0.0  # right-handed about the axis
    assert all(row.inertial for row in rows)  # an unbalance's force grows as ω² in a sweep


def test_sweep_of_one_machine(runner):
    result = runner.invoke(app, ["sweep", "configs/block_two_machines.toml", "--speed", "1000:2600:5", "--machine", "motor", "--json"])
    assert result.exit_code == 0, result.stderr
    doc = json.loads(result.stdout)
    assert doc["machine"] == "motor" and len(doc["points"]) == 5
    # the motor's own speed (1490 rpm) lies between rows 2 and 3; 2400 rpm is within 0.1 % of the vertical mode
    assert doc["points"][0]["status"] == "pass" and doc["points"][-1]["status"] == "fail"
    unnamed = runner.invoke(app, ["sweep", "configs/block_two_machines.toml", "--speed", "1000:2600:5"])
    assert unnamed.exit_code == 2 and "compressor, motor" in unnamed.stderr


def test_a_block_sweep_writes_its_rows_to_csv_and_a_plot(runner, tmp_path):
    """--csv holds the --json rows (SI, the shortest round-trip floats: equal to the last bit);
    --plot writes a PNG (the soil sweep's: tests/test_block_soil_sweep.py)."""
    import csv

    pytest.importorskip("matplotlib")
    args = ["sweep", "configs/block_two_machines.toml", "--speed", "1000:2600:5", "--machine", "motor"]
    doc = json.loads(runner.invoke(app, [*args, "--json"]).stdout)
    table, picture = tmp_path / "sweep.csv", tmp_path / "sweep.png"
    result = runner.invoke(app, [*args, "--csv", str(table), "--plot", str(picture)])
    assert result.exit_code == 0, result.stderr
    with table.open(encoding="utf-8") as stream:
        rows = list(csv.DictReader(stream))
    assert len(rows) == len(doc["points"]) == 5
    for row, point in zip(rows, doc["points"]):
        assert float(row["omega_rad_s"]) == point["omega"] and row["status"] == point["status"]
        assert [float(row[f"peak_{d}_m"]) for d in "xyz"] == [point["peak"][d] for d in "xyz"]
        assert row["governing_condition"] == point["governing_condition"] and float(row["margin"]) == point["margin"]
    assert picture.read_bytes()[:8] == b"\x89PNG\r\n\x1a\n"


def test_office_checks_judge_as_their_sources_say(tmp_path, runner):
    """Eccentricity (a "should": warns), bearing pressure (statics against the allowable: fails),
    on a block and on a crank scene, values by hand."""
    from foundation_calc.checks.office import bearing_row, eccentricity_rows, mass_ratio_row

    rows = eccentricity_rows([0.42, -0.1], 7.0, 4.0, 0.05)
    assert [r.outcome.value for r in rows] == ["warn", "pass"] and rows[0].value == pytest.approx(0.06)
    # machines placed symmetrically: the centre of mass's round-off (4e-21 m on the shipped
    # opposed compressor) is no eccentricity; 1 µm on a 5 m base is one
    assert [r.text.split(" is ")[0] for r in eccentricity_rows([3.9e-21, 1e-6], 5.0, 5.0, 0.05)] == ["e_x = 0 m", "e_y = 1e-06 m"]
    # W = 1 MN on 4 m x 2 m with e_x = 0.2 m: q_max = 125 kPa (1 + 0.3) = 162.5 kPa
    row = bearing_row(1.0e6, 0.2, 0.0, 4.0, 2.0, 1.6e5)
    assert row.value == pytest.approx(162.5e3, rel=1e-14) and row.outcome.value == "fail"
    assert mass_ratio_row(20e3, 10e3, 3.0).outcome.value == "warn"
    text = Path("configs/compressor_vendor_loads.toml").read_text().replace("detuning = 0.2", "detuning = 0.2\nbearing_pressure = 5.0e4")
    scene = tmp_path / "crank.toml"
    scene.write_text(text)
    result = runner.invoke(app, ["check", str(scene), "--json"])
    office = [c for c in json.loads(result.stdout)["scenes"][0]["checks"] if c["check"] == "office"]
    assert result.exit_code == 1 and office[0]["verdict"] == "fail"  # 114.8 t on 21 m²: 53.6 kPa


def test_two_torsion_springs_of_a_square_base_agree():
    """Gazetas' fit K_t = 4 G J_t^0.75 and Reissner-Sagoci's rigid circle of the same polar second
    moment, 16 G r³/3, are independent results for a square base; they agree within 5 %
    (8.35 against 7.93 G b³ for a square of side 2b)."""
    from foundation_calc.solvers.soil.torsion import gazetas_torsion, lysmer_torsion

    k_gazetas = gazetas_torsion(1.0e8, 4.0, 4.0)
    k_circle, _ = lysmer_torsion(1.0e8, 1800.0, 4.0, 4.0, 1.0e5, 0.0)
    assert k_gazetas / k_circle == pytest.approx(1.053, abs=0.005)


@pytest.mark.parametrize("method", ["lysmer", "gazetas", "sp26"])
def test_every_soil_method_gives_six_springs_that_turn_with_the_base(method):
    """Every spring and dashpot is positive, and a base turned a quarter turn (L and B exchanged)
    exchanges the x and y springs and the rocking springs about x and y (to round-off)."""
    import tomllib

    from foundation_calc.scenes import parse_scene

    data = tomllib.loads(Path("configs/block_fan_torsion_near_speed.toml").read_text(encoding="utf-8"))
    soil = {"method": method, "deformation_modulus": 3.0e7, "soil_class": "sand"} if method == "sp26" else {
        "method": method, "shear_wave_velocity": 150.0, "density": 1850.0, "poisson": 0.33, "material_damping": 0.03}
    data["soil"] = soil
    scene = parse_scene(data)
    model = scene.model()
    k, c = model.springs, np.diag(model.C)
    assert np.all(k > 0) and np.all(c > 0)
    L, B = scene.base
    swapped = parse_scene({**data, "block": {**data["block"], "length": B, "width": L}}).model().springs
    np.testing.assert_allclose(swapped[[1, 0, 2, 4, 3, 5]], k, rtol=1e-12)


@pytest.mark.parametrize("config", ["block_two_machines.toml", "compressor_vendor_loads.toml"])
def test_amplitudes_judges_the_amplitudes_alone(runner, tmp_path, config):
    """Each command judges its own check, on a block as on a crank scene: a bearing pressure over
    its allowable fails `check`'s office check (exit 1), not `amplitudes` (exit 0, verdict pass),
    which lists the office rows of a block for information only."""
    from tests.conftest import CONFIGS

    text = (CONFIGS / config).read_text(encoding="utf-8").replace("[limits]", "[limits]\nbearing_pressure = 1.0e4", 1)
    scene = tmp_path / config
    scene.write_text(text, encoding="utf-8")
    checked = runner.invoke(app, ["check", str(scene), "--json", "--jobs", "1"])
    verdicts = {c["check"]: c["verdict"] for c in json.loads(checked.stdout)["scenes"][0]["checks"]}
    assert checked.exit_code == 1 and verdicts["office"] == "fail" and verdicts["amplitudes"] == "pass", verdicts
    result = runner.invoke(app, ["amplitudes", str(scene), "--json"])
    doc = json.loads(result.stdout)
    assert result.exit_code == 0 and doc["verdict"] == "pass", result.output
    table = runner.invoke(app, ["amplitudes", str(scene)], env={"COLUMNS": "200"})
    assert table.exit_code == 0 and table.stdout.rstrip().splitlines()[-1].startswith("PASS"), table.stdout
    if "office" in doc:  # a block's office rows: information, judged by check
        assert [row["verdict"] for row in doc["office"] if row["check"] == "bearing pressure"] == ["fail"]
        assert "fcalc check judges them" in " ".join(table.stdout.split())
