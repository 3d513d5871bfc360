"""A validation case, its result, and the run of the whole record.

A case holds a reference value (printed in a source, or computed by an independent method), the
function giving fcalc's value of the same quantity, and the tolerance with the reason for it
(for a printed value: half a unit of its last printed digit; for an independent method: the
accuracy fcalc states for the method under test). fcalc's value passes when
|fcalc - reference| <= tolerance (relative to |reference| for a relative case).
"""

from __future__ import annotations

from collections.abc import Callable, Sequence
from dataclasses import dataclass

#: A case's value: one number, or several compared element by element (e.g. a table's row).
Value = float | tuple[float, ...]


@dataclass(frozen=True)
class Case:
    """One comparison of fcalc with a source.

    Attributes
    ----------
    key : stable identifier, e.g. ``"das-ramana-K_z"``
    quantity : what is compared, with its unit in brackets, e.g. ``"K_z [MN/m]"``
    example : the example or problem it belongs to, e.g. ``"Lysmer block 4 x 2 x 1.5 m"``
    source : key of :data:`~foundation_calc.references.REFERENCES`
    where : equation, table or page in the source
    reference : the source's value in the unit of ``quantity`` (a callable for a value computed by
        an independent method)
    printed : the reference as the source prints it (None when computed)
    fcalc : returns fcalc's value in the unit of ``quantity``
    method : the fcalc function that gives the value
    tolerance : largest allowed |difference| (relative when ``relative``)
    relative : the tolerance and the difference are relative to |reference|
    basis : why this tolerance
    scale : size of the quantity, below whose round-off (1e-12 of it) a value is shown as 0
        (default: the reference's size; needed when the reference is 0)
    """

    key: str
    quantity: str
    example: str
    source: str
    where: str
    reference: Value | Callable[[], Value]
    printed: str | None
    fcalc: Callable[[], Value]
    method: str
    tolerance: float
    basis: str
    relative: bool = False
    scale: float | None = None


@dataclass(frozen=True)
class CaseResult:
    """A case evaluated: reference and fcalc values, the difference (fcalc - reference, the
    element of largest size for a row; relative to |reference| for a relative case) and the verdict."""

    case: Case
    reference: Value
    value: Value
    difference: float

    @property
    def passed(self) -> bool:
        """|difference| within the case's tolerance."""
        return abs(self.difference) <= self.case.tolerance


#: Why the tolerance of a printed value is what it is.
HALF_DIGIT = "half a unit of the last printed digit"


def half_digit(printed: str) -> float:
    """Half a unit of the last digit of a printed number (of each number of a " / " row).

    >>> half_digit("685.94"), half_digit("2.6"), half_digit("11.0 / 7.1"), half_digit("2")
    (0.005, 0.05, 0.05, 0.5)
    """
    decimals = max(len(p.partition(".")[2]) for p in printed.split(" / "))
    return 0.5 * 10.0**-decimals


def printed_case(key: str, quantity: str, example: str, source: str, where: str, printed: str,
                 fcalc: Callable[[], Value], method: str) -> Case:
    """A case against a value as its source prints it: the reference is the printed number (a
    " / " row gives a tuple) and the tolerance half a unit of its last digit."""
    numbers = tuple(float(p) for p in printed.split(" / "))
    return Case(key=key, quantity=quantity, example=example, source=source, where=where,
                reference=numbers if len(numbers) > 1 else numbers[0], printed=printed, fcalc=fcalc,
                method=method, tolerance=half_digit(printed), basis=HALF_DIGIT)


def _tuple(value: Value) -> tuple[float, ...]:
    return tuple(float(v) for v in value) if isinstance(value, Sequence) else (float(value),)


def difference(reference: Value, value: Value, relative: bool) -> float:
    """fcalc - reference of the element with the largest |difference| (relative to |reference|
    when ``relative``; a zero reference then compares absolutely).

    >>> difference((2.3, 4.5), (2.3, 4.4), False)
    -0.09999999999999964
    >>> difference(2.0, 2.2, True)
    0.10000000000000009
    """
    diffs = []
    for r, v in zip(_tuple(reference), _tuple(value), strict=True):
        d = v - r
        diffs.append(d / abs(r) if relative and r != 0.0 else d)
    return max(diffs, key=abs)


def evaluate(case: Case) -> CaseResult:
    """Compute fcalc's value and the reference of ``case`` and compare them."""
    reference = case.reference() if callable(case.reference) else case.reference
    value = case.fcalc()
    if isinstance(value, Sequence):
        value = tuple(float(v) for v in value)
    else:
        value = float(value)
    return CaseResult(case, reference, value, difference(reference, value, case.relative))


__all__ = ["HALF_DIGIT", "Case", "CaseResult", "Value", "difference", "evaluate", "half_digit", "printed_case"]
