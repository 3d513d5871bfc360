"""fcalc runup: passage through resonance, closed form against time integration.

Validation: the single-mode peaks of the soil-damping note (constant force, sweep from 0.3 ω_n
to 2 ω_n starting in the steady state), reproduced independently here by scipy's DOP853 at
the printed three significant figures; Lewis' 1.467/sqrt(η) (Lewis 1932, printed to 4 figures).
"""

from __future__ import annotations

import json
from pathlib import Path

import numpy as np
import pytest

from foundation_calc.solvers.numerics.passage import LEWIS_COEFFICIENT, lewis_peak, passage_peak
from foundation_calc.solvers.numerics.sweep_response import Ramp, RotatingLoad, integrate, refined_peak, time_step

#: (ζ, η, peak / (F/k)) of the note, "Passage through resonance".
NOTE = [
    (0.0, 1e-3, 46.1), (0.0, 1e-2, 14.4), (0.0, 1e-1, 4.31),
    (0.05, 1e-3, 9.59), (0.05, 1e-2, 7.07), (0.05, 1e-1, 3.37),
    (0.1, 1e-3, 4.98), (0.1, 1e-2, 4.42), (0.1, 1e-1, 2.67),
]


def single_mode(zeta, eta, steps=256):
    """Peak of x'' + 2ζx' + x = cos φ, φ' from 0.3 to 2 at rate η, from the steady state."""
    M, K, C = np.eye(1), np.eye(1), 2.0 * zeta * np.eye(1)
    load = RotatingLoad(np.array([1.0]), np.zeros((1, 1), complex), np.ones((1, 1), complex))
    ramp = Ramp(0.3, 2.0, 1.7 / eta)
    Z = load.steady(M, C, K, 0.3)
    q0, v0 = Z.sum(0).real, (0.3j * Z).sum(0).real
    run = integrate(M, C, K, load, ramp, ramp.duration, time_step(M, K, load, 2.0, steps), q0, v0,
                    np.ones((1, 1, 1)), np.eye(1))
    return refined_peak(run.t, run.magnitude, 0.0, ramp.duration)[0]


def dop853(zeta, eta):
    """The same single mode by scipy's DOP853 (independent of the exponential integrator)."""
    from scipy.integrate import solve_ivp

    def rhs(t, s):
        return [s[1], np.cos(s[2]) - 2 * zeta * s[1] - s[0], 0.3 + eta * t]

    H = 1.0 / complex(1 - 0.09, 0.6 * zeta)
    sol = solve_ivp(rhs, (0, 1.7 / eta), [H.real, (0.3j * H).real, 0.0], method="DOP853", rtol=1e-10,
                    atol=1e-12, dense_output=True)
    t = np.linspace(0, 1.7 / eta, 200_001)
    return np.abs(sol.sol(t)[0]).max()


@pytest.mark.parametrize("zeta, eta, printed", NOTE, ids=[f"note-zeta{z}-eta{e:g}" for z, e, _ in NOTE])
def test_single_mode_reproduces_the_note(zeta, eta, printed):
    digits = 3
    assert f"{single_mode(zeta, eta):.{digits}g}" == f"{printed:.{digits}g}"


@pytest.mark.parametrize("zeta, eta", [(0.05, 1e-2), (0.0, 1e-1)])
def test_exponential_integrator_agrees_with_dop853(zeta, eta):
    # DOP853 output sampled at 200 001 points: its maximum is low by at most ~1e-4
    assert single_mode(zeta, eta) == pytest.approx(dop853(zeta, eta), rel=3e-4)


