"""Modes and damped steady state of the block under its machines' loads.

Source: :mod:`foundation_calc.solvers.rigid_body` (modes: K v = p² M v; harmonic response:
(K - Ω² M + i Ω C) Z = Q) applied to Eq. (1) of :mod:`.model`, per machine and order, Ω = n ω.
A point P moves by u_P(t) = Σ Re(T_P Z e^{iΩt}).

Several machines at unrelated speeds: their sum is not periodic. Over a long time their phases
take every relative value, so the peak of the sum tends to the **sum of the machines' peaks**
(an upper bound, reached in the limit), each machine's peak being exact over its own period
(:func:`foundation_calc.solvers.numerics.trig_series.peak`). The mean square of the sum is the
sum of the mean squares of all harmonics, so **RMS values add as the root-sum-square of every
harmonic of every machine**: sqrt(Σ |V|²/2).
"""

from __future__ import annotations

from dataclasses import dataclass

import numpy as np

from foundation_calc.errors import PhysicsError
from foundation_calc.solvers.block.model import BlockModel, Excitation
from foundation_calc.solvers.rigid_body.harmonic import harmonic_response
from foundation_calc.solvers.rigid_body.kinematics import point_maps
from foundation_calc.solvers.rigid_body.modes import MOTIONS, dominant_motions, eigen

#: Relative distance |nω - p|/p within which an undamped mode has no steady state [-].
RESONANT_MARGIN = 1e-6


@dataclass(frozen=True)
class BlockModes:
    """Undamped modes: frequencies p [rad/s] ascending, mass-normalised shapes (6, 6) as columns,
    the dominant motion of each (:data:`~foundation_calc.solvers.rigid_body.modes.MOTIONS`), and
    the modal damping ratios ζ = φᵀ C φ / (2 p) [-]."""

    frequencies: np.ndarray
    shapes: np.ndarray
    dominant: tuple[str, ...]
    damping: np.ndarray


def block_modes(model: BlockModel) -> BlockModes:
    """The six modes of Eq. (1) of :mod:`.model` without damping.

    Raises
    ------
    PhysicsError
        when a squared frequency is not positive: a direction without a spring, or a block that
        tips over (its weight's moment W z_G above the rocking spring).
    """
    p2, shapes = eigen(model.K, model.M, model.size)
    dominant = tuple(MOTIONS[int(i)] for i in dominant_motions(shapes, model.mass, model.cog, np.diag(model.J_G)))
    if p2[0] <= 1e-12 * p2[-1]:
        raise PhysicsError(
            f"the block is unstable or unrestrained in {dominant[0]}: squared natural frequency {float(p2[0]):.4g} rad²/s²"
            f" (the weight's overturning moment W z_G = {model.mass * 9.81 * model.cog[2]:.4g} N m per rad is"
            " at or above the rocking spring, or a spring is missing)",
            field="soil",
            hint="stiffen the rocking springs or lower the centre of mass",
        )
    p = np.sqrt(p2)
    modal_c = np.einsum("im,ij,jm->m", shapes, model.C, shapes)
    return BlockModes(p, shapes, dominant, modal_c / (2.0 * p))


@dataclass(frozen=True)
class Resonances:
    """Every order of one machine against every mode.

    Attributes
    ----------
    orders : (H,) orders n
    critical : (H, 6) speeds n ω = p_j [rad/s], i.e. p_j / n
    margin : (H, 6) |n ω - p_j| / p_j [-]
    share : (H, 6) forcing share |φ_jᵀ Q_n| / p_j of order n on mode j, over its largest value
        for the machine [-] (the resonance rule's measure of what a harmonic drives)
    """

    orders: np.ndarray
    critical: np.ndarray
    margin: np.ndarray
    share: np.ndarray


def resonances(modes: BlockModes, exc: Excitation, omega=None) -> Resonances:
    """Margins of the machine's orders from every mode at its speed (or at ``omega`` [rad/s])."""
    omega = exc.omega if omega is None else omega
    p = modes.frequencies
    n = exc.orders[:, None].astype(float)
    static = np.abs(exc.Q @ modes.shapes) / p  # (H, 6): |φ_jᵀ Q_n| / p_j
    share = static / static.max()
    return Resonances(exc.orders, p[None, :] / n, np.abs(n * omega - p[None, :]) / p[None, :], share)


