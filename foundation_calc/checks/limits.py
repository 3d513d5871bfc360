"""The limit check shared by every command: which quantities a scene limits, and when a peak
exceeds its limit. ``fcalc amplitudes``, ``fcalc check`` and ``fcalc sweep`` all call these, so
a scene that fails on velocity in one command fails on it in every other."""

from __future__ import annotations

#: Quantities a limit may bound, with the scene's ``[limits]`` key of each (peak values) [m, m/s, m/s²].
QUANTITIES = {"displacement": "amplitude", "velocity": "velocity", "acceleration": "acceleration"}


def limited_quantities(limits) -> dict[str, float]:
    """``quantity -> limit`` for every quantity the scene's ``[limits]`` bounds (SI units).

    >>> from types import SimpleNamespace
    >>> limited_quantities(SimpleNamespace(amplitude=2e-4, velocity=None, acceleration=0.3))
    {'displacement': 0.0002, 'acceleration': 0.3}
    """
    found = {quantity: getattr(limits, key, None) for quantity, key in QUANTITIES.items()}
    return {quantity: limit for quantity, limit in found.items() if limit is not None}


def exceeds(peak, limit):
    """Whether a peak exceeds its limit (arrays of peaks welcome): equal to the limit passes."""
    return peak > limit
