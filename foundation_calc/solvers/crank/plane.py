"""The crank foundation as the one rigid-body model: the block on its base springs and dashpots,
carrying one crank throw in the x-z plane, read in the plane's coordinates.

The block model (:mod:`foundation_calc.solvers.block.model`): O at the centre of the base, z up,
q = (u_x, u_y, u_z, θ_x, θ_y, θ_z). The crank foundation's coordinates
(:mod:`foundation_calc.solvers.crank.dynamics`): x, y (downward) of the centre of mass C at the
height h above O, and θ turning +x toward +y, i.e. about +y of the block. A point's displacement
u + θ × r gives, at r_C = (0, 0, h)::

    x = u_x + h θ_y,   y = -u_z,   θ = θ_y       so   q = P (x, y, θ),
    P = e_ux (1, 0, -h) - e_uz (0, 1, 0) + e_θy (0, 0, 1)                                      (1)

and a matrix A or a generalised force Q about O reads Pᵀ A P, Pᵀ Q in the crank's coordinates
(virtual work). The supports are the base's springs K_x, K_z, K_φ and dashpots C_x, C_z, C_φ at O
(Barkan's c1 S, c S, c_φ I1, or the soil method's), and a pile group's coupling K_xφ, C_xφ of u_x
with θ_y; the weight's tilt W z_G of the model is the
paper's -P h (Krichever & Makarov (3.4), corrected) for a body at C.

The machine (:mod:`foundation_calc.solvers.machines.crank_mechanism`): one throw with its crank
centre A at the distance a above C, its slider axis -z (the guide from A towards C), its shaft
axis +y (the pin's sideways motion -r sin φ along x), crank angle 0 (φ from the downward vertical),
the rod with the slider lumped in. The plane machine does not reach the out-of-plane coordinates
(the throw moves in the x-z plane, the block is symmetric about it): the model has no springs
there and is solved in the plane alone.

The averaged operator (:mod:`foundation_calc.solvers.crank.averaged`) is the model's M, C, K
(the mechanism's time-averaged mass and weight are bodies of the model) with the mechanism's mean
Coriolis terms, in the crank's coordinates, and its forcing the mechanism's, Eq. (4) of
crank_mechanism. The motor off the foundation adds the drive's reaction, which the block's
mechanism (an ideal rheonomic constraint on the body) does not carry:
:func:`~foundation_calc.solvers.crank.dynamics.drive_reaction`.
"""

from __future__ import annotations

from dataclasses import dataclass

import numpy as np

from foundation_calc.solvers.block.model import BlockModel, block_model
from foundation_calc.solvers.rigid_body.inertia import diagonal_matrices
from foundation_calc.solvers.machines.crank_mechanism import (
    CrankThrow,
    MechanismSamples,
    crank_throw,
    mean_mass_properties,
    mechanism_samples,
)

#: The block's coordinates the plane machine moves: u_x, u_z, θ_y.
PLANE = (0, 2, 4)


def plane_map(h) -> np.ndarray:
    """P of Eq. (1), (..., 6, 3): the block's q at O of the crank's (x, y, θ) at C, h [m] above O
    (an array of heights gives a stack)."""
    h = np.asarray(h, dtype=float)
    P = np.zeros(h.shape + (6, 3))
    P[..., 0, 0], P[..., 0, 2], P[..., 2, 1], P[..., 4, 2] = 1.0, -h, -1.0, 1.0
    return P


def in_plane(A, h) -> np.ndarray:
    """Pᵀ A P: a matrix (..., 6, 6) about O in the crank's coordinates at C, (..., 3, 3)."""
    P = plane_map(h)
    return np.swapaxes(P, -1, -2) @ A @ P


def plane_throw(design) -> CrankThrow:
    """The crank design's mechanism as a throw on the block (module docstring), O at the base."""
    rod = design.rod
    return crank_throw([0.0, 0.0, design.h + design.a], [0.0, 1.0, 0.0], [0.0, 0.0, -1.0], 0.0,
                       design.r, design.l, rod.m, rod.l1, rod.rho, 0.0)


def support(K_x, K_z, K_phi, C_x, C_z, C_phi) -> tuple[np.ndarray, np.ndarray]:
    """The base's springs and dashpots at O, (..., 6) each [N/m, N m/rad; N s/m, N m s/rad], none
    out of the plane (arrays broadcast: a batch of blocks)."""
    zero = 0.0 * np.asarray(K_x, dtype=float)
    springs = np.stack(np.broadcast_arrays(K_x, zero, K_z, zero, K_phi, zero), axis=-1).astype(float)
    dashpots = np.stack(np.broadcast_arrays(C_x, zero, C_z, zero, C_phi, zero), axis=-1).astype(float)
    return springs, np.broadcast_to(dashpots, springs.shape)


