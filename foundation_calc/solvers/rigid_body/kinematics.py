"""Points of a rigid body: their motion, and springs, dashpots and loads carried to O.

Source: rigid-body kinematics in small motion. A point at r_P from O moves by

    u_P = u + θ × r_P = T_P q,   T_P = [I, -[r_P]×]   (3×6)                               (1)

and turns by θ. A 6-vector of motion at P (u_P, θ) is E_P q with E_P = [[I, -[r_P]×], [0, I]]
(6×6). By virtual work a force F and moment M at P are Q = E_Pᵀ (F, M) = (F, M + r_P × F) about
O (2), and a spring matrix K_P (or dashpot matrix) acting on the motion at P is E_Pᵀ K_P E_P about
O (3). The weight W of a body whose centre of mass is a height z_G above O adds -W z_G to the
rocking stiffnesses about x and y (its overturning moment after a small tilt) (4).
"""

from __future__ import annotations

import numpy as np

from foundation_calc.solvers.rigid_body.inertia import skew, skews


def point_map(p) -> np.ndarray:
    """T_P of Eq. (1): T_P q = displacement of the body point p [m], shape 3×6."""
    return np.hstack([np.eye(3), -skew(np.asarray(p, dtype=float))])


def point_maps(points) -> np.ndarray:
    """T_P of Eq. (1) of each point of a stack (..., 3) [m], shape (..., 3, 6)."""
    points = np.asarray(points, dtype=float)
    return np.concatenate([np.broadcast_to(np.eye(3), points.shape + (3,)), -skews(points)], axis=-1)


def offset_map(p) -> np.ndarray:
    """E_P of Eq. (2): the 6-vector of motion (u_P, θ) at p [m] from q, shape 6×6."""
    out = np.eye(6)
    out[:3, 3:] = -skew(np.asarray(p, dtype=float))
    return out


def spring_at(p, K_P) -> np.ndarray:
    """A 6×6 spring (or dashpot) matrix K_P acting at p [m], carried to O: E_Pᵀ K_P E_P, Eq. (3).

    >>> spring_at((0.0, 0.0, -1.0), np.diag([1.0, 0, 0, 0, 0, 0]))[[0, 4]][:, [0, 4]].tolist()
    [[1.0, -1.0], [-1.0, 1.0]]
    """
    E = offset_map(p)
    return E.T @ np.asarray(K_P, dtype=float) @ E


def springs_at(points, stiffness) -> np.ndarray:
    """Σ_i T_iᵀ diag(k_i) T_i: translational springs k_i (N, 3) [N/m] along x, y, z at the points
    (N, 3) [m], carried to O, Eq. (3); 6×6 [N/m, N, N m/rad]."""
    T = point_maps(points).reshape(-1, 6)
    return T.T @ (np.asarray(stiffness, dtype=float).reshape(-1, 1) * T)


def load_at(p, F, M) -> np.ndarray:
    """Generalised force about O of a force F [N] and moment M [N m] at p [m], Eq. (2):
    (F, M + p × F), shape (..., 6) (complex amplitudes allowed, stacks of p, F and M broadcast)."""
    F, M = np.asarray(F), np.asarray(M)
    return np.concatenate(np.broadcast_arrays(F, M + np.cross(np.asarray(p, dtype=float), F)), axis=-1)


def weight_tilt(W, z_G) -> np.ndarray:
    """Stiffness of the weight W [N] of a body whose centre of mass is z_G [m] above O, Eq. (4):
    diag(0, 0, 0, -W z_G, -W z_G, 0) [N m/rad]; stacks of W and z_G give a stack (..., 6, 6)."""
    tilt = -np.asarray(W, dtype=float) * np.asarray(z_G, dtype=float)
    out = np.zeros(tilt.shape + (6, 6))
    out[..., 3, 3] = out[..., 4, 4] = tilt
    return out


__all__ = ["load_at", "offset_map", "point_map", "point_maps", "spring_at", "springs_at", "weight_tilt"]
