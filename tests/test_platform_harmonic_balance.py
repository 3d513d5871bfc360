"""Harmonic balance of the platform: against time integration from rest, convergence in the
truncation order, resonances (damped: answered; undamped and exact: named), lack of restraint,
and the scenes that a Neumann series could not answer."""

from __future__ import annotations

import json
import math
from dataclasses import replace

import numpy as np
import pytest
from scipy.optimize import brentq
from typer.testing import CliRunner

from foundation_calc.cli.app import app
from foundation_calc.errors import PhysicsError
from foundation_calc.scenes import parse_scene
from foundation_calc.solvers.platform.dynamics import (
    RigidPlatform,
    block_inertia,
    inertia_about_corner,
    natural_frequencies,
    periodic_system,
    rotor,
)
from foundation_calc.solvers.platform.harmonic_balance import VARIANT_TOL, VariantBasis, steady_state, steady_state_near
from foundation_calc.solvers.platform.verification import build
from tests.platform_linear_time import harmonic_history, integrate_from_rest

W = 50 * math.pi
runner = CliRunner()


def scene(inertia, extras=(), damping_ratio=0.08, rotor_mass=100.0):
    """A platform designed "below" resonance (every mode above 0.9 ω, so that stiffness-proportional
    dashpots damp every mode and a start from rest settles within ~35 periods)."""
    data = {
        "kind": "platform",
        "platform": {"mass": 2e4, "length": 3.0, "width": 2.0, "cog": [1.5, 1.0, 0.65], "inertia": list(inertia)},
        "exciter": {"rotor_mass": rotor_mass, "eccentricity": 0.2, "position": [0.0, 0.0]},
        "operation": {"omega": W, "amplitude": 1e-3, "regime": "below"},
        "isolators": {"vertical_reference": 1.6e8, "damping_ratio": damping_ratio},
        "extra_exciters": list(extras),
    }
    loaded = parse_scene(data, source="test", expect="platform")
    return build(loaded.design(), loaded.model())


def tuned(inertia_index, mode, target, extras=()):
    """Inertia with the natural frequency of ``mode`` (a coordinate name) at ``target`` rad/s."""

    def miss(J):
        inertia = [9e3, 1.7e4, 2.2e4]
        inertia[inertia_index] = J
        m = natural_frequencies(*scene(inertia, extras))
        return m.frequencies[m.dominant.index(mode)] - target

    inertia = [9e3, 1.7e4, 2.2e4]
    inertia[inertia_index] = brentq(miss, 3e3, 6e4, xtol=1e-6)
    return inertia


# Transients decay as exp(-D p²/ω t) with p >= 147 rad/s: after 36 periods below 1e-7 of the response;
# DOP853 at rtol 1e-10 adds ~1e-9. So 1e-6 of the largest displacement is a strict but safe bound.
TIME_TOL = 1e-6


def _compare_with_integration(platform, rotors, window_periods):
    state = steady_state(platform, rotors)
    T = 2 * math.pi / W
    t = np.linspace(36 * T - window_periods * T, 36 * T, 301)
    d = integrate_from_rest(platform, rotors, np.concatenate([[0.0], t]))[:, 1:]
    h = harmonic_history(state, t)
    scale = np.max(np.abs(h[:3]))
    np.testing.assert_allclose(d[:3], h[:3], atol=TIME_TOL * scale, rtol=0)
    np.testing.assert_allclose(d[3:], h[3:], atol=TIME_TOL * scale / 3.6, rtol=0)  # rotations × diagonal
    return state, h


def test_one_rotor_near_its_2w_resonance_matches_time_integration():
    # the yaw mode 1.5 % above 2ω: the 2ω harmonic is amplified; nothing else is near
    inertia = tuned(2, "gamma", 2 * W * 1.015)
    platform, rotors = scene(inertia)
    state, h = _compare_with_integration(platform, rotors, 1)
    k = np.argmin(np.abs(state.omega - 2 * W))
    # the 2ω part is 6e-4 of the rotations: the 1e-6 comparison checks it to better than 1 %
    assert np.max(np.abs(state.amplitudes[k, 3:])) > 3e-4 * np.max(np.abs(h[3:]))


