"""``fcalc report SCENE -o FILE``: a calculation sheet to file (PDF, HTML or Markdown)."""

from __future__ import annotations

import shlex
import sys
from pathlib import Path
from typing import Annotated, Optional

import typer

from foundation_calc.cli.kinds import scene_argument
from foundation_calc.cli.guard import print_warnings, reports_errors
from foundation_calc.cli.units import UnitsOpt, display_units

SceneArg = Annotated[Path, scene_argument("Scene file (TOML): crank_foundation, platform or block_foundation.")]
OutputOpt = Annotated[
    Optional[Path],
    typer.Option("-o", "--output", metavar="FILE", help="FILE.pdf, FILE.html or FILE.md; default: the scene's name with .pdf."),
]
#: Units of a sheet's tables unless --units names others: amplitudes in mm, velocities in mm/s
#: (the vibration codes' zones are in mm/s); speeds in rad/s with Hz beside them.
SHEET_UNITS = ("mm", "mm/s")

ExactOpt = Annotated[
    bool, typer.Option("--exact", help="Crank scenes: also solve the exact equations and state the closed forms' errors.")
]
ValidationOpt = Annotated[
    bool, typer.Option("--validation", help="Append the validation record (the cases of fcalc validate) to the sheet.")
]


def command_line() -> str:
    """The command that is running, as a user would type it."""
    return shlex.join(["fcalc", *sys.argv[1:]])


def check_output(path: Path, hint: str) -> None:
    """Raise a usage error when ``path`` has no sheet format or the report extra is missing."""
    from foundation_calc.output.report import FORMATS, INSTALL_HINT, missing_packages

    if path.suffix.lower() not in FORMATS:
        raise typer.BadParameter(f"{path}: the file must end in .pdf, .html or .md", param_hint=hint)
    missing = missing_packages(path.suffix.lower())
    if missing:
        raise typer.BadParameter(f"{', '.join(missing)} not installed: {INSTALL_HINT}", param_hint=hint)


@reports_errors
def report(
    scene: SceneArg, output: OutputOpt = None, exact: ExactOpt = False, units: UnitsOpt = None, validation: ValidationOpt = False
) -> None:
    """Write a calculation sheet: title block, the verdict of every check fcalc check runs on the
    scene, inputs, derived quantities, frequencies, amplitudes or the platform design, the start-up,
    every check's rows with limit, ratio and verdict, the equations with their sources and
    corrections, plots and the accuracy statement.

    Exits as fcalc check does on the scene: 0 all pass, 1 a check fails (the sheet is written either way).
    With --validation the sheet ends with the validation record of fcalc validate; its cases show
    their own verdicts and do not change the exit code.
    """
    from foundation_calc.output.report import write_sheet
    from foundation_calc.output.report.documents import scene_sheet

    from foundation_calc.cli.outputs import writable_path, writing

    path = output if output is not None else scene.with_suffix(".pdf")
    check_output(path, "'-o'")
    writable_path(path, "-o")
    shown = display_units(units, SHEET_UNITS)
    sheet, checked = scene_sheet(scene, command_line(), shown, exact)
    print_warnings(checked.warnings, str(scene))  # on the sheet too, in its summary
    if validation:
        from dataclasses import replace

        from foundation_calc.output.report.validation import validation_section
        from foundation_calc.validation.cases import run_record

        sheet = replace(sheet, sections=(*sheet.sections, validation_section(run_record())))
    with writing(path, "-o"):
        written = write_sheet(sheet, path)
    for file in written:
        print(f"wrote {file}", file=sys.stderr)
    raise typer.Exit(int(checked.exit_code(strict=False)))
