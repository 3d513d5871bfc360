"""The platform's parts on their own: its isolators as a support, each exciter as a machine part.

Independent references, written here and nowhere else:

- the isolators' springs at O as the brute-force sum over the twelve springs of c g gᵀ, g the
  gradient of one spring's elongation δ = e_k · (u + θ × r_i) = e_k · u + θ · (r_i × e_k) (a
  triple product, not the code's point maps); their dashpots against the platform's own complex
  stiffness, iΩ C(Ω) = i (η sgn Ω + β Ω) K;
- the exciter's M(φ), D(φ), S(φ) and forcing by Newton-Euler on the rotor's point mass, carried
  by the body in a prescribed motion q(t) = ε (q0 + q1 τ + q2 τ²/2): its position p = u + R(θ) S(t)
  (R the exact rotation exp([θ]×), S(t) the rotor's path transcribed from the paper's (1.3),
  (1.7)), its acceleration by an 8th-order central difference in t, the force m p'' and the moment
  R S × m p'' about the moving O1 with the weight's moment m g R S × e3, and the part linear in
  ε by a complex step (ε = 1e-30 i: exact to round-off). Tolerance 1e-9 of each matrix's largest
  entry: the difference stencil's truncation at ωh = 0.05 is about (ωh)^8/630 ≈ 6e-14 of the
  acceleration, its round-off about 1e-16/(ωh)² ≈ 4e-14;
- the exciter's mean mass matrix against the average of M(φ) over 64 phases.
"""

from __future__ import annotations

import math

import numpy as np
import pytest
from scipy.linalg import expm

from foundation_calc.solvers.machines.exciter import UnbalancedExciter
from foundation_calc.solvers.platform.dynamics import RigidPlatform, inertia_about_corner, periodic_system, rotor
from foundation_calc.solvers.rigid_body.inertia import mass_matrix, parallel_axis
from foundation_calc.solvers.rigid_body.kinematics import load_at
from foundation_calc.solvers.supports.isolators import Isolators

E3 = np.array([0.0, 0.0, 1.0])
G = 9.81
OMEGA = 157.0

#: Points off a rectangle and off the base plane, so that every coupling of K shows.
POINTS = np.array([[0.0, 0.0, 0.0], [3.0, 0.2, -0.1], [2.8, 2.0, 0.15], [-0.1, 1.9, 0.05]])
STIFFNESS = np.array([[6.2e7, 6.0e7, 1.0e8], [6.1e7, 1.2e8, 1.1e8], [5.0e7, 1.3e8, 0.9e8], [6.5e7, 6.3e7, 1.05e8]])


def _brute_force_springs(points, stiffness) -> np.ndarray:
    K = np.zeros((6, 6))
    for r, springs in zip(points, stiffness):
        for e, c in zip(np.eye(3), springs):
            g = np.concatenate([e, np.cross(r, e)])  # ∂δ/∂(u, θ)
            K += c * np.outer(g, g)
    return K


def test_the_isolators_springs_at_O_are_the_sum_over_the_twelve_springs():
    iso = Isolators(POINTS, STIFFNESS, 0.0, 0.0)
    expected = _brute_force_springs(POINTS, STIFFNESS)
    np.testing.assert_allclose(iso.springs, expected, rtol=0, atol=1e-12 * np.abs(expected).max())
    at = iso.impedance(np.array([0.0, 50.0]))
    assert at.springs.shape == (2, 6) and at.coupling[0].shape == (2, 6, 6)
    np.testing.assert_allclose(at.K[1], expected, rtol=0, atol=1e-12 * np.abs(expected).max())
    assert abs(expected[0, 4]) > 1e6 and abs(expected[1, 5]) > 1e6  # coupled: sway-rocking, sway-torsion


