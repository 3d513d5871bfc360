"""Start-up on a frequency-dependent soil (Gazetas', Pais & Kausel's impedance): one set of modes.

The run-up passes the modes ``fcalc resonance`` reports (frequencies, numbering, shapes, damping
ratios), integrating each harmonic on the springs and dashpots at its own frequency; its steady
state at the operating speed is ``fcalc amplitudes``'. Yardsticks: the resonance and amplitudes
checks themselves (the run-up must agree with them); scipy's solve_ivp of the 6-DOF equations at
constant speed, each order on its own K(nω), C(nω), run from rest into the steady state; and a
one-degree-of-freedom oscillator whose spring and dashpot follow the forcing frequency
continuously, integrated by solve_ivp with the speed ramp (and with a motor), against the
tabulated soil of the run-up. The scene of most tests is docs/runup.md's: the two-machine block on a
6 m × 3.5 m × 1.8 m base on medium-dense sand (V_s = 210 m/s), where the motor passes the rocking
mode at 142.7 rad/s that the static springs put at 162.2 rad/s, above its 156 rad/s.
"""

from __future__ import annotations

import functools
import json

import numpy as np
import pytest
import tomli_w
from scipy.integrate import solve_ivp
from scipy.optimize import brentq

from foundation_calc.cli.app import app
from foundation_calc.scenes import load_scene, parse_scene, read_toml
from tests.conftest import CONFIGS

#: docs/runup.md's soil under the two-machine block: medium-dense sand.
SAND = {"shear_wave_velocity": 210.0, "density": 1900.0, "poisson": 0.3, "material_damping": 0.03}

#: A sampled peak of a sinusoid with N samples per period is low by at most 1 - cos(π/N): the
#: run-up samples its steady state 16384 times over 16 periods of the slowest order (512 samples a
#: period of order 2: 1.9e-5); amplitudes' peaks are exact (trig_series.peak) [-].
SAMPLED = 5e-5


def _block_document(method: str) -> dict:
    document = read_toml(CONFIGS / "block_two_machines.toml")
    document["block"].update(length=6.0, width=3.5, height=1.8)
    document["soil"] = {"method": method, **SAND}
    return document


@functools.lru_cache(maxsize=None)
def _block(method: str):
    return parse_scene(_block_document(method))


@functools.lru_cache(maxsize=None)
def _block_runup(method: str):
    from foundation_calc.checks.runup import check_runup

    return check_runup(_block(method), 1.0, None)


@functools.lru_cache(maxsize=None)
def _crank_scene(name: str):
    """A shipped crank scene on Gazetas' soil (the compressor on medium sand at 600 rpm, above p1
    and k0 on the static springs; the vendor-loads compressor)."""
    document = read_toml(CONFIGS / name)
    document["soil"] = {"method": "gazetas", "shear_wave_velocity": 170.0, "density": 1800.0, "poisson": 0.3,
                        "material_damping": 0.03}
    if "mechanism" in document:
        document["mechanism"]["speed_rpm"] = 600.0
    return parse_scene(document)


@functools.lru_cache(maxsize=None)
def _crank_runup(name: str):
    """The start-up in 0.5 s of :func:`_crank_scene` ``name``."""
    from foundation_calc.checks.runup import check_runup

    return check_runup(_crank_scene(name), 0.5, None)


