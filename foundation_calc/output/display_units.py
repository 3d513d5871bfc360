"""Units of the numbers shown in tables: SI by default, the units an office quotes on request.

Every command that prints a table takes ``--units`` and hands the parsed :class:`DisplayUnits`
to its report; JSON output never goes through here and stays SI. A quantity is named by what it
measures (``"amplitude"``, ``"speed"``); each unit name belongs to exactly one quantity, so
``--units mm --units rpm`` (or ``--units mm,rpm``) is unambiguous.

>>> units = parse_units(["mm,rpm"])
>>> units.show("amplitude", 2.0e-4), units.show("speed", 31.41592653589793)
('0.2 mm', '300 rpm')
>>> DisplayUnits().show("speed", 31.41592653589793)
'31.416 rad/s'
"""

from __future__ import annotations

from collections.abc import Iterable
from dataclasses import dataclass

from foundation_calc.output.console import fmt
from foundation_calc.units import hz_from_omega, rpm_from_omega

#: quantity -> {unit label: conversion from the SI value}; the first unit is the SI one.
CONVERSIONS = {
    "amplitude": {"m": lambda v: v, "mm": lambda v: v * 1e3, "µm": lambda v: v * 1e6},
    "speed": {"rad/s": lambda v: v, "Hz": hz_from_omega, "rpm": rpm_from_omega},
    "velocity": {"m/s": lambda v: v, "mm/s": lambda v: v * 1e3},
    "acceleration": {"m/s²": lambda v: v, "mm/s²": lambda v: v * 1e3},
}

#: Spellings accepted on the command line besides the labels themselves.
ALIASES = {"um": "µm", "micron": "µm", "hz": "Hz", "rad_s": "rad/s", "rads": "rad/s", "m/s2": "m/s²", "mm/s2": "mm/s²"}

#: Every unit a user may name, for ``--help``.
UNIT_CHOICES = ", ".join(unit for table in CONVERSIONS.values() for unit in table) + " (um = µm)"


@dataclass(frozen=True)
class DisplayUnits:
    """The unit each quantity is shown in (SI unless chosen otherwise)."""

    amplitude: str = "m"
    speed: str = "rad/s"
    velocity: str = "m/s"
    acceleration: str = "m/s²"

    def label(self, quantity: str) -> str:
        """The unit label of ``quantity``, e.g. ``"mm"``."""
        return getattr(self, quantity)

    def convert(self, quantity: str, si_value: float) -> float:
        """``si_value`` (m, rad/s) expressed in the chosen unit of ``quantity``."""
        return CONVERSIONS[quantity][self.label(quantity)](si_value)

    def show(self, quantity: str, si_value: float, digits: int = 5) -> str:
        """A value with its unit, e.g. ``"0.2 mm"``."""
        return f"{fmt(self.convert(quantity, si_value), digits)} {self.label(quantity)}"

    def render(self, parts) -> str:
        """Join a check's reason: text parts as they are (user text is never interpreted), and
        ``(quantity, SI value)`` parts shown in these units."""
        return "".join(part if isinstance(part, str) else self.show(*part) for part in parts)


def parse_units(tokens: Iterable[str], defaults: Iterable[str] = ()) -> DisplayUnits:
    """Build :class:`DisplayUnits` from ``--units`` values (each may be comma-separated);
    ``defaults`` (unit names) hold for the quantities the tokens do not name.

    Raises ``ValueError`` naming the unknown unit and the choices, or a quantity given twice.

    >>> parse_units(["rpm", "m"], defaults=("mm", "mm/s"))
    DisplayUnits(amplitude='m', speed='rpm', velocity='mm/s', acceleration='m/s²')
    """
    return DisplayUnits(**(_named(defaults) | _named(tokens)))


def named_quantities(tokens: Iterable[str]) -> set[str]:
    """The quantities whose unit ``--units`` values name.

    >>> sorted(named_quantities(["mm,rpm"]))
    ['amplitude', 'speed']
    """
    return set(_named(tokens))


def _named(tokens: Iterable[str]) -> dict[str, str]:
    """quantity -> unit named by ``tokens``."""
    chosen: dict[str, str] = {}
    for token in tokens:
        for name in filter(None, (part.strip() for part in token.split(","))):
            unit = ALIASES.get(name, name)
            quantity = next((q for q, table in CONVERSIONS.items() if unit in table), None)
            if quantity is None:
                raise ValueError(f"unknown unit {name!r}; choose from {UNIT_CHOICES}")
            if quantity in chosen and chosen[quantity] != unit:
                raise ValueError(f"two units for {quantity}: {chosen[quantity]} and {unit}")
            chosen[quantity] = unit
    return chosen
