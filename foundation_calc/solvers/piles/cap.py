"""A pile group under a rigid cap: its 6 × 6 impedance at the cap's origin O.

Axes as the block's (:mod:`foundation_calc.solvers.block.model`): O at the centre of the base, z
up, q = (u_x, u_y, u_z, θ_x, θ_y, θ_z). The pile heads lie in the base plane at (x_i, y_i, 0)
and move with the cap::

    w_i = u_z + y_i θ_x - x_i θ_y,   u_x,i = u_x - y_i θ_z,   u_y,i = u_y + x_i θ_z

and turn with it (fixed heads: θ_x, θ_y; pinned heads carry no moment). Superposition with the
interaction factors of :mod:`.group` (Dobry & Gazetas 1988, their Eqs. for a rigid cap): with
A_ij = α(S_ij) (A_ii = 1) the heads' displacements are u = A P / K_1 for the head forces P, so that
under the cap's motion the forces are P = K_1 A⁻¹ u and the cap's impedance

    K_cap = Σ_directions D_kᵀ (K_1 A_k⁻¹) D_k + Σ_i T_iᵀ k_i T_i

D_k the (n × 6) map of q to the heads' displacements in direction k (vertical: α_v; x and y:
α_h with θ measured from x, resp. y), k_i a pile's own rocking, sway-rocking coupling and
torsion (no interaction in these, as in [1] of :mod:`.group`), T_i = [[I, -[r_i]×], [0, I]] the
rigid-body map to its head. Rocking of the cap is then Σ K_v x_i² (with interaction) plus the
piles' own K_MM; its torsion Σ K_HH r_i² plus the piles' own K_T.
"""

from __future__ import annotations

import numpy as np

from foundation_calc.solvers.piles.group import horizontal_factor, vertical_factor


def group_stiffness(K_1, alpha, D):
    """Dᵀ (K_1 A⁻¹) D [..., 6, 6] for one direction: ``K_1`` the single pile's impedance (...),
    ``alpha`` the interaction matrix A (..., n, n), ``D`` the map (..., n, 6)."""
    solved = np.linalg.solve(alpha, D.astype(complex))
    return K_1[..., None, None] * np.einsum("...ni,...nj->...ij", D, solved)


def cap_impedance(x, y, head, d, V_v, V_h, nu, beta, omega):
    """K + iω C of the group at O, complex (..., 6, 6) (module docstring).

    Parameters
    ----------
    x, y : the pile heads' coordinates from O, (..., n) [m]
    head : :class:`~foundation_calc.solvers.piles.single.PileHead` at ``omega`` (pinned heads:
        its K_MM = K_HM = 0)
    d : pile diameter [m] (an array broadcasts with ``omega``)
    V_v, V_h : the shear-wave velocities [m/s] the vertical and the horizontal interaction take
    nu : the soil's Poisson's ratio [-]
    beta : the soil's material damping ratio [-]
    omega : circular frequency [rad/s], broadcasting with the heads' leading axes

    >>> from foundation_calc.solvers.piles.single import PileHead
    >>> one = PileHead(1.0, 2.0, 3.0, -0.5, 4.0, 5.0)
    >>> K = cap_impedance(np.array([0.0]), np.array([0.0]), one, 0.5, 100.0, 100.0, 0.3, 0.0, 0.0)
    >>> np.diagonal(K).real.tolist(), float(K[0, 4].real), float(K[1, 3].real)
    ([2.0, 2.0, 1.0, 3.0, 3.0, 4.0], -0.5, 0.5)
    """
    omega = np.asarray(omega, dtype=float)
    x, y = np.broadcast_arrays(np.asarray(x, dtype=float), np.asarray(y, dtype=float))
    batch = np.broadcast_shapes(x.shape[:-1], omega.shape)
    x, y = np.broadcast_to(x, batch + x.shape[-1:]), np.broadcast_to(y, batch + x.shape[-1:])
    w = omega[..., None, None]
    dx = x[..., :, None] - x[..., None, :]
    dy = y[..., :, None] - y[..., None, :]
    S = np.hypot(dx, dy)
    same = S == 0.0
    S = np.where(same, 1.0, S)

    def interaction(values):
        return np.where(same, 1.0, values)

    V_v, V_h, d = (v[..., None, None] if np.ndim(v) else v for v in (V_v, V_h, d))
    A_v = interaction(vertical_factor(S, d, V_v, beta, w))
    A_x = interaction(horizontal_factor(S, (dx / S) ** 2, d, V_h, nu, beta, w))
    A_y = interaction(horizontal_factor(S, (dy / S) ** 2, d, V_h, nu, beta, w))
    zero, one = np.zeros_like(x), np.ones_like(x)
    D_z = np.stack([zero, zero, one, y, -x, zero], axis=-1)
    D_x = np.stack([one, zero, zero, zero, zero, -y], axis=-1)
    D_y = np.stack([zero, one, zero, zero, zero, x], axis=-1)

    def each(value):
        return np.broadcast_to(np.asarray(value, dtype=complex), batch)

    K = (group_stiffness(each(head.K_v), A_v, D_z) + group_stiffness(each(head.K_HH), A_x, D_x)
         + group_stiffness(each(head.K_HH), A_y, D_y))
    n = x.shape[-1]
    K_MM, K_HM, K_T = (n * each(v) for v in (head.K_MM, head.K_HM, head.K_T))
    # the piles' own rocking and coupling act on the head rotations and on their sway
    # u_x,i = u_x - y_i θ_z, u_y,i = u_y + x_i θ_z (T_iᵀ k_i T_i summed over the piles)
    sx, sy = each(head.K_HM) * np.sum(x, axis=-1), each(head.K_HM) * np.sum(y, axis=-1)
    K[..., 3, 3] += K_MM
    K[..., 4, 4] += K_MM
    K[..., 5, 5] += K_T
    for (i, j), value in {(0, 4): K_HM, (1, 3): -K_HM, (4, 5): -sy, (3, 5): -sx}.items():
        K[..., i, j] += value
        K[..., j, i] += value
    return K


