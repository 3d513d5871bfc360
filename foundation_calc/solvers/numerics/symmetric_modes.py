"""Undamped modes of a linear structure: the generalised symmetric eigenproblem K φ = p² M φ.

M symmetric positive definite, K symmetric. Cholesky reduction: with M = L Lᵀ and v the
orthonormal eigenvectors of L⁻¹ K L⁻ᵀ, the shapes φ = L⁻ᵀ v are mass-normalised (φᵀ M φ = 1) and
the eigenvalues p² are those of the reduced symmetric matrix (solved by ``numpy.linalg.eigh``).
Shared by the rigid-body core (6 DOF, :mod:`~foundation_calc.solvers.rigid_body.modes`) and the
forcing weights of the crank foundation's 3 DOF (:mod:`.modal_forcing`).
"""

from __future__ import annotations

import numpy as np


def symmetric_modes(K, M, scale=None) -> tuple[np.ndarray, np.ndarray]:
    """p² (ascending, units of K/M) and mass-normalised shapes (columns) of K φ = p² M φ, for one
    (D, D) pair or stacks (..., D, D). Only the symmetric parts of K and M are used.

    ``scale``: optional diagonal matrix S (D, D) (or a stack (..., D, D)) of coordinate scales; the problem is solved in
    the coordinates q = S⁻¹ u (S K S, S M S: rotations scaled by a length to the size of the
    translations, say) and the shapes are returned in the original ones (φ = S L⁻ᵀ v), the
    eigenvalues unchanged.

    >>> p2, phi = symmetric_modes(np.diag([8.0, 9.0]), np.diag([2.0, 1.0]))
    >>> np.round(p2, 12).tolist(), np.round(phi.T @ np.diag([2.0, 1.0]) @ phi, 12).tolist()
    ([4.0, 9.0], [[1.0, 0.0], [0.0, 1.0]])

    Raises
    ------
    numpy.linalg.LinAlgError
        when M is not positive definite in double precision (the callers name the cause).
    """
    if scale is not None:  # S A S of a diagonal S (or a stack of them), element by element
        s = np.diagonal(scale, 0, -2, -1)
        outer = s[..., :, None] * s[..., None, :]
        M, K = M * outer, K * outer
    Li = np.linalg.inv(np.linalg.cholesky(0.5 * (M + np.swapaxes(M, -1, -2))))
    p2, v = np.linalg.eigh(Li @ (0.5 * (K + np.swapaxes(K, -1, -2))) @ np.swapaxes(Li, -1, -2))
    back = np.swapaxes(Li, -1, -2) if scale is None else s[..., :, None] * np.swapaxes(Li, -1, -2)
    return p2, back @ v


__all__ = ["symmetric_modes"]