def sway_rocking(K_xphi, C_xphi) -> tuple[np.ndarray, np.ndarray] | None:
    """The coupling of u_x with θ_y at O, K_xφ [N/rad] and C_xφ [N s/rad], as the off-diagonal
    (..., 6, 6) springs and dashpots of :func:`~foundation_calc.solvers.block.model.block_model`;
    None when both are 0 (the paper's uncoupled base)."""
    K_xphi, C_xphi = np.broadcast_arrays(np.asarray(K_xphi, dtype=float), np.asarray(C_xphi, dtype=float))
    if not (np.any(K_xphi != 0.0) or np.any(C_xphi != 0.0)):
        return None
    K_c, C_c = np.zeros(K_xphi.shape + (6, 6)), np.zeros(K_xphi.shape + (6, 6))
    K_c[..., 0, 4] = K_c[..., 4, 0] = K_xphi
    C_c[..., 0, 4] = C_c[..., 4, 0] = C_xphi
    return K_c, C_c


def block_on_base(bodies, K_x, K_z, K_phi, C_x, C_z, C_phi, g, K_xphi=0.0, C_xphi=0.0) -> BlockModel:
    """The block model of ``bodies`` (masses, centres of mass from O, central moments) on the
    base's springs and dashpots (:func:`support`) and their sway-rocking coupling
    (:func:`sway_rocking`). The size is that of a rotation of 1 m (the model is solved in the
    plane, not by the block's scaled eigen-solve)."""
    springs, dashpots = support(K_x, K_z, K_phi, C_x, C_z, C_phi)
    return block_model(*bodies, springs, g, 1.0, dashpots=dashpots, coupling=sway_rocking(K_xphi, C_xphi))


def rigid_block(M, I_c, h) -> tuple[list, list, list]:
    """A body of mass M [kg] and moment of inertia I_c [kg m²] about +y through its centre of mass
    at the height h [m] above O (arrays: a batch), as ``bodies`` of :func:`block_on_base`."""
    M, I_c, h = np.broadcast_arrays(*(np.asarray(v, dtype=float) for v in (M, I_c, h)))
    zero = 0.0 * M
    return [M], [np.stack([zero, zero, h], axis=-1)], [diagonal_matrices(np.stack([zero, I_c, zero], axis=-1))]


@dataclass(frozen=True)
class PlaneFoundation:
    """A crank design as the block model with its one machine (module docstring).

    Attributes
    ----------
    model : the block (M, I_c at C) and the mechanism's mean mass properties on the base's springs
        and dashpots at O
    throw : the mechanism
    h : height of C above O [m]
    """

    model: BlockModel
    throw: CrankThrow
    h: float


def plane_foundation(design) -> PlaneFoundation:
    """The crank design (:class:`~foundation_calc.solvers.crank.mechanism.CrankDesign`) as the one
    rigid-body model: block, supports, machine (module docstring)."""
    d = design
    throw = plane_throw(d)
    m, cog, J = mean_mass_properties([throw])
    masses, cogs, inertias = rigid_block(d.M, d.I_c, d.h)
    model = block_on_base((masses + [m], cogs + [cog], inertias + [J]),
                          d.c1 * d.S, d.c * d.S, d.c_phi * d.I1, d.C_x, d.C_z, d.C_phi, d.g, d.K_xphi, d.C_xphi)
    return PlaneFoundation(model, throw, float(d.h))


def plane_samples(throw: CrankThrow, h, omega, g, N: int) -> MechanismSamples:
    """The throw's Eqs. (1)-(4) at N phases (crank_mechanism) at speed ω [rad/s], gravity g
    [m/s²], in the crank's coordinates at C, h [m] above O: M, D, S (N, 3, 3), f_inertia,
    f_weight (N, 3)."""
    s = mechanism_samples([throw], omega, g, N)
    P = plane_map(h)
    return MechanismSamples(s.omega, *(in_plane(A, h) for A in (s.M, s.D, s.S)), s.f_inertia @ P, s.f_weight @ P)


__all__ = ["PLANE", "PlaneFoundation", "block_on_base", "in_plane", "plane_foundation", "plane_map",
           "plane_samples", "plane_throw", "rigid_block", "support", "sway_rocking"]
