"""A mode whose squared frequency on the springs at ω is negative has no real frequency there, and
the root search of ω = p(K(ω)) takes no crossing of its sqrt|λ|.

A frequency-dependent support's springs at ω are the real part of an impedance and can be
negative (a pile group's K_z). The case, built here: a crank's plane model (x, y, θ of C) on a
support coupling sway with rocking (K_xφ: the one-model eigen-solve's path, as on a pile group),
whose vertical spring

    K_z(ω) = K0 (1 − (ω/ω1)²) for ω < ω2,   K_z(ω2) (ω2/ω)^(1/4) beyond

turns negative at ω1 = 50 rad/s and stays so. Static k0 = sqrt(K0/M) = 100 rad/s; the true root of
ω = k0(K(ω)) is ω* = k0_s / sqrt(1 + (k0_s/ω1)²) = 44.72 rad/s. sqrt(|K_z(ω)|/M) crosses ω again
at 118.9 rad/s, where K_z < 0: no natural frequency, but the root integ's search took (its first
bracket [p_s, p(p_s)] = [100, 121.5] by sqrt|λ|).

Independent reference, written here: M and K(ω) transcribed from the plane model (the base's
springs on u_x = x − h θ, the weight's −P h on θ; the rod's mass negligible, 1e-6 kg), checked
against fcalc's averaged operator; the roots of det(K(ω) − ω² M) = 0 on a grid of 4000 points
(0.1 % apart) refined by bisection to 1e-12. Every root fcalc reports must be one of them (1e-9:
the fixed point's rtol 1e-10 and the bisection's width), and k0 the vertical one.
"""

from __future__ import annotations

import numpy as np
import pytest

from foundation_calc.solvers.crank.natural import by_static_rank, consistent_frequencies, design_frequencies
from foundation_calc.solvers.crank.averaged import averaged_operator, natural_modes
from foundation_calc.solvers.crank.mechanism import CrankDesign, lump_slider

M_TOT, I_C, H, G = 1.0e5, 1.0e5, 1.0, 9.81  # kg, kg m², m, m/s²
S, I1 = 10.0, 10.0  # base area [m²] and second moment [m⁴]: springs = c S, c_φ I1
K0, OMEGA1, OMEGA2 = 1.0e9, 50.0, 80.0  # N/m, rad/s, rad/s
K_X, K_PHI, K_XPHI = 4.0e7, 9.0e9, 1.0e7  # N/m, N m/rad, N/rad: sway-rocking modes near 20 and 300 rad/s

#: The true root of ω = k0(K(ω)) in closed form, and the spurious crossing of sqrt(|K_z(ω)|/M) = ω
#: beyond ω2: ω^(9/8) = sqrt(|K_z(ω2)|/M) ω2^(1/8).
TRUE_K0 = np.sqrt(K0 / M_TOT) / np.sqrt(1.0 + K0 / M_TOT / OMEGA1**2)
SPURIOUS_K0 = (np.sqrt(K0 * (OMEGA2**2 / OMEGA1**2 - 1.0) / M_TOT) * OMEGA2**0.125) ** (8.0 / 9.0)


def k_z(omega: float) -> float:
    """The vertical spring [N/m] at ω [rad/s] (module docstring)."""
    if omega < OMEGA2:
        return K0 * (1.0 - (omega / OMEGA1) ** 2)
    return K0 * (1.0 - (OMEGA2 / OMEGA1) ** 2) * (OMEGA2 / omega) ** 0.25


def design_at(omega: float) -> CrankDesign:
    """The design on the springs at ω [rad/s] (K_z(ω) varies; the others do not)."""
    return CrankDesign(M=M_TOT - 1e-6, I_c=I_C, h=H, S=S, I1=I1, c=k_z(omega) / S, c1=K_X / S, c_phi=K_PHI / I1,
                       C_x=0.0, C_z=0.0, C_phi=0.0, omega=10.0, r=0.1, l=0.5, a=1.0,
                       rod=lump_slider(1e-6, 0.5, 0.25, 0.15, 0.0), drive_on_foundation=True, g=G,
                       K_xphi=K_XPHI, soil_frequency=omega)


def mass() -> np.ndarray:
    """M of x, y, θ of C [kg, kg, kg m²] (the rod's 1e-6 kg left out)."""
    return np.diag([M_TOT, M_TOT, I_C])


