"""Mass properties of a concrete block foundation carrying a machine, in the plane of motion.

Source: rigid-body statics (Das & Ramana, *Principles of Soil Dynamics*, ch. 5, worked
examples; Richart, Hall & Woods 1970, ch. 10). The block L × B × H (L in the plane of motion,
height H) of density ρ_c stands on the base; the machine of mass m_m has its centre of mass
h_m above the base, over the base's centroid, and I_m about its own centre of mass::

    M   = ρ_c L B H + m_m
    h   = (ρ_c L B H · H/2 + m_m h_m) / M
    I_c = ρ_c L B H (L² + H²)/12 + ρ_c L B H (H/2 - h)² + I_m + m_m (h_m - h)²

I_c is about the axis through the common centre of mass C, normal to the plane of motion.
"""

from __future__ import annotations

from dataclasses import dataclass


@dataclass(frozen=True)
class MassProperties:
    """Mass, moment of inertia about C and height of C above the base.

    Attributes
    ----------
    M : block and machine [kg]
    I_c : about the common centre of mass C, axis normal to the plane of motion [kg m²]
    h : height of C above the base [m]
    """

    M: object
    I_c: object
    h: object


def block_with_machine(L, B, H, rho_c, m_m, h_m, I_m) -> MassProperties:
    """M, I_c and h of a block carrying a machine (module docstring).

    Parameters
    ----------
    L : block length along the plane of motion [m]
    B : block width [m]
    H : block height [m]
    rho_c : density of the block's material [kg/m³]
    m_m : machine mass [kg] (0: block alone)
    h_m : height of the machine's centre of mass above the base [m]
    I_m : machine's moment of inertia about its own centre of mass [kg m²]

    >>> p = block_with_machine(4.0, 2.0, 1.5, 2400.0, 6000.0, 2.0, 0.0)
    >>> float(p.M), round(float(p.h), 6)
    (34800.0, 0.965517)
    """
    m_b = rho_c * L * B * H
    M = m_b + m_m
    h = (m_b * H / 2.0 + m_m * h_m) / M
    I_c = m_b * (L**2 + H**2) / 12.0 + m_b * (H / 2.0 - h) ** 2 + I_m + m_m * (h_m - h) ** 2
    return MassProperties(M=M, I_c=I_c, h=h)


__all__ = ["MassProperties", "block_with_machine"]