@pytest.mark.parametrize("method", ["gazetas", "pais_kausel"])
def test_runup_passes_the_modes_resonance_reports(runner, tmp_path, method):
    """`fcalc runup --json` against `fcalc resonance --json` of the same scene: every run's natural
    frequencies, mode names, and each passage's frequency and damping ratio are mode j's of
    resonance (rel 1e-12: the same function computes both); the run-up's mode shapes are the
    resonance check's. The static springs put the modes 1.5 % (sliding) to 14 % (rocking)
    higher and number torsion and rocking the other way round."""
    from foundation_calc.checks.amplitudes.machines import check_block
    from foundation_calc.checks.runup import _block_structures

    path = tmp_path / f"{method}.toml"
    path.write_text(tomli_w.dumps(_block_document(method)), encoding="utf-8")
    resonance = runner.invoke(app, ["resonance", str(path), "--json"])
    run = runner.invoke(app, ["runup", str(path), "--time", "1", "--json"])
    assert run.exit_code == 0, run.stderr
    modes = json.loads(resonance.stdout)["modes"]
    frequencies = [m["frequency"]["omega"] for m in modes]
    rocking = next(m for m in modes if m["dominant"] == "ry")
    assert rocking["frequency"]["omega"] < 156.0 < rocking["static_frequency"]["omega"]  # passed on its own frequency only
    for key, doc in json.loads(run.stdout)["runs"].items():
        assert doc["natural_frequencies"] == pytest.approx(frequencies, rel=1e-12), key
        assert doc["mode_names"] == [m["dominant"] for m in modes]
        for passage in doc["passages"]:
            mode = modes[passage["mode"] - 1]
            assert passage["natural_frequency"] == pytest.approx(mode["frequency"]["omega"], rel=1e-12)
            assert passage["damping_ratio"] == pytest.approx(mode["damping_ratio"], rel=1e-12)
            assert passage["mode_name"] == mode["dominant"]
    passed = {(p["mode"], p["harmonic"]) for p in json.loads(run.stdout)["runs"]["run_up:motor"]["passages"]}
    assert (rocking["mode"], 1.0) in passed  # the motor passes the rocking mode
    shapes = check_block(_block(method)).modes.shapes
    for _, structure, _ in _block_structures(_block(method))[0]:
        np.testing.assert_array_equal(structure.modes.shapes, shapes)


@pytest.mark.parametrize("scene", [
    pytest.param(lambda: (_crank_scene("compressor_medium_sand_lysmer.toml"),
                          _crank_runup("compressor_medium_sand_lysmer.toml")), id="mechanism-gazetas"),
    pytest.param(lambda: (_crank_scene("compressor_vendor_loads.toml"), None), id="vendor-loads-gazetas"),
    pytest.param(lambda: (load_scene(CONFIGS / "compressor_damped_near_resonance.toml"), None), id="mechanism-static"),
    pytest.param(lambda: (load_scene(CONFIGS / "compressor_vendor_loads.toml"), None), id="vendor-loads-static"),
])
def test_crank_runup_passes_the_averaged_frequencies_resonance_reports(scene):
    """A crank foundation's run-up passes the k0, p1, p2 that `fcalc resonance` reports with the
    mechanism's inertia averaged (a machine given by its loads: its block's), each at its own
    frequency on Gazetas' soil, ascending and named (rel 1e-12). Before, its modes were those of
    its own linearisation: on the static springs there 88.4 / 139.7 rad/s where resonance has
    83.7 / 119.4, and 4e-6 apart even on a frequency-independent soil (the rod's weight)."""
    from foundation_calc.checks.resonance import scene_resonances_as_given
    from foundation_calc.checks.runup import check_runup

    scene, report = scene()
    averaged = scene_resonances_as_given(scene).averaged
    run = (report or check_runup(scene, 0.5, None)).runs["run_up"]
    expected = sorted(float(getattr(averaged, name)) for name in ("k0", "p1", "p2"))
    assert list(run.natural) == pytest.approx(expected, rel=1e-12)
    assert len(run.names) == 3
    for natural, name in zip(run.natural, run.names):
        assert natural == pytest.approx(float(getattr(averaged, name)), rel=1e-12)


@pytest.mark.parametrize("method", ["gazetas", "pais_kausel"])
def test_block_steady_peaks_are_the_amplitudes_checks(method):
    """Every point's steady peak along x, y, z in the run-up (the machines' peaks added) against
    `fcalc amplitudes`' (each order on K(nω), C(nω)): within the run-up's sampling, 5e-5. On the
    static springs they were up to 17 % apart on this scene."""
    from foundation_calc.checks.amplitudes.machines import check_block

    expected = check_block(_block(method)).motion.peak  # (P, 3), G first
    np.testing.assert_allclose(_block_runup(method).steady_directions, expected, rtol=SAMPLED)