@pytest.mark.parametrize("eta, beta", [(0.02, 0.0), (0.0, 4e-4), (0.03, 2e-4)])
def test_the_isolators_dashpots_are_the_platforms_complex_stiffness(eta, beta):
    """iΩ C(Ω) of the support = the complex part of the platform's dynamic matrix at ±Ω, and the
    dashpots of a hysteretic η fall as 1/|Ω| (C = β K at rest, where a hysteretic force vanishes)."""
    J = inertia_about_corner(2e4, (1.5, 1.0, 0.65), (9.0e3, 1.7e4, 2.2e4))
    platform = RigidPlatform(2e4, (1.5, 1.0, 0.65), J, 3.0, 2.0, STIFFNESS, eta, G, beta)
    system = periodic_system(platform, [rotor(25.0, 0.2, (1.5, 1.0, 2.6), 0.0, 0.0, OMEGA, 0.0)])
    Omega = np.array([-2.0 * OMEGA, -OMEGA, OMEGA, 3.0 * OMEGA])
    undamped = system.stiff[0] + 1j * Omega[:, None, None] * system.gyro[0] - Omega[:, None, None] ** 2 * system.mass[0]
    complex_part = system.dynamic_matrices(Omega) - undamped
    at = platform.isolators.impedance(Omega)
    K = _brute_force_springs(platform.corners, STIFFNESS)
    np.testing.assert_allclose(1j * Omega[:, None, None] * at.C, complex_part, rtol=0, atol=1e-12 * np.abs(complex_part).max())
    hysteretic = K * (1.0 + 1j * eta * np.sign(Omega))[:, None, None] + 1j * Omega[:, None, None] * beta * K
    np.testing.assert_allclose(complex_part, hysteretic - K, rtol=0, atol=1e-12 * np.abs(complex_part).max())
    equivalent = (beta + eta / np.abs(Omega))[:, None, None] * K
    np.testing.assert_allclose(at.C, equivalent, rtol=0, atol=1e-12 * np.abs(equivalent).max())
    np.testing.assert_allclose(platform.isolators.impedance(0.0).C, beta * K, rtol=1e-12, atol=1e-12 * np.abs(K).max())
    assert platform.isolators.frequency_dependent == (eta > 0)


def test_the_isolators_answer_the_support_interface():
    iso = Isolators(POINTS, STIFFNESS, 0.02, 1e-4)
    assert iso.validity().a0_max is None and iso.a0(np.array([10.0]))[0] is None
    assert [a.topic for a in iso.assumptions()] == ["isolators", "base"]
    assert "η = 0.02" in iso.assumptions()[0].text and "β = 0.0001 s" in iso.assumptions()[0].text
    section = iso.soil_section({"exciter": OMEGA})
    assert section.document["isolators"]["stiffness"] == STIFFNESS.tolist()
    grid, text = iso.sheet(None, ())
    np.testing.assert_allclose(grid.values, STIFFNESS * 1e-6)
    assert "η/|Ω|" in text.text


# ---- the exciter: Newton-Euler on the rotor's point mass ----


def _path(part: UnbalancedExciter, omega: float, t):
    """S(t) = ρ + l (t1 cos θ + t2 sin θ), θ = σ ω t + φ0, transcribed from the paper's (1.3), (1.7)."""
    d1, d2 = part.delta1, part.delta2
    t1 = np.array([math.sin(d1), -math.cos(d1), 0.0])
    t2 = np.array([math.cos(d1) * math.cos(d2), math.sin(d1) * math.cos(d2), -math.sin(d2)])
    theta = part.sense * omega * t + part.phi0
    return np.asarray(part.rho) + part.l * (t1 * np.cos(theta) + t2 * np.sin(theta))


#: 8th-order central difference of a second derivative: weights of f(t + k h), k = -4..4.
D2 = np.array([-1 / 560, 8 / 315, -1 / 5, 8 / 5, -205 / 72, 8 / 5, -1 / 5, 8 / 315, -1 / 560])


def _newton_euler(part, omega, t0, q0, q1, q2, eps):
    """The rotor's force and moment about the moving O1 on the body, (m p'', R S × m p'' + m g R S × e3),
    at t0 with the body in the motion q(t) = eps (q0 + q1 τ + q2 τ²/2), τ = t - t0."""
    h = 0.05 / omega
    positions = []
    for k in range(-4, 5):
        tau = k * h
        q = eps * (q0 + q1 * tau + 0.5 * q2 * tau * tau)
        th = q[3:]
        R = expm(np.array([[0, -th[2], th[1]], [th[2], 0, -th[0]], [-th[1], th[0], 0]]))
        positions.append(q[:3] + R @ _path(part, omega, t0 + tau))
    a = np.tensordot(D2, np.array(positions), axes=1) / (h * h)
    th = eps * q0[3:]
    R = expm(np.array([[0, -th[2], th[1]], [th[2], 0, -th[0]], [-th[1], th[0], 0]]))
    arm = R @ _path(part, omega, t0)
    return np.concatenate([part.m * a, part.m * np.cross(arm, a) + part.m * G * np.cross(arm, E3)])


def _linear_part(part, omega, t0, q0, q1, q2):
    eps = 1e-30j
    return (_newton_euler(part, omega, t0, q0, q1, q2, eps) / eps).real  # complex step: Im(E(iε))/ε


PARTS = [
    UnbalancedExciter(6.0, 0.1, (2.0, 0.5, 0.3), 0.4, 1.2, 0.7, 1.0),
    UnbalancedExciter(6.0, 0.1, (2.0, 0.5, 0.3), 0.4, 1.2, -0.7, -1.0),
    UnbalancedExciter(25.0, 0.2, (0.3, -0.4, 2.6), 0.0, 0.0, 0.0, 1.0),
]


