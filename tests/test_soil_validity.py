"""The soil model's range of validity: a0 at every judged mode and harmonic against the range its
method was fitted over (checks/soil_validity.py), on a crank and a block foundation.

Independent values: a0 = ω b/V_s computed here from the scene's own numbers, b the method's length
written out here (Lysmer's equivalent radii r0 = √(BL/π), r0ψ = (BL³/(3π))^¼; Gazetas' B'), and
ω the natural frequency of an eigen-solve assembled here (scipy.linalg.eigh of the plane model's
M, K built from the scene's masses and Lysmer's springs, or of the block's own matrices), not the
closed forms (4.5)-(4.7) the resonance check uses. Tolerance 1e-9 relative: the eigen-solve and the
closed forms agree to round-off.
"""

from __future__ import annotations

import json
import math

import numpy as np
import pytest

from foundation_calc.cli.app import app
from foundation_calc.scenes import load_scene
from tests.conftest import CONFIGS

linalg = pytest.importorskip("scipy.linalg")

COMPRESSOR = CONFIGS / "compressor_medium_sand_lysmer.toml"

#: The compressor's block, machine and soil as a block foundation (the same numbers: a 6 m × 4 m ×
#: 1.6 m block, a 14 t machine 2.9 m above the base, V_s = 170 m/s by Lysmer's analogs).
BLOCK_COMPRESSOR = """\
kind = "block_foundation"
name = "the compressor's block in six degrees of freedom"

[block]
length = 6.0
width = 4.0
height = 1.6
density = 2400.0

[[machines]]
name = "compressor"
mass = 14.0e3
cog = [0.0, 0.0, 2.9]
inertia = [9.0e3, 9.0e3, 9.0e3]
speed_rpm = 150.0

[[machines.loads]]
order = 1
force = [2.0e3, 0.0, 4.0e3]
at = [0.0, 0.0, 3.0]

[soil]
method = "lysmer"
shear_wave_velocity = 170.0
density = 1800.0
poisson = 0.30
material_damping = 0.03

[limits]
amplitude = 1.5e-4
"""

TOLERANCE = 1e-9


def _json(runner, *args):
    result = runner.invoke(app, [*map(str, args), "--json"])
    assert result.exit_code in (0, 1), result.output
    return json.loads(result.stdout)


def _plane_frequencies(scene) -> np.ndarray:
    """k0, p1, p2 [rad/s] ascending by an eigen-solve of the plane model about C (x, y, θ): the base
    springs act on x − hθ, y, θ; the weight's −M g h on θ."""
    from foundation_calc.solvers.constants import GRAVITY
    from foundation_calc.solvers.soil.lysmer import lysmer_springs

    f, s = scene.foundation, scene.soil
    M, I_c, h = scene.total_mass, f.moment_of_inertia, f.cog_height
    L, B = f.dimensions
    springs = lysmer_springs(s.G, s.density, s.poisson, L, B, M, I_c + M * h * h, s.material_damping)
    T = np.array([[1.0, 0.0, -h], [0.0, 1.0, 0.0], [0.0, 0.0, 1.0]])  # (x − hθ, y, θ) from (x, y, θ)
    K = T.T @ np.diag([springs.K_x, springs.K_z, springs.K_phi]) @ T - np.diag([0.0, 0.0, M * GRAVITY * h])
    return np.sqrt(linalg.eigvalsh(K, np.diag([M, M, I_c])))


def test_the_crank_compressors_upper_mode_is_beyond_lysmers_range(runner):
    """p2 of the shipped compressor: a0 = p2 r0ψ/V_s = 2.56 in rocking and p2 r0/V_s = 2.29 in
    sliding, beyond Lysmer's 1.5 (Richart, Hall & Woods); k0 and p1 lie within it."""
    scene = load_scene(COMPRESSOR)
    L, B = 6.0, 4.0
    r0, r_rock = math.sqrt(B * L / math.pi), (B * L**3 / (3.0 * math.pi)) ** 0.25
    V_s = 170.0
    p2 = _plane_frequencies(scene)[-1]
    doc = _json(runner, "resonance", COMPRESSOR)["soil_validity"]
    assert doc["method"] == "lysmer" and doc["a0_max"] == 1.5 and "Richart" in doc["source"]
    beyond = {(v["at"], v["motion"]): v["a0"] for v in doc["beyond"]}
    assert set(beyond) == {("p2", "rocking"), ("p2", "horizontal")}
    assert beyond["p2", "rocking"] == pytest.approx(p2 * r_rock / V_s, rel=TOLERANCE)
    assert beyond["p2", "horizontal"] == pytest.approx(p2 * r0 / V_s, rel=TOLERANCE)
    assert beyond["p2", "rocking"] == pytest.approx(2.558, abs=5e-4)
    within = {(v["at"], v["motion"]) for v in doc["values"]} - set(beyond)
    assert ("k0", "vertical") in within and ("p1", "rocking") in within
    assert ("k0", "rocking") not in within  # k0 strains no rocking spring: not judged there


