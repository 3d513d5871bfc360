"""Frequency-dependent impedance of a footing: the published forms' own consistency, the plane-wave
radiation of base and sidewalls by numerical integration, the torsion against the torsional cone's
wave equation, the root of ω = p(K(ω)) against Brent's and where a plain iteration cycles, and the
per-harmonic steady state against a direct complex solve."""

from __future__ import annotations

import math

import numpy as np
import pytest
from scipy.optimize import brentq

from foundation_calc.scenes import load_scene, parse_scene
from foundation_calc.errors import PhysicsError
from foundation_calc.solvers.soil.impedance import (
    consistent_frequency,
    footing_impedance,
    footing_torsion,
    rocking_radiation_coefficient,
    stiffness_modifiers,
    torsion_modifier,
    torsion_radiation_coefficient,
)
from tests.conftest import CONFIGS, read_toml

G, RHO, NU = 5.2e7, 1800.0, 0.30
V_S = math.sqrt(G / RHO)
V_LA = 3.4 * V_S / (math.pi * (1.0 - NU))


@pytest.mark.parametrize("a0", [0.0, 0.3, 0.8, 1.2, 2.0])
def test_the_two_rocking_forms_of_pais_and_kausel_coincide_for_a_square(a0):
    """A square has no long and short axis: Table 2-3a's rocking about x and about y must give
    the same modifier and radiation shape at r = 1 (2.4 - 0.4 = 0.6 + 1.4, 2.2 - 0.4 = 1.8)."""
    _, k_rx, k_ry = stiffness_modifiers(a0, 1.0)
    assert k_rx == pytest.approx(k_ry, rel=1e-15)
    assert rocking_radiation_coefficient(a0, 1.0, True) == pytest.approx(rocking_radiation_coefficient(a0, 1.0, False), rel=1e-15)


@pytest.mark.parametrize("r", [1.0, 1.5, 3.0, 10.0])
def test_limits_at_rest_and_at_high_frequency(r):
    """At rest the springs are static and rocking radiates nothing (c̃_r ~ a0²); at high frequency
    c̃_r → 1, Gazetas' normalisation of the charts (C_r → ρ V_La I_b)."""
    assert [float(k) for k in stiffness_modifiers(0.0, r)] == [1.0, 1.0, 1.0]
    for short in (True, False):
        small = rocking_radiation_coefficient(1e-5, r, short)  # relative departure from a0² ~ 3 a0²/c_r < 1e-8
        assert small == pytest.approx(rocking_radiation_coefficient(2e-5, r, short) / 4.0, rel=1e-8)
        assert rocking_radiation_coefficient(1e4, r, short) == pytest.approx(1.0, abs=1e-6)


def _plane_wave_dashpots(L, B, D, n=8):
    """High-frequency dashpots of a rigid box (base L × B at depth D, sidewalls to the surface) by
    quadrature of the local plane-wave condition: traction = -ρ (V_n u_n n + V_s u_t) per unit
    area, V_n = V_La where the surface pushes the soil, V_s where it shears it. Motion in the
    x-z plane: unit velocity along x, along z, and unit rotation rate about the y-axis through
    the base's centroid (z up from the base). Returns (C_z, C_x, C_φ) [SI]."""
    nodes, weights = np.polynomial.legendre.leggauss(n)  # exact for the quadratic integrands
    t, w = (nodes + 1.0) / 2.0, weights / 2.0
    ww = np.outer(w, w).ravel()
    surfaces = []  # (points (m, 3), normal, area weights (m,))
    x, y = np.meshgrid(L * (t - 0.5), B * (t - 0.5), indexing="ij")
    surfaces.append((np.stack([x.ravel(), y.ravel(), 0.0 * x.ravel()], -1), np.array([0.0, 0.0, 1.0]), L * B * ww))
    if D > 0.0:
        for sign in (-1.0, 1.0):
            yy, zz = np.meshgrid(B * (t - 0.5), D * t, indexing="ij")
            surfaces.append((np.stack([0 * yy.ravel() + sign * L / 2, yy.ravel(), zz.ravel()], -1),
                             np.array([sign, 0.0, 0.0]), B * D * ww))
            xx, zz = np.meshgrid(L * (t - 0.5), D * t, indexing="ij")
            surfaces.append((np.stack([xx.ravel(), 0 * xx.ravel() + sign * B / 2, zz.ravel()], -1),
                             np.array([0.0, sign, 0.0]), L * D * ww))

    def dashpot(velocity):
        total = 0.0
        for points, normal, weight in surfaces:
            u = velocity(points)
            u_n = u @ normal
            u_t = u - u_n[:, None] * normal
            total += RHO * np.sum(weight * (V_LA * u_n**2 + V_S * np.sum(u_t**2, -1)))
        return total

    C_z = dashpot(lambda p: np.tile([0.0, 0.0, 1.0], (len(p), 1)))
    C_x = dashpot(lambda p: np.tile([1.0, 0.0, 0.0], (len(p), 1)))
    C_phi = dashpot(lambda p: np.stack([p[:, 2], 0.0 * p[:, 0], -p[:, 0]], -1))  # ω_y × r
    return C_z, C_x, C_phi


