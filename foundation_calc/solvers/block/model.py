"""The block and its machines as matrices about O: mass, springs, dashpots, weight, loads.

Axes: O at the centre of the base at base level, x along the length, y along the width, z up;
q = (u_x, u_y, u_z, θ_x, θ_y, θ_z) of O (:mod:`foundation_calc.solvers.rigid_body`). Equations
of motion about the static equilibrium, linear::

    M q'' + C q' + K q = Σ_machines Σ_orders Re(Q_n e^{i n ω t})                           (1)

    M = Σ_bodies M_body (parallel axes)                       block and every machine, Eq. (1) of inertia.py
    K = diag(K_x, K_y, K_z, K_rx, K_ry, K_rz) - W z_G (about x and y)    springs at O, weight tilt
        (+ K_c, C_c: the off-diagonal springs and dashpots of a coupled support, a pile group's)
    C = diag(C_x, ..., C_rz)       given, or C_i = 2 ξ_i sqrt(K_i m_i) of each uncoupled motion with
                                   m_i = M_Σ for a translation and the moment of inertia about the
                                   axis through O for a rotation (ACI 351.3R-18, 4.5; Richart, Hall
                                   & Woods 1970, ch. 10)
        + Σ_machines D̄            the machines' mean gyroscopic coupling at their speeds: the mean
                                   over a revolution of D(φ) of Eq. (1) of
                                   :mod:`foundation_calc.solvers.rigid_body.periodic`
                                   (:meth:`~foundation_calc.solvers.machines.part.MachinePart.gyroscopic`),
                                   part of the averaged operator as the mean mass is of M
    Q_n = Σ_loads of order n (F, M + r_F × F) e^{iφ}        a load F, M at r_F carried to O

The weight's term makes the rocking modes of a tall block softer (Krichever & Makarov (3.4), the
crank foundation's −P h). D̄ is skew-symmetric (-[h]× in the rotations, h a machine's mean angular
momentum relative to the block: a multi-throw crankshaft's and rods', a single exciter rotor's): it
does no work, leaves the modes and their damping ratios as they are, and couples the two rotations
normal to h in the steady state; it grows as its machine's speed (:meth:`Excitation.damping_change`).
"""

from __future__ import annotations

from dataclasses import dataclass

import numpy as np

from foundation_calc.solvers.machines.part import LoadRow
from foundation_calc.solvers.rigid_body.inertia import bodies_mass_matrix, centre_of_mass, diagonal_matrices
from foundation_calc.solvers.rigid_body.kinematics import load_at, weight_tilt


