"""Base dashpots of a rigid foundation from damping ratios of its uncoupled modes.

Source: the project's soil note ("What the model needs"); the usual reduction of a damping ratio
ξ of a single-degree-of-freedom mode to its dashpot, C = 2 ξ sqrt(K m), applied to the vertical,
horizontal and rocking modes of the block taken one at a time (Richart, Hall & Woods 1970, ch. 10;
ACI 351.3R-18, 4.5)::

    C_z = 2 ξ_z sqrt(K_z M_tot),   C_x = 2 ξ_x sqrt(K_x M_tot),   C_φ = 2 ξ_φ sqrt(K_φ I_0)

with I_0 = I_c + M_tot h² the mass moment of inertia about the base's centroidal axis.
"""

from __future__ import annotations

from dataclasses import dataclass

import numpy as np


@dataclass(frozen=True)
class BaseDashpots:
    """Viscous dashpots at the base of a foundation.

    Attributes
    ----------
    C_x : horizontal [N s/m], at base level
    C_z : vertical [N s/m]
    C_phi : rocking about the base's centroidal axis [N m s/rad]
    """

    C_x: object
    C_z: object
    C_phi: object


def dashpots_from_ratios(xi_z, xi_x, xi_phi, K_z, K_x, K_phi, M_tot, I_0) -> BaseDashpots:
    """Dashpots C = 2 ξ sqrt(K m) of the three uncoupled modes (module docstring).

    Parameters
    ----------
    xi_z, xi_x, xi_phi : damping ratios of the vertical, horizontal and rocking modes [-]
    K_z, K_x, K_phi : base springs [N/m, N/m, N m/rad]
    M_tot : total vibrating mass [kg]
    I_0 : mass moment of inertia about the base's centroidal axis [kg m²]

    >>> d = dashpots_from_ratios(0.1, 0.0, 0.0, 4.0e6, 1.0, 1.0, 1.0e4, 1.0)
    >>> float(d.C_z)
    40000.0
    """
    return BaseDashpots(
        C_x=2.0 * np.asarray(xi_x) * np.sqrt(K_x * M_tot),
        C_z=2.0 * np.asarray(xi_z) * np.sqrt(K_z * M_tot),
        C_phi=2.0 * np.asarray(xi_phi) * np.sqrt(K_phi * I_0),
    )


__all__ = ["BaseDashpots", "dashpots_from_ratios"]
