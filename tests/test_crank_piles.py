"""A crank scene on a pile group (``[piles]``, configs/crank_on_piles.toml): the group couples
sway with rocking (K_xφ at O), so the paper's closed forms (4.5)-(4.7) do not apply and k0, p1, p2
are the one model's eigen-solve in the plane, each mode on the group's springs at its own frequency.

Independent references, written here:

- a brute-force eigen-solve: the group's impedance at O (the support's 6 × 6 K read at the mode's
  frequency) carried to the crank's x, y, θ of C by u_x = x − h θ, the weight's −W z_G on θ, and the
  mean mass of block and rod by averaging over one revolution the rod's kinematics written out
  below (crank pin, rod on its slider axis, the rod's centre of mass at l' from the pin); each
  reported p must be a natural frequency of (K(p), M̄) (1e-6: the fixed point's tolerance of
  1e-9 and the mean of 4096 samples of a smooth periodic function, exact to round-off);
- the same machine written as a ``block_foundation`` with one ``[[machines.cranks]]`` throw on the
  same piles: its 6-DOF model's modes in the plane are k0, p1, p2 (1e-6, the one-model bar).
"""

from __future__ import annotations

import numpy as np
import pytest
from scipy.linalg import eigvals

import foundation_calc as fc
from foundation_calc.cli.app import app
from foundation_calc.scenes import parse_scene, read_toml
from foundation_calc.solvers.constants import GRAVITY

from tests.conftest import CONFIGS

CONFIG = CONFIGS / "crank_on_piles.toml"


@pytest.fixture(scope="module")
def document():
    return read_toml(CONFIG)


@pytest.fixture(scope="module")
def resonance(document):
    return fc.resonance(document).to_dict()


@pytest.fixture(scope="module")
def frequencies(resonance):
    return resonance["natural_frequencies"]


#: Samples of one revolution: the means and Fourier coefficients of smooth periodic functions are exact to
#: round-off well before this many.
SAMPLES = 4096


def _kinematics(scene):
    """The mechanism at SAMPLES phases φ over one revolution, in x, y (down) from C: crank pin, slider
    (on the guide x = 0 below the crank centre A, which is a above C; φ from the downward vertical),
    the rod's centre of mass at l' from the pin, and the rod's angle."""
    m = scene.mechanism
    r, l, l1, a = m.crank_radius, m.rod_length, m.rod_cog_to_crank_pin, m.crank_axis_to_cog
    phi = np.linspace(0.0, 2.0 * np.pi, SAMPLES, endpoint=False)
    pin = np.stack([-r * np.sin(phi), -a + r * np.cos(phi)])
    slider = np.stack([0.0 * phi, pin[1] + np.sqrt(l * l - pin[0] ** 2)])
    rod = pin + l1 / l * (slider - pin)
    angle = np.arctan2(slider[1] - pin[1], slider[0] - pin[0])
    return rod, slider, angle


def _mean_mass(scene) -> tuple[np.ndarray, float]:
    """M̄ (3, 3) in x, y (down), θ (turning +x toward +y) of C: the block (M, I_c at C), the rod and the
    slider averaged over one revolution of :func:`_kinematics`; and z_G [m], the mean centre of mass
    of the whole above O. A body of mass m at p moves by (x − θ p_y, y + θ p_x)."""
    f, m = scene.foundation, scene.mechanism
    rod, slider, _ = _kinematics(scene)
    M = np.diag([f.mass, f.mass, f.moment_of_inertia + m.rod_mass * m.rod_radius_of_gyration**2])
    for mass, p in ((m.rod_mass, rod), (m.slider_mass, slider)):
        px, py = p
        M += mass * np.array([[1.0, 0.0, -py.mean()], [0.0, 1.0, px.mean()],
                              [-py.mean(), px.mean(), (px * px + py * py).mean()]])
    moving = m.rod_mass + m.slider_mass
    z_G = f.cog_height - (m.rod_mass * rod[1].mean() + m.slider_mass * slider[1].mean()) / (f.mass + moving)
    return M, z_G


