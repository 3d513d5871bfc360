"""The resonance rule (docs/resonance-rule.md): one rule, the same governing condition and
margin in every command, a forcing share that decides which higher harmonics are judged, and a
detuning band per order."""

from __future__ import annotations

import json
import math
import re

import numpy as np
import pytest
import tomli_w
from scipy.integrate import quad

from foundation_calc.cli.app import app
from foundation_calc.scenes import parse_scene, read_toml
from tests.conftest import CONFIGS, mechanism_configs

CRANK_CONFIGS = [*mechanism_configs(), CONFIGS / "compressor_vendor_loads.toml"]


def _json(runner, *args):
    result = runner.invoke(app, [*map(str, args), "--json"])
    return result, json.loads(result.stdout)


def _write(tmp_path, scene, name="scene.toml"):
    path = tmp_path / name
    path.write_text(tomli_w.dumps(scene), encoding="utf-8")
    return path


@pytest.mark.parametrize("config", CRANK_CONFIGS, ids=lambda p: p.name)
def test_every_command_names_the_same_governing_condition_and_margin(runner, config):
    _, resonance = _json(runner, "resonance", config)
    _, amplitudes = _json(runner, "amplitudes", config)
    _, check = _json(runner, "check", config)
    governing = resonance["rule"]["governing"]
    assert amplitudes["resonance_rule"]["governing"] == governing
    phrase = f"{governing['condition']} at {governing['margin']:.1%} (needs {governing['required']:.0%})"
    reasons = {c["check"]: c["reason"] for c in check["scenes"][0]["checks"]}
    assert phrase in reasons["resonance"] and phrase in reasons["amplitudes"]
    for command in ("resonance", "amplitudes"):
        text = runner.invoke(app, [command, str(config)], env={"COLUMNS": "400"}).stdout
        last = text.strip().splitlines()[-1]
        assert phrase in last, (command, last)
        assert "nearest resonance" not in text


def test_a_near_harmonic_without_forcing_is_information_in_every_command(runner):
    """The Lysmer compressor runs 0.58 % from 9ω = p2, whose forcing share is about 3e-10: every
    command governs with 3ω = p1 at 36.2 %, and 9ω = p2 appears only as information."""
    config = CONFIGS / "compressor_medium_sand_lysmer.toml"
    _, doc = _json(runner, "resonance", config)
    row = next(r for r in doc["resonances"] if r["condition"] == "9ω = p2")
    assert row["margin"] < 0.01 and row["forcing_share"] < 1e-6 and row["status"] == "information"
    for command in ("resonance", "amplitudes", "check"):
        text = runner.invoke(app, [command, str(config)], env={"COLUMNS": "400"}).stdout
        assert "3ω = p1 at 36.2% (needs 20%)" in text, command
        for line in text.splitlines():
            if "9ω = p2" in line and "│" not in line:
                assert "information, not the verdict" in line, (command, line)


def _cos_psi_harmonic(lam: float, k: int) -> float:
    """Coefficient of cos 2kφ in cos ψ = sqrt(1 - λ² sin² φ), by adaptive quadrature."""
    return 2.0 / math.pi * quad(lambda p: math.sqrt(1.0 - (lam * math.sin(p)) ** 2) * math.cos(2 * k * p), 0.0, math.pi)[0]


def test_forcing_share_of_the_vertical_harmonics_against_quadrature(runner, tmp_path):
    """k0 is the purely vertical mode of the averaged operator and the vertical forcing at 2ω and
    4ω is the rod's centre of mass accelerating as l' d²(cos ψ)/dt² (the crank pin moves at ω
    only), so share(4ω = k0)/share(2ω = k0) = 16 |a2| / (4 |a1|), a_k the cos 2kφ coefficients
    of cos ψ, here by scipy's quad (independent of the FFT fcalc uses; the ratio is a smooth
    function sampled 256 times a revolution, so the two agree to round-off: rtol 1e-9)."""
    scene = read_toml(CONFIGS / "frame_saw.toml")
    scene["mechanism"]["crank_radius"] = 0.6  # λ = 0.5: a 4ω forcing that matters
    _, doc = _json(runner, "resonance", _write(tmp_path, scene))
    rows = {r["condition"]: r for r in doc["resonances"]}
    lam = doc["derived"]["lambda"]
    expected = 16 * abs(_cos_psi_harmonic(lam, 2)) / (4 * abs(_cos_psi_harmonic(lam, 1)))
    assert rows["4ω = k0"]["forcing_share"] / rows["2ω = k0"]["forcing_share"] == pytest.approx(expected, rel=1e-9)
    assert rows["4ω = k0"]["forcing_share"] >= 0.01 and rows["4ω = k0"]["judged"]


def test_a_judged_higher_harmonic_fails_inside_its_band(runner, tmp_path):
    """With λ = 0.5 the 4ω = k0 forcing share is above 1 %: 10 % from 4ω = k0 fails."""
    scene = read_toml(CONFIGS / "frame_saw.toml")
    scene["mechanism"]["crank_radius"] = 0.6
    k0 = parse_scene(scene).design()
    from foundation_calc.solvers.crank.natural import design_frequencies

    zero, _ = design_frequencies(k0)
    del scene["mechanism"]["speed_rpm"]
    scene["mechanism"]["omega"] = zero.k0 / 4 * 1.1
    result, doc = _json(runner, "resonance", _write(tmp_path, scene))
    assert doc["rule"]["governing"]["condition"] == "4ω = k0" and result.exit_code == 1


