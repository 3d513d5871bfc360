"""Head impedances of one flexible pile: static springs from published closed forms, their
frequency dependence and radiation from the pile on a dynamic Winkler foundation.

Sources
-------
.. [1] EN 1998-5:2004, Annex C (informative), Table C.1: static head stiffnesses of flexible
   piles (after Gazetas 1991), E_s the Young's modulus of the table's soil model at depth z = d,
   which Annex C sets to 3 G (an incompressible soil's; not 2 G (1 + ν))::

       profile            K_HH/(d E_s)          K_MM/(d³ E_s)         K_HM/(d² E_s)
       E = E_s            1.08 (E_p/E_s)^0.21   0.16 (E_p/E_s)^0.75   -0.22 (E_p/E_s)^0.50
       E = E_s z/d        0.60 (E_p/E_s)^0.35   0.14 (E_p/E_s)^0.80   -0.17 (E_p/E_s)^0.60
       E = E_s sqrt(z/d)  0.79 (E_p/E_s)^0.28   0.15 (E_p/E_s)^0.77   -0.24 (E_p/E_s)^0.53

.. [2] G. Gazetas, "Foundation vibrations", ch. 15 of *Foundation Engineering Handbook*, 2nd ed.
   (H.-Y. Fang, ed.), 1991: the active length of a flexible pile, l_a ≈ 2 d (E_p/E_s)^(1/4)
   (uniform), 2 d (E_p/E_s)^0.20 (linear), 2 d (E_p/E_s)^0.22 (parabolic); Table C.1's source.
.. [3] M.F. Randolph, C.P. Wroth, "Analysis of deformation of vertically loaded piles",
   J. Geotech. Eng. Div. ASCE 104(GT12), 1978, Eq. (17): the head stiffness of a compressible
   pile with G rising linearly with depth::

       P/(w G_L r0) = [4η/((1 - ν) ξ) + (2π ρ/ζ) (tanh μL/μL) (L/r0)]
                      / [1 + (1/(π λ)) (4η/((1 - ν) ξ)) (tanh μL/μL) (L/r0)]
       ζ = ln(r_m/r0), r_m = {0.25 + ξ [2.5 ρ (1 - ν) - 0.25]} L, λ = E_p/G_L,
       (μL)² = (2/(ζ λ)) (L/r0)², η = r_b/r0 = 1, ξ = G_L/G_b, ρ = G(L/2)/G_L

   G_L the soil's shear modulus at the tip, G_b below it: ξ = 1 for a floating pile (the same
   soil under the tip), ξ → 0 for an end-bearing one (the tip on rock; the limit is taken).
.. [4] N. Makris, G. Gazetas, "Dynamic pile-soil-pile interaction. Part II: lateral and seismic
   response", Earthq. Eng. Struct. Dyn. 21, 1992, and G. Gazetas, N. Makris, "Part I: analysis
   of axial vibration", ibid. 20, 1991: Winkler springs and dashpots per unit length of pile,
   a0 = ω d/V_s::

       k_x = 1.2 E_s,                       c_x = 6 a0^(-1/4) ρ V_s d
       k_z = 0.6 E_s (1 + 0.5 sqrt(a0)),    c_z = 1.2 a0^(-1/4) ρ V_s π d

   (material damping excluded here: the scene adds the soil's ratio to each motion, as for
   the footings).
.. [5] M.F. Randolph, "Piles subjected to torsion", J. Geotech. Eng. Div. ASCE 107(GT8), 1981:
   the shaft's torsional reaction per unit length 4π G r0² of a long cylinder in an elastic
   medium (plane strain), whence the head stiffness sqrt(4π G r0² G_p J_p) tanh(μ_t L) of a
   shaft on that reaction; its radiation at high frequency 2π r0³ ρ V_s per unit length (SH
   waves from the shaft, the plane-strain limit).

Dynamic head impedances, K(ω) + iω C(ω) = K_static × χ(ω)^p: the static value is the closed form
([1], [3], [5]) and the frequency shape that of a long pile on the Winkler foundation of [4] in a
uniform soil equal to the profile's at a representative depth z_r (l_a/2 laterally, L/2
vertically and in torsion). A semi-infinite beam on springs k + iωc - m ω² has the head
stiffnesses 4 EI λ³, -2 EI λ², 2 EI λ with λ⁴ = (k + iωc - m ω²)/(4 EI): with
χ = 1 + iω c/k - m ω²/k the sway, coupling and rocking go as χ^(3/4), χ^(1/2), χ^(1/4); a shaft in
torsion as χ^(1/2). The vertical shape is that of a rod of length L on k_z, c_z (end-bearing:
fixed tip; floating: a rigid disc at the tip, 4 G r0/(1 - ν) and Lysmer's 3.4 r0² sqrt(ρ G)/(1 - ν)),
divided by its own static value.

Arithmetic and numpy ufuncs only: every argument may be an array and the results broadcast.
"""