def test_three_rotors_near_a_combination_resonance_match_time_integration():
    # main rotor ω, a counter-rotating rotor -ω and one at 1.5 ω; the rocking mode β 1.5 % below ω1 + ω3
    extras = (
        {"rotor_mass": 40.0, "eccentricity": 0.2, "position": [2.5, 0.4, 0.3], "speed_ratio": -1.0, "phase": 0.4},
        {"rotor_mass": 30.0, "eccentricity": 0.15, "position": [0.5, 1.6, 0.2], "axis": [0.3, 1.2],
         "speed_ratio": 1.5, "phase": 1.1},
    )
    inertia = tuned(1, "beta", 2.5 * W / 1.015, extras)
    platform, rotors = scene(inertia, extras)
    state, h = _compare_with_integration(platform, rotors, 2)  # period 2T: the speeds share ω/2
    k = np.argmin(np.abs(state.omega - 2.5 * W))
    assert np.max(np.abs(state.amplitudes[k])) > 1e-4 * np.max(np.abs(h[:3]))


def test_truncation_converges_geometrically_and_the_estimate_bounds_the_error():
    extras = ({"rotor_mass": 40.0, "eccentricity": 0.2, "position": [2.5, 0.4, 0.3], "speed_ratio": -1.0},
              {"rotor_mass": 30.0, "eccentricity": 0.15, "position": [0.5, 1.6, 0.2], "speed_ratio": 0.673})
    platform, rotors = scene(tuned(2, "gamma", 2 * W * 1.01, extras), extras, damping_ratio=0.01)
    reference = steady_state(platform, rotors)
    assert reference.truncation_error < 1e-11 * np.max(np.abs(reference.amplitudes[:, :3]))
    errors = []
    for K in range(2, 7):  # the forcing reaches order 2: the periodic stiffness acting on the static deflection
        s = steady_state(platform, rotors, max_order=K)
        assert s.order == K
        rows = reference.omega.searchsorted(s.omega)
        assert np.allclose(reference.omega[rows], s.omega)
        full = np.zeros_like(reference.amplitudes)
        full[rows] = s.amplitudes
        error = float(np.max(np.abs(full - reference.amplitudes)[:, :3]))
        assert error <= 2.0 * s.truncation_error  # the reported estimate is not optimistic
        errors.append(error)
    assert all(b < 0.1 * a for a, b in zip(errors, errors[1:])), errors


def test_equal_speeds_share_one_frequency():
    extras = tuple({"rotor_mass": 6.0, "eccentricity": 0.1, "position": [0.3 * j, 0.1 * j, 0.3],
                    "speed_ratio": (-1.0) ** j} for j in range(16))
    platform, rotors = scene([9e3, 1.7e4, 2.2e4], extras, damping_ratio=0.02)
    state = steady_state(platform, rotors)
    assert len(rotors) == 17
    assert np.allclose(state.omega / W, np.round(state.omega / W))  # only multiples of ω
    assert len(state.omega) == 2 * state.order + 1


def _peaks(state):
    """Peak over time of each coordinate x, y, z [m], α, β, γ [rad]."""
    return state.peaks(np.eye(6)[:, None, :])


