"""The soil's uncertainty on every scene kind that stands on soil (crank and block foundations),
through one machinery: the modulus factor applied to a batch in one array operation (Eqs. (1),
(2) of ``checks/design/block_range.py``), and ``fcalc soil --sample``'s distribution, checked
against the scalar ``fcalc check`` path and the lognormal distribution it samples."""

from __future__ import annotations

import json
import math

import numpy as np
import pytest
from scipy.optimize import bisect

from foundation_calc.cli.app import app
from foundation_calc.scenes import parse_scene
from tests.conftest import CONFIGS, read_toml

#: Every soil method of a block, on the block of block_two_machines.toml.
BLOCK_SOILS = {
    "springs": {"method": "springs", "stiffness": [8.4e9, 8.0e9, 1.05e10, 6.6e10, 1.6e11, 9.1e10], "dashpot": [1.9e7] * 6},
    "coefficients": {"c_z": 7.0e7, "c_x": 4.9e7, "c_psi": 6.0e7, "damping": [0.1, 0.1, 0.05]},
    "lysmer": {"method": "lysmer", "shear_wave_velocity": 200.0, "density": 1800.0, "poisson": 0.3, "material_damping": 0.03},
    "gazetas": {"method": "gazetas", "shear_modulus": 7.2e7, "density": 1800.0, "poisson": 0.33, "material_damping": 0.03},
    "pais_kausel": {"method": "pais_kausel", "shear_wave_velocity": 180.0, "density": 1900.0, "poisson": 0.3},
    "sp26": {"method": "sp26", "deformation_modulus": 3.0e7, "soil_class": "sand"},
}


def _block(soil: dict | None = None, config: str = "block_two_machines.toml"):
    document = read_toml(CONFIGS / config)
    if soil is not None:
        document["soil"] = soil
    return parse_scene(document)


@pytest.mark.parametrize("method", BLOCK_SOILS)
def test_one_batch_of_factors_is_the_factored_scenes(method):
    """Eq. (2): K(f, ω) = f K(1, ω/√f), C(f, ω) = √f C(1, ω/√f) for every method (Eq. (1) where
    nothing depends on ω), against the scene factored key by key and rebuilt (rel 1e-12: round-off)."""
    from foundation_calc.checks.design.block_range import on_factors, scaled_impedance

    scene = _block(BLOCK_SOILS[method])
    factors = np.array([0.4, 1.0, 2.3])
    omega = np.array([[0.0, 60.0, 240.0]] * 3)  # the batch's axis first, then the frequencies
    springs, dashpots = scaled_impedance(scene.soil_impedance, factors)(omega)
    batch = on_factors(scene.model(), factors)
    for i, f in enumerate(factors):
        factored = scene.with_modulus_factor(float(f))
        K, C = factored.soil_impedance(omega[i])
        np.testing.assert_allclose(springs[i], K, rtol=1e-12)
        np.testing.assert_allclose(dashpots[i], C, rtol=1e-12, atol=1e-12 * np.abs(C).max())
        model = factored.model()
        for key in ("K", "C", "M"):
            np.testing.assert_allclose(getattr(batch, key)[i], getattr(model, key), rtol=1e-12, atol=1e-12 * np.abs(model.K).max()
                                       if key == "K" else 1e-12 * np.abs(getattr(model, key)).max())


def _crank_fails(scene):
    from foundation_calc.checks.resonance import check_scene_resonances

    return lambda f: check_scene_resonances(scene.with_modulus_factor(f)).outcome.value == "fail"


def _block_fails(scene):
    from foundation_calc.checks.resonance.report import modes_resonances
    from foundation_calc.solvers.block.response import block_modes

    def fails(f):
        factored = scene.with_modulus_factor(f)
        rows = modes_resonances(block_modes(factored.model()), factored.excitations(), factored.limits.detuning).rows
        return any(r.outcome.value == "fail" for r in rows)

    return fails


def _sample(scene, n, cov, seed):
    from foundation_calc.checks.soil_sample import sample_scene

    return sample_scene(scene, n, cov, seed=seed)


@pytest.mark.parametrize(("config", "fails"), [("frame_saw.toml", _crank_fails), ("block_two_machines.toml", _block_fails)])
def test_sampled_probability_of_a_resonance_failure_against_the_lognormal_cdf(config, fails):
    """Each scene fails its resonance check where the stiffness factor F lies in intervals found by
    a scan and bisection of the scalar check (``fcalc check``'s path); with F lognormal (median 1,
    COV 0.3, ln F ~ N(0, s²)) that probability is a sum of Φ(ln b / s) - Φ(ln a / s). The sample of
    20 000 must agree within 4 standard errors sqrt(p (1 - p)/n)."""
    from scipy.stats import norm

    scene = parse_scene(read_toml(CONFIGS / config))
    fails = fails(scene)
    grid = np.geomspace(0.2, 5.0, 300)
    failing = np.array([fails(f) for f in grid])
    edges = np.flatnonzero(failing[1:] != failing[:-1])
    s = math.sqrt(math.log1p(0.3**2))
    bounds = [bisect(lambda f: float(fails(f)) - 0.5, grid[i], grid[i + 1], xtol=1e-9) for i in edges]
    points = [0.0, *bounds, math.inf]
    probability = 0.0
    for i, (a, b) in enumerate(zip(points, points[1:])):
        if failing[0] if i == 0 else failing[edges[i - 1] + 1]:
            probability += (1.0 if b == math.inf else norm.cdf(math.log(b) / s)) - (0.0 if a == 0.0 else norm.cdf(math.log(a) / s))
    n = 20_000
    sampled = _sample(scene, n, 0.3, 3).failure_probability["resonance"]
    assert 0.05 < probability < 0.95  # inside the sampled range, away from 0 and 1: a test that can fail
    assert sampled == pytest.approx(probability, abs=4.0 * math.sqrt(probability * (1 - probability) / n))


