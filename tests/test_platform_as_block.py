"""A ``platform`` scene read as a block on its isolators (``PlatformScene.as_block``) by the
commands of the one rigid body: ``fcalc resonance``, ``amplitudes``, ``sweep --speed``, ``soil``.

Independent references, written here:

- the six natural frequencies by a brute-force generalised eigen-solve of a 6 × 6 pair assembled
  here about O1 from the scene file's numbers and ``fcalc platform``'s designed stiffnesses c_ij
  and exciter point (a, b, c): the platform's body (central inertia given, or a homogeneous box
  A × B × H), the rotor as a ring m l²/2 (I + e eᵀ) on its vertical axis, the twelve springs at
  the corners carried to O1 (K = Σ T_iᵀ diag(c_i) T_i) less the weight's tilt W z_G in rocking.
  Tolerance 1e-12 relative: two eigen-solves of the same well-conditioned pair in double precision
  (measured 2e-15: the block is the platform's body exactly, its exciters' machines of parts alone);
- the amplitudes by ``fcalc platform``'s own verification (its harmonic balance about O1): an
  undamped design translates on a circle, which the block's exact periodic solution and its first
  approximation both give; 1e-12 of u (measured 3e-15);
- the block itself against that test's hand-built twin (``_platform_twin``: the platform's body
  less 1 kg as the block, the 1 kg as the exciter's frame): the same mass and stiffness matrices
  to 1e-12 of their largest entries (they differ by the split of one body's mass) and the same loads;
- an extra exciter's rotating force against its position written from Eq. (1.3) of paper 001,
  L = l (t1 cos θ + t2 sin θ), θ = σ ω_j t + φ0 (round-off of sin, cos: 1e-12).
"""

from __future__ import annotations

import copy
import json
import math
import tomllib

import numpy as np
import pytest
import scipy.linalg

import foundation_calc as fc
from foundation_calc.cli.app import app
from foundation_calc.scenes import load_scene, parse_scene
from tests.conftest import CONFIGS, configs_of_kind
from tests.test_block_exciters import _platform_twin

G = 9.81
PLATFORMS = [p.name for p in configs_of_kind("platform")]
UNDAMPED = [name for name in PLATFORMS if name != "platform_damped.toml"]


def _json(runner, *args) -> dict:
    run = runner.invoke(app, [*args, "--json"])
    assert run.exit_code in (0, 1), run.output
    return json.loads(run.stdout)


@pytest.fixture(scope="module")
def designs() -> dict:
    """``fcalc platform``'s document of every shipped platform."""
    return {name: fc.platform(CONFIGS / name).to_dict() for name in PLATFORMS}


def _brute_force_frequencies(config: str, design: dict) -> np.ndarray:
    """ω_1..ω_6 [rad/s] of det(K - ω² M) = 0, M and K about O1 (module docstring)."""
    with open(CONFIGS / config, "rb") as fh:
        s = tomllib.load(fh)
    p, e = s["platform"], s["exciter"]
    M_p, (A, B), r_c = p["mass"], (p["length"], p["width"]), np.array(p["cog"])
    if "inertia" in p:
        J_c = np.diag(p["inertia"])
    else:  # homogeneous box A × B × H, H = 2ζ (docs/platform.md)
        H = p.get("product_height", 2.0 * r_c[2])
        J_c = M_p / 12.0 * np.diag([B**2 + H**2, A**2 + H**2, A**2 + B**2])
    m, l = e["rotor_mass"], e["eccentricity"]
    rho = np.array([design["a"], design["b"], design["c"]])
    z = np.array([0.0, 0.0, 1.0])
    M = np.zeros((6, 6))
    for mass, r, J in ((M_p, r_c, J_c), (m, rho, 0.5 * m * l**2 * (np.eye(3) + np.outer(z, z)))):
        rx = np.array([[0.0, -r[2], r[1]], [r[2], 0.0, -r[0]], [-r[1], r[0], 0.0]])
        M[:3, :3] += mass * np.eye(3)
        M[:3, 3:] -= mass * rx
        M[3:, :3] += mass * rx
        M[3:, 3:] += J + mass * (r @ r * np.eye(3) - np.outer(r, r))
    K = np.zeros((6, 6))
    for r, i in zip(([0.0, 0.0, 0.0], [A, 0.0, 0.0], [A, B, 0.0], [0.0, B, 0.0]), "1234"):
        c = np.diag([design[f"c{i}{j}"] for j in "123"])
        T = np.hstack([np.eye(3), -np.array([[0.0, -r[2], r[1]], [r[2], 0.0, -r[0]], [-r[1], r[0], 0.0]])])
        K += T.T @ c @ T
    K[3, 3] -= G * (M_p * r_c[2] + m * rho[2])
    K[4, 4] -= G * (M_p * r_c[2] + m * rho[2])
    return np.sqrt(scipy.linalg.eigh(K, M, eigvals_only=True))


