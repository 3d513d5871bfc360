"""Single piles and capped pile groups (``foundation_calc.solvers.piles``) against values none of
their formulas produced.

* EN 1998-5 Annex C, Table C.1: the coefficients and exponents transcribed below from the table
  (rows per profile, columns K_HH/(d E_s), K_MM/(d³ E_s), K_HM/(d² E_s)), compared at the
  table's printed precision (two decimals on a coefficient: 5e-3 relative on each).
* A pile on a Winkler foundation solved along the pile by cubic beam elements (statics: k_x =
  1.2 E(z), the profile's modulus; Table C.1 came from a continuum, so the two agree to within
  20 % (measured 0.84-1.10 for E_p/E_s = 300-5000), the Winkler model's known accuracy; dynamics: the Winkler springs and dashpots of Makris &
  Gazetas, a finite pile, against the closed-form frequency shape of a semi-infinite one, 0.5 %).
* The vertical frequency shape against a finite-element rod (1e-3).
* A 2 × 2 group's vertical and horizontal impedance over four single piles by Dobry & Gazetas'
  factors written out for the square here (each pile sees two neighbours at s, one at 0° and
  one at 90° to the loading, and one at s sqrt 2 and 45°), at two frequencies, 1e-3.
* A group whose spacing grows tends to n single piles (within 3 sqrt(r0/S), the factors' decay).
"""

from __future__ import annotations

import cmath
import math

import numpy as np
import pytest

from foundation_calc.solvers.piles.cap import cap_impedance
from foundation_calc.solvers.piles.single import PileHead, lateral_static, pinned, single_pile, vertical_shape

TABLE_C1 = {  # EN 1998-5:2004 Table C.1, as printed: (K_HH, K_MM, K_HM) coefficient, exponent
    "uniform": [(1.08, 0.21), (0.16, 0.75), (-0.22, 0.50)],
    "linear": [(0.60, 0.35), (0.14, 0.80), (-0.17, 0.60)],
    "parabolic": [(0.79, 0.28), (0.15, 0.77), (-0.24, 0.53)],
}
PRINTED = 5e-3  # two decimals on coefficients of about 1


@pytest.mark.parametrize("profile", sorted(TABLE_C1))
@pytest.mark.parametrize("ratio", [300.0, 1000.0, 5000.0])
def test_lateral_static_is_table_c1(profile, ratio):
    d, E_s = 0.8, 5.0e7
    got = lateral_static(E_s, ratio * E_s, d, profile)
    for value, (c, n), power in zip(got, TABLE_C1[profile], (1, 3, 2)):
        assert float(value) / (d**power * E_s) == pytest.approx(c * ratio**n, rel=PRINTED)


@pytest.mark.parametrize("nu", [0.25, 0.45])
def test_a_pile_at_rest_takes_table_c1_with_its_soil_model_modulus(nu):
    """Annex C defines the table's E_s as the soil model's Young's modulus "equal to 3G" (not the
    soil's own 2 G (1 + ν)): the static sway spring of a pile on a soil of shear modulus G is the
    table's at E_s = 3 G, whatever ν (ν = 0.25 would differ by 10 %)."""
    d, G, E_p = 0.6, 4.0e7, 3.0e10
    head = single_pile(d, 20.0, E_p, 2500.0, G, nu, 1900.0, "uniform", False, 0.0)
    (c, n), E_s = TABLE_C1["uniform"][0], 3.0 * G
    assert float(head.K_HH.real) == pytest.approx(d * E_s * c * (E_p / E_s) ** n, rel=PRINTED)


def _beam_on_winkler(EI, k_of_z, L, n=240, m=0.0, omega=0.0):
    """Head stiffness matrix [[H/u, H/θ], [M/u, M/θ]] of a free-tip beam on springs k(z) (complex
    allowed) minus m ω², cubic Hermite elements, z down, θ = du/dz."""
    h = L / n
    Ke = EI / h**3 * np.array([[12, 6 * h, -12, 6 * h], [6 * h, 4 * h * h, -6 * h, 2 * h * h],
                               [-12, -6 * h, 12, -6 * h], [6 * h, 2 * h * h, -6 * h, 4 * h * h]])
    Me = h / 420.0 * np.array([[156, 22 * h, 54, -13 * h], [22 * h, 4 * h * h, 13 * h, -3 * h * h],
                               [54, 13 * h, 156, -22 * h], [-13 * h, -3 * h * h, -22 * h, 4 * h * h]])
    K = np.zeros((2 * n + 2, 2 * n + 2), dtype=complex)
    for e in range(n):
        z = (e + 0.5) * h
        s = slice(2 * e, 2 * e + 4)
        K[s, s] += Ke + (k_of_z(z) - m * omega**2) * Me
    head, rest = [0, 1], list(range(2, 2 * n + 2))
    Khr = K[np.ix_(head, rest)]
    return K[np.ix_(head, head)] - Khr @ np.linalg.solve(K[np.ix_(rest, rest)], Khr.T)


