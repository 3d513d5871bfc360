"""Springs and damping of a rigid block on an elastic half-space: Lysmer's and Hall's analogs.

Source: F.E. Richart, J.R. Hall, R.D. Woods, *Vibrations of Soils and Foundations* (1970),
ch. 7 and 10 (Lysmer's analog for vertical motion, Hall's for sliding and rocking); B.M. Das,
G.V. Ramana, *Principles of Soil Dynamics*, 2nd ed., ch. 5 (Eqs. of the vertical, sliding and
rocking analogs and the worked example used in the tests); ACI 351.3R-18, 4.5 (same set).

A rectangular base L × B (L in the plane of motion) is replaced by the circle of the same area
for vertical and sliding motion and of the same second moment for rocking::

    r0 = sqrt(B L / π),           r0ψ = (B L³ / (3π))^(1/4)
    k_z = 4 G r0 / (1 - ν),                     B_z = (1 - ν) m / (4 ρ r0³),          D_z = 0.425 / sqrt(B_z)
    k_x = 32 (1 - ν) G r0 / (7 - 8ν),           B_x = (7 - 8ν) m / (32 (1 - ν) ρ r0³), D_x = 0.2875 / sqrt(B_x)
    k_φ = 8 G r0ψ³ / (3 (1 - ν)),               B_φ = 3 (1 - ν) I_0 / (8 ρ r0ψ⁵),     D_φ = 0.15 / ((1 + B_φ) sqrt(B_φ))

D are the radiation damping ratios of each mode; the soil's material damping ratio is added to
each (Richart et al., 10.3; ACI 351.3R-18, 4.5.1.3).
"""

from __future__ import annotations

import math

from foundation_calc.solvers.soil.springs import SoilSprings

#: Largest dimensionless frequency a0 = ω r/V_s (r the equivalent radius of the motion: r0 for
#: vertical and sliding, r0ψ for rocking, r0θ for torsion) over which the analogs' springs and
#: frequency-independent damping ratios were fitted to the half-space solutions [-].
A0_FITTED = 1.5

#: Where :data:`A0_FITTED` comes from.
A0_SOURCE = "Richart, Hall & Woods (1970), ch. 7"


def equivalent_radii(L, B):
    """Radii of the circles equivalent to an L × B base: (r0 for area, r0ψ for rocking) [m].

    r0 = sqrt(B L/π) has the base's area; r0ψ = (B L³/(3π))^(1/4) has its second moment about
    the axis normal to L (Das & Ramana, ch. 5).

    Parameters
    ----------
    L : base length along the plane of motion [m]
    B : base width, normal to the plane of motion [m]

    >>> r0, r0_psi = equivalent_radii(4.0, 2.0)
    >>> round(float(r0), 4), round(float(r0_psi), 4)
    (1.5958, 1.9197)
    """
    return (B * L / math.pi) ** 0.5, (B * L**3 / (3.0 * math.pi)) ** 0.25


def lysmer_springs(G, rho, nu, L, B, M_tot, I_0, material_damping) -> SoilSprings:
    """K_z, K_x, K_φ and damping ratios of Lysmer's and Hall's analogs (module docstring).

    Parameters
    ----------
    G : shear modulus of the soil, G = ρ V_s² [Pa]
    rho : mass density of the soil [kg/m³]
    nu : Poisson's ratio of the soil [-]
    L : base length along the plane of motion [m]
    B : base width [m]
    M_tot : total vibrating mass (block, machine, rod and slider) [kg]
    I_0 : mass moment of inertia about the base's centroidal axis normal to the plane [kg m²]
    material_damping : material damping ratio of the soil, added to each radiation ratio [-]

    Notes
    -----
    Arithmetic operators only: floats or numpy arrays alike. The analogs hold for a rigid base on the surface of a uniform half-space; the damping ratios
    are frequency-independent (Richart et al. fit them over the dimensionless frequencies of
    block foundations, a0 < 1.5).

    >>> s = lysmer_springs(7.2e7, 1800.0, 0.33, 4.0, 2.0, 34800.0, 1.0e5, 0.0)
    >>> round(float(s.K_z) / 1e6, 1)
    685.9
    """
    r0, r0_psi = equivalent_radii(L, B)
    B_z = (1.0 - nu) * M_tot / (4.0 * rho * r0**3)
    B_x = (7.0 - 8.0 * nu) * M_tot / (32.0 * (1.0 - nu) * rho * r0**3)
    B_phi = 3.0 * (1.0 - nu) * I_0 / (8.0 * rho * r0_psi**5)
    return SoilSprings(
        K_z=4.0 * G * r0 / (1.0 - nu),
        K_x=32.0 * (1.0 - nu) * G * r0 / (7.0 - 8.0 * nu),
        K_phi=8.0 * G * r0_psi**3 / (3.0 * (1.0 - nu)),
        xi_z=0.425 / B_z**0.5 + material_damping,
        xi_x=0.2875 / B_x**0.5 + material_damping,
        xi_phi=0.15 / ((1.0 + B_phi) * B_phi**0.5) + material_damping,
    )


__all__ = ["A0_FITTED", "A0_SOURCE", "equivalent_radii", "lysmer_springs"]
