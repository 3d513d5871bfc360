"""``[[machines.exciters]]``: paper 001's unbalanced exciter as a block machine's part.

Independent references, written here and nowhere else:

- the platform of paper 001 (``fcalc platform``, its own design, isolators and 6-DOF harmonic
  balance about the corner O1) rebuilt as a block scene on ``[[isolators]]`` with one exciter, O
  moved to the centre of the base: its amplitudes and frequencies are the platform's. On the
  paper's design (exact translation, one harmonic) to 1e-9 of u. On the damped variant, where the
  platform rocks, the platform's peak is the sum of its harmonics' peaks (an upper bound) and the
  block's the peak over time of the same harmonics: they agree to the higher harmonics' share,
  1e-5 of the translations and 2e-3 of the rotations (measured 1.2e-6 and 1.05e-3), the block's
  never above;
- a two-shaft directional exciter (two rotors, one axis and point, opposite senses, one phase)
  by the hand formula: the force 2 m l ω² cos ωt along d = t1 cos φ0 + t2 sin φ0, t1 = e × z/|e × z|,
  t2 = e × t1 (docs/block-foundation.md), its weight's moment -2 g m l cos ωt d × z; and the
  block's response to it by one complex 6 × 6 solve written out here (block, frame and the two
  rotors as rings m l²/2 (I + e eᵀ); springs less the weight's tilt W z_G; dashpots).
  Tolerance 1e-12 for the forces (round-off of sin, cos), 1e-8 for the solve (two 6 × 6 solves).
"""

from __future__ import annotations

import copy
import json
import math
import tomllib

import numpy as np
import pytest

import foundation_calc as fc
from foundation_calc.cli.app import app
from foundation_calc.scenes import load_scene, parse_scene
from tests.conftest import CONFIGS

G = 9.81
E3 = np.array([0.0, 0.0, 1.0])
TABLE = CONFIGS / "block_vibrating_table.toml"
with open(TABLE, "rb") as _fh:
    SHIPPED = tomllib.load(_fh)


# ---- the platform of paper 001 as a block -------------------------------------------------------

def _platform_twin(config: str) -> tuple[dict, dict, np.ndarray]:
    """(block scene, ``fcalc platform``'s document, shift O1 -> O): the platform's body, its design's
    twelve springs at the corners and its one exciter (vertical axis, positive sense, φ0 = 0) as a
    block on [[isolators]]; the body's mass less 1 kg is the block, the 1 kg the machine's frame at
    the same centre of mass (a machine needs a mass), so the body is the platform's. Points: O1 and
    the product box's corners."""
    path = CONFIGS / config
    scene = load_scene(path)
    d = scene.design()
    platform = fc.platform(path).to_dict()
    shift = np.array([d.A / 2.0, d.B / 2.0, 0.0])
    corners = np.array([[0.0, 0.0, 0.0], [d.A, 0.0, 0.0], [d.A, d.B, 0.0], [0.0, d.B, 0.0]]) - shift
    cog = (np.array([d.xi, d.eta, d.zeta]) - shift).tolist()
    box = [np.array(c["position"]) - shift for c in platform["verification"]["corners"]]
    twin = {
        "kind": "block_foundation", "name": "the platform as a block",
        "block": {"length": d.A, "width": d.B, "mass": d.M - 1.0, "cog": cog, "inertia": list(scene.inertia)},
        "machines": [{"name": "exciter", "mass": 1.0, "cog": cog, "speed_rpm": d.omega * 30.0 / math.pi,
                      "exciters": [{"rotor_mass": d.m, "eccentricity": d.l, "axis": [0.0, 0.0, 1.0],
                                    "at": (np.array([d.a, d.b, d.c]) - shift).tolist(), "sense": 1, "phase": 0.0}]}],
        "isolators": [{"position": r.tolist(), "stiffness": k.tolist()} for r, k in zip(corners, np.asarray(d.stiffness))],
        "isolation": {"loss_factor": scene.isolators.loss_factor},
        "points": [{"name": "O1", "at": (-shift).tolist()}] + [{"name": f"box {i}", "at": p.tolist()} for i, p in enumerate(box)],
    }
    return twin, platform, shift