@pytest.mark.parametrize("factor", [1.01, 1.5])  # a tolerance variant; one far away (direct-solve fallback)
@pytest.mark.parametrize("extra_count", [2, 16])  # dense refinement; GMRES with the nominal's preconditioner
def test_a_variant_on_the_nominal_basis_matches_its_own_full_solve(factor, extra_count):
    speeds = [-1.0, 0.673] if extra_count == 2 else [(0.55 + 0.9 * ((j + 1) * 0.618034 % 1.0)) * (-1) ** j for j in range(16)]
    extras = tuple({"rotor_mass": 5.0 + j, "eccentricity": 0.1, "position": [0.2 * j, 1.5 - 0.08 * j, 0.3],
                    "speed_ratio": r, "phase": 0.3 * j} for j, r in enumerate(speeds))
    platform, rotors = scene([9e3, 1.7e4, 2.2e4], extras, damping_ratio=0.01)
    nominal = steady_state(platform, rotors)
    basis = VariantBasis(nominal, float(np.hypot(platform.A, platform.B)))
    assert basis.dense == (extra_count == 2)
    assert len(basis.harmonics) < len(nominal.omega)
    changed = replace(platform, stiffness=platform.stiffness * np.array([factor, 1.0, 1.0]))
    near = steady_state_near(basis, changed, rotors)
    full = steady_state(changed, rotors)
    scale = np.max(np.abs(full.amplitudes[:, :3]))
    # the basis drops harmonics worth VARIANT_TOL of the largest; the rest is solved to 1e-9
    assert near.truncation_error >= nominal.truncation_error
    np.testing.assert_allclose(_peaks(near), _peaks(full), rtol=0, atol=2 * VARIANT_TOL * scale * 3.6)


def _undamped_paper_platform():
    M, r_c = 2e4, (1.5, 1.0, 0.65)
    J = inertia_about_corner(M, r_c, block_inertia(M, 3.0, 2.0, 1.3))
    stiffness = np.array([[6e7, 6e7, 1e8], [6e7, 1.2e8, 1e8], [1.2e8, 1.2e8, 1e8], [1.2e8, 6e7, 1e8]])
    return RigidPlatform(M, r_c, J, 3.0, 2.0, stiffness, 0.0, 9.81)


def _gyroscopic_frequencies(system):
    """Ω with det(K0 + iΩ G0 - Ω² M0) = 0, from the companion form of the quadratic eigenproblem."""
    M, G, K = system.mass[0].real, system.gyro[0].real, system.stiff[0].real
    Mi = np.linalg.inv(M)
    A = np.block([[np.zeros((6, 6)), np.eye(6)], [-Mi @ K, -Mi @ G]])
    return np.sort(np.abs((np.linalg.eigvals(A) / 1j).real))


def test_undamped_exact_combination_resonance_is_named():
    platform = _undamped_paper_platform()
    omega = 150.0
    for _ in range(60):  # 2ω on the 5th frequency of the gyroscopic system (which depends on ω)
        rotors = [rotor(25.0, 0.2, (1.0, 0.7, 0.5), 0.0, 0.0, omega, 0.0)]
        omega = _gyroscopic_frequencies(periodic_system(platform, rotors))[-2] / 2
    rotors = [rotor(25.0, 0.2, (1.0, 0.7, 0.5), 0.0, 0.0, omega, 0.0)]
    with pytest.raises(PhysicsError, match=r"the combination 2ω = [\d.]+ rad/s .* natural frequency") as err:
        steady_state(platform, rotors)
    assert f"{2 * omega:.6g}" in str(err.value)
    # 0.1 % away it is an answer, and a large one
    rotors = [rotor(25.0, 0.2, (1.0, 0.7, 0.5), 0.0, 0.0, omega * 1.001, 0.0)]
    assert steady_state(platform, rotors).order >= 2


def test_a_platform_without_horizontal_springs_is_told_at_once():
    p = _undamped_paper_platform()
    free = RigidPlatform(p.M, p.r_c, p.J_O1, p.A, p.B, p.stiffness * np.array([0.0, 1.0, 1.0]), 0.0, p.g)
    rotors = [rotor(25.0, 0.2, (1.0, 0.7, 0.5), 0.0, 0.0, W, 0.0)]
    with pytest.raises(PhysicsError, match="not restrained in x"):
        natural_frequencies(free, rotors)
    with pytest.raises(PhysicsError, match="not restrained"):
        steady_state(free, rotors)


# ---- scenes a Neumann series refused (exit 3 "periodic terms do not converge") ----

