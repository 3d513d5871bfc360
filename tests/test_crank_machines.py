"""Crank mechanisms as machines on the 6-DOF block (solvers.machines.crank_mechanism,
solvers.rigid_body.periodic, solvers.block.periodic_inertia) against independent methods:

* the mean mass matrix by brute-force averaging of the test's own kinematics (slider from the
  rod's length by Pythagoras, derivatives spectrally from 1024 samples) and the natural
  frequencies of (K, M̄) by scipy.linalg.eigh, to 1e-6;
* the exact periodic solution against a shooting method on the equations of block and
  mechanisms linearised in the block's small motion, derived here by virtual work with the
  attitude R = exp([θ]×) differentiated numerically (scipy.linalg.expm, complex step and central
  differences), integrated by scipy's DOP853 over one period;
* a plane throw against the crank foundation's own equations (solvers.crank.dynamics,
  linearised by complex step): the mechanism's operator pointwise in φ to 1e-9; the block's first
  approximation against the crank scene's averaged operator to 1e-9.
"""

from __future__ import annotations

import numpy as np
import pytest
import scipy.linalg
from scipy.integrate import solve_ivp

from foundation_calc.solvers.block.periodic_inertia import exact_response, first_approximation_error
from foundation_calc.solvers.block.model import block_model, excitation
from foundation_calc.solvers.block.response import block_modes, complex_amplitudes
from foundation_calc.solvers.machines.crank_mechanism import (
    CrankMechanism, crank_throw, forcing_harmonics, mean_mass_properties, mechanism_samples,
)
from foundation_calc.solvers.rigid_body.kinematics import point_maps

G = 9.81
RPM = np.pi / 30.0


def _throw_data(A, n, s, alpha, rot=(0.0, 0.0, 0.0)):
    return dict(A=np.array(A, float), n=np.array(n, float), s=np.array(s, float), alpha=alpha, r=0.11, l=0.5, m=65.0,
                l1=0.15, rho=0.17, m1=140.0, rot=rot)


#: The shipped configs' machines (configs/block_two_throw_compressor.toml, block_opposed_compressor.toml).
TWO_THROW = [_throw_data([0.0, -0.4, 3.0], [0, 1, 0], [0, 0, 1], 0.0, rot=(40.0, 0.08, np.pi)),
             _throw_data([0.0, 0.4, 3.0], [0, 1, 0], [0, 0, 1], np.pi / 2)]
OPPOSED = [_throw_data([0.0, -0.25, 1.6], [0, 1, 0], [1, 0, 0], 0.0),
           _throw_data([0.0, 0.25, 1.6], [0, 1, 0], [-1, 0, 0], 0.0)]
CASES = {"two-throw": (TWO_THROW, 600.0), "opposed": (OPPOSED, 500.0)}


def _fcalc_throws(data):
    return [crank_throw(d["A"], d["n"], d["s"], d["alpha"], d["r"], d["l"], d["m"], d["l1"], d["rho"], d["m1"], *d["rot"])
            for d in data]


# --- the test's own kinematics: point masses and their spectral derivatives -------------------------

SAMPLES = 1024


def _positions(d, phi):
    """Point masses (m, positions (N, 3)) of one throw: rod halves at C1 ± ρ e, slider, rotating mass."""
    n, s = d["n"] / np.linalg.norm(d["n"]), d["s"] / np.linalg.norm(d["s"])
    t = np.cross(n, s)
    a = phi + d["alpha"]
    pin = d["A"] + d["r"] * (np.cos(a)[:, None] * s + np.sin(a)[:, None] * t)
    offset = np.einsum("ni,i->n", pin - d["A"], t)  # the pin's distance from the slider's line
    along = np.einsum("ni,i->n", pin - d["A"], s) + np.sqrt(d["l"] ** 2 - offset**2)  # Pythagoras on the rod
    slider = d["A"] + along[:, None] * s
    e = (slider - pin) / d["l"]
    c1 = pin + d["l1"] * e
    m_r, r_r, beta = d["rot"]
    rot = d["A"] + r_r * (np.cos(a + beta)[:, None] * s + np.sin(a + beta)[:, None] * t)
    return [(d["m"] / 2, c1 + d["rho"] * e), (d["m"] / 2, c1 - d["rho"] * e), (d["m1"], slider), (m_r, rot)]


