"""Corrected first approximation of the forced vibration of a crank-mechanism foundation, damped.

Source: Krichever & Makarov [1]_, Eqs. (4.11)-(4.14), with the corrections of the project note
(docs/theory.md, "Corrections to the sources"):

- (1.6): the series of the rod's angular acceleration has the wrong sign; the rod couple enters
  with ``+κ ε_rod``, ε_rod = +λω²(1-λ²)[(1 + 9λ²/8) sin φ - (3/8)λ² sin 3φ] + O(λ⁵).
- (4.12) A': the crank term lacks 1/l (printed ``l'' a r ω²``) and the rod-couple term has the
  wrong sign; with the motor on the foundation the rod's weight adds ``g`` to ``a ω²``.
- (4.13) A''': wrong sign.
- (4.14): μ multiplies the solution of (4.11) once (printed: twice, through (4.11)'s right side
  being read with μ and the μ in front).

Corrected formulas (y positive downward; θ turns +x toward +y)::

    μ = m/M_tot,  λ = r/l,  l'' = l - l',  ρ1² = I_c/M_tot,  κ = l'l'' - ρ²
    A'   = [-(l''/l) r (a ω² + g*) + κ λ ω² (1 - λ²)(1 + 9λ²/8)] / ρ1²
    A''' = -κ λ ω² (1 - λ²)(3/8) λ² / ρ1²
    Δ(W) = (a0 - W²)(b1 - W²) - a1 b0 = (p1² - W²)(p2² - W²)
    b'   = [A' b0 - (l''/l) r ω² (b1 - ω²)] / Δ(ω),   c'   = [A'(a0 - ω²) - (l''/l) r ω² a1] / Δ(ω)
    b''' = A''' b0 / Δ(3ω),                          c''' = A'''(a0 - 9ω²) / Δ(3ω)
    y = μ [r ω²/(k0² - ω²) cos ωt + (l'/l) λ r ω²/(k0² - 4ω²) cos 2ωt]
    x = μ [b' sin ωt + b''' sin 3ωt],   θ = μ [c' sin ωt + c''' sin 3ωt]

``g* = g`` when the motor's reaction torque acts on the foundation, ``0`` for the paper's (3.7).
Δ is evaluated in its factored form with p1², p2² of (4.7), which keeps its relative accuracy
near a resonance. The paper's rocking spring c I1 is c_φ I1 here (b1 of (4.5)).

Extension (not in the paper): base dashpots. The soil's dashpots C_z, C_x (on x' - hθ') and C_φ
(on θ') of :mod:`~foundation_calc.solvers.crank.dynamics` add to the reduced equations (4.11)::

    y1'' + ζ_z y1' + k0² y1 = ...                                        ζ_z = C_z/M_tot
    x1'' + γ_x (x1' - h θ1') + a0 x1 - b0 θ1 = ...                       γ_x = C_x/M_tot
    θ1'' - γ_θ h (x1' - h θ1') + γ_φ θ1' - a1 x1 + b1 θ1 = ...         γ_θ = C_x/I_c, γ_φ = C_φ/I_c

so that harmonic n (W = nω) of a forcing F cos Wt (y) or F_x, F_θ sin Wt (x, θ) has the complex
amplitude Y = F/(k0² - W² + i W ζ_z) and

    X = (D F_x + B F_θ)/Δ,   Θ = (C F_x + A F_θ)/Δ,   Δ = A D - B C,
    A = a0 - W² + i W γ_x,   B = b0 + i W h γ_x,   C = a1 + i W h γ_θ,   D = b1 - W² + i W (h² γ_θ + γ_φ),
    Δ = (p1² - W²)(p2² - W²) - W² γ_x γ_φ + i W [a0 γ_φ + k_φ γ_x - W² (γ_x + h² γ_θ + γ_φ)],
    k_φ = (c_φ I1 - P h)/I_c.

The real part of Δ keeps the factored form and the quotients are taken in real arithmetic
(:func:`complex_quotient`), so an undamped design gives the undamped numbers to the last digit.
The amplitudes are complex in the paper's convention: the real part multiplies the paper's term
(cos nωt for y, sin nωt for x, θ), the imaginary part the term in quadrature: y = Re(Y e^{inωt}),
x = Im(X e^{inωt}), θ = Im(Θ e^{inωt}). C = 0 gives (4.14): real amplitudes.

Every function uses arithmetic only, so arrays of designs or speeds go through the same call.

References
----------
.. [1] M.F. Krichever, S.M. Makarov, "Application of the small-parameter method to the problem
   of forced vibrations of the foundation of a crank-slider mechanism".
"""