def _forcing(scene) -> np.ndarray:
    """The mechanism's generalised force on the body at rest, (3, SAMPLES) in x, y, θ of C: minus the
    rate of change of the rod's and slider's momentum and of their moment of momentum about C, and
    their weights' moment (derivatives in time by the Fourier series, φ = ω t)."""
    m, g = scene.mechanism, GRAVITY
    omega = scene.speed.omega_rad_s
    rod, slider, angle = _kinematics(scene)
    k = np.fft.fftfreq(SAMPLES, 1.0 / SAMPLES)

    def second_derivative(v):
        return np.fft.ifft(-((k * omega) ** 2) * np.fft.fft(v)).real

    Q = np.zeros((3, SAMPLES))
    turning = np.unwrap(angle)
    for mass, p in ((m.rod_mass, rod), (m.slider_mass, slider)):
        a = np.stack([second_derivative(p[0]), second_derivative(p[1])])
        Q[0] -= mass * a[0]
        Q[1] -= mass * a[1]
        Q[2] -= mass * (p[0] * a[1] - p[1] * a[0]) - mass * g * p[0]
    Q[2] -= m.rod_mass * m.rod_radius_of_gyration**2 * second_derivative(turning - turning.mean())
    return Q


def _plane(scene, omega: float, z_G: float) -> tuple[np.ndarray, np.ndarray]:
    """The group's K and C at O at ``omega`` [rad/s] in x, y, θ of C (u_x = x − h θ, u_z = −y, θ_y = θ),
    the weight's −W z_G on K's θ."""
    at = scene.support().impedance(omega)
    h = scene.foundation.cog_height
    P = np.zeros((6, 3))
    P[0, 0], P[0, 2], P[2, 1], P[4, 2] = 1.0, -h, -1.0, 1.0
    K, C = (P.T @ (np.diag(d) + c) @ P for d, c in zip((at.springs, at.dashpots), at.coupling))
    return K - np.diag([0.0, 0.0, scene.total_mass * GRAVITY * z_G]), C


def test_the_piled_crank_frequencies_are_a_brute_force_eigen_solve(document, frequencies):
    """Each of k0, p1, p2 is a natural frequency of the plane's (K(p), M̄) assembled here (module docstring)."""
    scene = parse_scene(document)
    M, z_G = _mean_mass(scene)
    for mode in ("k0", "p1", "p2"):
        p = frequencies[mode]
        roots = np.sqrt(np.sort(eigvals(_plane(scene, p, z_G)[0], M).real))
        assert np.min(np.abs(roots - p)) / p < 1e-6, (mode, p, roots)
    assert frequencies["k0"] != pytest.approx(frequencies["p1"], rel=1e-3)


def _static_sway_rocking(scene, K_phi=None) -> np.ndarray:
    """The group's static stiffness at O in (u_x, θ_y), read from its 6 × 6 at rest (u_x the 1st
    motion, θ_y the 5th), with the weight's tilt −P h on θ_y; ``K_phi`` [N m/rad] replaces the group's own."""
    at = scene.support().impedance(0.0)
    K = np.diag(at.springs) + at.coupling[0]
    K = K[np.ix_((0, 4), (0, 4))]
    K[1, 1] = K[1, 1] if K_phi is None else K_phi
    return K - np.diag([0.0, scene.total_mass * GRAVITY * scene.foundation.cog_height])


def test_the_rocking_stability_margin_takes_the_coupling(resonance, document):
    """The margin is the weight's factor s* − 1 at which the static (u_x, θ_y) stiffness at O, the weight's
    tilt −s P h on θ_y, first has a zero eigenvalue, found by bisection of numpy's eigenvalues
    (tolerance 1e-9: the bisection's 1e-13 and round-off of the eigen-solve of a matrix with entries
    of 1e9 to 1e12 are far below it). Without the coupling (K_φ/(P h) − 1) it would be 3 % larger."""
    from scipy.optimize import brentq

    scene = parse_scene(document)
    K, Ph = _static_sway_rocking(scene), scene.total_mass * GRAVITY * scene.foundation.cog_height
    assert K[0, 1] != 0.0
    softest = lambda s: np.linalg.eigvalsh(K - np.diag([0.0, (s - 1.0) * Ph]))[0]  # noqa: E731
    critical = brentq(softest, 1.0, (K[1, 1] + Ph) / Ph, xtol=1e-13, rtol=1e-15)
    margin = resonance["derived"]["rocking_stability_margin"]
    assert margin == pytest.approx(critical - 1.0, rel=1e-9)
    assert (K[1, 1] + Ph) / Ph - 1.0 > margin * 1.01


