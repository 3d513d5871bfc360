"""Torsional spring and damping of a rigid base on an elastic half-space: Reissner-Sagoci's
analog (with Lysmer's and Hall's) and Gazetas' formula.

Source: F.E. Richart, J.R. Hall, R.D. Woods, *Vibrations of Soils and Foundations* (1970),
ch. 7 and 10 (torsion of a rigid circular base, as collected in B.M. Das, G.V. Ramana,
*Principles of Soil Dynamics*, 2nd ed., ch. 5, and ACI 351.3R-18, 4.5). A rectangular base
L × B is replaced by the circle of the same polar second moment::

    r0θ = (L B (L² + B²) / (6π))^(1/4)
    k_ψ = 16 G r0θ³ / 3,      B_ψ = J_z / (ρ r0θ⁵),      D_ψ = 0.5 / (1 + 2 B_ψ)

J_z: the mass moment of inertia about the vertical axis through the base's centroid.
"""

from __future__ import annotations

import math

import numpy as np


def torsion_radius(L, B):
    """r0θ of the circle with the polar second moment of an L × B base [m].

    >>> round(torsion_radius(2.0, 2.0), 4)
    1.1415
    """
    return (L * B * (L * L + B * B) / (6.0 * math.pi)) ** 0.25


def lysmer_torsion(G, rho, L, B, J_z, material_damping):
    """(k_ψ [N m/rad], damping ratio D_ψ + material damping [-]) of the module docstring.

    Parameters
    ----------
    G : shear modulus [Pa]
    rho : soil density [kg/m³]
    L, B : base sides [m]
    J_z : mass moment of inertia about the vertical axis through the base's centroid [kg m²]
    material_damping : material damping ratio added [-]

    >>> k, D = lysmer_torsion(1.0, 1.0, 2.0, 2.0, 1.0e9, 0.0)
    >>> round(k / torsion_radius(2.0, 2.0) ** 3, 12), D < 1e-8
    (5.333333333333, True)
    """
    r = torsion_radius(L, B)
    B_psi = J_z / (rho * r**5)
    return 16.0 * G * r**3 / 3.0, 0.5 / (1.0 + 2.0 * B_psi) + material_damping




def gazetas_torsion(G, L, B):
    """Static torsional spring of a rectangular surface footing [N m/rad], Gazetas (1991), Table 1:
    K_t = G J_t^0.75 [4 + 11 (1 - χ)^10], J_t = L B (L² + B²)/12 the polar second moment of the
    base, χ = B'/L' (short over long side); L and B may be arrays. Its radiation damping vanishes at low frequency, as
    the rocking's does (:mod:`~foundation_calc.solvers.soil.gazetas`): material damping only.

    >>> round(float(gazetas_torsion(1.0, 2.0, 2.0)) / (8.0 / 3.0) ** 0.75, 12)   # square: 4 + 0
    4.0
    """
    chi = np.minimum(L, B) / np.maximum(L, B)
    J_t = L * B * (L * L + B * B) / 12.0
    return G * J_t**0.75 * (4.0 + 11.0 * (1.0 - chi) ** 10)


__all__ = ["gazetas_torsion", "lysmer_torsion", "torsion_radius"]
