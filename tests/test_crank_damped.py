"""Damped crank foundation (base dashpots from soil.damping): independent checks.

- The exact periodic solution (harmonic balance) against time integration from rest to the
  steady state of the sympy Lagrange reference equations of ``test_crank_exact``, with the base
  dashpots and c_φ added there as generalised forces written from the physics (not from fcalc).
- The damped closed forms (first approximation, averaged operator) against the exact solution,
  at exact resonance and away from it.
- Properties: damping → 0 recovers the undamped numbers; at resonance the amplitude scales as
  1/ξ; no NaN or inf at exact resonance for any ξ > 0.
"""

from __future__ import annotations

import math
from dataclasses import replace

import numpy as np
import pytest
from hypothesis import example, given, settings
from hypothesis import strategies as st

from foundation_calc.solvers.crank.averaged import averaged_response
from foundation_calc.solvers.crank.closed_form import design_first_approximation, with_damping
from foundation_calc.solvers.crank.exact import exact_periodic_solution
from foundation_calc.solvers.crank.frequencies import zero_order_frequencies
from foundation_calc.solvers.numerics.trig_series import analyse
from tests.test_crank_exact import design_args, make_design, reference_equations


def damped(design, xi_z, xi_x=None, xi_phi=None):
    """``design`` with the dashpots of damping ratios ξ (the scene's soil.damping)."""
    return with_damping(design, xi_z, xi_z if xi_x is None else xi_x, xi_z if xi_phi is None else xi_phi)


def harmonic(motion, dof, n):
    i = ("x", "y", "theta").index(dof)
    return complex(motion.cos[i, n], -motion.sin[i, n])


def test_damped_exact_solution_is_the_limit_of_time_integration_from_rest():
    """Start at rest (static equilibrium), integrate the reference equations until the free
    vibration has decayed by e^-25, then compare one period with the harmonic balance.

    The speed is exactly the lowest natural frequency of the averaged operator (a resonance) and
    c_φ = 1.5 c. Tolerance 1e-8 of each coordinate's largest coefficient: the transient left is
    e^-25 ≈ 1e-11 of its start (of the order of the response), the integrator's rtol is 1e-10.
    """
    from scipy.integrate import solve_ivp

    base = replace(make_design(drive_on=True, m=6.0e3, m1=3.0e3), c_phi=6.0e7)
    undamped = averaged_response(base)
    design = replace(damped(base, 0.3), omega=float(undamped.natural[0]))
    response = averaged_response(design)
    decay = float((response.damping_ratios * response.natural).min())  # slowest free vibration [1/s]
    mo = exact_periodic_solution(design).motion

    mass, rhs = reference_equations(True)
    args = design_args(design)
    d = design

    def f(t, z):
        q, dq, ph = z[:3], z[3:], d.omega * t
        slip = dq[0] - d.h * dq[2]  # base velocity in x
        extra = np.array([
            -d.C_x * slip,
            -d.C_z * dq[1],
            d.h * d.C_x * slip - d.C_phi * dq[2] - (d.c_phi - d.c) * d.I1 * q[2],
        ])
        acc = np.linalg.solve(np.asarray(mass(args, ph, q, dq), float), np.asarray(rhs(args, ph, q, dq), float).ravel() + extra)
        return np.concatenate([dq, acc])

    T = 2 * np.pi / d.omega
    periods = math.ceil(25.0 / decay / T)
    N = 64
    t_eval = periods * T + np.arange(N) * T / N
    sol = solve_ivp(f, (0.0, t_eval[-1]), np.zeros(6), method="DOP853", rtol=1e-10, atol=1e-14, t_eval=t_eval)
    assert sol.success
    cos, sin = analyse(sol.y[:3], 8)
    for i in range(3):
        scale = np.abs(mo.cos[i]).max() + np.abs(mo.sin[i]).max()
        np.testing.assert_allclose(cos[i], mo.cos[i, :9], rtol=0, atol=1e-8 * scale)
        np.testing.assert_allclose(sin[i, 1:], mo.sin[i, 1:9], rtol=0, atol=1e-8 * scale)


def _errors(motion, exact):
    return {
        f"{dof}{n}": abs(harmonic(motion, dof, n) - harmonic(exact, dof, n)) / abs(harmonic(exact, dof, n))
        for dof, n in (("y", 1), ("y", 2), ("x", 1), ("theta", 1))
    }


