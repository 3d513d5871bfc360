"""A ``platform`` scene read as a block on its isolators (``PlatformScene.as_block``) by the
commands of the one rigid body: ``fcalc resonance``, ``amplitudes``, ``sweep --speed``, ``soil``.

Independent references, written here:

- the six natural frequencies by a brute-force generalised eigen-solve of a 6 × 6 pair assembled
  here about O1 from the scene file's numbers and ``fcalc platform``'s designed stiffnesses c_ij
  and exciter point (a, b, c): the platform's body (central inertia given, or a homogeneous box
  A × B × H), the rotor as a ring m l²/2 (I + e eᵀ) on its vertical axis, the twelve springs at
  the corners carried to O1 (K = Σ T_iᵀ diag(c_i) T_i) less the weight's tilt W z_G in rocking.
  Tolerance 1e-9 relative: two eigen-solves of the same well-conditioned pair in double precision;
- the amplitudes by ``fcalc platform``'s own verification (its harmonic balance about O1): an
  undamped design translates on a circle, which the block's exact periodic solution and its first
  approximation both give; 1e-9 of u, as the block built by hand in tests/test_block_exciters.py;
- the block itself against that test's hand-built twin (``_platform_twin``: the platform's body
  less 1 kg as the block, the 1 kg as the exciter's frame): the same mass and stiffness matrices
  to 1e-12 of their largest entries (they differ by the split of one body's mass) and the same loads;
- an extra exciter's rotating force against its position written from Eq. (1.3) of paper 001,
  L = l (t1 cos θ + t2 sin θ), θ = σ ω_j t + φ0 (round-off of sin, cos: 1e-12).
"""

from __future__ import annotations

import copy
import math
import tomllib

import numpy as np
import pytest

from foundation_calc.scenes import load_scene, parse_scene
from tests.conftest import CONFIGS
from tests.test_block_exciters import _platform_twin

G = 9.81


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