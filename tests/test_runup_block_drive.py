"""`fcalc runup` on a block machine started by its own motor ([machines.drive]): the start-up
against an independent solve_ivp of the block's 6 DOF and the motor's angle and speed written out
in the test, the Sommerfeld boundary of the note (a motor too weak for the resonance sticks), the
report naming the machine, and a machine without a drive keeping the ramp."""

from __future__ import annotations

import json

import numpy as np
import pytest
from scipy.integrate import solve_ivp

from foundation_calc.checks.runup import check_runup
from foundation_calc.cli.app import app
from foundation_calc.scenes import load_scene
from foundation_calc.solvers.numerics.runup import HOLD_FRACTION, HOLD_PERIODS

#: A 22 t block whose centre of mass and springs are both at O, so that sway and rocking do not
#: couple: its modes are x 40, y 80, z 100, about x, y and z 120 rad/s, each with a damping
#: ratio 0.1. A fan at O turns about z at 60 rad/s with an unbalance G 100 mm/s of a 2 t rotor:
#: m e = 2000 × 0.1/60 = 3.333 kg m, a rotating force in the x-y plane at O that drives the x and
#: y modes alone; its start-up passes the x mode (40 rad/s) only.
SCENE = """
kind = "block_foundation"
name = "one driven fan"

[block]
length = 4.0
width = 3.0
mass = 19.0e3
cog = [0.0, 0.0, 0.0]
inertia = [2.0e4, 3.0e4, 4.0e4]

[[machines]]
name = "fan"
mass = 3.0e3
cog = [0.0, 0.0, 0.0]
speed = 60.0

[machines.unbalance]
balance_grade_mm_s = 100.0
rotor_mass = 2000.0
axis = [0.0, 0.0, 1.0]

[machines.drive]
torque = TORQUE
inertia = INERTIA

[soil]
method = "springs"
stiffness = [3.52e7, 1.408e8, 2.2e8, 2.88e8, 4.32e8, 5.76e8]
dashpot = [1.76e5, 3.52e5, 4.4e5, 4.8e5, 7.2e5, 9.6e5]

[[points]]
name = "bearing"
at = [0.5, 0.0, 1.0]
"""

#: The note's Sommerfeld torque (m e)² ω_n²/(4 ζ M) at the x mode: M = 22 t, ω_n = 40 rad/s,
#: ζ = 0.1 [N m] (2.020 N m).
ME, OMEGA, OMEGA_N, ZETA, MASS = 2000.0 * 0.1 / 60.0, 60.0, 40.0, 0.1, 22.0e3
ESTIMATE = ME**2 * OMEGA_N**2 / (4.0 * ZETA * MASS)
#: The rotor's own inertia m_r e² about the shaft, e = G/ω [kg m²].
ROTOR = 2000.0 * (0.1 / OMEGA) ** 2


def scene_file(tmp_path, torque, inertia, extra=""):
    path = tmp_path / "fan.toml"
    path.write_text(SCENE.replace("TORQUE", repr(torque)).replace("INERTIA", repr(inertia)) + extra, encoding="utf-8")
    return path


