"""The exact equations of motion and their harmonic-balance steady state, against independent methods.

Reference equations: Lagrange's equations derived here with sympy from the *inertial* positions
of the block, the crank pin and the slider (rod angle from the pin-to-slider vector, slider
distance s = r cos φ + sqrt(l² - r² sin² φ)), with the crank angle φ as a coordinate so that the
drive-off model comes from the virtual work of an external motor torque (E_θ - E_φ = Q_θ) rather
than from the rod's force balance used in the package. Reference steady state: shooting over one
period with scipy's solve_ivp (DOP853, rtol 1e-12) on those equations.
"""

from __future__ import annotations

from dataclasses import replace
from functools import cache

import numpy as np
import pytest

from foundation_calc.errors import ConvergenceError
from foundation_calc.solvers.crank.dynamics import mechanism_motion, residual
from foundation_calc.solvers.crank.exact import exact_periodic_solution
from foundation_calc.solvers.crank.mechanism import CrankDesign, lump_slider
from foundation_calc.solvers.numerics.trig_series import analyse

sp = pytest.importorskip("sympy")


def make_design(drive_on=True, m=1.5e3, omega=31.41592653589793, a=2.0, r=0.3, l=1.2, l1=1.0, rho=0.35, m1=0.0):
    return CrankDesign(
        M=1.0e5, I_c=4.5e5, h=1.5, S=30.0, I1=90.0, c=4.0e7, c1=2.8e7, c_phi=4.0e7,
        C_x=0.0, C_z=0.0, C_phi=0.0, omega=omega, r=r, l=l, a=a,
        rod=lump_slider(m, l, l1, rho, m1), drive_on_foundation=drive_on, g=9.81,
    )


@cache
def reference_equations(drive_on: bool):
    """Mass matrix M(q, t) and right side f(q, q', t) of M q'' = f, as numpy functions of (design, ...)."""
    t = sp.Symbol("t")
    syms = sp.symbols("M I_c h S I1 c c1 omega r l a m l1 rho g")
    M, I_c, h, S, I1, c, c1, omega, r, l, a, m, l1, rho, g = syms
    x, y, th, ph = (sp.Function(n)(t) for n in ("x", "y", "th", "ph"))
    R = sp.Matrix([[sp.cos(th), -sp.sin(th)], [sp.sin(th), sp.cos(th)]])
    X = sp.Matrix([x, y])
    A = X + R * sp.Matrix([0, -a])
    pin = A + R * sp.Matrix([-r * sp.sin(ph), r * sp.cos(ph)])
    slider = A + R * sp.Matrix([0, r * sp.cos(ph) + sp.sqrt(l**2 - r**2 * sp.sin(ph) ** 2)])
    C1 = pin + (l1 / l) * (slider - pin)
    d = slider - pin
    rod_rate = (d[0] * d[1].diff(t) - d[1] * d[0].diff(t)) / (d[0] ** 2 + d[1] ** 2)
    v1 = C1.diff(t)
    T = (M * X.diff(t).dot(X.diff(t)) + I_c * th.diff(t) ** 2 + m * v1.dot(v1) + m * rho**2 * rod_rate**2) / 2
    V = -g * (M * y + m * C1[1])
    L = T - V
    P = (M + m) * g
    Q = {x: -c1 * S * (x - h * th), y: -c * S * y - P, th: c1 * h * S * x - (c1 * h**2 * S + c * I1 - P * h) * th}

    def E(q):
        return sp.diff(L.diff(q.diff(t)), t) - L.diff(q)

    eqs = [E(x) - Q[x], E(y) - Q[y], E(th) - Q[th] - (0 if drive_on else E(ph))]
    qs = sp.symbols("q0:3")
    dqs = sp.symbols("dq0:3")
    ddqs = sp.symbols("ddq0:3")
    subs = {}
    for f, q0, q1, q2 in zip((x, y, th), qs, dqs, ddqs):
        subs.update({f.diff(t, 2): q2, f.diff(t): q1, f: q0})
    phase = sp.Symbol("phase")
    drive = {ph.diff(t, 2): 0, ph.diff(t): omega, ph: phase}
    eqs = [e.subs(drive).subs(subs) for e in eqs]
    Mmat = sp.Matrix([[sp.diff(e, q2) for q2 in ddqs] for e in eqs])
    rhs = sp.Matrix([-e.subs({q2: 0 for q2 in ddqs}) for e in eqs])
    args = (syms, phase, qs, dqs)
    return sp.lambdify(args, Mmat, "numpy", cse=True), sp.lambdify(args, rhs, "numpy", cse=True)


