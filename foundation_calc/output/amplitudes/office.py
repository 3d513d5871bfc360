"""The office checks of a scene (bearing pressure, settlement, a block's eccentricity and mass
ratio; :mod:`~foundation_calc.checks.office`): their JSON rows and their table."""

from __future__ import annotations

from foundation_calc.output.console import Hanging, natural_width, stdout, two_lines_for, verdict_text
from foundation_calc.output.console import titled_table as _table


def office_rows_document(report) -> list[dict]:
    """The rows of ``report`` (a :class:`~foundation_calc.checks.amplitudes.machines.BlockReport` or an
    :class:`~foundation_calc.checks.office.OfficeReport`)."""
    return [
        {"check": o.name, "value": o.value, "limit": o.limit, "unit": o.unit, "verdict": o.outcome.value,
         "source": o.source, "text": o.text}
        for o in report.office
    ]


def office_document(report, scene, source: str) -> dict:
    """The office checks of a scene of any kind as a JSON document (``report``: its
    :class:`~foundation_calc.checks.office.OfficeReport`, :func:`~foundation_calc.checks.office.scene_office`)."""
    return {"scene": {"source": source, "kind": scene.kind, "name": scene.name}, "office": office_rows_document(report),
            "verdict": report.office_outcome.value}


def print_office(report, strict: bool = False) -> None:
    """The office checks' table, for information: ``fcalc check`` judges them. Where the table
    does not fit the console with no column wrapped (a narrow terminal), the sources leave it for
    a line under it, each named once with its checks, and a result takes one or two lines."""
    from rich.markup import escape

    out = stdout()

    def table(sources: bool):
        t = _table("Office checks, for information: fcalc check judges them",
                   ("check", "result", *(("source",) if sources else ()), "verdict"))
        for o in report.office:
            t.add_row(o.name, escape(o.text), *((escape(o.source),) if sources else ()), verdict_text(o.outcome.value, strict))
        return t

    whole = table(sources=True)
    if natural_width(whole) <= out.width:  # a file, a pipe, a wide terminal
        out.print(whole)
        return
    narrow = table(sources=False)
    two_lines_for(narrow, 1, [o.text for o in report.office], out.width)
    sources = {}
    for o in report.office:
        sources.setdefault(o.source, []).append(o.name)
    out.print(narrow, Hanging(escape("sources: " + "; ".join(f"{', '.join(names)}: {source}" for source, names in sources.items())),
                              len("sources: ")))


__all__ = ["office_document", "office_rows_document", "print_office"]
