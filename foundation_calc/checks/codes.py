"""Vibration codes a scene may name in ``[limits] code``: their zone tables, stored as data.

ISO 10816-3:2009, *Mechanical vibration — Evaluation of machine vibration by measurements on
non-rotating parts — Part 3: Industrial machines with nominal power above 15 kW and nominal
speeds between 120 r/min and 15 000 r/min when measured in situ*, Annex A (normative):

- Table A.1, group 1: large machines, rated power above 300 kW up to 50 MW;
- Table A.2, group 2: medium-size machines, rated power above 15 kW up to 300 kW.

Each table gives the zone boundaries A/B, B/C, C/D of the broad-band r.m.s. vibration velocity
[mm/s] for a rigid and a flexible support (clause 3.4: rigid when the lowest natural frequency
of the machine on its support is at least 25 % above the main excitation frequency). Zones
(clause 6.2.2): A, newly commissioned machines; B, unrestricted long-term operation; C, not
suitable for long-term continuous operation; D, severe enough to cause damage. A value equal to
a boundary belongs to the lower zone.

Below 600 r/min the tables judge the broad-band r.m.s. displacement [µm] as well as the velocity
(Annex A, Tables A.1 and A.2, displacement columns: at low speeds a velocity within its zone may
still mean a displacement beyond it). Those displacement boundaries are not stored:
their printed values could not be checked against the standard, and a boundary is kept here only
with its printed value and clause. For a machine below :data:`DISPLACEMENT_SPEED_RPM`,
:func:`application_warnings` says so, and the velocity zone alone is judged. ISO 20816-3:2022,
which replaced ISO 10816-3, is not accepted: its tables have not been checked against these.
"""

from __future__ import annotations

from dataclasses import dataclass

from foundation_calc.checks.outcomes import Outcome

#: Speed [r/min] below which ISO 10816-3 judges the r.m.s. displacement as well (Annex A).
DISPLACEMENT_SPEED_RPM = 600.0

#: Zone names in order of severity.
ZONES = ("A", "B", "C", "D")


@dataclass(frozen=True)
class ZoneTable:
    """The zone boundaries of one code, machine group and support class.

    Attributes
    ----------
    code : the code's name as a scene writes it, e.g. ``"ISO 10816-3"``
    displacement_boundaries_um : r.m.s. displacement at A/B, B/C, C/D [µm] for speeds below
        :data:`DISPLACEMENT_SPEED_RPM`, or None where the printed boundary is not stored
    clause : edition, annex and table the boundaries come from
    group : machine group (1 or 2)
    foundation : support class, ``"rigid"`` or ``"flexible"``
    boundaries_mm_s : r.m.s. velocity at the zone boundaries A/B, B/C, C/D [mm/s]
    speed_range_rpm : range of machine speeds the code applies to [rpm]
    power_range_kw : range of rated power of the group, (above, up to and including) [kW]
    """

    code: str
    clause: str
    group: int
    foundation: str
    boundaries_mm_s: tuple[float, float, float]
    speed_range_rpm: tuple[float, float]
    power_range_kw: tuple[float, float]
    displacement_boundaries_um: tuple[float, float, float] | None = None

    @property
    def boundaries(self) -> tuple[float, float, float]:
        """The zone boundaries A/B, B/C, C/D [m/s]."""
        return tuple(b / 1e3 for b in self.boundaries_mm_s)

    @property
    def title(self) -> str:
        """E.g. ``"ISO 10816-3, group 2, rigid"``."""
        return f"{self.code}, group {self.group}, {self.foundation}"


_ISO_10816_3 = dict(code="ISO 10816-3", speed_range_rpm=(120.0, 15000.0))
_GROUP_1 = dict(group=1, clause="ISO 10816-3:2009, Annex A, Table A.1", power_range_kw=(300.0, 50000.0))
_GROUP_2 = dict(group=2, clause="ISO 10816-3:2009, Annex A, Table A.2", power_range_kw=(15.0, 300.0))