def test_the_record_does_not_depend_on_the_chunk_size(monkeypatch):
    """The run is filtered in chunks with the state carried across their edges: one chunk and
    chunks of 1000 steps give the same record (tolerance 1e-12: rounding only, the recursion is
    the same)."""
    from foundation_calc.solvers.numerics import sweep_response

    def record(chunk):
        monkeypatch.setattr(sweep_response, "CHUNK", chunk)
        M, K, C = np.eye(1), np.eye(1), 0.1 * np.eye(1)
        load = RotatingLoad(np.array([1.0]), np.zeros((1, 1), complex), np.ones((1, 1), complex))
        ramp = Ramp(0.3, 2.0, 170.0)
        return integrate(M, C, K, load, ramp, ramp.duration, time_step(M, K, load, 2.0), np.zeros(1), np.zeros(1),
                         np.ones((1, 1, 1)), np.eye(1)).magnitude

    whole = record(1 << 20)
    assert whole.size > 10_000
    np.testing.assert_allclose(record(1000), whole, rtol=1e-12, atol=1e-12 * whole.max())


def test_halving_the_step_moves_the_peak_less_than_1e_4():
    assert single_mode(0.05, 1e-2, 512) == pytest.approx(single_mode(0.05, 1e-2, 256), rel=1e-4)


def test_lewis_asymptote():
    assert f"{LEWIS_COEFFICIENT:.4g}" == "1.467"  # Lewis (1932), as printed
    # ζ → 0: the closed form tends to Lewis; the integrated undamped peak approaches it as η falls
    assert float(passage_peak(1e-6, 1e-3, 0.0, 1.0, 1).ratio) == pytest.approx(float(lewis_peak(1e-3)), rel=1e-3)
    errors = [abs(single_mode(0.0, eta) / lewis_peak(eta) - 1.0) for eta in (1e-2, 1e-3)]
    assert errors[1] < errors[0] and errors[1] < 0.006


def test_slow_sweep_tends_to_the_steady_resonant_amplitude():
    # steady resonant amplitude: 1/(2ζ) for a constant force; max of ν²/|1 - ν² + 2iζν| =
    # 1/(2ζ sqrt(1 - ζ²)) for an unbalance (the envelope's linearised detuning: 0.4 % high)
    assert float(passage_peak(0.05, 1e-7, 0.0, 1.0, 1).ratio) == pytest.approx(10.0, rel=1e-3)
    unbalance = 1.0 / (2 * 0.05 * np.sqrt(1 - 0.05**2))
    assert float(passage_peak(0.05, 1e-7, 1.0, 0.0, 1).ratio) == pytest.approx(unbalance, rel=5e-3)
    assert single_mode(0.1, 1e-3) == pytest.approx(5.0, rel=5e-3)


@pytest.mark.parametrize("zeta, eta", [(0.0, 1e-3), (0.05, 1e-3), (0.1, 1e-2), (0.05, 1e-2)])
def test_closed_form_error_as_stated(zeta, eta):
    # module docstring of passage.py: high by at most 0.6 % at η = 1e-3 and 2.2 % at η = 1e-2
    ratio = float(passage_peak(zeta, eta, 0.0, 1.0, 1).ratio) / single_mode(zeta, eta)
    assert 0.999 < ratio < (1.006 if eta <= 1e-3 else 1.022)


def test_platform_paper_example_loss_factor_005_five_second_ramp():
    from dataclasses import replace

    from foundation_calc.scenes import load_scene
    from foundation_calc.solvers.numerics.runup import runup
    from foundation_calc.solvers.platform.runup import structure

    scene = load_scene("configs/platform_paper_example.toml", expect="platform")
    model = replace(scene.model(), eta=0.05)
    built, _ = structure(scene.design(), model)
    result = runup(built, scene.design().omega, 5.0, 1)
    assert len(result.passages) == 2  # the two horizontal modes below 157 rad/s the rotor drives
    for p in result.passages:
        assert p.zeta == pytest.approx(0.025)
        # closed form (one mode, ≤ +3 % at these η ≈ 2.5e-3) against the mode's motion in the 6-DOF run
        assert 1.0 < p.closed_form / p.integrated < 1.03
    assert 5.0 < result.transient_points.max() / result.steady < 20.0


