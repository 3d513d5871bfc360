"""A soil stratum over rigid bedrock (``[soil] stratum_depth``): the half-space as H → ∞, the cutoff
frequencies by an independent transcription, the static factors of near-square bases against
Kausel's circle on the equivalent radius, and a block whose vertical mode lies below the layer's
cutoff: warned about, and its resonant amplitude that of material damping alone (a direct complex
solve of the 6-DOF equations written here)."""

from __future__ import annotations

import json
import math

import numpy as np
import pytest
import scipy.linalg
import tomli_w

from foundation_calc.cli.app import app
from foundation_calc.scenes import parse_scene
from foundation_calc.solvers.soil.gazetas import gazetas_springs
from foundation_calc.solvers.soil.lysmer import lysmer_springs
from foundation_calc.solvers.soil.pais_kausel import pais_kausel_springs
from foundation_calc.solvers.soil.stratum import on_stratum

SOIL = {"shear_wave_velocity": 120.0, "density": 1800.0, "poisson": 0.33, "material_damping": 0.03}


def _block(method: str, soil: dict | None = None, speed_rpm: float = 600.0, height: float = 2.5) -> dict:
    """A 4 m × 3 m block of concrete with a 10 t machine pushed vertically at the top centre."""
    return {
        "kind": "block_foundation",
        "block": {"length": 4.0, "width": 3.0, "height": height, "density": 2400.0},
        "machines": [{
            "name": "press", "mass": 1.0e4, "cog": [0.0, 0.0, height + 0.5], "inertia": [5.0e3, 5.0e3, 5.0e3],
            "speed_rpm": speed_rpm,
            "loads": [{"name": "vertical", "order": 1, "force": [0.0, 0.0, 2.0e4], "at": [0.0, 0.0, height]}],
        }],
        "soil": {"method": method, **SOIL, **(soil or {})},
        "limits": {"amplitude": 1.0e-3},
    }


@pytest.mark.parametrize("method", ["lysmer", "gazetas", "pais_kausel"])
def test_an_infinitely_deep_stratum_is_the_half_space(method):
    """H = ∞ in the solver: springs and ratios bit for bit at rest and above (every factor 1, both
    cutoffs 0); H = 1e12 m in a scene: its springs and dashpots at O at the modes' frequencies within
    rel 1e-9 of the half-space's (the factors differ from 1 by 1.28 R/H ≈ 3e-12)."""
    args = (7.2e7, 1800.0, 0.33, 4.0, 3.0)
    for omega in (0.0, 50.0, np.array([10.0, 100.0])):
        if method == "lysmer":
            hs = lysmer_springs(*args, 5.0e4, 8.0e4, 0.03)
        else:
            springs = gazetas_springs if method == "gazetas" else pais_kausel_springs
            hs = springs(*args, 0.0, 5.0e4, 8.0e4, 0.03, omega)
        deep = on_stratum(hs, 4.0, 3.0, math.inf, 200.0, 0.33, 0.03, omega)
        for key in ("K_z", "K_x", "K_phi", "xi_z", "xi_x", "xi_phi"):
            assert np.array_equal(np.broadcast_to(getattr(deep, key), np.shape(omega)),
                                  np.broadcast_to(getattr(hs, key), np.shape(omega))), key
    half, deep = parse_scene(_block(method)), parse_scene(_block(method, {"stratum_depth": 1.0e12}))
    omega = np.array([20.0, 60.0, 90.0, 150.0])
    for a, b in zip(half.soil_impedance(omega), deep.soil_impedance(omega)):
        np.testing.assert_allclose(b, a, rtol=1e-9, atol=0.0)


@pytest.mark.parametrize("method", ["lysmer", "gazetas", "pais_kausel"])
def test_the_radiation_starts_exactly_at_v_s_over_4h_and_v_la_over_4h(method):
    """Without material damping the dashpots are the half-space's at and above their cutoff and
    nothing just below it: f_s = V_s/(4H) for x, y and torsion, f_c = V_La/(4H) with Lysmer's
    analog V_La = 3.4 V_s/(π (1 - ν)) for z, rx, ry (transcribed here from Gazetas 1991)."""
    H, V_s, nu = 6.0, SOIL["shear_wave_velocity"], SOIL["poisson"]
    f_s = V_s / (4.0 * H)
    f_c = 3.4 * V_s / (math.pi * (1.0 - nu)) / (4.0 * H)
    undamped = {"material_damping": 0.0}
    half = parse_scene(_block(method, undamped))
    layer = parse_scene(_block(method, undamped | {"stratum_depth": H}))
    for f, motions in ((f_s, (0, 1, 5)), (f_c, (2, 3, 4))):
        omega = 2.0 * math.pi * f * np.array([1.0 - 1e-9, 1.0])
        _, C_half = half.soil_impedance(omega)
        _, C = layer.soil_impedance(omega)
        for i in motions:
            assert C[0, i] == 0.0 and C_half[0, i] > 0.0, (f, i)
            assert C[1, i] == pytest.approx(C_half[1, i], rel=1e-12), (f, i)


