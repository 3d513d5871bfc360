"""What every foundation's ``resonance``, ``amplitudes`` and ``check`` say beside their tables, the
same for every scene kind: the soil model's range of validity
(:mod:`~foundation_calc.checks.soil_validity`) and the support class of a vibration code
(:mod:`~foundation_calc.checks.support`), as text lines and JSON parts (SI units)."""

from __future__ import annotations


def soil_validity_line(validity) -> str:
    """One line on the soil model's validity, ``"warning: ..."`` when an a0 lies beyond the range or a
    judged frequency below a stratum's cutoff."""
    prefix = "warning: soil model" if validity.warns else "soil model"
    return f"{prefix}: {validity.text}"


def print_soil_validity(validity) -> None:
    """Print :func:`soil_validity_line` (yellow when it warns); nothing without a validity."""
    if validity is None:
        return
    from rich.text import Text

    from foundation_calc.output.console import Hanging, stdout

    stdout().print(Hanging(Text(soil_validity_line(validity), style="yellow" if validity.warns else "")))


def soil_validity_document(validity) -> dict | None:
    """The JSON part ``soil_validity``."""
    return None if validity is None else validity.document()


def support_heading() -> str:
    """The rule of the classification, as a heading."""
    from foundation_calc.checks.support import CLAUSE, RIGID_RATIO

    return (f"Support class ({CLAUSE}: rigid in a measuring direction when its lowest natural frequency is at"
            f" least {RIGID_RATIO:g} × the main excitation frequency)")


def support_lines(rows) -> list[str]:
    """The heading and the classification of the code's zone ``rows`` (each with ``point`` and
    ``support``), a line per direction and class."""
    from foundation_calc.checks.support import support_lines as lines

    found = lines({row.point: row.support for row in rows if row.support})
    return [support_heading() + ":", *(f"  {line}" for line in found)] if found else []


def print_supports(rows) -> None:
    """The support class lines (:func:`support_lines`), each wrapped at words under its own text."""
    from rich.text import Text

    from foundation_calc.output.console import Hanging, stdout

    for line in support_lines(rows):
        stdout().print(Hanging(Text(line)))


def support_document(limits, rows) -> dict:
    """The JSON keys of the support class in a ``code`` part: how it was found and the tables of
    every class used (``rows``: the zone rows, each with ``table``)."""
    from foundation_calc.checks.support import CLAUSE, DIRECTION_SHARE, RIGID_RATIO

    tables = {row.table.foundation: row.table for row in rows}
    return {
        "support_rule": {"clause": CLAUSE, "ratio": RIGID_RATIO, "direction_share": DIRECTION_SHARE,
                         "given_in_scene": limits.foundation is not None},
        "tables": {kind: {"clause": t.clause, "boundaries": dict(zip(("A/B", "B/C", "C/D"), t.boundaries)),
                          "displacement_boundaries": dict(zip(("A/B", "B/C", "C/D"), t.displacement_boundaries))}
                   for kind, t in tables.items()},
    }


def point_support_document(row) -> dict:
    """The per-point keys: the governing table's class and the class of each direction."""
    return {"foundation": row.table.foundation, "support": [c.document() for c in row.support]}


__all__ = ["point_support_document", "print_soil_validity", "print_supports", "soil_validity_document",
           "soil_validity_line", "support_document", "support_heading", "support_lines"]
