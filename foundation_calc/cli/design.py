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


def _options(plot: Path | None, write: Path | None, step: float | None, points: int | None, margin: float | None) -> None:
    from foundation_calc.cli.outputs import plot_path, writable_path

    if margin is not None and not 0.0 <= margin < 1.0:
        raise typer.BadParameter(f"the reserve must be 0 <= M < 1 (a fraction of every limit; got {margin:g})",
                                 param_hint="'--margin'")
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
    from foundation_calc.checks.design.apply import VaryError, given_dimensions
    from foundation_calc.checks.design.grid import grid, parse_range
    from foundation_calc.scenes.loading import parse_scene, read_scene
    from foundation_calc.scenes.unit_strings import with_unit_strings_converted

    _options(plot, write, step, points, margin)
    loaded = parse_scene(read_scene(scene), str(scene), expect=("block_foundation", "crank_foundation"))
    document = with_unit_strings_converted(loaded.kind, read_scene(scene), str(scene))[0]  # numbers to vary, not "6000 mm"
    _meets_requirements(loaded)
    try:
        given = given_dimensions(document)
        evaluate, evaluator, maximum, refine = _evaluator(loaded.kind, loaded, document, str(scene), given)
        searched_grid = grid(loaded.kind, [parse_range(text) for text in vary], step, points, maximum, evaluator)
    except VaryError as exc:
        raise typer.BadParameter(str(exc), param_hint="'--vary'") from None
    sizing = _size(scene, loaded, document, searched_grid, (evaluate, evaluator, refine), given, (strict, margin))
    if write is not None and sizing.found.found:
        sizing = _write(scene, write, sizing)
    elif write is not None:
        from foundation_calc.output.console import stderr

        stderr().print(f"{write} not written: no candidate passes", soft_wrap=True, markup=False)
    _report(sizing, json, plot)
    if sizing.disagreements:
        raise typer.Exit(4)
    raise typer.Exit(0 if sizing.found.found else 1)


def _meets_requirements(loaded) -> None:
    """Exit 1 when the scene fails an office rule (fcalc.toml ``[require]``): no dimension changes
    it, so every candidate would fail it."""
    from foundation_calc.checks.outcomes import Outcome
    from foundation_calc.checks.requirements import requirement_rows

    failed = [r for r in requirement_rows(loaded) if r.outcome is Outcome.FAIL]
    if failed:
        from foundation_calc.output.console import stderr

        for r in failed:
            stderr().print(f"error: the scene fails the office rule {r.rule} ({r.given}); no dimension changes it:"
                           " nothing searched", soft_wrap=True, markup=False)
        raise typer.Exit(1)


def _size(scene: Path, loaded, document, searched_grid, judge, given, rule: tuple[bool, float | None]):
    """Search with ``judge`` (evaluate, its name, refinement factor) by ``rule`` (strict, the
    reserve), the checks it defers confirmed by fcalc check's path; then re-check the best and the
    shown Pareto designs (or the closest one), and leave out the Pareto designs that fail a
    deferred check there (or its reserve)."""
    import dataclasses
    import functools

    import numpy as np

    from foundation_calc.checks.design import reference
    from foundation_calc.checks.design.recheck import recheck
    from foundation_calc.checks.design.search import CHUNK, search, thinned
    from foundation_calc.output.design import PARETO_SHOWN, Sizing

    evaluate, evaluator, refine = judge
    strict, margin = rule
    confirm = functools.partial(reference.evaluate, document, source=str(scene))
    found = search(searched_grid, evaluate, given, strict, refine=refine, confirm=confirm, margin=margin)
    if found.found:
        pareto = thinned(found.pareto, PARETO_SHOWN)
        designs = pareto if pareto.volume[0] == found.best.volume[0] else found.best.joined(pareto)
    else:
        designs = found.closest
    batch = {k: np.asarray(v) for k, v in designs.values.items()}
    full, disagreements = recheck(document, batch, evaluate(batch), str(scene))
    failing = 0
    if found.found and found.deferred:  # the Pareto designs the full path confirms, the best first
        keep = found.passes(full)
        keep[0] = True
        failing = int(np.count_nonzero(~keep))
        designs = designs.take(keep)
        full = dataclasses.replace(full, volume=full.volume[keep], mass=full.mass[keep],
                                   **{name: {c: a[keep] for c, a in getattr(full, name).items()}
                                      for name in ("outcome", "utilisation", "governing")})
    return Sizing(str(scene), loaded.name, found, designs, full, tuple(disagreements), evaluator, CHUNK,
                  pareto_failing=failing)


#: What follows a key of the scene that the written design leaves out (a crank scene's mass
#: properties and base given beside [foundation.block]: computed from the block).
LEFT_OUT = "left out by fcalc design: computed from [foundation.block]"


def _write(scene: Path, path: Path, sizing):
    """Write the cheapest design: the user's scene file (its own text, without office defaults)
    with the values of :func:`~foundation_calc.checks.design.apply.applied_document` written into
    it (:func:`~foundation_calc.output.scene_edit.edited_scene`), after checking that fcalc check's
    path judges the edited scene as the re-check judged the design."""
    import dataclasses

    from foundation_calc.checks.design.apply import applied_document
    from foundation_calc.checks.design.grid import DECIMALS
    from foundation_calc.cli.outputs import writing
    from foundation_calc.output.files import write_atomically
    from foundation_calc.output.scene_edit import edited_scene
    from foundation_calc.scenes.files import parse_toml, read_text
    from foundation_calc.scenes.unit_strings import kept_as_written, with_unit_strings_converted

    best = sizing.designs.design(0)
    text = read_text(scene)
    raw = parse_toml(text, str(scene))
    converted = with_unit_strings_converted(raw["kind"], raw, str(scene))[0]
    new = kept_as_written(applied_document(converted, best), converted, raw)  # "6000 mm" stays where unchanged
    edited = edited_scene(text, new, decimals=DECIMALS, note=LEFT_OUT)
    _same_verdicts(scene, edited.text, sizing.full)
    with writing(path, "--write"):
        write_atomically(path, edited.text)
    return dataclasses.replace(sizing, written=str(path), written_changes=edited.changes)


def _same_verdicts(scene: Path, text: str, full) -> None:
    """Raise (a bug: exit 4) unless fcalc check's path gives each check of the edited scene
    ``text`` as it stands (read with the office defaults of ``scene``) the outcome the re-check
    gave the design (``full``, its first design): the numbers written are rounded to the grid's
    precision, and the edit is not the search's own :func:`~.apply.applied_document`."""
    from foundation_calc.checks.batch import run_checks
    from foundation_calc.checks.design.recheck import OUTCOME_NAMES
    from foundation_calc.checks.design.reference import judged
    from foundation_calc.scenes.files import parse_toml
    from foundation_calc.scenes.loading import parse_scene
    from foundation_calc.scenes.project import with_office_defaults

    written = parse_scene(with_office_defaults(parse_toml(text, str(scene)), scene), str(scene))
    now = {run.check: OUTCOME_NAMES[judged(run)[0]] for run in run_checks(written)}
    said = {name: OUTCOME_NAMES[int(column[0])] for name, column in full.outcome.items()}
    if any(said.get(name, "pass") != now.get(name, "pass") for name in {*said, *now}):  # a check not run passes
        raise RuntimeError(f"the written design is judged {now}, the re-check judged it {said}")


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
            out.print_written(sizing)