@pytest.mark.parametrize("m", [1.5e3, 6.0e3], ids=["mu=0.015", "mu=0.057"])
@pytest.mark.parametrize("xi", [0.05, 0.2])
@pytest.mark.parametrize("where", ["at p1", "away"])
def test_damped_closed_forms_against_the_exact_solution(m, xi, where):
    """Error per harmonic of the damped closed forms against the damped exact solution.

    Tolerances from μ (measured: about half of each bound):
    - y1: the vertical inertia is exactly M_tot; only coupling terms remain: < 2e-3 μ.
    - y2: the first approximation truncates the slider motion at λ² (λ = 0.25): < 3 %; the
      averaged operator has the exact forcing: < 0.4 μ.
    - x1, θ1 at the resonance: the first approximation's resonance is O(μ) off the true one and
      the peak is ξ wide, so its error is O(μ/ξ): < 0.6 μ/ξ; away, O(μ): < 2 μ. The averaged
      operator leaves out only the periodic part of the operator: < 0.1 μ at p1, < 0.03 μ away.
    """
    base = damped(make_design(drive_on=True, m=m), xi)
    p1 = float(averaged_response(base).natural[0])
    design = replace(base, omega=p1 if where == "at p1" else 0.6 * p1)
    mu = design.mu
    exact = exact_periodic_solution(design).motion
    first = _errors(design_first_approximation(design).motion(design.omega), exact)
    averaged = _errors(averaged_response(design).motion, exact)
    rocking_first = 0.6 * mu / xi if where == "at p1" else 2.0 * mu
    rocking_averaged = 0.1 * mu if where == "at p1" else 0.03 * mu
    assert first["y1"] < 2e-3 * mu and averaged["y1"] < 2e-3 * mu
    assert first["y2"] < 3e-2 and averaged["y2"] < 0.4 * mu
    for key in ("x1", "theta1"):
        assert first[key] < rocking_first, (key, first[key])
        assert averaged[key] < rocking_averaged, (key, averaged[key])


BASE = make_design(drive_on=True, m=3.0e3)
ZERO = zero_order_frequencies(BASE.M_tot, BASE.I_c, BASE.h, BASE.S, BASE.I1, BASE.c, BASE.c1, BASE.c_phi, BASE.g)
#: The first approximation's critical speeds: ω = k0, 2ω = k0, ω = p1, p2, 3ω = p1, p2.
CRITICAL = (ZERO.k0, ZERO.k0 / 2, ZERO.p1, ZERO.p2, ZERO.p1 / 3, ZERO.p2 / 3)
FIRST_KEYS = ("y1", "y2", "x1", "x3", "theta1", "theta3")


def _coefficients(design):
    fa = design_first_approximation(design)
    return np.array([np.asarray(getattr(fa, k)) for k in FIRST_KEYS]), fa


@settings(max_examples=30, deadline=None)
@given(factor=st.floats(0.3, 3.0), xi=st.floats(1e-10, 1e-7))
def test_vanishing_damping_recovers_the_undamped_numbers(factor, xi):
    """ξ → 0: the damped closed forms tend to the undamped ones (paper's (4.14) for the first
    approximation). The change is of order ξ/margin; with margin ≥ 1e-2 and ξ ≤ 1e-7 it is below
    1e-5 relative, bounded here by 1e-4 of the largest coefficient."""
    omega = factor * ZERO.p1
    margins = [abs(omega - w) / w for w in CRITICAL]
    if min(margins) < 1e-2:
        omega = ZERO.p1 * 0.5  # 1/3 of p1 < 0.5 p1 < k0/2: away from every condition
    undamped = replace(BASE, omega=omega)
    damped_design = damped(undamped, xi)
    got, _ = _coefficients(damped_design)
    want, _ = _coefficients(undamped)
    assert np.all(np.imag(want) == 0.0)
    np.testing.assert_allclose(got, want, rtol=0, atol=1e-4 * np.abs(want).max())
    av0, av1 = averaged_response(undamped).motion, averaged_response(damped_design).motion
    scale = max(np.abs(av0.cos).max(), np.abs(av0.sin).max())
    np.testing.assert_allclose(av1.cos, av0.cos, rtol=0, atol=1e-4 * scale)
    np.testing.assert_allclose(av1.sin, av0.sin, rtol=0, atol=1e-4 * scale)


