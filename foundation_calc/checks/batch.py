"""Run every supported check on many scene files, one bad file never hiding the others.

A scene that cannot be loaded, or a check that raises a :class:`~foundation_calc.errors.FcalcError`
(an impossible design), is recorded as ``invalid`` (exit 3); any other exception inside one
scene's check is recorded as ``internal`` (exit 4, a bug) and the run goes on. The exit code of
the run is the worst of all: 4 internal > 3 invalid > 1 fail (or warn with ``strict``) > 0.
"""

from __future__ import annotations

import os
import time
from collections.abc import Callable, Iterable, Iterator, Mapping
from dataclasses import dataclass, field, replace
from pathlib import Path
from typing import Any

from foundation_calc.checks.registry import CHECKS, Finding, Reason
from foundation_calc.errors import ExitCode, FcalcError, NonFiniteError, PhysicsError, SceneError

#: Verdicts of one check, from best to worst, and the exit code each one implies.
VERDICT_EXIT = {"pass": ExitCode.OK, "warn": ExitCode.OK, "fail": ExitCode.CHECK_FAILED,
                "invalid": ExitCode.INVALID_SCENE, "internal": ExitCode.INTERNAL}


@dataclass(frozen=True)
class CheckRun:
    """One check on one scene: a finding, or the problems that stopped it.

    ``verdict`` is ``pass``/``warn``/``fail`` from the finding, ``invalid`` for a scene that
    cannot be loaded or designed, ``internal`` for a bug. ``reason`` is in the parts of
    :data:`~foundation_calc.checks.registry.Reason`; ``problems`` are ``(field, message)``.
    ``seconds`` is the wall-clock time the check took [s] (JUnit's ``time``); it is no part of
    the result, so two runs of one check compare equal.
    """

    check: str
    verdict: str
    reason: Reason = ()
    values: Mapping[str, tuple[str, float]] = field(default_factory=dict)
    report: Any = None
    problems: tuple[tuple[str, str], ...] = ()
    details: tuple[str, ...] = ()
    seconds: float = field(default=0.0, compare=False)

    def exit_code(self, strict: bool) -> ExitCode:
        if strict and self.verdict == "warn":
            return ExitCode.CHECK_FAILED
        return VERDICT_EXIT[self.verdict]


@dataclass(frozen=True)
class SceneRun:
    """All checks of one scene file. ``kind`` and ``name`` are empty and ``scene`` (the validated
    scene model) is ``None`` when it did not load; ``skipped`` marks a TOML file found in a folder
    that is no scene (no ``kind`` key and no scene table, e.g. ``.taplo.toml``, or no regular
    file, e.g. a FIFO), which has no checks; ``skip_note`` says why it was skipped."""

    source: str
    kind: str
    name: str
    runs: tuple[CheckRun, ...]
    scene: Any = None
    skipped: bool = False
    warnings: tuple[str, ...] = ()
    skip_note: str = ""

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
    if isinstance(exc, PhysicsError):
        return CheckRun(check, "invalid", (str(exc),), problems=tuple(exc.problems))
    if isinstance(exc, FcalcError):
        return CheckRun(check, "invalid", (str(exc),), problems=(("", str(exc)),))
    text = f"{type(exc).__name__}: {exc}"
    return CheckRun(check, "internal", (f"internal error (a bug in fcalc): {text}",), problems=(("", text),))


def _finite(finding: Finding) -> Finding:
    """``finding`` itself; NaN or inf in its numbers raises :class:`NonFiniteError` (the scene
    cannot be computed), naming the value."""
    found = NonFiniteError.find({"values": {name: value for name, (_, value) in finding.values.items()}})
    if found is not None:
        raise found
    return finding


def _not_regular(path: str | Path) -> str:
    """What ``path`` is when it is no regular file (a FIFO, a socket, a device), else ``""``;
    only its status is read, the file is never opened (a FIFO would wait for a writer)."""
    import stat

    try:
        mode = os.stat(path).st_mode
    except (OSError, ValueError):
        return ""  # reported when it is read
    kinds = ((stat.S_ISFIFO, "a FIFO"), (stat.S_ISSOCK, "a socket"), (stat.S_ISCHR, "a device"), (stat.S_ISBLK, "a device"))
    return next((name for test, name in kinds if test(mode)), "")


def run_scene(path: str | Path, skip_non_scenes: bool = False) -> SceneRun:
    """Load one scene and run every check of its kind (``"load"`` stands for a scene that fails).

    With ``skip_non_scenes`` (a file found in a folder) a file that is not a regular file is
    skipped unopened, and a TOML document without a kind and without any scene table
    (:func:`~foundation_calc.scenes.kinds.is_scene`) is skipped, not invalid; ``skip_note``
    says why.
    """
    from foundation_calc.scenes import parse_scene, read_toml
    from foundation_calc.scenes.kinds import is_scene
    from foundation_calc.scenes.project import with_office_defaults

    source = str(path)
    if skip_non_scenes and _not_regular(path):
        return SceneRun(source, "", "", (), skipped=True, skip_note=f"{_not_regular(path)}, not a regular file: not opened")
    start = time.perf_counter()
    try:
        document = read_toml(path)
        if skip_non_scenes and not is_scene(document):
            return SceneRun(source, "", "", (), skipped=True, skip_note="TOML without a kind or a scene table, not a scene")
        scene = parse_scene(with_office_defaults(document, path), source)
    except Exception as exc:  # noqa: BLE001 - reported per scene, see the module docstring
        if os.environ.get("FCALC_DEBUG") and not isinstance(exc, FcalcError):
            raise
        return SceneRun(source, "", "", (replace(_error_run("load", exc), seconds=time.perf_counter() - start),))
    return check_scene(scene, source)


