"""Mass properties of rigid bodies about a reference point O.

Source: the parallel-axis (Huygens-Steiner) theorem and the kinetic energy of a rigid body in
small motion, T = ½ q'ᵀ M q', with u_G = u + θ × r for a body's centre of mass G at r from O:

    M = [[m I, -m [r]×], [m [r]×, J_O]],   J_O = J_G + m (|r|² I - r rᵀ)                (1)

([v]× is the cross-product matrix, :func:`skew`). Several bodies rigidly joined add their M.
"""

from __future__ import annotations

import numpy as np


def skew(v) -> np.ndarray:
    """Cross-product matrix: skew(v) @ w == v × w (complex v allowed).

    >>> skew([1.0, 2.0, 3.0]) @ np.array([0.0, 0.0, 1.0])
    array([ 2., -1.,  0.])
    """
    v = np.asarray(v)
    return np.array([[0 * v[0], -v[2], v[1]], [v[2], 0 * v[0], -v[0]], [-v[1], v[0], 0 * v[0]]])


def skews(v) -> np.ndarray:
    """:func:`skew` of each vector of a stack, shape (..., 3) -> (..., 3, 3)."""
    v = np.asarray(v)
    out = np.zeros(v.shape + (3,), dtype=v.dtype)
    out[..., 0, 1], out[..., 0, 2], out[..., 1, 2] = -v[..., 2], v[..., 1], -v[..., 0]
    out[..., 1, 0], out[..., 2, 0], out[..., 2, 1] = v[..., 2], -v[..., 1], v[..., 0]
    return out


def block_inertia(M, A, B, H):
    """Central principal moments of a homogeneous block A × B × H of mass M [kg m²], about
    axes along A, B, H: M (B² + H²)/12, M (A² + H²)/12, M (A² + B²)/12.

    >>> block_inertia(12.0, 1.0, 2.0, 3.0)
    (13.0, 10.0, 5.0)
    """
    return M * (B * B + H * H) / 12.0, M * (A * A + H * H) / 12.0, M * (A * A + B * B) / 12.0


def diagonal_matrices(v) -> np.ndarray:
    """Diagonal matrices of the vectors of a stack, shape (..., n) -> (..., n, n).

    >>> diagonal_matrices([[1.0, 2.0]]).tolist()
    [[[1.0, 0.0], [0.0, 2.0]]]
    """
    v = np.asarray(v, dtype=float)
    return v[..., :, None] * np.eye(v.shape[-1])


def inertia_tensor(J) -> np.ndarray:
    """A 3×3 inertia tensor from principal moments (3,) along x, y, z, or a tensor (or a stack of
    tensors (..., 3, 3)) as given [kg m²]."""
    J = np.asarray(J, dtype=float)
    return diagonal_matrices(J) if J.shape == (3,) else J


def _steiner(m, r) -> np.ndarray:
    """m (|r|² I - r rᵀ), the parallel-axis term of Eq. (1), for stacks of m (...) and r (..., 3)."""
    m, r = np.asarray(m, dtype=float), np.asarray(r, dtype=float)
    rr = np.einsum("...i,...i->...", r, r)
    return m[..., None, None] * (rr[..., None, None] * np.eye(3) - r[..., :, None] * r[..., None, :])


def parallel_axis(m, r, J_G) -> np.ndarray:
    """Inertia tensor about O of a body of mass m [kg] whose centre of mass is at r [m] from O,
    J_O = J_G + m (|r|² I - r rᵀ), Eq. (1); J_G about its centre of mass, moments (3,) or 3×3.
    Stacks broadcast: m (...), r (..., 3), J_G (..., 3, 3) give (..., 3, 3) (a batch of designs).

    >>> parallel_axis(2.0, (0.0, 0.0, 1.0), (1.0, 1.0, 1.0)).diagonal().tolist()
    [3.0, 3.0, 1.0]
    """
    return inertia_tensor(J_G) + _steiner(m, r)


def mass_matrix(m, r, J_O) -> np.ndarray:
    """6×6 mass matrix of Eq. (1) of one body about O: mass m [kg], centre of mass r [m] from O,
    inertia tensor J_O about O [kg m²]; stacks m (...), r (..., 3), J_O (..., 3, 3) broadcast to
    (..., 6, 6)."""
    m, r, J_O = np.asarray(m, dtype=float), np.asarray(r, dtype=float), np.asarray(J_O, dtype=float)
    out = np.zeros(np.broadcast_shapes(m.shape, r.shape[:-1], J_O.shape[:-2]) + (6, 6))
    s = m[..., None, None] * skews(r)
    out[..., :3, :3], out[..., :3, 3:], out[..., 3:, :3], out[..., 3:, 3:] = m[..., None, None] * np.eye(3), -s, s, J_O
    return out


def bodies_mass_matrix(masses, cogs, inertias) -> np.ndarray:
    """Σ of Eq. (1) over bodies rigidly joined: masses (N,) [kg], centres of mass (N, 3) [m] from
    O, central inertias (N, 3) principal moments along x, y, z or (N, 3, 3) [kg m²]. A body may
    be a batch of designs (mass (...), centre (..., 3), inertia tensor (..., 3, 3)): the sum is
    then a stack (..., 6, 6).

    >>> bodies_mass_matrix([1.0, 1.0], [(1.0, 0, 0), (-1.0, 0, 0)], [(0, 0, 0)] * 2).diagonal().tolist()
    [2.0, 2.0, 2.0, 0.0, 2.0, 2.0]
    """
    return sum(mass_matrix(m, r, parallel_axis(m, r, J)) for m, r, J in zip(masses, cogs, inertias))


def centre_of_mass(M) -> tuple[float, np.ndarray, np.ndarray]:
    """Total mass [kg], centre of mass from O [m] and central inertia tensor [kg m²] of a 6×6
    mass matrix of Eq. (1) (or of a stack (..., 6, 6): masses (...), centres (..., 3), tensors
    (..., 3, 3))."""
    M = np.asarray(M, dtype=float)
    m = M[..., 0, 0][()]  # a scalar for one matrix
    r = np.stack([M[..., 5, 1], M[..., 3, 2], M[..., 4, 0]], axis=-1) / m[..., None]  # m [r]× sits in the lower-left block
    return m, r, M[..., 3:, 3:] - _steiner(m, r)


__all__ = [
    "block_inertia",
    "bodies_mass_matrix",
    "centre_of_mass",
    "diagonal_matrices",
    "inertia_tensor",
    "mass_matrix",
    "parallel_axis",
    "skew",
    "skews",
]