def test_crank_damped_scene_closed_form_against_integration():
    from foundation_calc.checks.runup import check_runup
    from foundation_calc.scenes import load_scene

    scene = load_scene("configs/frame_saw_soft_soil_runup.toml")
    report = check_runup(scene, 10.0, None)
    main = max(report.runs["run_up"].passages, key=lambda p: p.closed_form)
    assert main.ratio == 1.0 and main.closed_form / main.integrated == pytest.approx(1.0, abs=0.06)


def test_cli_runup_exit_codes_and_json(runner, tmp_path):
    from foundation_calc.cli.app import app

    result = runner.invoke(app, ["runup", "configs/platform_damped.toml", "--json"])
    assert result.exit_code == 0, result.output
    doc = json.loads(result.stdout)
    assert set(doc["runs"]) == {"run_up", "run_down"} and doc["runs"]["run_up"]["passages"]
    text = Path("configs/frame_saw_soft_soil_runup.toml").read_text().replace("transient_amplitude = 2.0e-2",
                                                                               "transient_amplitude = 1.0e-3")
    scene = tmp_path / "tight.toml"
    scene.write_text(text)
    assert runner.invoke(app, ["runup", str(scene), "--time", "5"]).exit_code == 1
    bare = tmp_path / "bare.toml"
    bare.write_text(Path("configs/frame_saw.toml").read_text())
    result = runner.invoke(app, ["runup", str(bare)])
    assert result.exit_code == 3 and "run_up_time" in result.output
    result = runner.invoke(app, ["runup", str(bare), "--time", "2", "--json"])  # no soil damping
    assert result.exit_code == 0 and "undamped" in result.stderr and json.loads(result.stdout)["warnings"]


def test_a_platform_that_tips_over_is_refused_by_name_before_its_start_up(runner, tmp_path):
    """platform_damped.toml with its centre of mass raised to ζ = 3 m on vertical isolators of
    K = 1e5 N/m: the weight's tilting moment exceeds the isolators' rocking stiffness, a squared
    natural frequency is negative (-0.99 rad²/s²). The run-up names the isolators and the cause,
    as `fcalc check`'s design row does, and takes no square root of it (the suite turns warnings
    into errors: the loss factor's modal damping sqrt(p²) would warn of a NaN)."""
    from foundation_calc.cli.app import app
    from foundation_calc.errors import PhysicsError
    from foundation_calc.scenes import parse_scene, read_toml
    from foundation_calc.solvers.platform.runup import structure

    document = read_toml(Path("configs/platform_damped.toml"))
    document["platform"]["cog"][2] = 3.0
    document["isolators"]["vertical_reference"] = 1.0e5
    scene = parse_scene(document)
    with pytest.raises(PhysicsError, match="unstable") as err:
        structure(scene.design(), scene.model())
    assert err.value.field == "isolators.vertical"
    path = tmp_path / "tall.toml"
    path.write_text(Path("configs/platform_damped.toml").read_text().replace("cog = [1.5, 1.0, 0.65]", "cog = [1.5, 1.0, 3.0]")
                    .replace("vertical_reference = 1.0e8", "vertical_reference = 1.0e5"))
    result = runner.invoke(app, ["runup", str(path)])
    assert result.exit_code == 3 and "isolators.vertical: the platform is unstable" in result.stderr, result.output

def one_mode_with_unbalance(zeta):
    """M = 1000 kg on k = M (100 rad/s)², damping ratio ζ, unbalance m e = 1 kg m."""
    from foundation_calc.solvers.numerics.runup import Structure

    M, w = 1000.0, 100.0
    load = RotatingLoad(np.array([1.0]), np.array([[1.0 + 0j]]), np.array([[0j]]))
    return Structure(np.array([[M]]), np.array([[2 * zeta * M * w]]), np.array([[M * w * w]]), load, np.ones((1, 1, 1)))


