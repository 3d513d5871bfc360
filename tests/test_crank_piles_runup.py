"""``fcalc runup`` on a crank scene on a pile group (configs/crank_on_piles.toml): the group couples
sway with rocking (K_xφ, C_xφ at O), and the start-up integrates the plane's one model with the
coupling in both K and C, each harmonic on the group's springs and dashpots at its own frequency.

Independent reference, written here: scipy's solve_ivp of the plane's three equations (x, y down,
θ of C) for each harmonic n of the mechanism's forcing, M̄ q'' + C(nΩ) q' + K(nΩ) q = Re(F_n e^{inφ}):

- M̄, and K, C at a frequency, as tests/test_crank_piles.py assembles them by brute force: the mean
  mass of block, rod and slider over one revolution of the rod's kinematics, and the group's 6 × 6
  impedance at O (its coupling included) carried to C by u_x = x − h θ, with the weight's −W z_G;
- the forcing at any speed Ω and acceleration Ω': minus the rate of change of the rod's and
  slider's momentum and moment of momentum about C, d²p/dt² = p_φφ Ω² + p_φ Ω' (φ = ∫Ω dt), and
  their weights' moment, each split into its harmonics of φ;
- the ramp from rest (the static deflection under the weight's harmonics at φ = 0) to ω in the run
  time, held at ω as long as fcalc holds it; the peak |u| of C over the whole run.

The scene runs at 700 rpm (ω = 73.3 rad/s) so that the start-up passes p1 (63.6 rad/s) with the
first harmonic and k0 (193 rad/s) with the fourth; at 150 rpm, as shipped, the harmonics that pass
a mode drive it too little to be listed.
"""

from __future__ import annotations

import copy
import json
from dataclasses import replace

import numpy as np
import pytest
from scipy.integrate import solve_ivp

import foundation_calc as fc
from foundation_calc.cli.app import app
from foundation_calc.scenes import parse_scene, read_toml
from foundation_calc.solvers.constants import GRAVITY
from foundation_calc.solvers.supports.piles import Piles
from tests.conftest import CONFIGS
from tests.test_crank_piles import SAMPLES, _kinematics, _mean_mass, _plane

CONFIG = CONFIGS / "crank_on_piles.toml"

#: The run-up time [s] and the speed [rpm] of the integrated scene (module docstring).
RUN = 1.0
SPEED_RPM = 700.0

#: Harmonics of the forcing integrated: fcalc's (solvers/crank/runup.py HARMONICS); the slider's
#: series falls by about λ = 0.22 an order, the 9th is under 1e-5 of the first.
HARMONICS = 8

#: Frequencies at which the test tabulates the group's K, C (linear interpolation between them).
GRID = 300

#: Relative agreement of the peaks [-], measured 4e-6 to 3.2e-5: fcalc holds each step's springs at
#: the nearest of its nodes 1 % apart in frequency (solvers/numerics/runup.py SOIL_SPACING), the test
#: interpolates linearly between its GRID frequencies (2 rad/s apart; 1200 of them move the peaks by
#: 1.4e-5); solve_ivp's rtol 1e-8 (1e-7 gives the same 9 digits) and the samples of the peak every
#: 5e-5 s (1 - cos(ω Δt/2) < 2e-6 for the first harmonic, which carries the peak) are far below.
PEAKS = 2e-4


def _fast(document) -> dict:
    found = copy.deepcopy(document)
    found["mechanism"]["speed_rpm"] = SPEED_RPM
    return found


@pytest.fixture(scope="module")
def document():
    return _fast(read_toml(CONFIG))


@pytest.fixture
def uncoupled(monkeypatch):
    """The group's sway-rocking K_xφ, C_xφ forced to 0 (its diagonal springs and dashpots kept)."""
    impedance = Piles.impedance

    def without_coupling(self, omega):
        at = impedance(self, omega)
        return replace(at, coupling=tuple(np.zeros_like(c) for c in at.coupling))

    monkeypatch.setattr(Piles, "impedance", without_coupling)


