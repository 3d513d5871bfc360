"""``fcalc check PATH...``: every check of every scene under the given files and folders."""

from __future__ import annotations

from pathlib import Path
from typing import Annotated, Optional

import typer

from foundation_calc.cli.kinds import scene_argument
from foundation_calc.cli.guard import reports_errors
from foundation_calc.cli.units import UnitsOpt

PathsArg = Annotated[
    list[Path],
    scene_argument("Scene files (TOML) or folders, searched recursively for *.toml.", metavar="PATH"),
]
JsonOpt = Annotated[bool, typer.Option("--json", help="Print one JSON document (SI units) instead of the table.")]
JunitOpt = Annotated[
    Optional[Path],
    typer.Option("--junit", metavar="FILE", help="Also write a JUnit XML report (one test case per scene and check)."),
]
ReportDirOpt = Annotated[
    Optional[Path],
    typer.Option("--report-dir", metavar="DIR", help="Also write a calculation sheet (PDF) per valid scene into DIR."),
]
StrictOpt = Annotated[bool, typer.Option("--strict", help="Treat warnings (e.g. extra resonances) as failures.")]
JobsOpt = Annotated[
    Optional[int],
    typer.Option("--jobs", "-j", min=1, help="Worker processes (default: the number of cores); 1 checks in this process."),
]
VerboseOpt = Annotated[
    bool, typer.Option("--verbose", "-v", help="Every problem of an invalid scene and every limit row in the table.")
]


def _report_problems(scenes) -> None:
    """Every scene that could not be checked, on stderr, as the single-scene commands print it: a
    problem that makes several checks invalid (a block that tips over stops the resonance and the
    amplitudes alike) once."""
    from foundation_calc.cli.guard import print_warnings, report_error, report_internal
    from foundation_calc.errors import SceneError

    for scene in scenes:
        print_warnings(scene.warnings, scene.source)
        shown: set = set()
        for run in scene.runs:
            if run.verdict == "invalid":
                new = [problem for problem in run.problems if tuple(problem) not in shown]
                shown.update(tuple(problem) for problem in new)
                if new:
                    report_error(SceneError(scene.source, new))
            elif run.verdict == "internal":
                report_internal(f"{scene.source}, check {run.check}: {run.problems[0][1]}")


def _write_sheets(scenes, folder: Path, shown, fit_units: bool) -> None:
    """One PDF sheet per scene that could be checked, named after its file: ``DIR/<stem>.pdf``
    (``fit_units``: the displacement unit fitted to each scene, as ``fcalc report`` does).

    Scenes of the same name in different folders get ``<stem>-2.pdf``, ``<stem>-3.pdf``… in the
    order they were checked.
    """
    from foundation_calc.api.options import writing
    from foundation_calc.api.report import sheet_sizing
    from foundation_calc.cli.report import command_line
    from foundation_calc.errors import UsageError
    from foundation_calc.output.report import write_sheet
    from foundation_calc.output.report.documents import scene_sheet

    try:
        folder.mkdir(parents=True, exist_ok=True)
    except OSError as exc:
        raise UsageError(f"cannot create {folder}: {exc.strerror or exc}", "'--report-dir'") from None
    used: dict[str, int] = {}
    for scene in scenes:
        if scene.skipped or any(run.verdict in ("invalid", "internal") for run in scene.runs):
            continue
        path = Path(scene.source)
        used[path.stem] = used.get(path.stem, 0) + 1
        suffix = "" if used[path.stem] == 1 else f"-{used[path.stem]}"
        sheet, _ = scene_sheet(path, command_line(), shown, fit_units=fit_units, size=sheet_sizing)
        target = folder / f"{path.stem}{suffix}.pdf"
        with writing(target, "--report-dir"):
            write_sheet(sheet, target)