def test_crank_steady_peaks_are_the_amplitudes_checks():
    """The crank compressor on Gazetas' soil: C's steady horizontal and vertical peaks in the
    run-up against `fcalc amplitudes`' averaged operator, each harmonic on K(nω): 1e-4 (the run-up's
    sampling, 5e-5, and the rod's weight at its mean height, which the averaged operator of
    `amplitudes` keeps and the resonance check's leaves out: 4e-6)."""
    from foundation_calc.checks.amplitudes.approximations import check_scene_amplitudes

    amplitudes = check_scene_amplitudes(_crank_scene("compressor_medium_sand_lysmer.toml"))
    expected = amplitudes.approximations[amplitudes.checked].points["C"].displacement
    np.testing.assert_allclose(_crank_runup("compressor_medium_sand_lysmer.toml").steady_directions[0], expected, rtol=1e-4)


def test_block_steady_state_against_solve_ivp_at_constant_speed():
    """The compressor alone at its speed: scipy's solve_ivp (DOP853) of M q'' + C(nω) q' + K(nω) q
    = Re(Q_n e^{inωt}) for each order n, from rest for 4.5 s (the slowest-decaying mode, torsion at
    ζ = 0.032, p = 147 rad/s, decays by e^{-21}), the orders' motions added; the largest |u| of
    every point over the last two periods against the run-up's steady peaks (5e-5: the run-up's
    sampling; DOP853 at rtol 1e-10, its record sampled 8192 times a period)."""
    scene = _block("gazetas")
    model = scene.model()
    compressor = scene.excitations()[0]
    springs, dashpots = scene.soil_impedance(compressor.omega * compressor.orders)
    K, C = model.soil_matrices(springs, dashpots)
    Minv = np.linalg.inv(model.M)
    period = 2.0 * np.pi / compressor.omega
    settle = 4.5
    t = np.linspace(settle - 2.0 * period, settle, 16385)
    q = np.zeros((6, t.size))
    for h, n in enumerate(compressor.orders):
        Q, w = compressor.Q[h], n * compressor.omega

        def rhs(s, y, K=K[h], C=C[h], Q=Q, w=w):
            force = (Q * np.exp(1j * w * s)).real
            return np.concatenate([y[6:], Minv @ (force - C @ y[6:] - K @ y[:6])])

        sol = solve_ivp(rhs, (0.0, settle), np.zeros(12), method="DOP853", rtol=1e-10, atol=1e-16, dense_output=True)
        assert sol.success
        q += sol.sol(t)[:6]
    from foundation_calc.solvers.rigid_body.kinematics import point_map

    at = [model.cog, *(p.at for p in scene.points)]
    peaks = [np.linalg.norm(point_map(a) @ q, axis=0).max() for a in at]
    steady = _block_runup("gazetas").runs["run_up:compressor"].steady_points
    np.testing.assert_allclose(steady, peaks, rtol=SAMPLED)


# A one-degree-of-freedom oscillator on a spring and dashpot that follow the forcing frequency w
# (a0 = w/w0): k(w) = k0 (1 - 0.3 a0²/(1 + a0²)) softens as Gazetas' rocking spring does, c(w) =
# c0 (1 + 3 a0²/(1 + a0²)) rises as its radiation dashpot does; a unit unbalance (1 kg m) turns at Ω.
MASS, W0 = 1.0e3, 100.0
K0, C0 = MASS * W0**2, 2.0 * 0.03 * MASS * W0


def _spring(w):
    a2 = (np.asarray(w, dtype=float) / W0) ** 2
    return K0 * (1.0 - 0.3 * a2 / (1.0 + a2))


def _dashpot(w):
    a2 = (np.asarray(w, dtype=float) / W0) ** 2
    return C0 * (1.0 + 3.0 * a2 / (1.0 + a2))