NEAR_RESONANCE = """
kind = "platform"
name = "One rotor, loss factor 0.014: vertical mode 1.7 % below ω, yaw 0.6 % above 2ω"
[platform]
mass = 2.0e4
length = 3.0
width = 2.0
cog = [1.5, 1.0, 0.65]
inertia = [9.0e3, 1.7e4, 1.2811e4]
[exciter]
rotor_mass = 100.0
eccentricity = 0.2
position = [0.0, 0.0]
[operation]
omega = 157.07963267948966
amplitude = 4.0e-3
regime = "above"
[isolators]
vertical_reference = 1.1928e8
loss_factor = 0.014
[limits]
detuning = 0.1
"""

RUBBER_THREE_EXCITERS = """
kind = "platform"
name = "Paper platform on rubber, two extra exciters, soft horizontally"
[platform]
mass = 2.0e4
length = 3.0
width = 2.0
cog = [1.5, 1.0, 0.65]
[exciter]
rotor_mass = 25.0
eccentricity = 0.2
position = [1.5, 1.0]
[operation]
omega = 157.07963267948966
amplitude = 2.6e-4
regime = "above"
[isolators]
vertical_reference = 1.0e8
loss_factor = 0.01
[[extra_exciters]]
rotor_mass = 6.0
eccentricity = 0.1
position = [2.0, 0.5, 0.3]
speed_ratio = -1.0
[[extra_exciters]]
rotor_mass = 6.0
eccentricity = 0.1
position = [1.0, 1.5, 0.3]
speed_ratio = 0.673
"""


def _platform_json(tmp_path, text):
    path = tmp_path / "scene.toml"
    path.write_text(text)
    result = runner.invoke(app, ["platform", str(path), "--json"])
    return result.exit_code, json.loads(result.stdout)


def test_damped_design_next_to_two_resonances_fails_with_all_its_numbers(tmp_path):
    code, doc = _platform_json(tmp_path, NEAR_RESONANCE)
    assert code == 1
    checks = {c["name"]: c["verdict"] for c in doc["checks"]}
    assert checks["natural frequencies"] == "fail"
    assert "margin 1.7%" in next(c["message"] for c in doc["checks"] if c["name"] == "natural frequencies")
    assert doc["verification"]["amplitudes"]["x"] > 0 and doc["verification"]["harmonic_balance"]["order"] >= 3
    assert doc["sensitivity_with_damping"] is True
    assert all(r["rocking_percent_plus"] is not None for r in doc["sensitivity"])
    path = tmp_path / "scene.toml"
    assert runner.invoke(app, ["check", str(path)]).exit_code == 1


def test_rubber_platform_with_three_exciters_is_answered(tmp_path):
    code, doc = _platform_json(tmp_path, RUBBER_THREE_EXCITERS)
    assert code == 1  # it rocks 43 % of u: a finding, not an invalid scene
    assert next(c for c in doc["checks"] if c["name"] == "rocking")["verdict"] == "fail"
    hb = doc["verification"]["harmonic_balance"]
    assert hb["truncation_error_over_u"] < 1e-10 and hb["frequencies"] > 10


def test_a_tolerance_that_reaches_a_resonance_fails_the_design(tmp_path):
    # the yaw mode 0.2 % above 2ω: ±1 % on the horizontal stiffnesses moves it across 2ω
    text = NEAR_RESONANCE.replace("1.2811e4", "1.2913e4")
    code, doc = _platform_json(tmp_path, text)
    assert code == 1
    tolerances = next(c for c in doc["checks"] if c["name"] == "tolerances")
    assert tolerances["verdict"] == "fail"
    assert "resonant within ±1%" in tolerances["message"] and "2ω meets mode 6 at 314.2 rad/s" in tolerances["message"]
    assert doc["sensitivity"][0]["resonance"]  # resonant rows first, with their numbers
    assert doc["sensitivity"][0]["rocking_percent_plus"] is not None
