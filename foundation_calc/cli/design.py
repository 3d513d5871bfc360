"""``fcalc design SCENE --vary KEY=LO:HI ...``: the cheapest block that passes every check
(:func:`foundation_calc.api.design.design`)."""

from __future__ import annotations

from pathlib import Path
from typing import Annotated, Optional

import typer

from foundation_calc.cli.guard import reports_errors
from foundation_calc.cli.kinds import scene_argument

SceneArg = Annotated[Path, scene_argument("Scene file (TOML) of kind block_foundation or crank_foundation.")]
VaryOpt = Annotated[list[str], typer.Option(
    "--vary", metavar="KEY=LO:HI", show_default=False,
    help="A dimension to vary and its range [m], e.g. block.length=4:10; repeat for each. Keys: block.length,"
    " block.width, block.height (a crank scene's foundation.block.*, block.* as shorthand), and the sizes of the"
    " scene's support (piles.length, piles.diameter on [piles]).",
)]
StepOpt = Annotated[Optional[float], typer.Option(
    "--step", metavar="S", show_default=False, help="Grid step of every range [m] (default 0.1; ends included, so"
    " the step is at most S).",
)]
PointsOpt = Annotated[Optional[int], typer.Option(
    "--points", metavar="N", show_default=False, help="Grid points of every range, instead of --step.",
)]
StrictOpt = Annotated[bool, typer.Option("--strict", help="A candidate that warns (e.g. the mass ratio) does not pass.")]
MarginOpt = Annotated[Optional[float], typer.Option(
    "--margin", metavar="M", show_default=False,
    help="Ask a reserve: a candidate passes only when every utilisation is at most 1 - M (0 <= M < 1),"
    " a warning's too.",
)]
JsonOpt = Annotated[bool, typer.Option("--json", help="Print one JSON document (SI units) instead of the tables.")]
PlotOpt = Annotated[Optional[Path], typer.Option(
    "--plot", metavar="FILE", show_default=False,
    help="Draw worst margin against volume, the Pareto set and the cheapest design (.png, .svg or .pdf); needs the plot extra.",
)]
WriteOpt = Annotated[Optional[Path], typer.Option(
    "--write", metavar="BEST.toml", show_default=False,
    help="Write the cheapest passing design as a scene file: the scene's own text with the varied keys and the"
    " positions that moved changed, its comments and layout kept.",
)]


@reports_errors
def design(
    scene: SceneArg,
    vary: VaryOpt = [],  # noqa: B006 - typer reads the default, never mutates it
    step: StepOpt = None,
    points: PointsOpt = None,
    strict: StrictOpt = False,
    margin: MarginOpt = None,
    json: JsonOpt = False,
    plot: PlotOpt = None,
    write: WriteOpt = None,
) -> None:
    """Size the block: the cheapest (concrete volume) that passes every check of fcalc check.

    The varied dimensions run over a grid, judged chunk by chunk by the kind's vectorised
    evaluator (or, for a kind or scene it does not take, such as a soil's modulus_range, by fcalc
    check's path candidate by candidate, and the output says so); the search then refines one
    grid step around the cheapest passing design at a 5 times finer step (2 times, candidate by
    candidate).
    Shows the cheapest passing design with its checks, the Pareto set of volume against worst
    margin (1 - the largest utilisation), and which check governs where the cheaper candidates
    fail. With --margin M every utilisation must be at most 1 - M; the output says when the answer
    sits within 1 % of its bound (on a limit), and which check holds it there. A check the
    evaluator defers (a run-up, integrated in time) is judged by fcalc check's path on the
    candidates that pass the others, cheapest first, until one passes (at most 20).
    The shown designs are checked again by fcalc check's own path; a disagreement on a check the
    search evaluated is reported as an internal error (exit 4). Machines and points on the block's top rise with it,
    those on an end face follow the face (docs/design.md). Exit 0 when a design passes, 1 when
    none does, 2 for bad options, 3 for an invalid scene.
    """
    from foundation_calc.api.design import design
    from foundation_calc.api.options import plot_path

    if plot is not None:
        plot_path(plot)
    result = design(scene, vary=vary, step=step, points=points, strict=strict, margin=margin, write=write)
    if not result.document:  # the scene fails an office rule
        from foundation_calc.output.console import stderr

        for r in result.report:
            stderr().print(f"error: the scene fails the office rule {r.rule} ({r.given}); no dimension changes it:"
                           " nothing searched", soft_wrap=True, markup=False)
        raise typer.Exit(result.exit_code)
    sizing = result.report
    if write is not None and not sizing.found.found:
        from foundation_calc.output.console import stderr

        stderr().print(f"{write} not written: no candidate passes", soft_wrap=True, markup=False)
    if plot is not None:
        from foundation_calc.api.options import writing
        from foundation_calc.output.design import plot_design

        with writing(plot, "--plot"):
            plot_design(sizing, plot)
    if json:
        from foundation_calc.output.console import print_json

        print_json(result.document)
    else:
        from foundation_calc.output.design import print_design, print_written

        print_design(sizing)
        if sizing.written:
            print_written(sizing)
    raise typer.Exit(result.exit_code)