@dataclass(frozen=True)
class BlockModel:
    """The matrices of Eq. (1) and what the checks read from them (SI units).

    Attributes
    ----------
    M, K, C : 6×6 mass [kg, kg m, kg m²], stiffness [N/m, N, N m/rad], damping [N s/m, ...] about O
    mass : total mass M_Σ [kg]
    cog : combined centre of mass G from O [m]
    J_G : central inertia tensor [kg m²]
    size : the base's diagonal [m] (the scale of rotations in the eigen-solve)
    springs : the six springs at O [N/m, N m/rad]
    coupling : the off-diagonal springs at O of a coupled support (a pile group's sway-rocking),
        (..., 6, 6), zero on the diagonal; None for six uncoupled springs
    gyroscopic : Σ D̄ of the machines at their speeds (6, 6), in C (module docstring); None for none

    A batch of designs (``fcalc design``) holds stacks: M, K, C (..., 6, 6), mass and size (...),
    cog (..., 3), J_G (..., 3, 3), springs (..., 6).
    """

    M: np.ndarray
    K: np.ndarray
    C: np.ndarray
    mass: float | np.ndarray
    cog: np.ndarray
    J_G: np.ndarray
    size: float | np.ndarray
    springs: np.ndarray
    coupling: np.ndarray | None = None
    gyroscopic: np.ndarray | None = None

    @property
    def damped(self) -> bool:
        """True when a dashpot acts (C's symmetric part: the gyroscopic coupling dissipates nothing)."""
        return bool(np.any(self.C + np.swapaxes(self.C, -1, -2) != 0.0))

    def soil_matrices(self, springs, dashpots, coupled=None, coupled_dashpots=None) -> tuple[np.ndarray, np.ndarray]:
        """K and C of Eq. (1) with the springs and dashpots at O replaced by ``springs`` and
        ``dashpots`` [N/m, N m/rad; N s/m, N m s/rad] (a frequency-dependent soil's at each
        frequency), shaped batch + extra + (6,): the model's batch axes first (none for one
        block), then any further axes (the frequencies of several orders); K, C batch + extra + (6, 6).
        ``coupled``, ``coupled_dashpots``: a coupled support's off-diagonal springs and dashpots
        there, batch + extra + (6, 6) (replacing :attr:`coupling`). C keeps the machines' mean
        gyroscopic coupling (:attr:`gyroscopic`), which is not the support's."""
        springs = np.asarray(springs, dtype=float)
        extra = springs.ndim - np.ndim(self.springs)
        batch = np.ndim(self.springs) - 1
        axes = tuple(range(batch, batch + extra))
        own = np.expand_dims(self.springs, axes)
        K = np.expand_dims(self.K, axes) + diagonal_matrices(springs - own)
        C = diagonal_matrices(np.broadcast_to(dashpots, springs.shape))
        if self.gyroscopic is not None:
            C = C + self.gyroscopic
        if coupled is None:
            return K, C
        return K + coupled - np.expand_dims(self.coupling, axes), C + coupled_dashpots


@dataclass(frozen=True)
class Excitation:
    """One machine's loads at its speed: the orders n and the generalised forces Q_n about O.

    Attributes
    ----------
    name : the machine's name
    omega : its speed ω [rad/s]
    orders : distinct orders n, ascending, shape (H,)
    Q : complex amplitudes (F, M about O) of order n at the speed ω, shape (H, 6) [N, N m]
    Q_inertial : the part of Q that grows as the speed squared in a speed sweep (unbalances, the
        parts' inertia forces), shape (H, 6)
    Q_weight : the part of Q of the moving weight (a crank mechanism's, an exciter rotor's), the
        same at every speed in every command, shape (H, 6); the rest of Q (Q - Q_weight: inertia
        forces, unbalances and a vendor's loads) grows as the speed squared in a start-up
        (:mod:`~foundation_calc.solvers.block.runup`)
    gyroscopic : the machine's mean gyroscopic coupling D̄ at the speed ω (6, 6) [kg/s, ..., kg m²/s],
        which the block's C holds (:class:`BlockModel`); None for none
    """

    name: str
    omega: float
    orders: np.ndarray
    Q: np.ndarray
    Q_inertial: np.ndarray
    Q_weight: np.ndarray
    gyroscopic: np.ndarray | None = None

    def damping_change(self, omega):
        """What the block's C gains when this machine runs at the speeds ``omega`` [rad/s] (any
        shape) instead of ω: D̄ (ω'/ω - 1) (D̄ grows as the speed), shape omega.shape + (6, 6); 0 without D̄."""
        if self.gyroscopic is None:
            return 0.0
        ratio = np.asarray(omega, dtype=float) / self.omega - 1.0
        return ratio[..., None, None] * self.gyroscopic

    def loads_at(self, omega) -> np.ndarray:
        """Q at the speeds ``omega`` [rad/s] (any shape): Q + Q_inertial ((ω/ω_0)² - 1), shape
        omega.shape + (H, 6)."""
        ratio = (np.asarray(omega, dtype=float) / self.omega) ** 2 - 1.0
        return self.Q + ratio[..., None, None] * self.Q_inertial


