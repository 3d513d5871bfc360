"""A batch of 6-DOF candidate blocks in array operations: each block's own rigid body (what
:attr:`~foundation_calc.scenes.block_parts.BlockBody.mass_properties` gives for one block), for the
batch checker of ``fcalc design`` (:mod:`~foundation_calc.checks.design.block`), which places the
machines, points and support on each candidate."""

from __future__ import annotations

import numpy as np


def block_bodies(L, B, H, rho):
    """Mass [kg], centre of mass (N, 3) [m] from O (the base's centre) and central inertia tensor
    (N, 3, 3) [kg m²] of each solid block L × B × H [m] of density ρ [kg/m³]: m = ρ L B H at
    (0, 0, H/2), I = m (B² + H², L² + H², L² + B²) / 12
    (:func:`~foundation_calc.solvers.rigid_body.inertia.block_inertia`)."""
    from foundation_calc.solvers.rigid_body.inertia import block_inertia, diagonal_matrices

    m = L * B * H * rho
    cog = np.stack([np.zeros_like(H), np.zeros_like(H), H / 2.0], axis=-1)
    return m, cog, diagonal_matrices(np.stack(block_inertia(m, L, B, H), axis=-1))


__all__ = ["block_bodies"]