def test_a_crank_tipping_over_on_its_coupled_support_is_refused(document):
    """A rocking spring above P h but below P h + K_xφ²/K_x leaves the static (u_x, θ_y) stiffness at O
    indefinite (its eigenvalues, checked here): the scene refuses it, naming the coupled margin; twice
    the coupling's share is positive definite and passes, as the same spring without the coupling does."""
    scene = parse_scene(document)
    K = _static_sway_rocking(scene)
    K_x, K_xphi, Ph = K[0, 0], K[0, 1], scene.total_mass * GRAVITY * scene.foundation.cog_height
    for share, stable in ((0.5, False), (2.0, True)):
        K_phi = Ph + share * K_xphi**2 / K_x
        assert (np.linalg.eigvalsh(_static_sway_rocking(scene, K_phi))[0] > 0.0) == stable
        if stable:
            scene.require_stable_rocking(K_phi, K_x, K_xphi)
            continue
        with pytest.raises(fc.PhysicsError, match=r"\(K_φ - K_xφ²/K_x\)/\(P·h\) - 1 = -\d") as error:
            scene.require_stable_rocking(K_phi, K_x, K_xphi)
        assert "sway-rocking coupling" in str(error.value)
        scene.require_stable_rocking(K_phi, K_x, 0.0)


def _as_block(document) -> dict:
    """The crank scene written as a block_foundation: the same block and machine, the mechanism one
    throw in the x-z plane (its crank centre a above C, its slider below it), the same soil and piles."""
    scene = parse_scene(document)
    f, m = document["foundation"], scene.mechanism
    h = scene.foundation.cog_height
    throw = {"crank_centre": [0.0, 0.0, h + m.crank_axis_to_cog], "shaft_axis": [0.0, 1.0, 0.0],
             "slider_axis": [0.0, 0.0, -1.0], "crank_angle": 0.0, "crank_radius": m.crank_radius,
             "rod_length": m.rod_length, "rod_mass": m.rod_mass, "rod_cog_to_crank_pin": m.rod_cog_to_crank_pin,
             "rod_radius_of_gyration": m.rod_radius_of_gyration, "slider_mass": m.slider_mass}
    machine = {"name": "compressor", "mass": f["machine"]["mass"], "cog": [0.0, 0.0, f["machine"]["cog_height"]],
               "inertia": [f["machine"]["moment_of_inertia"]] * 3, "speed_rpm": m.speed_rpm, "cranks": [throw]}
    return {"kind": "block_foundation", "name": "the same on a block", "block": dict(f["block"]),
            "machines": [machine], "soil": document["soil"], "piles": document["piles"], "limits": {"detuning": 0.2}}


def test_the_same_machine_on_a_block_has_the_same_frequencies(document, frequencies):
    """The one-model bar: the block_foundation's modes dominated by x, z and ry are p1, k0, p2 (1e-6)."""
    modes = fc.resonance(_as_block(document)).to_dict()["modes"]
    by_motion = {mode["dominant"]: mode["frequency"]["omega"] for mode in modes}
    assert by_motion["x"] == pytest.approx(frequencies["p1"], rel=1e-6)
    assert by_motion["z"] == pytest.approx(frequencies["k0"], rel=1e-6)
    assert by_motion["ry"] == pytest.approx(frequencies["p2"], rel=1e-6)


#: The harmonics compared: those the mechanism drives in the plane (the others are round-off).
DRIVEN = (("x", 1), ("y", 1), ("y", 2), ("y", 4), ("theta", 1), ("x", 3), ("theta", 3))


@pytest.fixture(scope="module")
def amplitudes(document):
    return fc.amplitudes(document).to_dict()


