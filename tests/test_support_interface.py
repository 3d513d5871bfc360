"""A support is one module: a toy support defined only here (constant springs and dashpots at O,
coupled sway-rocking), handed to :func:`foundation_calc.solvers.supports.register` as a new
module's builder would be, runs through fc.check, fc.soil, fc.resonance, fc.amplitudes and
fc.report with no other edit, and its numbers are checked independently: the modes by a
brute-force generalized eigen-solve of the 6 × 6 matrices, the amplitudes by a direct complex
solve of one harmonic. The block's mass matrix M and the machine's load Q are the body's and the
machine's (not the support's) and are taken from the scene's model."""

from __future__ import annotations

import numpy as np
import pytest
from scipy.linalg import eigh

import foundation_calc as fc
from foundation_calc.solvers.constants import GRAVITY
from foundation_calc.solvers.supports import register, unregister
from foundation_calc.solvers.supports.base import Assumption, AtO, SoilSection, Validity
from foundation_calc.solvers.supports.sheet import Given, HandCalc, Step, Text

#: The toy's springs [N/m, N/rad, N m/rad] and dashpots at O, a sway-rocking coupling off the diagonal.
K_TOY = np.diag([2.0e9, 1.8e9, 3.0e9, 2.0e10, 3.0e10, 1.5e10])
K_TOY[0, 4] = K_TOY[4, 0] = -1.0e9
C_TOY = np.diag([2.0e7, 1.9e7, 3.0e7, 4.0e7, 6.0e7, 3.0e7])
C_TOY[0, 4] = C_TOY[4, 0] = -5.0e6
OFF = 1.0 - np.eye(6)

SCENE = """
kind = "block_foundation"
name = "toy"

[block]
length = 5.0
width = 3.0
height = 1.6
density = 2400.0

[[machines]]
name = "fan"
mass = 9.0e3
cog = [1.4, 0.0, 2.6]
inertia = [4.0e3, 6.0e3, 6.0e3]
speed_rpm = 990.0

[machines.unbalance]
balance_grade_mm_s = 6.3
rotor_mass = 2.5e3
axis = [1.0, 0.0, 0.0]
at = [1.8, 0.0, 2.7]

[soil]
method = "springs"
stiffness = [1.0e9, 1.0e9, 1.0e9, 1.0e10, 1.0e10, 1.0e10]
"""


class Toy:
    """Constant springs and dashpots at O: the whole of a support's interface."""

    label = "toy"
    method = "toy"
    unscaled = None
    frequency_dependent = False

    def impedance(self, omega) -> AtO:
        shape = np.shape(omega)
        six = (lambda X: np.broadcast_to(np.diagonal(X), shape + (6,)))
        full = (lambda X: np.broadcast_to(X * OFF, shape + (6, 6)))
        return AtO(six(K_TOY), six(C_TOY), (full(K_TOY), full(C_TOY)))

    def validity(self) -> Validity:
        return Validity("toy", None, "", "the toy's springs are constant: no range of a0 applies")

    def a0(self, omega):
        return None, "no a0"

    def soil_section(self, speeds) -> SoilSection:
        return SoilSection({"toy": {"K_x,ry": K_TOY[0, 4]}}, ("The toy's springs couple x and ry.",))

    def assumptions(self) -> tuple:
        return (Assumption("soil", "The toy support: constant springs and dashpots at O, coupled (x with ry)."
                                   " Frequency-independent."),)

    def sheet(self, model, orders) -> list:
        return [HandCalc("The toy's vertical spring", (Given("k_1", 1.5e9, "N/m", "half the toy's spring"),
                                                       Step("K_z", "2*k_1", "N/m", "[toy]", "the toy's vertical spring"))),
                Text("The toy support's springs are constant.")]


def build(scene, L, B, masses):
    return Toy() if scene.name == "toy" else None


@pytest.fixture(scope="module")
def toy(tmp_path_factory):
    """The toy scene's file, with the toy registered while the module's tests run."""
    path = tmp_path_factory.mktemp("toy") / "toy.toml"
    path.write_text(SCENE, encoding="utf-8")
    register(build)
    yield path
    unregister(build)


def _tilt(M):
    """The weight's tilt W z_G on the rocking entries, from M's first moment (independent of the model's K)."""
    tilt = np.zeros((6, 6))
    tilt[3, 3] = tilt[4, 4] = -GRAVITY * M[0, 4]  # W z_G = M g (S_y/M)
    return tilt


def test_soil_shows_the_toys_springs(toy):
    doc = fc.soil(toy).to_dict()
    assert doc["method"] == "toy" and doc["frequency_dependent"] is False
    assert [row["K"] for row in doc["springs"]] == pytest.approx(np.diagonal(K_TOY).tolist(), rel=1e-12)
    assert [row["C"] for row in doc["springs"]] == pytest.approx(np.diagonal(C_TOY).tolist(), rel=1e-12)
    assert doc["toy"] == {"K_x,ry": K_TOY[0, 4]} and doc["at_frequencies"] == []


def test_resonance_is_the_eigen_solve_of_the_toys_springs(toy):
    """Undamped modes: K v = p² M v with K the toy's springs less the weight's tilt; both are
    symmetric eigen-solves of the same 6 × 6 matrices (round-off: 1e-9)."""
    model = fc.load(toy).model.model()
    p = np.sqrt(eigh(K_TOY + _tilt(model.M), model.M, eigvals_only=True))
    found = [m["frequency"]["omega"] for m in fc.resonance(toy).to_dict()["modes"]]
    assert sorted(found) == pytest.approx(p, rel=1e-9)


def test_amplitudes_are_the_harmonic_solve_with_the_toys_dashpots(toy):
    """One machine, one order: Z = (K − Ω² M + iΩ C)⁻¹ Q and G's peak displacement |(T_G Z)_i| (1e-9)."""
    scene = fc.load(toy).model
    model = scene.model()
    (excitation,) = scene.excitations()
    W = excitation.omega
    Z = np.linalg.solve(K_TOY + _tilt(model.M) - W**2 * model.M + 1j * W * C_TOY, excitation.Q[0])
    x, y, z = model.cog
    T = np.hstack([np.eye(3), -np.array([[0.0, -z, y], [z, 0.0, -x], [-y, x, 0.0]])])  # u_P = u + θ × r_P
    peak = np.abs(T @ Z)
    found = fc.amplitudes(toy).to_dict()["points"]["G"]["displacement_peak"]
    assert [found[a] for a in "xyz"] == pytest.approx(peak, rel=1e-9)


def test_check_judges_the_toy(toy):
    result = fc.check(toy)
    assert result.exit_code in (0, 1)
    assert "the toy's springs are constant" in str(result.to_dict())


def test_sheet_shows_the_toys_hand_calculation(toy, tmp_path):
    out = tmp_path / "toy.md"
    fc.report(toy, output=out)
    text = out.read_text(encoding="utf-8")
    assert "The toy's vertical spring" in text and "The toy support's springs are constant." in text
    assert "| soil | The toy support: constant springs and dashpots at O, coupled (x with ry)." in text  # its own assumption
    assert "uncoupled" not in text  # and no footing's
    (unchecked,) = (line for line in text.splitlines() if line.startswith("| not checked |"))
    assert "The support's static capacity and settlement" in unchecked  # the toy says nothing: the default does
    assert "bearing pressure" not in unchecked and "W/K" not in unchecked  # and no footing's terms
    assert "| K\\_z | 2·k\\_1 | 2 × 1.500·10⁹ | 3.000·10⁹ | N/m | \\[toy\\] |" in text  # the chain, evaluated