def test_the_papers_platform_as_a_block_with_one_exciter_moves_as_fcalc_platform_verifies():
    """Paper 001's design translates on a circle of radius u = 1 mm: every corner of the product box
    moves 1 mm along x and y, nothing along z, no rotation; and the six frequencies are the platform's."""
    twin, platform, _ = _platform_twin("platform_paper_example.toml")
    found = fc.amplitudes(twin).to_dict()
    v = platform["verification"]
    u = v["amplitudes"]["x"]
    for i, corner in enumerate(v["corners"]):
        peak = found["points"][f"box {i}"]["displacement_peak"]
        assert [peak["x"], peak["y"]] == pytest.approx([corner["peak"]] * 2, rel=1e-9)
        assert peak["z"] < 1e-9 * u
    O1 = found["points"]["O1"]["displacement_peak"]
    assert [O1[a] for a in "xyz"] == pytest.approx([v["amplitudes"][a] for a in "xyz"], rel=1e-9, abs=1e-9 * u)
    assert max(found["rotation_peak"].values()) < 1e-9 * u
    (periodic,) = found["periodic_inertia"]
    assert periodic["first_approximation_error"] < 1e-9  # a pure translation: the rotor's inertia cannot couple
    frequencies = sorted(m["frequency"]["omega"] for m in fc.resonance(twin).to_dict()["modes"])
    np.testing.assert_allclose(frequencies, sorted(m["omega"] for m in platform["natural_frequencies"]), rtol=1e-9)


def test_the_damped_platform_as_a_block_rocks_as_fcalc_platform_verifies():
    """With a loss factor the platform rocks (paper note: exact translation is impossible): the
    block's exact periodic solution of the same exciter gives the platform's amplitudes of O1 and
    rotations, within the higher harmonics that the platform sums as peaks (module docstring)."""
    twin, platform, _ = _platform_twin("platform_damped.toml")
    found = fc.amplitudes(twin).to_dict()
    (periodic,) = found["periodic_inertia"]
    exact = periodic["exact"]
    v = platform["verification"]
    block = [exact["displacement_peak"]["O1"][a] for a in "xyz"]
    plat = [v["amplitudes"][a] for a in "xyz"]
    np.testing.assert_allclose(block[:2], plat[:2], rtol=1e-5)
    assert abs(block[2] - plat[2]) < 1e-5 * v["amplitudes"]["x"]
    rotations = [exact["rotation_peak"][k] for k in ("rx", "ry", "rz")]
    expected = [v["rotations"][k] for k in ("alpha", "beta", "gamma")]
    np.testing.assert_allclose(rotations, expected, rtol=2e-3)
    assert all(b <= p * (1.0 + 1e-9) for b, p in zip(block + rotations, plat + expected))
    assert min(rotations) > 1e-3 * v["amplitudes"]["x"] / 3.0  # it does rock: the comparison is not of zeros


# ---- a two-shaft directional exciter ------------------------------------------------------------

M_ROTOR, ECC, AXIS, AT, PHI0 = 40.0, 0.08, np.array([1.0, 2.0, 2.0]), np.array([0.4, 0.3, 2.6]), 0.7
BLOCK = (6.0, 4.0, 2.0, 2400.0)  # L, B, H [m], density [kg/m³]
FRAME = (5.0e3, np.array([0.5, 0.2, 2.5]), np.diag([1.0e3, 2.0e3, 2.0e3]))
SPRINGS = np.array([6.0e9, 5.5e9, 8.0e9, 4.0e10, 7.0e10, 5.0e10])
DASHPOTS = np.array([1.5e7, 1.5e7, 2.5e7, 3.0e7, 5.0e7, 2.0e7])
RPM = 960.0
CORNER = np.array([3.0, 2.0, 2.0])


def _rotor(sense: int) -> dict:
    return {"rotor_mass": M_ROTOR, "eccentricity": ECC, "axis": AXIS.tolist(), "at": AT.tolist(), "sense": sense,
            "phase": PHI0}


def _screen(**machine) -> dict:
    """A vibrating screen's directional exciter on a block on given springs and dashpots."""
    L_, B_, H_, rho = BLOCK
    m, cog, J = FRAME
    return {
        "kind": "block_foundation", "name": "directional exciter on a block",
        "block": {"length": L_, "width": B_, "height": H_, "density": rho},
        "machines": [{"name": "screen", "mass": m, "cog": cog.tolist(), "inertia": np.diag(J).tolist(),
                      "speed_rpm": RPM, "exciters": [_rotor(1), _rotor(-1)]} | machine],
        "soil": {"method": "springs", "stiffness": SPRINGS.tolist(), "dashpot": DASHPOTS.tolist()},
        "points": [{"name": "corner", "at": CORNER.tolist()}],
    }


