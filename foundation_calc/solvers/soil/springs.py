"""What every soil method returns: the base springs and the damping ratio of each uncoupled mode.

A soil method (Lysmer's analogs, Gazetas' formulas, SP 26's coefficients) turns soil data into
the three springs of a rigid block at its base and one damping ratio per direction; the ratios
become dashpots through :func:`~foundation_calc.solvers.soil.dashpots.dashpots_from_ratios`.
"""

from __future__ import annotations

from dataclasses import dataclass


@dataclass(frozen=True)
class SoilSprings:
    """Base springs and damping ratios of a rigid foundation (floats or equally shaped arrays).

    Attributes
    ----------
    K_z : vertical spring [N/m]
    K_x : horizontal spring at base level, along the plane of motion [N/m]
    K_phi : rocking spring about the base's centroidal axis normal to the plane of motion [N m/rad]
    xi_z, xi_x, xi_phi : damping ratios of the uncoupled vertical, horizontal and rocking modes [-]
    """

    K_z: object
    K_x: object
    K_phi: object
    xi_z: object
    xi_x: object
    xi_phi: object


@dataclass(frozen=True)
class UncoupledFrequencies:
    """Natural circular frequencies of the block's modes taken one at a time [rad/s].

    Attributes
    ----------
    omega_z : vertical, sqrt(K_z / M_tot)
    omega_x : horizontal (sliding with rocking held), sqrt(K_x / M_tot)
    omega_phi : rocking about the base axis (sliding held), sqrt((K_φ - P h) / I_0)
    """

    omega_z: object
    omega_x: object
    omega_phi: object


def uncoupled_frequencies(K_z, K_x, K_phi, M_tot, I_0, h, g) -> UncoupledFrequencies:
    """Frequencies of the vertical, horizontal and rocking modes of the block, one at a time.

    Source: Richart, Hall & Woods (1970), ch. 10; Das & Ramana, *Principles of Soil Dynamics*,
    ch. 5 (ω_n = sqrt(k/m) of each mode). The rocking mode rotates about the base's centroidal
    axis with moment of inertia I_0 = I_c + M_tot h² and loses the weight's overturning moment
    P h = M_tot g h (the paper's (3.4))::

        ω_z = sqrt(K_z / M_tot),   ω_x = sqrt(K_x / M_tot),   ω_φ = sqrt((K_φ - M_tot g h) / I_0)

    Parameters
    ----------
    K_z, K_x : vertical and horizontal base springs [N/m]
    K_phi : rocking spring [N m/rad]
    M_tot : total vibrating mass [kg]
    I_0 : mass moment of inertia about the base's centroidal axis [kg m²]
    h : height of the centre of mass above the base [m]
    g : acceleration of gravity [m/s²]

    Returns ω_φ = 0 where K_φ <= M_tot g h (the block tips over; the caller reports that).
    Arithmetic operators only: floats or numpy arrays alike.

    >>> f = uncoupled_frequencies(4.0e6, 1.0e6, 2.0e6, 1.0e4, 1.0e4, 0.0, 9.81)
    >>> float(f.omega_z), float(f.omega_x), float(f.omega_phi)
    (20.0, 10.0, 14.142135623730951)
    """
    net = K_phi - M_tot * g * h
    return UncoupledFrequencies(
        omega_z=(K_z / M_tot) ** 0.5,
        omega_x=(K_x / M_tot) ** 0.5,
        omega_phi=(net * (net > 0.0) / I_0) ** 0.5,
    )


__all__ = ["SoilSprings", "UncoupledFrequencies", "uncoupled_frequencies"]
