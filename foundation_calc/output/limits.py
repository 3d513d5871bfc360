"""The limit rows and code zones of ``fcalc amplitudes`` (:mod:`~foundation_calc.checks.limits`,
:func:`~foundation_calc.checks.codes.zone_rows`), the same for every scene kind: their JSON parts
and their tables. The kinds differ in their points' directions only (the crank's horizontal and
vertical, the block's x, y, z)."""

from __future__ import annotations

from foundation_calc.checks.governing import worst_rows
from foundation_calc.checks.limits import display_quantity
from foundation_calc.output.console import fits, fmt, frameless, verdict_text, whole_if_fits
from foundation_calc.output.notes import point_support_document, support_document

#: Points besides C or G up to which the tables list every point and limit row; with more, they
#: show the governing points and the largest value/limit ratios (every row with --all-points or --json).
ALL_POINTS_UP_TO = 12


def summarised(points: int, all_points: bool = False) -> bool:
    """Whether the tables of a scene with ``points`` points (C or G not counted) show the governing
    points and the largest value/limit ratios rather than every row (``all_points``: every row)."""
    return not all_points and points > ALL_POINTS_UP_TO


#: Limit rows shown for a scene with many points: the largest ratios (and each quantity's largest).
WORST_ROWS = 10

#: Where a summarised table's rows all are.
EVERY_ROW = "every row: --all-points or --json"

#: Names of a code table's zone boundaries.
BOUNDARIES = ("A/B", "B/C", "C/D")


def limits_document(rows) -> list[dict]:
    """The ``limits`` part of the JSON document: every limit row (SI units)."""
    return [
        {"point": row.point, "direction": row.direction, "quantity": row.quantity, "value": row.value,
         "limit": row.limit, "ratio": row.ratio, "verdict": row.outcome.value, "source": row.source}
        for row in rows
    ]


def code_document(limits, rows, warnings, directions=None) -> dict | None:
    """The ``code`` part of the JSON document: the scene's code, the table used, the zone of every
    point (``rows``), ``warnings`` (why the code may not apply); None without a code.
    ``directions`` (the crank's): also the governing table's boundaries and each point's RMS
    velocity and displacement by those directions' names."""
    if getattr(limits, "code", None) is None:
        return None
    table = rows[0].table if rows else None
    doc = {"code": limits.code, "machine_group": limits.machine_group, "foundation": limits.foundation,
           "acceptable_zone": limits.acceptable_zone, "clause": table.clause if table else None}
    if directions is not None:
        doc["boundaries"] = dict(zip(BOUNDARIES, table.boundaries)) if table else None
        doc["displacement_boundaries"] = dict(zip(BOUNDARIES, table.displacement_boundaries)) if table else None
    doc.update(support_document(limits, rows))
    doc["points"] = [_zone_document(row, directions) for row in rows]
    doc["warnings"] = list(warnings)
    return doc


def _zone_document(row, directions) -> dict:
    values = {} if directions is None else {"velocity_rms": dict(zip(directions, row.velocity)),
                                             "displacement_rms": dict(zip(directions, row.displacement))}
    return {
        "point": row.point, **values, "quantity": row.judged.quantity, "velocity_zone": row.judged.velocity_zone,
        "displacement_zone": row.judged.displacement_zone, "governing": row.direction, "value": row.value,
        "zone": row.zone, "limit": row.limit, "ratio": row.ratio, "verdict": row.outcome.value,
        "reason": row.verdict_text, **point_support_document(row),
    }


