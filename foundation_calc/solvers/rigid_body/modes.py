"""Undamped modes of a rigid body on springs: K v = p² M v.

Source: the generalised symmetric eigenproblem of a linear undamped system; M symmetric positive
definite, K symmetric. Solved by Cholesky reduction
(:func:`~foundation_calc.solvers.numerics.symmetric_modes.symmetric_modes`), with the rotations
scaled by a length of the body so that translations and rotations are alike in size (the
eigenvalues do not change).
"""

from __future__ import annotations

import numpy as np

from foundation_calc.errors import ConvergenceError
from foundation_calc.solvers.numerics.symmetric_modes import symmetric_modes
from foundation_calc.solvers.rigid_body.inertia import diagonal_matrices, skews

#: Names of the six coordinates, in order: translations of O, rotations about x, y, z.
MOTIONS = ("x", "y", "z", "rx", "ry", "rz")


def eigen(K, M, length) -> tuple[np.ndarray, np.ndarray]:
    """p² [rad²/s²] (ascending) and mass-normalised shapes (columns, vᵀ M v = 1) of K v = p² M v,
    for one 6×6 pair or stacks (..., 6, 6); ``length`` [m]: a size of the body (the scale of the
    rotations), one value or one per pair of the stack (...).

    >>> p2, v = eigen(np.diag([4.0, 9.0, 1.0, 1.0, 1.0, 1.0]), np.eye(6), 1.0)
    >>> p2.tolist()
    [1.0, 1.0, 1.0, 1.0, 4.0, 9.0]

    Raises
    ------
    ConvergenceError
        when M is not positive definite in double precision.
    """
    inverse = 1.0 / np.asarray(length, dtype=float)[..., None]
    D = diagonal_matrices(np.concatenate([np.ones_like(inverse)] * 3 + [inverse] * 3, axis=-1))
    try:
        p2, shapes = symmetric_modes(K, M, D)
    except np.linalg.LinAlgError:
        raise ConvergenceError(
            "the 6-DOF natural frequencies cannot be computed in double precision: the body's"
            " masses, sizes and stiffnesses span too many orders of magnitude"
        ) from None
    return p2, shapes


def dominant_motions(shapes, m, r_G, J_G) -> np.ndarray:
    """Index into :data:`MOTIONS` of the motion holding the largest share of each mode's kinetic
    energy: translation of the centre of mass (m u_G²) or rotation about a central axis
    (J_G,ii θ_i²); ``shapes`` (6, n) about O, m [kg], r_G [m] from O, J_G central moments (3,)
    [kg m²]; stacks (..., 6, n), (...), (..., 3), (..., 3) give (..., n)."""
    at_cog = shapes[..., :3, :] - skews(np.asarray(r_G, dtype=float)) @ shapes[..., 3:, :]
    energy = np.concatenate([np.asarray(m, dtype=float)[..., None, None] * at_cog**2,
                             np.asarray(J_G, dtype=float)[..., :, None] * shapes[..., 3:, :] ** 2], axis=-2)
    return np.argmax(energy, axis=-2)


__all__ = ["MOTIONS", "dominant_motions", "eigen"]
