"""Soil methods: published worked examples, identities between sources, SP 26 by hand, and the
block's mass properties against a brute-force integration."""

from __future__ import annotations

import math

import numpy as np
import pytest
from scipy.linalg import eigh

from foundation_calc.scenes import parse_scene
from foundation_calc.solvers.crank.block import block_with_machine
from foundation_calc.solvers.soil.gazetas import gazetas_springs, lysmer_analog_velocity
from foundation_calc.solvers.soil.lysmer import equivalent_radii, lysmer_springs
from foundation_calc.solvers.soil.sp26 import sp26_springs
from foundation_calc.solvers.soil.springs import uncoupled_frequencies

#: Das & Ramana, Principles of Soil Dynamics (2nd ed.), ch. 5, worked example of a block
#: 4 m × 2 m × 1.5 m of concrete (2400 kg/m³) carrying a 6 t machine on a soil with
#: V_s = 200 m/s, ρ = 1800 kg/m³, ν = 0.33 (the soil note's "Worked example").
DAS_SCENE = {
    "kind": "crank_foundation",
    "foundation": {
        "block": {"length": 4.0, "width": 2.0, "height": 1.5, "density": 2400.0},
        "machine": {"mass": 6000.0, "cog_height": 2.0},
    },
    "soil": {"method": "lysmer", "shear_wave_velocity": 200.0, "density": 1800.0, "poisson": 0.33},
    "mechanism": {
        "speed_rpm": 500.0, "crank_radius": 0.11, "rod_length": 0.5, "rod_mass": 1.0e-9,
        "rod_cog_to_crank_pin": 0.15, "rod_radius_of_gyration": 0.17, "crank_axis_to_cog": 1.3,
    },
}


def test_das_ramana_worked_example_at_its_printed_precision():
    """r0 = 1.5958 m, k_z = 685.9 MN/m, f_z = 22.345 Hz, each to half a unit of its last printed digit."""
    scene = parse_scene(DAS_SCENE)
    assert scene.total_mass == pytest.approx(34800.0, abs=1e-6)  # 28.8 t block + 6 t machine, as printed
    L, B = scene.foundation.dimensions
    r0, _ = equivalent_radii(L, B)
    springs = scene.soil_springs()
    f_z = math.sqrt(springs.K_z / scene.total_mass) / (2.0 * math.pi)
    assert abs(r0 - 1.5958) <= 0.5e-4
    assert abs(springs.K_z / 1e6 - 685.9) <= 0.05
    assert abs(f_z - 22.345) <= 0.5e-3


@pytest.mark.parametrize(("L", "B", "nu"), [(4.0, 2.0, 0.33), (2.0, 4.0, 0.25), (3.0, 3.0, 0.45), (10.0, 1.0, 0.0)])
def test_gazetas_vertical_dashpot_at_low_frequency_is_lysmers(L, B, nu):
    """Gazetas' C_z = ρ V_La A_b (c̃_z → 1) equals Lysmer's 3.4 r0² sqrt(ρ G)/(1 - ν), r0 = sqrt(A_b/π)
    (soil note), and Lysmer's D_z = 0.425/sqrt(B_z) is that same dashpot over 2 sqrt(k_z m): both
    identities are exact (0.425 = 3.4/8), so round-off (1e-12) is the tolerance."""
    G, rho, M, I_0 = 6.0e7, 1900.0, 5.0e4, 2.0e5
    r0 = math.sqrt(L * B / math.pi)
    lysmer_dashpot = 3.4 * r0**2 * math.sqrt(rho * G) / (1.0 - nu)
    gaz = gazetas_springs(G, rho, nu, L, B, 0.0, M, I_0, 0.0)
    assert float(gaz.xi_z) * 2.0 * math.sqrt(float(gaz.K_z) * M) == pytest.approx(lysmer_dashpot, rel=1e-12)
    lys = lysmer_springs(G, rho, nu, L, B, M, I_0, 0.0)
    assert float(lys.xi_z) * 2.0 * math.sqrt(float(lys.K_z) * M) == pytest.approx(lysmer_dashpot, rel=1e-12)


def test_gazetas_square_footing_against_the_exact_rigid_circle():
    """Gazetas' fits for a square 2B' × 2B' against the exact rigid circle of the same area (vertical:
    4 G R/(1 - ν), Sneddon; horizontal: 8 G R/(2 - ν), Bycroft) and of the same second moment
    (rocking: 8 G R³/(3 (1 - ν)), Borowicka). The equivalent circle is known to be within a few per
    cent for a square (Richart, Hall & Woods 1970, 10.4); tolerances 2 %, 2 %, 7 %."""
    G, rho, nu, side = 5.0e7, 1800.0, 0.3, 3.0
    s = gazetas_springs(G, rho, nu, side, side, 0.0, 1.0e5, 1.0e5, 0.0)
    R = side / math.sqrt(math.pi)
    R_phi = (side**4 / (3.0 * math.pi)) ** 0.25
    assert float(s.K_z) == pytest.approx(4.0 * G * R / (1.0 - nu), rel=0.02)
    assert float(s.K_x) == pytest.approx(8.0 * G * R / (2.0 - nu), rel=0.02)
    assert float(s.K_phi) == pytest.approx(8.0 * G * R_phi**3 / (3.0 * (1.0 - nu)), rel=0.07)


