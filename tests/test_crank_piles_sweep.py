"""``fcalc sweep`` of a crank scene on a pile group (configs/crank_on_piles.toml): the group couples
sway with rocking (K_xφ, C_xφ at O), so the sweep's peaks are the plane's one model's, the averaged
operator with each harmonic n on the group's springs and dashpots at n ω, and the paper's first
approximation is "not applicable".

Independent references, written here or in tests/test_crank_piles.py (whose helpers assemble the
plane's operator from the group's 6 × 6 at O, the mean mass and the forcing of the mechanism's
kinematics written out there):

- a direct complex 3 × 3 solve per harmonic n = 0 ... :data:`HARMONICS` at each speed, and the
  peak of the series so found by sampling one revolution and refining the largest sample with a
  bounded scalar search (1e-9 relative: the two differ by the forcing's Fourier coefficients from
  4096 samples and the matrices summed in another order, about 1e-11 on the harmonics; the
  harmonics above 24 are below 1e-15 of the peaks);
- ``fcalc amplitudes --json`` and ``fcalc resonance --json`` of the same scene: the sweep's row at
  the scene's own speed is the amplitudes' checked peaks, its critical speeds the modes resonance
  reports (1e-9: the same operator, solved speed by speed instead of for every speed at once).
"""

from __future__ import annotations

import copy
import json

import numpy as np
import pytest
from scipy.optimize import minimize_scalar

from foundation_calc.cli.app import app
from foundation_calc.scenes import parse_scene, read_toml
from tests.test_crank_piles import CONFIG, SAMPLES, _forcing, _mean_mass, _plane

#: Harmonics of the direct solve: those above are below 1e-15 of the peaks (module docstring).
HARMONICS = 24

#: The speeds compared with the direct solve [rpm]: below, between and above the modes p1 and k0/4.
SPEEDS = "100:800:4"


def _run(runner, *args) -> tuple[int, dict | None, str]:
    run = runner.invoke(app, [*args])
    try:
        document = json.loads(run.stdout)
    except ValueError:
        document = None
    return run.exit_code, document, run.output


@pytest.fixture(scope="module")
def swept(runner_module):
    code, document, output = _run(runner_module, "sweep", str(CONFIG), "--speed", SPEEDS, "--json")
    assert code == 0, output
    return document


@pytest.fixture(scope="module")
def runner_module():
    from typer.testing import CliRunner

    return CliRunner()


@pytest.fixture(scope="module")
def own(runner_module):
    """The sweep of the one point at the scene's own speed, 150 rpm."""
    code, document, output = _run(runner_module, "sweep", str(CONFIG), "--speed", "150", "--json")
    assert code == 0, output
    return document


@pytest.fixture(scope="module")
def resonance(runner_module):
    code, document, output = _run(runner_module, "resonance", str(CONFIG), "--json")
    assert code == 0, output
    return document


def _direct(speed_rpm: float) -> tuple[np.ndarray, float]:
    """Z_n (3, HARMONICS + 1) of x, y, θ (q(t) = Re Σ Z_n e^{i n ω t}) of the scene at ``speed_rpm``, each
    harmonic solved as (K(nω) + i nω C(nω) − (nω)² M̄) Z_n = F_n, and ω [rad/s]."""
    document = copy.deepcopy(read_toml(CONFIG))
    document["mechanism"]["speed_rpm"] = speed_rpm
    scene = parse_scene(document)
    M, z_G = _mean_mass(scene)
    F = (np.fft.rfft(_forcing(scene), axis=-1) * 2.0 / SAMPLES).conj()
    F[:, 0] /= 2.0  # the mean is counted once
    omega = scene.speed.omega_rad_s
    Z = np.empty((3, HARMONICS + 1), dtype=complex)
    for n in range(HARMONICS + 1):
        K, C = _plane(scene, n * omega, z_G)
        Z[:, n] = np.linalg.solve(K + 1j * n * omega * C - (n * omega) ** 2 * M, F[:, n])
    return Z, omega


