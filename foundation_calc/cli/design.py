"""``fcalc design SCENE --vary KEY=LO:HI ...``: the cheapest block that passes every check."""

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
    " block.width, block.height (a crank scene's foundation.block.*, block.* as shorthand).",
)]
StepOpt = Annotated[Optional[float], typer.Option(
    "--step", metavar="S", show_default=False, help="Grid step of every range [m] (default 0.1; ends included, so"
    " the step is at most S).",
)]
PointsOpt = Annotated[Optional[int], typer.Option(
    "--points", metavar="N", show_default=False, help="Grid points of every range, instead of --step.",
)]
StrictOpt = Annotated[bool, typer.Option("--strict", help="A candidate that warns (e.g. the mass ratio) does not pass.")]
JsonOpt = Annotated[bool, typer.Option("--json", help="Print one JSON document (SI units) instead of the tables.")]
PlotOpt = Annotated[Optional[Path], typer.Option(
    "--plot", metavar="FILE", show_default=False,
    help="Draw worst margin against volume, the Pareto set and the cheapest design (.png, .svg or .pdf); needs the plot extra.",
)]
WriteOpt = Annotated[Optional[Path], typer.Option(
    "--write", metavar="BEST.toml", show_default=False,
    help="Write the cheapest passing design as a scene file: the scene with the varied keys replaced.",
)]


def _evaluator(kind: str, scene, document, source: str, given: dict[str, float]):
    """(evaluate(batch), its name, the largest grid it takes, the refinement's factor): the kind's
    vectorised evaluator, or the reference evaluator (fcalc check's path, candidate by candidate)
    with a note on speed, refining at half the grid step rather than a fifth. A vectorised
    evaluator that does not take the scene (NotImplementedError on the scene's own block, e.g. a
    crank scene's [[loads]]) leaves it to the reference evaluator, and the name says why."""
    import functools
    import importlib

    import numpy as np

    from foundation_calc.checks.design import grid, reference
    from foundation_calc.checks.design.candidates import EVALUATORS
    from foundation_calc.checks.design.search import REFINE

    why = f"no vectorised evaluator for {kind}"
    if kind in EVALUATORS:
        evaluate = functools.partial(importlib.import_module(EVALUATORS[kind]).evaluate, scene)
        try:
            evaluate({key: np.array([value]) for key, value in given.items()})
            return evaluate, f"vectorised evaluator of {kind}", grid.MAX_CANDIDATES, REFINE
        except NotImplementedError as exc:
            why = f"the vectorised evaluator of {kind} does not take this scene ({exc})"
    import time

    evaluate = functools.partial(reference.evaluate, document, source=source)
    own = {key: np.array([value]) for key, value in given.items()}
    evaluate(own)  # imports and caches: the second call is what a candidate costs
    start = time.perf_counter()
    evaluate(own)
    cost = time.perf_counter() - start
    maximum = max(1, min(grid.MAX_REFERENCE_CANDIDATES, int(grid.MAX_REFERENCE_SECONDS / cost)))
    name = (f"{why}: each candidate through fcalc check's path, {cost * 1e3:.3g} ms on the scene's own block;"
            f" at most {maximum} candidates")
    return evaluate, name, maximum, 2


def _options(plot: Path | None, write: Path | None, step: float | None, points: int | None) -> None:
    from foundation_calc.cli.outputs import plot_path, writable_path

    if step is not None and points is not None:
        raise typer.BadParameter("give --step or --points, not both", param_hint="'--step' / '--points'")
    if step is not None and not step > 0:
        raise typer.BadParameter(f"the grid step must be > 0 m (got {step:g})", param_hint="'--step'")
    if points is not None and points < 2:
        raise typer.BadParameter(f"a range needs at least 2 points (got {points})", param_hint="'--points'")
    if plot is not None:
        plot_path(plot)
    if write is not None:
        writable_path(write, "--write")


