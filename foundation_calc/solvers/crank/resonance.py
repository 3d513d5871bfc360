"""Resonance conditions of the crank-mechanism foundation.

Source: Krichever & Makarov [1]_, section 4: the first approximation resonates when a harmonic of
the crank speed meets a natural frequency: ω = k0, 2ω = k0 (vertical, harmonics of the slider
motion), ω = p1, p2 and 3ω = p1, p2 (sliding-rocking, crank force and rod couple).

The exact equations also resonate at 4ω = k0 (the λ³ part of the slider motion) and, at order
μ², at 2ω = p1, p2; those are listed as ``source="extra"``.

Beyond the paper's list, every harmonic n ω of a machine's forcing meets k0, p1, p2
(:mod:`~foundation_calc.solvers.crank.machine_conditions`).

References
----------
.. [1] M.F. Krichever, S.M. Makarov, "Application of the small-parameter method to the problem
   of forced vibrations of the foundation of a crank-slider mechanism".
"""

from __future__ import annotations

from dataclasses import dataclass


@dataclass(frozen=True)
class ResonanceCondition:
    """One condition n·ω = natural frequency.

    Attributes
    ----------
    label : as written in the paper, e.g. ``"3ω = p1"``
    harmonic : n, the harmonic of the crank speed that excites the mode
    mode : ``"k0"``, ``"p1"`` or ``"p2"``
    source : ``"paper"`` (the paper's list), ``"extra"`` (resonances of the exact equations) or
        ``"loads"`` (a harmonic of the scene's [[loads]])
    excitation : what drives this harmonic
    driven : whether a load of this harmonic drives the mode (``"loads"`` only; the paper's
        conditions are driven by the mechanism, the extra ones only weakly)
    """

    label: str
    harmonic: int
    mode: str
    source: str
    excitation: str
    driven: bool = False


MODE_NAMES = {
    "k0": "vertical",
    "p1": "rocking, lower",
    "p2": "rocking, upper",
}

CONDITIONS: tuple[ResonanceCondition, ...] = (
    ResonanceCondition("ω = k0", 1, "k0", "paper", "crank-pin inertia force, vertical"),
    ResonanceCondition("2ω = k0", 2, "k0", "paper", "slider inertia, λ term"),
    ResonanceCondition("ω = p1", 1, "p1", "paper", "crank-pin force and rod couple"),
    ResonanceCondition("ω = p2", 1, "p2", "paper", "crank-pin force and rod couple"),
    ResonanceCondition("3ω = p1", 3, "p1", "paper", "rod couple, λ³ term"),
    ResonanceCondition("3ω = p2", 3, "p2", "paper", "rod couple, λ³ term"),
    ResonanceCondition("4ω = k0", 4, "k0", "extra", "slider inertia, λ³ term (exact equations)"),
    ResonanceCondition("2ω = p1", 2, "p1", "extra", "parametric terms, order μ² (exact equations)"),
    ResonanceCondition("2ω = p2", 2, "p2", "extra", "parametric terms, order μ² (exact equations)"),
)


def critical_speed(natural_frequency, harmonic):
    """Crank speed [rad/s] at which harmonic n meets the natural frequency: ω_c = p / n."""
    return natural_frequency / harmonic


def relative_detuning(omega, omega_critical):
    """Relative distance of the operating speed from a critical speed, |ω - ω_c| / ω_c [-].

    >>> relative_detuning(80.0, 100.0)
    0.2
    """
    return abs(omega - omega_critical) / omega_critical


def condition_margin(omega, zero_order, averaged, condition: ResonanceCondition):
    """Margin [-] of ω from one condition, measured to the nearer of its two critical speeds.

    ``zero_order`` and ``averaged`` hold k0, p1, p2 [rad/s] of the paper's operator and of the
    operator with the mechanism's averaged inertia. Arithmetic only: arrays of designs or speeds
    give an array of margins.

    >>> from types import SimpleNamespace as F
    >>> condition_margin(95.0, F(k0=100.0), F(k0=100.0), CONDITIONS[0])
    0.05
    """
    w0 = critical_speed(getattr(zero_order, condition.mode), condition.harmonic)
    w1 = critical_speed(getattr(averaged, condition.mode), condition.harmonic)
    d0, d1 = relative_detuning(omega, w0), relative_detuning(omega, w1)
    return (d0 + d1 - abs(d0 - d1)) / 2.0

