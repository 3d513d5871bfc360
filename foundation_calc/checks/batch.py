"""Run every supported check on many scene files, one bad file never hiding the others.

A scene that cannot be loaded, or a check that raises a :class:`~foundation_calc.errors.FcalcError`
(an impossible design), is recorded as ``invalid`` (exit 3); any other exception inside one
scene's check is recorded as ``internal`` (exit 4, a bug) and the run goes on. The exit code of
the run is the worst of all: 4 internal > 3 invalid > 1 fail (or warn with ``strict``) > 0.
"""

from __future__ import annotations

import json
import os
from collections.abc import Callable, Iterable, Iterator, Mapping
from dataclasses import dataclass, field, replace
from pathlib import Path
from typing import Any

from foundation_calc.checks.registry import CHECKS, Finding, Reason
from foundation_calc.errors import ExitCode, FcalcError, SceneError

#: Verdicts of one check, from best to worst, and the exit code each one implies.
VERDICT_EXIT = {"pass": ExitCode.OK, "warn": ExitCode.OK, "fail": ExitCode.CHECK_FAILED,
                "invalid": ExitCode.INVALID_SCENE, "internal": ExitCode.INTERNAL}


@dataclass(frozen=True)
class CheckRun:
    """One check on one scene: a finding, or the problems that stopped it.

    ``verdict`` is ``pass``/``warn``/``fail`` from the finding, ``invalid`` for a scene that
    cannot be loaded or designed, ``internal`` for a bug. ``reason`` is in the parts of
    :data:`~foundation_calc.checks.registry.Reason`; ``problems`` are ``(field, message)``.
    """

    check: str
    verdict: str
    reason: Reason = ()
    values: Mapping[str, tuple[str, float]] = field(default_factory=dict)
    report: Any = None
    problems: tuple[tuple[str, str], ...] = ()
    details: tuple[str, ...] = ()

    def exit_code(self, strict: bool) -> ExitCode:
        if strict and self.verdict == "warn":
            return ExitCode.CHECK_FAILED
        return VERDICT_EXIT[self.verdict]


@dataclass(frozen=True)
class SceneRun:
    """All checks of one scene file. ``kind`` and ``name`` are empty and ``scene`` (the validated
    scene model) is ``None`` when it did not load; ``skipped`` marks a TOML file found in a folder
    that is no scene (no ``kind`` key, e.g. ``.taplo.toml``), which has no checks."""

    source: str
    kind: str
    name: str
    runs: tuple[CheckRun, ...]
    scene: Any = None
    skipped: bool = False
    warnings: tuple[str, ...] = ()

    def exit_code(self, strict: bool) -> ExitCode:
        return max((run.exit_code(strict) for run in self.runs), default=ExitCode.OK)

    def light(self) -> "SceneRun":
        """This run without the scene model and the checks' reports: what a summary table, the
        exit code and JUnit read, small enough to keep for ten thousand scenes."""
        return replace(self, scene=None, runs=tuple(replace(run, report=None) for run in self.runs))


def scene_files(paths: Iterable[str | Path]) -> dict[Path, bool]:
    """The scene files named by ``paths``, each with whether it was found by a folder search.

    Files are taken as given and folders searched for ``*.toml`` (but ``fcalc.toml``, the office
    defaults, which is no scene); files found in folders are
    sorted so reports are stable; a path that does not exist is kept, so that it is reported as a
    scene that cannot be read.
    """
    from foundation_calc.scenes.project import OFFICE_FILE

    found: dict[Path, bool] = {}
    for path in map(Path, paths):
        searched = (f for f in sorted(path.rglob("*.toml")) if f.name != OFFICE_FILE)  # office defaults, no scene
        for file in searched if path.is_dir() else [path]:
            found[file] = found.get(file, True) and path.is_dir()
    return found


def _error_run(check: str, exc: BaseException) -> CheckRun:
    if isinstance(exc, SceneError):
        return CheckRun(check, "invalid", ("the scene cannot be used",), problems=tuple(exc.problems))
    if isinstance(exc, FcalcError):
        return CheckRun(check, "invalid", (str(exc),), problems=(("", str(exc)),))
    text = f"{type(exc).__name__}: {exc}"
    return CheckRun(check, "internal", (f"internal error (a bug in fcalc): {text}",), problems=(("", text),))


def _finite(finding: Finding) -> Finding:
    """``finding`` itself; NaN or inf in its numbers is a bug, so it raises ``ValueError``."""
    json.dumps(list(finding.values.values()), allow_nan=False)
    return finding