def limits_table(rows, units, title: str, summarised: bool = False, strict: bool = False, width: int | None = None):
    """The limit rows as a table (numbers in ``units``, each quantity's unit beside its name, never
    wrapped apart from it; ratio: the row's value/limit); ``summarised``: only the
    :data:`WORST_ROWS` largest value/limit ratios and the largest of each quantity. ``width``: the
    terminal's [cells] (None in a file or a pipe): the points' names whole where the table fits so
    (:func:`~foundation_calc.output.console.whole_if_fits`), with the units beside the quantities
    or else in the title; where it does not fit even with the names wrapped and without its frame,
    the units go into the title, each quantity's once, and the quantities stand alone."""
    from rich.markup import escape

    if summarised:
        shown = worst_rows(rows, WORST_ROWS)
        title += (f": {len(shown)} of {len(rows)} rows, the {WORST_ROWS} largest value/limit ratios and the"
                  f" largest of each quantity ({EVERY_ROW})")
        rows = shown
    labels = {row.quantity: units.label(display_quantity(row.quantity)) for row in rows}
    table = _limit_rows(rows, units, title, strict, labels)
    if width is None:
        return table
    bare = _limit_rows(rows, units, title + escape(" — " + ", ".join(f"{q} [{u}]" for q, u in labels.items())), strict)
    for candidate in (table, bare):  # the points' names whole where the table fits so
        if (whole := whole_if_fits(candidate, width, ("point",))) is not None:
            return whole
    return table if fits(frameless(table), width) else bare


def _limit_rows(rows, units, title: str, strict: bool, labels: dict | None = None):
    """The table of :func:`limits_table`: each quantity with its unit from ``labels`` (one line),
    or alone without them."""
    from rich.table import Table
    from rich.text import Text

    table = Table(title=title, title_justify="left")
    for col in ("point", "along", "quantity", "value", "limit", "ratio", "verdict"):
        table.add_column(col, justify="right" if col in ("value", "limit", "ratio") else "left")
    for row in rows:  # the unit with the quantity, so that the numbers' columns stay narrow (80 columns)
        quantity = display_quantity(row.quantity)
        named = Text(row.quantity if labels is None else f"{row.quantity} [{labels[row.quantity]}]", no_wrap=True)
        table.add_row(Text(row.point), row.direction, named,
                      fmt(units.convert(quantity, row.value)), fmt(units.convert(quantity, row.limit)),
                      f"{row.ratio:.3f}", verdict_text(row.outcome.value, strict))
    return table


def zones_table(rows, units, directions, strict: bool = False):
    """The code zone of every point in two tables that fit 80 columns: its RMS velocity in each of
    ``directions`` and its largest RMS displacement; then the deciding quantity and direction, the
    support class, the zone and the verdict."""
    from rich.table import Table
    from rich.text import Text

    first = rows[0].table
    tables = {row.table.foundation: row.table for row in rows}
    bounds = "; ".join(
        f"{kind} ({t.clause}) {', '.join(f'{n} {b:g}' for n, b in zip(BOUNDARIES, t.boundaries_mm_s))}"
        f" mm/s, {', '.join(f'{n} {b:g}' for n, b in zip(BOUNDARIES, t.displacement_boundaries_um))} µm"
        for kind, t in tables.items()
    )
    unit = units.label("velocity")
    values = Table(title=f"{first.code}, group {first.group}: RMS velocity of each point and its largest RMS displacement",
                   title_justify="left")
    for col in ("point", *(f"{d} [{unit}]" for d in directions), f"displacement [{units.label('amplitude')}]"):
        values.add_column(col.replace("[", "\\["), justify="left" if col == "point" else "right")
    zones = Table(title=f"{first.code}, group {first.group}: zones of the RMS velocity and displacement, the more"
                  f" restrictive deciding (boundaries: {bounds})", title_justify="left")
    for col in ("point", "by", "governs", "support", "zone", "fails over", "verdict"):
        zones.add_column(col, justify="right" if col == "fails over" else "left")
    for row in rows:
        shown = "velocity" if row.judged.quantity == "velocity" else "amplitude"
        values.add_row(Text(row.point), *(fmt(units.convert("velocity", v)) for v in row.velocity),
                       fmt(units.convert("amplitude", max(row.displacement))))
        zones.add_row(Text(row.point), row.judged.quantity, row.direction, row.table.foundation, row.zone,
                      units.show(shown, row.limit), verdict_text(row.outcome.value, strict))
    return values, zones


__all__ = ["ALL_POINTS_UP_TO", "EVERY_ROW", "WORST_ROWS", "code_document", "limits_document", "limits_table", "summarised",
           "zones_table"]
