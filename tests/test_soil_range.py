"""``[soil] modulus_range``: a check passes only if it passes over the whole range of the soil's
stiffness; the crossing of a resonance inside the range is found, not only the ends."""

from __future__ import annotations

import json
import math

import numpy as np
import pytest
import tomli_w
from scipy.linalg import eigh
from scipy.optimize import bisect

from foundation_calc.cli.app import app
from foundation_calc.scenes import parse_scene
from foundation_calc.solvers.constants import GRAVITY
from tests.conftest import CONFIGS, read_toml


def _write(tmp_path, document: dict):
    path = tmp_path / "scene.toml"
    path.write_text(tomli_w.dumps(document), encoding="utf-8")
    return path


def _frame_saw(modulus_range):
    document = read_toml(CONFIGS / "frame_saw.toml")
    document["soil"]["modulus_range"] = modulus_range
    return document


@pytest.mark.parametrize(("modulus_range", "code"), [([0.5, 1.5], 1), ([0.8, 1.2], 0)])
def test_frame_saw_over_the_modulus_range(runner, tmp_path, modulus_range, code):
    """The frame saw passes with its soil as given (3ω = p1 is 31 % away); at half the stiffness
    p1 falls to about 3ω (margin 2 %) and the check fails at factor 0.5; within ±20 % it passes."""
    path = _write(tmp_path, _frame_saw(modulus_range))
    resonance = runner.invoke(app, ["resonance", str(path), "--json"])
    assert resonance.exit_code == code, resonance.stdout
    ranged = json.loads(resonance.stdout)["modulus_range"]
    assert ranged["verdict"] == ("fail" if code else "pass")
    assert ranged["governing_factor"] == pytest.approx(modulus_range[0])
    assert "3ω = p1" in ranged["governing"]
    check = runner.invoke(app, ["check", str(path), "--json"])
    assert check.exit_code == code
    rows = {c["check"]: c for c in json.loads(check.stdout)["scenes"][0]["checks"]}
    assert rows["resonance"]["verdict"] == ("fail" if code else "pass")
    assert f"governing factor {modulus_range[0]:g}" in rows["resonance"]["reason"]


def _p1(scene, factor):
    """p1 of the sliding-rocking block by scipy.linalg.eigh on the factored coefficients."""
    f, s = scene.foundation, scene.soil
    M, h = scene.total_mass, f.cog_height
    K_x, K_phi = s.c_x * factor * f.base_area, s.c_z * factor * f.base_second_moment
    K = np.array([[K_x, -h * K_x], [-h * K_x, K_phi - M * GRAVITY * h + h * h * K_x]])
    return math.sqrt(eigh(K, np.diag([M, f.moment_of_inertia]), eigvals_only=True)[0])


def test_a_resonance_crossed_between_the_grid_points_fails_the_range():
    """Both ends of [0.6, 1.5] are more than 5 % from 3ω = p1, but p1 passes 3ω inside: the
    crossing factor (p1 = 3ω, margin 0) is found and fails the check. Its factor against a
    bisection of the eigen-solved p1 (rel 1e-7: Brent's tolerance against bisection's)."""
    from foundation_calc.checks.resonance import check_scene_resonances

    document = _frame_saw([0.6, 1.5])
    document["limits"]["detuning"] = 0.05
    scene = parse_scene(document)
    # speed at which 3ω = p1 at factor 0.93 (not a grid point); other conditions stay far away
    document["mechanism"]["speed_rpm"] = _p1(scene, 0.93) / 3.0 * 30.0 / math.pi
    scene = parse_scene(document)
    omega = scene.speed.omega_rad_s
    report = check_scene_resonances(scene)
    crossings = dict((label, f) for f, label in report.modulus_range.crossings)
    expected = bisect(lambda f: _p1(scene, f) - 3.0 * omega, 0.6, 1.5, xtol=1e-13)
    assert crossings["3ω = p1"] == pytest.approx(expected, rel=1e-7)
    ends = [p for p in report.modulus_range.points if p.factor in (0.6, 1.5)]
    assert [p.outcome.value for p in ends] == ["pass", "pass"]
    assert report.modulus_range.outcome.value == "fail"
    assert report.modulus_range.governing.factor in crossings.values()  # margin 0 at a crossing


@pytest.mark.parametrize(
    ("soil", "key", "factor"),
    [
        ({"c_z": 7.0e7, "c_x": 4.9e7}, "c_x", 0.5),
        ({"method": "lysmer", "shear_wave_velocity": 200.0, "density": 1800.0, "poisson": 0.3}, "shear_wave_velocity", 0.25),
        ({"method": "sp26", "deformation_modulus": 3.0e7, "soil_class": "sand"}, "deformation_modulus", 2.0),
    ],
)
def test_the_factor_scales_every_spring(soil, key, factor):
    """Every spring of every method scales with the stiffness data: K(f) = f K(1) (V_s by sqrt f)."""
    document = read_toml(CONFIGS / "frame_saw.toml")
    document["soil"] = soil
    scene = parse_scene(document)
    base, scaled = scene.soil_springs(), scene.with_modulus_factor(factor).soil_springs()
    for name in ("K_z", "K_x", "K_phi"):
        assert float(getattr(scaled, name)) == pytest.approx(factor * float(getattr(base, name)), rel=1e-12)