def resonant(modes: BlockModes, res: Resonances) -> bool:
    """True when an order sits within :data:`RESONANT_MARGIN` of an undamped mode (no steady state)."""
    return bool(np.any((res.margin < RESONANT_MARGIN) & (modes.damping[None, :] <= 0.0)))


def complex_amplitudes(model: BlockModel, exc: Excitation, omega=None) -> np.ndarray:
    """Z of (K - (nω)² M + i nω C) Z = Q_n for every order, shape (..., H, 6) [m, rad], at the
    machine's speed or at the speeds ``omega`` (any shape) [rad/s] (an unbalance's load grows as
    ω², :meth:`~foundation_calc.solvers.block.model.Excitation.loads_at`)."""
    if omega is None:
        return harmonic_response(model.K, model.C, model.M, exc.Q, exc.omega * exc.orders)
    omega = np.asarray(omega, dtype=float)
    return harmonic_response(model.K, model.C, model.M, exc.loads_at(omega), omega[..., None] * exc.orders)


@dataclass(frozen=True)
class PointMotion:
    """Steady motion of named points, per machine and order, and its combination.

    Attributes
    ----------
    names : point names, ``"G"`` (the centre of mass) first
    machines : machine names
    orders : per machine, its orders (H_m,)
    omegas : per machine, its speed [rad/s]
    displacement : per machine, complex amplitudes (P, 3, H_m) [m] along x, y, z: u(t) = Re(Z e^{i n ω t})
    rotation : per machine, complex rotation amplitudes (3, H_m) [rad] about x, y, z
    peak : (P, 3) peak displacement over time, machines' peaks added [m]
    velocity_peak : (P, 3) [m/s], likewise
    velocity_rms : (P, 3) root-sum-square of every harmonic's RMS velocity [m/s]
    displacement_rms : (P, 3) [m]
    rotation_peak : (3,) [rad]
    """

    names: tuple[str, ...]
    machines: tuple[str, ...]
    orders: tuple[np.ndarray, ...]
    omegas: tuple[float, ...]
    displacement: tuple[np.ndarray, ...]
    rotation: tuple[np.ndarray, ...]
    peak: np.ndarray
    velocity_peak: np.ndarray
    velocity_rms: np.ndarray
    displacement_rms: np.ndarray
    rotation_peak: np.ndarray


def _series_peak(Z: np.ndarray, orders: np.ndarray) -> np.ndarray:
    """Peak over one period of Σ_n Re(Z_n e^{inφ}) for each row of Z (..., H)."""
    from foundation_calc.solvers.numerics.trig_series import peak

    K = int(orders.max())
    a = np.zeros(Z.shape[:-1] + (K + 1,), dtype=complex)
    a[..., orders] = Z
    return peak(a.real, -a.imag)


def point_motion(model: BlockModel, excitations, names, points) -> PointMotion:
    """Steady motion of G and of ``points`` (P, 3) [m] from O under every machine (module
    docstring: peaks add, RMS values add as root-sum-square)."""
    at = np.vstack([model.cog[None, :], np.asarray(points, dtype=float).reshape(-1, 3)])
    T = point_maps(at)  # (P, 3, 6)
    disp, rot = [], []
    peak = np.zeros((len(at), 3))
    vpeak, vsq, usq, rpeak = np.zeros_like(peak), np.zeros_like(peak), np.zeros_like(peak), np.zeros(3)
    for exc in excitations:
        Z = complex_amplitudes(model, exc)  # (H, 6)
        U = np.einsum("pij,hj->pih", T, Z)  # (P, 3, H)
        V = U * (1j * exc.omega * exc.orders)
        disp.append(U)
        rot.append(Z[:, 3:].T)
        peak += _series_peak(U, exc.orders)
        vpeak += _series_peak(V, exc.orders)
        rpeak += _series_peak(Z[:, 3:].T, exc.orders)
        vsq += (np.abs(V) ** 2).sum(-1) / 2.0
        usq += (np.abs(U) ** 2).sum(-1) / 2.0
    return PointMotion(
        tuple(["G", *names]), tuple(e.name for e in excitations), tuple(e.orders for e in excitations),
        tuple(e.omega for e in excitations), tuple(disp), tuple(rot), peak, vpeak, np.sqrt(vsq), np.sqrt(usq), rpeak,
    )


__all__ = [
    "BlockModes",
    "PointMotion",
    "Resonances",
    "block_modes",
    "complex_amplitudes",
    "point_motion",
    "resonances",
    "resonant",
]
