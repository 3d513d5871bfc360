"""The plain items a support's part of the calculation sheet is made of; the output layer renders
them (:mod:`foundation_calc.output.report.block_soil`): a hand calculation (:class:`HandCalc` of
:class:`Given` and :class:`Step` rows, each formula evaluated and shown with its values), a
paragraph (:class:`Text`), a table of numbers (:class:`Grid`), or the chains of a soil method of
the footing (:class:`SoilMethod`, the hand calculations the crank foundation's sheet shares)."""

from __future__ import annotations

from dataclasses import dataclass


@dataclass(frozen=True)
class Given:
    """A value given: ``symbol`` = ``value`` [``unit``], what it is."""

    symbol: str
    value: float
    unit: str
    meaning: str


@dataclass(frozen=True)
class Step:
    """A value computed: ``symbol`` = ``formula`` (of the symbols before it) [``unit``], by ``source``."""

    symbol: str
    formula: str
    unit: str
    source: str
    meaning: str


class Rows(list):
    """The rows of a :class:`HandCalc` as they are written: ``rows.given(...)``, ``rows.step(...)``
    (the arguments of :class:`Given`, :class:`Step`)."""

    def given(self, symbol: str, value: float, unit: str, meaning: str) -> None:
        self.append(Given(symbol, value, unit, meaning))

    def step(self, symbol: str, formula: str, unit: str, source: str, meaning: str) -> None:
        self.append(Step(symbol, formula, unit, source, meaning))


@dataclass(frozen=True)
class HandCalc:
    """A hand calculation: its title and its rows (:class:`Given`, :class:`Step`) in order."""

    title: str
    rows: tuple


@dataclass(frozen=True)
class Text:
    """A paragraph."""

    text: str


@dataclass(frozen=True)
class Grid:
    """A table of numbers: a row per name, ``values`` (rows × columns), ``digits`` significant figures."""

    title: str
    head: tuple
    names: tuple
    values: object
    digits: int = 4


@dataclass(frozen=True)
class SoilMethod:
    """The hand calculations of the soil method ``method`` for a footing: its ``soil`` (the data of
    :func:`~.footing_springs.six_springs`), ``base`` (L, B) [m] and ``embedment`` D [m]."""

    method: str
    soil: object
    base: tuple
    embedment: float


__all__ = ["Given", "Grid", "HandCalc", "Rows", "SoilMethod", "Step", "Text"]
