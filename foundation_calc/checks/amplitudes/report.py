"""The common part of an amplitude report of every scene kind (:mod:`~foundation_calc.checks.amplitudes`):
the limit rows, the code's zone rows and warnings of a steady state (:func:`judge`), and the
report's base (:class:`AmplitudeVerdict`) that holds them with the resonance rule's report, the
soil's modulus range and the soil model's validity, and gives the verdict."""

from __future__ import annotations

from collections.abc import Callable
from dataclasses import dataclass

from foundation_calc.checks.codes import ZoneRow, code_warnings, zone_rows
from foundation_calc.checks.limits import LimitRow, amplitude_outcome, limit_rows
from foundation_calc.checks.outcomes import Outcome


@dataclass(frozen=True)
class Judgement:
    """The judged part of an amplitude report: the limit rows, the code's zone rows and why the
    code may not apply."""

    limit_rows: tuple[LimitRow, ...]
    zone_rows: tuple[ZoneRow, ...]
    code_warnings: tuple[str, ...]


def judge(names, directions, values: Callable | None, limits, speeds, supports=None) -> Judgement:
    """The limit rows, zone rows and code warnings of a steady state, for every scene kind.

    ``names``: the points, the centre of mass first; ``directions``: the names of the last axis of
    every array (the crank's horizontal, vertical; the block's x, y, z); ``values``: limited
    quantity (``displacement``, ``velocity_rms`` ... as :data:`~foundation_calc.checks.limits.QUANTITIES`
    and ``RMS_QUANTITIES`` name them) -> its array (points, directions) in SI units, None without
    a steady state (no rows); ``limits``: the scene's ``[limits]`` or None; ``speeds``: (label, ω
    [rad/s]) of every machine (:func:`~foundation_calc.checks.codes.code_warnings`; the code's
    warnings are said with or without a steady state); ``supports``: point name -> the code's
    support class per direction, None for ``limits.foundation`` everywhere.
    """
    warnings = code_warnings(limits, speeds)
    if values is None:
        return Judgement((), (), warnings)
    zones = zone_rows(names, directions, values("velocity_rms"), values("displacement_rms"), limits, supports)
    return Judgement(limit_rows(names, directions, values, limits), zones, warnings)


@dataclass(frozen=True, kw_only=True)
class AmplitudeVerdict:
    """The common part of an amplitude report of any kind, and the verdict from it with the kind's
    ``resonant`` (no steady state to judge)."""

    #: the limit rows, zone rows and code warnings (:func:`judge`)
    judgement: Judgement
    #: the resonance rule's report beside the amplitudes (a block's: every order of every machine
    #: against every mode, with the check over the soil's ``modulus_range`` and the soil model's
    #: validity once they are known)
    resonance: object = None
    #: the amplitude check over the soil's ``modulus_range``
    #: (:class:`~foundation_calc.checks.soil_range.ModulusRangeResult`), if the scene gives one
    amplitude_range: object = None
    #: a0 of the judged modes and orders against the soil method's fitted range
    #: (:class:`~foundation_calc.checks.soil_validity.SoilValidity`; a scene's report only)
    soil_validity: object = None

    @property
    def limit_rows(self) -> tuple[LimitRow, ...]:
        return self.judgement.limit_rows

    @property
    def zone_rows(self) -> tuple[ZoneRow, ...]:
        return self.judgement.zone_rows

    @property
    def code_warnings(self) -> tuple[str, ...]:
        return self.judgement.code_warnings

    @property
    def amplitude_outcome(self) -> Outcome:
        """:func:`~foundation_calc.checks.limits.amplitude_outcome` of the rows, the code's
        warnings (a machine's speed or power outside the code's group: its zones may not apply, the
        verdict warns) and the soil's modulus range."""
        noted = (Outcome.WARN,) if self.code_warnings else ()
        ranged = () if self.amplitude_range is None else (self.amplitude_range.outcome,)
        return amplitude_outcome(self.resonant, self.limit_rows, self.zone_rows, (*noted, *ranged))


__all__ = ["AmplitudeVerdict", "Judgement", "judge"]
