"""A block on ``[[isolators]]`` (an inertia block on spring isolators): its modes, its response,
its static deflections, its twin the platform, and the scene's validation.

Independent references, written here and nowhere else:

- M about O of the homogeneous block (m = ρ L B H, centre at H/2 above O, central moments
  m (b² + c²)/12) and of every machine (its mass at its centre, its central moments), each carried
  to O by the kinetic energy of a rigid body, M = [[m I, m Sᵀ], [m S, J_c + m (|r|² I - r rᵀ)]],
  S the cross-product matrix of r;
- K as the sum over every isolator's three springs of c g gᵀ, g = (e, r_i × e) the gradient of the
  spring's elongation δ = e · (u + θ × r_i), less the weight's tilt W z_G on θ_x and θ_y (the
  weight's potential under a small rotation about O, -W z_G (θ_x² + θ_y²)/2);
- the natural frequencies by ``scipy.linalg.eigh(K, M)``; the response by one complex 6 × 6
  solve with the hysteretic springs K_s (1 + iη) + iΩ β K_s; the static deflections by a real
  solve and the equilibrium Σ loads = W.

Tolerances: 1e-9 relative for the eigen- and linear solves (double round-off of well-conditioned
6 × 6 systems, and of the platform's own eigen-solve in its twin).
"""

from __future__ import annotations

import copy
import math
import tomllib

import numpy as np
import pytest
import scipy.linalg

import foundation_calc as fc
from foundation_calc.cli.app import app
from foundation_calc.scenes import load_scene, parse_scene
from foundation_calc.solvers.constants import GRAVITY
from tests.conftest import CONFIGS

ISOLATED = CONFIGS / "block_on_isolators.toml"
with open(ISOLATED, "rb") as _fh:
    SHIPPED = tomllib.load(_fh)


def _document(**changes) -> dict:
    document = copy.deepcopy(SHIPPED)
    for key, value in changes.items():
        if value is None:
            document.pop(key, None)
        else:
            document[key] = value
    return document


def _skew(r) -> np.ndarray:
    x, y, z = r
    return np.array([[0.0, -z, y], [z, 0.0, -x], [-y, x, 0.0]])


def _body(m, r, J_c) -> np.ndarray:
    r, S = np.asarray(r, dtype=float), _skew(r)
    M = np.zeros((6, 6))
    M[:3, :3], M[:3, 3:], M[3:, :3] = m * np.eye(3), m * S.T, m * S
    M[3:, 3:] = np.diag(J_c) + m * (r @ r * np.eye(3) - np.outer(r, r))
    return M


def _matrices(document) -> tuple[np.ndarray, np.ndarray, np.ndarray, float, np.ndarray]:
    """(M, K with the weight's tilt, the isolators' springs K_s alone, W, r_G) of a document
    whose block is given by height and density and whose machines carry no crank."""
    b = document["block"]
    m_b = b["density"] * b["length"] * b["width"] * b["height"]
    L, B, H = b["length"], b["width"], b["height"]
    bodies = [(m_b, [0.0, 0.0, H / 2.0], [m_b * (B * B + H * H) / 12.0, m_b * (L * L + H * H) / 12.0,
                                         m_b * (L * L + B * B) / 12.0])]
    bodies += [(mc["mass"], mc["cog"], mc["inertia"]) for mc in document["machines"]]
    M = sum(_body(*body) for body in bodies)
    mass = sum(body[0] for body in bodies)
    cog = sum(body[0] * np.asarray(body[1], dtype=float) for body in bodies) / mass
    K_s = np.zeros((6, 6))
    for isolator in document["isolators"]:
        r = np.asarray(isolator["position"], dtype=float)
        for e, c in zip(np.eye(3), isolator["stiffness"]):
            g = np.concatenate([e, np.cross(r, e)])
            K_s += c * np.outer(g, g)
    W = mass * GRAVITY
    K = K_s.copy()
    K[3, 3] -= W * cog[2]
    K[4, 4] -= W * cog[2]
    return M, K, K_s, W, cog


#: A second layout: five isolators on brackets above the base, unequal and coupled.
BRACKETS = [
    {"position": [-1.3, -0.9, 0.25], "stiffness": [2.0e5, 3.5e5, 4.5e5]},
    {"position": [1.25, -0.85, 0.25], "stiffness": [3.0e5, 2.5e5, 3.8e5]},
    {"position": [1.3, 0.9, 0.2], "stiffness": [2.2e5, 2.9e5, 4.1e5]},
    {"position": [-1.2, 0.95, 0.3], "stiffness": [2.6e5, 2.1e5, 4.4e5]},
    {"position": [0.1, 0.0, 0.0], "stiffness": [0.0, 0.0, 2.0e5]},
]


