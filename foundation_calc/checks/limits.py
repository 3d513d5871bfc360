"""The limit check shared by every command: which quantities a scene limits, and when a value
exceeds its limit. ``fcalc amplitudes``, ``fcalc check`` and ``fcalc sweep`` all call these, so
a scene that fails on velocity in one command fails on it in every other.

Two statistics of the periodic motion are limited: the **peak** over one revolution (keys
``amplitude``, ``velocity``, ``acceleration``) and the **RMS** over one revolution of the
vibration, the mean (static) part left out (keys ``amplitude_rms``, ``velocity_rms``,
``acceleration_rms``), sqrt(Σ_{n≥1} |Q_n|²/2) of the harmonics Q_n.
"""

from __future__ import annotations

from collections.abc import Mapping
from dataclasses import dataclass, field

from foundation_calc.checks.outcomes import Outcome, worst

#: Peak quantities a limit may bound, with the scene's ``[limits]`` key of each [m, m/s, m/s²].
QUANTITIES = {"displacement": "amplitude", "velocity": "velocity", "acceleration": "acceleration"}

#: RMS quantities a limit may bound, with the scene's ``[limits]`` key of each [m, m/s, m/s²].
RMS_QUANTITIES = {f"{quantity}_rms": f"{key}_rms" for quantity, key in QUANTITIES.items()}


def limited_quantities(limits) -> dict[str, float]:
    """``quantity -> limit`` for every peak or RMS quantity the scene's ``[limits]`` bounds (SI).

    >>> from types import SimpleNamespace
    >>> limited_quantities(SimpleNamespace(amplitude=2e-4, velocity=None, acceleration=0.3, velocity_rms=2e-3))
    {'displacement': 0.0002, 'acceleration': 0.3, 'velocity_rms': 0.002}
    """
    keys = QUANTITIES | RMS_QUANTITIES
    found = {quantity: getattr(limits, key, None) for quantity, key in keys.items()}
    return {quantity: limit for quantity, limit in found.items() if limit is not None}


def display_quantity(quantity: str) -> str:
    """The display quantity (``output.display_units``) of a limited quantity, peak or RMS.

    >>> display_quantity("displacement_rms"), display_quantity("velocity")
    ('amplitude', 'velocity')
    """
    return QUANTITIES[quantity.removesuffix("_rms")]


def limit_key(quantity: str) -> str:
    """The scene's ``[limits]`` key of a limited quantity (``"velocity_rms"`` -> ``"velocity_rms"``)."""
    return (QUANTITIES | RMS_QUANTITIES)[quantity]


def exceeds(value, limit):
    """Whether a value exceeds its limit (arrays welcome): equal to the limit passes."""
    return value > limit


@dataclass(frozen=True)
class LimitRow:
    """A peak or RMS value of one point, direction and quantity against its limit (SI units)."""

    point: str
    direction: str
    quantity: str
    value: float
    limit: float
    outcome: Outcome

    @property
    def ratio(self) -> float:
        return self.value / self.limit

    @property
    def source(self) -> str:
        return f"scene [limits] {limit_key(self.quantity)}"


def limit_rows(names, directions, values, limits) -> tuple[LimitRow, ...]:
    """Every limited quantity of every point and direction against its limit, for every scene kind
    (the crank's C and points in horizontal, vertical; the block's G and points in x, y, z): rows
    quantity by quantity, then point by point, then direction.

    ``values``: limited quantity -> its values, an array (points, directions) in SI units, called
    only for the quantities ``limits`` bounds.

    >>> import numpy as np
    >>> from types import SimpleNamespace
    >>> rows = limit_rows(["C"], ("x", "y"), lambda q: np.array([[1e-4, 3e-4]]), SimpleNamespace(amplitude=2e-4))
    >>> [(r.direction, r.outcome.value) for r in rows]
    [('x', 'pass'), ('y', 'fail')]
    """
    rows = []
    for quantity, limit in limited_quantities(limits).items():
        array = values(quantity)
        over = exceeds(array, limit).tolist()
        for name, value, fails in zip(names, array.tolist(), over):
            rows += [LimitRow(name, direction, quantity, v, limit, Outcome.FAIL if f else Outcome.PASS)
                     for direction, v, f in zip(directions, value, fails)]
    return tuple(rows)


def amplitude_outcome(resonant: bool, rows, zone_rows, others=()) -> Outcome:
    """The verdict of the amplitudes of every scene kind: FAIL without a steady state (``resonant``),
    else the worst of the limit rows, the code's zone rows and ``others`` (outcomes: a code's
    warnings, the soil's modulus range)."""
    if resonant:
        return Outcome.FAIL
    return worst((*(row.outcome for row in rows), *(row.outcome for row in zone_rows), *others))


@dataclass(frozen=True)
class AmplitudeWording:
    """How an amplitude report is stated as ``fcalc check``'s finding
    (:func:`~foundation_calc.checks.registry.amplitudes_finding`), chosen by the report itself.

    Attributes
    ----------
    resonant : the reason without a steady state, as parts (literal text, ``(quantity, SI value)``)
    values : name -> (quantity, SI value) said before the judged ones (a crank's speed)
    statement : the resonance rule's verdict, said after the limits; None for none
    itemised : the crank's wording, kept as CI scripts read it: the count of values over their
        limits, the worst zone's values and a detail line per zone
    """

    resonant: tuple
    values: Mapping[str, tuple[str, float]] = field(default_factory=dict)
    statement: str | None = None
    itemised: bool = False