class Kinematics:
    """Positions of every point mass at N phases φ_j = 2πj/N of one revolution, and their time
    derivatives by spectral differentiation (exact for a series of degree < N/2; the harmonics of
    the kinematics fall below round-off well before N/2)."""

    def __init__(self, data, omega):
        phi = 2 * np.pi * np.arange(SAMPLES) / SAMPLES
        parts = [p for d in data for p in _positions(d, phi)]
        self.m = np.array([p[0] for p in parts])
        self.samples = np.stack([p[1] for p in parts])  # (P, N, 3)
        k = np.fft.fftfreq(SAMPLES, 1.0 / SAMPLES)
        k[SAMPLES // 2] = 0.0
        spectrum = np.fft.fft(self.samples, axis=1)
        self.v, self.a = (np.fft.ifft(spectrum * ((1j * k * omega) ** order)[None, :, None], axis=1).real for order in (1, 2))
        self.omega = omega


def _mean_mass_matrix(kin):
    """Brute force: Σ_k m_k [[I, -[r]×], [[r]×, |r|²I - r rᵀ]] averaged over the samples."""
    r = kin.samples
    X = np.zeros(r.shape + (3,))
    X[..., 0, 1], X[..., 0, 2], X[..., 1, 2] = -r[..., 2], r[..., 1], -r[..., 0]
    X[..., 1, 0], X[..., 2, 0], X[..., 2, 1] = r[..., 2], -r[..., 1], r[..., 0]
    top = np.concatenate([np.broadcast_to(np.eye(3), X.shape), -X], axis=-1)
    bottom = np.concatenate([X, np.swapaxes(X, -1, -2) @ X], axis=-1)
    return np.einsum("p,pnij->ij", kin.m, np.concatenate([top, bottom], axis=-2)) / SAMPLES


# --- the test's own equations: virtual work with R = exp([θ]×) ------------------------------------------


def _rotate(theta, r):
    X = np.array([[0, -theta[2], theta[1]], [theta[2], 0, -theta[0]], [-theta[1], theta[0], 0]])
    return scipy.linalg.expm(X) @ r


def _jacobian(theta, r, h=1e-20):
    """∂(R(θ) r)/∂θ by complex step (expm of a complex matrix)."""
    return np.stack([(_rotate(theta + 1j * h * e, r)).imag / h for e in np.eye(3)], axis=1)


def _geometric_tensor(step=1e-4):
    """W[c][k, a, b] = ∂/∂θ_b of ∂(R r)_k/∂θ_a at θ = 0 for r = e_c (central differences)."""
    return np.array([[(_jacobian(step * e_b, e_c) - _jacobian(-step * e_b, e_c)) / (2 * step) for e_b in np.eye(3)]
                     for e_c in np.eye(3)]).transpose(0, 2, 3, 1)  # (c, k, a, b)


W = _geometric_tensor()
J0 = np.array([_jacobian(np.zeros(3), e) for e in np.eye(3)])  # ∂(R e_c)/∂θ at 0 (= -[e_c]×), (c, k, a)


def _linear_equations(kin):
    """M, D, S (N, 6, 6) and f (N, 6) of the mechanisms at the N phases: Σ_k J_kᵀ m_k (x_k'' + g e_z)
    linearised in q.

    x = u + R(θ) r, J = [I, ∂(R r)/∂θ]; the linear part of x'' is u'' + J_θ(r) θ'' + 2 J_θ(r') θ' + J_θ(r'') θ
    (J_θ linear in its vector); the linear part of J_θ(r)ᵀ as θ varies gives Σ r_c r''_k W[c][k, a, b] θ_b.
    The weight: its moment m g e_z·(∂(R r)/∂θ) and the tilt -m g z (about x and y), as the block model has it.
    """
    r, v, a, m = kin.samples, kin.v, kin.a, kin.m
    Jr, Jv, Ja = (np.einsum("pnc,cka->pnka", x, J0) for x in (r, v, a))
    T = np.concatenate([np.broadcast_to(np.eye(3), Jr.shape), Jr], axis=-1)  # (P, N, 3, 6)
    M = np.einsum("p,pnka,pnkb->nab", m, T, T)
    D, S = np.zeros_like(M), np.zeros_like(M)
    D[..., 3:] = 2 * np.einsum("p,pnka,pnkb->nab", m, T, Jv)
    S[..., 3:] = np.einsum("p,pnka,pnkb->nab", m, T, Ja)
    S[:, 3:, 3:] += np.einsum("p,pnc,pnk,ckab->nab", m, r, a, W)
    S[:, 3, 3] -= G * m @ r[..., 2]
    S[:, 4, 4] -= G * m @ r[..., 2]
    f = -np.einsum("p,pnka,pnk->na", m, T, a)  # the inertia of the mechanism at q = 0
    f[:, 3:] -= G * np.einsum("p,pnk->nk", m, Jr[:, :, 2, :])
    return M, D, S, f


class Series:
    """A periodic array given at the N phases, evaluated at any time by its Fourier series."""

    def __init__(self, values, omega, K=100):
        c = np.fft.rfft(values, axis=0)[:K] / len(values)
        c[1:] *= 2.0
        self.cos, self.sin = c.real.reshape(K, -1), -c.imag.reshape(K, -1)
        self.shape, self.k, self.omega = values.shape[1:], np.arange(K), omega

    def __call__(self, t):
        phase = self.k * self.omega * t
        return (np.cos(phase) @ self.cos + np.sin(phase) @ self.sin).reshape(self.shape)


# --- the block ------------------------------------------------------------------------------------------

BLOCK = dict(mass=1.2e5, cog=[0.0, 0.0, 1.0], inertia=[1.7e5, 3.6e5, 4.8e5])
MACHINE = dict(mass=14.0e3, cog=[0.0, 0.0, 2.9], inertia=[6.0e3, 9.0e3, 7.0e3])
SPRINGS = np.array([6.0e8, 5.0e8, 9.0e8, 1.4e9, 2.3e9, 1.6e9])


def _model(throws, ratio=0.0):
    m, cog, J = mean_mass_properties(throws)
    return block_model([BLOCK["mass"], MACHINE["mass"], m], [BLOCK["cog"], MACHINE["cog"], cog],
                       [BLOCK["inertia"], MACHINE["inertia"], J], SPRINGS, G, 7.2,
                       ratios=np.full(6, ratio) if ratio else None)


def _excitation(throws, omega):
    fh = forcing_harmonics(throws, omega, G)
    Q = fh.inertial + fh.weight
    rows = [(int(n), q[:3].real, q[3:].real, 0.0, np.zeros(3), True) for n, q in zip(fh.orders, Q)]
    rows += [(int(n), q[:3].imag, q[3:].imag, np.pi / 2, np.zeros(3), True) for n, q in zip(fh.orders, Q)]
    return excitation("compressor", omega, rows)


@pytest.fixture(scope="module", params=sorted(CASES))
def case(request):
    data, rpm = CASES[request.param]
    throws = _fcalc_throws(data)
    omega = rpm * RPM
    model = _model(throws, ratio=0.02)
    exc = _excitation(throws, omega)
    return dict(name=request.param, data=data, throws=throws, omega=omega, model=model, exc=exc,
                kin=Kinematics(data, omega), exact=exact_response(model, exc, [CrankMechanism(tuple(throws), (0.0, 0.0, 0.0))], G))


def test_mean_mass_matrix_and_natural_frequencies_by_brute_force(case):
    """M̄ to 1e-10 of its largest entry (both exact for a trigonometric series of degree < N/2);
    natural frequencies of (K, M̄) by scipy.linalg.eigh on the test's M̄ to 1e-6 relative."""
    model, kin = case["model"], case["kin"]
    M_fixed = block_model([BLOCK["mass"], MACHINE["mass"]], [BLOCK["cog"], MACHINE["cog"]],
                          [BLOCK["inertia"], MACHINE["inertia"]], SPRINGS, G, 7.2).M
    M_mech = _mean_mass_matrix(kin)
    assert np.abs(model.M - M_fixed - M_mech).max() <= 1e-10 * np.abs(M_mech).max()
    # K: the springs and the weight of the mean positions W z̄_G about x and y, assembled here
    z_mean = (BLOCK["mass"] * BLOCK["cog"][2] + MACHINE["mass"] * MACHINE["cog"][2]
              + np.sum(kin.m[:, None] * kin.samples[..., 2]) / SAMPLES)
    K = np.diag(SPRINGS) - np.diag([0, 0, 0, G * z_mean, G * z_mean, 0])
    p = np.sqrt(scipy.linalg.eigh(K, M_fixed + M_mech, eigvals_only=True))
    assert block_modes(model).frequencies == pytest.approx(p, rel=1e-6)


def _shooting(case):
    """The T-periodic solution of the test's linear equations: fundamental matrix and a particular
    solution over one period (the test's equations at 1024 phases, between them by their Fourier
    series; DOP853, rtol 1e-10), then (I - Φ) y0 = y_p(T); harmonics 1 ... 8 of q
    from 64 samples of the periodic solution (exact for a series of degree < 32; the solution's
    harmonics above 8 are below 1e-9 of its largest)."""
    model, kin, omega = case["model"], case["kin"], case["omega"]
    M_f = model.M - _mean_mass_matrix(kin)  # the block's and the machine's fixed parts
    K_f = np.diag(SPRINGS) - np.diag([0, 0, 0, 1, 1, 0]) * G * (BLOCK["mass"] * BLOCK["cog"][2] + MACHINE["mass"] * MACHINE["cog"][2])
    C = model.C

    series = [Series(x, omega) for x in _linear_equations(kin)]

    def rhs(t, y):
        Mm, D, S, f = (x(t) for x in series)
        Y = y.reshape(12, -1)
        q, dq = Y[:6], Y[6:]
        force = -(D + C) @ dq - (S + K_f) @ q
        force[:, -1] += f
        return np.vstack([dq, np.linalg.solve(M_f + Mm, force)]).ravel()

    T = 2 * np.pi / omega
    y0 = np.hstack([np.eye(12), np.zeros((12, 1))]).ravel()  # columns: the 12 free solutions, then the forced one
    end = solve_ivp(rhs, (0, T), y0, method="DOP853", rtol=1e-10, atol=1e-14).y[:, -1].reshape(12, 13)
    Phi, particular = end[:, :12], end[:, 12]
    start = np.linalg.solve(np.eye(12) - Phi, particular)  # one forced column: the periodic solution
    times = np.arange(64) * T / 64
    q = solve_ivp(rhs, (0, T), start, method="DOP853", rtol=1e-10, atol=1e-14, t_eval=times).y[:6]
    return 2.0 * np.fft.rfft(q, axis=1)[:, 1:9].T / 64  # Z_n, n = 1 ... 8, as Re(Z_n e^{inωt})


@pytest.fixture(scope="module")
def shot(case):
    return _shooting(case)


def test_exact_periodic_solution_against_shooting(case, shot):
    """Harmonics 1-8 of the six coordinates to 1e-5 of each coordinate's largest (measured: 2e-6 at
    worst, the shooting's own accuracy: DOP853 at rtol 1e-10 over a period, amplified by the
    conditioning of I - Φ); a coordinate the throws balance out (below 1e-9 of the largest
    displacement: round-off both ways) is skipped."""
    Z = case["exact"].Z[:8]
    largest = np.abs(shot[:, :3]).max()
    for j in range(6):
        scale = np.abs(shot[:, j]).max()
        if scale > 1e-9 * largest:
            assert np.abs(Z[:, j] - shot[:, j]).max() <= 1e-5 * scale, (case["name"], j)


POINTS = np.array([[3.0, 2.0, 2.0], [-3.0, -2.0, 0.0], [0.0, 0.4, 3.0]])


def test_point_amplitudes_and_first_approximation_error(case, shot):
    """Peaks of the points' displacements within 0.5 % of the shooting's (they agree to 1e-6); the
    first approximation's peaks within the error fcalc reports for it."""
    model, exc, exact = case["model"], case["exc"], case["exact"]
    T = point_maps(np.vstack([model.cog, POINTS]))
    first = complex_amplitudes(model, exc)
    found = first_approximation_error("compressor", first, exc, exact, T)
    from foundation_calc.solvers.block.response import series_peak

    reference = series_peak(np.einsum("pij,hj->pih", T, shot), np.arange(1, 9))
    big = reference > 1e-6 * reference.max()
    assert found.exact_peak[big] == pytest.approx(reference[big], rel=5e-3)
    assert np.abs(found.exact_peak - reference)[big].max() <= 1e-6 * reference.max()
    shown = reference > 1e-9 * reference.max()
    assert (np.abs(found.first_peak - reference)[shown] <= found.error * reference[shown] * (1 + 1e-3) + 1e-7 * reference.max()).all()
    assert 0.0 < found.error < 0.05


def test_opposed_pair_cancels_first_order_forces_and_keeps_a_couple():
    """Balanced-opposed pair (slider axes ±x, both crank angles 0): the forces of every order
    cancel to round-off (the throws mirror each other in x and z); the couples of the first order
    remain, by hand: along x each throw's rod centre of mass and slider move by r cos φ plus even
    harmonics (cos ψ), so the x forces (m + m1) r ω² at y = ±0.25 m turn about z; across, the rod's
    centre of mass moves by r (l''/l) sin φ (the slider not at all), so m (l''/l) r ω² turn about x."""
    throws = _fcalc_throws(OPPOSED)
    omega = 500 * RPM
    fh = forcing_harmonics(throws, omega, G)
    Q = fh.inertial + fh.weight
    single = forcing_harmonics(throws[:1], omega, G)
    assert np.abs(Q[:, :3]).max() <= 1e-12 * np.abs(single.inertial[:, :3]).max()
    d = OPPOSED[0]
    arm = 0.5
    assert abs(Q[0, 5]) == pytest.approx((d["m"] + d["m1"]) * d["r"] * omega**2 * arm, rel=1e-9)
    assert abs(Q[0, 3]) == pytest.approx(d["m"] * (d["l"] - d["l1"]) / d["l"] * d["r"] * omega**2 * arm, rel=1e-9)


# --- one throw in the x-z plane against the crank foundation's plane model --------------------------

PLANE_CONFIGS = ["configs/frame_saw.toml", "configs/vertical_compressor.toml", "configs/crank_press.toml"]


def _plane_design(config):
    from pathlib import Path

    from foundation_calc.scenes.loading import load_scene

    root = Path(__file__).resolve().parents[1]
    return load_scene(root / config)


def _plane_throw(scene, height):
    """The crank scene's throw: crank axis A a distance a above C (here ``height`` + a above the
    reference point), guide downward from A towards C, φ from the downward vertical: the slider
    axis is -z, and the pin's sideways motion -r sin φ along x makes the shaft axis +y."""
    d, m = scene.design(), scene.mechanism
    return crank_throw([0.0, 0.0, height + d.a], [0, 1, 0], [0, 0, -1], 0.0, d.r, d.l, m.rod_mass,
                       m.rod_cog_to_crank_pin, m.rod_radius_of_gyration, m.slider_mass)


PLANE = [0, 2, 4]  # the crank model's (x, y, θ) are (u_x, -u_z, θ_y) of the block's coordinates
SIGN = np.array([1.0, -1.0, 1.0])


@pytest.mark.parametrize("config", PLANE_CONFIGS)
def test_plane_throw_operator_matches_crank_equations(config):
    """Eqs. (1)-(4) of crank_mechanism about C against the crank foundation's exact equations
    (solvers.crank.dynamics, derived by Lagrange and checked with sympy) linearised by complex
    step, mechanism only (no block, no soil; its M_tot x'' then lacks the moving mass m, added
    here), at 64 phases: to 1e-9 of each matrix's largest entry."""
    from dataclasses import replace

    from foundation_calc.solvers.crank.averaged import linearise
    from foundation_calc.solvers.numerics.trig_series import phases

    scene = _plane_design(config)
    d = scene.design()
    bare = replace(d, M=-d.rod.m, I_c=0.0, c=0.0, c1=0.0, c_phi=0.0, C_x=0.0, C_z=0.0, C_phi=0.0)
    lin = linearise(bare, phases(64))
    lin.mass[[0, 1], [0, 1]] += d.rod.m
    ours = mechanism_samples([_plane_throw(scene, 0.0)], d.omega, d.g, 64)
    flip = SIGN[:, None] * SIGN[None, :]
    for theirs, mine in ((lin.mass, ours.M), (lin.damping, ours.D), (lin.stiffness, ours.S)):
        mine = mine[:, PLANE][:, :, PLANE] * flip
        assert np.abs(mine - np.moveaxis(theirs, -1, 0)).max() <= 1e-9 * np.abs(mine).max()
    f = (ours.f_inertia + ours.f_weight)[:, PLANE] * SIGN
    assert np.abs(f - lin.forcing.T).max() <= 1e-9 * np.abs(f).max()


def _plane_block(scene):
    """The crank scene's block as a 6-DOF block about O (the base's centre): springs c1 S, c S,
    c_φ I1 in x, z, about y; the out-of-plane springs and moments of inertia only keep it stable
    (the plane motion does not reach them)."""
    d = scene.design()
    throw = _plane_throw(scene, d.h)
    m, cog, J = mean_mass_properties([throw])
    springs = np.array([d.c1 * d.S, 1e9, d.c * d.S, 1e11, d.c_phi * d.I1, 1e11])
    model = block_model([d.M, m], [[0.0, 0.0, d.h], cog], [[1e6, d.I_c, 1e6], J], springs, d.g, 10.0)
    fh = forcing_harmonics([throw], d.omega, d.g)
    return d, throw, model, fh.orders, fh.inertial + fh.weight


@pytest.mark.parametrize("config", PLANE_CONFIGS)
def test_plane_throw_first_approximation_matches_crank_averaged_operator(config):
    """Natural frequencies and every harmonic of x, y, θ of C by the block's first approximation
    against the crank scene's averaged operator (solvers.crank.averaged), to 1e-9: the models
    coincide there (the mean mass matrices are one congruence apart, the forcing is the same)."""
    from foundation_calc.solvers.crank.averaged import averaged_response
    from foundation_calc.solvers.rigid_body.harmonic import harmonic_response

    d, _, model, orders, Q = _plane_block(_plane_design(config))
    theirs = averaged_response(d)
    p = block_modes(model).frequencies
    in_plane = [np.argmin(np.abs(p - x)) for x in theirs.natural]
    assert p[in_plane] == pytest.approx(theirs.natural, rel=1e-9)
    Z = harmonic_response(model.K, model.C, model.M, Q, orders * d.omega)
    at_C = (point_maps(np.array([[0.0, 0.0, d.h]]))[0] @ Z.T)  # (3, H)
    mine = np.array([at_C[0], -at_C[2], Z[:, 4]])
    H = len(orders)
    ref = theirs.motion.cos[:, 1:H + 1] - 1j * theirs.motion.sin[:, 1:H + 1]
    assert (np.abs(mine - ref).max(axis=1) <= 1e-9 * np.abs(ref).max(axis=1)).all()


def test_periodic_solver_reproduces_the_crank_exact_solution():
    """rigid_body.periodic on the crank foundation's own equations linearised in q (complex step)
    against its exact nonlinear periodic solution (solvers.crank.exact, Newton harmonic balance):
    to 1e-7 of each coordinate's largest harmonic (measured 5e-9: the nonlinear terms, of the
    order of μ θ)."""
    from foundation_calc.solvers.crank.averaged import averaged_operator, linearise
    from foundation_calc.solvers.crank.exact import exact_periodic_solution
    from foundation_calc.solvers.machines.crank_mechanism import harmonics
    from foundation_calc.solvers.numerics.trig_series import phases
    from foundation_calc.solvers.rigid_body.periodic import periodic_solution

    d = _plane_design("configs/frame_saw.toml").design()
    M, C, K, *_ = averaged_operator(d)

    def periodic(N):
        lin = linearise(d, phases(N))
        return tuple(np.moveaxis(a, -1, 0) - b for a, b in ((lin.mass, M), (lin.damping, C), (lin.stiffness, K)))

    Q = harmonics(linearise(d, phases(256)).forcing.T)[1:40]
    mine = periodic_solution(d.omega, M, K, C, periodic, Q).Z.T
    exact = exact_periodic_solution(d).motion
    k = 12
    ref = exact.cos[:, 1:k + 1] - 1j * exact.sin[:, 1:k + 1]
    assert (np.abs(mine[:, :k] - ref).max(axis=1) <= 1e-7 * np.abs(ref).max(axis=1)).all()
