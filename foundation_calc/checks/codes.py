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

The tables state each class twice, in broad-band r.m.s. velocity [mm/s] and r.m.s. displacement
[µm] (displacement columns of Tables A.1 and A.2), and clause 5.2.3 applies the more restrictive
of the two zones. Annex A adds that the velocity alone usually suffices and that both should be
judged where the spectrum carries low-frequency components: below 600 r/min, where the machine's
own frequency lies under 10 Hz, a velocity within its zone may still mean a displacement beyond
it. fcalc computes both at every point, so :func:`code_zone` classifies both and the worse zone
decides (5.2.3); above about 750 r/min (group 1) or 600 r/min (group 2) the displacement of a
response at the running speed and its multiples cannot decide, save by the tables' rounding.
The displacement boundaries stored here (group 1 rigid 29/57/90, flexible 45/90/140; group 2
rigid 22/45/71, flexible 37/71/113 µm) are each, within 1 µm, the displacement amplitude of a
sinusoid with the velocity boundary's amplitude at 12.5 Hz (group 1) or 10 Hz (group 2), a
relation the tests use to catch a mistyped digit. ISO 20816-3:2022, which replaced ISO 10816-3,
is not accepted: its tables have not been checked against these.
"""

from __future__ import annotations

from dataclasses import dataclass

from foundation_calc.checks.outcomes import Outcome

#: The caveat of applying a code's zones to a prediction: said beside every zone found, on the sheet
#: and in ``fcalc check``'s notes.
ZONE_CAVEAT = (
    "ISO 10816-3's zones judge vibration measured on the machine's non-rotating parts (its bearing housings"
    " or pedestals) in situ; fcalc applies them to the predicted motion of the foundation block at the"
    " machine's points, a calculated rigid-body motion and not a measurement: the zone found is an"
    " indication for design, not the acceptance the code describes"
)

#: Zone names in order of severity.
ZONES = ("A", "B", "C", "D")


@dataclass(frozen=True)
class ZoneTable:
    """The zone boundaries of one code, machine group and support class.

    Attributes
    ----------
    code : the code's name as a scene writes it, e.g. ``"ISO 10816-3"``
    clause : edition, annex and table the boundaries come from
    group : machine group (1 or 2)
    foundation : support class, ``"rigid"`` or ``"flexible"``
    boundaries_mm_s : r.m.s. velocity at the zone boundaries A/B, B/C, C/D [mm/s]
    displacement_boundaries_um : r.m.s. displacement at A/B, B/C, C/D [µm]
    speed_range_rpm : range of machine speeds the code applies to [rpm]
    power_range_kw : range of rated power of the group, (above, up to and including) [kW]
    """

    code: str
    clause: str
    group: int
    foundation: str
    boundaries_mm_s: tuple[float, float, float]
    displacement_boundaries_um: tuple[float, float, float]
    speed_range_rpm: tuple[float, float]
    power_range_kw: tuple[float, float]

    @property
    def boundaries(self) -> tuple[float, float, float]:
        """The zone boundaries A/B, B/C, C/D [m/s]."""
        return tuple(b / 1e3 for b in self.boundaries_mm_s)

    @property
    def displacement_boundaries(self) -> tuple[float, float, float]:
        """The displacement zone boundaries A/B, B/C, C/D [m]."""
        return tuple(b / 1e6 for b in self.displacement_boundaries_um)

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
        ZoneTable(**_ISO_10816_3, **_GROUP_1, foundation="rigid", boundaries_mm_s=(2.3, 4.5, 7.1),
                  displacement_boundaries_um=(29.0, 57.0, 90.0)),
        ZoneTable(**_ISO_10816_3, **_GROUP_1, foundation="flexible", boundaries_mm_s=(3.5, 7.1, 11.0),
                  displacement_boundaries_um=(45.0, 90.0, 140.0)),
        ZoneTable(**_ISO_10816_3, **_GROUP_2, foundation="rigid", boundaries_mm_s=(1.4, 2.8, 4.5),
                  displacement_boundaries_um=(22.0, 45.0, 71.0)),
        ZoneTable(**_ISO_10816_3, **_GROUP_2, foundation="flexible", boundaries_mm_s=(2.3, 4.5, 7.1),
                  displacement_boundaries_um=(37.0, 71.0, 113.0)),
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


def zone_index(velocity_rms, table: ZoneTable, boundaries=None):
    """Index into :data:`ZONES` of r.m.s. velocities [m/s] (float or array) in ``table``, or of
    other values against ``boundaries`` (the displacement's [m]); a boundary value belongs to the
    lower zone."""
    import numpy as np

    bounds = table.boundaries if boundaries is None else boundaries
    return np.sum(np.asarray(velocity_rms, dtype=float)[..., None] > np.asarray(bounds), axis=-1)


def displacement_zone(displacement_rms: float, table: ZoneTable) -> str:
    """The zone of an r.m.s. displacement [m] in ``table``; a boundary value belongs to the lower zone.

    >>> displacement_zone(45e-6, TABLES["ISO 10816-3", 2, "rigid"]), displacement_zone(46e-6, TABLES["ISO 10816-3", 2, "rigid"])
    ('B', 'C')
    """
    return ZONES[int(zone_index(displacement_rms, table, table.displacement_boundaries))]


def code_zone_index(velocity_rms, displacement_rms, table: ZoneTable):
    """:func:`code_zone` on arrays (a batch of designs): (zone index into :data:`ZONES`, True where
    the displacement decides). Velocities [m/s], displacements [m] of the same shape."""
    import numpy as np

    by_velocity = zone_index(velocity_rms, table)
    by_displacement = zone_index(displacement_rms, table, table.displacement_boundaries)
    return np.maximum(by_velocity, by_displacement), by_displacement > by_velocity


@dataclass(frozen=True)
class CodeZone:
    """The zone of one point and the quantity that decides it.

    Attributes
    ----------
    zone : the worse of the judged quantities' zones
    quantity : ``"velocity"`` or ``"displacement"``, the one that gives ``zone`` (the velocity on a tie)
    value : the governing quantity's r.m.s. value [m/s or m]
    limit : its boundary above which the verdict fails (the ``acceptable`` zone's upper boundary) [m/s or m]
    velocity_zone : zone of the r.m.s. velocity
    displacement_zone : zone of the r.m.s. displacement
    """

    zone: str
    quantity: str
    value: float
    limit: float
    velocity_zone: str
    displacement_zone: str

    @property
    def ratio(self) -> float:
        return self.value / self.limit

    def describe(self, table: ZoneTable) -> str:
        """E.g. ``"zone C, 3.1 mm/s RMS > 2.8"`` or ``"zone C, 48 µm RMS > 45"`` (the code's units)."""
        i = ZONES.index(self.zone)
        if self.quantity == "velocity":
            shown, bounds, unit = self.value * 1e3, table.boundaries_mm_s, "mm/s"
        else:
            shown, bounds, unit = self.value * 1e6, table.displacement_boundaries_um, "µm"
        bound = f"> {bounds[i - 1]:g}" if i else f"<= {bounds[0]:g}"
        return f"zone {self.zone}, {shown:.3g} {unit} RMS {bound}"


class JudgedRow:
    """What a row holding ``judged`` (a :class:`CodeZone`) and ``table`` says: the zone, the
    deciding quantity's value and limit [m/s or m], their ratio, and the verdict's text (with
    the row's ``direction_text``)."""

    @property
    def zone(self) -> str:
        return self.judged.zone

    @property
    def value(self) -> float:
        return self.judged.value

    @property
    def limit(self) -> float:
        return self.judged.limit

    @property
    def ratio(self) -> float:
        return self.judged.ratio

    @property
    def verdict_text(self) -> str:
        """E.g. ``"ISO 10816-3, group 2, rigid: zone C, 3.1 mm/s RMS > 2.8 (horizontal)"`` (the code's units)."""
        return f"{self.table.title}: {self.judged.describe(self.table)} ({self.direction_text})"


def code_zone(table: ZoneTable, velocity_rms: float, displacement_rms: float, acceptable: str | None) -> CodeZone:
    """Zone of a point with r.m.s. velocity [m/s] and displacement [m]: the more restrictive of
    the two (ISO 10816-3:2009, 5.2.3; module docstring). ``acceptable``: the scene's
    ``acceptable_zone`` (None: B), whose upper boundary is the row's limit.

    >>> t = TABLES["ISO 10816-3", 2, "rigid"]
    >>> z = code_zone(t, 2.0e-3, 60e-6, None)
    >>> z.zone, z.quantity, z.velocity_zone, z.describe(t)
    ('C', 'displacement', 'B', 'zone C, 60 µm RMS > 45')
    >>> code_zone(t, 2.0e-3, 20e-6, None).quantity
    'velocity'
    """
    highest = ZONES.index(acceptable or "B")
    index, decides = code_zone_index(velocity_rms, displacement_rms, table)
    by_velocity, by_displacement = zone(velocity_rms, table), displacement_zone(displacement_rms, table)
    if decides:
        return CodeZone(ZONES[int(index)], "displacement", displacement_rms, table.displacement_boundaries[highest],
                        by_velocity, by_displacement)
    return CodeZone(ZONES[int(index)], "velocity", velocity_rms, table.boundaries[highest], by_velocity, by_displacement)


def point_zone(tables, velocity, displacement, acceptable: str | None) -> tuple[CodeZone, ZoneTable, int]:
    """The zone of a point whose directions may be judged in different tables (a support rigid in
    one measuring direction and flexible in another, ISO 10816-3:2009, 3.4): the directions of one
    table together by their largest r.m.s. velocity [m/s] and displacement [m] (:func:`code_zone`),
    the worst zone (then the larger ratio to its limit) governing. ``tables``, ``velocity`` and
    ``displacement`` hold one entry per direction. Returns the zone, its table and the index of
    the governing direction (the deciding quantity's largest in that table's directions, the first
    on a tie). With one table it is :func:`code_zone` of the largest values.

    >>> rigid, flexible = TABLES["ISO 10816-3", 2, "rigid"], TABLES["ISO 10816-3", 2, "flexible"]
    >>> z, table, d = point_zone((flexible, rigid), (3.5e-3, 2.0e-3), (1e-6, 1e-6), None)
    >>> z.zone, table.foundation, d
    ('B', 'flexible', 0)
    """
    groups: dict[ZoneTable, list[int]] = {}
    for d, table in enumerate(tables):
        groups.setdefault(table, []).append(d)
    found = None
    for table, directions in groups.items():
        judged = code_zone(table, max(velocity[d] for d in directions), max(displacement[d] for d in directions),
                           acceptable)
        values = velocity if judged.quantity == "velocity" else displacement
        governing = max(directions, key=lambda d: values[d])
        severity = (ZONES.index(judged.zone), judged.ratio)
        if found is None or severity > found[0]:
            found = (severity, judged, table, governing)
    return found[1:]


def zone_outcome(zone_name: str, acceptable: str | None) -> Outcome:
    """The verdict of a code zone (docs/checks.md, "Code limits"): C and D fail; with no ``acceptable``
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
    outside the group's range. Empty when it applies.

    >>> application_warnings(TABLES["ISO 10816-3", 2, "rigid"], 100.0, 100.0)[0]
    'ISO 10816-3 applies to speeds of 120 to 15000 rpm; the machine runs at 100 rpm'
    """
    found = []
    lo, hi = table.speed_range_rpm
    if not lo <= speed_rpm <= hi:
        found.append(
            f"{table.code} applies to speeds of {lo:g} to {hi:g} rpm; the machine runs at {speed_rpm:.6g} rpm"
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


@dataclass(frozen=True)
class ZoneRow(JudgedRow):
    """A point's zone in a vibration code, for every scene kind: its largest RMS velocity and its
    largest RMS displacement, the more restrictive deciding (``judged`` says which; ``direction``
    is that quantity's direction, "horizontal"/"vertical" on a crank scene, x/y/z on a block).

    ``velocity``, ``displacement``: the point's RMS velocity [m/s] and RMS displacement [m], one
    per direction; ``support``: the support class of each direction
    (:mod:`~foundation_calc.checks.support`), each direction judged in its class's table
    (``table``: the governing one's); empty when the scene's ``limits.foundation`` judges them all.
    """

    point: str
    direction: str
    judged: CodeZone
    outcome: Outcome
    table: ZoneTable
    support: tuple = ()
    velocity: tuple = ()
    displacement: tuple = ()

    @property
    def direction_text(self) -> str:
        return self.direction

    @property
    def governing(self) -> str:
        """The direction of the deciding quantity's larger value (:attr:`direction`)."""
        return self.direction

    @property
    def quantity(self) -> str:
        """``"r.m.s. velocity"`` or ``"r.m.s. displacement"``."""
        return f"r.m.s. {self.judged.quantity}"


def zone_rows(names, directions, velocity, displacement, limits, supports=None) -> tuple[ZoneRow, ...]:
    """The code zone of every point, for every scene kind (none without ``[limits] code``): its
    largest RMS velocity and its largest RMS displacement, the more restrictive deciding, each
    direction in the table of its support class (:func:`point_zone`).

    ``velocity``, ``displacement``: arrays (points, directions) [m/s, m]; ``supports``: point name
    -> one :class:`~foundation_calc.checks.support.SupportClass` per direction, None for the
    scene's ``limits.foundation`` everywhere.

    Raises
    ------
    ValueError
        neither ``supports`` nor ``limits.foundation``.
    """
    if getattr(limits, "code", None) is None:
        return ()
    if supports is None and limits.foundation is None:
        raise ValueError("the code's support class: give limits.foundation or the classification from the modes")
    rows = []
    for name, v, x in zip(names, velocity.tolist(), displacement.tolist()):
        classes = () if supports is None else supports[name]
        kinds = [c.support for c in classes] or [limits.foundation] * len(directions)
        tables = [TABLES[limits.code, limits.machine_group, kind] for kind in kinds]
        judged, table, d = point_zone(tables, v, x, limits.acceptable_zone)
        rows.append(ZoneRow(name, directions[d], judged, zone_outcome(judged.zone, limits.acceptable_zone), table,
                            classes, tuple(v), tuple(x)))
    return tuple(rows)


def code_warnings(limits, speeds) -> tuple[str, ...]:
    """Why the scene's code may not apply (:func:`application_warnings` of its group's speed and
    power ranges, whatever the support), for every scene kind; none without a code.

    ``speeds``: (label, ω [rad/s]) of every machine, the label (None: unnamed) before each one's
    speed warning; the power's warnings once.
    """
    if getattr(limits, "code", None) is None:
        return ()
    from foundation_calc.units import rpm_from_omega

    table = TABLES[limits.code, limits.machine_group, "rigid"]
    power = None if limits.machine_power is None else limits.machine_power / 1e3
    found = []
    for label, omega in speeds:
        found += [w if label is None else f"{label}: {w}"
                  for w in application_warnings(table, rpm_from_omega(omega), power) if "rpm" in w]
    found += [w for w in application_warnings(table, rpm_from_omega(speeds[0][1]), power) if "rpm" not in w]
    return tuple(found)


__all__ = ["CODES", "TABLES", "ZONES", "ZONE_CAVEAT", "CodeZone", "JudgedRow", "ZoneRow", "ZoneTable",
           "application_warnings", "code_warnings", "code_zone", "code_zone_index", "displacement_zone", "point_zone", "zone", "zone_index",
           "zone_outcome", "zone_rows", "zone_verdicts"]