@pytest.mark.parametrize("bad", [[1.5, 0.5], [0.0, 1.0], [0.5, 20.0], [0.5]])
def test_a_range_out_of_order_is_refused(runner, tmp_path, bad):
    result = runner.invoke(app, ["resonance", str(_write(tmp_path, _frame_saw(bad)))])
    assert result.exit_code == 3 and "modulus_range" in result.stderr, result.stderr


def test_fcalc_soil_sample_reports_percentiles_and_probabilities(runner):
    result = runner.invoke(app, ["soil", str(CONFIGS / "frame_saw.toml"), "--sample", "2000", "--json"])
    assert result.exit_code == 0
    sample = json.loads(result.stdout)["sample"]
    p5, p50, p95 = sample["values"]["p1"]
    assert p5 < p50 < p95
    assert set(sample["failure_probability"]) == {"tips_over", "resonance", "amplitudes", "any"}
    assert json.loads(runner.invoke(app, ["soil", str(CONFIGS / "frame_saw.toml"), "--json"]).stdout)["sample"] is None


@pytest.mark.parametrize("config", ["frame_saw.toml", "compressor_medium_sand_lysmer.toml"])
def test_a_sample_without_scatter_is_the_checks_own_numbers(config):
    """With a vanishing COV every sample is the scene as given: its frequencies are those of
    ``fcalc resonance`` (the frequency-consistent ones on Gazetas' soil, rel 1e-7: the fixed
    points' tolerance) and its peaks of C those of the first approximation in ``fcalc amplitudes``
    (at most 0.5 % low: 96 phases a revolution against Newton's peak)."""
    from foundation_calc.checks.amplitudes.approximations import check_scene_amplitudes
    from foundation_calc.checks.resonance import check_scene_resonances
    from foundation_calc.checks.soil_sample import sample_scene

    document = read_toml(CONFIGS / config)
    if "method" in document["soil"]:
        document["soil"]["method"] = "gazetas"
    scene = parse_scene(document)
    drawn = sample_scene(scene, 8, 1e-12)
    frequencies = check_scene_resonances(scene).zero_order
    for mode in ("k0", "p1", "p2"):
        assert drawn.percentiles[mode][1] == pytest.approx(getattr(frequencies, mode), rel=1e-7)
    peaks = check_scene_amplitudes(scene).approximations["first_approximation"].peaks.displacement
    for key, i in (("peak_horizontal_C", 0), ("peak_vertical_C", 1)):
        assert float(peaks[i]) * (1 - 0.0049) <= drawn.percentiles[key][1] <= float(peaks[i]) * (1 + 1e-12)


def _block_on_springs(modulus_range, crossing_factor=None):
    """One motor (G 6.3 unbalance) on the block of ``block_two_machines.toml``, its springs spread so
    that one mode at a time meets the speed, dashpots a tenth of the file's (ζ of mode 5: 0.017), a
    5 % detuning band and an RMS velocity limit of 1.4 mm/s. With ``crossing_factor`` the motor
    runs at p5 (rocking about y) of the soil factored by it."""
    document = read_toml(CONFIGS / "block_two_machines.toml")
    document["machines"] = [document["machines"][1]]
    document["soil"]["stiffness"] = [8.4e9, 3.0e10, 1.05e10, 6.6e10, 1.6e11, 9.1e10]
    document["soil"]["dashpot"] = [0.1 * c for c in document["soil"]["dashpot"]]
    document["soil"]["modulus_range"] = modulus_range
    document["limits"] |= {"detuning": 0.05, "velocity_rms": 1.4e-3}
    if crossing_factor is not None:
        document["machines"][0]["speed_rpm"] = _block_frequencies(parse_scene(document), crossing_factor)[4] * 30.0 / math.pi
    return document


def _block_frequencies(scene, factor):
    """The six natural frequencies [rad/s] of the block on its springs times ``factor``, by
    scipy.linalg.eigh on the assembled K(f) = f diag(springs) + weight tilt and M."""
    model = scene.model()
    tilt = model.K - np.diag(model.springs)
    return np.sqrt(eigh(factor * np.diag(model.springs) + tilt, model.M, eigvals_only=True))