from __future__ import annotations

from dataclasses import dataclass

import numpy as np

from foundation_calc.solvers.crank.frequencies import zero_order_frequencies
from foundation_calc.solvers.crank.resonance import CONDITIONS, relative_detuning
from foundation_calc.solvers.crank.response import PeriodicMotion

#: Relative distance |nω - p|/p below which a speed counts as resonant for an undamped mode: the
#: undamped periodic solution does not exist there (or is larger than anything the linear soil
#: model can carry). A damped mode is never resonant in this sense: its amplitude is finite.
RESONANT_MARGIN = 1e-6

#: Damping ratio [-] below which a mode counts as undamped (and so can be resonant): any ratio
#: above it gives a finite amplitude, at most about 1/(2 ratio) times the static one, far from
#: overflow; below it the amplitude would be the round-off of a singular denominator.
UNDAMPED_RATIO = 1e-12

#: The resonance conditions whose denominators appear in the first approximation.
FIRST_APPROXIMATION_CONDITIONS = tuple(c for c in CONDITIONS if c.source == "paper")


@dataclass(frozen=True)
class FirstApproximation:
    """Complex coefficients of the corrected first approximation (already multiplied by μ).

    y(t) = Re(y1 e^{iωt} + y2 e^{2iωt}) [m],  x(t) = Im(x1 e^{iωt} + x3 e^{3iωt}) [m],
    θ(t) = Im(theta1 e^{iωt} + theta3 e^{3iωt}) [rad]: the real part multiplies the paper's
    cos nωt (y) or sin nωt (x, θ), the imaginary part the term in quadrature (0 undamped).

    ``margins`` maps each condition label of the paper ("ω = k0", "3ω = p2", ...) to the
    relative detuning |nω - p|/p [-]; ``resonant`` is true where the margin of a condition of an
    undamped mode is below :data:`RESONANT_MARGIN`. There the coefficients are not defined and
    are set to 0.
    """

    y1: object
    y2: object
    x1: object
    x3: object
    theta1: object
    theta3: object
    margins: dict
    resonant: object

    def motion(self, omega) -> PeriodicMotion:
        """The coefficients as series x, y, θ with harmonics 0 ... 3 (shape (..., 3, 4))."""
        shape = np.broadcast(self.y1, self.x1, self.theta1, omega).shape
        cos, sin = np.zeros(shape + (3, 4)), np.zeros(shape + (3, 4))
        cos[..., 1, 1], cos[..., 1, 2] = np.real(self.y1), np.real(self.y2)
        sin[..., 1, 1], sin[..., 1, 2] = 0.0 - np.imag(self.y1), 0.0 - np.imag(self.y2)  # no -0.0
        for row, first, third in ((0, self.x1, self.x3), (2, self.theta1, self.theta3)):
            sin[..., row, 1], sin[..., row, 3] = np.real(first), np.real(third)
            cos[..., row, 1], cos[..., row, 3] = np.imag(first) + 0.0, np.imag(third) + 0.0
        return PeriodicMotion(omega=omega, cos=cos, sin=sin)


def _guarded(denominator, resonant):
    """The denominator, with 1 put where the design is resonant (the result is zeroed there)."""
    return np.where(resonant, 1.0, denominator)


