"""One number format for every table of a calculation sheet.

Each kind of quantity has its own count of significant figures (:data:`DIGITS`), numbers are
written in plain decimal notation between :data:`PLAIN_RANGE` and as ``a.bc·10^n`` outside it,
so a column never mixes ``0.000112958`` with ``2.54806e-05``; a value below its quantity's own
scale (``scale`` times :data:`ROUND_OFF`) is round-off and is printed as ``0``. Margins and
ratios print at one precision everywhere.

>>> figure(2.54806e-05, 4), figure(0.000112958, 4), figure(3.5e8, 4)
('2.548·10⁻⁵', '1.130·10⁻⁴', '3.500·10⁸')
>>> figure(5.34e-20, 3, scale=1e-3), figure(26.17994, 4), figure(-0.0, 3)
('0', '26.18', '0')
>>> percent(0.842376), percent(0.309), ratio(1.2994)
('84.2 %', '30.9 %', '1.30')
"""

from __future__ import annotations

import math

#: Significant figures per kind of quantity shown on a sheet.
DIGITS = {
    "speed": 4,        # rad/s, rpm, Hz: a resonance margin is read to 0.1 %
    "amplitude": 3,    # m, mm, µm: limits are given to 1-2 figures
    "velocity": 3,
    "acceleration": 3,
    "input": 6,        # the scene's own numbers, echoed as given
    "derived": 4,      # masses, stiffnesses, lengths computed from the inputs
}

#: Magnitudes written in plain decimal notation; outside, ``a.bc·10^n``.
PLAIN_RANGE = (1e-3, 1e6)

#: A value smaller than this fraction of its quantity's scale is round-off, printed as 0.
ROUND_OFF = 1e-9

_SUPERSCRIPT = str.maketrans("-0123456789", "⁻⁰¹²³⁴⁵⁶⁷⁸⁹")


def figure(value: float | None, digits: int, scale: float | None = None) -> str:
    """``value`` with ``digits`` significant figures (``-`` for None); 0 when it is below
    :data:`ROUND_OFF` of ``scale`` (or is zero)."""
    if value is None:
        return "-"
    if not math.isfinite(value):
        return str(value)
    if value == 0 or (scale is not None and abs(value) < ROUND_OFF * abs(scale)):
        return "0"
    exponent = math.floor(math.log10(abs(value)))
    mantissa = round(value / 10.0**exponent, digits - 1)
    if abs(mantissa) >= 10:  # 9.9996 rounds up to 10.000
        exponent, mantissa = exponent + 1, mantissa / 10
    if PLAIN_RANGE[0] <= abs(value) < PLAIN_RANGE[1]:
        decimals = max(0, digits - 1 - exponent)
        return f"{value:.{decimals}f}"
    return f"{mantissa:.{digits - 1}f}·10{str(exponent).translate(_SUPERSCRIPT)}"


def percent(fraction: float) -> str:
    """A margin or share given as a fraction, in percent to one decimal."""
    return f"{fraction * 100:.1f} %"


def ratio(value: float | None) -> str:
    """A demand/limit ratio to two decimals (``-`` when there is none, ``inf`` for no margin)."""
    if value is None:
        return "-"
    return "inf" if math.isinf(value) else f"{value:.2f}"


def quantity(units, kind: str, si_value: float | None, scale: float | None = None) -> str:
    """``si_value`` of the display quantity ``kind`` (``amplitude``, ``speed`` …) in the chosen
    ``units`` with its unit label, at that kind's figures."""
    if si_value is None:
        return "-"
    shown = units.convert(kind, si_value)
    shown_scale = None if scale is None else units.convert(kind, scale)
    return f"{figure(shown, DIGITS[kind], shown_scale)} {units.label(kind)}"
