"""Peak of one mode swept linearly through its resonance: closed form and Lewis' asymptote.

Single mode, time in units of 1/ω_n, sweep rate η = Ω̇/ω_n² [-]::

    x'' + 2ζ x' + x = f(ν) cos φ,   φ' = ν = 1 + η τ   (τ = 0 at the resonance)

Slowly varying amplitude (x = Re(a e^{iφ}), a'' and the non-resonant term dropped, ν² - 1 ≈ 2ητ)
gives the envelope equation a' + (ζ + iητ) a = -i f(τ)/2, whose solution from rest at τ → -∞ is
the Faddeeva function w (derived here, the method of Lewis [1]_ with damping kept). For a
constant force f::

    |a(τ)| / f = |J0|/2,   J0 = sqrt(π)/(2k) w(-ik(τ - iζ/η)),   k = sqrt(η/2) e^{-iπ/4}

For the force of an unbalance, f = A (ν² - iν') + B (A ∝ m l ω_n², B the rotating weight),
a polynomial in τ; integrating by parts with E' = (iηs + ζ) E, E = exp(iηs²/2 + ζs)::

    2|a(τ)| = |(A (1 - iη) + B) J0 - 2i A (1 - ζ J0) - i A η (τ - J0) + A ζ (1 - ζ J0)|

(no division by η: exact to round-off for slow sweeps). Run-down: the conjugate equation.

Its limits: ζ = 0 gives Lewis' peak 1.467/sqrt(η) (:data:`LEWIS_COEFFICIENT`), η → 0 the
steady resonant amplitude 1/(2ζ). Markert & Seidler [2]_ fit an approximation to the same
problem; it is not used. Against time integration from 0.3 ω_n in the steady state (the
reference values of the project's soil-damping note, reproduced by ``tests/test_runup_passage``)
the closed form is high by ≤ 0.6 % at η = 1e-3, ≤ 2.2 % at η = 1e-2 and ≤ 8 % at η = 1e-1
(ζ = 0 ... 0.1): valid, and on the safe side, for η ≤ 1e-2.

References
----------
.. [1] F.M. Lewis, "Vibration during acceleration through a critical speed", Trans. ASME 54
   (1932) 253-261.
.. [2] R. Markert, M. Seidler, "Analytically based estimation of the maximum amplitude during
   passage through resonance", Int. J. Solids Struct. 38 (2001) 1975-1992.
"""

from __future__ import annotations

from dataclasses import dataclass

import numpy as np
from scipy.special import wofz

#: Grid of s = τ sqrt(η) on which the envelope's maximum is searched, then refined by a parabola
#: through the best three points: the envelope rises from s = -3 (well before the resonance) and
#: peaks before s = 8 for every ζ ≥ 0 (the undamped peak is at s = 2.1).
_S_GRID = np.linspace(-3.0, 8.0, 1101)


def _envelope(zeta, eta, s, a, b, direction):
    """|a(τ)| at s = τ sqrt(η) for the force (a (ν² - iν') + b), ν = 1 + direction η τ
    (broadcast; module docstring) [unit of a, b]."""
    tau = s / np.sqrt(eta)
    k = np.sqrt(0.5 * eta) * np.exp(-0.25j * np.pi)
    J0 = np.sqrt(np.pi) / (2.0 * k) * wofz(-1j * k * (tau - 1j * zeta / eta))
    if direction < 0:  # the conjugate equation runs the sweep the other way
        a, b = np.conj(a), np.conj(b)
    lag = 1.0 - zeta * J0
    S = (a * (1.0 - 1j * eta) + b) * J0 - 2j * direction * a * lag - 1j * a * eta * (tau - J0) + a * zeta * lag
    return 0.5 * np.abs(S)


@dataclass(frozen=True)
class PassagePeak:
    """Peak of the envelope during a passage (arrays broadcast over the inputs).

    Attributes
    ----------
    ratio : peak amplitude / static deflection of the force at the peak, f(ν)/k [-]
    tau : time of the peak after the resonance, in units of 1/ω_n [-] (positive: after)
    nu : speed at the peak / ω_n [-]
    """

    ratio: np.ndarray
    tau: np.ndarray
    nu: np.ndarray


def passage_peak(zeta, eta, inertial, constant, direction) -> PassagePeak:
    """Peak amplitude of a mode swept through its resonance, closed form (module docstring).

    Parameters
    ----------
    zeta : modal damping ratio ζ [-], ≥ 0
    eta : sweep rate |Ω̇|/ω_n² [-], > 0
    inertial, constant : the force amplitude is f(ν) = |inertial ν² + constant| (complex,
        any common unit): (0, 1) a constant force, (1, 0) an unbalance; the peak of
        f(ν(τ)) |a(τ)|/f is taken
    direction : +1 run-up (speed rising), -1 run-down [-]

    Returns
    -------
    PassagePeak
        ``ratio`` = max over τ of f(ν) |a|/f over f(1), i.e. the peak amplitude over the static
        deflection f(1)/k of the force at the resonant speed.

    >>> p = passage_peak(0.0, 1e-3, 0.0, 1.0, 1)
    >>> f"{float(p.ratio):.1f}"
    '46.4'
    """
    zeta = np.asarray(zeta, dtype=float)[..., None]
    eta = np.asarray(eta, dtype=float)[..., None]
    a = np.asarray(inertial, dtype=complex)[..., None]
    b = np.asarray(constant, dtype=complex)[..., None]
    scale = np.abs(a + b)
    s = _S_GRID
    values = _envelope(zeta, eta, s, a / scale, b / scale, direction)
    i = np.clip(np.argmax(values, axis=-1), 1, s.size - 2)
    y0, y1, y2 = (np.take_along_axis(values, (i + k)[..., None], axis=-1)[..., 0] for k in (-1, 0, 1))
    curvature = y0 - 2.0 * y1 + y2
    shift = np.where(curvature < 0.0, 0.5 * (y0 - y2) / np.where(curvature < 0.0, curvature, -1.0), 0.0)
    best = s[i] + shift * (s[1] - s[0])
    eta0 = eta[..., 0]
    peak_nu = 1.0 + direction * best * np.sqrt(eta0)
    ratio = _envelope(zeta[..., 0], eta0, best, (a / scale)[..., 0], (b / scale)[..., 0], direction)
    return PassagePeak(ratio=ratio, tau=best / np.sqrt(eta0), nu=peak_nu)


def _lewis_coefficient() -> float:
    """max over s of sqrt(π/8) |w(-i sqrt(1/2) e^{-iπ/4} s)|: the undamped peak × sqrt(η)."""
    return float(passage_peak(0.0, 1.0, 0.0, 1.0, 1).ratio)


#: Lewis' undamped peak amplitude × sqrt(η) over the static deflection [-] (1.467 in print).
LEWIS_COEFFICIENT = _lewis_coefficient()


def lewis_peak(eta):
    """Undamped peak amplitude over the static deflection, F/k, of a linear sweep [-].

    Source: Lewis (1932) [1]_, A_max/(F/k) ≈ 1.467/sqrt(η), η = Ω̇/ω_n² [-] (asymptotic for
    small η, constant force, sweep starting far below the resonance).

    >>> f"{lewis_peak(1e-2):.2f}"
    '14.67'
    """
    return LEWIS_COEFFICIENT / np.sqrt(eta)


__all__ = ["LEWIS_COEFFICIENT", "PassagePeak", "lewis_peak", "passage_peak"]