def independent_start(scene, torque, inertia):
    """The block's Eq. (1) and the motor written out (Lagrange, the unbalance a point mass m_r at
    e = G/ω from the axis z through O): with d(φ) = (cos φ, sin φ, 0) the mass's direction and
    d' = (-sin φ, cos φ, 0),

        M q'' + m e Q(d') Ω' = m e Ω² Q(d) - C q' - K q,
        m e Q(d')·q'' + J Ω' = T,          J = drive inertia + m_r e²,

    Q(v) = (v, r × v) the generalised force at O of a force v at the rotor (r = 0 here), solved
    for (q'', Ω') as one 7 × 7 linear system each step; the speed held at ω once reached, for as
    long as fcalc holds it. Returns (arrival time, largest |u| of G and the bearing)."""
    model = scene.model()
    M, C, K = model.M, model.C, model.K
    J = inertia + ROTOR
    Minv = np.linalg.inv(M)

    r = np.zeros(3)  # the rotor at O
    lever = np.vstack([np.eye(3), [[0.0, -r[2], r[1]], [r[2], 0.0, -r[0]], [-r[1], r[0], 0.0]]])  # v -> (v, r × v)

    def Q(v):
        return lever @ v

    def rhs(t, y, held=False):
        q, v, phi, w = y[:6], y[6:12], y[12], y[13]
        d, dd = np.array([np.cos(phi), np.sin(phi), 0.0]), np.array([-np.sin(phi), np.cos(phi), 0.0])
        A = np.zeros((7, 7))
        A[:6, :6], A[:6, 6], A[6, :6], A[6, 6] = M, ME * Q(dd), ME * Q(dd), J
        b = np.concatenate([ME * w * w * Q(d) - C @ v - K @ q, [torque]])
        if held:
            return np.concatenate([v, Minv @ b[:6], [w, 0.0]])
        a = np.linalg.solve(A, b)
        return np.concatenate([v, a[:6], [w, a[6]]])

    def arrived(t, y):
        return y[13] - OMEGA

    arrived.terminal, arrived.direction = True, 1
    options = dict(method="DOP853", rtol=1e-9, atol=1e-12, dense_output=True)
    up = solve_ivp(rhs, (0.0, 100.0), np.zeros(14), events=arrived, **options)
    assert up.status == 1
    lowest = np.sqrt(np.linalg.eigvals(np.linalg.solve(M, K)).real.min())
    hold = max(HOLD_FRACTION * up.t[-1], HOLD_PERIODS * 2.0 * np.pi / lowest)
    held = solve_ivp(lambda t, y: rhs(t, y, True), (up.t[-1], up.t[-1] + hold), up.y[:, -1], **options)
    step = 2e-3  # 80 samples per period of the x mode, read from the dense output
    q = np.concatenate([up.sol(np.arange(0.0, up.t[-1], step))[:6], held.sol(np.arange(up.t[-1], held.t[-1], step))[:6]], axis=1)
    at = (model.cog, np.array([0.5, 0.0, 1.0]))
    # u_P = translation + rotation × r_P (small rotations), the point's displacement vector
    peaks = [np.linalg.norm(q[:3] + np.cross(q[3:6].T, r).T, axis=0).max() for r in at]
    return up.t[-1], np.array(peaks)


def test_motor_start_against_an_independent_integration(tmp_path):
    """Arrival time to 1e-4 (both integrations at rtol ≤ 1e-8); the peaks to 1 %: fcalc takes the
    largest |u| over its integration steps (at most a quarter of the shortest period, 2π/(4 × 120 rad/s)),
    and the peak is the x mode's orbit, sampled at least 12 times per period at 40 rad/s: the
    sampled maximum of a near-circular orbit lies within 1 - cos(π/12) = 3 % below the true one,
    and much closer since the orbit's radius varies slowly between samples."""
    torque, inertia = 2.5 * ESTIMATE, 0.1
    scene = load_scene(scene_file(tmp_path, torque, inertia))
    report = check_runup(scene, None, None)
    motor = report.motors["fan"]
    assert motor.reached and motor.inertia == pytest.approx(inertia + ROTOR, rel=1e-12)
    arrival, peaks = independent_start(scene, torque, inertia)
    assert motor.time == pytest.approx(arrival, rel=1e-4)
    np.testing.assert_allclose(motor.transient_points, peaks, rtol=1e-2)
    assert peaks.max() > 2.0 * report.steady_points.max()  # the passage, not the steady orbit, governs