def test_a_block_that_passes_as_given_fails_where_a_mode_crosses_the_speed_inside_the_range():
    """The motor runs at p5 of the soil factored by 0.8, which is no grid point of [0.7, 1.4]: as
    given (p5 10.6 % away) and at both ends the block passes, inside it fails. The crossing against
    a bisection of the eigen-solved p5 (rel 1e-7: Brent's tolerance against bisection's); the
    verdict against a brute-force scan of 2001 factors (every mode's margin by eigh, fail inside
    5 %); the amplitude range's worst ratio against the largest of a scan of 150 factors, which it
    must not under-state by more than 1e-3 (the damped peak lies off the undamped crossing by about
    ζ5² = 3e-4)."""
    from foundation_calc.checks.amplitudes.machines import check_block, check_block_as_given

    scene = parse_scene(_block_on_springs([0.7, 1.4], crossing_factor=0.8))
    omega = scene.machines[0].omega_rad_s
    report = check_block(scene)
    assert check_block_as_given(scene).resonance.outcome.value == "pass"
    ranged = report.resonance.modulus_range
    crossings = {label: f for f, label in ranged.crossings}
    expected = bisect(lambda f: _block_frequencies(scene, f)[4] - omega, 0.7, 1.4, xtol=1e-13)
    assert crossings["motor: ω = mode 5 (ry)"] == pytest.approx(expected, rel=1e-7)
    assert [p.outcome.value for p in ranged.points if p.factor in (0.7, 1.4)] == ["pass", "pass"]
    assert ranged.governing.factor == crossings["motor: ω = mode 5 (ry)"]
    scan = np.geomspace(0.7, 1.4, 2001)
    margins = np.array([np.abs(omega - p) / p for p in (_block_frequencies(scene, f) for f in scan)])
    assert (ranged.outcome.value == "fail") == bool(margins.min() < 0.05)
    assert report.resonance.outcome.value == "fail" and "governing factor 0.8" in report.resonance.modulus_range.text

    amplitude = report.amplitude_range
    assert crossings["motor: ω = mode 5 (ry)"] in [p.factor for p in amplitude.points]
    worst_ratio = max(
        max(row.ratio for row in check_block_as_given(scene.with_modulus_factor(f)).limit_rows)
        for f in np.geomspace(0.7, 1.4, 150)
    )
    assert amplitude.governing.severity >= worst_ratio * (1.0 - 1e-3)
    assert amplitude.outcome.value == "fail" and check_block_as_given(scene).amplitude_outcome.value == "pass"


@pytest.mark.parametrize(
    "soil",
    [
        {"method": "springs", "stiffness": [8.4e9, 8.0e9, 1.05e10, 6.6e10, 1.6e11, 9.1e10], "dashpot": [1.9e7] * 6},
        {"c_z": 7.0e7, "c_x": 4.9e7, "c_psi": 6.0e7, "damping": [0.1, 0.1, 0.05]},
        {"c_z": 7.0e7, "c_x": 4.9e7},
        {"method": "lysmer", "shear_wave_velocity": 200.0, "density": 1800.0, "poisson": 0.3, "material_damping": 0.03},
        {"method": "gazetas", "shear_modulus": 7.2e7, "density": 1800.0, "poisson": 0.33},
        {"method": "sp26", "deformation_modulus": 3.0e7, "soil_class": "sand"},
    ],
    ids=["springs", "coefficients", "coefficients-default-c_psi", "lysmer", "gazetas", "sp26"],
)
def test_the_factor_scales_every_spring_and_dashpot_of_the_block(soil):
    """Every method of the block's soil: the six springs go as f and the six dashpots as sqrt(f)
    (the half-spaces' radiation dashpots as ρ V_s, the damping ratios' 2 ξ sqrt(K m) as sqrt K)."""
    document = read_toml(CONFIGS / "block_two_machines.toml")
    document["soil"] = soil
    scene = parse_scene(document)
    base, scaled = scene.model(), scene.with_modulus_factor(0.4).model()
    np.testing.assert_allclose(scaled.springs, 0.4 * base.springs, rtol=1e-12)
    np.testing.assert_allclose(np.diag(scaled.C), 0.4**0.5 * np.diag(base.C), rtol=1e-12)


def test_a_block_range_in_check_resonance_amplitudes_and_the_sheet(runner, tmp_path):
    """The range's verdict and governing factor reach every command and the calc sheet."""
    path = _write(tmp_path, _block_on_springs([0.7, 1.4], crossing_factor=0.8))
    check = runner.invoke(app, ["check", str(path), "--json"])
    assert check.exit_code == 1, check.stdout
    rows = {c["check"]: c for c in json.loads(check.stdout)["scenes"][0]["checks"]}
    assert "governing factor 0.8" in rows["resonance"]["reason"] and rows["resonance"]["verdict"] == "fail"
    assert "modulus range [0.7, 1.4]" in rows["amplitudes"]["reason"]
    resonance = json.loads(runner.invoke(app, ["resonance", str(path), "--json"]).stdout)
    assert resonance["modulus_range"]["verdict"] == "fail" and resonance["modulus_range"]["crossings"]
    amplitudes = runner.invoke(app, ["amplitudes", str(path), "--json"])
    assert amplitudes.exit_code == 1 and json.loads(amplitudes.stdout)["modulus_range"]["verdict"] == "fail"
    sheet = tmp_path / "sheet.md"
    assert runner.invoke(app, ["report", str(path), "-o", str(sheet)]).exit_code == 1
    text = sheet.read_text(encoding="utf-8").replace("\\[", "[").replace("\\]", "]")
    assert "| resonance | over the soil's modulus range [0.7, 1.4]: motor: ω = mode 5 (ry) at 0.0% (needs 5%) | governing factor 0.8" in text
    assert "| amplitudes | over the soil's modulus range [0.7, 1.4]: velocity\\_rms" in text