def check_scene(scene, source: str) -> SceneRun:
    """Every check of the validated ``scene`` read from ``source`` (:func:`run_checks`), with its
    plausibility warnings."""
    return SceneRun(source, scene.kind, scene.name, run_checks(scene), scene, warnings=tuple(scene.plausibility_warnings()))


def run_checks(scene) -> tuple[CheckRun, ...]:
    """Every check of :data:`~foundation_calc.checks.registry.CHECKS` for the kind of the validated
    ``scene``, in the registry's order; a check that judges nothing in the scene is left out, and
    one that raises is recorded as ``invalid`` or ``internal`` (see the module docstring).

    ``fcalc check`` and the calculation sheet (``fcalc report``) both call this, so they judge
    the same rows."""
    runs = []
    for name, check in CHECKS[scene.kind].items():
        start = time.perf_counter()
        try:
            finding = check(scene)
            if finding is None:  # the scene gives nothing this check judges
                continue
            finding = _finite(finding)
        except Exception as exc:  # noqa: BLE001 - one check's error must not stop the others
            if os.environ.get("FCALC_DEBUG") and not isinstance(exc, FcalcError):
                raise
            runs.append(replace(_error_run(name, exc), seconds=time.perf_counter() - start))
            continue
        f = finding
        runs.append(CheckRun(name, f.outcome.value, f.reason, f.values, f.report, details=f.details,
                             seconds=time.perf_counter() - start))
    return tuple(runs)


def run_scenes(paths: Iterable[str | Path], jobs: int = 1) -> list[SceneRun]:
    """:func:`run_scene` on every file of :func:`scene_files`, in their order (:func:`iter_scenes`)."""
    return list(iter_scenes(paths, jobs))


def _unchanged(scene: SceneRun) -> SceneRun:
    return scene


def _run_and_finish(task: tuple[Path, bool, Callable[[SceneRun], Any]]) -> Any:
    path, searched, finish = task
    return finish(run_scene(path, searched))


def _start_worker() -> None:
    """Set up a worker process: it leaves SIGINT to its parent (Ctrl-C reaches the whole process
    group; the parent ends the batch), dies of SIGTERM, and on Linux is sent SIGTERM when its
    parent dies, however it dies, so that no worker outlives the batch."""
    import signal

    signal.signal(signal.SIGINT, signal.SIG_IGN)
    signal.signal(signal.SIGTERM, signal.SIG_DFL)
    signal.pthread_sigmask(signal.SIG_UNBLOCK, {signal.SIGINT, signal.SIGTERM})  # blocked by the fork
    try:
        import ctypes

        ctypes.CDLL(None, use_errno=True).prctl(1, int(signal.SIGTERM))  # 1 = PR_SET_PDEATHSIG
    except (OSError, AttributeError):  # not Linux: the parent's terminate() is the only guard
        pass


def _fork_pool(jobs: int):
    """A pool of ``jobs`` forked workers (:func:`_start_worker`). SIGINT and SIGTERM wait while it
    forks: Python drops the exception of a handler that runs inside the fork's callbacks, which
    would lose the signal; they are delivered just after."""
    import multiprocessing
    import signal

    previous = signal.pthread_sigmask(signal.SIG_BLOCK, {signal.SIGINT, signal.SIGTERM})
    try:
        return multiprocessing.get_context("fork").Pool(jobs, initializer=_start_worker)
    finally:
        signal.pthread_sigmask(signal.SIG_SETMASK, previous)


def iter_scenes(paths: Iterable[str | Path], jobs: int = 1, finish: Callable[[SceneRun], Any] = _unchanged) -> Iterator[Any]:
    """``finish(run_scene(file))`` for every file of :func:`scene_files`, yielded in their order as
    they are done; files found in folders that are no scenes are skipped.

    With ``jobs`` > 1 the scenes after the first are spread over that many worker processes
    (fork); the results are the same, in the same order, as the serial run's (each scene is
    checked on its own, and errors stay per scene); when the caller stops early (an exception
    such as an interruption, or closing the generator) the workers are ended at once. ``finish`` runs in the worker: it turns a scene's run into what the
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
    # the first scene is checked here: what its kind imports is then loaded once, before the fork
    yield finish(run_scene(*files[0]))
    rest = files[1:]
    chunk = max(1, min(16, len(rest) // (4 * jobs)))
    pool = _fork_pool(jobs)
    try:
        yield from pool.imap(_run_and_finish, [(path, searched, finish) for path, searched in rest], chunksize=chunk)
    finally:
        pool.terminate()  # every result is in, or the caller stopped: no worker is left running
        pool.join()


def exit_code(scenes: Iterable[SceneRun], strict: bool = False) -> ExitCode:
    """The worst exit code over all scenes (0 when there are none)."""
    return max((scene.exit_code(strict) for scene in scenes), default=ExitCode.OK)
