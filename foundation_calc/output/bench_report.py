"""Tables, JSON and the error-against-time plot of ``fcalc bench``."""

from __future__ import annotations

from collections.abc import Callable, Iterator
from contextlib import contextmanager
from pathlib import Path

from foundation_calc.output.console import JSON_SCHEMA_VERSION, fmt, stderr, stdout


def seconds_text(seconds: float) -> str:
    """A duration with a readable unit: ``12.3 µs``, ``4.56 ms``, ``1.23 s``."""
    for scale, unit in ((1.0, "s"), (1e-3, "ms"), (1e-6, "µs")):
        if seconds >= scale:
            return f"{fmt(seconds / scale, 3)} {unit}"
    return f"{fmt(seconds / 1e-9, 3)} ns"


def bytes_text(size: int) -> str:
    """A memory size in kB or MB (10³ bytes)."""
    return f"{fmt(size / 1e6, 3)} MB" if size >= 1e6 else f"{fmt(size / 1e3, 3)} kB"


@contextmanager
def progress_bar(total: int, enabled: bool = True) -> Iterator[Callable[[str], None]]:
    """A progress bar on stderr (cleared when done); yields ``step(text)``, called before each step."""
    if not enabled:
        yield lambda text: None
        return
    from rich.progress import BarColumn, MofNCompleteColumn, Progress, TextColumn, TimeElapsedColumn

    columns = (TextColumn("{task.description}"), BarColumn(), MofNCompleteColumn(), TimeElapsedColumn())
    with Progress(*columns, console=stderr(), transient=True) as progress:
        task = progress.add_task("fcalc bench", total=total)
        started = [False]

        def step(text: str) -> None:
            if started[0]:
                progress.advance(task)
            started[0] = True
            progress.update(task, description=text)

        yield step


def _method_document(result) -> dict:
    return {
        "key": result.method.key,
        "label": result.method.label,
        "seconds": result.seconds,
        "peak_bytes": result.peak_bytes,
        "calls": result.calls,
        "error": result.error,
        "errors": result.errors,
        "failure": result.failure,
    }


def _throughput_document(t) -> dict:
    return {
        "designs": t.designs,
        "vectorised_designs_per_second": t.vectorised_per_second,
        "scalar_designs_per_second": t.scalar_per_second,
        "speedup": t.speedup,
        "vectorised_peak_bytes": t.vectorised_peak_bytes,
    }


def _truncation_document(truncation) -> dict | None:
    if truncation is None:
        return None
    rows, checks = truncation
    return {
        "error_definition": "largest difference of the peaks (x, y, z, rocking, product corners) from the"
        " converged solve, relative to the required amplitude u; estimate: the solver's own",
        "orders": [
            {
                "exciters": r.exciters,
                "order_cap": r.cap,
                "order": r.order,
                "harmonics": r.harmonics,
                "seconds": r.seconds,
                "peak_bytes": r.peak_bytes,
                "error_over_u": r.error,
                "estimate_over_u": r.estimate,
            }
            for r in rows
        ],
        "whole_check": [
            {"exciters": c.exciters, "seconds": c.seconds, "peak_bytes": c.peak_bytes, "ratio_to_one_exciter": c.ratio_to_one_exciter}
            for c in checks
        ],
    }


def _runup_document(runups) -> list | None:
    if runups is None:
        return None
    return [
        {
            "rig": r.rig,
            "duration": r.duration,
            "passages": r.passages,
            "steps": r.steps,
            "closed_form_seconds": r.closed_form_seconds,
            "integration_seconds": r.integration_seconds,
            "dop853_seconds": r.dop853_seconds,
            "closed_form_error": r.closed_form_error,
            "integrator_difference": r.integrator_difference,
        }
        for r in runups
    ]