@pytest.mark.parametrize("factor, reached", [(0.8, False), (1.25, True)], ids=["sticks", "passes"])
def test_a_motor_too_weak_for_the_resonance_sticks(tmp_path, factor, reached):
    """The note's torque (m e)² ω_n²/(4 ζ M) is the boundary: fcalc's steady need at the x mode is
    within 5 % of it (measured +3.3 %: the estimate is the leading term for small ζ, the exact
    single-mode peak at ζ = 0.1 lies ~ 2 % above it, and the y mode, off resonance, adds its own
    dissipation), so a motor 20 % short of it sticks on the mode's rising flank and one 25 % above
    passes. The approach, η = T/(J ω_n²) = 2e-2, is slow enough that the shaft cannot coast
    through on its kinetic energy: at 0.8 it sticks at the same speed, 38.6 rad/s, as on
    η = 4e-3 (and on 1e-2), whose run is four times longer."""
    torque = factor * ESTIMATE
    inertia = torque / (2e-2 * OMEGA_N**2) - ROTOR
    scene = load_scene(scene_file(tmp_path, torque, inertia))
    report = check_runup(scene, None, None)
    (row,) = report.torques
    assert row.machine == "fan" and row.needed == pytest.approx(ESTIMATE, rel=0.05)
    assert row.speed == pytest.approx(OMEGA_N, rel=0.05)
    motor = report.motors["fan"]
    assert motor.reached is reached
    if not reached:
        assert 0.9 * row.speed < motor.stuck_speed < row.speed
        assert report.outcome.value == "fail"


def test_cli_names_the_machine_and_keeps_the_ramp_of_a_machine_without_a_drive(runner, tmp_path):
    """A stuck motor exits 1 naming the machine in the text, JSON and `fcalc check`; a second
    machine without [machines.drive] is run along [operation]'s ramp as before."""
    torque = 0.4 * ESTIMATE
    second = """
[[machines]]
name = "pump"
mass = 1.0e3
cog = [0.0, 0.0, 0.0]
speed = 60.0

[[machines.loads]]
order = 1
force = [0.0, 0.0, 50.0]

[operation]
run_up_time = 2.0
"""
    path = scene_file(tmp_path, torque, torque / (4e-2 * OMEGA_N**2), second)
    result = runner.invoke(app, ["runup", str(path)])
    text = " ".join(result.output.split())  # the table titles wrap
    assert result.exit_code == 1, result.output
    assert "Motor start-up of fan (Sommerfeld)" in text and "sticks at" in text
    result = runner.invoke(app, ["runup", str(path), "--json"])
    assert result.exit_code == 1
    doc = json.loads(result.stdout)
    assert doc["motor"] is None and list(doc["motors"]) == ["fan"]
    fan = doc["motors"]["fan"]
    assert fan["machine"] == "fan" and not fan["reached"] and fan["sommerfeld"][0]["verdict"] == "fail"
    assert set(doc["runs"]) == {"run_up:fan", "run_up:pump", "run_up:*"}
    assert {row["run"] for row in doc["limits"]} >= {"motor:fan"}
    result = runner.invoke(app, ["check", str(path)])
    # modes numbered from 1 as in every table (the x mode is the lowest)
    assert result.exit_code == 1 and "the motor of fan sticks at mode 1:" in " ".join(result.output.split())


def test_drive_keys_of_a_machine_are_validated(runner, tmp_path):
    """The crank's [drive] model: exactly one of torque or power, named under the machine."""
    path = scene_file(tmp_path, 1.0, 0.5)
    path.write_text(path.read_text(encoding="utf-8").replace("torque = 1.0", "torque = 1.0\npower = 5e3"), encoding="utf-8")
    result = runner.invoke(app, ["runup", str(path)])
    assert result.exit_code == 3 and "exactly one" in result.output and "machines" in result.output


def test_a_motor_below_every_resonance_is_judged(tmp_path):
    """A fan run at 30 rad/s, below the block's lowest mode (40 rad/s), passes no resonance: its
    motor reaching the speed is a pass, not "not judged" (no limit, no Sommerfeld row)."""
    path = scene_file(tmp_path, 5.0, 0.1)
    path.write_text(path.read_text(encoding="utf-8").replace("speed = 60.0", "speed = 30.0"), encoding="utf-8")
    report = check_runup(load_scene(path), None, None)
    assert report.motors["fan"].reached and report.torques == ()
    assert report.judged and report.outcome.value == "pass"