def _line() -> np.ndarray:
    """d = t1 cos φ0 + t2 sin φ0: where both rotors stand at t = 0 (t1 = e × z/|e × z|, t2 = e × t1)."""
    e = AXIS / np.linalg.norm(AXIS)
    t1 = np.cross(e, E3) / np.linalg.norm(np.cross(e, E3))
    return t1 * math.cos(PHI0) + np.cross(e, t1) * math.sin(PHI0)


def test_a_directional_pair_shakes_along_one_line_with_twice_one_rotors_force():
    """Opposite senses on one axis: F(t) = 2 m l ω² cos ωt d (rectilinear), the weight's moment
    -2 g m l cos ωt d × z, at every instant of a revolution."""
    machine = parse_scene(_screen(), "screen.toml").machines[0]
    omega = RPM * math.pi / 30.0
    t = np.linspace(0.0, 2.0 * math.pi / omega, 37)
    rows = machine.load_rows()
    assert {r.order for r in rows} == {1} and all(np.allclose(r.at, AT) for r in rows)
    F = sum(np.multiply.outer(np.cos(omega * t + r.phase), r.force) for r in rows)
    Mw = sum(np.multiply.outer(np.cos(omega * t + r.phase), r.moment) for r in rows)
    d = _line()
    F0 = 2.0 * M_ROTOR * ECC * omega**2
    np.testing.assert_allclose(F, np.multiply.outer(F0 * np.cos(omega * t), d), rtol=0, atol=1e-12 * F0)
    np.testing.assert_allclose(Mw, np.multiply.outer(-2.0 * G * M_ROTOR * ECC * np.cos(omega * t), np.cross(d, E3)),
                               rtol=0, atol=1e-12 * F0)


def _direct_block(omega: float) -> tuple[np.ndarray, float]:
    """(Z, total mass): the complex amplitude of q at ω from (K - ω² M + iω C) Z = Q, written out."""
    L_, B_, H_, rho = BLOCK
    m_b = L_ * B_ * H_ * rho
    e = AXIS / np.linalg.norm(AXIS)
    ring = 0.5 * M_ROTOR * ECC**2 * (np.eye(3) + np.outer(e, e))
    bodies = [(m_b, np.array([0.0, 0.0, H_ / 2.0]), np.diag([B_**2 + H_**2, L_**2 + H_**2, L_**2 + B_**2]) * m_b / 12.0),
              FRAME, (M_ROTOR, AT, ring), (M_ROTOR, AT, ring)]
    M = np.zeros((6, 6))
    for m, r, J in bodies:  # kinetic energy of a rigid body about O: [[m I, -m [r]×], [m [r]×, J + m (|r|² I - r rᵀ)]]
        rx = np.array([[0.0, -r[2], r[1]], [r[2], 0.0, -r[0]], [-r[1], r[0], 0.0]])
        M[:3, :3] += m * np.eye(3)
        M[:3, 3:] -= m * rx
        M[3:, :3] += m * rx
        M[3:, 3:] += J + m * (r @ r * np.eye(3) - np.outer(r, r))
    mass = M[0, 0]
    z_G = sum(m * r[2] for m, r, _ in bodies) / mass
    K = np.diag(SPRINGS)
    K[3, 3] -= mass * G * z_G
    K[4, 4] -= mass * G * z_G
    d = _line()
    F = 2.0 * M_ROTOR * ECC * omega**2 * d
    Q = np.concatenate([F, np.cross(AT, F) - 2.0 * G * M_ROTOR * ECC * np.cross(d, E3)])
    return np.linalg.solve(K - omega**2 * M + 1j * omega * np.diag(DASHPOTS), Q), mass


def test_a_directional_pair_on_a_block_answers_the_direct_complex_solve():
    omega = RPM * math.pi / 30.0
    Z, mass = _direct_block(omega)
    found = fc.amplitudes(_screen()).to_dict()
    assert found["total_mass"] == pytest.approx(mass, rel=1e-12)
    peak = np.abs(Z[:3] + np.cross(Z[3:], CORNER))
    assert [found["points"]["corner"]["displacement_peak"][a] for a in "xyz"] == pytest.approx(peak, rel=1e-8)
    assert [found["rotation_peak"][k] for k in ("rx", "ry", "rz")] == pytest.approx(np.abs(Z[3:]), rel=1e-8)
    (periodic,) = found["periodic_inertia"]  # the rotors' angle-dependent inertia, by the exact periodic solution
    assert periodic["machine"] == "screen" and periodic["first_approximation_error"] < 1e-3