@pytest.mark.parametrize(("L", "B", "K_phi"), [(3.0, 2.0, 422150729.0333), (2.0, 3.0, 218027424.1324)])
def test_gazetas_rocking_against_an_independent_implementation(L, B, K_phi):
    """Surface rocking of a 3 m × 2 m footing, G = 30 MPa, ν = 0.3, about either axis, as the open
    implementation eng-tools/geofound computes it (tests/test_stiffness.py, test_rotation; its own
    code, printed to 4 decimals): K_ry when the motion runs along the long side, K_rx across it."""
    s = gazetas_springs(30.0e6, 1800.0, 0.3, L, B, 0.0, 1.0e5, 1.0e5, 0.0)
    assert float(s.K_phi) == pytest.approx(K_phi, rel=1e-12)


def test_gazetas_takes_the_side_in_the_plane_of_motion():
    """Sliding along the long side is softer than across it (K_x < K_y) and rocking about the short
    axis stiffer than about the long one; K_z does not care; an array call equals the loop."""
    args = (5.0e7, 1800.0, 0.3)
    along_long = gazetas_springs(*args, 6.0, 2.0, 0.0, 1.0e5, 1.0e5, 0.0)
    across = gazetas_springs(*args, 2.0, 6.0, 0.0, 1.0e5, 1.0e5, 0.0)
    assert float(along_long.K_z) == float(across.K_z)
    assert float(along_long.K_x) < float(across.K_x)
    assert float(along_long.K_phi) > float(across.K_phi)
    batch = gazetas_springs(*args, np.array([6.0, 2.0]), np.array([2.0, 6.0]), np.array([0.0, 0.0]), 1.0e5, 1.0e5, 0.0)
    assert batch.K_x.tolist() == [float(along_long.K_x), float(across.K_x)]


def test_gazetas_embedment_only_stiffens():
    args = (5.0e7, 1800.0, 0.3, 5.0, 4.0)
    surface = gazetas_springs(*args, 0.0, 1.0e5, 1.0e5, 0.0)
    for D in (0.5, 1.0, 2.0):
        embedded = gazetas_springs(*args, D, 1.0e5, 1.0e5, 0.0)
        for key in ("K_z", "K_x", "K_phi"):
            assert float(getattr(embedded, key)) > float(getattr(surface, key)), (key, D)


def test_lysmer_analog_velocity():
    """V_La = 3.4 V_s/(π(1 - ν)): for ν = 1/3, 3.4·1.5/π = 1.62338 V_s."""
    assert float(lysmer_analog_velocity(100.0, 1.0 / 3.0)) == pytest.approx(162.338, abs=5e-4)


#: SP 26.13330 / SNiP 2.02.05-87: C_z = b0 E (1 + sqrt(A10/A)), A10 = 10 m²; b0 = 1.0 1/m for sands,
#: 1.2 for sandy loams and loams, 1.5 for clays and coarse soils. Worked by hand for E = 30 MPa,
#: A = 8 m²: sqrt(10/8) = 1.118034, so 1 + sqrt = 2.118034 and C_z = b0 · 63.54102 MN/m³.
SP26_BY_HAND = [
    ("sand", 63.54102e6),
    ("sandy_loam", 76.24922e6),
    ("loam", 76.24922e6),
    ("clay", 95.31153e6),
    ("coarse", 95.31153e6),
]


@pytest.mark.parametrize(("soil_class", "C_z"), SP26_BY_HAND, ids=[c for c, _ in SP26_BY_HAND])
def test_sp26_coefficients_by_hand(soil_class, C_z):
    """Through the scene: base 4 m × 2 m (A = 8 m², I = 2·4³/12 = 10.6667 m⁴), weight chosen so that
    p_m = 100 kPa: ξ_z = 2/sqrt(100) = 0.2, ξ_x = 0.6 ξ_z = 0.12, ξ_φ = 0.5 ξ_z = 0.1."""
    from foundation_calc.solvers.constants import GRAVITY

    M = 100.0e3 * 8.0 / GRAVITY
    scene = parse_scene({
        **DAS_SCENE,
        "foundation": {"base_length": 4.0, "base_width": 2.0, "mass": M - 1.0e-9, "moment_of_inertia": 1.0e5,
                       "cog_height": 1.0},
        "soil": {"method": "sp26", "deformation_modulus": 30.0e6, "soil_class": soil_class},
    })
    s = scene.soil_springs()
    assert float(s.K_z) / 8.0 == pytest.approx(C_z, rel=1e-6)
    assert float(s.K_x) / 8.0 == pytest.approx(0.7 * C_z, rel=1e-6)
    assert float(s.K_phi) / (2.0 * 4.0**3 / 12.0) == pytest.approx(2.0 * C_z, rel=1e-6)
    assert (float(s.xi_z), float(s.xi_x), float(s.xi_phi)) == pytest.approx((0.2, 0.12, 0.1), rel=1e-9)


