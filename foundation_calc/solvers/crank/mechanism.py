"""Crank-slider mechanism of Krichever & Makarov [1]_: rod lumping and time averages.

Conventions (docs/crank-foundation.md, "The model"): body axes u (horizontal) and v (vertical, positive downward)
through the block's centre of mass C; the crank axis A is at (0, -a); the crank angle φ = ωt is
measured from the downward vertical; crank pin M' = A + r(-sin φ, cos φ); slider pin
M'' = A + (0, s) with s = r cos φ + l cos ψ and sin ψ = λ sin φ, λ = r/l.

References
----------
.. [1] M.F. Krichever, S.M. Makarov, "Application of the small-parameter method to the problem
   of forced vibrations of the foundation of a crank-slider mechanism".
"""

from __future__ import annotations

from dataclasses import dataclass

import numpy as np


@dataclass(frozen=True)
class CrankDesign:
    """Every input of the crank-foundation problem, in SI units and the paper's symbols.

    Attributes
    ----------
    M : block and machine frame, without rod and slider [kg]
    I_c : block's moment of inertia about its centre of mass C [kg m²]
    h : height of C above the base [m]
    S : base area [m²]
    I1 : second moment of the base area about its centroidal axis [m⁴]
    c : coefficient of elastic uniform compression [N/m³]; vertical spring K_z = c S
    c1 : coefficient of elastic uniform shear [N/m³]; horizontal spring K_x = c1 S at the base
    c_phi : coefficient of elastic non-uniform compression [N/m³]; rocking spring K_φ = c_phi I1
        (the paper takes c_phi = c)
    C_x : horizontal base dashpot [N s/m], acting on x' - h θ' like K_x on x - h θ
    C_z : vertical base dashpot [N s/m]
    C_phi : rocking base dashpot [N m s/rad] about the base's centroidal axis (0, 0, 0: undamped,
        the paper's model)
    omega : crank speed relative to the foundation [rad/s]
    r : crank radius [m]
    l : rod length [m]
    a : signed distance from the crank axis A to C, positive when A is above C [m]
    rod : the rod with the slider lumped in
    drive_on_foundation : the motor's reaction torque acts on the foundation
    g : acceleration of gravity [m/s²]
    K_xphi, C_xphi : the support's coupling of u_x with θ_y at O [N/rad; N s/rad] (a pile group's
        sway-rocking); 0 for the paper's uncoupled springs, whose closed forms hold only then
        (:attr:`coupled`)
    soil_frequency : the frequency [rad/s] a frequency-dependent support's springs and dashpots were
        taken at (0: the static springs, or a support whose springs do not depend on frequency); at
        ω ≠ 0 they are the real and imaginary parts of an impedance, on which no stability is
        judged (:func:`~foundation_calc.solvers.crank.frequencies.require_stable_design`)
    """

    M: float
    I_c: float
    h: float
    S: float
    I1: float
    c: float
    c1: float
    c_phi: float
    C_x: float
    C_z: float
    C_phi: float
    omega: float
    r: float
    l: float
    a: float
    rod: "LumpedRod"
    drive_on_foundation: bool
    g: float
    K_xphi: float = 0.0
    C_xphi: float = 0.0
    soil_frequency: float = 0.0

    @property
    def coupled(self) -> bool:
        """Whether the support couples u_x with θ_y (K_xφ or C_xφ not 0, for any design of a batch):
        the paper's closed forms, which take three uncoupled springs, do not apply."""
        return bool(np.any(np.asarray(self.K_xphi) != 0.0) or np.any(np.asarray(self.C_xphi) != 0.0))

    @property
    def M_tot(self) -> float:
        """Total mass M + m [kg] (m: rod and slider)."""
        return self.M + self.rod.m

    @property
    def mu(self) -> float:
        """Small parameter μ = m / M_tot [-]."""
        return self.rod.m / self.M_tot

    @property
    def lam(self) -> float:
        """λ = r / l [-]."""
        return self.r / self.l

    @property
    def rho1_sq(self) -> float:
        """ρ1² = I_c / M_tot [m²], the reduced radius of gyration squared."""
        return self.I_c / self.M_tot


@dataclass(frozen=True)
class LumpedRod:
    """A connecting rod with the slider's mass lumped into it (a point mass at M'').

    Attributes
    ----------
    m : rod + slider mass [kg]
    l1 : distance l' from the combined centre of mass C1 to the crank pin M' [m]
    l2 : distance l'' = l - l' from C1 to the slider pin M'' [m]
    rho : radius of gyration of the combined body about C1 [m]
    """

    m: object
    l1: object
    l2: object
    rho: object

    @property
    def kappa(self):
        """κ = l'l'' - ρ² [m²], the rod-couple coefficient of Eq. (2.6)."""
        return self.l1 * self.l2 - self.rho**2