@pytest.mark.parametrize("part", PARTS, ids=["tilted", "tilted-counter", "vertical"])
def test_the_exciters_periodic_inertia_is_newton_euler_of_its_point_mass(part):
    N, at = 8, (0, 1, 3, 6)
    M, D, S = part.periodic_inertia(OMEGA, G, N)
    zero = np.zeros(6)
    # the model's weight tilt keeps -g m c on θx, θy of the mean position and leaves out its
    # off-diagonal terms g m a, g m b about z (as the block's weight tilt does): put them back
    mean_weight = np.zeros((6, 6))
    mean_weight[3:5, 5] = G * part.m * np.asarray(part.rho)[:2]
    for j in at:
        t0 = 2.0 * math.pi * j / N / OMEGA
        columns = [[_linear_part(part, OMEGA, t0, *(e if k == which else zero for k in range(3))) for e in np.eye(6)]
                   for which in (2, 1, 0)]  # q'' -> M, q' -> D, q -> S
        for mine, theirs in zip((M[j], D[j], S[j] + mean_weight), columns):
            theirs = np.array(theirs).T
            np.testing.assert_allclose(mine, theirs, rtol=0, atol=1e-9 * np.abs(theirs).max())


@pytest.mark.parametrize("part", PARTS, ids=["tilted", "tilted-counter", "vertical"])
def test_the_exciters_forcing_is_newton_euler_on_a_body_at_rest(part):
    """The load rows carried to O are minus the rotor's force and moment on a body at rest (its
    static weight m g ρ × e3 aside, the static load); the force grows as ω², the weight's moment not."""
    rows = part.load_rows(OMEGA, G)
    assert len(rows) == 4 and [r.inertial for r in rows] == [True, True, False, False]
    for phi in (0.0, 0.9, 2.5, 4.0):
        Q = sum(load_at(r.at, np.array(r.force) * math.cos(phi + r.phase), np.array(r.moment) * math.cos(phi + r.phase))
                for r in rows)
        E0 = _newton_euler(part, OMEGA, phi / OMEGA, np.zeros(6), np.zeros(6), np.zeros(6), 0.0)
        static = np.concatenate([np.zeros(3), part.m * G * np.cross(part.rho, E3)])
        np.testing.assert_allclose(Q, -(E0 - static), rtol=0, atol=1e-9 * np.abs(E0).max())
    faster = part.load_rows(2.0 * OMEGA, G)
    for slow, fast in zip(rows, faster):
        scale = 4.0 if slow.inertial else 1.0
        np.testing.assert_allclose(fast.force, scale * np.array(slow.force), rtol=1e-14)
        np.testing.assert_allclose(fast.moment, np.array(slow.moment), rtol=1e-14)


@pytest.mark.parametrize("part", PARTS, ids=["tilted", "tilted-counter", "vertical"])
def test_the_exciters_mean_mass_is_the_average_of_its_periodic_mass(part):
    m, cog, J = part.mass_properties()
    mine = mass_matrix(m, cog, parallel_axis(m, cog, J))
    average = part.periodic_inertia(OMEGA, G, 64)[0].mean(axis=0)
    np.testing.assert_allclose(mine, average, rtol=0, atol=1e-12 * np.abs(average).max())
    assert part.carried_inertia(OMEGA) == pytest.approx(part.m * part.l**2, rel=1e-15)


def test_the_platform_sheet_states_its_isolators_assumptions():
    """The sheet's assumptions are the support's: a loss factor and dashpots named with their values."""
    from foundation_calc.output.report.assumptions import assumptions_section
    from foundation_calc.scenes import load_scene

    scene = load_scene("configs/platform_damped.toml")
    scene = scene.model_copy(update={"isolators": scene.isolators.model_copy(update={"damping_ratio": 0.02})})
    rows = dict(assumptions_section(scene, []).blocks[0].rows)
    assert "η = 0.005" in rows["isolators"] and "dashpots β c_ij" in rows["isolators"]
    assert "coupled" in rows["base"] and "corner O1" in rows["base"]


# ---- the exciter on a block: one module, no edit across checks/ or output/ ----

BLOCK = (6.0, 4.0, 2.0, 2400.0)  # L, B, H [m], density [kg/m³]
SPRINGS = np.array([6.0e9, 5.5e9, 8.0e9, 4.0e10, 7.0e10, 5.0e10])
DASHPOTS = np.array([1.5e7, 1.5e7, 2.5e7, 3.0e7, 5.0e7, 2.0e7])
EXCITER = UnbalancedExciter(40.0, 0.15, (0.5, 0.3, 2.4), 0.3, 1.1, 0.4, -1.0)


