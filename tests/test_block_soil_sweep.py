"""`fcalc sweep --soil` of a block foundation: each row is `fcalc amplitudes` and the resonance
verdict of `fcalc check` of the block on the soil with its stiffness data × the row's factor.

The factored scenes are written here by hand from the shipped TOML (given springs × f and their
dashpots × sqrt(f); a shear wave velocity × sqrt(f), so G × f), not by the code's own
``factored``: the sweep and the factored scene meet only through the commands' JSON.
Tolerances: factor 1 is the scene as given, the same arithmetic (1e-12 relative); another factor
goes through V_s = sqrt(f) V_s0 written in decimal and squared back (a few ulp on G), 1e-9.
"""

from __future__ import annotations

import copy
import json
import math
import re

import numpy as np
import pytest
import tomli_w

from foundation_calc.checks.resonance.rule import condition_phrase
from foundation_calc.cli.app import app
from foundation_calc.scenes import read_toml
from tests.conftest import CONFIGS

#: A block on a frequency-dependent soil: block_two_machines.toml on Gazetas' embedded footing.
GAZETAS = {"method": "gazetas", "shear_wave_velocity": 260.0, "density": 1900.0, "poisson": 0.33, "material_damping": 0.03}

#: The sweep's value keys -> the amplitudes document's per-point keys.
VALUES = {"peak": "displacement_peak", "velocity_peak": "velocity_peak", "displacement_rms": "displacement_rms",
          "velocity_rms": "velocity_rms", "acceleration_peak": "acceleration_peak", "acceleration_rms": "acceleration_rms"}


def _springs():
    return read_toml(CONFIGS / "block_two_machines.toml")


def _gazetas():
    document = _springs()
    document["soil"] = dict(GAZETAS)
    document["block"]["embedment"] = 1.0
    return document


def _piles():
    return read_toml(CONFIGS / "block_on_piles.toml")


SCENES = {"springs": _springs, "gazetas": _gazetas, "piles": _piles}


def _factored(document: dict, f: float) -> dict:
    """``document`` with its soil's stiffness data × ``f``, written out by hand."""
    out = copy.deepcopy(document)
    soil = out["soil"]
    if soil.get("method") == "springs":
        soil["stiffness"] = [k * f for k in soil["stiffness"]]
        soil["dashpot"] = [c * math.sqrt(f) for c in soil["dashpot"]]
    else:
        soil["shear_wave_velocity"] = soil["shear_wave_velocity"] * math.sqrt(f)
    return out


def _write(tmp_path, name: str, document: dict):
    path = tmp_path / f"{name}.toml"
    path.write_text(tomli_w.dumps(document), encoding="utf-8")
    return path


def _json(runner, *args) -> dict:
    result = runner.invoke(app, [*args, "--json"])
    assert result.exit_code in (0, 1), result.stderr
    return json.loads(result.stdout)


def _assert_row_is_the_scenes(runner, row, path, rel):
    """``row`` against `fcalc amplitudes` and `fcalc check` of the scene at ``path``."""
    amplitudes = _json(runner, "amplitudes", str(path))
    for key, name in VALUES.items():
        for d in "xyz":
            largest = max(point[name][d] for point in amplitudes["points"].values())
            assert row[key][d] == pytest.approx(largest, rel=rel, abs=0.0), (key, d)
    governing = next(r for r in amplitudes["resonances"] if r["condition"] == row["governing_condition"])
    assert row["margin"] == pytest.approx(governing["margin"], rel=rel, abs=0.0)
    assert row["resonance_status"] == governing["status"]
    (scene,) = _json(runner, "check", str(path))["scenes"]
    checks = {c["check"]: c for c in scene["checks"]}
    assert condition_phrase(row["governing_condition"], row["margin"], row["needed"]) in checks["resonance"]["reason"]
    failing = sorted({r["quantity"] for r in checks["amplitudes"]["result"]["limits"] if r["verdict"] == "fail"})
    assert sorted(row["over_limits"]) == failing
    rule = {"clear": "pass", "information": "pass", "warn": "warn", "fail": "fail"}[row["resonance_status"]]
    assert rule == checks["resonance"]["verdict"]
    assert row["status"] == ("fail" if failing else rule) and not row["resonant"]


@pytest.mark.parametrize("kind", list(SCENES))
def test_each_row_is_the_block_on_its_factored_soil(runner, tmp_path, kind):
    """Factor 1 is the scene as given; 0.6 and 1.8 are the scene written with its soil × f (a pile
    group recomputed from the factored soil around its piles), to the tolerances of the module
    docstring; every machine runs at its own speed."""
    document = SCENES[kind]()
    path = _write(tmp_path, kind, document)
    sweep = _json(runner, "sweep", str(path), "--soil", "1")
    assert sweep["variable"] == "soil_factor" and [p["soil_factor"] for p in sweep["points"]] == [1.0]
    assert sweep["machines"].keys() == {m["name"] for m in document["machines"]}
    _assert_row_is_the_scenes(runner, sweep["points"][0], path, 1e-12)
    rows = _json(runner, "sweep", str(path), "--soil", "0.6:1.8:2")["points"]
    assert [r["soil_factor"] for r in rows] == [0.6, 1.8]
    for row in rows:
        factored = _write(tmp_path, f"{kind}_{row['soil_factor']}", _factored(document, row["soil_factor"]))
        _assert_row_is_the_scenes(runner, row, factored, 1e-9)


