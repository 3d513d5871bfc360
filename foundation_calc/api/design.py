"""``fc.design``: the cheapest block that passes every check of ``fc.check`` (``fcalc design``)."""

from __future__ import annotations

from pathlib import Path

from foundation_calc.api.result import Result, command_result
from foundation_calc.api.scene import scene_of


def design(scene, *, vary=(), step: float | None = None, points: int | None = None, strict: bool = False,
           margin: float | None = None, write=None) -> Result:
    """Size the block: the cheapest (concrete volume) that passes every check of ``fc.check``.

    The varied dimensions run over a grid judged by the kind's vectorised evaluator (or, for a
    scene it does not take, by ``fc.check``'s path candidate by candidate), refined around the
    cheapest passing design; the designs shown are checked again by ``fc.check``'s path.

    Parameters
    ----------
    scene : Scene, path or mapping
        A ``block_foundation`` or ``crank_foundation`` scene (:func:`~foundation_calc.api.scene.load`).
    vary : iterable of str
        ``--vary``: ``"KEY=LO:HI"`` per dimension [m], e.g. ``["block.length=4:10"]``; keys
        ``block.length``, ``block.width``, ``block.height`` (a crank scene's
        ``foundation.block.*``), and the sizes the scene's support lets a design vary
        (``piles.length``, ``piles.diameter`` of a block on ``[piles]``).
    step : float, optional
        ``--step``: grid step of every range [m] (default 0.1).
    points : int, optional
        ``--points``: grid points of every range, instead of ``step``.
    strict : bool
        ``--strict``: a candidate that warns does not pass.
    margin : float, optional
        ``--margin``: a reserve M, 0 <= M < 1: every utilisation at most 1 - M.
    write : str or os.PathLike, optional
        ``--write``: write the cheapest passing design as a scene file (the scene's own text with
        the varied keys changed); a scene given as a file only.

    Returns
    -------
    Result
        ``to_dict()`` is the document of ``fcalc design --json`` (its ``grid.seconds``, and the
        evaluator's measured cost when it names one, are the run's own); ``exit_code`` 0 when a
        design passes, 1 when none does (or the scene fails an office rule that no dimension
        changes: then ``to_dict()`` is empty and ``report`` the failing rules), 4 when the
        re-check disagrees with the search (a bug). ``report`` is the sizing.

    Raises
    ------
    SceneError
        An invalid scene, or a scene of another kind.
    PhysicsError
        A block on a support no design sizes a block on (``[[isolators]]``; field ``isolators``).
    UsageError
        A bad range or option.
    """
    from foundation_calc.checks.design.apply import VaryError, given_dimensions, variable
    from foundation_calc.checks.design.grid import grid, parse_range
    from foundation_calc.checks.design.supported import refuse_unsized
    from foundation_calc.errors import UsageError
    from foundation_calc.scenes.unit_strings import with_unit_strings_converted

    _options(write, step, points, margin)
    loaded = scene_of(scene, ("block_foundation", "crank_foundation"))
    if write is not None and loaded.path is None:
        raise UsageError("writes the design into the scene's own file: give the scene as a file", "'--write'")
    document = with_unit_strings_converted(loaded.kind, loaded.document, loaded.source)[0]  # numbers to vary, not "6000 mm"
    refuse_unsized(loaded.model.support())
    failed = _failed_requirements(loaded.model)
    if failed:
        return Result("design", {}, 1, "fail", loaded, failed)
    try:
        given = given_dimensions(document)
        ranges = [parse_range(text) for text in vary]
        for found in ranges:
            variable(loaded.kind, found.key, given)  # a key this scene has not (a support's size): refused here
        evaluate, evaluator, maximum, refine = _evaluator(loaded.kind, loaded.model, document, loaded.source, given)
        searched_grid = grid(loaded.kind, ranges, step, points, maximum, evaluator)
    except VaryError as exc:
        raise UsageError(str(exc), "'--vary'") from None
    sizing = _size(loaded, document, searched_grid, (evaluate, evaluator, refine), given, (strict, margin))
    if write is not None and sizing.found.found:
        sizing = _write(loaded, Path(write), sizing)
    from foundation_calc.output.design import design_document

    code = 4 if sizing.disagreements else 0 if sizing.found.found else 1
    return command_result("design", design_document(sizing), code, loaded, sizing)


def _options(write, step: float | None, points: int | None, margin: float | None) -> None:
    from foundation_calc.api.options import writable_path
    from foundation_calc.errors import UsageError

    if margin is not None and not 0.0 <= margin < 1.0:
        raise UsageError(f"the reserve must be 0 <= M < 1 (a fraction of every limit; got {margin:g})", "'--margin'")
    if step is not None and points is not None:
        raise UsageError("give --step or --points, not both", "'--step' / '--points'")
    if step is not None and not step > 0:
        raise UsageError(f"the grid step must be > 0 m (got {step:g})", "'--step'")
    if points is not None and points < 2:
        raise UsageError(f"a range needs at least 2 points (got {points})", "'--points'")
    if write is not None:
        writable_path(Path(write), "--write")