def test_every_block_command_takes_a_machine_with_exciters(runner, tmp_path):
    """resonance, sweep, soil, check and design run (runup: the shipped table in the JSON record);
    the sheet states the rotors' derivation and the kind's assumption."""
    import tomli_w

    path = tmp_path / "screen.toml"
    path.write_bytes(tomli_w.dumps(_screen() | {"limits": {"amplitude": 5.0e-5}}).encode())
    for args in (["resonance"], ["sweep", "--speed", "600:1200:5"], ["soil"],
                 ["check"], ["design", "--vary", "block.length=5:7", "--points", "2"]):
        result = runner.invoke(app, [args[0], str(path), *args[1:], "--json"])
        assert result.exit_code in (0, 1), (args, result.stdout + result.stderr)
        assert json.loads(result.stdout)
    sheet = tmp_path / "screen.md"
    result = runner.invoke(app, ["report", str(path), "-o", str(sheet)])
    assert result.exit_code in (0, 1), result.stdout + result.stderr
    text = sheet.read_text(encoding="utf-8")
    assert text.count("unbalanced exciter F = m l ω²") == 2
    assert "turning positively" in text and "turning negatively" in text
    assert "The exciters' rotors, point masses m at the eccentricity l" in text


# ---- bad input ----------------------------------------------------------------------------------

def _table(**rotor) -> dict:
    """The shipped table with its first rotor's keys changed (None removes a key)."""
    document = copy.deepcopy(SHIPPED)
    first = document["machines"][0]["exciters"][0]
    for key, value in rotor.items():
        if value is None:
            first.pop(key, None)
        else:
            first[key] = value
    return document


@pytest.mark.parametrize("document,words", [
    (_table(axis=[0.0, 0.0, 0.0]), ["machines.0.exciters.0.axis", "must not be [0, 0, 0]", "e [-]"]),
    (_table(sense=0), ["machines.0.exciters.0.sense", "+1", "-1", "right-hand rule"]),
    (_table(sense=2), ["machines.0.exciters.0.sense", "+1", "-1"]),
    (_table(eccentricity=-0.05), ["machines.0.exciters.0.eccentricity", "> 0", "l [m]"]),
    (_table(rotor_mass=0.0), ["machines.0.exciters.0.rotor_mass", "> 0", "m [kg]"]),
    (_table(axis=None), ["machines.0.exciters.0.axis"]),
    (_table(eccentricty=0.05), ["machines.0.exciters.0.eccentricty", "unknown key"]),
    ({**SHIPPED, "machines": [{**{k: v for k, v in SHIPPED["machines"][0].items() if k != "exciters"},
                                "exciter": SHIPPED["machines"][0]["exciters"]}]},
     ["machines.0.exciter", "did you mean exciters"]),
])
def test_bad_exciters_exit_3_naming_the_key(runner, tmp_path, document, words):
    import tomli_w

    path = tmp_path / "bad.toml"
    path.write_bytes(tomli_w.dumps(document).encode())
    result = runner.invoke(app, ["resonance", str(path)])
    assert result.exit_code == 3, result.stdout + result.stderr
    for word in words:
        assert word in result.stderr, (word, result.stderr)


def test_an_eccentricity_typed_in_mm_or_wider_than_the_block_is_warned_of():
    assert parse_scene(SHIPPED, "table.toml").plausibility_warnings() == []
    typed_in_mm = parse_scene(_table(eccentricity=50.0), "table.toml").plausibility_warnings()
    assert any(w.startswith("machines[0].exciters[0].eccentricity = 50 m") and "50 mm = 0.05 m" in w for w in typed_in_mm), typed_in_mm
    assert len([w for w in typed_in_mm if "exciters[0].eccentricity" in w]) == 1  # the range, not the block's rule too
    narrow = _table(eccentricity=0.9)
    narrow["block"]["width"] = 1.6  # half of it, 0.8 m, is the largest eccentricity that stays on the block
    wide = parse_scene(narrow, "table.toml").plausibility_warnings()
    assert any(w.startswith("machines[0].exciters[0].eccentricity = 0.9 m exceeds half the block's smaller side")
               for w in wide), wide