def design_args(d: CrankDesign):
    return (d.M, d.I_c, d.h, d.S, d.I1, d.c, d.c1, d.omega, d.r, d.l, d.a, d.rod.m, d.rod.l1, d.rod.rho, d.g)


@pytest.mark.parametrize("drive_on", [True, False])
def test_residual_matches_independent_lagrange_equations(drive_on):
    """Residual of the package's equations = M q'' - f of the sympy reference, at random states."""
    design = make_design(drive_on=drive_on, m=4.0e3, m1=2.0e3)
    mass, rhs = reference_equations(drive_on)
    rng = np.random.default_rng(3)
    for _ in range(5):
        phase = rng.uniform(0, 2 * np.pi)
        q = rng.normal(size=3) * np.array([1e-2, 1e-2, 0.05])
        dq, ddq = rng.normal(size=3), rng.normal(size=3) * 10
        ref = np.asarray(mass(design_args(design), phase, q, dq), float) @ ddq - np.asarray(
            rhs(design_args(design), phase, q, dq), float
        ).ravel()
        motion = mechanism_motion(np.array([phase]), design.omega, design.r, design.l, design.rod.l1)
        got = residual(design, motion, q[:, None], dq[:, None], ddq[:, None])[:, 0]
        # forces ~1e6 N: agreement to round-off of the largest term
        np.testing.assert_allclose(got, ref, rtol=0, atol=1e-9 * np.abs(ref).max())


def shooting(design: CrankDesign, state0):
    """Periodic orbit by shooting with solve_ivp on the reference equations; samples on 64 phases."""
    from scipy.integrate import solve_ivp
    from scipy.optimize import fsolve

    mass, rhs = reference_equations(design.drive_on_foundation)
    args = design_args(design)
    T = 2 * np.pi / design.omega
    scale = np.abs(state0) + 1e-3 * np.abs(state0).max()

    def f(t, z):
        q, dq = z[:3], z[3:]
        ph = design.omega * t
        return np.concatenate([dq, np.linalg.solve(np.asarray(mass(args, ph, q, dq), float), np.asarray(rhs(args, ph, q, dq), float).ravel())])

    def flow(z0, t_eval=None):
        return solve_ivp(f, (0, T), z0, method="DOP853", rtol=1e-12, atol=1e-16, t_eval=t_eval)

    def gap(u):
        z0 = u * scale
        return (flow(z0).y[:, -1] - z0) / scale

    u = fsolve(gap, state0 / scale, xtol=1e-13)
    N = 64
    sol = flow(u * scale, t_eval=np.arange(N) * T / N)
    return sol.y[:3], np.abs(gap(u)).max()


def hb_state0(design):
    """HB solution and its state (q, q') at t = 0."""
    mo = exact_periodic_solution(design).motion
    return mo, np.concatenate([mo.cos.sum(-1), (mo.sin * np.arange(mo.sin.shape[-1]) * design.omega).sum(-1)])


def assert_same_harmonics(samples, mo):
    """Harmonics 0..8 of 64 samples = HB's, to 1e-8 of each coordinate's largest coefficient.

    Tolerance: the integrator's rtol 1e-12 over one period (the orbit is neutrally stable, so
    errors do not grow) keeps the reference's error well below 1e-8.
    """
    cos, sin = analyse(samples, 8)
    for i in range(3):
        scale = np.abs(mo.cos[i]).max() + np.abs(mo.sin[i]).max()
        np.testing.assert_allclose(cos[i], mo.cos[i, :9], rtol=0, atol=1e-8 * scale)
        np.testing.assert_allclose(sin[i, 1:], mo.sin[i, 1:9], rtol=0, atol=1e-8 * scale)