def _frame_saw_at(rpm: float, detuning=None) -> dict:
    scene = read_toml(CONFIGS / "frame_saw.toml")
    scene["mechanism"]["speed_rpm"] = rpm
    if detuning is not None:
        scene["limits"]["detuning"] = detuning
    return scene


def test_detuning_per_order_is_the_offices_rule(runner, tmp_path):
    """At 420 rpm 3ω = p1 is 15.7 % away: it fails the default 20 % band, passes an office rule
    that bands 1× and 2× only, and still fails within 5 % (the build-tolerance floor)."""
    result, doc = _json(runner, "resonance", _write(tmp_path, _frame_saw_at(420)))
    assert result.exit_code == 1 and doc["rule"]["governing"]["condition"] == "3ω = p1"
    office = {"1": 0.2, "2": 0.2}
    path = _write(tmp_path, _frame_saw_at(420, office))
    result, doc = _json(runner, "resonance", path)
    assert result.exit_code == 0 and doc["rule"]["detuning"] == {"1": 0.2, "2": 0.2}
    row = next(r for r in doc["resonances"] if r["condition"] == "3ω = p1")
    assert row["required"] == 0.0 and row["verdict"] == "pass"
    text = runner.invoke(app, ["resonance", str(path)], env={"COLUMNS": "400"}).stdout
    assert "detuning = {1 = 0.2, 2 = 0.2}" in text
    _, check = _json(runner, "check", path)
    assert check["scenes"][0]["checks"][0]["result"]["rule"]["detuning"] == {"1": 0.2, "2": 0.2}
    _, amplitudes = _json(runner, "amplitudes", path)
    assert amplitudes["resonance_rule"]["detuning"] == {"1": 0.2, "2": 0.2}
    near = 38.003 * 30 / math.pi * 1.03  # 3 % above 3ω = p1
    result, doc = _json(runner, "resonance", _write(tmp_path, _frame_saw_at(near, office)))
    assert result.exit_code == 1 and doc["rule"]["governing"]["condition"] == "3ω = p1"


@pytest.mark.parametrize(
    ("detuning", "words"),
    [
        ({"0": 0.2}, ["detuning key '0'", "1 ... 64"]),
        ({"x": 0.2}, ["detuning key 'x'", "1 ... 64"]),
        ({"2": 1.5}, ["detuning.2 = 1.5", "(0, 1)"]),
        ({"2": 0.0}, ["detuning.2 = 0.0", "(0, 1)"]),
        ({"1": "0.2"}, ["detuning.1", "number"]),
        ({}, ["names no order"]),
        (1.2, ["detuning = 1.2", "(0, 1)"]),
    ],
)
def test_a_bad_detuning_names_the_key_the_value_and_the_range(runner, tmp_path, detuning, words):
    result = runner.invoke(app, ["resonance", str(_write(tmp_path, _frame_saw_at(250, detuning)))])
    assert result.exit_code == 3
    message = " ".join(result.stderr.split())
    assert "limits.detuning" in message and all(w in message for w in words), message


def test_a_plain_detuning_keeps_working(runner, tmp_path):
    result, doc = _json(runner, "resonance", _write(tmp_path, _frame_saw_at(250, 0.35)))
    assert result.exit_code == 1 and doc["rule"]["detuning"] == 0.35


def test_sweep_status_names_the_failing_condition_that_governs(runner):
    """420 rpm is 5.9 % from 4ω = k0 (share 0.3 %, not judged) and 15.7 % from 3ω = p1 (judged):
    the row fails on 3ω = p1; 250 rpm is only over the displacement limit of 0.1 mm."""
    config = CONFIGS / "frame_saw_over_amplitude_limit.toml"
    _, doc = _json(runner, "sweep", config, "--speed", "250:420:2")
    low, high = doc["points"]
    assert high["governing_condition"] == "3ω = p1" and high["margin"] == pytest.approx(0.157, abs=1e-3)
    assert high["resonance_status"] == "fail" and high["status"] == "fail"
    assert low["resonance_status"] in ("clear", "information") and low["over_limits"] == ["displacement"]
    text = runner.invoke(app, ["sweep", str(config), "--speed", "250:420:2"], env={"COLUMNS": "400"}).stdout
    rows = [line for line in text.splitlines() if re.match(r"^│\s+(250|420) ", line)]
    assert "fail: over displacement limit; resonances clear, governing 3ω = p1 at 30.9% (needs 20%)" in rows[0]
    assert "fail: inside 3ω = p1 at 15.7% (needs 20%); over displacement limit" in rows[1]
    assert "4ω = k0" not in rows[1]


def test_sweep_row_at_the_operating_speed_agrees_with_check(runner):
    config = CONFIGS / "frame_saw.toml"
    _, sweep = _json(runner, "sweep", config, "--speed", "250:300:2")
    _, resonance = _json(runner, "resonance", config)
    governing = resonance["rule"]["governing"]
    row = sweep["points"][0]
    assert row["governing_condition"] == governing["condition"]
    assert row["margin"] == pytest.approx(governing["margin"], rel=1e-12)
    assert np.isclose(row["needed"], governing["required"])