def block_model(masses, cogs, inertias, springs, g, size, dashpots=None, ratios=None, coupling=None,
                gyroscopic=None) -> BlockModel:
    """Assemble Eq. (1).

    Parameters
    ----------
    masses, cogs, inertias : bodies (N,) [kg], (N, 3) [m] from O, central moments (N, 3) [kg m²]
    springs : (6,) springs at O [N/m, N m/rad]
    g : acceleration of gravity [m/s²]
    size : the base's diagonal [m]
    dashpots : (6,) dashpots at O [N s/m, N m s/rad], or None
    ratios : (6,) damping ratios of the uncoupled motions [-] (instead of ``dashpots``), or None
    coupling : (K_c, C_c) off-diagonal springs and dashpots at O of a coupled support, (..., 6, 6)
        each, added to K and C; or None
    gyroscopic : (6, 6) the machines' mean gyroscopic coupling Σ D̄ at their speeds
        [kg/s, ..., kg m²/s], added to C (the same for every block of a batch: D̄ does not change
        when a machine moves along the body); or None

    A batch of designs: a body given as a stack (:func:`~foundation_calc.solvers.rigid_body.inertia.bodies_mass_matrix`),
    springs, ratios (..., 6) and size (...) give the stacks of :class:`BlockModel`.
    """
    M = bodies_mass_matrix(masses, cogs, inertias)
    mass, cog, J_G = centre_of_mass(M)
    springs = np.asarray(springs, dtype=float)
    K = diagonal_matrices(springs) + weight_tilt(mass * g, cog[..., 2])
    if dashpots is not None:
        C = diagonal_matrices(dashpots)
    elif ratios is not None:
        C = diagonal_matrices(2.0 * np.asarray(ratios, dtype=float) * np.sqrt(springs * np.diagonal(M, 0, -2, -1)))
    else:
        C = np.zeros((6, 6))
    K_c = None
    if coupling is not None:
        K_c, C_c = coupling
        K, C = K + K_c, C + C_c
    if gyroscopic is not None:
        gyroscopic = np.asarray(gyroscopic, dtype=float)
        C = C + gyroscopic
    C = np.broadcast_to(C, K.shape)
    size = float(size) if np.ndim(size) == 0 else np.asarray(size, dtype=float)
    return BlockModel(M, K, C, mass, cog, J_G, size, springs, K_c, gyroscopic)


def excitation(name, omega, rows, gyroscopic=None) -> Excitation:
    """A machine's :class:`Excitation` from its loads ``rows``: (order, force [N], moment [N m],
    phase [rad], point [m], inertial[, weight]) each (:class:`~foundation_calc.solvers.machines.part.LoadRow`;
    weight False when left out); loads of one order add. A point may be a batch (..., 3) (the
    machine on each of a batch of candidate blocks): Q is then (..., H, 6).
    ``gyroscopic``: the machine's mean gyroscopic coupling D̄ at ω (6, 6), or None."""
    rows = [LoadRow(*row) for row in rows]
    orders = np.array(sorted({int(r.order) for r in rows}), dtype=int)
    batch = np.broadcast_shapes(*(np.shape(r.at)[:-1] for r in rows))
    Q = np.zeros(batch + (len(orders), 6), dtype=complex)
    Q_inertial, Q_weight = np.zeros_like(Q), np.zeros_like(Q)
    for row in rows:
        q = load_at(row.at, np.asarray(row.force, dtype=float), np.asarray(row.moment, dtype=float)) * np.exp(1j * row.phase)
        h = np.searchsorted(orders, row.order)
        Q[..., h, :] += q
        if row.inertial:
            Q_inertial[..., h, :] += q
        if row.weight:
            Q_weight[..., h, :] += q
    return Excitation(str(name), float(omega), orders, Q, Q_inertial, Q_weight,
                      None if gyroscopic is None else np.asarray(gyroscopic, dtype=float))


__all__ = ["BlockModel", "Excitation", "block_model", "excitation"]