def run_scene(path: str | Path, skip_non_scenes: bool = False) -> SceneRun:
    """Load one scene and run every check of its kind (``"load"`` stands for a scene that fails).

    With ``skip_non_scenes`` a TOML document without a ``kind`` key is skipped, not invalid.
    """
    from foundation_calc.scenes import parse_scene, read_toml
    from foundation_calc.scenes.project import with_office_defaults

    source = str(path)
    try:
        document = read_toml(path)
        if skip_non_scenes and "kind" not in document:
            return SceneRun(source, "", "", (), skipped=True)
        scene = parse_scene(with_office_defaults(document, path), source)
    except Exception as exc:  # noqa: BLE001 - reported per scene, see the module docstring
        if os.environ.get("FCALC_DEBUG") and not isinstance(exc, FcalcError):
            raise
        return SceneRun(source, "", "", (_error_run("load", exc),))
    return SceneRun(source, scene.kind, scene.name, run_checks(scene), scene, warnings=tuple(scene.plausibility_warnings()))


def run_checks(scene) -> tuple[CheckRun, ...]:
    """Every check of :data:`~foundation_calc.checks.registry.CHECKS` for the kind of the validated
    ``scene``, in the registry's order; a check that judges nothing in the scene is left out, and
    one that raises is recorded as ``invalid`` or ``internal`` (see the module docstring).

    ``fcalc check`` and the calculation sheet (``fcalc report``) both call this, so they judge
    the same rows."""
    runs = []
    for name, check in CHECKS[scene.kind].items():
        try:
            finding = check(scene)
            if finding is None:  # the scene gives nothing this check judges
                continue
            finding = _finite(finding)
        except Exception as exc:  # noqa: BLE001 - one check's error must not stop the others
            if os.environ.get("FCALC_DEBUG") and not isinstance(exc, FcalcError):
                raise
            runs.append(_error_run(name, exc))
            continue
        f = finding
        runs.append(CheckRun(name, f.outcome.value, f.reason, f.values, f.report, details=f.details))
    return tuple(runs)


def run_scenes(paths: Iterable[str | Path], jobs: int = 1) -> list[SceneRun]:
    """:func:`run_scene` on every file of :func:`scene_files`, in their order (:func:`iter_scenes`)."""
    return list(iter_scenes(paths, jobs))


def _unchanged(scene: SceneRun) -> SceneRun:
    return scene


def _run_and_finish(path: Path, searched: bool, finish: Callable[[SceneRun], Any]) -> Any:
    return finish(run_scene(path, searched))


def iter_scenes(paths: Iterable[str | Path], jobs: int = 1, finish: Callable[[SceneRun], Any] = _unchanged) -> Iterator[Any]:
    """``finish(run_scene(file))`` for every file of :func:`scene_files`, yielded in their order as
    they are done; files found in folders that are no scenes are skipped.

    With ``jobs`` > 1 the scenes after the first are spread over that many worker processes
    (fork); the results are the same, in the same order, as the serial run's (each scene is
    checked on its own, and errors stay per scene). ``finish`` runs in the worker: it turns a scene's run into what the
    caller keeps (e.g. :meth:`SceneRun.light` and the scene's JSON text), so that a batch of many
    scenes neither holds nor ships whole reports; it must be picklable (a module-level function or
    a ``functools.partial`` of one).
    """
    files = list(scene_files(paths).items())
    jobs = min(jobs, len(files) - 1)
    if jobs <= 1:
        for path, searched in files:
            yield finish(run_scene(path, searched))
        return
    import itertools
    import multiprocessing
    from concurrent.futures import ProcessPoolExecutor

    # the first scene is checked here: what its kind imports is then loaded once, before the fork
    yield finish(run_scene(*files[0]))
    rest = files[1:]
    chunk = max(1, min(16, len(rest) // (4 * jobs)))
    with ProcessPoolExecutor(jobs, mp_context=multiprocessing.get_context("fork")) as pool:
        paths_, searched_ = zip(*rest)
        yield from pool.map(_run_and_finish, paths_, searched_, itertools.repeat(finish), chunksize=chunk)


def exit_code(scenes: Iterable[SceneRun], strict: bool = False) -> ExitCode:
    """The worst exit code over all scenes (0 when there are none)."""
    return max((scene.exit_code(strict) for scene in scenes), default=ExitCode.OK)