def test_sp26_with_the_dynamic_modulus_is_the_notes_trap():
    """E = 2G(1 + ν) from V_s = 200 m/s (the worked example's soil) gives SP 26 springs 4.7 times
    Lysmer's (soil note, "Trap")."""
    G, nu = 1800.0 * 200.0**2, 0.33
    sp = sp26_springs(2.0 * G * (1.0 + nu), 1.0, 8.0, 2.0 * 4.0**3 / 12.0, 1.0e5)
    ly = lysmer_springs(G, 1800.0, nu, 4.0, 2.0, 34800.0, 1.0e5, 0.0)
    assert float(sp.K_z) / float(ly.K_z) == pytest.approx(4.7, abs=0.05)


def test_block_mass_properties_against_brute_force_integration():
    """M, h and I_c of a block with a machine (a point mass with its own I_m) against a midpoint-rule
    integration over the block's section in the plane of motion (error O(1/n²) ~ 1e-6 at n = 400)."""
    L, B, H, rho_c, m_m, h_m, I_m = 5.0, 4.0, 2.2, 2400.0, 14.0e3, 2.9, 9.0e3
    n = 400
    x = (np.arange(n) + 0.5) / n * L - L / 2.0
    z = (np.arange(n) + 0.5) / n * H
    X, Z = np.meshgrid(x, z)
    dm = rho_c * B * (L / n) * (H / n)
    M = dm * X.size + m_m
    h = (dm * Z.sum() + m_m * h_m) / M
    I_c = dm * (X**2 + (Z - h) ** 2).sum() + m_m * (h_m - h) ** 2 + I_m
    props = block_with_machine(L, B, H, rho_c, m_m, h_m, I_m)
    assert float(props.M) == pytest.approx(M, rel=1e-12)
    assert float(props.h) == pytest.approx(h, rel=1e-9)
    assert float(props.I_c) == pytest.approx(I_c, rel=1e-5)


def _sliding_rocking_eigen(K_x, K_phi, M, I_c, h):
    from foundation_calc.solvers.constants import GRAVITY

    K = np.array([[K_x, -h * K_x], [-h * K_x, K_phi - M * GRAVITY * h + h * h * K_x]])
    return np.sqrt(eigh(K, np.diag([M, I_c]), eigvals_only=True))


def test_coupled_frequencies_of_fcalc_soil_against_an_eigen_solve():
    """p1, p2 with the method's own rocking spring (c_φ in the rocking row) against
    scipy.linalg.eigh of the sliding-rocking block: K = [[K_x, -h K_x], [-h K_x, K_φ - P h + h² K_x]],
    M = diag(M_tot, I_c), coordinates x of C and θ. A frequency-dependent method's p_i is an
    eigenvalue of the block on the springs taken at p_i itself (ω = p(K(ω))), its k0 the vertical
    frequency on K_z(k0); its static frequencies are those of the static springs."""
    from foundation_calc.checks.soil_methods import compare_soil_methods
    from foundation_calc.solvers.constants import GRAVITY

    scene = parse_scene(DAS_SCENE)
    f = scene.foundation
    M, h, I_c = scene.total_mass, f.cog_height, f.moment_of_inertia
    for r in compare_soil_methods(scene).results:
        static = _sliding_rocking_eigen(r.K_x, r.K_phi, M, I_c, h)
        if r.static_frequencies is None:
            assert (r.p1, r.p2) == pytest.approx(tuple(static), rel=1e-10), r.method
            u = uncoupled_frequencies(r.K_z, r.K_x, r.K_phi, M, I_c + M * h * h, h, GRAVITY)
            assert r.k0 == pytest.approx(float(u.omega_z), rel=1e-14)
            continue
        assert (r.static_frequencies["p1"], r.static_frequencies["p2"]) == pytest.approx(tuple(static), rel=1e-10)
        for i, mode in enumerate(("p1", "p2")):
            s = scene.soil_springs(r.method, getattr(r, mode))
            assert getattr(r, mode) == pytest.approx(_sliding_rocking_eigen(s.K_x, s.K_phi, M, I_c, h)[i], rel=1e-8)
        assert r.k0 == pytest.approx(math.sqrt(float(scene.soil_springs(r.method, r.k0).K_z) / M), rel=1e-8)