def complex_quotient(nr, ni, dr, di):
    """(nr + i ni)/(dr + i di) in real arithmetic (Smith's algorithm), as real + i imaginary.

    With ``di = 0`` the real part is ``nr/dr`` to the last bit (numpy's complex division rounds
    differently), so an undamped design keeps its undamped numbers exactly; the branch is chosen
    per element, so arrays of designs go through one call. ``dr = di = 0`` is the caller's to
    avoid (:func:`_guarded`).

    >>> complex(complex_quotient(1.0, 0.0, 0.0, 2.0))
    -0.5j
    """
    small = np.abs(di) <= np.abs(dr)
    big_r = np.where(small, dr, 1.0)  # the branch not taken divides by 1, never by 0
    big_i = np.where(small, 1.0, di)
    t = di / big_r
    s = dr / big_i
    den_r = big_r * (1.0 + t * t)
    den_i = big_i * (1.0 + s * s)
    real = np.where(small, (nr + ni * t) / den_r, (nr * s + ni) / den_i)
    imag = np.where(small, (ni - nr * t) / den_r, (ni * s - nr) / den_i)
    return real + 1j * imag


def first_approximation(
    M_tot, I_c, h, S, I1, c, c1, c_phi, C_x, C_z, C_phi, g, g_star, omega, m, r, l, l1, rho, a
) -> FirstApproximation:
    """Steady state of [1]_, Eqs. (4.11)-(4.14), corrected, with base dashpots (module docstring).

    Parameters
    ----------
    M_tot : total mass M + m (block, rod and slider) [kg]
    I_c : moment of inertia of the block about its centre of mass C [kg m²]
    h : height of C above the base [m]
    S : base area [m²]
    I1 : second moment of the base area about its centroidal axis [m⁴]
    c : coefficient of elastic uniform compression [N/m³]
    c1 : coefficient of elastic uniform shear [N/m³]
    c_phi : coefficient of elastic non-uniform compression, rocking spring c_φ I1 [N/m³]
    C_x : horizontal base dashpot, acting on x' - hθ' [N s/m]
    C_z : vertical base dashpot [N s/m]
    C_phi : rocking base dashpot, acting on θ' [N m s/rad]
    g : acceleration of gravity, in the weight term P h of the rocking stiffness [m/s²]
    g_star : g when the motor's reaction torque acts on the foundation, 0 for (3.7) as printed [m/s²]
    omega : crank speed [rad/s]
    m : rod mass, slider lumped in [kg]
    r : crank radius [m]
    l : rod length [m]
    l1 : l' = C1M', rod centre of mass to crank pin (slider lumped in) [m]
    rho : radius of gyration of the rod about C1 (slider lumped in) [m]
    a : distance from the crank axis A to C, positive when A is above C [m]

    Raises
    ------
    PhysicsError
        when the foundation is unstable in rocking (from :func:`zero_order_frequencies`).

    Notes
    -----
    Valid for small μ (the error of x and θ is O(μ) relative) and small λ (the 2ω vertical
    term and the rod couple are truncated at O(λ²) relative). At a resonance of the list
    (ω = k0, 2ω = k0, ω = p1, p2, 3ω = p1, p2) an undamped mode has no periodic solution:
    ``resonant``. The vertical mode is damped when C_z > 0; both sliding-rocking modes are
    damped when C_x > 0 or C_φ > 0 (no mode shape leaves both x - hθ and θ at rest); a damping
    ratio below :data:`UNDAMPED_RATIO` counts as none.

    >>> fa = first_approximation(1.015e5, 4.5e5, 1.5, 30.0, 90.0, 4.0e7, 2.8e7, 4.0e7, 0.0, 0.0, 0.0,
    ...                          9.81, 9.81, 31.41592653589793, 1.5e3, 0.3, 1.2, 1.0, 0.35, 2.0)
    >>> f"{fa.y1.real:.6e} {fa.x1.real:.6e} {fa.theta1.real:.6e}"
    '4.038213e-04 -2.446398e-04 -8.489545e-05'
    >>> bool(fa.resonant), float(fa.x1.imag)
    (False, 0.0)
    """
    freqs = zero_order_frequencies(M_tot, I_c, h, S, I1, c, c1, c_phi, g)
    mu = m / M_tot
    lam = r / l
    l2 = l - l1
    rho1_sq = I_c / M_tot
    kappa = l1 * l2 - rho * rho
    a0 = c1 * S / M_tot
    b0 = c1 * h * S / M_tot
    a1 = c1 * h * S / I_c
    b1 = (c1 * h * h * S + c_phi * I1 - M_tot * g * h) / I_c
    k_phi = (c_phi * I1 - M_tot * g * h) / I_c
    zeta_z, gamma_x, gamma_t, gamma_phi = C_z / M_tot, C_x / M_tot, C_x / I_c, C_phi / I_c
    w2 = omega * omega

    margins = {
        cond.label: relative_detuning(cond.harmonic * omega, getattr(freqs, cond.mode))
        for cond in FIRST_APPROXIMATION_CONDITIONS
    }
    I_0 = I_c + M_tot * h * h  # ratios of the uncoupled modes, as the soil note defines them
    undamped = {
        "k0": C_z <= 2.0 * UNDAMPED_RATIO * np.sqrt(c * S * M_tot),
        "p": (C_x <= 2.0 * UNDAMPED_RATIO * np.sqrt(c1 * S * M_tot))
        & (C_phi <= 2.0 * UNDAMPED_RATIO * np.sqrt(np.abs(k_phi) * I_c * I_0)),
    }
    resonant = np.logical_or.reduce([
        (np.asarray(margins[cond.label]) < RESONANT_MARGIN) & undamped["k0" if cond.mode == "k0" else "p"]
        for cond in FIRST_APPROXIMATION_CONDITIONS
    ])
    k0_sq, p1_sq, p2_sq = freqs.k0**2, freqs.p1**2, freqs.p2**2

    def vertical(force, n):
        """Y of the harmonic n for the forcing ``force`` cos nωt."""
        return complex_quotient(force, 0.0, _guarded(k0_sq - n * n * w2, resonant), n * omega * zeta_z)

    def sliding_rocking(force_x, force_t, scale, n):
        """(X, Θ) of the harmonic n for ``scale`` (F_x, F_θ) sin nωt (module docstring)."""
        W, W_sq = n * omega, n * n * w2
        D_r, D_i = b1 - W_sq, W * (h * h * gamma_t + gamma_phi)
        det_r = _guarded((p1_sq - W_sq) * (p2_sq - W_sq) - W_sq * gamma_x * gamma_phi, resonant)
        det_i = W * (a0 * gamma_phi + k_phi * gamma_x - W_sq * (gamma_x + h * h * gamma_t + gamma_phi))
        X = complex_quotient(
            scale * (force_t * b0 + force_x * D_r), scale * (force_t * W * h * gamma_x + force_x * D_i), det_r, det_i
        )
        T = complex_quotient(
            scale * (force_t * (a0 - W_sq) + force_x * a1),
            scale * (force_t * W * gamma_x + force_x * W * h * gamma_t),
            det_r,
            det_i,
        )
        return X, T

    crank = (l2 / l) * r * w2
    couple = kappa * lam * w2 * (1.0 - lam * lam)
    A1 = (-(l2 / l) * r * (a * w2 + g_star) + couple * (1.0 + 9.0 * lam * lam / 8.0)) / rho1_sq
    A3 = -couple * (3.0 / 8.0) * lam * lam / rho1_sq
    keep = np.where(resonant, 0.0, mu)
    x1, theta1 = sliding_rocking(-crank, A1, keep, 1)
    x3, theta3 = sliding_rocking(0.0, keep * A3, 1.0, 3)
    return FirstApproximation(
        y1=vertical(keep * r * w2, 1),
        y2=vertical(keep * (l1 / l) * lam * r * w2, 2),
        x1=x1,
        x3=x3,
        theta1=theta1,
        theta3=theta3,
        margins=margins,
        resonant=resonant,
    )


__all__ = ["RESONANT_MARGIN", "UNDAMPED_RATIO", "FirstApproximation", "complex_quotient", "first_approximation"]