def _runup_table(runups):
    from rich.table import Table

    table = Table(
        title="Start-up through resonance: closed form against time integration, same run"
        " (error: largest passage's peak against the exponential integrator; difference: largest"
        " displacement, exponential against DOP853)",
        title_justify="left",
    )
    for name in ("rig", "passages", "closed form, all modes", "exponential integrator", "steps", "DOP853",
                 "closed-form error", "integrator difference"):
        table.add_column(name, justify="left" if name == "rig" else "right")
    for r in runups:
        table.add_row(
            r.rig, str(r.passages), seconds_text(r.closed_form_seconds), seconds_text(r.integration_seconds),
            str(r.steps), seconds_text(r.dop853_seconds), f"{r.closed_form_error:.1e}", f"{r.integrator_difference:.1e}",
        )
    return table


def _batch_document(batch) -> dict | None:
    if batch is None:
        return None
    from dataclasses import asdict

    rows = {"one": batch.one, "many": batch.many, "many_two_jobs": batch.many_two_jobs, "large": batch.large}
    return {
        **{key: None if row is None else asdict(row) for key, row in rows.items()},
        "marginal_seconds_per_platform_scene": batch.marginal_seconds,
        "marginal_cpu_seconds_per_platform_scene": batch.marginal_cpu_seconds,
        "ratio_many_to_one": batch.many_over_one,
        "cpu_ratio_many_to_one": batch.cpu_many_over_one,
        "ratio_many_two_jobs_to_one": batch.many_two_jobs_over_one,
        "speedup_two_jobs": batch.jobs_speedup,
    }


def bench_document(scenes, platforms, throughput, startup, truncation=None, batch=None, runups=None) -> dict:
    """The whole benchmark as one JSON-ready dict (seconds, bytes, relative errors)."""
    return {
        "schema_version": JSON_SCHEMA_VERSION,
        "error_definition": "largest relative error of the x, y, θ peak amplitudes against the"
        " converged harmonic balance of the exact equations",
        "scenes": [
            {
                "scene": s.scene,
                "name": s.name,
                "reference_peaks": s.reference_peaks,
                "reference_failure": s.reference_failure,
                "methods": [_method_document(r) for r in s.results],
            }
            for s in scenes
        ],
        "platform_scenes": [
            {
                "scene": p.scene,
                "name": p.name,
                "design_seconds": p.design_seconds,
                "verification_seconds": p.verification_seconds,
                "rotation_residual": p.rotation_residual,
                "rocking_percent_of_u": p.rocking_percent,
                "failure": p.failure,
            }
            for p in platforms
        ],
        "platform_harmonic_balance": _truncation_document(truncation),
        "runup": _runup_document(runups),
        "throughput": None if throughput is None else {k: _throughput_document(t) for k, t in throughput.items()},
        "startup": None
        if startup is None
        else [
            {
                "label": row.label,
                "seconds": row.seconds,
                "ratio_to_import_floor": row.ratio_to_import_floor,
                "ratio_to_framework_floor": row.ratio_to_framework_floor,
                "cpu_seconds": row.cpu_seconds,
                "cpu_ratio_to_framework_floor": row.cpu_ratio_to_framework_floor,
            }
            for row in startup
        ],
        "batch": _batch_document(batch),
    }


def _scene_table(s):
    from rich.markup import escape
    from rich.table import Table

    table = Table(title=f"{escape(s.name or s.scene)} — {escape(s.scene)}", title_justify="left")
    table.add_column("method")
    table.add_column("time per evaluation", justify="right")
    table.add_column("peak memory", justify="right")
    table.add_column("largest peak error (x, y, θ)", justify="right")
    for r in s.results:
        if r.failure is not None:
            table.add_row(r.method.label, "—", "—", f"[red]failed[/]: {escape(r.failure)}")
            continue
        if r.error is not None:
            error = f"{r.error:.1e}"
        else:
            error = "reference" if s.reference_failure is None else "no reference"
        table.add_row(r.method.label, seconds_text(r.seconds), bytes_text(r.peak_bytes), error)
    return table