@pytest.mark.parametrize("isolators", [None, BRACKETS], ids=["shipped", "brackets"])
def test_natural_frequencies_are_the_eigen_solve_of_the_isolators_springs(isolators):
    document = _document(isolators=isolators) if isolators else _document()
    M, K, *_ = _matrices(document)
    expected = np.sqrt(scipy.linalg.eigh(K, M, eigvals_only=True))
    found = sorted(m["frequency"]["omega"] for m in fc.resonance(document).to_dict()["modes"])
    np.testing.assert_allclose(found, expected, rtol=1e-9)


def test_static_deflections_carry_the_weight():
    """Each isolator's deflection from K_s q = F_W, the loads k_z δ summing to the weight."""
    _, _, K_s, W, cog = _matrices(SHIPPED)
    q = np.linalg.solve(K_s, np.array([0.0, 0.0, -W, -W * cog[1], W * cog[0], 0.0]))
    r = np.array([i["position"] for i in SHIPPED["isolators"]])
    expected = -(q[2] + q[3] * r[:, 1] - q[4] * r[:, 0])
    found = fc.soil(ISOLATED).to_dict()["isolators"]
    np.testing.assert_allclose(found["static_deflection"], expected, rtol=1e-9)
    assert math.isclose(sum(found["static_load"]), W, rel_tol=1e-9)
    assert 0.015 < min(expected) and max(expected) < 0.025  # the catalogue's 25 mm series, under its rating
    grid = load_scene(ISOLATED).support().sheet(None, ())[0]  # the sheet's isolators table
    assert len(grid.head) == 1 + grid.values.shape[1] and grid.head[-2:] == ("δ_i [mm]", "load [kN]")
    np.testing.assert_allclose(grid.values[:, 3], expected * 1e3, rtol=1e-9)


def test_amplitude_at_a_point_is_the_complex_solve_with_hysteretic_springs():
    """One machine, one order: the peak of each direction is |Z_u + Z_θ × r_P| of
    (K_s (1 + iη) + iΩ β K_s - W z_G tilt - Ω² M) Z = (F, M + r_F × F)."""
    machine = {"name": "fan", "mass": 1.2e3, "cog": [0.45, 0.1, 0.95], "inertia": [250.0, 300.0, 300.0],
               "speed_rpm": 1480.0,
               "loads": [{"order": 1, "force": [400.0, 900.0, -700.0], "moment": [30.0, -50.0, 80.0],
                          "at": [0.6, 0.2, 1.0]}]}
    eta, beta = 0.06, 2.0e-3
    document = _document(machines=[machine], isolators=BRACKETS, isolation={"loss_factor": eta, "time_constant": beta})
    M, K, K_s, *_ = _matrices(document)
    omega = 1480.0 * math.pi / 30.0
    load = machine["loads"][0]
    Q = np.concatenate([load["force"], np.asarray(load["moment"]) + np.cross(load["at"], load["force"])])
    Z = np.linalg.solve(K + (1j * eta + 1j * omega * beta) * K_s - omega**2 * M, Q)
    found = fc.amplitudes(document).to_dict()["points"]
    for name, at in (("fan bearing", SHIPPED["points"][0]["at"]), ("G", found["G"]["at"])):
        u = Z[:3] + np.cross(Z[3:], at)
        peak = found[name]["displacement_peak"]
        np.testing.assert_allclose([peak[a] for a in "xyz"], np.abs(u), rtol=1e-9, atol=1e-15)