from __future__ import annotations

from dataclasses import dataclass

import numpy as np

#: The soil profiles of [1]: the soil's Young's modulus E(z) = E_s f(z/d) with f = 1, z/d, sqrt(z/d).
PROFILES = ("uniform", "linear", "parabolic")

#: Table C.1 of EN 1998-5 ([1]): per profile, (coefficient, exponent of E_p/E_s) of K_HH/(d E_s),
#: K_MM/(d³ E_s) and K_HM/(d² E_s).
TABLE_C1 = {
    "uniform": ((1.08, 0.21), (0.16, 0.75), (-0.22, 0.50)),
    "linear": ((0.60, 0.35), (0.14, 0.80), (-0.17, 0.60)),
    "parabolic": ((0.79, 0.28), (0.15, 0.77), (-0.24, 0.53)),
}

#: Exponent of E_p/E_s in the active length l_a = 2 d (E_p/E_s)^n of [2], per profile.
ACTIVE_LENGTH_EXPONENT = {"uniform": 0.25, "linear": 0.20, "parabolic": 0.22}

#: Winkler coefficients of [4]: k_x = 1.2 E_s, c_x = 6 a0^(-1/4) ρ V_s d; k_z = 0.6 E_s (1 + 0.5 sqrt a0),
#: c_z = 1.2 a0^(-1/4) ρ V_s π d.
K_X, C_X, K_Z, C_Z = 1.2, 6.0, 0.6, 1.2

#: Smallest a0 = ω d/V_s at which the a0^(-1/4) of [4]'s dashpots is taken [-]: the fits start
#: there; below it the dashpot is held (a finite dashpot at rest, radiation iω C → 0 with ω).
A0_MIN = 0.05

#: Largest a0 = ω d/V_s the pile's impedances are taken to hold to [-]: Makris & Gazetas ([4]) fitted
#: their Winkler springs and dashpots, and Dobry & Gazetas checked their interaction factors, over
#: the frequencies of their figures, which end about there (not checked against the print here).
A0_FITTED = 1.0

#: Where :data:`A0_FITTED` comes from.
A0_SOURCE = "Makris & Gazetas (1992), Dobry & Gazetas (1988): figures to a0 = ω d/V_s of about 1"

#: Poisson's ratio of the pile's material for its shear modulus G_p = E_p/(2 (1 + ν_p)) in torsion
#: [-] (concrete, EN 1992-1-1, 3.1.3(4)); torsion of single piles is a small part of a group's.
PILE_POISSON = 0.2


def profile_factor(z_over_d, profile):
    """f(z/d) of the soil's modulus E(z) = E_s f(z/d) ([1]) [-]: 1, z/d or sqrt(z/d).

    >>> [float(profile_factor(4.0, p)) for p in PROFILES]
    [1.0, 4.0, 2.0]
    """
    z = np.asarray(z_over_d, dtype=float)
    return {"uniform": np.ones_like(z), "linear": z, "parabolic": np.sqrt(z)}[profile]


def lateral_static(E_s, E_p, d, profile):
    """(K_HH [N/m], K_MM [N m/rad], K_HM [N/rad]) of a fixed-head flexible pile, Table C.1 of [1].

    Parameters
    ----------
    E_s : the soil's Young's modulus at depth d [Pa]
    E_p : the pile's Young's modulus [Pa]
    d : pile diameter [m]
    profile : "uniform", "linear" or "parabolic"

    K_HM is negative in [1]'s sign convention (a head force with the rotation held gives a moment
    against it).

    >>> [round(float(k), 2) for k in lateral_static(1.0, 1000.0, 1.0, "uniform")]
    [4.61, 28.45, -6.96]
    """
    ratio = E_p / E_s
    (a, m), (b, n), (c, p) = TABLE_C1[profile]
    return d * E_s * a * ratio**m, d**3 * E_s * b * ratio**n, d**2 * E_s * c * ratio**p


def active_length(E_s, E_p, d, profile):
    """l_a = 2 d (E_p/E_s)^n [m] of [2]: below it a flexible pile hardly moves; Table C.1 holds
    for L >= l_a.

    >>> round(float(active_length(1.0, 1.0e4, 0.6, "uniform")), 3)
    12.0
    """
    return 2.0 * d * (E_p / E_s) ** ACTIVE_LENGTH_EXPONENT[profile]