def _platform_table(platforms):
    from rich.markup import escape
    from rich.table import Table

    table = Table(title="Platform scenes: design formulas, 6-DOF verification", title_justify="left")
    for name in ("scene", "design", "6-DOF verification", "rotation residual", "rocking"):
        table.add_column(name, justify="left" if name == "scene" else "right")
    for p in platforms:
        if p.failure is not None:
            table.add_row(escape(Path(p.scene).name), "—", "—", f"[red]failed[/]: {escape(p.failure)}", "—")
        else:
            table.add_row(
                escape(Path(p.scene).name),
                seconds_text(p.design_seconds),
                seconds_text(p.verification_seconds),
                f"{p.rotation_residual:.1e} rad",
                f"{p.rocking_percent:.1e} % of u",
            )
    return table


def _truncation_tables(truncation):
    from rich.table import Table

    rows, checks = truncation
    orders = Table(
        title="Platform harmonic balance: time and error against the truncation order K (error in units of u)",
        title_justify="left",
    )
    for name in ("exciters", "K cap", "K", "harmonics", "time", "peak memory", "error", "estimate"):
        orders.add_column(name, justify="right")
    for r in rows:
        orders.add_row(
            str(r.exciters),
            "converged" if r.cap is None else str(r.cap),
            str(r.order),
            str(r.harmonics),
            seconds_text(r.seconds),
            bytes_text(r.peak_bytes),
            "reference" if r.error is None else f"{r.error:.1e}",
            f"{r.estimate:.1e}",
        )
    whole = Table(title="Whole platform check (6-DOF verification and 28 tolerance variants)", title_justify="left")
    for name in ("exciters", "time", "peak memory", "× one exciter"):
        whole.add_column(name, justify="right")
    for c in checks:
        whole.add_row(str(c.exciters), seconds_text(c.seconds), bytes_text(c.peak_bytes), f"{c.ratio_to_one_exciter:.2f}")
    return orders, whole


def _batch_tables(batch):
    """The batch rows and the ratios measured between them."""
    from rich.table import Table
    from rich.text import Text

    rows = Table(title="Batch: fcalc check, whole processes (medians of interleaved runs)", title_justify="left")
    for name in ("scenes", "jobs", "time", "CPU time", "peak memory, largest process", "peak memory, all processes"):
        rows.add_column(name, justify="left" if name == "scenes" else "right")
    for row in (batch.one, batch.many, batch.many_two_jobs, batch.large):
        if row is not None:
            tree = "-" if row.peak_bytes_all_processes is None else bytes_text(row.peak_bytes_all_processes)
            rows.add_row(Text(row.label), str(row.jobs), seconds_text(row.seconds), seconds_text(row.cpu_seconds),
                         bytes_text(row.peak_bytes_largest_process), tree)
    n = batch.many.scenes
    ratios = Table(title="Batch: ratios measured in this run", title_justify="left")
    ratios.add_column("figure")
    ratios.add_column("value", justify="right")
    ratios.add_row(f"marginal cost of a platform scene, (t({n}) - t(1))/{n - 1}, 1 job", seconds_text(batch.marginal_seconds))
    ratios.add_row("the same in CPU time, 1 job", seconds_text(batch.marginal_cpu_seconds))
    ratios.add_row(f"t({n} scenes) / t(1 scene), 1 job", f"{batch.many_over_one:.2f}")
    ratios.add_row("the same in CPU time, 1 job", f"{batch.cpu_many_over_one:.2f}")
    ratios.add_row(f"t({n} scenes) / t(1 scene), 2 jobs", f"{batch.many_two_jobs_over_one:.2f}")
    ratios.add_row(f"t({n} scenes, 1 job) / t({n} scenes, 2 jobs)", f"{batch.jobs_speedup:.2f}")
    return rows, ratios


def print_skipped(left_out) -> None:
    """One line per scene a section could not use: (scene, reason)."""
    from rich.markup import escape

    for scene, reason in left_out:
        stdout().print(f"skipped {escape(scene)}: {escape(reason)}", soft_wrap=True)


