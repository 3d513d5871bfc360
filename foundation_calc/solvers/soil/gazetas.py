"""Static springs of a rigid rectangular footing, surface or embedded, and its radiation dashpots.

Source: G. Gazetas, "Formulas and charts for impedances of surface and embedded foundations",
J. Geotech. Eng. 117(9), 1991, Table 1 (surface), Table 2 (embedded); the same formulas in
NIST GCR 12-917-21 (2012), Tables 2-2a and 2-2b, written with full dimensions.

Gazetas' footing is 2L' × 2B' with L' >= B', χ = B'/L', x along the long side::

    K_z  = 2 G L' / (1 - ν) (0.73 + 1.54 χ^0.75)
    K_y  = 2 G L' / (2 - ν) (2 + 2.5 χ^0.85)                       horizontal, along the short side
    K_x  = K_y - 0.2 G L' (1 - χ) / (0.75 - ν)                     horizontal, along the long side
    K_rx = G / (1 - ν) I_bx^0.75 (L'/B')^0.25 (2.4 + 0.5 χ)        rocking about the long axis x
    K_ry = 3 G / (1 - ν) I_by^0.75 (L'/B')^0.15                    rocking about the short axis y

The crank foundation moves in the plane of its base length L (the scene's ``base_length``):
its horizontal spring is K_x when L is the longer side and K_y when it is the shorter, and its
rocking spring, about the axis normal to that plane, is K_ry or K_rx; in both cases the base's
second moment is the scene's I1 = B L³/12.

Embedment D (sidewall in contact over its full height d = D; A_w = 2 d (2L' + 2B') the
sidewall area, h = D - d/2 the depth of its centroid), Table 2::

    η_z  = [1 + D/(21 B') (1 + 1.3 χ)] [1 + 0.2 (A_w / (4 B' L'))^(2/3)]
    η_y  = [1 + 0.15 (D/B')^0.5] [1 + 0.52 (h A_w / (B' L'²))^0.4]
    η_x  = [1 + 0.15 (D/B')^0.5] [1 + 0.52 (h A_w / (L' B'²))^0.4]
    η_rx = 1 + 1.26 (d/B') [1 + (d/B') (d/D)^-0.2 χ^0.5]
    η_ry = 1 + 0.92 (d/L')^0.6 [1.5 + (d/L')^1.9 (d/D)^-0.6]

(Some open implementations use B' in η_ry's first factor or the larger side as B'; the
published table has L' there and B' the smaller half-side. Pais & Kausel's independent embedded
rocking spring (:mod:`~foundation_calc.solvers.soil.pais_kausel`) sides with L': within 15 % of
this K_ry for L'/B' = 1.5-4 and D/B' <= 0.5, where the B' reading is 19-28 % above it.)

Dashpots and the change of the springs with frequency are those of
:func:`~foundation_calc.solvers.soil.impedance.footing_impedance` (Gazetas' Tables 1-2 for the
dashpots of the base and the sidewalls, Pais & Kausel's closed forms for the stiffness modifiers
and for the rise of the rocking radiation with frequency), taken at the frequency ``omega``. The
damping ratio of each mode at that frequency is ξ = C(ω)/(2 sqrt(K(ω) m)) plus the soil's
material damping; at the mode's own frequency ω = sqrt(K(ω)/m) it is C ω/(2 K), the ratio of
Pais & Kausel's β. At ω = 0 the rocking radiation of a surface footing vanishes (it grows as a0²),
so the rocking damping of the static springs is the material damping alone: evaluate the
springs at the rocking mode's frequency for its damping.
"""

from __future__ import annotations

import numpy as np

from foundation_calc.solvers.soil.impedance import footing_impedance
from foundation_calc.solvers.soil.springs import SoilSprings


def lysmer_analog_velocity(V_s, nu):
    """Lysmer's analog wave velocity V_La = 3.4 V_s / (π (1 - ν)) [m/s] (Gazetas 1991, Table 1).

    Parameters
    ----------
    V_s : shear wave velocity [m/s]
    nu : Poisson's ratio [-]

    >>> round(float(lysmer_analog_velocity(200.0, 1.0 / 3.0)), 3)
    324.676
    """
    return 3.4 * V_s / (np.pi * (1.0 - nu))