@pytest.mark.parametrize(("L", "B", "D"), [(6.0, 4.0, 0.0), (6.0, 4.0, 1.0), (4.0, 6.0, 1.0), (5.0, 5.0, 2.0)])
def test_base_and_sidewall_dashpots_against_plane_wave_quadrature(L, B, D):
    """At high frequency (c̃_r = 1) every surface of the box radiates a plane wave: the closed
    forms of the base (Gazetas 1991, Table 1) and of the sidewalls (Table 2, wall by wall) must
    equal the quadrature of ρ V per unit area over the box. Gauss-Legendre quadrature is exact
    for these quadratic integrands: tolerance 1e-9 (rounding; c̃_r = 1 - 1e-12 at a0 ~ 1e6)."""
    z = footing_impedance(1.0, 1.0, 1.0, G, RHO, NU, L, B, D, 1.0e8)  # a0 ~ 1e6: c̃_r = 1 - 1e-12
    C_z, C_x, C_phi = _plane_wave_dashpots(L, B, D)
    assert float(z.C_z) == pytest.approx(C_z, rel=1e-9)
    assert float(z.C_x) == pytest.approx(C_x, rel=1e-9)
    assert float(z.C_phi) == pytest.approx(C_phi, rel=1e-9)


def test_the_rocking_mode_solves_omega_equals_p_of_k_of_omega():
    """The fixed point of :func:`consistent_frequency` against Brent's root of ω - p(K(ω)) on the
    shipped compressor block with Gazetas' springs (ω_φ = sqrt((K_φ(ω) - P h)/I_0))."""
    document = read_toml(CONFIGS / "compressor_medium_sand_lysmer.toml")
    document["soil"]["method"] = "gazetas"
    scene = parse_scene(document)
    f, M = scene.foundation, scene.total_mass
    I_0 = f.moment_of_inertia + M * f.cog_height**2

    def p(w):
        return math.sqrt((float(scene.soil_springs(omega=w).K_phi) - M * 9.80665 * f.cog_height) / I_0)

    fixed = consistent_frequency(p, p(0.0))
    assert fixed == pytest.approx(brentq(lambda w: w - p(w), 1.0, p(0.0)), rel=1e-9)
    assert fixed < 0.9 * p(0.0)  # the rocking spring softens by about a fifth at a0 ≈ 1.1


def test_a_root_where_the_plain_iteration_cycles():
    """p(ω) = c + 40 tanh((c - ω)/s) falls through ω = c with slope -40/s: for s = 5 (slope -8)
    the plain iteration ω_{k+1} = p(ω_k) from p(0) jumps between c ± 40 for ever (the former
    solver's ArithmeticError after 200 steps), for s = 50 (slope -0.8) it converges slowly. The
    bracket [p(p_s), p_s] closes on c in both, every element of a batch at once: rel 1e-9 (the
    solver's bracket 1e-10), in at most 40 evaluations of p (bisection alone takes 37)."""
    c, scale = np.array([30.0, 50.0, 80.0, 50.0]), np.array([5.0, 5.0, 5.0, 50.0])
    calls = []

    def p(w):
        calls.append(w)
        return c + 40.0 * np.tanh((c - w) / scale)

    assert consistent_frequency(p, p(0.0)) == pytest.approx(c, rel=1e-9)
    assert len(calls) <= 41


