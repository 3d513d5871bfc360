"""The block's averaged operator keeps its machines' mean gyroscopic coupling D̄ (the mean over a
revolution of the Coriolis matrix D(ωt) of Eq. (1) of foundation_calc/solvers/rigid_body/periodic.py).

Independent references, written here:

- D̄ of configs/block_two_throw_compressor.toml from the mechanism's kinematics written here (crank
  pin, slider and rod of each throw as the scene's keys describe them; the rod a rigid body of
  radius of gyration ρ about its centre of mass, the crank web's rotating mass a point): the moving
  parts' angular momentum about O relative to the block, h(t) = Σ m r × r' + m ρ² e × e', by central
  differences in time, averaged over a revolution. A body carrying an angular momentum h turns by
  Euler's equation J θ'' + θ' × h = moment, so D̄ = -[h̄]× in the rotations (0 in the translations:
  r' has no mean). Central differences of step δ = 1e-6 of a revolution: truncation δ² ~ 1e-12,
  round-off 1e-16/δ ~ 1e-10 relative; compared to 1e-7.
- The first approximation by a harmonic solve written here, (K - Ω² M + iΩ(C_0 + D̄)) Z = Q_n at
  Ω = nω, C_0 the scene's dashpots: to 1e-10 of the largest amplitude, far below the 3e-8 that D̄
  changes (a first approximation without D̄ fails), at the speed, at swept speeds (D̄ grows as the
  speed) and on a frequency-dependent soil (D̄ stays beside the soil's dashpots).
- The exact periodic solution with D(φ) whole by the harmonic balance called here with the
  scene's dashpots alone (no double count of D̄), and the first approximation's error in the motion
  D̄ causes against it.
"""

from __future__ import annotations

import copy
from dataclasses import replace
from pathlib import Path

import numpy as np
import pytest

from foundation_calc.scenes import parse_scene
from foundation_calc.solvers.block.response import complex_amplitudes
from foundation_calc.solvers.constants import GRAVITY
from tests.conftest import read_toml

ROOT = Path(__file__).resolve().parents[1]
TWO_THROW = ROOT / "configs" / "block_two_throw_compressor.toml"


def _unit(v) -> np.ndarray:
    v = np.asarray(v, dtype=float)
    return v / np.linalg.norm(v)


def _angular_momentum(throw: dict, omega: float, t: np.ndarray) -> np.ndarray:
    """h(t) (N, 3) [N m s] of one [[machines.cranks]] table's moving parts about O, turning at ω."""
    A, n = np.asarray(throw["crank_centre"], dtype=float), _unit(throw["shaft_axis"])
    s = _unit(throw["slider_axis"])
    tt = np.cross(n, s)
    r, l, m = throw["crank_radius"], throw["rod_length"], throw["rod_mass"]
    l1, rho, m1 = throw["rod_cog_to_crank_pin"], throw["rod_radius_of_gyration"], throw["slider_mass"]
    m_r, r_r, beta = throw.get("rotating_mass", 0.0), throw.get("rotating_radius", 0.0), throw.get("rotating_angle", 0.0)

    def parts(time):
        f = omega * time + throw["crank_angle"]  # the crank's angle from its top dead centre
        pin = A + np.outer(r * np.cos(f), s) + np.outer(r * np.sin(f), tt)
        slider = A + np.outer(r * np.cos(f) + l * np.sqrt(1.0 - (r / l * np.sin(f)) ** 2), s)
        e = (slider - pin) / l
        rotating = A + np.outer(r_r * np.cos(f + beta), s) + np.outer(r_r * np.sin(f + beta), tt)
        return pin + l1 * e, e, slider, rotating

    dt = 1e-6 * 2.0 * np.pi / omega
    now, ahead, behind = parts(t), parts(t + dt), parts(t - dt)
    rate = [(a - b) / (2.0 * dt) for a, b in zip(ahead, behind)]
    (c1, e, slider, rotating), (v1, de, vs, vr) = now, rate
    return (m * np.cross(c1, v1) + m * rho**2 * np.cross(e, de) + m1 * np.cross(slider, vs)
            + m_r * np.cross(rotating, vr))


def _gyroscopic(data: dict, omega: float) -> np.ndarray:
    """D̄ (6, 6) of the scene's first machine at speed ω (module docstring)."""
    t = np.arange(720) * (2.0 * np.pi / omega) / 720
    h = sum(_angular_momentum(throw, omega, t) for throw in data["machines"][0]["cranks"]).mean(axis=0)
    D = np.zeros((6, 6))
    D[3:, 3:] = -np.array([[0.0, -h[2], h[1]], [h[2], 0.0, -h[0]], [-h[1], h[0], 0.0]])
    return D


def _solve(K, C, M, Q, Omega) -> np.ndarray:
    return np.array([np.linalg.solve(K_n - w * w * M + 1j * w * C_n, q) for K_n, C_n, q, w in zip(K, C, Q, Omega)])


@pytest.fixture(scope="module")
def two_throw() -> dict:
    return read_toml(TWO_THROW)


@pytest.fixture(scope="module")
def scene(two_throw):
    return parse_scene(copy.deepcopy(two_throw))


def test_the_two_throw_crankshafts_mean_gyroscopic_coupling_is_its_angular_momentums(two_throw, scene):
    """±85.27 N m s between θ_x and θ_z: the crankshaft along y carries h̄ = 85.27 N m s along y."""
    omega = scene.machines[0].omega_rad_s
    expected = _gyroscopic(two_throw, omega)
    assert expected[3, 5] == pytest.approx(-85.27, abs=0.01) and expected[5, 3] == pytest.approx(85.27, abs=0.01)
    np.testing.assert_allclose(scene.model().gyroscopic, expected, rtol=0, atol=1e-7 * np.abs(expected).max())
    np.testing.assert_allclose(scene.excitations()[0].gyroscopic, expected, rtol=0, atol=1e-7 * np.abs(expected).max())