@functools.lru_cache(maxsize=None)
def _oscillator():
    """The oscillator as a run-up structure: its mode at p = p(k(p)) (found here by Brent's method)."""
    from foundation_calc.solvers.numerics.runup import Modes, Structure
    from foundation_calc.solvers.numerics.sweep_response import RotatingLoad

    p = brentq(lambda w: w * w - _spring(w) / MASS, 1.0, 2.0 * W0)
    return Structure(
        mass=np.array([[MASS]]), damping=np.array([[C0]]), stiffness=np.array([[K0]]),
        load=RotatingLoad(np.array([1.0]), np.array([[1.0 + 0.0j]]), np.array([[0.0j]])), points=np.ones((1, 1, 1)),
        modes=Modes(np.array([p]), np.array([[MASS**-0.5]]), np.array([_dashpot(p) / (2.0 * MASS * p)]), ("x",)),
        at_frequency=lambda w: (_dashpot(w)[..., None, None], _spring(w)[..., None, None]),
    )


def _ramp(direction, top, duration):
    """(Ω, Ω', φ) of the linear ramp at time t, as the run-up's Ramp gives them."""

    def speed(t):
        if t >= duration:
            return (top, 0.0, 0.5 * top * duration + top * (t - duration)) if direction > 0 else (0.0, 0.0, 0.5 * top * duration)
        if direction > 0:
            return top * t / duration, top / duration, 0.5 * top / duration * t * t
        return top * (1.0 - t / duration), -top / duration, top * t - 0.5 * top / duration * t * t

    return speed


@pytest.mark.parametrize("direction", [1, -1])
def test_tabulated_soil_against_a_continuously_varying_spring(direction, monkeypatch):
    """Start-up (rest to 1.6 p in 4 s) and run-down of the oscillator: the run-up's tabulated
    springs (each step on the node nearest its forcing frequency) against solve_ivp of
    m x'' + c(Ω(t)) x' + k(Ω(t)) x = Ω² cos φ + Ω' sin φ with the spring and dashpot at the
    instantaneous frequency (the run-down from the steady state at 1.6 p on k, c there): the
    largest |x| to 1e-3 (measured 6e-5 and 2e-4), and halving the nodes' spacing moves it by less
    than 1e-3 (4e-5, 2e-4)."""
    import foundation_calc.solvers.numerics.runup as numerics
    from foundation_calc.solvers.numerics.runup import run_end, runup

    structure = _oscillator()
    p = float(structure.modes.natural[0])
    top, duration = 1.6 * p, 4.0
    result = runup(structure, top, duration, direction)
    assert result.passages and result.passages[0].natural == p
    speed = _ramp(direction, top, duration)

    def rhs(t, y):
        w, dw, phi = speed(t)
        return [y[1], (w * w * np.cos(phi) + dw * np.sin(phi) - _dashpot(w) * y[1] - _spring(w) * y[0]) / MASS]

    start = [0.0, 0.0]
    if direction < 0:
        Z = top * top / (_spring(top) - top * top * MASS + 1j * top * _dashpot(top))
        start = [Z.real, (1j * top * Z).real]
    end = run_end(duration, [p])
    sol = solve_ivp(rhs, (0.0, end), start, method="DOP853", rtol=1e-10, atol=1e-14, dense_output=True, max_step=0.01)
    peak = np.abs(sol.sol(np.linspace(0.0, end, 400_001))[0]).max()
    assert result.transient_points[0] == pytest.approx(peak, rel=1e-3)
    monkeypatch.setattr(numerics, "SOIL_SPACING", numerics.SOIL_SPACING / 2.0)
    assert runup(structure, top, duration, direction).transient_points[0] == pytest.approx(result.transient_points[0], rel=1e-3)


