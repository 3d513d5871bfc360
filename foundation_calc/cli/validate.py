"""``fcalc validate``: fcalc against published worked examples and independent solutions."""

from __future__ import annotations

from typing import Annotated

import typer

from foundation_calc.cli.guard import reports_errors

JsonOpt = Annotated[bool, typer.Option("--json", help="Print one JSON document instead of the table.")]
MarkdownOpt = Annotated[
    bool, typer.Option("--markdown", help="Print the record as Markdown (docs/validation.md).")
]


@reports_errors
def validate(json: JsonOpt = False, markdown: MarkdownOpt = False) -> None:
    """The validation record: every case's reference (a published value or an independent
    solution), its source, fcalc's value, the difference and the tolerance (half a unit of the
    printed last digit, or the stated accuracy of the method). Exit 1 if any case fails.
    """
    from foundation_calc.output import validation as out
    from foundation_calc.validation.cases import run_record

    if json and markdown:
        raise typer.BadParameter("--json and --markdown exclude each other", param_hint="--markdown")
    results = run_record()
    if json:
        from foundation_calc.output.console import print_json

        print_json(out.record_document(results))
    elif markdown:
        print(out.record_markdown(results), end="")
    else:
        out.print_record(results)
    raise typer.Exit(0 if all(r.passed for r in results) else 1)