def test_the_platforms_isolators_and_body_as_a_block_give_its_natural_frequencies():
    """The platform's worked example (its design's twelve springs at the corners, its body and its
    rotor at the rotor's mean inertia, a ring m l² about its axis) as a block scene, O moved from
    the corner O1 to the centre of the base: the six frequencies of ``fcalc platform``."""
    platform_path = CONFIGS / "platform_paper_example.toml"
    scene = load_scene(platform_path)
    d = scene.design()
    shift = np.array([d.A / 2.0, d.B / 2.0, 0.0])
    corners = np.array([[0.0, 0.0, 0.0], [d.A, 0.0, 0.0], [d.A, d.B, 0.0], [0.0, d.B, 0.0]]) - shift
    axis = (np.array([d.a, d.b, d.c]) - shift).tolist()
    twin = {
        "kind": "block_foundation", "name": "the platform as a block",
        "block": {"length": d.A, "width": d.B, "mass": d.M, "cog": (np.array([d.xi, d.eta, d.zeta]) - shift).tolist(),
                  "inertia": list(scene.inertia)},
        "machines": [{"name": "exciter", "mass": d.m, "cog": axis,
                      "inertia": [d.m * d.l**2 / 2.0, d.m * d.l**2 / 2.0, d.m * d.l**2],
                      "speed_rpm": d.omega * 30.0 / math.pi,
                      "loads": [{"order": 1, "force": [d.m * d.l * d.omega**2, 0.0, 0.0], "at": axis}]}],
        "isolators": [{"position": r.tolist(), "stiffness": k.tolist()} for r, k in zip(corners, np.asarray(d.stiffness))],
        "isolation": {"loss_factor": scene.isolators.loss_factor},
    }
    found = sorted(m["frequency"]["omega"] for m in fc.resonance(twin).to_dict()["modes"])
    expected = sorted(m["omega"] for m in fc.platform(platform_path).to_dict()["natural_frequencies"])
    np.testing.assert_allclose(found, expected, rtol=1e-9)


def test_soil_shows_the_isolators_table_and_the_base_bears_no_pressure(runner):
    result = runner.invoke(app, ["soil", str(ISOLATED)], env={"COLUMNS": "80"})
    assert result.exit_code == 0, result.stderr
    assert "δ_static" in result.stdout and "load" in result.stdout and "η = 0.02" in result.stdout
    office = fc.amplitudes(_document(limits=SHIPPED["limits"] | {"bearing_pressure": 1.5e5})).to_dict()["office"]
    bearing = next(row for row in office if row["check"] == "bearing pressure")
    assert bearing["value"] is None and "not applicable" in bearing["text"]


def test_design_refuses_a_block_on_isolators_by_name(runner):
    result = runner.invoke(app, ["design", str(ISOLATED), "--vary", "block.length=2:4"])
    assert result.exit_code == 3, result.stdout + result.stderr
    assert "isolators" in result.stderr and "not sized by fcalc design" in result.stderr


def test_the_design_batch_refuses_a_block_on_isolators_as_the_command_does(runner):
    """The batch checker itself (:func:`foundation_calc.checks.design.block.evaluate`, what
    ``fc.design`` runs) refuses the scene with the command's error, not a numpy broadcast error."""
    from foundation_calc.checks.design.block import evaluate

    said = runner.invoke(app, ["design", str(ISOLATED), "--vary", "block.length=2:4"]).stderr
    with pytest.raises(fc.PhysicsError) as batch:
        evaluate(load_scene(ISOLATED), {"block.length": np.array([2.4, 2.6])})
    with pytest.raises(fc.PhysicsError) as api:
        fc.design(ISOLATED, vary=["block.length=2:4"])
    for raised in (batch.value, api.value):
        assert raised.exit_code == 3 and [p.field for p in raised.problems] == ["isolators"]
        assert " ".join(str(raised).split()) in " ".join(said.split())


def _moved(**changes):
    """The shipped isolators with each isolator's keys changed: index -> keys, or "all" -> keys."""
    isolators = copy.deepcopy(SHIPPED["isolators"])
    for where, keys in changes.items():
        for i in range(len(isolators)) if where == "all" else [int(where[1:])]:
            isolators[i] |= keys
    return isolators


_SOIL = {"method": "springs", "stiffness": [1e8, 1e8, 1e8, 1e8, 1e8, 1e8]}