def _derivative(v, order: int):
    """d^order v/dφ^order of samples over one revolution (Fourier series)."""
    k = np.fft.fftfreq(SAMPLES, 1.0 / SAMPLES)
    return np.fft.ifft((1j * k) ** order * np.fft.fft(v)).real


def _forcing_harmonics(scene) -> np.ndarray:
    """(3, 3, H + 1) complex: the harmonics c_n (of e^{inφ}) of the parts of the mechanism's
    generalised force on the body at rest (x, y, θ of C) that go with Ω², with Ω' and with neither
    (the weights' moment): Q = Re Σ_n (c2_n Ω² + c1_n Ω' + cg_n) e^{inφ}."""
    m = scene.mechanism
    rod, slider, angle = _kinematics(scene)
    parts = np.zeros((3, 3, SAMPLES))  # [Ω², Ω', weight] × (x, y, θ)
    for mass, p in ((m.rod_mass, rod), (m.slider_mass, slider)):
        for part, order in ((0, 2), (1, 1)):
            a = np.stack([_derivative(p[0], order), _derivative(p[1], order)])
            parts[part, :2] -= mass * a
            parts[part, 2] -= mass * (p[0] * a[1] - p[1] * a[0])
        parts[2, 2] += mass * GRAVITY * p[0]
    turning = np.unwrap(angle)
    for part, order in ((0, 2), (1, 1)):
        parts[part, 2] -= m.rod_mass * m.rod_radius_of_gyration**2 * _derivative(turning - turning.mean(), order)
    c = np.fft.rfft(parts, axis=-1) * 2.0 / SAMPLES  # v = Re Σ c_n e^{inφ}: c_n = 2 X_n / N, X_n numpy's Σ v e^{-inφ}
    c[..., 0] /= 2.0
    return c[..., : HARMONICS + 1]


def _integrated_peak(scene, t_end: float) -> np.ndarray:
    """Peak |u| of C and its peaks along x and y over a run of ``t_end`` [s]: (|u|, |x|, |y|) [m]."""
    omega = scene.speed.omega_rad_s
    M, z_G = _mean_mass(scene)
    c = _forcing_harmonics(scene)[..., 1:]  # the mean is the static weight: no motion (fcalc's too)
    n = np.arange(1, HARMONICS + 1)
    grid = np.linspace(0.0, HARMONICS * omega, GRID)
    K, C = (np.array(v) for v in zip(*(_plane(scene, w, z_G) for w in grid)))
    table = np.linalg.solve(M, np.concatenate([K, C], axis=2))  # M̄⁻¹ [K C] at each grid frequency, (GRID, 3, 6)
    step, H = grid[1], n.size
    inertial, tangential, weight = np.einsum("ij,pjh->pih", np.linalg.inv(M), c)  # M̄⁻¹ F

    def rhs(t, state):
        speed, rate = omega * min(t, RUN) / RUN, (omega / RUN if t < RUN else 0.0)
        phi = 0.5 * omega * min(t, RUN) ** 2 / RUN + omega * max(t - RUN, 0.0)
        where = n * (speed / step)
        j = np.minimum(where.astype(int), GRID - 2)
        f = (where - j)[:, None, None]
        A = (1.0 - f) * table[j] + f * table[j + 1]  # (H, 3, 6)
        force = ((inertial * speed**2 + tangential * rate + weight) * np.exp(1j * n * phi)).real.T
        q_v = state.reshape(2, H, 3).transpose(1, 0, 2).reshape(H, 6)
        a = force - np.einsum("hij,hj->hi", A, q_v)
        return np.concatenate([q_v[:, 3:].ravel(), a.ravel()])

    q0 = np.linalg.solve(K[0], c[2].real).T  # at rest under the weight's harmonics at φ = 0
    t = np.arange(0.0, t_end, 5e-5)
    found = solve_ivp(rhs, (0.0, t_end), np.concatenate([q0.ravel(), np.zeros(3 * H)]), method="DOP853",
                      t_eval=t, rtol=1e-8, atol=1e-11)
    assert found.success, found.message
    x, y = found.y[: 3 * H].reshape(H, 3, -1).sum(axis=0)[:2]
    return np.array([np.hypot(x, y).max(), np.abs(x).max(), np.abs(y).max()])