def _failed_requirements(loaded) -> list:
    """The office rules (fcalc.toml ``[require]``) the scene fails: no dimension changes them, so
    every candidate would fail them."""
    from foundation_calc.checks.outcomes import Outcome
    from foundation_calc.checks.requirements import requirement_rows

    return [r for r in requirement_rows(loaded) if r.outcome is Outcome.FAIL]


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


def _size(loaded, document, searched_grid, judge, given, rule: tuple[bool, float | None]):
    """Search with ``judge`` (evaluate, its name, refinement factor) by ``rule`` (strict, the
    reserve), the checks it defers confirmed by fcalc check's path; then re-check the best and the
    shown Pareto designs (or the closest one), and leave out the Pareto designs that fail a
    deferred check there (or its reserve)."""
    import dataclasses
    import functools

    import numpy as np

    from foundation_calc.checks.design import reference
    from foundation_calc.checks.design.apply import volumes
    from foundation_calc.checks.design.recheck import recheck
    from foundation_calc.checks.design.search import CHUNK, search, thinned
    from foundation_calc.output.design import PARETO_SHOWN, Sizing

    evaluate, evaluator, refine = judge
    strict, margin = rule
    confirm = functools.partial(reference.evaluate, document, source=loaded.source)
    found = search(searched_grid, evaluate, given, strict, refine=refine, confirm=confirm, margin=margin,
                   volume=volumes(loaded.model, given))
    if found.found:
        pareto = thinned(found.pareto, PARETO_SHOWN)
        designs = pareto if pareto.volume[0] == found.best.volume[0] else found.best.joined(pareto)
    else:
        designs = found.closest
    batch = {k: np.asarray(v) for k, v in designs.values.items()}
    full, disagreements = recheck(document, batch, evaluate(batch), loaded.source)
    failing = 0
    if found.found and found.deferred:  # the Pareto designs the full path confirms, the best first
        keep = found.passes(full)
        keep[0] = True
        failing = int(np.count_nonzero(~keep))
        designs = designs.take(keep)
        full = dataclasses.replace(full, volume=full.volume[keep], mass=full.mass[keep],
                                   **{name: {c: a[keep] for c, a in getattr(full, name).items()}
                                      for name in ("outcome", "utilisation", "governing")})
    return Sizing(loaded.source, loaded.name, found, designs, full, tuple(disagreements), evaluator, CHUNK,
                  pareto_failing=failing)


#: What follows a key of the scene that the written design leaves out (a crank scene's mass
#: properties and base given beside [foundation.block]: computed from the block).
LEFT_OUT = "left out by fcalc design: computed from [foundation.block]"


def _write(loaded, path: Path, sizing):
    """Write the cheapest design: the user's scene file (its own text, without office defaults)
    with the values of :func:`~foundation_calc.checks.design.apply.applied_document` written into
    it (:func:`~foundation_calc.output.scene_edit.edited_scene`), after checking that fcalc check's
    path judges the edited scene as the re-check judged the design."""
    import dataclasses

    from foundation_calc.api.options import writing
    from foundation_calc.checks.design.apply import applied_document
    from foundation_calc.checks.design.grid import DECIMALS
    from foundation_calc.output.files import write_atomically
    from foundation_calc.output.scene_edit import edited_scene
    from foundation_calc.scenes.files import parse_toml, read_text
    from foundation_calc.scenes.unit_strings import kept_as_written, with_unit_strings_converted

    best = sizing.designs.design(0)
    scene, source = loaded.path, loaded.source
    text = read_text(scene)
    raw = parse_toml(text, source)
    converted = with_unit_strings_converted(raw["kind"], raw, source)[0]
    new = kept_as_written(applied_document(converted, best), converted, raw)  # "6000 mm" stays where unchanged
    edited = edited_scene(text, new, decimals=DECIMALS, note=LEFT_OUT)
    _same_verdicts(scene, source, edited.text, sizing.full)
    with writing(path, "--write"):
        write_atomically(path, edited.text)
    return dataclasses.replace(sizing, written=str(path), written_changes=edited.changes)


def _same_verdicts(scene: Path, source: str, text: str, full) -> None:
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

    written = parse_scene(with_office_defaults(parse_toml(text, source), scene), source)
    now = {run.check: OUTCOME_NAMES[judged(run)[0]] for run in run_checks(written)}
    said = {name: OUTCOME_NAMES[int(column[0])] for name, column in full.outcome.items()}
    if any(said.get(name, "pass") != now.get(name, "pass") for name in {*said, *now}):  # a check not run passes
        raise RuntimeError(f"the written design is judged {now}, the re-check judged it {said}")