def print_bench(scenes, platforms, throughput, startup, truncation=None, batch=None, runups=None) -> None:
    """The benchmark as rich tables on stdout."""
    from rich.table import Table

    out = stdout()
    for s in scenes:
        out.print(_scene_table(s))
        if s.reference_failure:
            out.print(f"  [yellow]reference failed[/]: {s.reference_failure}", soft_wrap=True)
        out.print()
    if platforms:
        out.print(_platform_table(platforms))
        out.print()
    if truncation is not None:
        for table in _truncation_tables(truncation):
            out.print(table)
            out.print()
    if runups:
        out.print(_runup_table(runups))
        out.print()
    if throughput:
        table = Table(title="Throughput: one vectorised call against a Python loop, same run", title_justify="left")
        for name in ("computation", "designs", "vectorised", "scalar loop", "speed-up", "peak memory (vectorised)"):
            table.add_column(name, justify="left" if name == "computation" else "right")
        labels = {"resonance_check": "resonance check (k0, p1, p2, margins)",
                  "closed_form_amplitudes": "closed-form amplitudes (first approximation), undamped",
                  "closed_form_amplitudes_damped": "the same, damped (base dashpots)",
                  "sweep_damped": "speed sweep, damped: amplitudes, peaks, margins, status"}
        for key, t in throughput.items():
            table.add_row(
                labels.get(key, key),
                f"{t.designs:.3g}",
                f"{t.vectorised_per_second:.3g} designs/s",
                f"{t.scalar_per_second:.3g} designs/s",
                f"{t.speedup:.0f}×",
                bytes_text(t.vectorised_peak_bytes),
            )
        out.print(table)
        out.print()
    if startup:
        table = Table(title="Start-up: medians of whole processes, interleaved runs", title_justify="left")
        for name in ("command", "time", "× import typer, pydantic, rich", "× framework floor", "CPU time", "CPU × framework floor"):
            table.add_column(name, justify="left" if name == "command" else "right")
        for row in startup:
            table.add_row(
                row.label, seconds_text(row.seconds), f"{row.ratio_to_import_floor:.2f}", f"{row.ratio_to_framework_floor:.2f}",
                seconds_text(row.cpu_seconds), f"{row.cpu_ratio_to_framework_floor:.2f}",
            )
        out.print(table)
        out.print("framework floor: a typer command that reads a TOML scene, validates a small pydantic model"
                  " and prints one rich table", soft_wrap=True)
        out.print()
    if batch is not None:
        for table in _batch_tables(batch):
            out.print(table)
            out.print()


def plot_bench(scenes, path: str | Path) -> None:
    """Error against time per evaluation, log-log, one marker per method and scene."""
    from foundation_calc.output.plots import new_figure, save

    fig, ax = new_figure()
    markers = "osD^v<>p*hX"
    keys = [r.method.key for r in scenes[0].results] if scenes else []
    for i, key in enumerate(keys):
        pts = [
            (r.seconds, max(r.error, 1e-17))
            for s in scenes
            for r in s.results
            if r.method.key == key and r.error is not None and r.seconds is not None
        ]
        if pts:
            label = next(r.method.label for r in scenes[0].results if r.method.key == key)
            ax.loglog(*zip(*pts), markers[i % len(markers)], label=label, alpha=0.8)
    ax.set_xlabel("time per evaluation [s]")
    ax.set_ylabel("largest relative error of the x, y, θ peaks [-]")
    ax.set_title("Crank foundation: run time against error (" + ", ".join(Path(s.scene).stem for s in scenes) + ")")
    ax.grid(True, which="both", alpha=0.3)
    ax.legend(fontsize=8)
    save(fig, path)


__all__ = ["bench_document", "bytes_text", "plot_bench", "print_bench", "progress_bar", "seconds_text"]
