"""Steady-state response of the rigid block to harmonic loads given by a machine's vendor.

Most vendors give a machine's unbalanced forces and moments per order of the speed, not the
geometry of its mechanism. Each load of order n acts on the block at a point (u, H) from its
centre of mass C (u in +x, H above C) and varies as ``F cos(nωt + φ)``. Its generalised forces
about C, by virtual work on the point's displacement (x + H θ, y + u θ) (docs/crank-foundation.md, "The model"), are

    Q_x = F_x,   Q_y = F_y,   Q_θ = H F_x + u F_y + M                                    (1)

The motion is the linear steady state of the block on the soil's springs and base dashpots,
harmonic by harmonic (complex amplitudes, ``q(t) = Re(Z e^{inωt})``)::

    (K - n²ω² M + i nω C) Z_n = Σ_loads of order n  Q e^{iφ}                              (2)

    M = diag(M_tot, M_tot, I_c)                                 rigid block about C, order x, y, θ
    K = [[K_x, 0, -h K_x], [0, K_z, 0], [-h K_x, 0, K_φ + h² K_x - P h]]     Krichever & Makarov
                                                                (3.2)-(3.4), corrected, P = M_tot g
    C = [[C_x, 0, -h C_x], [0, C_z, 0], [-h C_x, 0, C_φ + h² C_x]]          the soil note's dashpots

K and C are those of the exact equations (``dynamics.py``) at rest; M is the paper's zero-order
mass matrix (a crank mechanism's inertia, O(μ), is left out of the loads' response).
"""

from __future__ import annotations

from dataclasses import dataclass

import numpy as np

from foundation_calc.solvers.crank.first_approximation import RESONANT_MARGIN
from foundation_calc.solvers.crank.frequencies import NaturalFrequencies, zero_order_frequencies
from foundation_calc.solvers.crank.plane import block_on_base, in_plane, rigid_block
from foundation_calc.solvers.crank.response import PeriodicMotion

#: Modes of the block in the order of :attr:`NaturalFrequencies`.
MODES = ("k0", "p1", "p2")


@dataclass(frozen=True)
class RigidBlock:
    """The block on its soil, in SI units; fields may be numpy arrays (a batch of blocks, e.g.
    a soil sweep), which broadcast with the speeds.

    Attributes
    ----------
    M_tot : total mass of block and machine [kg]
    I_c : moment of inertia about the centre of mass C [kg m²]
    h : height of C above the base [m]
    K_x, K_z : horizontal and vertical base springs [N/m] (c1 S, c S)
    K_phi : rocking spring about the base's centroidal axis [N m/rad] (c_φ I1)
    C_x, C_z : horizontal and vertical base dashpots [N s/m]
    C_phi : rocking base dashpot [N m s/rad]
    g : acceleration of gravity [m/s²]
    """

    M_tot: float
    I_c: float
    h: float
    K_x: float
    K_z: float
    K_phi: float
    C_x: float
    C_z: float
    C_phi: float
    g: float


@dataclass(frozen=True)
class HarmonicLoads:
    """Loads ``F cos(nωt + φ)`` on the block, one entry per load (arrays of equal length).

    Attributes
    ----------
    order : n, multiple of the speed (integers ≥ 1)
    horizontal : F_x, amplitude of the force along +x [N]
    vertical : F_y, amplitude of the force along +y, downward [N]
    moment : M, amplitude of a couple turning +x toward +y [N m]
    phase : φ [rad], at t = 0 (crank angle φ = 0 when there is a mechanism)
    u : horizontal position of the point of action from C, +x [m]
    H : height of the point of action above C [m]
    """

    order: np.ndarray
    horizontal: np.ndarray
    vertical: np.ndarray
    moment: np.ndarray
    phase: np.ndarray
    u: np.ndarray
    H: np.ndarray

    def generalized(self) -> np.ndarray:
        """Complex generalised forces Q e^{iφ} about C, Eq. (1), shape (L, 3) [N, N, N m]."""
        q = np.stack([self.horizontal, self.vertical, self.H * self.horizontal + self.u * self.vertical + self.moment], -1)
        return q * np.exp(1j * np.asarray(self.phase, dtype=float))[:, None]


@dataclass(frozen=True)
class LoadsResponse:
    """Steady state of the loads at one or many speeds.

    ``motion`` holds harmonics 0 ... max order (a resonant speed's coefficients are NaN);
    ``resonant``, ``margin`` [-] and ``nearest`` (index into :func:`load_conditions`) have the
    shape of ``omega``.
    """

    motion: PeriodicMotion
    resonant: np.ndarray
    margin: np.ndarray
    nearest: np.ndarray


def matrices(block: RigidBlock) -> tuple[np.ndarray, np.ndarray, np.ndarray]:
    """M, K, C of Eq. (2) [kg, kg m²; N/m, N, N m/rad; N s/m, N s, N m s/rad], order x, y, θ,
    shape (..., 3, 3) with the block's batch shape in front.

    >>> M, K, C = matrices(RigidBlock(1.0, 2.0, 0.5, 4.0, 3.0, 5.0, 0.0, 0.0, 0.0, 0.0))
    >>> K.tolist()
    [[4.0, 0.0, -2.0], [0.0, 3.0, 0.0], [-2.0, 0.0, 6.0]]
    """
    b = block
    bodies = rigid_block(b.M_tot, b.I_c, b.h)
    model = block_on_base(bodies, b.K_x, b.K_z, b.K_phi, b.C_x, b.C_z, b.C_phi, b.g)
    return tuple(np.broadcast_arrays(*(in_plane(A, b.h) for A in (model.M, model.K, model.C))))