@pytest.mark.parametrize(("config", "soil", "rel"), [
    ("block_two_machines.toml", None, 1e-9),
    ("block_fan_torsion_near_speed.toml", None, 1e-9),
    ("block_fan_torsion_near_speed.toml", BLOCK_SOILS["gazetas"], 1e-6),
], ids=["springs", "lysmer", "gazetas"])
def test_a_block_sample_without_scatter_is_the_checks_own_numbers(config, soil, rel):
    """With a vanishing COV every sample is the scene as given: its six frequencies are those of
    `fcalc check` (on Gazetas' soil each at its own frequency: rel 1e-6, the fixed points'
    tolerance), its resonance utilisation the governing condition's needed over its margin, its
    amplitude utilisation the largest limit or zone ratio (rel 1e-9 elsewhere: round-off)."""
    from foundation_calc.checks.amplitudes.machines import check_block_as_given
    from foundation_calc.checks.soil_sample import sample_scene
    from foundation_calc.checks.soil_sample.block import MODES
    from foundation_calc.checks.outcomes import RESONANCE_FAIL_MARGIN

    scene = _block(soil, config)
    drawn = sample_scene(scene, 8, 1e-12)
    report = check_block_as_given(scene)
    for key, p in zip(MODES, report.modes.frequencies):
        assert drawn.percentiles[key][1] == pytest.approx(p, rel=rel)
    g = report.nearest
    assert drawn.percentiles["resonance_utilisation"][1] == pytest.approx(max(g.required, RESONANCE_FAIL_MARGIN) / g.margin, rel=rel)
    ratios = [r.ratio for r in (*report.limit_rows, *report.zone_rows)]
    assert drawn.percentiles["amplitude_utilisation"][1] == pytest.approx(max(ratios), rel=rel)
    expected = {"resonance": report.resonance.outcome.value == "fail", "amplitudes": report.amplitude_outcome.value == "fail"}
    assert {k: drawn.failure_probability[k] == 1.0 for k in expected} == expected


def test_fcalc_soil_samples_a_block(runner):
    """`fcalc soil --sample` of a block scene reports the distribution (before, the option was
    silently dropped); the speed is a crank scene's to sample (exit 2)."""
    path = str(CONFIGS / "block_two_machines.toml")
    result = runner.invoke(app, ["soil", path, "--sample", "2000", "--json"])
    assert result.exit_code == 0, result.stderr
    sample = json.loads(result.stdout)["sample"]
    assert sample["samples"] == 2000
    p5, p50, p95 = sample["values"]["mode1"]
    assert p5 < p50 < p95
    assert set(sample["failure_probability"]) == {"tips_over", "resonance", "amplitudes", "any"}
    table = runner.invoke(app, ["soil", path, "--sample", "500"])
    assert table.exit_code == 0 and "probability of failing" in table.stdout and "mode 1, lowest" in table.stdout
    speed = runner.invoke(app, ["soil", path, "--sample", "500", "--speed-cov", "0.05"])
    assert speed.exit_code == 2 and "--speed-cov" in speed.stderr


@pytest.mark.parametrize(("config", "modulus_range", "crossed"), [
    ("frame_saw.toml", [0.4, 1.5], "3ω = p1"),
    ("block_fan_torsion_near_speed.toml", [0.5, 1.5], "fan: ω = mode 5 (ry)"),
])
def test_the_range_reaches_check_alike_on_both_kinds(runner, tmp_path, config, modulus_range, crossed):
    """One range machinery (``checks/soil_range.py``) on a crank and a block scene: `fcalc check
    --json` gives the same `modulus_range` document for the resonances and the amplitudes, with the
    crossing where a critical speed passes the running speed and the factors it judged (the calc
    sheet reads this document, whatever the kind: output/report/verdict.py)."""
    import tomli_w

    document = read_toml(CONFIGS / config)
    document["soil"]["modulus_range"] = modulus_range
    path = tmp_path / config
    path.write_text(tomli_w.dumps(document), encoding="utf-8")
    result = runner.invoke(app, ["check", str(path), "--json"])
    assert result.exit_code == 1, result.stderr
    checks = {c["check"]: c for c in json.loads(result.stdout)["scenes"][0]["checks"]}
    ranged = {check: checks[check]["result"]["modulus_range"] for check in ("resonance", "amplitudes")}
    for found in ranged.values():
        assert set(found) == {"low", "high", "verdict", "governing_factor", "governing", "crossings", "factors"}
        assert [found["low"], found["high"]] == modulus_range
    crossings = {c["condition"]: c["factor"] for c in ranged["resonance"]["crossings"]}
    assert modulus_range[0] < crossings[crossed] < modulus_range[1]
    assert crossings[crossed] in [f["factor"] for f in ranged["amplitudes"]["factors"]]  # the amplitudes peak there
    assert ranged["resonance"]["verdict"] == "fail" and f"{crossed} crossed at factor" in checks["resonance"]["reason"]