@pytest.mark.parametrize("method", ["lysmer", "gazetas", "pais_kausel"])
@pytest.mark.parametrize("L, B", [(3.0, 3.0), (3.3, 3.0), (3.0, 3.3)])
@pytest.mark.parametrize("h_over_r", [1.0, 2.0, 5.0])
def test_near_square_bases_stiffen_as_kausels_circle_on_the_equivalent_radius(method, L, B, h_over_r):
    """K(stratum)/K(half-space) of a near-square base against Kausel's disk (1974, via Gazetas 1983):
    1 + 1.28 R/H vertical, 1 + R/(2H) horizontal, 1 + R/(6H) rocking, with R the radius of the circle
    of the base's area (translations) or of its second moment about the rocking axis (rocking),
    within 10 %."""
    R = math.sqrt(L * B / math.pi)
    H = h_over_r * R
    R_ry = (4.0 * (B * L**3 / 12.0) / math.pi) ** 0.25  # same second moment about y as the base
    R_rx = (4.0 * (L * B**3 / 12.0) / math.pi) ** 0.25
    expected = [1 + R / (2 * H), 1 + R / (2 * H), 1 + 1.28 * R / H, 1 + R_rx / (6 * H), 1 + R_ry / (6 * H)]
    document = _block(method)
    document["block"] |= {"length": L, "width": B}
    half = parse_scene(document)
    document["soil"]["stratum_depth"] = H
    layer = parse_scene(document)
    ratio = layer.soil_impedance(0.0)[0] / half.soil_impedance(0.0)[0]
    np.testing.assert_allclose(ratio[:5], expected, rtol=0.10)


def _vertical_mode(scene, stiffen):
    """(ω of the mode dominated by z, K at O) of the block on its half-space springs times ``stiffen``
    (6,), from scipy's generalised eigensolver on M and K = diag(springs) + the weight's tilt."""
    model = scene.model()
    K = model.K + np.diag(model.springs * (stiffen - 1.0))
    values, vectors = scipy.linalg.eigh(K, model.M)
    j = int(np.argmax(np.abs(vectors[2]) / np.abs(vectors).max(axis=0)))
    return math.sqrt(values[j]), K


def test_a_block_resonating_below_the_cutoff_is_warned_and_damped_by_the_material_alone(runner, tmp_path):
    """A 82 t block on 3 m of soft soil (V_s = 120 m/s) over rock, Lysmer's springs (frequency-
    independent, so the springs are those at every frequency): its vertical mode near 13 Hz lies
    below the layer's f_c = V_La/4H = 16.2 Hz, and the machine runs at it. ``fcalc amplitudes`` warns
    of it, and the amplitude at G is the direct solve (K - ω² M + i ω C) u = F at O with K the half-space
    springs times Kausel's factors and C = 2 ξ_m sqrt(K_i m_i) of the material damping ξ_m = 0.03
    alone (rel 1e-6; the tool's speed is the mode's frequency rounded in rpm, the same ω here). With
    the half-space's radiation the peak would be several times smaller."""
    H, L, B = 3.0, 4.0, 3.0
    R = math.sqrt(L * B / math.pi)
    R_rx, R_ry = (L * B**3 / (3 * math.pi)) ** 0.25, (B * L**3 / (3 * math.pi)) ** 0.25
    stiffen = np.array([1 + R / (2 * H), 1 + R / (2 * H), 1 + 1.28 * R / H, 1 + R_rx / (6 * H), 1 + R_ry / (6 * H), 1.0])
    omega, K = _vertical_mode(parse_scene(_block("lysmer")), stiffen)
    f_c = 3.4 * 120.0 / (math.pi * (1 - 0.33)) / (4 * H)
    assert omega / (2 * math.pi) < 0.9 * f_c
    document = _block("lysmer", {"stratum_depth": H}, speed_rpm=round(omega * 60 / (2 * math.pi), 6))
    path = tmp_path / "thin_stratum.toml"
    path.write_text(tomli_w.dumps(document))
    result = runner.invoke(app, ["amplitudes", str(path), "--json"])
    assert result.exit_code in (0, 1), result.output
    out = json.loads(result.stdout)
    below = out["soil_validity"]["stratum"]["below"]
    assert any(v["at"] == "ω" and v["motion"] == "z" for v in below)  # the speed (one machine: "ω")
    assert any(v["motion"] == "z" and v["at"].startswith("mode") for v in below)
    assert "no radiation damping" in out["soil_validity"]["text"]

    half = parse_scene(_block("lysmer")).model()  # the half-space's springs and (radiating) dashpots
    w = parse_scene(document).machines[0].omega_rad_s
    C = np.diag(2.0 * 0.03 * np.sqrt(half.springs * stiffen * np.diag(half.M)))
    F = np.array([0.0, 0.0, 2.0e4, 0.0, 0.0, 0.0])  # the load at (0, 0, height) has no moment about O
    u = np.linalg.solve(K - w * w * half.M + 1j * w * C, F)
    u_G = u[:3] + np.cross(u[3:], half.cog)
    got = out["harmonics"][0]["points"]["G"]
    for i, axis in enumerate("xyz"):
        assert got[axis]["amplitude"] == pytest.approx(abs(u_G[i]), rel=1e-6, abs=1e-9 * abs(u_G[2])), axis
    u_half = np.linalg.solve(K - w * w * half.M + 1j * w * half.C, F)
    assert abs(u_G[2]) > 3.0 * abs(u_half[2])


