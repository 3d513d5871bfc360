"""A soil stratum of depth H over rigid bedrock: the half-space springs stiffened, the radiation
dashpots cut off below the stratum's own frequencies.

Sources
-------
.. [1] E. Kausel, *Forced vibrations of circular foundations on layered media*, MIT Research
   Report R74-11 (1974); the static springs of a rigid disk of radius R on a stratum of depth H
   over rigid rock, as collected by G. Gazetas, "Analysis of machine foundation vibrations: state
   of the art", Soil Dyn. Earthq. Eng. 2(1), 1983 (stratum over bedrock), and by J.P. Wolf,
   *Dynamic Soil-Structure Interaction* (1985)::

       K_z = 4 G R/(1 - ν) (1 + 1.28 R/H)         vertical
       K_x = 8 G R/(2 - ν) (1 + R/(2H))           horizontal
       K_r = 8 G R³/(3 (1 - ν)) (1 + R/(6H))      rocking

.. [2] G. Gazetas, "Foundation vibrations", ch. 15 of H.-Y. Fang (ed.), *Foundation Engineering
   Handbook*, 2nd ed., 1991 (the stratum's cutoff frequencies and radiation damping); the same
   statement in NIST GCR 12-917-21 (2012), 2.2.3: an undamped layer on rigid rock carries no
   propagating wave below its first natural frequency in the mode's own kind of motion, so the
   foundation radiates nothing there::

       f_s = V_s/(4H)       shear (sway x, y and torsion)
       f_c = V_La/(4H)      compression (vertical and rocking), V_La = 3.4 V_s/(π (1 - ν))

What this module does with them (each factor multiplies the half-space spring of the scene's method,
Lysmer's, Gazetas' or Pais & Kausel's, its dynamic modifier k(a0) included):

- Static factors: [1]'s circle factors on the radius of the circle equivalent to the base in that
  motion, the same radii as Lysmer's analog (:func:`~foundation_calc.solvers.soil.lysmer.equivalent_radii`):
  R = sqrt(B L/π) (same area) for the vertical and horizontal springs, R_r = (B L³/(3π))^(1/4)
  (same second moment about the rocking axis) for rocking. Torsion is left as the half-space's
  (no factor traced to a print; the layer's effect on torsion is the smallest of the four).
- Radiation: the half-space's radiation dashpot C (N s/m; not its damping ratio) at and above the
  cutoff of its motion, nothing below (a step: the transition [2] gives as a figure, not as a
  formula, is not modelled); the soil's material damping ratio is kept at every frequency. With the
  spring η K and the dashpot C unchanged, a damping ratio ξ = ξ_rad + ξ_m of the half-space becomes
  ξ' = g(ω) ξ_rad/sqrt(η) + ξ_m, g = 1 at or above the cutoff, 0 below.

Validity: the factors are fitted to the rigorous stratum for a surface disk; a rectangle is taken
through its equivalent circle (within 10 % of the disk for a near-square base, by construction; an
elongated base, L/B > 2, is stiffened more by a thin layer than its circle says). :data:`H_OVER_R_MIN`
is the smallest depth the static factors are used at without a warning. An embedded base takes the
surface factors with H measured from the surface (Kausel & Ushijima's embedded forms are not
applied). As H → ∞ every factor tends to 1 and both cutoffs to 0: the half-space exactly, at H = ∞.

Arithmetic and ``numpy`` ufuncs only: every argument may be an array and the results broadcast.
"""

from __future__ import annotations

import math
from dataclasses import dataclass

import numpy as np

from foundation_calc.solvers.soil.gazetas import lysmer_analog_velocity
from foundation_calc.solvers.soil.lysmer import equivalent_radii
from foundation_calc.solvers.soil.springs import SoilSprings

#: Kausel's stratum coefficients c of the factor 1 + c R/H ([1]): vertical, horizontal, rocking [-].
KAUSEL_COEFFICIENTS = (1.28, 0.5, 1.0 / 6.0)

#: Smallest H/R at which the static factors are used without a warning [-]: at H = 2R the
#: vertical factor is already 1.64, and the layer below is as deep as the base is wide.
H_OVER_R_MIN = 2.0

#: Where the factors and the cutoffs come from, for messages and the sheet.
SOURCE = "Kausel (1974) via Gazetas (1983); cutoffs V_s/4H, V_La/4H: Gazetas (1991), NIST GCR 12-917-21 2.2.3"


def stratum_factors(R, R_r, H):
    """Static factors (η_z, η_x, η_r) = (1 + 1.28 R/H, 1 + R/(2H), 1 + R_r/(6H)) of [1] [-].

    Parameters
    ----------
    R : radius of the circle of the base's area [m]
    R_r : radius of the circle of the base's second moment about the rocking axis [m]
    H : depth of the stratum, surface to rigid bedrock [m]; ``inf`` gives 1 exactly

    >>> [round(float(f), 4) for f in stratum_factors(1.0, 1.0, 2.0)]
    [1.64, 1.25, 1.0833]
    """
    c_z, c_x, c_r = KAUSEL_COEFFICIENTS
    return 1.0 + c_z * R / H, 1.0 + c_x * R / H, 1.0 + c_r * R_r / H