@pytest.mark.parametrize("ratio", [1.0, 0.5, 1.7])
def test_the_first_approximation_solves_with_the_mean_gyroscopic_coupling_at_the_speed(two_throw, scene, ratio):
    """At the machine's speed and along a speed sweep (D̄ ∝ ω): the first approximation is the
    harmonic solve written here with C_0 + D̄(ω') to 1e-10 of its largest amplitude; without D̄ it
    differs by 3e-8 of it."""
    model, exc = scene.model(), scene.excitations()[0]
    speed = ratio * exc.omega
    C = np.diag(two_throw["soil"]["dashpot"]) + _gyroscopic(two_throw, speed)
    Omega = speed * exc.orders
    H = len(Omega)
    expected = _solve([model.K] * H, [C] * H, model.M, exc.loads_at(speed), Omega)
    found = complex_amplitudes(model, exc) if ratio == 1.0 else complex_amplitudes(model, exc, np.array([speed]))[0]
    np.testing.assert_allclose(found, expected, rtol=0, atol=1e-10 * np.abs(expected).max())


def test_on_a_frequency_dependent_soil_the_coupling_stays_beside_the_soils_dashpots(two_throw):
    """Gazetas' impedance replaces the springs and dashpots order by order; D̄ is the machine's and stays."""
    data = copy.deepcopy(two_throw)
    data["soil"] = {"method": "gazetas", "shear_modulus": 1.2e8, "poisson": 0.3, "density": 2000.0}
    scene = parse_scene(data)
    model, exc = scene.model(), scene.excitations()[0]
    Omega = exc.omega * exc.orders
    springs, dashpots = scene.soil_impedance(Omega)[:2]
    K = [model.K + np.diag(k - model.springs) for k in springs]
    C = [np.diag(c) + _gyroscopic(two_throw, exc.omega) for c in dashpots]
    expected = _solve(K, C, model.M, exc.Q, Omega)
    found = complex_amplitudes(model, exc, impedance=scene.soil_impedance)
    np.testing.assert_allclose(found, expected, rtol=0, atol=1e-10 * np.abs(expected).max())


def _periodic(parts, omega, centred_D):
    """N -> (M - M̄, D or D - D̄, S - S̄) of ``parts`` at ω (the harmonic balance's input)."""
    def periodic(N):
        M, D, S = (sum(x) for x in zip(*(p.periodic_inertia(omega, GRAVITY, N) for p in parts)))
        return M - M.mean(axis=0), D - D.mean(axis=0) if centred_D else D, S - S.mean(axis=0)

    return periodic


def test_the_exact_solution_counts_the_coupling_once_and_the_first_approximation_gives_its_motion(two_throw, scene):
    """The exact periodic solution of the block (C with D̄, D(φ) less D̄) is the harmonic balance
    run here with the dashpots C_0 alone and D(φ) whole, to 1e-9 of its largest harmonic.

    What D̄ does to the exact solution, E = exact(C_0, D whole) - exact(C_0, D less D̄), 3e-8 of the
    largest amplitude: the first approximation without D̄ misses all of it (error 1); with D̄ its
    change, first(C_0 + D̄) - first(C_0), is E to 1.1e-3 (measured; the rest is D̄ acting with the
    mechanism's periodic inertia, second order). Tolerance 1e-2. (The peaks' largest error against the
    exact solution, the check's measure, is set by the other periodic terms: 1.43965e-4 without D̄,
    1.44004e-4 with; D̄'s motion is 1e-3 of that error.)"""
    from foundation_calc.solvers.block.periodic_inertia import dense_loads, exact_response
    from foundation_calc.solvers.rigid_body.periodic import periodic_solution

    model, exc, parts = scene.model(), scene.excitations()[0], scene.machines[0].periodic_parts
    C0 = np.diag(two_throw["soil"]["dashpot"])
    whole = periodic_solution(exc.omega, model.M, model.K, C0, _periodic(parts, exc.omega, False), dense_loads(exc))
    exact = exact_response(model, exc, parts, GRAVITY)
    assert np.abs(exact.Z - whole.Z).max() <= 1e-9 * np.abs(whole.Z).max()

    without = periodic_solution(exc.omega, model.M, model.K, C0, _periodic(parts, exc.omega, True), dense_loads(exc))
    H = len(exc.orders)
    E = whole.Z[:H] - without.Z[:H]
    assert 1e-8 < np.abs(E).max() / np.abs(whole.Z).max() < 1e-7
    first = complex_amplitudes(model, exc)
    first_without = _solve([model.K] * H, [C0] * H, model.M, exc.Q, exc.omega * exc.orders)
    assert np.abs(first - first_without - E).max() <= 1e-2 * np.abs(E).max()


def test_the_coupling_dissipates_nothing():
    """A skew-symmetric C alone leaves a block undamped: no damping ratio, and the run-up warns of
    an undamped structure."""
    from foundation_calc.solvers.block.model import block_model
    from foundation_calc.solvers.block.response import block_modes
    from foundation_calc.solvers.numerics.runup import Structure

    D = np.zeros((6, 6))
    D[3, 5], D[5, 3] = -85.0, 85.0
    model = block_model([1e5], [[0.0, 0.0, 1.0]], [[1e5, 2e5, 3e5]], [1e9, 1e9, 2e9, 1e10, 2e10, 3e10], GRAVITY, 7.0,
                        gyroscopic=D)
    assert not model.damped and np.all(block_modes(model).damping == 0.0)
    assert model.damped == replace(model, C=model.C - D).damped
    assert not Structure(model.M, model.C, model.K, None, None).damped