def test_a_stratum_above_the_base_or_of_zero_depth_is_refused(runner, tmp_path):
    """H must exceed the embedment (bedrock below the base) and be > 0: exit code 3, the field named."""
    for soil, block, field in (({"stratum_depth": 0.0}, {}, "soil.stratum_depth"),
                               ({"stratum_depth": 1.0}, {"embedment": 1.5}, "soil.stratum_depth")):
        document = _block("gazetas", soil)
        document["block"] |= block
        path = tmp_path / "bad.toml"
        path.write_text(tomli_w.dumps(document))
        result = runner.invoke(app, ["resonance", str(path)])
        assert result.exit_code == 3, result.output
        assert field in result.output and "m" in result.output


@pytest.mark.parametrize("method", ["lysmer", "gazetas", "pais_kausel"])
def test_a_crank_foundation_takes_the_stratum_in_its_plane(method):
    """The crank scene's plane springs on a stratum: K_z × (1 + 1.28 R/H), K_x × (1 + R/2H),
    K_φ × (1 + R_ψ/6H) (R_ψ of the base's second moment about the axis normal to the plane), and below
    both cutoffs only the material damping (0.03); H = 1e12 m gives the half-space to 1e-9."""
    from foundation_calc.scenes import load_scene

    crank = load_scene("configs/compressor_medium_sand_lysmer.toml")
    soil = crank.soil.model_dump(exclude_none=True) | {"method": method}

    def on(extra):
        return crank.model_copy(update={"soil": crank.soil.__class__(**soil, **extra)})

    L, B = crank.foundation.dimensions
    H = 6.0
    R, R_psi = math.sqrt(L * B / math.pi), (B * L**3 / (3 * math.pi)) ** 0.25
    omega = 2.0 * math.pi * 3.0  # below f_s = 170/24 = 7.1 Hz and f_c
    half, layer, deep = on({}).soil_springs(omega=omega), on({"stratum_depth": H}).soil_springs(omega=omega), \
        on({"stratum_depth": 1.0e12}).soil_springs(omega=omega)
    assert float(layer.K_z) / float(half.K_z) == pytest.approx(1 + 1.28 * R / H, rel=1e-12)
    assert float(layer.K_x) / float(half.K_x) == pytest.approx(1 + R / (2 * H), rel=1e-12)
    assert float(layer.K_phi) / float(half.K_phi) == pytest.approx(1 + R_psi / (6 * H), rel=1e-12)
    assert [float(layer.xi_z), float(layer.xi_x), float(layer.xi_phi)] == pytest.approx([0.03] * 3, abs=1e-15)
    for key in ("K_z", "K_x", "K_phi", "xi_z", "xi_x", "xi_phi"):
        assert float(getattr(deep, key)) == pytest.approx(float(getattr(half, key)), rel=1e-9), key