def _peak(Z: np.ndarray) -> float:
    """max over t of |Re Σ Z_n e^{i n φ}|: the largest of 8192 samples, refined by a bounded search."""
    n = np.arange(Z.size)

    def value(phi):
        return abs(float(np.real(np.sum(Z * np.exp(1j * n * phi)))))

    grid = np.linspace(0.0, 2.0 * np.pi, 8192, endpoint=False)
    samples = np.abs(np.real(np.exp(1j * np.outer(grid, n)) @ Z))
    best = grid[int(np.argmax(samples))]
    step = grid[1]
    found = minimize_scalar(lambda phi: -value(phi), bounds=(best - step, best + step), method="bounded",
                            options={"xatol": 1e-13})
    return max(value(found.x), float(samples.max()))


def test_the_sweep_peaks_are_a_direct_complex_solve(swept):
    """Each row's peaks of x, y, θ of C and its harmonics x1, y1, y2, θ1 are those of the direct solve
    at its speed (module docstring; 1e-9)."""
    rows = swept["points"]
    speeds = [100.0, 100.0 + 700.0 / 3.0, 100.0 + 1400.0 / 3.0, 800.0]  # [rpm]
    assert [r["omega"] * 30.0 / np.pi for r in rows] == pytest.approx(speeds)
    for row in rows:
        Z, omega = _direct(row["omega"] * 30.0 / np.pi)
        assert row["omega"] == pytest.approx(omega, rel=1e-15)
        assert not row["resonant"]
        for i, key in enumerate(("x_peak", "y_peak", "theta_peak")):
            assert row[key] == pytest.approx(_peak(Z[i]), rel=1e-9), (row["omega"], key)
        for key, (i, n) in {"x1": (0, 1), "y1": (1, 1), "y2": (1, 2), "theta1": (2, 1)}.items():
            assert row["harmonics"][key]["amplitude"] == pytest.approx(abs(Z[i, n]), rel=1e-9), (row["omega"], key)


def test_the_sweep_at_the_scene_speed_is_the_amplitudes(runner_module, own):
    """The row at the scene's own speed (150 rpm) is ``fcalc amplitudes --json``'s checked approximation,
    the averaged operator (1e-9), and the first approximation is named not applicable in both."""
    code, amplitudes, output = _run(runner_module, "amplitudes", str(CONFIG), "--json")
    assert code == 0, output
    swept = own
    checked = amplitudes["approximations"][amplitudes["checked_with"]]
    assert amplitudes["checked_with"] == "averaged_operator"
    (row,) = swept["points"]
    for key, dof in (("x_peak", "x"), ("y_peak", "y"), ("theta_peak", "theta")):
        assert row[key] == pytest.approx(checked["peaks"][dof]["displacement"], rel=1e-9), key
    for key, harmonic in row["harmonics"].items():
        assert harmonic["amplitude"] == pytest.approx(checked["harmonics"][key]["magnitude"], rel=1e-9, abs=1e-25), key
    rule = amplitudes["resonance_rule"]["governing"]
    assert (row["governing_condition"], row["margin"]) == (rule["condition"], pytest.approx(rule["margin"], rel=1e-9))
    assert swept["not_applicable"] == amplitudes["not_applicable"]
    assert "averaged operator" in swept["method"] and "first approximation" not in swept["method"]


def test_the_critical_speeds_are_the_resonance_modes(swept, resonance):
    """Every critical speed nω = mode inside the sweep is the mode ``fcalc resonance`` reports over n, the
    one model's eigen-solve (1e-9), and the judged ones are its rows' critical speeds."""
    modes = resonance["natural_frequencies"]
    rows = {r["condition"]: r for r in resonance["resonances"]}
    assert swept["critical_speeds"]
    lo, hi = swept["points"][0]["omega"], swept["points"][-1]["omega"]
    for critical in swept["critical_speeds"]:
        order, mode = critical["condition"].split("ω = ")
        expected = modes[mode] / (int(order) if order else 1)
        assert lo <= expected <= hi
        assert critical["zero_order"] == pytest.approx(expected, rel=1e-9)
        assert critical["averaged"] == pytest.approx(expected, rel=1e-9)
        if critical["judged"]:
            row = rows[critical["condition"]]
            assert critical["zero_order"] == pytest.approx(row["critical_speed"]["omega"], rel=1e-9)
            assert critical["averaged"] == pytest.approx(row["critical_speed_averaged_inertia"]["omega"], rel=1e-9)
            assert critical["band"] == row["required"]
    assert {"ω = p1", "3ω = p1"} <= {c["condition"] for c in swept["critical_speeds"] if c["judged"]}