@pytest.mark.parametrize("profile,f", [("uniform", lambda t: 1.0), ("linear", lambda t: t),
                                       ("parabolic", lambda t: math.sqrt(t))])
def test_lateral_static_near_a_winkler_pile(profile, f):
    d, E_s, E_p, L = 0.6, 4.0e7, 3.0e10, 20.0
    EI = E_p * math.pi * d**4 / 64.0
    K = _beam_on_winkler(EI, lambda z: 1.2 * E_s * f(max(z, 1e-9) / d), L).real
    K_HH, K_MM, K_HM = (float(v) for v in lateral_static(E_s, E_p, d, profile))
    assert K[0, 0] == pytest.approx(K_HH, rel=0.2)
    assert K[1, 1] == pytest.approx(K_MM, rel=0.2)
    assert -K[0, 1] == pytest.approx(K_HM, rel=0.2)  # Table C.1's sign: θ of the opposite sense


def test_lateral_dynamic_shape_is_a_long_winkler_pile():
    """single_pile's K(ω)/K(0) against a finite pile of about 8 active lengths on the same
    Winkler springs and dashpots, solved by beam elements: 0.5 %."""
    d, G, nu, rho, E_p, rho_p = 0.6, 7.0e7, 0.35, 1900.0, 3.0e10, 2500.0
    E, V_s = 2 * G * (1 + nu), math.sqrt(G / rho)
    EI, m = E_p * math.pi * d**4 / 64.0, rho_p * math.pi * d**2 / 4.0
    static = _beam_on_winkler(EI, lambda z: 1.2 * E, 30.0, n=400)
    rest = single_pile(d, 30.0, E_p, rho_p, G, nu, rho, "uniform", False, 0.0)
    for omega in (40.0, 250.0):
        a0 = omega * d / V_s
        k = 1.2 * E + 1j * omega * 6.0 * a0**-0.25 * rho * V_s * d  # Makris & Gazetas, written out
        dynamic = _beam_on_winkler(EI, lambda z: k, 30.0, n=400, m=m, omega=omega)
        p = single_pile(d, 30.0, E_p, rho_p, G, nu, rho, "uniform", False, omega)
        for (i, j), name in {(0, 0): "K_HH", (0, 1): "K_HM", (1, 1): "K_MM"}.items():
            want = dynamic[i, j] / static[i, j]
            got = complex(getattr(p, name) / getattr(rest, name))
            assert abs(got - want) < 5e-3 * abs(want), (name, omega, got, want)


def test_vertical_shape_is_a_finite_element_rod():
    d, L, E, rho, V_s, E_p, m, nu, G_tip = 0.5, 12.0, 1.5e8, 1900.0, 170.0, 3.0e10, 490.0, 0.3, 5.0e7
    EA, r0, n = E_p * math.pi * d**2 / 4.0, d / 2.0, 600
    h = L / n

    def rod(omega, end_bearing):
        a0 = max(omega * d / V_s, 0.05)
        k = 0.6 * E * (1 + 0.5 * math.sqrt(omega * d / V_s)) + 1j * omega * 1.2 * a0**-0.25 * rho * V_s * math.pi * d
        K = np.zeros((n + 1, n + 1), dtype=complex)
        for e in range(n):
            K[e:e + 2, e:e + 2] += EA / h * np.array([[1, -1], [-1, 1]]) + (k - m * omega**2) * h / 6 * np.array([[2, 1], [1, 2]])
        if end_bearing:
            K, free = K[:-1, :-1], n - 1
        else:
            K[n, n] += (4 * G_tip * r0 + 1j * omega * 3.4 * r0**2 * math.sqrt(rho * G_tip)) / (1 - nu)
            free = n
        rest = K[1:free + 1, 1:free + 1]
        return K[0, 0] - K[0, 1:free + 1] @ np.linalg.solve(rest, K[1:free + 1, 0])

    for end_bearing in (False, True):
        for omega in (30.0, 120.0):
            want = rod(omega, end_bearing) / rod(0.0, end_bearing)
            got = complex(vertical_shape(E, G_tip, nu, rho, V_s, E_p, d, L, m, end_bearing, omega))
            assert abs(got - want) < 1e-3 * abs(want)


def _alpha(S, V, beta, omega, d):
    return math.sqrt(d / 2 / S) * cmath.exp(-beta * omega * S / V) * cmath.exp(-1j * omega * S / V)