def _with_exciter(machine) -> list:
    """The builder a scene key would register: the machine named "vibrator" carries EXCITER."""
    return [EXCITER] if machine.name == "vibrator" else []


def _direct_block(omega):
    """Complex amplitude of q at ω from (K - ω² M + iω (C + D̄)) Z = Q, written out: the block, the
    machine's frame and the rotor as a ring m l²/2 (I + e eᵀ) about ρ; the rotating force
    m ω² L and the weight's moment -g m L × e3 of L = l (t1 cos θ + t2 sin θ), θ = σωt + φ0,
    as Re(Q e^{iωt}); the rotor's angular momentum relative to the block, h = σ ω m l² e, as the
    gyroscopic coupling D̄ = -[h]× of the rotations (Euler's J θ'' + θ' × h)."""
    L_, B_, H_, rho = BLOCK
    m_b = L_ * B_ * H_ * rho
    p = EXCITER
    t1 = np.array([math.sin(p.delta1), -math.cos(p.delta1), 0.0])
    t2 = np.array([math.cos(p.delta1) * math.cos(p.delta2), math.sin(p.delta1) * math.cos(p.delta2), -math.sin(p.delta2)])
    e = np.cross(t1, t2)
    bodies = [(m_b, (0.0, 0.0, H_ / 2.0), np.diag([B_**2 + H_**2, L_**2 + H_**2, L_**2 + B_**2]) * m_b / 12.0),
              (5.0e3, (0.5, 0.2, 2.5), np.diag([1.0e3, 2.0e3, 2.0e3])),
              (p.m, p.rho, 0.5 * p.m * p.l**2 * (np.eye(3) + np.outer(e, e)))]
    M = sum(mass_matrix(m, np.array(r), parallel_axis(m, np.array(r), J)) for m, r, J in bodies)
    z_G = sum(m * r[2] for m, r, _ in bodies) / M[0, 0]
    K = np.diag(SPRINGS).astype(float)
    K[3, 3] -= M[0, 0] * G * z_G
    K[4, 4] -= M[0, 0] * G * z_G
    # cos θ = Re(e^{iσ(ωt)} e^{iφ0}), sin θ = Re(-i e^{iσ ωt} e^{iφ0}); σ = -1 turns the phasor's conjugate
    phasor = p.l * (t1 - 1j * t2) * np.exp(1j * p.phi0)
    L_hat = phasor if p.sense > 0 else phasor.conj()
    F, Mw = p.m * omega**2 * L_hat, -G * p.m * np.cross(L_hat, E3)
    Q = np.concatenate([F, Mw + np.cross(p.rho, F)])
    h = p.sense * omega * p.m * p.l**2 * e
    C = np.diag(DASHPOTS).astype(float)
    C[3:, 3:] -= np.array([[0.0, -h[2], h[1]], [h[2], 0.0, -h[0]], [-h[1], h[0], 0.0]])
    return np.linalg.solve(K - omega**2 * M + 1j * omega * C, Q), M


def test_an_exciter_part_on_a_block_runs_through_the_machine_interface(monkeypatch, tmp_path):
    import foundation_calc as fc
    from foundation_calc.scenes import block_parts

    monkeypatch.setattr(block_parts, "MACHINE_PARTS", [*block_parts.MACHINE_PARTS, _with_exciter])
    L_, B_, H_, rho = BLOCK
    path = tmp_path / "vibrator.toml"
    path.write_text(f"""kind = "block_foundation"
name = "exciter on a block"
[block]
length = {L_}
width = {B_}
height = {H_}
density = {rho}
[[machines]]
name = "vibrator"
mass = 5.0e3
cog = [0.5, 0.2, 2.5]
inertia = [1.0e3, 2.0e3, 2.0e3]
speed_rpm = 1450.0
[soil]
method = "springs"
stiffness = {SPRINGS.tolist()}
dashpot = {DASHPOTS.tolist()}
[[points]]
name = "corner"
at = [3.0, 2.0, 2.0]
""", encoding="utf-8")
    omega = 1450.0 * 2.0 * math.pi / 60.0
    Z, M = _direct_block(omega)
    found = fc.amplitudes(path).to_dict()
    assert found["total_mass"] == pytest.approx(M[0, 0], rel=1e-12)
    peak = np.abs(Z[:3] + np.cross(Z[3:], [3.0, 2.0, 2.0]))
    assert [found["points"]["corner"]["displacement_peak"][d] for d in "xyz"] == pytest.approx(peak, rel=1e-8)
    (periodic,) = found["periodic_inertia"]  # the rotor's angle-dependent inertia, by the exact periodic solution
    assert periodic["machine"] == "vibrator" and periodic["first_approximation_error"] < 1e-3
