"""The rigid-body core against the platform's own assembly, and its parts against first principles.

The platform builds its mean mass matrix from the rotors' time-dependent terms averaged over a
revolution (Fourier coefficient 0) and its springs from the corners; the core builds the same
from bodies (a rotor averages to a ring: m l² about its axis, m l²/2 across) and from springs
carried to O one at a time. Equal to round-off (1e-12 relative: a few additions in another order).
"""

from __future__ import annotations

import numpy as np
import pytest

from foundation_calc.solvers.platform.dynamics import (
    RigidPlatform,
    inertia_about_corner,
    natural_frequencies,
    periodic_system,
    rotor,
    spring_stiffness,
)
from foundation_calc.solvers.rigid_body.inertia import bodies_mass_matrix, block_inertia, centre_of_mass
from foundation_calc.solvers.rigid_body.kinematics import load_at, point_map, spring_at, weight_tilt
from foundation_calc.solvers.rigid_body.modes import eigen

R_C = (1.4, 1.1, 0.65)
J_C = block_inertia(2e4, 3.0, 2.0, 1.3)
STIFFNESS = np.array([[6.2e7, 6.0e7, 1.0e8], [6.1e7, 1.2e8, 1.1e8], [5.0e7, 1.3e8, 0.9e8], [6.5e7, 6.3e7, 1.05e8]])


def _platform_and_rotors():
    platform = RigidPlatform(2e4, R_C, inertia_about_corner(2e4, R_C, J_C), 3.0, 2.0, STIFFNESS, 0.0, 9.81)
    rotors = (rotor(25.0, 0.2, (0.3, 0.2, 2.6), 0.4, 0.3, 157.0, 0.1), rotor(10.0, 0.1, (2.0, 1.5, 1.0), 0.0, 0.0, -90.0, 0.0))
    return platform, rotors


def _ring(rotor) -> np.ndarray:
    """Central inertia of a rotor's mass spread over its circle: m l²/2 (I + e eᵀ) [kg m²]."""
    e = rotor.part.axes()[2]
    return rotor.part.m * rotor.part.l**2 / 2.0 * (np.eye(3) + np.outer(e, e))


def test_core_mass_matrix_is_the_platforms_mean_mass_matrix():
    platform, rotors = _platform_and_rotors()
    system = periodic_system(platform, rotors)
    core = bodies_mass_matrix(
        [platform.M] + [r.part.m for r in rotors], [R_C] + [r.part.rho for r in rotors], [np.diag(J_C)] + [_ring(r) for r in rotors]
    )
    np.testing.assert_allclose(core, system.mass[0].real, rtol=1e-12, atol=1e-12 * np.abs(core).max())


def test_core_springs_and_weight_are_the_platforms_mean_stiffness():
    platform, rotors = _platform_and_rotors()
    system = periodic_system(platform, rotors)
    springs = sum(spring_at(corner, np.diag([*c, 0.0, 0.0, 0.0])) for corner, c in zip(platform.corners, STIFFNESS))
    np.testing.assert_allclose(springs, spring_stiffness(platform), rtol=1e-12, atol=1e-6)
    moment = platform.M * R_C[2] + sum(r.part.m * r.part.rho[2] for r in rotors)
    W = 9.81 * (platform.M + sum(r.part.m for r in rotors))
    core = springs + weight_tilt(W, moment / (platform.M + sum(r.part.m for r in rotors)))
    np.testing.assert_allclose(core, system.stiff[0].real, rtol=1e-12, atol=1e-12 * np.abs(core).max())


def test_core_modes_are_the_platforms_natural_frequencies():
    platform, rotors = _platform_and_rotors()
    system = periodic_system(platform, rotors)
    p2, _ = eigen(system.stiff[0].real, system.mass[0].real, 3.6)
    np.testing.assert_allclose(np.sqrt(p2), natural_frequencies(platform, rotors).frequencies, rtol=1e-12)


def test_centre_of_mass_inverts_the_parallel_axes():
    M = bodies_mass_matrix([3.0, 5.0], [(1.0, -2.0, 0.5), (0.2, 0.4, 2.0)], [(1.0, 2.0, 3.0), (0.5, 0.5, 0.5)])
    m, r, J = centre_of_mass(M)
    r_expected = (3.0 * np.array([1.0, -2.0, 0.5]) + 5.0 * np.array([0.2, 0.4, 2.0])) / 8.0
    assert m == 8.0
    np.testing.assert_allclose(r, r_expected, rtol=1e-14)
    # the central inertia is positive definite and symmetric
    assert np.all(np.linalg.eigvalsh(J) > 0.0)
    np.testing.assert_allclose(J, J.T, atol=1e-14)


@pytest.mark.parametrize("p", [(0.3, -1.2, 2.0), (-4.0, 0.5, 0.0)])
def test_a_load_does_the_virtual_work_of_the_point_it_acts_on(p):
    """Qᵀ δq equals F · δu_P + M · δθ for any virtual motion δq (the definition of Q)."""
    rng = np.random.default_rng(3)
    F, M, dq = rng.normal(size=3), rng.normal(size=3), rng.normal(size=6)
    assert load_at(p, F, M) @ dq == pytest.approx(F @ (point_map(p) @ dq) + M @ dq[3:], rel=1e-13)