def block_frequencies(block: RigidBlock) -> NaturalFrequencies:
    """Undamped k0, p1, p2 [rad/s] of Eq. (2): the zero-order operator, Eqs. (4.5)-(4.7) of
    Krichever & Makarov, with the springs K_z, K_x, K_φ in place of c S, c1 S, c_φ I1.

    Raises PhysicsError when K_φ <= P h (unstable in rocking).
    """
    b = block
    return zero_order_frequencies(b.M_tot, b.I_c, b.h, 1.0, 1.0, b.K_z, b.K_x, b.K_phi, b.g)


def load_conditions(loads: HarmonicLoads) -> tuple[tuple[int, str, bool], ...]:
    """``(n, mode, driven)`` for every distinct order n and every mode: the vertical mode k0 is
    driven by a vertical force, the sliding-rocking modes p1, p2 by a horizontal force or a
    moment about C, Eq. (1)."""
    q = np.abs(loads.generalized())
    found = []
    for n in sorted({int(k) for k in loads.order}):
        mine = q[np.asarray(loads.order) == n]
        vertical, rocking = bool(mine[:, 1].any()), bool(mine[:, [0, 2]].any())
        found += [(n, "k0", vertical), (n, "p1", rocking), (n, "p2", rocking)]
    return tuple(found)


def modal_damping(block: RigidBlock) -> np.ndarray:
    """φᵀ C φ of the undamped modes k0, p1, p2 (mass-normalised shapes), shape (..., 3) [1/s].

    Zero where the dashpots do not damp a mode: at that mode's resonance the matrix of Eq. (2)
    is singular (C is positive semi-definite, so φᵀ C φ = 0 means C φ = 0).
    """
    M, K, C = matrices(block)
    scale = 1.0 / np.sqrt(np.stack([M[..., 0, 0], M[..., 2, 2]], -1))
    _, vectors = np.linalg.eigh(scale[..., :, None] * K[..., [0, 2], :][..., :, [0, 2]] * scale[..., None, :])
    shapes = scale[..., :, None] * vectors  # columns: p1, p2 (eigh sorts ascending)
    rocking = np.einsum("...im,...ij,...jm->...m", shapes, C[..., [0, 2], :][..., :, [0, 2]], shapes)
    return np.concatenate([(C[..., 1, 1] / M[..., 1, 1])[..., None], rocking], -1)


def loads_response(block: RigidBlock, omega, loads: HarmonicLoads) -> LoadsResponse:
    """Steady state of Eq. (2) at the speeds ``omega`` [rad/s] (a float or an array, which
    broadcasts with the block's fields).

    A speed whose harmonic n ω of a load lies within :data:`RESONANT_MARGIN` (relative) of an
    undamped mode (:func:`modal_damping` zero) has no steady state (or, for a mode no load
    drives, one the slightest imperfection destroys): it is ``resonant`` and its coefficients
    are NaN, never a solve of a singular matrix.

    >>> block = RigidBlock(1.0, 1.0, 1.0, 1.0, 4.0, 10.0, 0.0, 0.0, 0.0, 1.0)
    >>> loads = HarmonicLoads(*(np.array([v]) for v in (1, 0.0, 3.0, 0.0, 0.0, 0.0, 0.0)))
    >>> r = loads_response(block, 1.0, loads)      # (4 - 1) y = 3
    >>> float(r.motion.cos[1, 1]), bool(r.resonant)
    (1.0, False)
    """
    M, K, C = matrices(block)
    omega = np.asarray(omega, dtype=float)
    shape = np.broadcast_shapes(omega.shape, M.shape[:-2])
    omega = np.broadcast_to(omega, shape)
    freqs = block_frequencies(block)
    modal = np.broadcast_to(modal_damping(block), shape + (3,))
    conditions = load_conditions(loads)
    margins, singular = [], []
    for n, mode, _ in conditions:
        natural = np.asarray(getattr(freqs, mode))
        margins.append(np.abs(n * omega - natural) / natural)
        singular.append(modal[..., MODES.index(mode)] <= 0.0)
    margins = np.stack(margins)
    resonant = ((margins < RESONANT_MARGIN) & np.stack(singular)).any(axis=0)
    nearest = np.argmin(margins, axis=0)
    margin = np.take_along_axis(margins, nearest[None], axis=0)[0]

    orders = np.asarray(loads.order, dtype=int)
    Q = loads.generalized()
    Z = np.zeros(shape + (3, int(orders.max()) + 1), dtype=complex)
    safe = np.where(resonant, 0.0, omega)[..., None, None]  # no solve of a singular matrix
    for n in sorted(set(orders.tolist())):
        A = K - (n * safe) ** 2 * M + 1j * (n * safe) * C
        rhs = np.broadcast_to(Q[orders == n].sum(0), shape + (3,))[..., None]
        Z[..., :, n] = np.linalg.solve(A, rhs)[..., 0]
    Z = np.where(resonant[..., None, None], np.nan, Z)
    return LoadsResponse(PeriodicMotion(omega, Z.real, -Z.imag), resonant, margin, nearest)


__all__ = [
    "MODES",
    "HarmonicLoads",
    "LoadsResponse",
    "RigidBlock",
    "block_frequencies",
    "load_conditions",
    "loads_response",
    "matrices",
    "modal_damping",
]
