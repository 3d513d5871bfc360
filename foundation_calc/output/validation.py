"""The validation record for people (rich table, Markdown for docs/validation.md) and scripts (JSON).

Numbers: a printed reference as the source prints it; computed values to 7 significant figures;
differences and tolerances to 2, in the case's unit, or in % for a relative case; a difference
below round-off of the quantity's scale (:data:`~foundation_calc.output.console.ROUNDOFF`) is 0.
"""

from __future__ import annotations

from collections.abc import Sequence

from foundation_calc.output.console import JSON_SCHEMA_VERSION, ROUNDOFF, column_room, stdout, verdict_text
from foundation_calc.validation.record import CaseResult, Value
from foundation_calc.references import REFERENCES


def _values(value: Value) -> tuple[float, ...]:
    return tuple(value) if isinstance(value, Sequence) else (value,)


def value_text(value: Value, scale: float = 0.0, sep: str = " / ") -> str:
    """A computed value (or row of values) to 7 significant figures, a row joined by ``sep``;
    0 for a value below round-off of ``scale``.

    >>> value_text((2.3000000000000003, 4.5)), value_text(685.9425477947023), value_text(1.3e-14, 100.0)
    ('2.3 / 4.5', '685.9425', '0')
    """
    return sep.join("0" if abs(v) < ROUNDOFF * scale else f"{v:.7g}" for v in _values(value))


def scale(result: CaseResult) -> float:
    """The size of the case's quantity: its ``scale``, else the largest |reference|."""
    if result.case.scale is not None:
        return result.case.scale
    return max(abs(v) for v in _values(result.reference))


def reference_text(result: CaseResult, sep: str = " / ") -> str:
    """The reference as printed by its source, or computed to 7 significant figures."""
    if result.case.printed is not None:
        return result.case.printed.replace(" / ", sep)
    return value_text(result.reference, sep=sep)


def difference_text(result: CaseResult) -> str:
    """fcalc - reference to 2 significant figures (in % for a relative case); 0 for round-off."""
    case, d = result.case, result.difference
    if abs(d) < ROUNDOFF * (1.0 if case.relative else scale(result)):
        return "0"
    return f"{100.0 * d:.2g} %" if case.relative else f"{d:.2g}"


def tolerance_text(result: CaseResult) -> str:
    """The tolerance, in % for a relative case."""
    t = result.case.tolerance
    return f"{100.0 * t:.2g} %" if result.case.relative else f"{t:.2g}"


def verdict(result: CaseResult) -> str:
    """``"pass"`` or ``"fail"``."""
    return "pass" if result.passed else "fail"


def summary(results: Sequence[CaseResult]) -> str:
    """E.g. ``"21 cases: 21 pass, 0 fail"``."""
    failed = sum(not r.passed for r in results)
    return f"{len(results)} cases: {len(results) - failed} pass, {failed} fail"


def sources(results: Sequence[CaseResult]) -> list[str]:
    """The keys of the sources the cases cite, sorted."""
    return sorted({r.case.source for r in results})


def print_record(results: Sequence[CaseResult]) -> None:
    """The record as a table, its cases grouped by example under the example's source, then the
    full references of the sources."""
    from rich.markup import escape
    from rich.table import Table

    table = Table(title="Validation record: fcalc against published and independent values", title_justify="left")
    for header, justify in (("#", "right"), ("case", "left"), ("reference", "right"), ("fcalc", "right"),
                            ("diff.", "right"), ("tol.", "right"), ("", "left")):
        table.add_column(header, justify=justify)
    example = None
    for i, r in enumerate(results, 1):
        c = r.case
        if c.example != example:
            if example is not None:
                table.add_section()
            example = c.example
            table.add_row("", f"[bold]{escape(c.example)}[/] \\[{c.source}]", "", "", "", "", "")
        table.add_row(str(i), f"{escape(c.quantity)}, {escape(c.where)}", reference_text(r, "\n"),
                      value_text(r.value, scale(r), "\n"), difference_text(r), tolerance_text(r), verdict_text(verdict(r)))
    out = stdout()
    if column_room(table, 1, out.width) >= CASE_WIDTH:  # the case column
        out.print(table)
    else:
        _print_cases(table.title, results)
    out.print(summary(results) + ("" if all(r.passed for r in results) else " (exit 1)"))
    out.print("\nSources:")
    for key in sources(results):
        out.print(f"  \\[{key}] {escape(REFERENCES[key])}")


#: The fewest cells of a terminal line the table leaves its cases before each case takes two lines
#: instead: its words over its numbers (:func:`_print_cases`).
CASE_WIDTH = 40


def _print_cases(title: str, results: Sequence[CaseResult]) -> None:
    """The record on a terminal too narrow for its table (80 columns): each case's number and words
    on one line, its reference, value (a row of values joined by "/"), difference, tolerance and
    verdict on the next, indented, each wrapped at words under its start; the examples as headings."""
    from rich.markup import escape

    from foundation_calc.output.console import Hanging

    out = stdout()
    out.print(title)
    example = None
    for i, r in enumerate(results, 1):
        c = r.case
        if c.example != example:
            example = c.example
            out.print(Hanging(f"[bold]{escape(c.example)}[/] \\[{c.source}]"))
        out.print(Hanging(f"{i:>3}  {escape(c.quantity)}, {escape(c.where)}", 5))
        out.print(Hanging(f"     reference {escape(reference_text(r, '/'))}, fcalc {value_text(r.value, scale(r), '/')}, diff."
                          f" {difference_text(r)}, tol. {tolerance_text(r)}: {verdict_text(verdict(r))}", 7))


def _cell(text: str) -> str:
    return text.replace("|", "\\|")


def record_markdown(results: Sequence[CaseResult]) -> str:
    """The record as a Markdown table and its references (docs/validation.md)."""
    lines = [
        "| # | case | source | reference | fcalc | difference | tolerance | why this tolerance | verdict |",
        "| --- | --- | --- | --- | --- | --- | --- | --- | --- |",
    ]
    for i, r in enumerate(results, 1):
        c = r.case
        lines.append("| " + " | ".join(_cell(t) for t in (
            str(i), f"{c.quantity}; {c.example}", f"[{c.source}] {c.where}", reference_text(r), value_text(r.value, scale(r)),
            difference_text(r), tolerance_text(r), c.basis, verdict(r).upper())) + " |")
    lines += ["", summary(results) + ".", ""]
    lines += [f"- [{key}] {REFERENCES[key]}" for key in sources(results)]
    return "\n".join(lines) + "\n"


def _number(value: Value):
    return list(_values(value)) if isinstance(value, Sequence) else value


def record_document(results: Sequence[CaseResult]) -> dict:
    """The record as one JSON document (values in each case's unit, as in ``quantity``)."""
    return {
        "schema_version": JSON_SCHEMA_VERSION,
        "command": "validate",
        "passed": all(r.passed for r in results),
        "summary": summary(results),
        "cases": [
            {
                "key": r.case.key,
                "quantity": r.case.quantity,
                "example": r.case.example,
                "source": r.case.source,
                "where": r.case.where,
                "reference": _number(r.reference),
                "printed": r.case.printed,
                "fcalc": _number(r.value),
                "difference": r.difference,
                "relative": r.case.relative,
                "tolerance": r.case.tolerance,
                "basis": r.case.basis,
                "method": r.case.method,
                "verdict": verdict(r),
            }
            for r in results
        ],
        "references": {key: REFERENCES[key] for key in sources(results)},
    }


__all__ = ["difference_text", "print_record", "record_document", "record_markdown", "reference_text",
           "scale", "sources", "summary", "tolerance_text", "value_text", "verdict"]
