"""A machine of parts alone: ``[[machines]] mass = 0`` for a machine whose parts carry mass (an
exciter's rotors), whose frame is part of the block (a platform's exciters).

Independent reference, written here: the 6×6 mass matrix about O of the block (a homogeneous box)
and the two rotors as rings m l²/2 (I + e eᵀ) (paper 001, the mean of Eq. (1)), with no frame body;
the six natural frequencies by a brute-force generalised eigen-solve of the diagonal springs less
the weight's tilt W z_G against that matrix. Tolerances: 1e-12 of the largest entry for the matrix
(the same sums in another order), 1e-9 relative for the frequencies (two eigen-solves of one
well-conditioned pair, measured 1e-15).
"""

from __future__ import annotations

import json

import numpy as np
import pytest
import scipy.linalg

import foundation_calc as fc
from foundation_calc.cli.app import app
from tests.test_machine_parts import _body
from tests.conftest import CONFIGS

L, B, H, RHO = 4.0, 2.0, 0.6, 2400.0
SPRINGS = [6.0e7, 6.0e7, 9.0e7, 4.0e8, 8.0e8, 5.0e8]
ROTOR_MASS, ECCENTRICITY, COG = 30.0, 0.05, [0.0, 0.0, 0.8]
ROTORS = ([0.15, 0.0, 0.8], [-0.15, 0.0, 0.8])  # two shafts along y, turning opposite ways
G_ACC = 9.81  # [m/s²] the project's gravity


def _scene(machine: str, exciters: bool = True) -> str:
    """A block on springs with one machine, ``machine`` its own keys, with the two rotors of a
    directional exciter if ``exciters``."""
    rotors = "" if not exciters else "".join(f"""
[[machines.exciters]]
rotor_mass = {ROTOR_MASS}
eccentricity = {ECCENTRICITY}
axis = [0.0, 1.0, 0.0]
at = {at}
sense = {sense}
""" for at, sense in zip(ROTORS, (1, -1)))
    return f"""kind = "block_foundation"
name = "exciters alone"
[block]
length = {L}
width = {B}
height = {H}
density = {RHO}
[[machines]]
name = "directional exciter"
cog = {COG}
speed_rpm = 1500.0
{machine}
{rotors}
[soil]
method = "springs"
stiffness = {SPRINGS}
dashpot = [0.0, 0.0, 0.0, 0.0, 0.0, 0.0]
"""


def _hand_mass_matrix():
    """The block and the two rotors about O (:func:`tests.test_machine_parts._body`), no frame."""
    m_b = L * B * H * RHO
    block = _body(m_b, [0.0, 0.0, H / 2.0], m_b / 12.0 * np.array([B * B + H * H, L * L + H * H, L * L + B * B]))
    ring = 0.5 * ROTOR_MASS * ECCENTRICITY**2 * np.array([1.0, 2.0, 1.0])  # m l²/2 (I + e eᵀ), e = y
    return block + sum(_body(ROTOR_MASS, at, ring) for at in ROTORS)


@pytest.fixture
def frameless(tmp_path):
    path = tmp_path / "frameless.toml"
    path.write_text(_scene("mass = 0.0"), encoding="utf-8")
    return path


def test_a_machine_of_rotors_alone_is_the_block_and_its_rotors(frameless):
    M = _hand_mass_matrix()
    model = fc.load(frameless).model.model()
    np.testing.assert_allclose(model.M, M, rtol=0, atol=1e-12 * np.abs(M).max())
    assert model.mass == pytest.approx(L * B * H * RHO + 2 * ROTOR_MASS, rel=1e-15)

    z_G = -M[3, 1] / M[0, 0]  # M_θu = Σ m [r]×: its (x, y) entry is -m z
    K = np.diag(SPRINGS)
    K[3, 3] -= M[0, 0] * G_ACC * z_G
    K[4, 4] -= M[0, 0] * G_ACC * z_G
    expected = np.sqrt(scipy.linalg.eigh(K, M, eigvals_only=True))
    found = fc.resonance(frameless).to_dict()
    np.testing.assert_allclose(sorted(m["frequency"]["omega"] for m in found["modes"]), expected, rtol=1e-9)


def test_a_machine_of_parts_alone_is_not_judged_a_mass_typed_in_t(frameless):
    assert not [f for f in fc.load(frameless).model.plausibility_findings() if f.key.endswith(".mass")]


@pytest.mark.parametrize(("machine", "key", "why"), [
    # given loads carry no mass: a load-only machine keeps its frame mass
    ("mass = 0.0\n[[machines.loads]]\norder = 1\nforce = [0.0, 0.0, 500.0]", "machines[0].mass = 0 kg", "parts carry no mass"),
    # an unbalance's rotor is part of the machine's mass, not a part with mass of its own
    ("mass = 0.0\n[machines.unbalance]\nbalance_grade_mm_s = 6.3\nrotor_mass = 100.0\naxis = [1.0, 0.0, 0.0]",
     "machines[0].mass = 0 kg", "parts carry no mass"),
    # no frame, no moment of inertia of its own
    ("mass = 0.0\ninertia = [10.0, 10.0, 10.0]", "machines[0].inertia", "needs machines[0].mass > 0 kg"),
], ids=["loads alone", "unbalance alone", "inertia without a frame"])
def test_a_machine_without_mass_anywhere_is_refused_by_its_key(runner, tmp_path, machine, key, why):
    path = tmp_path / "refused.toml"
    path.write_text(_scene(machine, exciters="inertia" in machine), encoding="utf-8")
    result = runner.invoke(app, ["resonance", str(path), "--json"])
    assert result.exit_code == 3, result.stdout + result.stderr
    assert key in result.stderr and why in result.stderr and "kg" in result.stderr
    assert "Traceback" not in result.stderr
    # a script reads the key at fault from the problem's field, not from its sentence
    checked = runner.invoke(app, ["check", str(path), "--json"])
    (problem,) = json.loads(checked.stdout)["scenes"][0]["checks"][0]["problems"]
    assert problem["field"] == key.replace("[", ".").replace("]", "").removesuffix(" = 0 kg")


def test_the_platform_read_as_a_block_is_its_body_exactly():
    """No share of the platform's mass is left to the exciters' machine: the block is its body."""
    platform = fc.load(CONFIGS / "platform_paper_example.toml").model
    block = platform.as_block()
    assert block.block.mass == platform.platform.mass
    assert [m.mass for m in block.machines] == [0.0] * len(block.machines)


@pytest.mark.parametrize(("cut", "added", "field"), [
    ("[soil]", "", "soil"),  # no support at all
    ("", "\n[isolation]\ndamping_ratio = 0.05\n", "isolation"),  # damping of isolators on soil
], ids=["no support", "isolation on soil"])
def test_a_rule_about_one_table_names_that_table_as_the_field(runner, tmp_path, cut, added, field):
    """A rule of the whole scene about one of its tables names it in ``check --json``'s problem."""
    text = (CONFIGS / "block_two_machines.toml").read_text(encoding="utf-8")
    if cut:
        start = text.index(cut)
        end = text.index("\n[", start + 1)
        text = text[:start] + text[end + 1:]
    path = tmp_path / "scene.toml"
    path.write_text(text + added, encoding="utf-8")
    result = runner.invoke(app, ["check", str(path), "--json"])
    assert result.exit_code == 3, result.stdout
    (problem,) = json.loads(result.stdout)["scenes"][0]["checks"][0]["problems"]
    assert problem["field"] == field, problem