def lump_slider(m, l, l1, rho, m1) -> LumpedRod:
    """Combine the rod (m, l', ρ) with a slider mass m1 at M'' into one rigid body.

    Source: [1]_, last paragraph (the slider mass is "added to the rod"). The slider is a point
    mass at M'', so the combination is exact: with m_c = m + m1,

        l'_c = (m l' + m1 l) / m_c
        ρ_c² = [m (ρ² + (l' - l'_c)²) + m1 (l - l'_c)²] / m_c

    Parameters
    ----------
    m : rod mass [kg]
    l : rod length M'M'' [m]
    l1 : l' = C1M', rod centre of mass to crank pin [m]
    rho : rod radius of gyration about C1 [m]
    m1 : slider mass [kg], >= 0

    >>> rod = lump_slider(m=2.0, l=1.0, l1=0.5, rho=0.3, m1=2.0)
    >>> round(rod.l1, 12), round(rod.rho**2, 12)
    (0.75, 0.1075)
    """
    mc = m + m1
    l1c = (m * l1 + m1 * l) / mc
    rho2 = (m * (rho**2 + (l1 - l1c) ** 2) + m1 * (l - l1c) ** 2) / mc
    return LumpedRod(m=mc, l1=l1c, l2=l - l1c, rho=rho2**0.5)


def rod_angle_cosine(phi, lam):
    """cos ψ and its first two derivatives with respect to φ, with sin ψ = λ sin φ (exact, checked
    with sympy), each shaped as ``phi`` [-, 1/rad, 1/rad²]: d(cos ψ)/dφ = -λ² sin φ cos φ / cos ψ,
    d²(cos ψ)/dφ² = -λ² (cos 2φ + λ² sin⁴ φ) / cos³ ψ.

    >>> [round(float(x), 12) for x in rod_angle_cosine(0.0, 0.25)]
    [1.0, -0.0, -0.0625]
    """
    s, co = np.sin(phi), np.cos(phi)
    c = np.sqrt(1.0 - lam * lam * s * s)
    return c, -lam * lam * s * co / c, -lam * lam * (np.cos(2.0 * phi) + lam * lam * s**4) / c**3


def mean_cos_psi(lam, iterations: int = 12):
    """⟨cos ψ⟩ over one revolution, with sin ψ = λ sin φ: (2/π) E(λ²).

    E is the complete elliptic integral of the second kind, computed by the arithmetic-geometric
    mean (quadratic convergence; 12 steps reach double precision for every λ < 1). Arithmetic only,
    so ``lam`` may be a float or a numpy array.

    >>> round(mean_cos_psi(0.0), 15)
    1.0
    >>> round(mean_cos_psi(0.25), 12)  # 1 - λ²/4 - 3λ⁴/64 - ...
    0.984186956472
    """
    a = 1.0 + 0.0 * lam
    b = (1.0 - lam * lam) ** 0.5
    c2 = lam * lam  # c_0²
    weighted = 0.5 * c2  # Σ 2^(n-1) c_n²
    scale = 1.0
    for _ in range(iterations):
        c2 = ((a - b) / 2.0) ** 2
        a, b = (a + b) / 2.0, (a * b) ** 0.5
        weighted = weighted + scale * c2
        scale *= 2.0
    return (1.0 - weighted) / a


def mean_position_v(a, l1, mean_cos):
    """⟨p_v⟩ [m]: time-averaged vertical body coordinate of C1 (positive downward).

    p_v = -a + (l''/l) r cos φ + (l'/l) s, hence ⟨p_v⟩ = -a + l' ⟨cos ψ⟩.
    """
    return -a + l1 * mean_cos


def mean_square_distance(a, r, l, l1, mean_cos):
    """⟨|p|²⟩ [m²]: time-averaged squared distance of C1 from C.

    With ⟨s²⟩ = l² and ⟨s cos φ⟩ = r/2 (exact):  ⟨|p|²⟩ = a² + l'² + l'' r²/l - 2 a l' ⟨cos ψ⟩.
    """
    return a * a + l1 * l1 + (l - l1) * r * r / l - 2.0 * a * l1 * mean_cos


__all__ = [
    "LumpedRod",
    "lump_slider",
    "mean_cos_psi",
    "mean_position_v",
    "mean_square_distance",
    "rod_angle_cosine",
]
