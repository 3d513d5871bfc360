"""``fcalc report SCENE -o FILE``: a calculation sheet to file (PDF, HTML or Markdown), by
:func:`foundation_calc.api.report.report`."""

from __future__ import annotations

import shlex
import sys
from pathlib import Path
from typing import Annotated, Optional

import typer

from foundation_calc.cli.kinds import scene_argument
from foundation_calc.cli.guard import print_warnings, reports_errors
from foundation_calc.cli.units import UnitsOpt

SceneArg = Annotated[Path, scene_argument("Scene file (TOML): block_foundation, crank_foundation or platform.")]
OutputOpt = Annotated[
    Optional[Path],
    typer.Option("-o", "--output", metavar="FILE", help="FILE.pdf, FILE.html or FILE.md; default: the scene's name with .pdf."),
]
ExactOpt = Annotated[
    bool, typer.Option("--exact", help="Crank scenes: also solve the exact equations and state the closed forms' errors"
                       " (a block's sheet always states how exact its numbers are).")
]
ValidationOpt = Annotated[
    bool, typer.Option("--validation", help="Append the validation record (the cases of fcalc validate) to the sheet.")
]


def command_line() -> str:
    """The command that is running, as a user would type it."""
    return shlex.join(["fcalc", *sys.argv[1:]])


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
    from foundation_calc.api.report import report

    result = report(scene, output=output, exact=exact, units=units, validation=validation, command=command_line())
    print_warnings(result.scene.warnings, str(scene))  # on the sheet too, in its summary
    for file in result.files:
        print(f"wrote {file}", file=sys.stderr)
    raise typer.Exit(result.exit_code)