@pytest.mark.parametrize("config", PLATFORMS)
def test_a_platforms_frequencies_are_its_bodys_on_its_designed_isolators(runner, designs, config):
    found = _json(runner, "resonance", str(CONFIGS / config))
    assert found["scene"]["kind"] == "block_foundation"
    assert "the platform read as a block on its isolators" in found["scene"]["name"]
    expected = _brute_force_frequencies(config, designs[config]["design"])
    np.testing.assert_allclose(sorted(m["frequency"]["omega"] for m in found["modes"]), expected, rtol=1e-12)


@pytest.mark.parametrize("config", UNDAMPED)
def test_an_undamped_platforms_amplitudes_are_fcalc_platforms_verification(runner, designs, config):
    found = _json(runner, "amplitudes", str(CONFIGS / config))
    v = designs[config]["verification"]
    u = v["amplitudes"]["x"]
    O1 = found["points"]["O1"]["displacement_peak"]
    assert [O1[a] for a in "xyz"] == pytest.approx([v["amplitudes"][a] for a in "xyz"], rel=1e-12, abs=1e-12 * u)
    for i, corner in enumerate(v["corners"]):
        point = found["points"][f"corner {i + 1}"]
        assert point["at"] == pytest.approx(np.add(corner["position"], found["points"]["O1"]["at"]).tolist(), abs=1e-12)
        peak = point["displacement_peak"]
        assert [peak["x"], peak["y"]] == pytest.approx([corner["peak"]] * 2, rel=1e-12)
    (periodic,) = found["periodic_inertia"]
    exact = periodic["exact"]["displacement_peak"]["O1"]
    assert [exact[a] for a in "xyz"] == pytest.approx([v["amplitudes"][a] for a in "xyz"], rel=1e-12, abs=1e-12 * u)


@pytest.mark.parametrize("config", ["platform_paper_example.toml", "platform_damped.toml"])
def test_as_block_is_the_hand_built_twin(config):
    """The block of ``as_block`` and the twin built by hand: one body split otherwise, the same
    isolators, rotor and damping."""
    block = load_scene(CONFIGS / config).as_block()
    twin, _, _ = _platform_twin(config)
    mine, theirs = block.model(), parse_scene(twin).model()
    for a, b in ((mine.M, theirs.M), (mine.K, theirs.K)):
        np.testing.assert_allclose(a, b, rtol=0, atol=1e-12 * np.abs(b).max())
    assert mine.mass == pytest.approx(theirs.mass, rel=1e-15)
    (rows,), (twin_rows,) = ([m.load_rows() for m in s.machines] for s in (block, parse_scene(twin)))
    for r, t in zip(rows, twin_rows, strict=True):
        assert (r.order, r.phase, r.inertial) == (t.order, t.phase, t.inertial)
        np.testing.assert_allclose(np.r_[r.force, r.moment, r.at], np.r_[t.force, t.moment, t.at], rtol=0, atol=1e-12)
    assert block.isolation.eta == pytest.approx(load_scene(CONFIGS / config).isolators.loss_factor)


def test_a_platforms_soil_lists_its_designed_isolators(runner, designs):
    """Isolators are the platform's support: ``fcalc soil`` shows them as a block's (their springs
    at the corners, each one's static deflection), not a soil."""
    found = _json(runner, "soil", str(CONFIGS / "platform_damped.toml"))
    d = designs["platform_damped.toml"]["design"]
    assert found["method"] == "isolators"
    iso = found["isolators"]
    np.testing.assert_allclose(iso["stiffness"], [[d[f"c{i}{j}"] for j in "123"] for i in "1234"], rtol=1e-15)
    assert iso["points"] == [[-1.5, -1.0, 0.0], [1.5, -1.0, 0.0], [1.5, 1.0, 0.0], [-1.5, 1.0, 0.0]]
    assert iso["loss_factor"] == 0.005
    # the design's static displacement z of the platform (down, negative) is every isolator's compression
    np.testing.assert_allclose(iso["static_deflection"], -d["static_deflection"], rtol=1e-9)


def test_a_platform_sweeps_its_exciters_speed(runner, designs):
    """At its operating speed (1500 rpm) the sweep's row is the design's circle of radius u."""
    found = _json(runner, "sweep", str(CONFIGS / "platform_paper_example.toml"), "--speed", "1500:1500:1")
    assert found["machine"] == "exciter"
    (row,) = found["points"]
    u = designs["platform_paper_example.toml"]["verification"]["amplitudes"]["x"]
    assert [row["peak"][a] for a in "xy"] == pytest.approx([u, u], rel=1e-9) and row["peak"]["z"] < 1e-9 * u


def test_a_platform_is_still_refused_by_name_where_no_block_command_takes_it(runner):
    run = runner.invoke(app, ["design", str(CONFIGS / "platform_paper_example.toml"), "--vary", "block.length=2:4"])
    assert run.exit_code == 3
    assert "use fcalc platform or fcalc resonance" in run.stderr.replace("\n  ", " ").replace("\n", " ")