def test_motor_start_up_on_a_frequency_dependent_spring():
    """A motor of 40 N m (inertia 0.05 kg m²; the steady torque peaks at 28 N m) starts the oscillator's unbalance through its
    resonance to 1.6 p: `motor_runup` against solve_ivp of the coupled equations written here,
    m x'' + c(Ω) x' + k(Ω) x = Ω² cos φ + Ω' sin φ, J Ω' = T + sin φ x'' (the reaction of the
    oscillator's acceleration on the unbalance, V = -sin φ), the spring and dashpot at the
    instantaneous speed: the time to reach the speed and the largest |x| on the way (at the times
    of the motor run's record) to 1e-5 (measured 3e-7 and 3e-6: the motor's springs are
    interpolated linearly between the nodes, 1 % apart). The steady torque at every speed is the power the
    dashpot at that frequency dissipates over Ω (1e-9)."""
    from foundation_calc.solvers.numerics.sommerfeld import motor_runup, steady_torque

    structure = _oscillator()
    p = float(structure.modes.natural[0])
    top, torque, inertia = 1.6 * p, 40.0, 0.05
    run = motor_runup(structure, top, torque, inertia)
    assert run.reached

    def rhs(t, y):
        x, v, phi, w = y
        # [m, -sin φ; -sin φ, J] [x''; Ω'] = [w² cos φ - c v - k x; T]
        A = np.array([[MASS, -np.sin(phi)], [-np.sin(phi), inertia]])
        b = np.array([w * w * np.cos(phi) - _dashpot(w) * v - _spring(w) * x, torque])
        acc, dw = np.linalg.solve(A, b)
        return [v, acc, w, dw]

    def arrived(t, y):
        return y[3] - top

    arrived.terminal, arrived.direction = True, 1
    sol = solve_ivp(rhs, (0.0, 10.0), [0.0, 0.0, 0.0, 0.0], method="DOP853", rtol=1e-10, atol=1e-13, events=arrived,
                    dense_output=True, max_step=0.005)
    assert sol.status == 1
    assert run.time == pytest.approx(sol.t[-1], rel=1e-5)
    before = run.t <= min(run.time, sol.t[-1])  # the record is the integrator's steps: compare at its times
    assert run.magnitude[before].max() == pytest.approx(np.abs(sol.sol(run.t[before])[0]).max(), rel=1e-5)
    speeds = np.linspace(0.2 * p, top, 7)
    Z = speeds**2 / (_spring(speeds) - speeds**2 * MASS + 1j * speeds * _dashpot(speeds))
    np.testing.assert_allclose(steady_torque(structure, speeds) * speeds, 0.5 * speeds**2 * _dashpot(speeds) * np.abs(Z) ** 2,
                               rtol=1e-9)


def test_block_soil_at_each_speed_and_mode(runner, tmp_path):
    """`fcalc soil` of the block on Gazetas' soil: the static springs labelled so, then the springs
    and dashpots at each machine's speed and at each mode's own frequency (the resonance check's),
    each column named. The values at a frequency against Pais & Kausel's modifiers transcribed
    here (NIST GCR 12-917-21, Table 2-3a): K_z(ω) = K_z k_z(a0), K_ry(ω) = K_ry k_ry(a0) (L along
    x, rocking about y about the short axis), K_x(ω) = K_x (1e-12); a frequency-independent soil
    has none."""
    path = tmp_path / "gazetas.toml"
    path.write_text(tomli_w.dumps(_block_document("gazetas")), encoding="utf-8")
    result = runner.invoke(app, ["soil", str(path), "--json"])
    assert result.exit_code == 0, result.stderr
    doc = json.loads(result.stdout)
    assert doc["frequency_dependent"] is True
    at = doc["at_frequencies"]
    assert [a["at"] for a in at] == ["static"] + ["speed"] * 2 + ["mode"] * 6
    assert [a["machine"] for a in at[1:3]] == ["compressor", "motor"]
    static = {row["motion"]: row["K"] for row in doc["springs"]}
    assert at[0]["omega"] == 0.0 and at[0]["springs"] == pytest.approx(static, rel=1e-12)
    resonance = json.loads(runner.invoke(app, ["resonance", str(path), "--json"]).stdout)["modes"]
    assert [a["omega"] for a in at[3:]] == pytest.approx([m["frequency"]["omega"] for m in resonance], rel=1e-12)
    assert [a["mode_name"] for a in at[3:]] == [m["dominant"] for m in resonance]
    r = 6.0 / 3.5
    for entry in at[1:]:
        a2 = (entry["omega"] * 1.75 / SAND["shear_wave_velocity"]) ** 2
        assert entry["a0"] ** 2 == pytest.approx(a2, rel=1e-12)
        k_z = 1.0 - (0.4 + 0.2 / r) * a2 / (10.0 / (1.0 + 3.0 * (r - 1.0)) + a2)
        k_ry = 1.0 - 0.55 * a2 / (0.6 + 1.4 / r**3 + a2)
        assert entry["springs"]["z"] == pytest.approx(static["z"] * k_z, rel=1e-12)
        assert entry["springs"]["ry"] == pytest.approx(static["ry"] * k_ry, rel=1e-12)
        assert entry["springs"]["x"] == pytest.approx(static["x"], rel=1e-12)
    text = runner.invoke(app, ["soil", str(path)], env={"COLUMNS": "80"}).stdout
    assert "static (ω = 0)" in text and "ω, compressor" in text and "5 (ry)" in text
    assert max(len(line) for line in text.splitlines() if "│" in line) <= 80
    plain = json.loads(runner.invoke(app, ["soil", str(CONFIGS / "block_two_machines.toml"), "--json"]).stdout)
    assert plain["frequency_dependent"] is False and plain["at_frequencies"] == []