def test_csv_plot_and_api_hold_the_json_rows(runner, tmp_path):
    """--csv holds the --json rows (the shortest round-trip floats: equal to the last bit), --plot
    writes a PNG, and fc.sweep's values are the factors; the table has one row per factor."""
    import csv

    import foundation_calc as fc

    pytest.importorskip("matplotlib")
    args = ["sweep", str(CONFIGS / "block_two_machines.toml"), "--soil", "0.5:2:3"]
    doc = _json(runner, *args)
    table, picture = tmp_path / "soil.csv", tmp_path / "soil.png"
    result = runner.invoke(app, [*args, "--csv", str(table), "--plot", str(picture)])
    assert result.exit_code == 0, result.stderr
    assert "factor" in result.stdout and "0.5" in result.stdout and "1.25" in result.stdout
    with table.open(encoding="utf-8") as stream:
        rows = list(csv.DictReader(stream))
    assert len(rows) == len(doc["points"]) == 3
    for row, point in zip(rows, doc["points"]):
        assert float(row["soil_factor"]) == point["soil_factor"] and row["status"] == point["status"]
        assert [float(row[f"velocity_rms_{d}_m_s"]) for d in "xyz"] == [point["velocity_rms"][d] for d in "xyz"]
        assert row["governing_condition"] == point["governing_condition"] and float(row["margin"]) == point["margin"]
    assert picture.read_bytes()[:8] == b"\x89PNG\r\n\x1a\n"
    assert fc.sweep(CONFIGS / "block_two_machines.toml", soil="0.5:2:3").values.tolist() == [0.5, 1.25, 2.0]


def test_a_soil_sweep_refuses_isolators_a_swept_machine_and_a_block_that_tips_over(runner):
    """Isolators are catalogue springs, no soil to factor; --machine/--alone choose a speed sweep's
    machine: usage errors (exit 2) that name the option and why. A factor so small that the block
    tips over (K_rx = 1e-5 × 6.6e10 N m/rad below W z_G = 2.1e6 N m) is an invalid scene (exit 3)
    naming the factor."""
    isolated = runner.invoke(app, ["sweep", str(CONFIGS / "block_on_isolators.toml"), "--soil", "0.5:2:3"])
    assert isolated.exit_code == 2 and "'--soil'" in isolated.stderr and "[[isolators]]" in isolated.stderr
    for extra in (["--machine", "motor"], ["--alone"]):
        result = runner.invoke(app, ["sweep", str(CONFIGS / "block_two_machines.toml"), "--soil", "0.5:2:3", *extra])
        assert result.exit_code == 2 and "every machine at its own speed" in result.stderr, extra
    tipped = runner.invoke(app, ["sweep", str(CONFIGS / "block_two_machines.toml"), "--soil", "0.00001:1:3"])
    assert tipped.exit_code == 3 and "at soil factor 1e-05: the block tips over about x" in tipped.stderr


def test_a_factor_where_an_order_meets_an_undamped_mode_is_resonant(runner, tmp_path):
    """block_two_machines.toml without dashpots: at the factor f where a mode's frequency is the
    motor's speed ω, det(f K_s + K_W - ω² M) = 0, f an eigenvalue of (ω² M - K_W) v = f K_s v
    (scipy; K_s the given springs, K_W the weight's tilt), the row has no steady state: status
    resonant, its values null in the JSON, empty in the CSV and a dash in the table."""
    import scipy.linalg

    from foundation_calc.scenes import parse_scene

    document = _springs()
    del document["soil"]["dashpot"]
    path = _write(tmp_path, "undamped", document)
    model = parse_scene(document).model()
    K_s = np.diag(model.springs)
    omega = 1490.0 * math.pi / 30.0  # the motor
    f = float(max(scipy.linalg.eigvals(omega**2 * model.M - (model.K - K_s), K_s).real))
    (row,) = _json(runner, "sweep", str(path), "--soil", repr(f))["points"]
    assert row["resonant"] and row["status"] == "resonant" and row["peak"] == {"x": None, "y": None, "z": None}
    assert row["governing_condition"].startswith("motor: ω = mode") and row["margin"] < 1e-9
    table = tmp_path / "undamped.csv"
    shown = runner.invoke(app, ["sweep", str(path), "--soil", repr(f), "--csv", str(table)])
    assert shown.exit_code == 0 and "resonant" in shown.stdout and re.search(r"│\s+-\s+│", shown.stdout)
    assert ",true,,,," in table.read_text(encoding="utf-8")


def test_each_row_names_the_modes_as_they_are_at_its_factor(runner, tmp_path):
    """block_on_piles.toml: mode 5 is dominated by z at factor 0.5 and by ry at 2 (the group's
    springs do not scale alike); each row's conditions carry the labels `fcalc resonance` gives the
    scene written with V_s × sqrt(f), not the first row's."""
    from foundation_calc.api.scene import load
    from foundation_calc.checks.sweep.block import sweep_block_soil

    document = _piles()
    sweep = sweep_block_soil(load(CONFIGS / "block_on_piles.toml").model, [0.5, 2.0])
    labels = [[c.label for c in rows] for rows in sweep.conditions]
    assert labels[0] != labels[1]
    for f, found in zip((0.5, 2.0), labels):
        path = _write(tmp_path, f"piles_{f}", _factored(document, f))
        assert found == [r["condition"] for r in _json(runner, "resonance", str(path))["resonances"]]