@pytest.fixture(scope="module")
def run(document):
    return fc.runup(document, time=RUN).to_dict()["runs"]["run_up"]


def test_the_runup_peaks_are_a_time_integration(document, run):
    """The start-up's peak |u| of C and its peaks along x and y are those of the integration written
    here (module docstring; :data:`PEAKS`)."""
    from foundation_calc.solvers.numerics.runup import run_end

    expected = _integrated_peak(parse_scene(document), run_end(RUN, run["natural_frequencies"]))
    directions = run["transient_directions"]["C"]
    found = [run["transient_points"]["C"], directions["horizontal"], directions["vertical"]]
    assert found == pytest.approx(expected, rel=PEAKS)


def test_the_runup_passes_the_modes_resonance_reports(document, run):
    """The modes passed are fcalc resonance's k0, p1, p2 on the coupled group, by rank (1e-12: the same
    fixed point): the start-up meets p1 with the first harmonic at p1 and k0 with the fourth at k0/4."""
    reported = fc.resonance(document).to_dict()["natural_frequencies"]
    assert run["mode_names"] == sorted(reported, key=reported.get)
    assert run["natural_frequencies"] == pytest.approx(sorted(reported.values()), rel=1e-12)
    passed = {(p["mode_name"], p["harmonic"]): p for p in run["passages"]}
    for passage in passed.values():
        assert passage["natural_frequency"] == pytest.approx(reported[passage["mode_name"]], rel=1e-12)
    assert passed["p1", 1.0]["speed"] == pytest.approx(reported["p1"], rel=1e-12)
    assert passed["k0", 4.0]["speed"] == pytest.approx(reported["k0"] / 4.0, rel=1e-12)


def test_without_the_coupling_the_runup_is_the_uncoupled_path(document, uncoupled):
    """K_xφ = C_xφ = 0 forced on the group: the start-up's structure is the paper's path, the block of
    three uncoupled springs and dashpots (the scene's RigidBlock, solvers/crank/loads.py) at every
    frequency, and its modes the closed forms' averaged-inertia k0, p1, p2 (1e-12: the same numbers
    by another assembly)."""
    from foundation_calc.checks.resonance.frequencies import scene_frequencies
    from foundation_calc.checks.runup import _structure
    from foundation_calc.solvers.crank.loads import matrices

    scene = parse_scene(document)
    assert not scene.design().coupled
    built, *_ = _structure(scene)
    omega = np.array([0.0, 20.0, 63.6, 193.4, 377.0])
    _, K, C = matrices(scene.block(omega))
    _, _, rest = matrices(scene.block())
    found_C, found_K = built.at_frequency(omega)
    assert np.allclose(found_K, K, rtol=1e-12, atol=1e-12 * np.abs(K).max())
    assert np.allclose(found_C, built.damping + C - rest, rtol=1e-12, atol=1e-12 * np.abs(C).max())
    closed = scene_frequencies(scene)
    assert built.modes.natural == pytest.approx(sorted([closed.k0, closed.p1, closed.p2]), rel=1e-12)


def test_the_command_on_piles(runner, tmp_path):
    """Exit codes (docs/exit-codes.md): 0 with a time (here a run-down), its JSON the crank's shape; 3
    without a time, naming the field; 2 for a time out of range."""
    run = runner.invoke(app, ["runup", str(CONFIG), "--down", "1", "--json"])
    assert run.exit_code == 0, run.output
    found = json.loads(run.stdout)
    assert set(found["runs"]) == {"run_down"} and found["scene"]["kind"] == "crank_foundation"
    assert found["runs"]["run_down"]["mode_names"] == ["p1", "k0", "p2"]
    missing = runner.invoke(app, ["runup", str(CONFIG)])
    assert missing.exit_code == 3 and "operation.run_up_time" in missing.output
    assert runner.invoke(app, ["runup", str(CONFIG), "--time", "-1"]).exit_code == 2
