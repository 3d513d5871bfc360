"""Report of ``fcalc runup``: rich tables and the JSON document (SI units: m, rad/s, s)."""

from __future__ import annotations

from rich.markup import escape
from rich.table import Table

from foundation_calc.checks.runup import RUN_TITLES, RunupReport
from foundation_calc.output.console import JSON_SCHEMA_VERSION, fmt, stdout, verdict_text
from foundation_calc.solvers.numerics.runup import RunupResult
from foundation_calc.units import speed_triplet


def _passage_document(p, result: RunupResult, points) -> dict:
    return {
        "mode": p.mode + 1,
        "natural_frequency": p.natural,
        "harmonic": p.ratio,
        "speed": p.speed,
        "time": p.time,
        "sweep_rate": p.eta,
        "damping_ratio": p.zeta,
        "point": points[p.point],
        "closed_form_peak": p.closed_form,
        "lewis_peak": p.lewis,
        "integrated_peak": p.integrated,
        "peak_time": p.peak_time,
        "total_peak": p.total,
        "ratio_to_steady": p.total / result.steady if result.steady > 0.0 else None,
        "window": list(p.window),
    }


def runup_document(report: RunupReport, scene, source: str) -> dict:
    """The JSON document of ``fcalc runup`` (every number SI)."""
    return {
        "schema_version": JSON_SCHEMA_VERSION,
        "command": "runup",
        "scene": {"source": source, "kind": scene.kind, "name": scene.name},
        "speed": speed_triplet(report.omega),
        "points": list(report.points),
        "runs": {
            key: {
                "duration": r.duration,
                "damped": r.damped,
                "natural_frequencies": [float(w) for w in r.natural],
                "steady_amplitude": r.steady,
                "steady_points": {n: float(v) for n, v in zip(report.points, r.steady_points)},
                "transient_points": {n: float(v) for n, v in zip(report.points, r.transient_points)},
                "time_step": r.response.step,
                "passages": [_passage_document(p, r, report.points) for p in r.passages],
            }
            for key, r in report.runs.items()
        },
        "limits": [
            {"point": row.point, "run": row.run, "value": row.value, "limit": row.limit, "ratio": row.ratio,
             "verdict": row.outcome.value}
            for row in report.rows
        ],
        "warnings": list(report.warnings),
        "verdict": report.outcome.value,
    }


def _passages_table(key: str, r: RunupResult, points) -> Table:
    title = (
        f"{RUN_TITLES[key].capitalize()} in {fmt(r.duration)} s: every resonance passed"
        f" (steady amplitude at the operating speed {fmt(r.steady)} m)"
    )
    table = Table(title=title, title_justify="left")
    for name in ("mode", "ω_n [rad/s]", "harmonic", "speed [rad/s]", "η [-]", "ζ [-]", "closed form [m]",
                 "Lewis, undamped [m]", "integration [m]", "at t [s]", "all modes [m]", "× steady", "point"):
        table.add_column(escape(name), justify="left" if name == "point" else "right")
    for p in r.passages:
        table.add_row(
            str(p.mode + 1), fmt(p.natural), f"{p.ratio:g}ω", fmt(p.speed), fmt(p.eta, 3), fmt(p.zeta, 3),
            fmt(p.closed_form, 4), fmt(p.lewis, 4), fmt(p.integrated, 4), fmt(p.peak_time, 4), fmt(p.total, 4),
            fmt(p.total / r.steady, 3) if r.steady > 0.0 else "-", escape(points[p.point]),
        )
    return table


def print_runup_report(report: RunupReport, scene, source: str) -> None:
    """Tables for people: per run the passages, then the points against the limit."""
    from foundation_calc.output.console import stderr

    out = stdout()
    out.print(f"[bold]{escape(scene.name or source)}[/]  ({escape(source)}, {scene.kind})")
    out.print(f"Operating speed ω = {fmt(report.omega, 6)} rad/s")
    for key, r in report.runs.items():
        if r.passages:
            out.print(_passages_table(key, r, report.points))
        else:
            out.print(f"{RUN_TITLES[key].capitalize()} in {fmt(r.duration)} s passes no resonance that the loads drive.")
    out.print(
        "closed form: the mode alone, Faddeeva envelope with the unbalance force (≤ +3 % for η ≤ 1e-2);"
        " integration: the same mode's motion in the time integration of the whole linear model;"
        " all modes: largest displacement of any point in the passage's window"
    )
    table = Table(title="Largest displacement during the runs", title_justify="left")
    for name in ("point", "run", "steady [m]", "transient [m]", "limit [m]", "ratio", "verdict"):
        table.add_column(escape(name), justify="left" if name in ("point", "run", "verdict") else "right")
    for row in report.rows:
        steady = report.runs[row.run].steady_points[report.points.index(row.point)]
        table.add_row(
            escape(row.point), RUN_TITLES[row.run], fmt(float(steady), 4), fmt(row.value, 4),
            fmt(row.limit, 4) if row.limit is not None else "none", fmt(row.ratio, 3) if row.ratio is not None else "-",
            verdict_text(row.outcome.value),
        )
    out.print(table)
    for text in report.warnings:
        stderr().print(f"[bold yellow]warning[/]: {escape(text)}", soft_wrap=True)
    out.print(f"Verdict: {verdict_text(report.outcome.value)}")


__all__ = ["print_runup_report", "runup_document"]