def test_zero_damping_is_the_undamped_design_to_the_last_digit():
    design = replace(BASE, omega=0.8 * ZERO.p1)
    got, _ = _coefficients(damped(design, 0.0))
    want, _ = _coefficients(design)
    assert np.array_equal(got, want)


@settings(max_examples=25, deadline=None)
@given(xi=st.floats(1e-6, 1e-4), mode=st.sampled_from(["k0", "p1", "p2"]))
def test_amplitude_at_resonance_scales_as_one_over_xi(xi, mode):
    """At ω = k0, p1, p2 (first approximation) and at the averaged operator's own resonances, the
    resonant harmonic times ξ tends to a constant: halving ξ doubles it, to O(ξ): the other
    modes add a background about 15 ξ of the resonant part (measured), < 1e-2 for ξ ≤ 1e-4."""
    omega = float(getattr(ZERO, mode))
    key = "y1" if mode == "k0" else "x1"
    sizes = [abs(complex(getattr(design_first_approximation(damped(replace(BASE, omega=omega), x)), key))) * x for x in (xi, xi / 2)]
    assert sizes[1] == pytest.approx(sizes[0], rel=1e-2)
    natural = averaged_response(BASE).natural
    w = float(natural[{"p1": 0, "k0": 1, "p2": 2}[mode]])
    dof = 1 if mode == "k0" else 0
    sizes = []
    for x in (xi, xi / 2):
        mo = averaged_response(damped(replace(BASE, omega=w), x)).motion
        sizes.append(math.hypot(mo.cos[dof, 1], mo.sin[dof, 1]) * x)
    assert sizes[1] == pytest.approx(sizes[0], rel=1e-2)


@settings(max_examples=40, deadline=None)
@given(
    xi=st.one_of(st.floats(min_value=0.0, max_value=0.99, exclude_min=True), st.floats(5e-324, 1e-10)),
    which=st.integers(0, len(CRITICAL) - 1),
    xi_x=st.floats(0.0, 0.99),
)
@example(xi=1e-12, which=0, xi_x=0.0)  # at the threshold of "undamped"
@example(xi=1e-12, which=2, xi_x=0.0)
def test_no_nan_or_inf_at_exact_resonance_for_any_damping(xi, which, xi_x):
    """Exactly at every critical speed of both closed forms, any ξ > 0 gives finite numbers; a
    ratio too small to tell from none (a mode's ratio < 1e-12; with ξ_x = 0 a coupled mode's ratio
    is a fraction of ξ_φ, hence the 1e-10 below) is reported resonant, never divided by."""
    omega = float(CRITICAL[which])
    design = damped(replace(BASE, omega=omega), xi, xi_x, xi)
    got, fa = _coefficients(design)
    assert np.all(np.isfinite(got))
    assert not bool(fa.resonant) or xi < 1e-10
    natural = averaged_response(BASE).natural
    for n, w in ((1, natural[0]), (1, natural[1]), (2, natural[1]), (3, natural[2])):
        res = averaged_response(replace(design, omega=float(w) / n))
        assert np.all(np.isfinite(res.motion.cos)) and np.all(np.isfinite(res.motion.sin))
        assert not res.resonant or xi < 1e-10


def test_shooting_converges_at_an_exact_resonance_when_damped():
    """Shooting (solve_ivp + Newton from rest) on the damped design exactly at the averaged
    operator's lowest natural frequency finds the harmonic-balance orbit (to 1e-8 of the largest
    coefficient: the integrator's rtol is 1e-10)."""
    from foundation_calc.solvers.crank.shooting import shooting_solution

    base = damped(make_design(drive_on=True, m=3.0e3), 0.05)
    design = replace(base, omega=float(averaged_response(base).natural[0]))
    shot = shooting_solution(design).motion
    exact = exact_periodic_solution(design).motion
    K = 9
    scale = max(np.abs(exact.cos).max(), np.abs(exact.sin).max())
    np.testing.assert_allclose(shot.cos[:, :K], exact.cos[:, :K], rtol=0, atol=1e-8 * scale)
    np.testing.assert_allclose(shot.sin[:, :K], exact.sin[:, :K], rtol=0, atol=1e-8 * scale)