@reports_errors
def check(
    paths: PathsArg,
    json: JsonOpt = False,
    junit: JunitOpt = None,
    strict: StrictOpt = False,
    units: UnitsOpt = None,
    verbose: VerboseOpt = False,
    jobs: JobsOpt = None,
    report_dir: ReportDirOpt = None,
) -> None:
    """Run every check that each scene's kind supports and report them all.

    A scene that cannot be read or validated is reported (exit 3) and the others still run; a
    crash inside one scene's check is reported as an internal error (exit 4). The exit code is
    the worst over all scenes: 4 internal error, 3 invalid scene, 1 a check fails, 0 all pass.
    SIGTERM or SIGINT ends the run and its workers at once (exit 143 / 130); the JUnit report
    then says it was interrupted.
    """
    from foundation_calc.cli.guard import Interrupted, interruptible

    done: list = []  # the scenes checked so far, for the report of an interrupted run
    try:
        with interruptible() as again:
            _check(paths, json, junit, strict, units, verbose, jobs, report_dir, done, again)
    except Interrupted as stop:
        _interrupted(stop, done, junit, strict)


def _kept(items, done: list, again):
    """``items`` (light scene runs, or ``(run, JSON text)`` pairs) passed on, each scene run
    also appended to ``done``; ``again`` (of :func:`~foundation_calc.cli.guard.interruptible`)
    is called after each."""
    for item in items:
        done.append(item[0] if isinstance(item, tuple) else item)
        again()
        yield item


def _interrupted(stop, done: list, junit: Path | None, strict: bool) -> None:
    """End a run stopped by a signal: the JUnit report (when asked) holds the scenes checked and an
    ``interrupted`` error, written whole or not at all; exit 128 + the signal's number."""
    import signal

    from rich.markup import escape

    from foundation_calc.output.console import stderr

    for signum in (signal.SIGTERM, signal.SIGINT):  # the report is written in milliseconds: let it finish
        signal.signal(signum, signal.SIG_IGN)
    checked = sum(not scene.skipped for scene in done)
    note = f"by {stop.name} after {checked} scene{'s' * (checked != 1)} had been checked"
    if junit is not None:
        from foundation_calc.output import check_report

        try:
            check_report.write_junit(junit, done, strict, interrupted=f"interrupted {note}")
            note += f"; {junit} says so"
        except OSError:
            note += f"; {junit} not written"
    stderr().print(f"[bold red]interrupted[/] {escape(note)}", soft_wrap=True)
    raise typer.Exit(128 + stop.signum)


def _check(paths, json, junit, strict, units, verbose, jobs, report_dir, done: list, again) -> None:
    import functools
    import os

    from foundation_calc.api.options import display_units
    from foundation_calc.checks.batch import SceneRun, exit_code, iter_scenes
    from foundation_calc.output import check_report

    shown = display_units(units)
    if junit is not None:
        from foundation_calc.api.options import writable_path

        writable_path(junit, "--junit")
    if report_dir is not None:
        from foundation_calc.api.report import check_output

        check_output(report_dir / "sheet.pdf", "'--report-dir'")
    jobs = jobs or os.cpu_count() or 1
    if json:  # the document is written while the scenes are checked; only their verdicts are kept
        entries = iter_scenes(paths, jobs, functools.partial(check_report.json_entry, strict=strict))
        scenes = check_report.stream_check_json(_kept(entries, done, again), strict)
    else:
        scenes = list(_kept(iter_scenes(paths, jobs, SceneRun.light), done, again))
    if all(scene.skipped for scene in scenes):
        raise typer.BadParameter("no scene files (*.toml) found", param_hint="PATHS")
    _report_problems(scenes)
    if junit is not None:
        from foundation_calc.api.options import writing

        with writing(junit, "--junit"):
            check_report.write_junit(junit, scenes, strict)
    if report_dir is not None:
        from foundation_calc.api.report import SHEET_UNITS, chosen_amplitude

        _write_sheets(scenes, report_dir, display_units(units, SHEET_UNITS), not chosen_amplitude(units))
    if not json:
        check_report.print_check_table(scenes, shown, strict, verbose)
    raise typer.Exit(int(exit_code(scenes, strict)))