#: (code, group, foundation) -> zone table.
TABLES: dict[tuple[str, int, str], ZoneTable] = {
    (t.code, t.group, t.foundation): t
    for t in (
        ZoneTable(**_ISO_10816_3, **_GROUP_1, foundation="rigid", boundaries_mm_s=(2.3, 4.5, 7.1)),
        ZoneTable(**_ISO_10816_3, **_GROUP_1, foundation="flexible", boundaries_mm_s=(3.5, 7.1, 11.0)),
        ZoneTable(**_ISO_10816_3, **_GROUP_2, foundation="rigid", boundaries_mm_s=(1.4, 2.8, 4.5)),
        ZoneTable(**_ISO_10816_3, **_GROUP_2, foundation="flexible", boundaries_mm_s=(2.3, 4.5, 7.1)),
    )
}

#: Code names that have tables (the scene model's ``code`` choices must be these).
CODES = tuple(sorted({code for code, _, _ in TABLES}))


def zone(velocity_rms: float, table: ZoneTable) -> str:
    """The zone of an r.m.s. velocity [m/s] in ``table``; a boundary value belongs to the lower zone.

    >>> zone(2.8e-3, TABLES["ISO 10816-3", 2, "rigid"]), zone(2.81e-3, TABLES["ISO 10816-3", 2, "rigid"])
    ('B', 'C')
    """
    return ZONES[int(zone_index(velocity_rms, table))]


def zone_index(velocity_rms, table: ZoneTable):
    """Index into :data:`ZONES` of r.m.s. velocities [m/s] (float or array) in ``table``; a
    boundary value belongs to the lower zone."""
    import numpy as np

    return np.sum(np.asarray(velocity_rms, dtype=float)[..., None] > np.asarray(table.boundaries), axis=-1)


def zone_outcome(zone_name: str, acceptable: str | None) -> Outcome:
    """The verdict of a code zone (README, "Code limits"): C and D fail; with no ``acceptable``
    zone A passes and B warns; otherwise the zones up to ``acceptable`` pass and the rest fail.

    >>> [zone_outcome(z, None).value for z in "ABCD"], [zone_outcome(z, "A").value for z in "AB"]
    (['pass', 'warn', 'fail', 'fail'], ['pass', 'fail'])
    """
    return zone_verdicts(acceptable)[ZONES.index(zone_name)]


def zone_verdicts(acceptable: str | None) -> tuple[Outcome, Outcome, Outcome, Outcome]:
    """The verdict of each zone of :data:`ZONES` (:func:`zone_outcome`)."""
    if acceptable is None:
        return (Outcome.PASS, Outcome.WARN, Outcome.FAIL, Outcome.FAIL)
    return tuple(Outcome.PASS if i <= ZONES.index(acceptable) else Outcome.FAIL for i in range(len(ZONES)))


def application_warnings(table: ZoneTable, speed_rpm: float, power_kw: float | None) -> list[str]:
    """Why the code may not apply to this machine: speed outside its range, power unknown or
    outside the group's range, a displacement boundary the code sets below 600 r/min that is not
    stored. Empty when it applies.

    >>> application_warnings(TABLES["ISO 10816-3", 2, "rigid"], 250.0, 100.0)[0][:60]
    'ISO 10816-3 judges machines below 600 r/min by their r.m.s. '
    """
    found = []
    lo, hi = table.speed_range_rpm
    if not lo <= speed_rpm <= hi:
        found.append(
            f"{table.code} applies to speeds of {lo:g} to {hi:g} rpm; the machine runs at {speed_rpm:.6g} rpm"
        )
    if speed_rpm < DISPLACEMENT_SPEED_RPM and table.displacement_boundaries_um is None:
        found.append(
            f"{table.code} judges machines below {DISPLACEMENT_SPEED_RPM:g} r/min by their r.m.s. displacement"
            f" as well as the velocity ({table.clause}, displacement columns); those boundaries are not stored"
            f" in fcalc: only the velocity zone is judged here - check the displacement against the printed table"
        )
    above, upto = table.power_range_kw
    if power_kw is None:
        found.append(
            f"the machine's rated power is not given ([limits] machine_power): group {table.group}"
            f" ({above:g} kW < P <= {upto:g} kW) is not verified"
        )
    elif not above < power_kw <= upto:
        found.append(
            f"machine_power = {power_kw:.6g} kW is outside group {table.group} of {table.code}"
            f" ({above:g} kW < P <= {upto:g} kW)"
        )
    return found


__all__ = ["CODES", "DISPLACEMENT_SPEED_RPM", "TABLES", "ZONES", "ZoneTable", "application_warnings", "zone",
           "zone_index", "zone_outcome", "zone_verdicts"]