def gazetas_springs(G, rho, nu, L, B, D, M_tot, I_0, material_damping, omega=0.0) -> SoilSprings:
    """K_z, K_x, K_φ and damping ratios of a rectangular footing at the frequency ``omega`` (module docstring).

    Parameters
    ----------
    G : shear modulus of the soil [Pa]
    rho : mass density of the soil [kg/m³]
    nu : Poisson's ratio of the soil [-]
    L : base length along the plane of motion [m]
    B : base width, normal to the plane of motion [m]
    D : embedment depth, 0 for a surface footing [m]
    M_tot : total vibrating mass [kg]
    I_0 : mass moment of inertia about the base's centroidal axis normal to the plane [kg m²]
    material_damping : material damping ratio of the soil, added to each radiation ratio [-]
    omega : circular frequency at which the springs and dashpots are taken [rad/s]; 0 (the
        default) gives Gazetas' static springs and the low-frequency dashpots

    >>> s = gazetas_springs(7.2e7, 1800.0, 0.33, 4.0, 2.0, 0.0, 34800.0, 1.0e5, 0.0)
    >>> round(float(s.K_z) / 1e6, 1), round(float(s.K_x) / 1e6, 1)
    (707.4, 549.8)
    """
    return footing_springs(gazetas_static_springs(G, nu, L, B, D), G, rho, nu, L, B, D, M_tot, I_0,
                           material_damping, omega)


def footing_springs(static, G, rho, nu, L, B, D, M_tot, I_0, material_damping, omega) -> SoilSprings:
    """The springs K(ω) and damping ratios of a footing whose static springs ``static`` = (K_z,
    K_x, K_φ) [N/m, N/m, N m/rad] a closed form gave (Gazetas', Pais & Kausel's): the dynamic
    modifiers and radiation dashpots of
    :func:`~foundation_calc.solvers.soil.impedance.footing_impedance` at ``omega`` [rad/s], each
    ratio ξ = C/(2 sqrt(K m)) plus the material damping. Other parameters as :func:`gazetas_springs`.
    """
    K_z, K_h, K_phi = static
    z = footing_impedance(K_z, K_h, K_phi, G, rho, nu, L, B, D, omega)
    return SoilSprings(
        K_z=z.K_z,
        K_x=z.K_x,
        K_phi=z.K_phi,
        xi_z=z.C_z / (2.0 * np.sqrt(z.K_z * M_tot)) + material_damping,
        xi_x=z.C_x / (2.0 * np.sqrt(z.K_x * M_tot)) + material_damping,
        xi_phi=z.C_phi / (2.0 * np.sqrt(z.K_phi * I_0)) + material_damping,
    )


def gazetas_static_springs(G, nu, L, B, D):
    """Static K_z, K_x, K_φ of Gazetas' Tables 1-2 (module docstring) [N/m, N/m, N m/rad].

    Parameters
    ----------
    G : shear modulus of the soil [Pa]
    nu : Poisson's ratio of the soil [-]
    L : base length along the plane of motion [m]
    B : base width, normal to the plane of motion [m]
    D : embedment depth, 0 for a surface footing [m]
    """
    long_half = np.maximum(L, B) / 2.0
    short_half = np.minimum(L, B) / 2.0
    chi = short_half / long_half
    along_long = L >= B
    I_b = B * L**3 / 12.0

    K_z = 2.0 * G * long_half / (1.0 - nu) * (0.73 + 1.54 * chi**0.75)
    K_y = 2.0 * G * long_half / (2.0 - nu) * (2.0 + 2.5 * chi**0.85)
    K_x_long = K_y - 0.2 * G * long_half * (1.0 - chi) / (0.75 - nu)
    K_rx = G / (1.0 - nu) * I_b**0.75 * (1.0 / chi) ** 0.25 * (2.4 + 0.5 * chi)
    K_ry = 3.0 * G / (1.0 - nu) * I_b**0.75 * (1.0 / chi) ** 0.15

    d = D  # sidewall in contact over the full embedment
    A_w = 2.0 * d * (2.0 * long_half + 2.0 * short_half)
    h_w = D - d / 2.0
    eta_z = (1.0 + D / (21.0 * short_half) * (1.0 + 1.3 * chi)) * (
        1.0 + 0.2 * (A_w / (4.0 * short_half * long_half)) ** (2.0 / 3.0)
    )
    sidewall = 1.0 + 0.15 * np.sqrt(D / short_half)
    eta_y = sidewall * (1.0 + 0.52 * (h_w * A_w / (short_half * long_half**2)) ** 0.4)
    eta_x = sidewall * (1.0 + 0.52 * (h_w * A_w / (long_half * short_half**2)) ** 0.4)
    embedded = D > 0.0
    depth_ratio = np.where(embedded, d / np.where(embedded, D, 1.0), 1.0)  # d/D, 1 when surface
    eta_rx = 1.0 + 1.26 * (d / short_half) * (1.0 + (d / short_half) * depth_ratio**-0.2 * np.sqrt(chi))
    eta_ry = 1.0 + 0.92 * (d / long_half) ** 0.6 * (1.5 + (d / long_half) ** 1.9 * depth_ratio**-0.6)

    K_h = np.where(along_long, K_x_long * eta_x, K_y * eta_y)
    K_phi = np.where(along_long, K_ry * eta_ry, K_rx * eta_rx)
    return K_z * eta_z, K_h, K_phi


__all__ = ["footing_springs", "gazetas_springs", "gazetas_static_springs", "lysmer_analog_velocity"]