def test_harmonic_balance_matches_shooting():
    """Motor on the foundation: shooting from a state 1 % off finds the HB orbit."""
    design = make_design(drive_on=True, m=6.0e3, m1=3.0e3, omega=45.0)
    mo, state0 = hb_state0(design)
    samples, closure = shooting(design, state0 * 1.01)
    assert closure < 1e-9
    assert_same_harmonics(samples, mo)


def test_harmonic_balance_is_a_periodic_orbit_of_the_drive_off_equations():
    """Motor off the foundation: one period of solve_ivp from HB's state at t = 0 retraces HB."""
    from scipy.integrate import solve_ivp

    design = make_design(drive_on=False, m=6.0e3, m1=3.0e3, omega=45.0)
    mo, state0 = hb_state0(design)
    mass, rhs = reference_equations(False)
    args = design_args(design)

    def f(t, z):
        q, dq, ph = z[:3], z[3:], design.omega * t
        acc = np.linalg.solve(np.asarray(mass(args, ph, q, dq), float), np.asarray(rhs(args, ph, q, dq), float).ravel())
        return np.concatenate([dq, acc])

    T = 2 * np.pi / design.omega
    sol = solve_ivp(f, (0, T), state0, method="DOP853", rtol=1e-12, atol=1e-16, t_eval=np.arange(64) * T / 64)
    assert_same_harmonics(sol.y[:3], mo)


def test_harmonic_balance_reports_its_convergence():
    sol = exact_periodic_solution(make_design())
    assert sol.harmonic_change < 1e-10
    assert sol.residual < 1e-12
    assert sol.harmonics in (16, 32, 64)


def test_harmonic_balance_refuses_a_resonant_speed():
    design = make_design()
    from foundation_calc.solvers.crank.averaged import averaged_response

    k0 = averaged_response(design).natural[1]
    with pytest.raises(ConvergenceError, match="no periodic solution"):
        exact_periodic_solution(replace(design, omega=k0 / 2))


def test_drive_torque_supplies_the_rods_energy():
    """Drive off, foundation at rest: τ ω = d/dt (rod's kinetic + potential energy)."""
    design = make_design(drive_on=False, m=2.0e3, m1=1.0e3)
    N = 512
    phi = 2 * np.pi * np.arange(N) / N
    motion = mechanism_motion(phi, design.omega, design.r, design.l, design.rod.l1)
    zero = np.zeros((3, N))
    on = replace(design, drive_on_foundation=True)
    tau = residual(on, motion, zero, zero, zero)[2] - residual(design, motion, zero, zero, zero)[2]
    rod = design.rod
    p = motion.p
    psi_rate = design.omega * design.lam * np.cos(phi) / motion.cos_psi
    energy = 0.5 * rod.m * (motion.dp**2).sum(0) + 0.5 * rod.m * rod.rho**2 * psi_rate**2 - rod.m * design.g * p[1]
    k = np.fft.rfftfreq(N, 1.0 / N)
    denergy = np.fft.irfft(1j * k * design.omega * np.fft.rfft(energy), N)
    np.testing.assert_allclose(tau * design.omega, denergy, rtol=0, atol=1e-9 * np.abs(denergy).max())


def test_galerkin_jacobian_is_the_derivative_of_the_residual_harmonics():
    """The Jacobian assembled from the DFT (product-to-sum identities) against central differences
    of the Galerkin residual itself, on the near-λ = 1 mechanism whose slow harmonic decay made it
    costly. Tolerance: the differences' truncation error, h² R''' ~ 1e-8 of the largest entry."""
    from foundation_calc.solvers.crank.exact import _Galerkin

    design = make_design(l=0.305, l1=0.15)
    galerkin = _Galerkin(design, 6)
    rng = np.random.default_rng(7)
    z = 1e-4 * rng.standard_normal((3, 13))
    J = galerkin.jacobian(z)
    h = 1e-7
    numeric = np.empty_like(J)
    for col in range(z.size):
        dz = np.zeros(z.size)
        dz[col] = h
        plus = galerkin.residual(z + dz.reshape(z.shape)).ravel()
        minus = galerkin.residual(z - dz.reshape(z.shape)).ravel()
        numeric[:, col] = (plus - minus) / (2 * h)
    assert np.abs(J - numeric).max() <= 1e-6 * np.abs(J).max()
