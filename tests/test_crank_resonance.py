"""Resonance table of `fcalc resonance`: critical speeds, margins and verdicts."""

from __future__ import annotations

import json
import math

import numpy as np
import pytest
import tomli_w

from foundation_calc.cli.app import app
from foundation_calc.scenes import parse_scene, read_toml
from tests import crank_reference as ref
from tests.conftest import CONFIGS, mechanism_configs

PAPER = {"ω = k0", "2ω = k0", "ω = p1", "ω = p2", "3ω = p1", "3ω = p2"}
EXTRA = {"4ω = k0", "2ω = p1", "2ω = p2"}


def _run_json(runner, tmp_path, doc, *args):
    path = tmp_path / "scene.toml"
    path.write_text(tomli_w.dumps(doc), encoding="utf-8")
    result = runner.invoke(app, ["resonance", str(path), "--json", *args])
    return result, (json.loads(result.stdout) if result.stdout else None)


def _reference_modes(doc):
    """(k0, p1, p2) zero-order and averaged, from the independent reference model."""
    f, s, m = doc["foundation"], doc["soil"], doc["mechanism"]
    M_tot = f["mass"] + m["rod_mass"] + m.get("slider_mass", 0.0)
    soil = dict(M_tot=M_tot, h=f["cog_height"], S=f["base_area"], I1=f["base_second_moment"], c=s["c_z"], c1=s["c_x"])
    K = ref.stiffness_matrix(**soil)
    zero = np.diag([M_tot, M_tot, f["moment_of_inertia"]])
    avg = ref.averaged_mass_matrix(
        M=f["mass"], I_c=f["moment_of_inertia"], m=m["rod_mass"], l1=m["rod_cog_to_crank_pin"],
        rho=m["rod_radius_of_gyration"], m1=m.get("slider_mass", 0.0), a=m["crank_axis_to_cog"],
        r=m["crank_radius"], l=m["rod_length"],
    )
    out = []
    for Mm in (zero, avg):
        k0 = math.sqrt(K[1, 1] / M_tot)
        p1, p2 = ref.frequencies(K[np.ix_([0, 2], [0, 2])], Mm[np.ix_([0, 2], [0, 2])])
        out.append({"k0": k0, "p1": p1, "p2": p2})
    return out


def test_table_lists_the_papers_and_the_extra_conditions(runner, tmp_path, frame_saw):
    result, doc = _run_json(runner, tmp_path, frame_saw)
    rows = {r["condition"]: r for r in doc["resonances"]}
    assert set(rows) == PAPER | EXTRA
    assert {r["source"] for c, r in rows.items() if c in PAPER} == {"paper"}
    assert {r["source"] for c, r in rows.items() if c in EXTRA} == {"extra"}


@pytest.mark.parametrize("config", mechanism_configs(), ids=lambda p: p.name)
def test_critical_speeds_and_margins_against_reference(runner, tmp_path, config):
    from foundation_calc.scenes import read_toml

    scene = read_toml(config)
    result, doc = _run_json(runner, tmp_path, scene)
    zero, avg = _reference_modes(scene)
    for mode in ("k0", "p1", "p2"):
        assert doc["natural_frequencies"][mode] == pytest.approx(zero[mode], rel=1e-9)
        assert doc["natural_frequencies_averaged_inertia"][mode] == pytest.approx(avg[mode], rel=1e-9)
    omega = doc["speed"]["omega"]
    for row in doc["resonances"]:
        n, mode = row["harmonic"], row["mode"]
        w0, w1 = zero[mode] / n, avg[mode] / n
        assert row["critical_speed"]["omega"] == pytest.approx(w0, rel=1e-9)
        assert row["critical_speed"]["speed_rpm"] == pytest.approx(w0 * 30 / math.pi, rel=1e-9)
        assert row["critical_speed_averaged_inertia"]["omega"] == pytest.approx(w1, rel=1e-9)
        margin = min(abs(omega - w0) / w0, abs(omega - w1) / w1)
        assert row["margin"] == pytest.approx(margin, rel=1e-9, abs=1e-12)
        inside = margin < row["required"]
        # README "Verdicts": a driven (paper) condition fails inside the band, any within 5 %
        if margin < 0.05 or (inside and row["source"] == "paper"):
            expected = "fail"
        else:
            expected = "warn" if inside else "pass"
        assert row["verdict"] == expected


@pytest.mark.parametrize(("mode", "harmonic", "label"), [("k0", 1, "ω = k0"), ("p1", 3, "3ω = p1"), ("p2", 1, "ω = p2"), ("k0", 2, "2ω = k0")])
@pytest.mark.parametrize("offset", [0.0, 1e-12, 0.05, -0.1])
def test_speed_inside_the_band_fails_with_its_margin(runner, tmp_path, frame_saw, mode, harmonic, label, offset):
    zero, _ = _reference_modes(frame_saw)
    del frame_saw["mechanism"]["speed_rpm"]
    frame_saw["mechanism"]["omega"] = zero[mode] / harmonic * (1 + offset)
    result, doc = _run_json(runner, tmp_path, frame_saw)
    assert result.exit_code == 1
    assert doc["verdict"] == "fail"
    row = next(r for r in doc["resonances"] if r["condition"] == label)
    assert row["verdict"] == "fail"
    assert row["margin"] <= abs(offset) * (1 + 1e-9) + 1e-15
    assert math.isfinite(row["margin"])


def test_detuning_from_the_scene_decides(runner, tmp_path):
    # the shipped frame saw at 250 rpm: nearest paper condition 3ω = p1, about 30.9 % away;
    # the extra 4ω = k0 is 37 % away
    scene = read_toml(CONFIGS / "frame_saw.toml")
    scene["limits"]["detuning"] = 0.35
    result, doc = _run_json(runner, tmp_path, scene)
    assert result.exit_code == 1
    failing = {r["condition"] for r in doc["resonances"] if r["verdict"] == "fail"}
    assert failing == {"3ω = p1"}
    scene["limits"]["detuning"] = 0.2
    result, doc = _run_json(runner, tmp_path, scene)
    assert result.exit_code == 0


def test_extra_resonance_warns_and_strict_fails(runner, tmp_path):
    scene = read_toml(CONFIGS / "frame_saw.toml")
    scene["mechanism"]["speed_rpm"] = 440  # extra only: 4ω = k0 11 %, 2ω = p1 18.9 % away
    result, doc = _run_json(runner, tmp_path, scene)
    assert doc["verdict"] == "warn" and result.exit_code == 0
    result, _ = _run_json(runner, tmp_path, scene, "--strict")
    assert result.exit_code == 1


def test_extra_resonance_within_five_percent_fails(runner, tmp_path, frame_saw):
    result, doc = _run_json(runner, tmp_path, frame_saw)  # 300 rpm is 0.5 % from 2ω = p1
    assert doc["verdict"] == "fail" and result.exit_code == 1
    row = next(r for r in doc["resonances"] if r["condition"] == "2ω = p1")
    assert row["source"] != "paper" and row["verdict"] == "fail"


def test_scene_speed_units_agree(frame_saw):
    rpm = parse_scene(frame_saw).design().omega
    del frame_saw["mechanism"]["speed_rpm"]
    frame_saw["mechanism"]["frequency_hz"] = 5.0
    assert parse_scene(frame_saw).design().omega == pytest.approx(rpm, rel=1e-15)
    assert rpm == pytest.approx(10 * math.pi, rel=1e-15)
