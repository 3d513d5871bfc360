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
from dataclasses import dataclass

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
    if PLAIN_RANGE[0] <= abs(value) < PLAIN_RANGE[1]:
        decimals = max(0, digits - 1 - math.floor(math.log10(abs(value))))
        return f"{value:.{decimals}f}"
    return _scientific(value, digits)


def column(values, digits: int, scale: float | None = None) -> list[str]:
    """A table column of ``values`` in one notation: plain when every non-zero value (above
    round-off of ``scale``) lies in :data:`PLAIN_RANGE`, otherwise ``a.bc·10^n`` for all.

    >>> column([0.000112958, 2.54806e-05, 0.0], 3)
    ['1.13·10⁻⁴', '2.55·10⁻⁵', '0']
    >>> column([0.113, 0.0255, 5e-20], 3, scale=0.1)
    ['0.113', '0.0255', '0']
    """
    return _one_notation(values, [digits] * len(values), [scale] * len(values))


def one_notation(values, digits: int, scales) -> list[str]:
    """:func:`column` with a round-off scale per value (a table column of several matrices, each
    with its own scale).

    >>> one_notation([165840.0, 8.4e9, 1e-3], 4, [1e6, 1e11, 1e11])
    ['1.658·10⁵', '8.400·10⁹', '0']
    """
    return _one_notation(values, [digits] * len(values), scales)


def _one_notation(values, digits, scales) -> list[str]:
    """Each value at its own figures and round-off scale, all plain or all ``a.bc·10^n``."""
    shown = [figure(v, d, s) for v, d, s in zip(values, digits, scales)]
    kept = [v for v, text in zip(values, shown) if v is not None and text != "0"]
    if all(PLAIN_RANGE[0] <= abs(v) < PLAIN_RANGE[1] for v in kept):
        return shown
    return ["0" if text == "0" else "-" if v is None else _scientific(v, d) for v, d, text in zip(values, digits, shown)]


@dataclass(frozen=True)
class Measure:
    """A table cell holding one number: ``prefix``, the value at ``digits`` figures, `` unit``,
    ``suffix``. Its notation is chosen with the other cells of its column that show the same
    quantity (same unit and suffix): see :func:`cells`."""

    value: float | None
    digits: int
    unit: str = ""
    scale: float | None = None
    prefix: str = ""
    suffix: str = ""


def cells(column_cells) -> list[str]:
    """The texts of one table column whose cells are strings or :class:`Measure` s: the measures
    of one quantity (unit and suffix) all in plain or all in ``a.bc·10^n`` notation, so a column
    never shows ``0.00135 mm`` above ``6.70·10⁻⁴ mm``.

    >>> cells([Measure(0.00135, 3, "mm"), Measure(6.7e-4, 3, "mm"), "margin 68.0 %", Measure(8.21, 3)])
    ['1.35·10⁻³ mm', '6.70·10⁻⁴ mm', 'margin 68.0 %', '8.21']
    """
    texts = [c if isinstance(c, str) else None for c in column_cells]
    groups: dict[tuple[str, str], list[int]] = {}
    for i, c in enumerate(column_cells):
        if isinstance(c, Measure):
            groups.setdefault((c.unit, c.suffix), []).append(i)
    for at in groups.values():
        ms = [column_cells[i] for i in at]
        numbers = _one_notation([m.value for m in ms], [m.digits for m in ms], [m.scale for m in ms])
        for i, m, number in zip(at, ms, numbers):
            texts[i] = f"{m.prefix}{number}{' ' + m.unit if m.unit and m.value is not None else ''}{m.suffix}"
    return texts


def _scientific(value: float, digits: int) -> str:
    exponent = math.floor(math.log10(abs(value)))
    mantissa = round(value / 10.0**exponent, digits - 1)
    if abs(mantissa) >= 10:
        exponent, mantissa = exponent + 1, mantissa / 10
    return f"{mantissa:.{digits - 1}f}·10{str(exponent).translate(_SUPERSCRIPT)}"


def echoed(value: float) -> str:
    """An input as given, up to 6 figures without trailing zeros, ``a·10ⁿ`` outside the plain range.

    >>> echoed(7e7), echoed(1.4931e10), echoed(0.35), echoed(100000.0)
    ('7·10⁷', '1.4931·10¹⁰', '0.35', '100000')
    """
    text = f"{value:.6g}"
    if "e" not in text:
        return text
    mantissa, exponent = text.split("e")
    return f"{mantissa}·10{str(int(exponent)).translate(_SUPERSCRIPT)}"


def percent(fraction: float) -> str:
    """A margin or share given as a fraction, in percent to one decimal."""
    return f"{fraction * 100:.1f} %"


def share(fraction: float) -> str:
    """A forcing share (a fraction of the largest, 1) in percent to two figures, plain: below
    0.01 % it only matters that it is under the rule's 1 %.

    >>> share(1.0), share(0.31), share(1.6e-3), share(7.9e-7), share(0.0)
    ('100 %', '31 %', '0.16 %', '< 0.01 %', '0 %')
    """
    if fraction == 0:
        return "0 %"
    if fraction < 1e-4:
        return "< 0.01 %"
    return f"{figure(fraction * 100, 2)} %"


def phased(magnitude: str, z: complex) -> str:
    """A complex amplitude ``z`` as its printed ``magnitude`` and phase lag φ [°] to 0.1°:
    Re(z e^{iΩt}) = |z| cos(Ωt − φ); the magnitude alone where it prints as 0 (no phase).

    >>> phased("2.000", 2j), phased("0", 1e-30)
    ('2.000 ∠-90.0°', '0')
    """
    if magnitude == "0":
        return magnitude
    return f"{round(-math.degrees(math.atan2(z.imag, z.real)), 1) + 0.0:.1f}°".join((f"{magnitude} ∠", ""))


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


def measure(units, kind: str, si_value: float | None, scale: float | None = None, prefix: str = "") -> Measure | str:
    """:func:`quantity` as a :class:`Measure`, its notation left to its column (``-`` for None)."""
    if si_value is None:
        return "-"
    shown_scale = None if scale is None else units.convert(kind, scale)
    return Measure(units.convert(kind, si_value), DIGITS[kind], units.label(kind), shown_scale, prefix)
