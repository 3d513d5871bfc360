"""The validation record as a section of the calculation sheet (``fcalc report --validation``).

The same cases, numbers and texts as ``fcalc validate`` (:mod:`foundation_calc.output.validation`),
laid out as one table and the full references of its sources.
"""

from __future__ import annotations

from collections.abc import Sequence
from itertools import groupby

from foundation_calc.output.report.model import Paragraph, Section, table
from foundation_calc.output.validation import (
    difference_text,
    reference_text,
    scale,
    sources,
    summary,
    tolerance_text,
    value_text,
    verdict,
)
from foundation_calc.validation.record import CaseResult
from foundation_calc.references import REFERENCES

TITLE = "Validation record"


#: How the tolerances are set, said once under the table (each case's reason is in fcalc validate).
TOLERANCES = (
    "Tolerances: a printed value is compared to half a unit of its last printed digit; a closed form"
    " to the accuracy stated for it; an exact method to round-off. Relative differences and"
    " tolerances are in %."
)


def validation_section(results: Sequence[CaseResult]) -> Section:
    """The record: how the tolerances are set and the summary line, a table per example (titled
    with its source; a row per case: what and where, reference, fcalc, difference, tolerance,
    verdict), then each source in full."""
    tables, numbered = [], list(enumerate(results, 1))
    for example, group in groupby(numbered, key=lambda item: item[1].case.example):
        group = list(group)
        rows = [
            (str(i), f"{r.case.quantity}, {r.case.where}", reference_text(r), value_text(r.value, scale(r)),
             difference_text(r), tolerance_text(r), verdict(r).upper())
            for i, r in group
        ]
        header = ("#", "case", "reference", "fcalc", "difference", "tolerance", "verdict")
        tables.append(table(f"{example} [{group[0][1].case.source}]", header, rows,
                            (True, False, True, True, True, True, False)))
    references = tuple(Paragraph(f"[{key}] {REFERENCES[key]}") for key in sources(results))
    return Section(TITLE, (Paragraph(summary(results) + ". " + TOLERANCES), *tables, *references))


__all__ = ["TITLE", "TOLERANCES", "validation_section"]