@pytest.mark.parametrize("omega", [25.0, 90.0])
def test_two_by_two_group_by_dobry_gazetas(omega):
    d, s, V_s, nu, beta = 0.6, 2.4, 150.0, 0.35, 0.04
    V_La = 3.4 * V_s / (math.pi * (1 - nu))
    one = PileHead(2.0e8 + 5e7j, 1.0e8 + 3e7j, 0.0, 0.0, 0.0, 1.0)
    x, y = np.array([-s / 2, s / 2, -s / 2, s / 2]), np.array([-s / 2, -s / 2, s / 2, s / 2])
    K = cap_impedance(x, y, one, d, V_s, V_s, nu, beta, omega)
    diag = s * math.sqrt(2)
    vertical = 1 + 2 * _alpha(s, V_s, beta, omega, d) + _alpha(diag, V_s, beta, omega, d)
    horizontal = (1 + _alpha(s, V_La, beta, omega, d) + _alpha(s, V_s, beta, omega, d)
                  + 0.5 * _alpha(diag, V_La, beta, omega, d) + 0.5 * _alpha(diag, V_s, beta, omega, d))
    assert abs(K[2, 2] / (4 * one.K_v) - 1 / vertical) < 1e-3
    assert abs(K[0, 0] / (4 * one.K_HH) - 1 / horizontal) < 1e-3
    assert abs(K[1, 1] / (4 * one.K_HH) - 1 / horizontal) < 1e-3
    # rocking: every pile at the arm s/2 about y, the same interaction as the vertical with the
    # neighbour across x moving against it: 1 - α(s, along x) + α(s, along y) - α(diagonal)
    rocking = 1 - _alpha(s, V_s, beta, omega, d) + _alpha(s, V_s, beta, omega, d) - _alpha(diag, V_s, beta, omega, d)
    assert abs(K[4, 4] / (4 * one.K_v * (s / 2) ** 2) - 1 / rocking) < 1e-3


def test_wide_group_is_n_single_piles():
    """Each pile sees three neighbours whose factors fall as sqrt(r0/S): the group's impedance
    departs from four single piles' by less than 3 sqrt(r0/S_min), at every spacing."""
    p = single_pile(0.6, 15.0, 3.0e10, 2500.0, 6.0e7, 0.3, 1850.0, "uniform", False, 60.0)
    for scale in (50.0, 5000.0, 500000.0):
        x, y = np.array([-1.0, 1.0, -1.0, 1.0]) * scale, np.array([-1.0, -1.0, 1.0, 1.0]) * scale
        K = cap_impedance(x, y, p, 0.6, 180.0, 180.0, 0.3, 0.0, 60.0)
        bound = 3.0 * math.sqrt(0.3 / (2.0 * scale))
        for i, single in ((0, p.K_HH), (1, p.K_HH), (2, p.K_v)):
            assert abs(K[i, i] / (4 * single) - 1) < bound
        assert abs(K[4, 4] / (4 * p.K_v * scale**2 + 4 * p.K_MM) - 1) < bound
        assert abs(K[0, 4] / (4 * p.K_HM) - 1) < 1e-12  # the piles' own coupling, no interaction


def test_pinned_head_is_the_free_head_sway():
    """A pinned head's sway is the fixed head's with the moment released: H/u at M = 0."""
    p = single_pile(0.6, 15.0, 3.0e10, 2500.0, 6.0e7, 0.3, 1850.0, "linear", True, 0.0)
    K = np.array([[p.K_HH, p.K_HM], [p.K_HM, p.K_MM]]).real
    u = np.linalg.solve(K, [1.0, 0.0])[0]
    assert float(pinned(p).K_HH.real) == pytest.approx(1.0 / u, rel=1e-12)


def test_cap_free_rotation_follows_the_sway():
    """Pushed along +x with no moment, a single fixed pile's cap rotates so that the head leans
    with the push (θ_y > 0 with z up: the pile's top moves most)."""
    p = single_pile(0.6, 15.0, 3.0e10, 2500.0, 6.0e7, 0.3, 1850.0, "uniform", False, 0.0)
    K = cap_impedance(np.array([0.0]), np.array([0.0]), p, 0.6, 180.0, 180.0, 0.3, 0.0, 0.0).real
    sub = K[np.ix_([0, 4], [0, 4])]
    u, theta = np.linalg.solve(sub, [1.0, 0.0])
    assert u > 0 and theta > 0
    sub = K[np.ix_([1, 3], [1, 3])]
    v, theta_x = np.linalg.solve(sub, [1.0, 0.0])
    assert v > 0 and theta_x < 0  # u_y = -θ_x z: the top leans along +y