def test_extra_exciters_keep_their_axes_senses_phases_and_speeds():
    """A rotor on a vertical axis with δ1 ≠ 0 (t1 turned by δ1), one with δ2 < 0 (the vector's
    angles reverse t1 and t2) and one at twice the speed counter-rotating: the block's rotating
    force at each instant is m ω_j² L(t), L from Eq. (1.3) written here."""
    with open(CONFIGS / "platform_paper_example.toml", "rb") as fh:
        document = tomllib.load(fh)
    extras = [(6.0, 0.1, [2.0, 0.5, 0.3], [0.7, 0.0], 1.0, 0.4),
              (5.0, 0.12, [1.0, 1.5, 0.2], [0.3, -0.8], 1.0, -1.1),
              (4.0, 0.08, [0.5, 1.0, 0.6], [1.2, 1.3], -2.0, 0.9)]
    scene = copy.deepcopy(document) | {"extra_exciters": [
        {"rotor_mass": m, "eccentricity": l, "position": r, "axis": a, "speed_ratio": k, "phase": f}
        for m, l, r, a, k, f in extras]}
    block = parse_scene(scene).as_block()
    omega = document["operation"]["omega"]
    assert [(m.name, m.omega_rad_s) for m in block.machines] == [("exciter", omega), ("exciters at 2 ω", 2.0 * omega)]
    t = np.linspace(0.0, 2.0 * math.pi / omega, 23)
    for machine, rotors in zip(block.machines, ([None, *extras[:2]], [extras[2]])):
        rows = [r for r in machine.load_rows() if r.inertial]
        w = machine.omega_rad_s
        for rotor in rotors[1:] if rotors[0] is None else rotors:
            m, l, r, (d1, d2), k, f = rotor
            mine = [row for row in rows if np.allclose(row.at, np.subtract(r, [1.5, 1.0, 0.0]))]
            F = sum(np.multiply.outer(np.cos(w * t + row.phase), row.force) for row in mine)
            t1 = np.array([math.sin(d1), -math.cos(d1), 0.0])
            t2 = np.array([math.cos(d1) * math.cos(d2), math.sin(d1) * math.cos(d2), -math.sin(d2)])
            theta = math.copysign(1.0, k) * w * t + f
            L = l * (np.multiply.outer(np.cos(theta), t1) + np.multiply.outer(np.sin(theta), t2))
            np.testing.assert_allclose(F, m * w * w * L, rtol=0, atol=1e-12 * m * w * w * l)


def test_a_platform_that_tips_over_is_refused_in_its_own_keys(runner, tmp_path):
    """platform_damped.toml with ζ = 3 m on vertical isolators of K = 1e5 N/m tips over (as in
    tests/test_runup.py): the block commands name the platform's key, not the block's."""
    path = tmp_path / "tall.toml"
    path.write_text((CONFIGS / "platform_damped.toml").read_text().replace("cog = [1.5, 1.0, 0.65]", "cog = [1.5, 1.0, 3.0]")
                    .replace("vertical_reference = 1.0e8", "vertical_reference = 1.0e5"))
    for command in ("resonance", "soil"):
        result = runner.invoke(app, [command, str(path)])
        assert result.exit_code == 3 and "isolators.vertical: the platform is unstable" in result.stderr, result.output


def test_the_header_says_the_platform_is_read_as_a_block(runner):
    result = runner.invoke(app, ["resonance", str(CONFIGS / "platform_paper_example.toml")], env={"COLUMNS": "200"})
    assert result.exit_code == 0
    assert result.stdout.splitlines()[0].startswith(
        "Bolotnik et al. (1986), section 3 example (the platform read as a block on its isolators)")


def test_a_purely_translational_platform_prints_no_vertical_noise_and_no_negative_zero_phase(runner):
    """The paper's platform moves purely translationally: z of every point is the solver's round-off
    (1e-39 to 1e-20 m beside u = 1 mm), which the peak, RMS and exact-solution tables print as 0, as
    the steady-state table does; a phase of -0.3° rounds to 0°, never -0°. The JSON keeps the
    computed numbers."""
    text = runner.invoke(app, ["amplitudes", str(CONFIGS / "platform_paper_example.toml")], env={"COLUMNS": "200"}).stdout
    rows = [[c.strip() for c in line.split("│")[1:-1]] for line in text.splitlines() if line.startswith("│")]
    assert rows and not any("e-" in cell for row in rows for cell in row), "a value of 1e-20 m beside 1 mm is noise"
    assert "∠-0°" not in text and "∠0°" in text
    peaks = _json(runner, "amplitudes", str(CONFIGS / "platform_paper_example.toml"))["points"]["O1"]["displacement_peak"]
    assert 0.0 < abs(peaks["z"]) < 1e-15 * peaks["x"]
