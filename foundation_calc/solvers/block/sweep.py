"""The block's steady state along a sweep of one machine's speed, the others at their own (or
left out: ``excitations`` holds the machines that run).

Source: :mod:`.response` at every speed at once: one batched solve of (K - (nω)² M + i nω C) Z = Q_n
for all speeds and orders of the swept machine, its points' peaks over their period searched
together (:func:`~foundation_calc.solvers.numerics.trig_series.peak`), and the other machines'
fixed peaks and mean squares added as :mod:`.response` says (peaks add, RMS values add as
root-sum-square).
"""

from __future__ import annotations

from dataclasses import dataclass

import numpy as np

from foundation_calc.solvers.block.model import BlockModel, Excitation
from foundation_calc.solvers.block.response import BlockModes, series_peak, complex_amplitudes, point_motion
from foundation_calc.solvers.rigid_body.kinematics import point_maps


@dataclass(frozen=True)
class SpeedSweep:
    """Peaks and RMS along a sweep of one machine's speed.

    Attributes
    ----------
    omega : the swept machine's speeds [rad/s], shape (N,)
    peak : (N, P, 3) peak displacement of G and every point along x, y, z [m]
    velocity_peak : (N, P, 3) peak velocity [m/s]
    displacement_rms : (N, P, 3) RMS displacement [m]
    velocity_rms : (N, P, 3) RMS velocity [m/s]
    acceleration_peak : (N, P, 3) peak acceleration [m/s²]
    acceleration_rms : (N, P, 3) RMS acceleration [m/s²]
    margin : (N, H, 6) |n ω - p_j| / p_j of the swept machine's orders against every mode [-]
    """

    omega: np.ndarray
    peak: np.ndarray
    velocity_peak: np.ndarray
    displacement_rms: np.ndarray
    velocity_rms: np.ndarray
    acceleration_peak: np.ndarray
    acceleration_rms: np.ndarray
    margin: np.ndarray


def speed_sweep(model: BlockModel, modes: BlockModes, excitations, swept: int, omega, points, impedance=None) -> SpeedSweep:
    """Sweep machine ``swept`` (index into ``excitations``) over the speeds ``omega`` [rad/s];
    ``points`` (P, 3) [m] from O besides G. A swept machine given by a balance grade keeps the
    rotor's eccentricity, so its force grows as ω²; vendor loads keep their amplitudes. On the
    soil ``impedance`` (:mod:`.response`) every order n of every speed is solved with the springs
    and dashpots at n ω, in the same batched solve, and ``modes`` are the frequency-consistent
    ones (:func:`~foundation_calc.solvers.block.response.consistent_modes`)."""
    omega = np.asarray(omega, dtype=float)
    exc: Excitation = excitations[swept]
    others = [e for i, e in enumerate(excitations) if i != swept]
    at = np.vstack([model.cog[None, :], np.asarray(points, dtype=float).reshape(-1, 3)])
    peak = velocity_peak = acceleration_peak = usq = vsq = asq = np.zeros((len(at), 3))
    if others:
        fixed = point_motion(model, others, [str(i) for i in range(len(at) - 1)], at[1:],
                             frozenset({"peak", "velocity_peak", "acceleration_peak"}), impedance=impedance)
        peak, velocity_peak, acceleration_peak = fixed.peak, fixed.velocity_peak, fixed.acceleration_peak
        usq, vsq, asq = fixed.displacement_rms**2, fixed.velocity_rms**2, fixed.acceleration_rms**2
    Z = complex_amplitudes(model, exc, omega, impedance)  # (N, H, 6)
    U = np.einsum("pij,nhj->npih", point_maps(at), Z)  # (N, P, 3, H)
    rate = 1j * omega[:, None, None, None] * exc.orders
    V, A = U * rate, U * rate**2
    p = modes.frequencies
    margin = np.abs(omega[:, None, None] * exc.orders[None, :, None] - p) / p
    return SpeedSweep(omega, peak + series_peak(U, exc.orders), velocity_peak + series_peak(V, exc.orders),
                      np.sqrt(usq + (np.abs(U) ** 2).sum(-1) / 2.0), np.sqrt(vsq + (np.abs(V) ** 2).sum(-1) / 2.0),
                      acceleration_peak + series_peak(A, exc.orders), np.sqrt(asq + (np.abs(A) ** 2).sum(-1) / 2.0),
                      margin)


__all__ = ["SpeedSweep", "speed_sweep"]