def cutoff_frequencies(V_s, nu, H):
    """The stratum's cutoff circular frequencies (ω_s, ω_c) = 2π (V_s/(4H), V_La/(4H)) [rad/s] of [2]:
    shear (sway and torsion) and compression (vertical and rocking).

    Parameters
    ----------
    V_s : shear wave velocity of the soil [m/s]
    nu : Poisson's ratio of the soil [-]
    H : depth of the stratum [m]

    >>> w_s, w_c = cutoff_frequencies(200.0, 1.0 / 3.0, 5.0)
    >>> round(float(w_s) / (2 * math.pi), 4), round(float(w_c) / (2 * math.pi), 4)
    (10.0, 16.2338)
    """
    return 2.0 * math.pi * V_s / (4.0 * H), 2.0 * math.pi * lysmer_analog_velocity(V_s, nu) / (4.0 * H)


def radiates(omega, omega_cut):
    """g(ω) = 1.0 where ``omega`` >= ``omega_cut`` [rad/s] (the stratum radiates), 0.0 below.

    >>> radiates(np.array([1.0, 2.0, 3.0]), 2.0).tolist()
    [0.0, 1.0, 1.0]
    """
    return np.where(np.asarray(omega) >= omega_cut, 1.0, 0.0)


@dataclass(frozen=True)
class Stratum:
    """The layer under a base L (in the plane of motion) × B: its static factors and cutoffs.

    Attributes
    ----------
    H : depth of the stratum [m]
    R, R_r : equivalent radii of the base (area; second moment about the rocking axis) [m]
    eta_z, eta_x, eta_r : static factors on the vertical, horizontal and rocking springs [-]
    omega_s, omega_c : cutoff circular frequencies, shear and compression [rad/s]
    """

    H: object
    R: object
    R_r: object
    eta_z: object
    eta_x: object
    eta_r: object
    omega_s: object
    omega_c: object


def stratum_of(L, B, H, V_s, nu) -> Stratum:
    """The :class:`Stratum` under a base L × B [m] (L in the plane of motion) of a soil with shear wave
    velocity ``V_s`` [m/s] and Poisson's ratio ``nu`` [-], bedrock at depth ``H`` [m].

    >>> s = stratum_of(4.0, 2.0, 5.0, 200.0, 1.0 / 3.0)
    >>> round(float(s.eta_z), 4), round(float(s.omega_s), 4)
    (1.4085, 62.8319)
    """
    R, R_r = equivalent_radii(L, B)
    eta_z, eta_x, eta_r = stratum_factors(R, R_r, H)
    omega_s, omega_c = cutoff_frequencies(V_s, nu, H)
    return Stratum(H, R, R_r, eta_z, eta_x, eta_r, omega_s, omega_c)


def _ratio(xi, eta, gate, xi_m):
    """ξ' = g ξ_rad/sqrt(η) + ξ_m of the module docstring, ξ_rad = ξ - ξ_m."""
    return gate * (xi - xi_m) / np.sqrt(eta) + xi_m


def on_stratum(springs: SoilSprings, L, B, H, V_s, nu, material_damping, omega) -> SoilSprings:
    """The half-space ``springs`` of a plane (L along it, B normal to it) [m] on a stratum of depth
    ``H`` [m] at the circular frequency ``omega`` [rad/s] (module docstring).

    Parameters
    ----------
    springs : the half-space method's springs and damping ratios at ``omega``
    L, B : base length in the plane of motion and width normal to it [m]
    H : depth of the stratum, surface to bedrock [m]
    V_s : shear wave velocity [m/s]
    nu : Poisson's ratio [-]
    material_damping : the soil's material damping ratio, included in ``springs``' ratios [-]
    omega : circular frequency [rad/s]

    >>> hs = SoilSprings(1.0, 1.0, 1.0, 0.25, 0.25, 0.25)
    >>> s = on_stratum(hs, 4.0, 2.0, 5.0, 200.0, 1.0 / 3.0, 0.05, 50.0)   # below both cutoffs
    >>> round(float(s.K_z), 4), float(s.xi_z), float(s.xi_x)
    (1.4085, 0.05, 0.05)
    """
    st = stratum_of(L, B, H, V_s, nu)
    shear, compression = radiates(omega, st.omega_s), radiates(omega, st.omega_c)
    xi_m = material_damping
    return SoilSprings(
        K_z=springs.K_z * st.eta_z,
        K_x=springs.K_x * st.eta_x,
        K_phi=springs.K_phi * st.eta_r,
        xi_z=_ratio(springs.xi_z, st.eta_z, compression, xi_m),
        xi_x=_ratio(springs.xi_x, st.eta_x, shear, xi_m),
        xi_phi=_ratio(springs.xi_phi, st.eta_r, compression, xi_m),
    )


def torsion_on_stratum(xi_t, H, V_s, material_damping, omega):
    """The torsional damping ratio on the stratum [-]: its radiation part only at or above the shear
    cutoff ω_s = 2π V_s/(4H) (module docstring; the torsional spring keeps the half-space's).

    >>> round(float(torsion_on_stratum(0.3, 5.0, 200.0, 0.05, 50.0)), 4)
    0.05
    """
    omega_s = 2.0 * math.pi * V_s / (4.0 * H)
    return _ratio(xi_t, 1.0, radiates(omega, omega_s), material_damping)


__all__ = ["H_OVER_R_MIN", "KAUSEL_COEFFICIENTS", "SOURCE", "Stratum", "cutoff_frequencies", "on_stratum",
           "radiates", "stratum_factors", "stratum_of", "torsion_on_stratum"]