def test_the_crank_warning_reaches_every_command(runner):
    text = " ".join(runner.invoke(app, ["resonance", str(COMPRESSOR)]).stdout.split())
    assert "warning: soil model: a0 beyond the range of soil method 'lysmer'" in text
    amplitudes = _json(runner, "amplitudes", COMPRESSOR)
    assert amplitudes["soil_validity"]["beyond"] and amplitudes["verdict"] == "pass"  # a warning, not a verdict
    check = _json(runner, "check", COMPRESSOR)
    runs = {c["check"]: c for c in check["scenes"][0]["checks"]}
    for name in ("resonance", "amplitudes"):
        assert "soil model: a0 of rocking = 2.56 at p2" in runs[name]["reason"]
        assert any(d.startswith("WARN soil model: a0 = ω b/V_s = 2.558 > 1.5 at p2") for d in runs[name]["details"])
        assert runs[name]["result"]["soil_validity"]["beyond"]
    assert check["exit_code"] == 0


def test_the_block_compressors_upper_mode_is_beyond_lysmers_range(runner, tmp_path):
    """The same block in six degrees of freedom: its upper sliding-rocking mode (rocking about y,
    with L = 6 m in its plane) has a0 = p r0ψ/V_s beyond 1.5; p from scipy's eigen-solve of the
    block's matrices."""
    path = tmp_path / "block.toml"
    path.write_text(BLOCK_COMPRESSOR)
    scene = load_scene(path)
    model = scene.model()
    frequencies = np.sqrt(linalg.eigvalsh(model.K, model.M))
    doc = _json(runner, "resonance", path)
    modes = doc["modes"]
    upper = max((m for m in modes if m["dominant"] == "ry"), key=lambda m: m["frequency"]["omega"])
    p = upper["frequency"]["omega"]
    assert np.min(np.abs(frequencies - p)) <= TOLERANCE * p
    r_ry = (4.0 * 6.0**3 / (3.0 * math.pi)) ** 0.25
    beyond = {(v["at"], v["motion"]): v["a0"] for v in doc["soil_validity"]["beyond"]}
    label = f"mode {upper['mode']} (ry)"
    assert beyond[label, "ry"] == pytest.approx(p * r_ry / 170.0, rel=TOLERANCE)
    assert beyond[label, "ry"] > 1.5
    text = " ".join(runner.invoke(app, ["amplitudes", str(path)]).stdout.split())
    assert "warning: soil model: a0 beyond the range of soil method 'lysmer'" in text


def test_gazetas_scales_every_motion_by_the_shorter_half_side(runner, tmp_path):
    """Gazetas' and Pais & Kausel's a0 = ω B'/V_s with B' = 2 m (the 4 m side's half), whatever the
    motion; their range is a0 <= 2."""
    path = tmp_path / "gazetas.toml"
    path.write_text(COMPRESSOR.read_text().replace('method = "lysmer"', 'method = "gazetas"'))
    doc = _json(runner, "resonance", path)["soil_validity"]
    assert doc["a0_max"] == 2.0 and doc["values"]
    for v in doc["values"]:
        assert v["length"] == 2.0 and v["a0"] == pytest.approx(v["omega"] * 2.0 / 170.0, rel=1e-12)


@pytest.mark.parametrize("config, method", [("frame_saw.toml", "coefficients"), ("compressor_medium_sand_sp26.toml", "sp26"),
                                            ("block_two_machines.toml", "springs")])
def test_a_frequency_independent_method_says_no_range_applies(runner, config, method):
    doc = _json(runner, "resonance", CONFIGS / config)["soil_validity"]
    assert doc["method"] == method and doc["a0_max"] is None and not doc["values"] and not doc["beyond"]
    assert "no range of a0 applies" in doc["text"]


def test_fcalc_soil_judges_each_method_by_its_own_a0():
    """``fcalc soil`` names Lysmer's p2 by its r0ψ (2.56), not by B' (1.65, the old note)."""
    from foundation_calc.checks.soil_methods import compare_soil_methods

    found = [f for f in compare_soil_methods(load_scene(COMPRESSOR)).findings if "soil method 'lysmer'" in f]
    assert len(found) == 1 and "at p2: rocking 2.56, horizontal 2.29" in found[0]