def stiffness(omega: float) -> np.ndarray:
    """K(ω) of x, y, θ of C: K_x on u_x = x − h θ, K_xφ of u_x with θ, K_φ and the weight's −P h."""
    xt = K_XPHI - H * K_X
    return np.array([[K_X, 0.0, xt], [0.0, k_z(omega), 0.0],
                     [xt, 0.0, K_PHI - 2.0 * H * K_XPHI + H * H * K_X - M_TOT * G * H]])


def det_roots(low: float, high: float) -> np.ndarray:
    """Every root [rad/s] of det(K(ω) − ω² M) between ``low`` and ``high``: sign changes on 4000
    log-spaced samples, each refined by bisection to 1e-12."""
    f = lambda w: np.linalg.det(stiffness(w) - w * w * mass())  # noqa: E731
    grid = np.geomspace(low, high, 4000)
    values = np.array([f(w) for w in grid])
    roots = []
    for k in np.nonzero(np.sign(values[:-1]) != np.sign(values[1:]))[0]:
        a, b, fa = grid[k], grid[k + 1], values[k]
        while b - a > 1e-12 * b:
            m = 0.5 * (a + b)
            a, b, fa = (m, b, f(m)) if np.sign(f(m)) == np.sign(fa) else (a, m, fa)
        roots.append(0.5 * (a + b))
    return np.array(roots)


def test_the_transcribed_model_is_fcalcs():
    """M and K(ω) written here are the averaged operator's (1e-9 of each matrix's largest entry:
    the rod's 1e-6 kg and round-off), on both sides of ω1 and ω2."""
    for omega in (0.0, 30.0, 60.0, 100.0):
        M, _, K, _, _ = averaged_operator(design_at(omega))
        assert np.allclose(M, mass(), rtol=0.0, atol=1e-9 * M_TOT), omega
        assert np.allclose(K, stiffness(omega), rtol=0.0, atol=1e-9 * K_PHI), omega


def test_the_root_search_takes_the_true_crossing_not_the_imaginary_modes():
    """fcalc resonance's path on a coupled support (scene_design_frequencies): each mode named at
    rest, followed by its rank at ω, re-solved as ω = p(K(ω)). integ took k0 = 118.9 rad/s, where
    K_z < 0 (det ≠ 0 there); now k0 = 44.72 rad/s, and p1, p2 are roots of the determinant too."""
    roots = det_roots(1.0, 2000.0)
    assert roots[np.argmin(np.abs(roots - TRUE_K0))] == pytest.approx(TRUE_K0, rel=1e-9)  # the reference finds it
    assert np.min(np.abs(roots - SPURIOUS_K0)) > 0.1 * SPURIOUS_K0  # and no root at the spurious crossing
    static = design_frequencies(design_at(0.0))[1]
    assert static.k0 == pytest.approx(100.0, rel=1e-9)  # the vertical mode named k0 at rest
    ranked = by_static_rank(static)
    found = consistent_frequencies(static, lambda w: ranked(design_frequencies(design_at(w))[1]))
    assert found.k0 == pytest.approx(TRUE_K0, rel=1e-9), (found, SPURIOUS_K0)
    assert SPURIOUS_K0 == pytest.approx(118.868, abs=1e-3)  # the crossing integ took, its value there
    for mode in ("p1", "p2"):
        p = getattr(found, mode)
        assert np.min(np.abs(roots - p)) < 1e-9 * p, (mode, p, roots)


def test_a_negative_squared_frequency_is_zero_at_frequency_and_unchanged_at_rest():
    """On the springs at 100 rad/s (K_z < 0) the vertical mode has no real frequency: 0, ranked
    lowest by its signed eigenvalue; the at-rest reading (the default) keeps sqrt|λ| by |λ|."""
    lam_z = k_z(100.0) / M_TOT
    assert lam_z < 0.0
    at_frequency, shapes = natural_modes(mass(), stiffness(100.0), at_rest=False)
    assert at_frequency[0] == 0.0 and abs(shapes[1, 0]) == pytest.approx(1.0)  # the vertical mode, first
    assert np.all(at_frequency[1:] > 0.0)
    as_before, _ = natural_modes(mass(), stiffness(100.0))
    assert np.sqrt(-lam_z) == pytest.approx(as_before[1], rel=1e-12)  # between the sway-rocking pair by |λ|