@reports_errors
def design(
    scene: SceneArg,
    vary: VaryOpt = [],  # noqa: B006 - typer reads the default, never mutates it
    step: StepOpt = None,
    points: PointsOpt = None,
    strict: StrictOpt = False,
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
    fail. A check the evaluator defers (a run-up, integrated in time) is judged by fcalc check's
    path on the candidates that pass the others, cheapest first, until one passes (at most 20).
    The shown designs are checked again by fcalc check's own path; a disagreement on a check the
    search evaluated is reported as an internal error (exit 4). Machines and points on the block's top rise with it,
    those on an end face follow the face (README, "Sizing"). Exit 0 when a design passes, 1 when
    none does, 2 for bad options, 3 for an invalid scene.
    """
    from foundation_calc.checks.design.apply import VaryError, given_dimensions
    from foundation_calc.checks.design.grid import grid, parse_range
    from foundation_calc.scenes.loading import parse_scene, read_scene

    _options(plot, write, step, points)
    loaded = parse_scene(read_scene(scene), str(scene), expect=("block_foundation", "crank_foundation"))
    document = read_scene(scene)
    try:
        given = given_dimensions(document)
        evaluate, evaluator, maximum, refine = _evaluator(loaded.kind, loaded, document, str(scene), given)
        searched_grid = grid(loaded.kind, [parse_range(text) for text in vary], step, points, maximum, evaluator)
    except VaryError as exc:
        raise typer.BadParameter(str(exc), param_hint="'--vary'") from None
    sizing = _size(scene, loaded, document, searched_grid, (evaluate, evaluator, refine), given, strict)
    if write is not None and sizing.found.found:
        sizing = _write(scene, write, sizing)
    elif write is not None:
        from foundation_calc.output.console import stderr

        stderr().print(f"{write} not written: no candidate passes", soft_wrap=True, markup=False)
    _report(sizing, json, plot)
    if sizing.disagreements:
        raise typer.Exit(4)
    raise typer.Exit(0 if sizing.found.found else 1)


def _size(scene: Path, loaded, document, searched_grid, judge, given, strict: bool):
    """Search with ``judge`` (evaluate, its name, refinement factor), the checks it defers
    confirmed by fcalc check's path; then re-check the best and the shown Pareto designs (or the
    closest one), and leave out the Pareto designs that fail a deferred check there."""
    import dataclasses
    import functools

    import numpy as np

    from foundation_calc.checks.design import reference
    from foundation_calc.checks.design.recheck import recheck
    from foundation_calc.checks.design.search import CHUNK, passing, search, thinned
    from foundation_calc.output.design import PARETO_SHOWN, Sizing

    evaluate, evaluator, refine = judge
    confirm = functools.partial(reference.evaluate, document, source=str(scene))
    found = search(searched_grid, evaluate, given, strict, refine=refine, confirm=confirm)
    if found.found:
        pareto = thinned(found.pareto, PARETO_SHOWN)
        designs = pareto if pareto.volume[0] == found.best.volume[0] else found.best.joined(pareto)
    else:
        designs = found.closest
    batch = {k: np.asarray(v) for k, v in designs.values.items()}
    full, disagreements = recheck(document, batch, evaluate(batch), str(scene))
    failing = 0
    if found.found and found.deferred:  # the Pareto designs the full path confirms, the best first
        keep = passing(full, strict)
        keep[0] = True
        failing = int(np.count_nonzero(~keep))
        designs = designs.take(keep)
        full = dataclasses.replace(full, volume=full.volume[keep], mass=full.mass[keep],
                                   **{name: {c: a[keep] for c, a in getattr(full, name).items()}
                                      for name in ("outcome", "utilisation", "governing")})
    return Sizing(str(scene), loaded.name, found, designs, full, tuple(disagreements), evaluator, CHUNK,
                  pareto_failing=failing)


def _tidy(value):
    """``value`` (a document) with every float to 12 significant digits: 2.1, not 2.0999999999999996
    (a moved position; the difference, 1e-16 m, changes no verdict)."""
    if isinstance(value, float):
        return float(f"{value:.12g}")
    if isinstance(value, dict):
        return {k: _tidy(v) for k, v in value.items()}
    if isinstance(value, list):
        return [_tidy(v) for v in value]
    return value


def _write(scene: Path, path: Path, sizing):
    """Write the cheapest design: the user's scene file (without office defaults) with the varied
    keys replaced (:func:`~foundation_calc.checks.design.apply.applied_document`)."""
    import dataclasses

    import tomli_w

    from foundation_calc.checks.design.apply import applied_document
    from foundation_calc.cli.outputs import writing
    from foundation_calc.output.files import write_atomically
    from foundation_calc.scenes import read_toml

    best = sizing.designs.design(0)
    values = ", ".join(f"{k} = {v:.6g} m" for k, v in best.items())
    header = f"# Sized by fcalc design from {scene.name}: {values}.\n# fcalc check passes it; its other keys are the scene's.\n"
    text = header + tomli_w.dumps(_tidy(applied_document(read_toml(scene), best)))
    with writing(path, "--write"):
        write_atomically(path, text)
    return dataclasses.replace(sizing, written=str(path))


def _report(sizing, json: bool, plot: Path | None) -> None:
    from foundation_calc.output import design as out

    if plot is not None:
        from foundation_calc.cli.outputs import writing

        with writing(plot, "--plot"):
            out.plot_design(sizing, plot)
    if json:
        from foundation_calc.output.console import print_json

        print_json(out.design_document(sizing))
    else:
        out.print_design(sizing)
        if sizing.written:
            from foundation_calc.output.console import stdout

            stdout().print(f"written: {sizing.written}")