def test_steady_torque_near_resonance_is_the_notes_estimate():
    from foundation_calc.solvers.numerics.sommerfeld import torque_needs

    # (m e)² ω_n²/(4 ζ M) = 50 N m at ζ = 0.05: the leading term of the exact steady curve's peak
    (need,) = torque_needs(one_mode_with_unbalance(0.05), 150.0)
    assert need.torque == pytest.approx(50.0, rel=0.01) and need.speed == pytest.approx(100.0, rel=0.01)


@pytest.mark.parametrize("factor, reached", [(0.8, False), (1.25, True)], ids=["sticks", "passes"])
def test_motor_sticks_below_the_torque_threshold_and_passes_above(factor, reached):
    from foundation_calc.solvers.numerics.sommerfeld import motor_runup, torque_needs

    structure = one_mode_with_unbalance(0.1)
    (need,) = torque_needs(structure, 150.0)
    torque = factor * need.torque
    inertia = torque / (4e-3 * 100.0**2)  # a slow approach (η = 4e-3 < ζ²): no passing on inertia
    run = motor_runup(structure, 150.0, torque, inertia)
    assert run.reached is reached
    if not reached:
        assert 0.9 * need.speed < run.stuck_speed < need.speed  # held on the resonance's rising flank


@pytest.mark.parametrize(
    "drive, message",
    [("power = 5e3\ninertia = 1.0", "rated_speed"), ("torque = 100.0\npower = 5e3\ninertia = 1.0", "exactly one"),
     ("torque = 100.0", "inertia")],
)
def test_drive_keys_are_validated(runner, tmp_path, drive, message):
    from foundation_calc.cli.app import app

    scene = tmp_path / "motor.toml"
    scene.write_text(Path("configs/frame_saw_soft_soil_runup.toml").read_text() + f"\n[drive]\n{drive}\n")
    result = runner.invoke(app, ["runup", str(scene)])
    assert result.exit_code == 3 and message in result.output


def test_vendor_loads_run_up_against_an_independent_integration():
    """A machine given by its vendor's loads alone (`compressor_vendor_loads.toml`), run up in 3 s:
    the largest displacement of C against solve_ivp (DOP853) of the block's rigid-body equations
    written here from the scene's numbers. Each load F cos(nφ + φ_F) acts as an unbalance whose
    amplitude at speed Ω is F (Ω/ω)², with the tangential part F Ω'/(n ω²) sin(nφ + φ_F) while
    the speed changes. Tolerance 1e-3: the exponential integrator's step (halving it moves a
    peak by 1e-5) and DOP853 at rtol 1e-10."""
    from scipy.integrate import solve_ivp

    from foundation_calc.checks.runup import check_runup
    from foundation_calc.scenes import load_scene
    from foundation_calc.solvers.constants import GRAVITY
    from foundation_calc.solvers.numerics.runup import run_end
    from tests.conftest import CONFIGS

    scene = load_scene(CONFIGS / "compressor_vendor_loads.toml")
    ramp = 3.0
    result = check_runup(scene, ramp, None).runs["run_up"]
    f, springs = scene.foundation, scene.soil_springs()
    Mt, Ic, h, w = scene.total_mass, f.moment_of_inertia, f.cog_height, scene.speed.omega_rad_s
    Kx, Kz, Kp = float(springs.K_x), float(springs.K_z), float(springs.K_phi)
    b = scene.block()
    M = np.diag([Mt, Mt, Ic])
    K = np.array([[Kx, 0, -h * Kx], [0, Kz, 0], [-h * Kx, 0, Kp + h * h * Kx - Mt * GRAVITY * h]])
    C = np.array([[b.C_x, 0, -h * b.C_x], [0, b.C_z, 0], [-h * b.C_x, 0, b.C_phi + h * h * b.C_x]])
    loads = [(ld.order, np.array([ld.horizontal, ld.vertical, ld.at.height * ld.horizontal
                                  + ld.at.horizontal * ld.vertical + ld.moment]), ld.phase) for ld in scene.loads]
    Minv = np.linalg.inv(M)

    def rhs(t, s):
        speed, rate = (w * t / ramp, w / ramp) if t < ramp else (w, 0.0)
        phi = 0.5 * w / ramp * t * t if t < ramp else 0.5 * w * ramp + w * (t - ramp)
        force = sum(F * ((speed / w) ** 2 * np.cos(n * phi + p) + rate / (n * w * w) * np.sin(n * phi + p))
                    for n, F, p in loads)
        return np.concatenate([s[3:], Minv @ (force - C @ s[3:] - K @ s[:3])])

    end = run_end(ramp, np.sqrt(np.linalg.eigvals(np.linalg.solve(M, K)).real))
    t = np.linspace(0.0, end, 200_001)
    sol = solve_ivp(rhs, (0.0, end), np.zeros(6), method="DOP853", rtol=1e-10, atol=1e-16, t_eval=t)
    peak_of_C = float(np.max(np.hypot(sol.y[0], sol.y[1])))
    assert result.transient_points[0] == pytest.approx(peak_of_C, rel=1e-3)