def test_the_piled_crank_amplitudes_are_a_direct_complex_solve(document, amplitudes):
    """Each driven harmonic n of the averaged operator is (K(nω) + i nω C(nω) − (nω)² M̄) Z = F_n, with
    K, C, M̄ and the mechanism's forcing F written out here (module docstring; 1e-6 relative: the
    forcing's Fourier coefficients from 4096 samples and the same matrices in another order). The
    first approximation (4.14) is reported as not applicable, never as a number."""
    scene = parse_scene(document)
    M, z_G = _mean_mass(scene)
    F = np.fft.rfft(_forcing(scene), axis=-1) * 2.0 / SAMPLES  # F_n: Q(t) = Re Σ F_n e^{i n ω t}
    F = F.conj()  # numpy's e^{-i n k}: the conjugate is the coefficient of e^{+i n ω t}
    omega = scene.speed.omega_rad_s
    found = amplitudes["approximations"]["averaged_operator"]["harmonics"]
    dofs = {"x": 0, "y": 1, "theta": 2}
    for n in range(1, 5):
        K, C = _plane(scene, n * omega, z_G)
        Z = np.linalg.solve(K + 1j * n * omega * C - (n * omega) ** 2 * M, F[:, n])
        for dof, order in DRIVEN:
            if order == n:
                assert found[f"{dof}{n}"]["magnitude"] == pytest.approx(abs(Z[dofs[dof]]), rel=1e-6), (dof, n)
    assert "first_approximation" not in amplitudes["approximations"]
    assert "not applicable" in amplitudes["not_applicable"]["first_approximation"]


def test_the_damped_line_names_the_coupling_dashpot(document, amplitudes, runner):
    """The damped response's dashpots carry the group's C_xφ at ω, read here from its 6 × 6 at O (u_x the
    1st motion, θ_y the 5th; the same numbers, 1e-12), and the text names it with its unit."""
    scene = parse_scene(document)
    at = scene.support().impedance(scene.speed.omega_rad_s)
    dashpots = amplitudes["damping"]["dashpots"]
    assert dashpots["C_xphi"] == pytest.approx(at.coupling[1][0, 4], rel=1e-12)
    assert dashpots["C_phi"] == pytest.approx(at.dashpots[4], rel=1e-12)
    run = runner.invoke(app, ["amplitudes", str(CONFIG)], env={"COLUMNS": "200"})
    assert run.exit_code == 0, run.output
    line = next(text for text in run.output.splitlines() if "damped (base dashpots" in text)
    assert "C_xφ = " in line and "N s/rad)" in line


def test_the_same_machine_on_a_block_has_the_same_amplitudes(document, amplitudes):
    """The one-model bar: the block_foundation's harmonics and peaks at C (a point there) are the
    crank's averaged operator's (1e-6 relative: the piles' material dashpots 2 ξ √(K m) take the block's
    masses about O, the crank's M_tot and I_0, which differ by the rod's own inertia)."""
    h = parse_scene(document).foundation.cog_height
    block = _as_block(document) | {"points": [{"name": "C", "at": [0.0, 0.0, h]}]}
    found = fc.amplitudes(block).to_dict()
    crank = amplitudes["approximations"]["averaged_operator"]
    by_order = {entry["order"]: entry for entry in found["harmonics"]}
    for dof, n in DRIVEN:
        entry = by_order[n]
        value = entry["rotation"]["ry"] if dof == "theta" else entry["points"]["C"]["x" if dof == "x" else "z"]
        assert value["amplitude"] == pytest.approx(crank["harmonics"][f"{dof}{n}"]["magnitude"], rel=1e-6), (dof, n)
    peaks = found["points"]["C"]["displacement_peak"]
    assert peaks["x"] == pytest.approx(crank["peaks"]["x"]["displacement"], rel=1e-6)
    assert peaks["z"] == pytest.approx(crank["peaks"]["y"]["displacement"], rel=1e-6)


def test_the_exact_solution_takes_the_coupling(document):
    """``--exact`` on piles: the harmonic balance of the exact equations, with the group's K_xφ, C_xφ, and
    the averaged operator on the same springs at ω differ by the error it reports, which for this small
    machine (μ = 0.2 %) is below 1e-5 of the peaks (dropping it from the exact equations gives 0.09 in x and 0.8 in θ)."""
    exact = fc.amplitudes(document, exact=True).to_dict()
    assert set(exact["errors"]) == {"averaged_operator"}
    for dof, error in exact["errors"]["averaged_operator"]["peaks"]["displacement"].items():
        assert error < 1e-5, dof
