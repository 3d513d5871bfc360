"""Corrected first approximation of the forced vibration of a crank-mechanism foundation.

Source: Krichever & Makarov [1]_, Eqs. (4.11)-(4.14), with the corrections of the project note
(README, "Corrections to the paper"):

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
near a resonance.

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

#: Relative distance |nω - p|/p below which a speed counts as resonant: the undamped periodic
#: solution does not exist there (or is larger than anything the linear soil model can carry).
RESONANT_MARGIN = 1e-6

#: The resonance conditions whose denominators appear in the first approximation.
FIRST_APPROXIMATION_CONDITIONS = tuple(c for c in CONDITIONS if c.source == "paper")


@dataclass(frozen=True)
class FirstApproximation:
    """Signed coefficients of the corrected first approximation (already multiplied by μ).

    y(t) = y1 cos ωt + y2 cos 2ωt [m],  x(t) = x1 sin ωt + x3 sin 3ωt [m],
    θ(t) = theta1 sin ωt + theta3 sin 3ωt [rad].

    ``margins`` maps each condition label of the paper ("ω = k0", "3ω = p2", ...) to the
    relative detuning |nω - p|/p [-]; ``resonant`` is true where the smallest margin is below
    :data:`RESONANT_MARGIN`. There the coefficients are not defined and are set to 0.
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
        cos[..., 1, 1], cos[..., 1, 2] = self.y1, self.y2
        sin[..., 0, 1], sin[..., 0, 3] = self.x1, self.x3
        sin[..., 2, 1], sin[..., 2, 3] = self.theta1, self.theta3
        return PeriodicMotion(omega=omega, cos=cos, sin=sin)


def _guarded(denominator, resonant):
    """The denominator, with 1 put where the design is resonant (the result is zeroed there)."""
    return np.where(resonant, 1.0, denominator)


def first_approximation(M_tot, I_c, h, S, I1, c, c1, g, g_star, omega, m, r, l, l1, rho, a) -> FirstApproximation:
    """Steady-state forced vibration of [1]_, Eqs. (4.11)-(4.14), corrected (module docstring).

    Parameters
    ----------
    M_tot : total mass M + m (block, rod and slider) [kg]
    I_c : moment of inertia of the block about its centre of mass C [kg m²]
    h : height of C above the base [m]
    S : base area [m²]
    I1 : second moment of the base area about its centroidal axis [m⁴]
    c : coefficient of elastic uniform compression [N/m³]
    c1 : coefficient of elastic uniform shear [N/m³]
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
    (ω = k0, 2ω = k0, ω = p1, p2, 3ω = p1, p2) there is no periodic solution: ``resonant``.

    >>> fa = first_approximation(1.015e5, 4.5e5, 1.5, 30.0, 90.0, 4.0e7, 2.8e7, 9.81, 9.81,
    ...                          31.41592653589793, 1.5e3, 0.3, 1.2, 1.0, 0.35, 2.0)
    >>> f"{fa.y1:.6e} {fa.x1:.6e} {fa.theta1:.6e}"
    '4.038213e-04 -2.446398e-04 -8.489545e-05'
    >>> bool(fa.resonant)
    False
    """
    freqs = zero_order_frequencies(M_tot, I_c, h, S, I1, c, c1, g)
    mu = m / M_tot
    lam = r / l
    l2 = l - l1
    rho1_sq = I_c / M_tot
    kappa = l1 * l2 - rho * rho
    a0 = c1 * S / M_tot
    b0 = c1 * h * S / M_tot
    a1 = c1 * h * S / I_c
    b1 = (c1 * h * h * S + c * I1 - M_tot * g * h) / I_c
    w2 = omega * omega

    margins = {
        cond.label: relative_detuning(cond.harmonic * omega, getattr(freqs, cond.mode))
        for cond in FIRST_APPROXIMATION_CONDITIONS
    }
    resonant = np.minimum.reduce([np.asarray(v) for v in margins.values()]) < RESONANT_MARGIN
    k0_sq, p1_sq, p2_sq = freqs.k0**2, freqs.p1**2, freqs.p2**2

    def delta(W_sq):
        return _guarded((p1_sq - W_sq) * (p2_sq - W_sq), resonant)

    crank = (l2 / l) * r * w2
    couple = kappa * lam * w2 * (1.0 - lam * lam)
    A1 = (-(l2 / l) * r * (a * w2 + g_star) + couple * (1.0 + 9.0 * lam * lam / 8.0)) / rho1_sq
    A3 = -couple * (3.0 / 8.0) * lam * lam / rho1_sq
    d1, d3 = delta(w2), delta(9.0 * w2)
    keep = np.where(resonant, 0.0, mu)
    return FirstApproximation(
        y1=keep * r * w2 / _guarded(k0_sq - w2, resonant),
        y2=keep * (l1 / l) * lam * r * w2 / _guarded(k0_sq - 4.0 * w2, resonant),
        x1=keep * (A1 * b0 - crank * (b1 - w2)) / d1,
        x3=keep * A3 * b0 / d3,
        theta1=keep * (A1 * (a0 - w2) - crank * a1) / d1,
        theta3=keep * A3 * (a0 - 9.0 * w2) / d3,
        margins=margins,
        resonant=resonant,
    )


__all__ = ["RESONANT_MARGIN", "FirstApproximation", "first_approximation"]