def test_crank_soil_sweep_recomputes_the_dynamic_soil_at_each_factor():
    """`fcalc sweep --soil` of the compressor on Gazetas' soil: at a factor the peaks of C's
    first approximation are `fcalc amplitudes`' of the scene with G × factor (each harmonic on the
    springs at n ω; 1e-9), and the governing margin is `fcalc resonance`'s there (the modes at
    their own frequencies). Scaling the static springs instead, as before, put x 9 % low at factor
    1.3 and judged 3ω = p2 failing there (now ω = p1, passing)."""
    from foundation_calc.checks.amplitudes.approximations import check_scene_amplitudes
    from foundation_calc.checks.resonance import scene_resonances_as_given
    from foundation_calc.checks.sweep.crank import scene_sweep_chunks
    from foundation_calc.checks.sweep.report import joined

    scene = _crank_scene("compressor_medium_sand_lysmer.toml")
    factors = np.array([1.3])
    report = joined(list(scene_sweep_chunks(scene, "soil_factor", factors)))
    assert report.variable == "soil_factor" and list(report.values) == list(factors)
    for k, factor in enumerate(factors):
        at = scene.with_modulus_factor(float(factor))
        expected = check_scene_amplitudes(at).approximations["first_approximation"].peaks.displacement
        np.testing.assert_allclose(report.columns["peaks"][k], expected, rtol=1e-9)
        assert report.rows.margin[k] == pytest.approx(scene_resonances_as_given(at).governing.margin, rel=1e-9)


def test_the_sheets_passages_use_the_resonance_checks_modes():
    """The calculation sheet's run-up columns (its own eigen-solve, K and C at each mode's own
    frequency) give each passage's ω_i, ζ and peaks as the run-up check does (1e-8: the fixed
    point ω = p(K(ω)) is solved to 1e-10), the modes the sheet's modes table shows."""
    from foundation_calc.checks.amplitudes.machines import check_block
    from foundation_calc.output.report.runup_methods import runup_columns
    from foundation_calc.output.runup import runup_document

    scene = _block("gazetas")
    doc = runup_document(_block_runup("gazetas"), scene, "")
    frequencies = check_block(scene).modes.frequencies
    tables = runup_columns(scene, doc)
    runs = [run for run in doc["runs"].values() if run["passages"]]
    assert tables and len(tables) == len(runs)
    for columns, run in zip(tables, runs):
        for values, passage in zip(columns.values, run["passages"]):
            assert values["omega_i"] == pytest.approx(frequencies[passage["mode"] - 1], rel=1e-8)
            for ours, judged in (("omega_i", "natural_frequency"), ("zeta", "damping_ratio"), ("eta_s", "sweep_rate"),
                                 ("x_L", "lewis_peak"), ("x_cf", "closed_form_peak")):
                assert values[ours] == pytest.approx(passage[judged], rel=1e-8), (passage["mode"], ours)