def vertical_static(G_L, nu, E_p, d, L, rho_G, end_bearing):
    """K_v [N/m] of a compressible pile, Randolph & Wroth ([3], module docstring).

    Parameters
    ----------
    G_L : the soil's shear modulus at the tip's depth [Pa]
    nu : Poisson's ratio of the soil [-]
    E_p : the pile's Young's modulus [Pa]
    d, L : the pile's diameter and length [m]
    rho_G : ρ = G(L/2)/G_L, the profile's mid-depth modulus over the tip's [-] (1 uniform)
    end_bearing : True for a tip on rock (ξ → 0), False for a floating pile (ξ = 1)

    >>> round(float(vertical_static(1.0, 0.5, 3000.0, 1.0, 30.0, 1.0, False)) / 0.5, 1)
    78.7
    """
    r0 = d / 2.0
    xi = np.where(end_bearing, 0.0, 1.0)
    r_m = (0.25 + xi * (2.5 * rho_G * (1.0 - nu) - 0.25)) * L
    zeta = np.log(r_m / r0)
    lam = E_p / G_L
    muL = np.sqrt(2.0 / (zeta * lam)) * L / r0
    shaft = 2.0 * np.pi * rho_G / zeta * np.tanh(muL) / muL * L / r0
    t = np.tanh(muL) / muL * L / r0 / (np.pi * lam)
    # base term b = 4η/((1 - ν) ξ); (b + shaft)/(1 + b t) with b → ∞ at ξ = 0 is 1/t
    b = 4.0 / ((1.0 - nu) * np.where(end_bearing, 1.0, xi))
    ratio = np.where(end_bearing, 1.0 / t, (b + shaft) / (1.0 + b * t))
    return ratio * G_L * r0


def torsion_static(G, E_p, d, L):
    """K_T [N m/rad] of a shaft on the torsional reaction 4π G r0² per unit length ([5]):
    sqrt(k_t G_p J_p) tanh(μ_t L), μ_t = sqrt(k_t/(G_p J_p)), J_p = π d⁴/32,
    G_p = E_p/(2 (1 + :data:`PILE_POISSON`)).

    >>> round(float(torsion_static(1.0e7, 3.0e10, 0.6, 15.0)) / 1e6, 3)
    42.383
    """
    k_t = 4.0 * np.pi * G * (d / 2.0) ** 2
    GJ = E_p / (2.0 * (1.0 + PILE_POISSON)) * np.pi * d**4 / 32.0
    return np.sqrt(k_t * GJ) * np.tanh(np.sqrt(k_t / GJ) * L)


@dataclass(frozen=True)
class PileHead:
    """One pile's head impedances K + iω C at a frequency (complex; floats or arrays).

    Attributes
    ----------
    K_v : vertical [N/m]
    K_HH, K_MM, K_HM : sway [N/m], rocking [N m/rad] and their coupling [N/rad] of a fixed head
        (Table C.1's sign); a pinned head has K_MM = K_HM = 0 and the condensed sway
        K_HH - K_HM²/K_MM
    K_T : torsion [N m/rad]
    l_a : active length [m]
    """

    K_v: object
    K_HH: object
    K_MM: object
    K_HM: object
    K_T: object
    l_a: object


def lateral_shape(E, rho, V_s, d, m_p, omega):
    """χ = 1 + iω c_x/k_x - m_p ω²/k_x of the lateral Winkler foundation of [4] [-].

    Parameters
    ----------
    E, rho, V_s : the soil's Young's modulus [Pa], density [kg/m³], shear-wave velocity [m/s]
    d : pile diameter [m]
    m_p : pile mass per unit length [kg/m]
    omega : circular frequency [rad/s]
    """
    a0 = np.maximum(omega * d / V_s, A0_MIN)
    k = K_X * E
    return 1.0 + 1j * omega * C_X * a0**-0.25 * rho * V_s * d / k - m_p * omega**2 / k