def test_the_json_sweep_exit_codes(swept, own, runner_module, tmp_path):
    """A sweep is a picture: exit 0 with failing rows (p1 near 607 rpm); a soil sweep recomputes the group from
    the factored soil (exit 0, its factor-1 row the scene's own); a bad range is a usage error (exit 2)."""
    assert swept["verdict"] == "fail" and {r["status"] for r in swept["points"]} >= {"pass", "fail"}
    code, soil, output = _run(runner_module, "sweep", str(CONFIG), "--soil", "0.9:1:2", "--json")
    assert code == 0, output
    assert soil["variable"] == "soil_factor" and "not_applicable" in soil
    softer, factor_one = soil["points"]
    assert factor_one["soil_factor"] == 1.0
    for key in ("x_peak", "y_peak", "theta_peak", "margin"):
        assert factor_one[key] == pytest.approx(own["points"][0][key], rel=1e-9), key
    assert softer["x_peak"] > factor_one["x_peak"]  # a softer group sways more
    code, document, output = _run(runner_module, "sweep", str(CONFIG), "--speed", "800:100", "--json")
    assert code == 2 and document is None, output
    csv = tmp_path / "piles.csv"
    code, _, output = _run(runner_module, "sweep", str(CONFIG), "--speed", "100:800:5", "--csv", str(csv))
    assert code == 0 and "first approximation: not applicable" in " ".join(output.split()), output
    assert len(csv.read_text(encoding="utf-8").splitlines()) == 6


def test_the_sheet_sweep_figure_draws_the_piled_crank(monkeypatch, resonance):
    """The crank sheet's sweep plot (``sweep_figure_of``, which ``fcalc report`` calls) draws the piled
    crank by the same sweep (a short grid: the figure, not its resolution, is under test)."""
    from foundation_calc.api.options import display_units
    from foundation_calc.output.report import documents

    monkeypatch.setattr(documents, "SWEEP_POINTS", 21)
    scene = parse_scene(read_toml(CONFIG))
    figure = documents.sweep_figure_of(scene, display_units(None), scene.speed.omega_rad_s, resonance["resonances"])
    assert figure is not None


def test_the_mechanism_operator_is_a_quadratic_in_the_speed():
    """The mechanism's averaged M̄, C̄, K̄ and forcing at any speed, from its three samples at 0, ω0, 2 ω0
    (``MechanismOperator.of(design, "omega")``), are ``mechanism_operator`` evaluated at that speed, the
    motor on the foundation or off it (the drive's reaction): to 1e-12 of each term's natural size (M̄,
    M̄ ω for the Coriolis terms, M̄ ω² for the stiffness, the largest forcing coefficient), round-off of
    sums of 256 samples carried to 8 ω0."""
    from dataclasses import replace

    from foundation_calc.solvers.crank.averaged import mechanism_operator
    from foundation_calc.solvers.crank.batch import MechanismOperator

    design = parse_scene(read_toml(CONFIG)).design()
    for drive in (True, False):
        d = replace(design, drive_on_foundation=drive)
        mech = MechanismOperator.of(d, "omega")
        for factor in (0.3, 2.7, 8.0):
            omega = factor * d.omega
            found = mech.at(np.array([omega]))
            direct = mechanism_operator(replace(d, omega=omega))
            mass, force = np.abs(direct[0]).max(), max(np.abs(direct[3]).max(), np.abs(direct[4]).max())
            scales = (mass, mass * omega, mass * omega**2, force, force)
            for name, a, b, scale in zip(("M", "C", "K", "fc", "fs"), found, direct, scales):
                assert np.abs(a[0] - b[..., : a.shape[-1]]).max() <= 1e-12 * scale, (drive, factor, name)