def test_fcalc_check_judges_the_start_up_of_a_scene_with_a_transient_limit(runner, tmp_path):
    """A limit written in a scene is never passed over: `fcalc check` runs the start-up of a scene
    with run times and [limits] transient_amplitude (here tightened below its 15.6 mm peak) and
    fails it with `fcalc runup`'s verdict; a scene without either has no runup row."""
    from foundation_calc.cli.app import app
    from tests.conftest import CONFIGS

    text = (CONFIGS / "frame_saw_soft_soil_runup.toml").read_text()
    (tmp_path / "tight.toml").write_text(text.replace("transient_amplitude = 2.0e-2", "transient_amplitude = 1.0e-2"))
    (tmp_path / "plain.toml").write_text((CONFIGS / "frame_saw.toml").read_text())
    result = runner.invoke(app, ["check", str(tmp_path), "--json"])
    scenes = {s["source"].rsplit("/", 1)[-1]: s for s in json.loads(result.stdout)["scenes"]}
    tight = {c["check"]: c for c in scenes["tight.toml"]["checks"]}
    assert tight["runup"]["verdict"] == "fail" and result.exit_code == 1
    assert tight["runup"]["result"]["limits"] and "of the limit" in tight["runup"]["reason"]
    assert "runup" not in {c["check"] for c in scenes["plain.toml"]["checks"]}
    single = runner.invoke(app, ["runup", str(tmp_path / "tight.toml")])
    assert single.exit_code == 1


@pytest.mark.parametrize("modulus", [0.0, 0.9, 0.999, 1.0], ids=["E=0", "|E|=0.9", "|E|=0.999", "|E|=1 (undamped)"])
@pytest.mark.parametrize("n", [1, 2, 7, 4096])
def test_first_order_recursion_is_the_sequential_recursion(modulus, n):
    """The prefix scan against the recursion z_j = E z_{j-1} + b1 u_j + b0 u_{j-1} written as a
    plain loop, for complex E on and inside the unit circle, over one to 4096 steps (a chunk).
    Tolerance 1e-12 of the largest |z|: the scan's rounding grows as log2(n) ε, the loop's as n ε."""
    from foundation_calc.solvers.numerics.sweep_response import first_order_recursion

    rng = np.random.default_rng(n)
    E = modulus * np.exp(0.37j)
    b0, b1, carry = complex(0.3, -0.2), complex(-0.7, 0.4), complex(1.5, 0.5)
    u = rng.standard_normal(n) + 1j * rng.standard_normal(n)
    expected = np.empty(n, complex)
    previous = None
    for j in range(n):
        expected[j] = b1 * u[j] + (carry if j == 0 else E * previous + b0 * u[j - 1])
        previous = expected[j]
    got = first_order_recursion(E, b0, b1, u.copy(), carry)
    assert np.max(np.abs(got - expected)) <= 1e-12 * np.max(np.abs(expected))
