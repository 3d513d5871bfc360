"""Static settlement s = W / K_z beside the bearing pressure, one office check for crank and block
scenes (``checks/office.py``, ``static_rows``), judged against ``[limits] settlement`` [m] where given.

Golden values by hand: W from the scene's masses (block L B H ρ plus the machines; a crank
foundation's M + m + m1) and g = 9.81 m/s² (the project's constant); K_z from the scene's own
numbers (a block's given spring, c_z S of Barkan's coefficients) or Gazetas' (1991) Table 1
surface formula transcribed here, K_z = 2 G L/(1 − ν) (0.73 + 1.54 χ^0.75), χ = A_b/(4 L²), L
the half-length.
"""

from __future__ import annotations

import json
import tomllib
from pathlib import Path

import pytest

from foundation_calc.checks.amplitudes.machines import check_block
from foundation_calc.checks.registry import CHECKS
from foundation_calc.scenes import parse_scene

CONFIGS = Path("configs")
G_ACC = 9.81


def _load(name: str) -> dict:
    with open(CONFIGS / f"{name}.toml", "rb") as fh:
        return tomllib.load(fh)


def _block(**limits) -> dict:
    document = _load("block_two_machines")
    document["limits"] |= limits
    return document


def _row(rows, name="settlement"):
    (row,) = [r for r in rows if r.name == name]
    return row


# W = (7.0 · 4.0 · 2.2 · 2400 + 12 000 + 6 000) kg · 9.81 m/s², K_z = 1.05e10 N/m (the scene's spring)
BLOCK_W = (7.0 * 4.0 * 2.2 * 2400.0 + 12.0e3 + 6.0e3) * G_ACC
BLOCK_S = BLOCK_W / 1.05e10  # 1.549e-4 m


@pytest.mark.parametrize("allowable, verdict", [(1.0e-4, "fail"), (2.0e-4, "pass")])
def test_a_blocks_settlement_is_its_weight_over_its_vertical_spring(allowable, verdict):
    report = check_block(parse_scene(_block(settlement=allowable), "two"))
    row = _row(report.office)
    assert row.value == pytest.approx(BLOCK_S, rel=1e-12)  # the same sum and one division: round-off
    assert (row.limit, row.unit, row.outcome.value, row.source) == (allowable, "m", verdict, "scene [limits] settlement")
    assert row.text.startswith("s = W/K_z = 1627 kN / 1.05e+10 N/m = 0.1549 mm")
    assert report.office_outcome.value == verdict
    names = [r.name for r in report.office]
    assert names == ["eccentricity x", "eccentricity y", "settlement", "mass ratio"]


def test_without_the_limit_no_settlement_row_and_beside_the_bearing_pressure_with_it():
    assert not [r for r in check_block(parse_scene(_block(), "two")).office if r.name == "settlement"]
    rows = check_block(parse_scene(_block(settlement=1e-3, bearing_pressure=1.5e5), "two")).office
    assert [r.name for r in rows][2:4] == ["bearing pressure", "settlement"]


def test_a_block_on_gazetas_soil_settles_on_the_static_surface_spring():
    G, rho, nu = 1950.0 * 450.0**2, 1950.0, 0.3
    document = _block(settlement=1e-3)
    document["soil"] = {"method": "gazetas", "shear_wave_velocity": 450.0, "density": rho, "poisson": nu,
                        "material_damping": 0.04}
    L, B = 7.0 / 2.0, 4.0 / 2.0  # Gazetas' half-sides
    chi = (4.0 * L * B) / (4.0 * L * L)
    K_z = 2.0 * G * L / (1.0 - nu) * (0.73 + 1.54 * chi**0.75)
    row = _row(check_block(parse_scene(document, "gazetas")).office)
    # Table 1's formula as printed: the code's transcription agrees to round-off
    assert row.value == pytest.approx(BLOCK_W / K_z, rel=1e-12)


def test_a_crank_scene_runs_the_office_check_for_its_settlement_alone():
    document = _load("compressor_damped_near_resonance")
    scene = parse_scene(document, "crank")
    assert CHECKS["crank_foundation"]["office"](scene) is None  # neither allowable given: not run
    document["limits"]["settlement"] = 1.0e-3
    finding = CHECKS["crank_foundation"]["office"](parse_scene(document, "crank"))
    W = (25.0e3 + 65.0 + 140.0) * G_ACC
    s = W / (2.0e7 * 12.0)  # c_z S = 2.4e8 N/m: 1.030e-3 m
    row = _row(finding.report.office)
    assert row.value == pytest.approx(s, rel=1e-12)
    assert finding.outcome.value == "fail" and "settlement: s = W/K_z" in finding.reason[0]
    document["limits"] |= {"settlement": 2.0e-3, "bearing_pressure": 1.5e5}
    rows = CHECKS["crank_foundation"]["office"](parse_scene(document, "crank")).report.office
    assert [r.name for r in rows] == ["bearing pressure", "settlement"]
    assert all(r.outcome.value == "pass" for r in rows)


@pytest.mark.parametrize("source", ["block_two_machines", "compressor_damped_near_resonance"])
def test_every_kind_reports_the_settlement_in_check_json_and_on_the_sheet(source, tmp_path):
    from typer.testing import CliRunner

    from foundation_calc.cli.app import app

    path = tmp_path / "scene.toml"
    path.write_text((CONFIGS / f"{source}.toml").read_text().replace("[limits]\n", "[limits]\nsettlement = 1.0e-5\n"))
    runner = CliRunner()
    result = runner.invoke(app, ["check", str(path), "--json"])
    assert result.exit_code == 1, result.output
    document = json.loads(result.stdout)
    text = json.dumps(document)
    assert "s = W/K_z" in text and "scene [limits] settlement" in text
    sheet = tmp_path / "scene.md"
    runner.invoke(app, ["report", str(path), "-o", str(sheet)])
    text = sheet.read_text()
    assert "s = W/K\\_z" in text and "\\[limits\\] settlement: scene value, no source given" in text  # Markdown escapes _ and [
    assert "no \\[limits\\] settlement" not in text


def test_a_settlement_typed_in_mm_warns():
    found = [f for f in parse_scene(_block(settlement=25.0), "two").plausibility_findings() if f.key == "limits.settlement"]
    assert found and "mm" in str(found[0])
    assert not [f for f in parse_scene(_block(settlement=0.025), "two").plausibility_findings() if f.key == "limits.settlement"]
