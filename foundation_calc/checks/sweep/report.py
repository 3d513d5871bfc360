"""The report of ``fcalc sweep`` for every scene kind: one row per swept value, every per-row
quantity a numpy array on the leading axis (no Python object per row), the rows judged by one set
of rules (:mod:`~foundation_calc.checks.sweep.status`). What differs by kind is data: the kind's
values per row (``columns``), its facts about the whole sweep (``setup``) and the type of its
critical speeds."""

from __future__ import annotations

from dataclasses import dataclass, field, fields, replace

import numpy as np

from foundation_calc.checks.sweep.status import RowVerdicts


@dataclass(frozen=True)
class SweepReport:
    """A sweep of a speed or of a factor on the soil, of any kind.

    Attributes
    ----------
    variable : ``"omega"`` (a speed [rad/s]) or ``"soil_factor"`` (a factor on the soil's stiffness data [-])
    values : (N,) the swept values
    resonant : (N,) no steady state at that row (its values 0, NaN or left out, as the kind says)
    rows : the rows' verdicts (:class:`~foundation_calc.checks.sweep.status.RowVerdicts`)
    conditions : the resonance conditions judged at every row (each with a ``label``), in the order
        of ``rows.governing``; where the labels change along the sweep (``per_row``: a block's soil
        sweep, whose modes are those at each factor) one tuple of them a row
    critical : the critical speeds of the conditions inside the swept range (a speed sweep; the
        kind's type: :class:`~foundation_calc.checks.sweep.crank.CriticalSpeed`,
        :class:`~foundation_calc.checks.sweep.block.SweepCondition`)
    limits : limited quantity -> limit (SI) judged along the sweep
    detuning : the scene's band, or bands by order
    columns : the kind's values per row, name -> (N, ...) array or a dict of such arrays (a crank
        scene: ``omega``, ``peaks``, ``points``, ``harmonics``; a block: the largest peak and RMS
        values over G and its points, :data:`~foundation_calc.checks.amplitudes.machines.LIMITED_VALUES`)
    setup : the kind's facts about the whole sweep (a crank scene: ``damped``, ``coupled``,
        ``not_applicable``; a block's speed sweep: ``machine``, ``alone``, ``speed``; its soil
        sweep: ``speeds``)
    per_row : ``conditions`` holds one tuple a row
    """

    variable: str
    values: np.ndarray
    resonant: np.ndarray
    rows: RowVerdicts
    conditions: tuple
    limits: dict
    detuning: object
    columns: dict
    setup: dict = field(default_factory=dict)
    critical: tuple = ()
    per_row: bool = False

    def governing_condition(self, i: int) -> str | None:
        """The label of the condition that governs row ``i`` (None: none can decide)."""
        return self.rows.condition(i, self.conditions[i] if self.per_row else self.conditions)


def _join(items):
    """Arrays joined end to end, or dicts of them key by key."""
    if isinstance(items[0], dict):
        return {key: _join([item[key] for item in items]) for key in items[0]}
    return np.concatenate(items)


def joined(parts: list[SweepReport]) -> SweepReport:
    """One report of the chunks ``parts`` of one sweep (their rows joined end to end; of each fact
    about the whole sweep the first chunk's that holds one, e.g. why an approximation is left out
    at some speeds)."""
    first = parts[0]
    if len(parts) == 1:
        return first
    return replace(
        first,
        values=_join([p.values for p in parts]),
        resonant=_join([p.resonant for p in parts]),
        rows=RowVerdicts(**{f.name: _join([getattr(p.rows, f.name) for p in parts]) for f in fields(RowVerdicts)}),
        conditions=sum((p.conditions for p in parts), ()) if first.per_row else first.conditions,
        columns=_join([p.columns for p in parts]),
        setup={key: next((p.setup[key] for p in parts if p.setup[key]), first.setup[key]) for key in first.setup},
    )


__all__ = ["SweepReport", "joined"]
