"""The block's torsion about z by each soil method, pinned by values worked by hand.

The coefficients method (Barkan) gives K_rz = c_ψ J_z with J_z = I_x + I_y the polar second
moment of the base and c_ψ = 1.5 c_x by default; SP 26 gives C_ψ = C_z on J_z and ξ_ψ = 0.3 ξ_z.
Both rules are as usually quoted, not read from their printed texts (docs/soil.md, "Block
foundations"); these tests pin what fcalc does with them, not that the rules are right. Lysmer's
torsion is pinned by Reissner-Sagoci's exact spring in tests/test_soil_independent.py.

The base here: L = 4 m, B = 2 m, A = 8 m², I_x = L B³/12 = 8/3 m⁴, I_y = B L³/12 = 32/3 m⁴,
J_z = 40/3 m⁴. The block 4 × 2 × 1.5 m of concrete 2400 kg/m³ weighs 28 800 kg, its moment of
inertia about its vertical axis 28 800 (4² + 2²)/12 = 48 000 kg m²; a machine of 6 t on that axis
with its own 1 000 kg m² about it makes I_zz = 49 000 kg m². With the centre of mass on the
vertical axis through O the twist about z couples with no other motion, so its frequency is
sqrt(K_rz/I_zz) exactly (the 6-DOF eigen-solve must give it to round-off, 1e-9).
"""

from __future__ import annotations

import math

import pytest

from foundation_calc.scenes import parse_scene
from foundation_calc.scenes.block_soil import BlockSoil
from foundation_calc.solvers.supports.footing_springs import six_springs
from foundation_calc.solvers.block.response import block_modes

L, B = 4.0, 2.0
I_ZZ = 49000.0  # kg m², module docstring


def _coefficients(**keys) -> BlockSoil:
    return BlockSoil.model_validate({"method": "coefficients", "c_z": 5.0e7, "c_x": 3.0e7, **keys})


def test_coefficients_give_the_six_springs_by_hand():
    """c_z = 5e7, c_x = 3e7 N/m³, c_φ = c_z: K_x = K_y = 3e7 · 8 = 2.4e8 N/m, K_z = 5e7 · 8 = 4e8 N/m,
    K_rx = 5e7 · 8/3 = 1.333333e8, K_ry = 5e7 · 32/3 = 5.333333e8, K_rz = 1.5 · 3e7 · 40/3 = 6e8 N m/rad."""
    springs, ratios = six_springs(_coefficients(damping=[0.1, 0.08, 0.05]), L, B, 34800.0, (1.0, 1.0, 1.0))
    expected = [2.4e8, 2.4e8, 4.0e8, 1.333333e8, 5.333333e8, 6.0e8]
    assert springs == pytest.approx(expected, rel=3e-7)  # 1.333333 typed to 7 digits
    assert ratios == [0.08, 0.08, 0.1, 0.05, 0.05, 0.05]


def test_a_given_torsion_coefficient_acts_on_the_polar_moment():
    """c_ψ = 4.2e7 N/m³: K_rz = 4.2e7 · 40/3 = 5.6e8 N m/rad; ξ_ψ given as the fourth ratio."""
    springs, ratios = six_springs(_coefficients(c_psi=4.2e7, damping=[0.1, 0.08, 0.05, 0.03]), L, B, 1.0, (1.0,) * 3)
    assert springs[5] == pytest.approx(5.6e8, rel=1e-12)
    assert ratios[5] == 0.03


def test_sp26_torsion_by_hand():
    """E = 30 MPa, sand (b0 = 1 1/m): C_z = 3e7 (1 + sqrt(10/8)) = 6.354102e7 N/m³, K_rz = C_z J_z =
    8.472136e8 N m/rad; total mass 81 549.44 kg on 8 m² is p_m = 100 kPa (g = 9.80665), so ξ_z =
    2/sqrt(100) = 0.2 and ξ_ψ = 0.3 ξ_z = 0.06."""
    from foundation_calc.solvers.constants import GRAVITY

    soil = BlockSoil.model_validate({"method": "sp26", "deformation_modulus": 3.0e7, "soil_class": "sand"})
    M = 1.0e5 * 8.0 / GRAVITY
    springs, ratios = six_springs(soil, L, B, M, (1.0e5, 1.0e5, 1.0e5))
    assert springs[5] == pytest.approx(8.472136e8, rel=1e-7)
    assert ratios[5] == pytest.approx(0.06, rel=1e-12)


def _scene(soil: dict):
    return parse_scene({
        "kind": "block_foundation",
        "block": {"length": L, "width": B, "height": 1.5, "density": 2400.0},
        "machines": [{"name": "fan", "mass": 6000.0, "cog": [0.0, 0.0, 2.0], "inertia": [1000.0, 1000.0, 1000.0],
                      "speed_rpm": 300.0, "loads": [{"order": 1, "force": [1.0e3, 0.0, 0.0], "at": [0.0, 0.0, 2.0]}]}],
        "soil": soil,
    })


@pytest.mark.parametrize(("soil", "omega"), [
    # sqrt(6e8/49 000) = sqrt(12 244.90): Barkan's default c_ψ = 1.5 c_x
    ({"method": "coefficients", "c_z": 5.0e7, "c_x": 3.0e7}, 110.6567),
    # sqrt(5.6e8/49 000) = sqrt(11 428.57)
    ({"method": "coefficients", "c_z": 5.0e7, "c_x": 3.0e7, "c_psi": 4.2e7}, 106.9045),
    # Reissner-Sagoci on the circle of the base's polar moment: R = (8 · 20/(6π))^¼ = 1.706887 m,
    # k_ψ = 16 · 7.2e7 · R³/3 = 1.909613e9 N m/rad; sqrt(k_ψ/49 000)
    ({"method": "lysmer", "shear_wave_velocity": 200.0, "density": 1800.0, "poisson": 0.33}, 197.4125),
], ids=["coefficients-default", "coefficients-given", "lysmer"])
def test_the_blocks_torsional_frequency_by_hand(soil, omega):
    frequencies = block_modes(_scene(soil).model()).frequencies
    nearest = min(frequencies, key=lambda p: abs(p - omega))
    assert nearest == pytest.approx(omega, rel=5e-7)  # the hand value's 7 digits


def test_the_torsional_inertia_of_the_scene_is_the_hand_value():
    """The premise of the frequencies above: I_zz about the vertical through O is 49 000 kg m²."""
    model = _scene({"method": "coefficients", "c_z": 5.0e7, "c_x": 3.0e7}).model()
    assert float(model.M[5, 5]) == pytest.approx(I_ZZ, rel=1e-12)
    assert math.isclose(float(model.M[5, 0]), 0.0, abs_tol=1e-9)
