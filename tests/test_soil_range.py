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
    from foundation_calc.checks.crank_resonance import check_scene_resonances

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


def test_sampled_probability_of_a_resonance_failure_against_the_lognormal_cdf():
    """The frame saw fails its resonance check exactly where the stiffness factor F leaves an
    interval found by bisection of the scalar check; with F lognormal (median 1, COV 0.3) that
    probability is Φ(ln f_low / s) + 1 - Φ(ln f_high / s). The sample of 20 000 must agree within
    4 standard errors sqrt(p (1 - p)/n)."""
    from scipy.stats import norm

    from foundation_calc.checks.crank_resonance import check_scene_resonances
    from foundation_calc.checks.soil_sample import sample_scene

    scene = parse_scene(read_toml(CONFIGS / "frame_saw.toml"))

    def fails(f):
        return check_scene_resonances(scene.with_modulus_factor(f)).outcome.value == "fail"

    grid = np.geomspace(0.2, 5.0, 400)
    failing = np.array([fails(f) for f in grid])
    edges = np.flatnonzero(failing[1:] != failing[:-1])
    s = math.sqrt(math.log1p(0.3**2))
    probability = 0.0
    bounds = [bisect(lambda f: float(fails(f)) - 0.5, grid[i], grid[i + 1], xtol=1e-10) for i in edges]
    points = [0.0, *bounds, math.inf]
    for i, (a, b) in enumerate(zip(points, points[1:])):
        inside = failing[0] if i == 0 else failing[edges[i - 1] + 1]
        if inside:
            probability += (1.0 if b == math.inf else norm.cdf(math.log(b) / s)) - (0.0 if a == 0.0 else norm.cdf(math.log(a) / s))
    n = 20_000
    sampled = sample_scene(scene, n, 0.3, seed=3).failure_probability["resonance"]
    assert 0.05 < probability < 0.5  # the interval is inside the sampled range: a test that can fail
    assert sampled == pytest.approx(probability, abs=4.0 * math.sqrt(probability * (1 - probability) / n))


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
    from foundation_calc.checks.crank_amplitudes import check_scene_amplitudes
    from foundation_calc.checks.crank_resonance import check_scene_resonances
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


def test_a_block_foundation_refuses_a_range_it_would_not_judge(runner, tmp_path):
    """The block's checks take the soil as given: its [soil] refuses modulus_range (exit 3) rather
    than ignore it."""
    document = read_toml(CONFIGS / "block_two_machines.toml")
    document["soil"]["modulus_range"] = [0.5, 1.5]
    result = runner.invoke(app, ["check", str(_write(tmp_path, document))])
    assert result.exit_code == 3 and "modulus_range is not a key" in result.stdout + result.stderr