@pytest.mark.parametrize("changes,words", [
    ({"isolators": _moved(i0={"stiffness": [-3.0e5, 3.0e5, 4.0e5]})}, ["isolators.0", "N/m", ">= 0"]),
    ({"isolators": _moved(i2={"stiffness": [3.0e5, 3.0e5, 0.0]})}, ["isolators.2", "k_z must be > 0"]),
    ({"isolators": SHIPPED["isolators"][:2]}, ["at least three [[isolators]]", "got 2"]),
    ({"isolators": [{"position": [x, 0.0, 0.0], "stiffness": [3e5, 3e5, 4e5]} for x in (-1.0, 0.0, 1.0)]},
     ["on one line", "free to turn"]),
    ({"isolators": _moved(all={"stiffness": [0.0, 0.0, 4.0e5]})}, ["without stiffness", "u_x", "k_x and k_y"]),
    ({"isolators": [{"position": [x, y, 0.0], "stiffness": [3e5, 3e5, 4e5]} for x in (0.6, 1.1) for y in (-0.7, 0.7)]},
     ["is pulled", "kN", "surround"]),
    ({"soil": _SOIL}, ["[[isolators]] or [soil]", "not both"]),
    ({"isolation": None}, ["[isolation]", "loss_factor", "damping_ratio"]),
    ({"isolation": {"loss_factor": 0.1, "damping_ratio": 0.01}}, ["isolation.loss_factor", "not both"]),
    ({"isolation": {"loss_factor": 1.5}}, ["isolation.loss_factor", "η [-]"]),
    ({"isolation": {"damping_ratio": 0.01, "damping": 0.02}}, ["isolation.damping"]),
    ({"isolators": _moved(i1={"stifness": [3e5, 3e5, 4e5]})}, ["isolators.1.stifness"]),
    ({"isolators": None, "isolation": None}, ["give [soil]", "[[isolators]]"]),
    ({"isolators": None, "soil": _SOIL}, ["[isolation] is the damping of [[isolators]]"]),
])
def test_bad_isolators_exit_3_naming_the_key(runner, tmp_path, changes, words):
    import tomli_w

    path = tmp_path / "bad.toml"
    path.write_bytes(tomli_w.dumps(_document(**changes)).encode())
    result = runner.invoke(app, ["resonance", str(path)])
    assert result.exit_code == 3, result.stdout + result.stderr
    for word in words:
        assert word in result.stderr, (word, result.stderr)


def test_isolators_too_close_for_the_weight_tip_the_block_over(runner, tmp_path):
    """Rocking spring Σ k_z y² = 6 × 4e5 × 0.08² = 1.5e4 N m/rad below W z_G = 2.1e4 N m/rad: exit 3."""
    import tomli_w

    path = tmp_path / "narrow.toml"
    narrow = [{"position": [x, y, 0.0], "stiffness": [3e5, 3e5, 4e5]} for x in (-1.05, 0.0, 1.05) for y in (-0.08, 0.08)]
    path.write_bytes(tomli_w.dumps(_document(isolators=narrow)).encode())
    result = runner.invoke(app, ["resonance", str(path)])
    assert result.exit_code == 3, result.stdout + result.stderr
    assert "tips over about x" in result.stderr and "isolators" in result.stderr


def test_a_catalogues_damping_ratio_is_the_loss_factor_twice_it():
    """ξ of a catalogue is η = 2 ξ: the same response, and each mode's damping ratio ξ where the
    springs alone store its energy (the weight's tilt, here under 2 % of the rocking springs, aside)."""
    as_ratio = fc.amplitudes(_document(isolation={"damping_ratio": 0.03})).to_dict()
    as_loss = fc.amplitudes(_document(isolation={"loss_factor": 0.06})).to_dict()
    for name, point in as_ratio["points"].items():
        for a in "xyz":
            assert math.isclose(point["displacement_peak"][a], as_loss["points"][name]["displacement_peak"][a], rel_tol=1e-12)
    np.testing.assert_allclose([m["damping_ratio"] for m in as_ratio["modes"]], 0.03, rtol=0.02)


def load_scene_document(document):
    return parse_scene(document, "isolators.toml")


def test_a_spring_rate_typed_in_N_per_mm_is_warned_of():
    isolators = _moved(i3={"stiffness": [300.0, 300.0, 400.0]})
    warnings = load_scene_document(_document(isolators=isolators)).plausibility_warnings()
    assert any(w.startswith("isolators[3].stiffness[0] = 300 N/m") and "N/mm" in w for w in warnings), warnings
    assert load_scene_document(SHIPPED).plausibility_warnings() == []


def test_a_run_up_on_hysteretic_isolators_is_damped_at_the_modes():
    """A loss factor's dashpots η K/|ω| vanish at rest only: the run-up, integrated on the
    isolators at each harmonic's frequency, is damped and not warned of; undamped springs are."""
    assert fc.runup(ISOLATED, time=1.0, down=1.0).to_dict()["warnings"] == []
    undamped = fc.runup(_document(isolation={"damping_ratio": 0.0}), time=1.0, down=1.0).to_dict()["warnings"]
    assert len(undamped) == 1 and "undamped" in undamped[0]