#: The frequency [rad/s] at which a group's dashpots are taken "at rest": C = Im Z/ω has a finite
#: limit as ω → 0 (the Winkler dashpots are held below a0 = :data:`~.single.A0_MIN`), which this
#: frequency gives to about 1e-6 (the interaction's e^(-β ω S/V_s) is linear in ω). The springs at
#: rest are taken at ω = 0 itself (Gazetas' vertical k_z grows as sqrt(a0): 1e-3 at this frequency).
OMEGA_REST = 1e-3


def pile_group(x, y, d, L, E_p, rho_p, G_s, nu, rho, beta, profile, end_bearing, pinned_head, omega):
    """The group's impedance at O, complex (..., 6, 6) [N/m, N/rad, N m/rad; + iω N s/m ...]: the
    single pile of :func:`~.single.single_pile` (pinned: :func:`~.single.pinned`) under the cap
    (:func:`cap_impedance`), the interaction taking the shear-wave velocity of the profile at
    the depth the single pile's vertical (L/2) and lateral (l_a/2) shapes take.

    Parameters
    ----------
    x, y : the pile heads from O (..., n) [m]
    d, L, E_p, rho_p : pile diameter [m], length [m], Young's modulus [Pa], density [kg/m³]
    G_s, nu, rho, beta : the soil's shear modulus at depth d [Pa], Poisson's ratio, density
        [kg/m³], material damping ratio [-]
    profile : "uniform", "linear" or "parabolic"
    end_bearing, pinned_head : the tip on rock; the heads free to rotate
    omega : circular frequency [rad/s]
    """
    from foundation_calc.solvers.piles.single import pinned, profile_factor, single_pile

    omega = np.asarray(omega, dtype=float)
    head = single_pile(d, L, E_p, rho_p, G_s, nu, rho, profile, end_bearing, omega)
    if pinned_head:
        head = pinned(head)

    def V_at(z):
        return np.sqrt(G_s * profile_factor(np.maximum(z, d) / d, profile) / rho)

    return cap_impedance(x, y, head, d, V_at(L / 2.0), V_at(head.l_a / 2.0), nu, beta, omega)


def springs_and_dashpots(impedance, omega):
    """(K, C) of the impedance K + iω C = ``impedance(ω)`` at ``omega`` [rad/s]: K at ω, C the nearest
    positive semi-definite matrix to Im Z/ω, at :data:`OMEGA_REST` where ω is below it.

    The superposition with Dobry & Gazetas' factors can radiate less than nothing: in an
    antisymmetric pattern (the cap's torsion, its rocking) a neighbour's wave arrives nearly in
    phase with its own pile and against the other, so that at low a0 the sum of the piles' own
    dashpots and the interaction's imaginary parts may be negative (a 2 × 2 group of 0.6 m piles
    at 4.0 × 2.4 m in torsion at rest: -2.4 MN m s). The rigorous group (Kaynia & Kausel) is passive:
    its damping matrix is positive semi-definite at every frequency. The negative eigenvalues of
    the symmetric part are therefore set to 0 (the nearest such matrix in the Frobenius norm)."""
    omega = np.asarray(omega, dtype=float)
    Z = impedance(omega)
    damped = np.maximum(omega, OMEGA_REST)
    K = Z.real
    C = (Z if np.all(omega >= OMEGA_REST) else impedance(damped)).imag / damped[..., None, None]
    values, vectors = np.linalg.eigh((C + np.swapaxes(C, -1, -2)) / 2.0)
    return K, np.einsum("...ik,...k,...jk->...ij", vectors, np.maximum(values, 0.0), vectors)


__all__ = ["OMEGA_REST", "cap_impedance", "group_stiffness", "pile_group", "springs_and_dashpots"]