def test_a_frequency_that_rises_with_frequency():
    """Springs that stiffen with frequency (a pile group's): where p rises more slowly than ω the root
    ω = 50 + ω/2 = 100 is found; where it rises faster there is none, a PhysicsError (fcalc's exit
    3, naming the soil), not a wrong root nor an endless loop; a p that rises then falls
    (not monotonic) gives the crossing nearest the static frequency."""
    assert consistent_frequency(lambda w: 50.0 + 0.5 * w, 50.0) == pytest.approx(100.0, rel=1e-9)
    with pytest.raises(PhysicsError, match="has no root found between"):
        consistent_frequency(lambda w: 50.0 + 1.5 * w, 50.0)
    bump = lambda w: 100.0 + 60.0 * np.exp(-((w - 130.0) / 20.0) ** 2)  # noqa: E731 - p(100) = 106, p(106) = 115: no bracket
    root = consistent_frequency(bump, bump(0.0))
    assert root == pytest.approx(bump(root), rel=1e-9)


@pytest.mark.parametrize(("L", "B"), [(4.0, 4.0), (6.0, 4.0), (3.0, 9.0)])
def test_torsion_dashpot_at_high_frequency_against_plane_wave_quadrature(L, B):
    """At high frequency every point of the base radiates a plane shear wave, traction ρ V_s times
    its velocity θ' (x² + y²)^½: C_t → ρ V_s ∫ (x² + y²) dA (Veletsos' exact limit for a disk),
    by Gauss-Legendre quadrature (exact for the quadratic integrand): rel 1e-9 (c̃_t = 1 - 1e-12
    at a0 ~ 1e6). At rest the spring is static and torsion radiates nothing (c̃_t ~ a0²)."""
    nodes, weights = np.polynomial.legendre.leggauss(4)
    x, y = L * nodes / 2.0, B * nodes / 2.0
    area = np.outer(weights, weights) * L * B / 4.0
    integral = float(np.sum(area * (x[:, None] ** 2 + y[None, :] ** 2)))
    K, C = footing_torsion(1.0, G, RHO, L, B, 1.0e8)
    assert float(C) == pytest.approx(RHO * V_S * integral, rel=1e-9)
    K0, C0 = footing_torsion(1.0, G, RHO, L, B, 0.0)
    assert (float(K0), float(C0)) == (1.0, 0.0)
    r = max(L, B) / min(L, B)
    assert torsion_radiation_coefficient(1e-5, r) == pytest.approx(torsion_radiation_coefficient(2e-5, r) / 4.0, rel=1e-8)


def _torsional_cone(b0):
    """Dynamic stiffness S/K of the torsional cone (Wolf 1994, ch. 2; Meek & Wolf 1992) at
    b0 = ω z0/V_s, from the cone's own wave equation: G (I u')' = -ω² ρ I u with I ∝ z⁴ (the
    cone's polar moment), whose outgoing solution is u = h1(k z)/z (h1 the spherical Hankel
    function of the second kind, e^{iωt}); S = -G I u'(z0)/u(z0), K = 3 G I/z0 its static value."""
    from scipy.special import spherical_jn, spherical_yn

    h = spherical_jn(1, b0) - 1j * spherical_yn(1, b0)
    dh = spherical_jn(1, b0, True) - 1j * spherical_yn(1, b0, True)
    return -(b0 * dh - h) / h / 3.0  # z0 = 1, I = 1, G = 1: u'/u = (k h1' z - h1)/(z h1)


@pytest.mark.parametrize("a0", [0.25, 0.5, 1.0, 1.5, 2.0, 3.0])
def test_torsion_modifier_of_a_square_against_the_torsional_cone(a0):
    """Pais & Kausel's k_t(a0) of a square against the torsional cone of the disk with the same
    polar moment (r0 = (2 J_t/π)^¼ = 1.1415 B'), apex height z0 = (9π/32) r0 so that its static
    stiffness is Reissner-Sagoci's 16 G r0³/3: b0 = (9π/32) a0 r0/B'. Two independent
    approximations of the rigorous solution (the cone's own error a few per cent, Pais & Kausel's
    fit about 5 %; 0.003-0.015 apart here, a0 = 3 beyond the fits included): within 0.025; the
    former static spring (k_t = 1) is 0.07-0.30 away from a0 = 0.5 on."""
    r0 = (2.0 * (4.0 / 3.0) * 2.0 / math.pi) ** 0.25  # B' = L' = 1: J_t = (4/3) L' B' (L'² + B'²)
    cone = _torsional_cone(9.0 * math.pi / 32.0 * a0 * r0)
    assert float(torsion_modifier(a0, 1.0)) == pytest.approx(cone.real, abs=0.025)