def vertical_shape(E, G_tip, nu, rho, V_s, E_p, d, L, m_p, end_bearing, omega):
    """Z(ω)/Z(0) of a rod of length L on the axial Winkler foundation of [4] (module docstring) [-].

    Parameters
    ----------
    E, rho, V_s : the soil's Young's modulus [Pa], density [kg/m³] and shear-wave velocity [m/s]
        along the shaft (the equivalent uniform soil)
    G_tip, nu : the soil's shear modulus [Pa] at the tip and Poisson's ratio [-]
    E_p, d, L, m_p : the pile's modulus [Pa], diameter, length [m], mass per length [kg/m]
    end_bearing : fixed tip (True) or a rigid disc on the soil at the tip (False)
    omega : circular frequency [rad/s]
    """
    EA = E_p * np.pi * d**2 / 4.0
    r0 = d / 2.0

    def head(w):
        a0 = np.maximum(w * d / V_s, A0_MIN)
        spring = K_Z * E * (1.0 + 0.5 * np.sqrt(w * d / V_s)) + 1j * w * C_Z * a0**-0.25 * rho * V_s * np.pi * d
        mu = np.sqrt((spring - m_p * w**2 + 0j) / EA)
        t = np.tanh(mu * L)
        base = (4.0 * G_tip * r0 + 1j * w * 3.4 * r0**2 * np.sqrt(rho * G_tip)) / (1.0 - nu) / (EA * mu)
        return np.where(end_bearing, EA * mu / t, EA * mu * (base + t) / (1.0 + base * t))

    return head(np.asarray(omega, dtype=float)) / head(np.zeros_like(np.asarray(omega, dtype=float)))


def single_pile(d, L, E_p, rho_p, G_s, nu, rho, profile, end_bearing, omega) -> PileHead:
    """Head impedances of one pile at the circular frequency ``omega`` (module docstring).

    Parameters
    ----------
    d, L : pile diameter and length [m]
    E_p, rho_p : the pile's Young's modulus [Pa] and density [kg/m³]
    G_s : the soil's shear modulus at depth z = d [Pa] (Table C.1's E_s = 3 G_s)
    nu, rho : the soil's Poisson's ratio [-] and density [kg/m³]
    profile : "uniform", "linear" or "parabolic": G(z) = G_s f(z/d) (:func:`profile_factor`)
    end_bearing : tip on rock (True) or floating (False)
    omega : circular frequency [rad/s]; 0 gives the static springs

    >>> p = single_pile(0.6, 15.0, 3.0e10, 2500.0, 7.2e7, 0.33, 1800.0, "uniform", False, 0.0)
    >>> round(float(p.K_HH.real) / 1e6, 1), round(float(p.K_v.real) / 1e6, 1)
    (394.4, 880.0)
    """
    omega = np.asarray(omega, dtype=float)
    E_s = 3.0 * G_s  # [1] Annex C: "E_s is a Young's modulus of the soil model, equal to 3G"
    m_p = rho_p * np.pi * d**2 / 4.0
    K_HH, K_MM, K_HM = lateral_static(E_s, E_p, d, profile)
    l_a = active_length(E_s, E_p, d, profile)

    def at(z):
        f = profile_factor(np.maximum(z, d) / d, profile)  # the profile is defined from z = d (Table C.1)
        return G_s * f, np.sqrt(G_s * f / rho)

    G_a, V_a = at(l_a / 2.0)
    chi = lateral_shape(2.0 * G_a * (1.0 + nu), rho, V_a, d, m_p, omega)
    G_m, V_m = at(L / 2.0)
    G_L, _ = at(L)
    K_v = vertical_static(G_L, nu, E_p, d, L, G_m / G_L, end_bearing)
    shape_v = vertical_shape(2.0 * G_m * (1.0 + nu), G_L, nu, rho, V_m, E_p, d, L, m_p, end_bearing, omega)
    k_t = 4.0 * np.pi * G_m * (d / 2.0) ** 2
    chi_t = 1.0 + 1j * omega * 2.0 * np.pi * (d / 2.0) ** 3 * rho * V_m / k_t
    return PileHead(
        K_v=K_v * shape_v,
        K_HH=K_HH * chi**0.75,
        K_MM=K_MM * chi**0.25,
        K_HM=K_HM * chi**0.5,
        K_T=torsion_static(G_m, E_p, d, L) * chi_t**0.5,
        l_a=l_a,
    )


def pinned(head: PileHead) -> PileHead:
    """The same pile with its head free to rotate: K_HH - K_HM²/K_MM, no rocking or coupling."""
    return PileHead(head.K_v, head.K_HH - head.K_HM**2 / head.K_MM, 0.0 * head.K_MM, 0.0 * head.K_HM, head.K_T, head.l_a)


__all__ = ["A0_FITTED", "A0_MIN", "A0_SOURCE", "PILE_POISSON", "PROFILES", "PileHead", "TABLE_C1", "active_length", "lateral_shape",
           "lateral_static", "pinned", "profile_factor", "single_pile", "torsion_static", "vertical_shape",
           "vertical_static"]
