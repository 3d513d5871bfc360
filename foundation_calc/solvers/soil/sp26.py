"""Springs and damping of a block foundation from the soil's static deformation modulus.

Source: SP 26.13330.2012 "Foundations of machines with dynamic loads" (updated SNiP
2.02.05-87), section on the elastic characteristics of natural bases, as collected in the
project's soil note: the coefficient of elastic uniform compression

    C_z = b0 E (1 + sqrt(A10 / A)),    A10 = 10 m²

with E the static deformation modulus of the soil and b0 by soil class (:data:`B0_BY_CLASS`),
and the other coefficients from it

    C_x = 0.7 C_z,   C_φ = 2 C_z       (so K_z = C_z A, K_x = C_x A, K_φ = C_φ I)

and the relative damping of steady (harmonic) vibration from the mean static pressure p_m
under the base, in kPa:

    ξ_z = 2 / sqrt(p_m),   ξ_x = 0.6 ξ_z,   ξ_φ = 0.5 ξ_z

The pressure is in kPa by the formula's own numbers (p_m = 100 kPa gives ξ_z = 0.2; in Pa it
would give 0.006). E is the *static* modulus of the site investigation: the dynamic
E = 2 G (1 + ν) from a shear wave velocity gives springs several times stiffer.
"""

from __future__ import annotations

from foundation_calc.solvers.soil.springs import SoilSprings

#: Reference area A10 of the formula for C_z [m²].
A10 = 10.0

#: b0 [1/m] by soil class: 1.0 sands, 1.2 sandy loams and loams, 1.5 clays and coarse soils.
B0_BY_CLASS = {"sand": 1.0, "sandy_loam": 1.2, "loam": 1.2, "clay": 1.5, "coarse": 1.5}

#: Pa per kPa: the damping formula takes the pressure in kPa.
PA_PER_KPA = 1.0e3


def sp26_springs(E, b0, A, I, p_m) -> SoilSprings:
    """K_z, K_x, K_φ and the damping ratios of SP 26.13330 (module docstring).

    Parameters
    ----------
    E : static deformation modulus of the soil [Pa]
    b0 : coefficient of the soil class [1/m] (:data:`B0_BY_CLASS`)
    A : base area [m²]
    I : second moment of the base area about its axis normal to the plane of motion [m⁴]
    p_m : mean static pressure under the base, weight over area [Pa]

    Arithmetic operators only: floats or numpy arrays alike, and no numpy import for a scene.

    >>> s = sp26_springs(3.0e7, 1.0, 10.0, 10.0, 1.0e5)
    >>> float(s.K_z), float(s.K_x), float(s.K_phi), round(float(s.xi_z), 6)
    (600000000.0, 420000000.0, 1200000000.0, 0.2)
    """
    C_z = b0 * E * (1.0 + (A10 / A) ** 0.5)
    xi_z = 2.0 / (p_m / PA_PER_KPA) ** 0.5
    return SoilSprings(
        K_z=C_z * A,
        K_x=0.7 * C_z * A,
        K_phi=2.0 * C_z * I,
        xi_z=xi_z,
        xi_x=0.6 * xi_z,
        xi_phi=0.5 * xi_z,
    )


__all__ = ["A10", "B0_BY_CLASS", "PA_PER_KPA", "sp26_springs"]