def test_resonance_check_uses_each_modes_own_frequency():
    """``fcalc resonance`` on Gazetas' soil: critical speeds from the frequency-consistent p1, p2,
    k0, each below its static value; the static ones reported beside."""
    from foundation_calc.checks.resonance import check_scene_resonances

    document = read_toml(CONFIGS / "compressor_medium_sand_lysmer.toml")
    document["soil"]["method"] = "gazetas"
    report = check_scene_resonances(parse_scene(document))
    for mode in ("k0", "p1", "p2"):
        assert getattr(report.zero_order, mode) < getattr(report.static, mode)
    row = next(r for r in report.rows if r.condition.label == "3ω = p1")
    assert row.critical == pytest.approx(report.zero_order.p1 / 3.0, rel=1e-12)
    lysmer = check_scene_resonances(load_scene(CONFIGS / "compressor_medium_sand_lysmer.toml"))
    assert lysmer.static is None  # frequency-independent: nothing to put beside


def test_each_harmonic_of_the_loads_on_its_own_springs_against_a_direct_solve():
    """The vendor loads' steady state on Gazetas' soil: harmonic n of the spliced motion equals
    the complex solve [K(nω) - (nω)² M + i nω C(nω)] q = Q_n with the block's matrices built at
    n ω (Eq. (2) of the loads module) - and differs from the springs at the speed alone."""
    from foundation_calc.checks.amplitudes.approximations import check_scene_amplitudes
    from foundation_calc.solvers.crank.loads import matrices

    document = read_toml(CONFIGS / "compressor_vendor_loads.toml")
    document["soil"] = {"method": "gazetas", "shear_wave_velocity": 220.0, "density": 1900.0, "poisson": 0.3,
                        "material_damping": 0.03}
    document["foundation"] |= {"base_length": 6.0, "base_width": 3.5}
    del document["foundation"]["base_area"], document["foundation"]["base_second_moment"]
    scene = parse_scene(document)
    motion = check_scene_amplitudes(scene).approximations["loads"].motion
    loads, omega = scene.harmonic_loads(), scene.speed.omega_rad_s
    Q = loads.generalized()
    for n in (1, 2):
        M, K, C = matrices(scene.block(n * omega))
        q = np.linalg.solve(K - (n * omega) ** 2 * M + 1j * n * omega * C, Q[np.asarray(loads.order) == n].sum(0))
        assert motion.cos[:, n] == pytest.approx(q.real, rel=1e-10)
        assert motion.sin[:, n] == pytest.approx(-q.imag, rel=1e-10)
    M, K, C = matrices(scene.block(omega))
    at_speed = np.linalg.solve(K - (2 * omega) ** 2 * M + 2j * omega * C, Q[np.asarray(loads.order) == 2].sum(0))
    assert not np.allclose(motion.cos[:, 2], at_speed.real, rtol=1e-3)


def test_embedded_rocking_about_the_short_axis_takes_the_long_half_side():
    """Gazetas (1991), Table 2: rocking about the short axis y embeds with
    η_ry = 1 + 0.92 (d/L')^0.6 [1.5 + (d/L')^1.9 (d/D)^-0.6], L' the long half-side (the side in
    the plane of motion), as the table prints it; some open implementations write (d/B')^0.6. The
    physics decides: at fixed d, B', the sidewalls' share of the rocking stiffness must vanish as the
    base grows long in the plane of motion (the base's K_ry grows as L'^2.4, the walls' as L'^2),
    which (d/L')^0.6 does and (d/B')^0.6, constant in L', does not."""
    from foundation_calc.solvers.soil.gazetas import gazetas_static_springs

    def eta(L, B=4.0, D=1.0):
        return float(gazetas_static_springs(G, NU, L, B, D)[2] / gazetas_static_springs(G, NU, L, B, 0.0)[2])

    excess = [eta(L) - 1.0 for L in (6.0, 24.0, 96.0, 384.0)]
    assert all(a > b for a, b in zip(excess, excess[1:])) and excess[-1] < 0.2 * excess[0]
    r = 1.0 / 3.0  # d/L' of the 6 m × 4 m block embedded 1 m (d/B' = 1/2)
    assert eta(6.0) == pytest.approx(1.0 + 0.92 * r**0.6 * (1.5 + r**1.9), rel=1e-12)
