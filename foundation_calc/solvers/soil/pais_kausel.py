"""Static springs of a rigid rectangular footing, surface or embedded, by Pais & Kausel's closed forms.

Source: J. Pais, E. Kausel, "Approximate formulas for dynamic stiffnesses of rigid foundations",
Soil Dyn. Earthq. Eng. 7(4), 1988, pp. 213-227, as tabulated in NIST GCR 12-917-21 (2012),
Table 2-2a (surface) and Table 2-2b (embedment factors). Footing 2L × 2B with half-sides L >= B,
r = L/B, x along the long side; embedment D with the sidewalls in contact over the full depth::

    K_z  = G B / (1 - ν) [3.1 r^0.75 + 1.6]
    K_y  = G B / (2 - ν) [6.8 r^0.65 + 0.8 r + 1.6]       horizontal, along the short side
    K_x  = G B / (2 - ν) [6.8 r^0.65 + 2.4]               horizontal, along the long side
    K_rx = G B³ / (1 - ν) [3.2 r + 0.8]                   rocking about the long axis x
    K_ry = G B³ / (1 - ν) [3.73 r^2.4 + 0.27]             rocking about the short axis y
    K_t  = G B³ [4.25 r^2.45 + 4.06]                      torsion about the vertical

    η_z  = 1 + (0.25 + 0.25/r) (D/B)^0.8
    η_x  = η_y = 1 + (0.33 + 1.34/(1 + r)) (D/B)^0.8
    η_rx = 1 + D/B + 1.6/(0.35 + r) (D/B)²
    η_ry = 1 + D/B + 1.6/(0.35 + r⁴) (D/B)²

Pais & Kausel fitted these to boundary-element results for the half-space; Gazetas (1991) fitted
his formulas (:mod:`~foundation_calc.solvers.soil.gazetas`) to other rigorous solutions, so the two
are independent estimates of the same springs. For a square the pairs K_x = K_y and K_rx = K_ry
coincide (2.4 = 0.8 + 1.6, 4.0 = 3.73 + 0.27), as the symmetry requires. The horizontal spring
along the long side is the smaller one, as in Gazetas' K_x < K_y.

The crank foundation moves in the plane of its base length L (the scene's ``base_length``, the
full side): its horizontal spring is K_x when that side is the longer and K_y when it is the
shorter, and its rocking spring (about the axis normal to the plane) K_ry or K_rx. The dashpots
and the change with frequency are those of
:func:`~foundation_calc.solvers.soil.impedance.footing_impedance`, as for Gazetas' springs.

Arithmetic and ``numpy`` ufuncs only: every argument may be an array.
"""

from __future__ import annotations

import numpy as np

from foundation_calc.solvers.soil.gazetas import footing_springs
from foundation_calc.solvers.soil.springs import SoilSprings


def pais_kausel_static_springs(G, nu, L, B, D):
    """Static K_z, K_x, K_φ of the module docstring in the plane of ``L`` [N/m, N/m, N m/rad].

    Parameters
    ----------
    G : shear modulus of the soil [Pa]
    nu : Poisson's ratio of the soil [-]
    L : base length along the plane of motion (full side) [m]
    B : base width, normal to the plane of motion (full side) [m]
    D : embedment depth, 0 for a surface footing [m]

    >>> K_z, K_h, K_phi = pais_kausel_static_springs(1.0, 0.0, 2.0, 2.0, 0.0)   # unit square, B = 1
    >>> round(float(K_z), 12), round(float(K_h), 12), round(float(K_phi), 12)
    (4.7, 4.6, 4.0)
    """
    half_long = np.maximum(L, B) / 2.0
    half_short = np.minimum(L, B) / 2.0
    r = half_long / half_short
    along_long = L >= B

    K_z = G * half_short / (1.0 - nu) * (3.1 * r**0.75 + 1.6)
    K_y = G * half_short / (2.0 - nu) * (6.8 * r**0.65 + 0.8 * r + 1.6)
    K_x = G * half_short / (2.0 - nu) * (6.8 * r**0.65 + 2.4)
    K_rx = G * half_short**3 / (1.0 - nu) * (3.2 * r + 0.8)
    K_ry = G * half_short**3 / (1.0 - nu) * (3.73 * r**2.4 + 0.27)

    depth = D / half_short
    eta_z = 1.0 + (0.25 + 0.25 / r) * depth**0.8
    eta_h = 1.0 + (0.33 + 1.34 / (1.0 + r)) * depth**0.8
    eta_rx = 1.0 + depth + 1.6 / (0.35 + r) * depth**2
    eta_ry = 1.0 + depth + 1.6 / (0.35 + r**4) * depth**2

    K_h = np.where(along_long, K_x, K_y) * eta_h
    K_phi = np.where(along_long, K_ry * eta_ry, K_rx * eta_rx)
    return K_z * eta_z, K_h, K_phi


def pais_kausel_torsion(G, L, B):
    """Static torsional spring of a rectangular surface footing, K_t = G B³ [4.25 r^2.45 + 4.06]
    (module docstring) [N m/rad]; L, B the full sides [m] in either order.

    >>> round(float(pais_kausel_torsion(1.0, 2.0, 2.0)), 12)   # unit square: 4.25 + 4.06
    8.31
    """
    half_short, r = np.minimum(L, B) / 2.0, np.maximum(L, B) / np.minimum(L, B)
    return G * half_short**3 * (4.25 * r**2.45 + 4.06)


def pais_kausel_springs(G, rho, nu, L, B, D, M_tot, I_0, material_damping, omega=0.0) -> SoilSprings:
    """K_z, K_x, K_φ and damping ratios of a rectangular footing at the frequency ``omega``:
    Pais & Kausel's static springs (module docstring) with the dynamic modifiers and dashpots of
    :func:`~foundation_calc.solvers.soil.gazetas.footing_springs`. Parameters as
    :func:`~foundation_calc.solvers.soil.gazetas.gazetas_springs`.

    >>> s = pais_kausel_springs(7.2e7, 1800.0, 0.33, 4.0, 2.0, 0.0, 34800.0, 1.0e5, 0.0)
    >>> round(float(s.K_z) / 1e6, 1), round(float(s.K_x) / 1e6, 1)
    (732.2, 563.5)
    """
    static = pais_kausel_static_springs(G, nu, L, B, D)
    return footing_springs(static, G, rho, nu, L, B, D, M_tot, I_0, material_damping, omega)


__all__ = ["pais_kausel_springs", "pais_kausel_static_springs", "pais_kausel_torsion"]
