"""Report of ``fcalc runup``: rich tables and the JSON document (SI units: m, rad/s, s)."""

from __future__ import annotations

from typing import TYPE_CHECKING

from rich.markup import escape
from rich.table import Table

from foundation_calc.checks.runup import TOGETHER, RunupReport, run_title
from foundation_calc.output.console import JSON_SCHEMA_VERSION, fmt, natural_width, stdout, two_lines_for, verdict_text
from foundation_calc.units import speed_triplet

if TYPE_CHECKING:  # the solver imports scipy: not before a run is computed
    from foundation_calc.solvers.numerics.runup import RunupResult


def mode_label(mode: int, names) -> str:
    """``"2 (k0)"``: a mode's number (ascending frequency, from 1) and its name in ``names`` (the
    resonance check's: a block's dominant motion, a crank foundation's k0, p1, p2), if any."""
    return f"{mode + 1} ({names[mode]})" if names else str(mode + 1)


def _passage_document(p, result: RunupResult, points) -> dict:
    return {
        "mode": p.mode + 1,
        "mode_name": result.names[p.mode] if result.names else None,
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


def _motor_document(report: RunupReport, machine: str) -> dict | None:
    """The start-up by the motor of ``machine`` ("" the scene's [drive]), or None without it."""
    m = report.motors.get(machine)
    if m is None:
        return None
    return {
        "machine": machine or None,
        "torque": m.torque,
        "inertia": m.inertia,
        "reached": m.reached,
        "time": m.time,
        "stuck_speed": m.stuck_speed,
        "transient_points": {n: float(v) for n, v in zip(report.points, m.transient_points)},
        "sommerfeld": [
            {"mode": t.mode + 1, "mode_name": report.names[t.mode] if report.names else None, "harmonic": t.ratio, "speed": t.speed, "torque_needed": t.needed,
             "torque_available": t.available, "ratio": t.needed / t.available, "verdict": t.outcome.value}
            for t in report.torques if t.machine == machine
        ],
    }


#: What a run-up figure of a point is (tables, JSON ``displacement``).
DISPLACEMENT = "|u|: magnitude of the point's displacement vector ({}), largest over time"

#: What a run on a frequency-dependent soil is (tables; docs/runup.md, "On a frequency-dependent soil").
SOIL_NOTE = (
    "frequency-dependent soil: the modes are fcalc resonance's, each on the springs and dashpots at its own"
    " frequency; each harmonic r ω is integrated on the springs and dashpots at its own frequency r Ω as the"
    " speed changes, so a passage meets its mode where resonance puts it and the steady state is fcalc amplitudes'"
)

#: Verdict of a row, and of a run, that no limit judges.
NOT_JUDGED = "not judged"


def _verdict(report: RunupReport) -> str:
    return report.outcome.value if report.judged else NOT_JUDGED


def _directions(report: RunupReport, peaks) -> dict:
    """{point: {direction: peak [m]}}."""
    return {n: dict(zip(report.directions, map(float, row))) for n, row in zip(report.points, peaks)}


def runup_document(report: RunupReport, scene, source: str) -> dict:
    """The JSON document of ``fcalc runup`` (every number SI)."""
    return {
        "schema_version": JSON_SCHEMA_VERSION,
        "command": "runup",
        "scene": {"source": source, "kind": scene.kind, "name": scene.name},
        "speed": speed_triplet(report.omega),
        "machines": [{"name": name, "speed": speed_triplet(w)} for name, w in report.speeds],
        "displacement": DISPLACEMENT.format(", ".join(report.directions)),
        "points": list(report.points),
        "steady_points": {n: float(v) for n, v in zip(report.points, report.steady_points)},
        "steady_directions": _directions(report, report.steady_directions),
        "runs": {
            key: {
                "duration": r.duration,
                "speed": r.omega,
                "damped": r.damped,
                "natural_frequencies": [float(w) for w in r.natural],
                "mode_names": list(r.names) or None,
                "steady_amplitude": r.steady,
                "steady_points": {n: float(v) for n, v in zip(report.points, r.steady_points)},
                "transient_points": {n: float(v) for n, v in zip(report.points, r.transient_points)},
                "transient_directions": _directions(report, r.transient_directions),
                "time_step": r.response.step,
                "passages": [_passage_document(p, r, report.points) for p in r.passages],
            }
            for key, r in report.runs.items()
        },
        "motor": _motor_document(report, ""),
        "motors": {machine: _motor_document(report, machine) for machine in report.motors if machine},
        "limits": [
            {"point": row.point, "run": row.run, "value": row.value, "limit": row.limit, "ratio": row.ratio,
             "verdict": NOT_JUDGED if row.outcome is None else row.outcome.value}
            for row in report.rows
        ],
        "warnings": [*scene.plausibility_warnings(), *report.warnings],
        "verdict": _verdict(report),
    }


def _passages_tables(key: str, r: RunupResult, points) -> tuple[Table, Table]:
    """A run's passages in two tables that fit 80 columns: each passage (its mode, harmonic, speed,
    sweep rate η, damping ζ and the time of its peak), then its peaks [m] by each method."""
    title = (
        f"{run_title(key).capitalize()} in {fmt(r.duration)} s: every resonance passed"
        f" (steady amplitude at the operating speed {fmt(r.steady)} m)"
    )
    passages = Table(title=title, title_justify="left")
    for name in ("mode", "ω_n [rad/s]", "harmonic", "speed [rad/s]", "η [-]", "ζ [-]", "peak at t [s]"):
        passages.add_column(escape(name), justify="right")
    peaks = Table(title=escape(f"{run_title(key).capitalize()}: peak of each passage [m]"), title_justify="left")
    for name in ("mode", "closed form", "Lewis, undamped", "integration", "all modes", "× steady", "point"):
        peaks.add_column(escape(name), justify="left" if name == "point" else "right")
    for p in r.passages:
        mode = escape(mode_label(p.mode, r.names))
        passages.add_row(mode, fmt(p.natural), f"{p.ratio:g}ω", fmt(p.speed), fmt(p.eta, 3), fmt(p.zeta, 3),
                         fmt(p.peak_time, 4))
        peaks.add_row(mode, fmt(p.closed_form, 4), fmt(p.lewis, 4), fmt(p.integrated, 4), fmt(p.total, 4),
                      fmt(p.total / r.steady, 3) if r.steady > 0.0 else "-", escape(points[p.point]))
    return passages, peaks


def _motor_table(report: RunupReport, machine: str) -> Table:
    m = report.motors[machine]
    outcome = (
        f"reaches the operating speed at t = {fmt(m.time, 4)} s" if m.reached
        else f"sticks at Ω ≈ {fmt(m.stuck_speed, 4)} rad/s (not at the operating speed after {fmt(m.time, 4)} s)"
    )
    title = (
        f"{run_title(f'motor:{machine}' if machine else 'motor').capitalize()} (Sommerfeld): torque {fmt(m.torque, 5)} N m, shaft inertia {fmt(m.inertia, 5)} kg m²;"
        f" {outcome}"
    )
    table = Table(title=title, title_justify="left")
    for name in ("mode", "harmonic", "speed [rad/s]", "torque needed [N m]", "available [N m]", "ratio", "verdict"):
        table.add_column(escape(name), justify="right")
    for t in (t for t in report.torques if t.machine == machine):
        table.add_row(
            escape(mode_label(t.mode, report.names)), f"{t.ratio:g}ω", fmt(t.speed), fmt(t.needed, 4), fmt(t.available, 4),
            fmt(t.needed / t.available, 3), verdict_text(t.outcome.value),
        )
    return table


def print_warnings(report: RunupReport) -> None:
    """The report's warnings on stderr (also with --json, whose stdout holds only the document)."""
    from foundation_calc.output.console import stderr, warning_line

    for text in report.warnings:
        stderr().print(warning_line(text))


def print_runup_report(report: RunupReport, scene, source: str) -> None:
    """Tables for people: per run the passages, then the points against the limit."""
    out = stdout()
    out.print(f"[bold]{escape(scene.name or source)}[/]  ({escape(source)}, {scene.kind})")
    if report.speeds:
        how = "each run from rest to its speed with the others' steady peaks added" + (", then all together" if report.runs else "")
        out.print(f"Machines, {how}: " + ", ".join(
            f"{escape(name)} ω = {fmt(w, 6)} rad/s" for name, w in report.speeds))
    else:
        out.print(f"Operating speed ω = {fmt(report.omega, 6)} rad/s")
    for key, r in report.runs.items():
        if r.passages:
            passages, peaks = _passages_tables(key, r, report.points)
            if natural_width(peaks) > out.width:  # a narrow terminal: the mode whole, a point's name in two or three lines
                peaks.columns[0].no_wrap = True
                two_lines_for(peaks, -1, [report.points[p.point] for p in r.passages], out.width)
            out.print(passages, peaks)
        else:
            out.print(f"{run_title(key).capitalize()} in {fmt(r.duration)} s passes no resonance that the loads drive.")
    if any(r.passages for r in report.runs.values()):  # what the passages' columns mean
        out.print(
            "closed form: the mode alone, Faddeeva envelope with the order's force (its inertial part growing as the"
            " speed squared; ≤ +3 % for η ≤ 1e-2);"
            " integration: the same mode's motion in the time integration of the whole linear model;"
            " all modes: largest displacement of any point in the passage's window"
        )
    if report.frequency_dependent:
        out.print(SOIL_NOTE)
    for machine in report.motors:
        out.print(_motor_table(report, machine))
    limited = any(row.limit is not None for row in report.rows)  # without a limit the verdict below says why
    table = Table(title="Largest displacement during the runs", title_justify="left")
    for name in ("point", "run", "steady |u| [m]", "transient |u| [m]", *(("limit [m]", "ratio", "verdict") if limited else ())):
        table.add_column(escape(name), justify="left" if name in ("point", "run", "verdict") else "right")
    for row in report.rows:
        steady = report.steady_points[report.points.index(row.point)]
        judged = (fmt(row.limit, 4) if row.limit is not None else "none", fmt(row.ratio, 3) if row.ratio is not None else "-",
                  NOT_JUDGED if row.outcome is None else verdict_text(row.outcome.value))
        table.add_row(escape(row.point), run_title(row.run), fmt(float(steady), 4), fmt(row.value, 4),
                      *(judged if limited else ()))
    out.print(table)
    out.print(_directions_table(report))
    same = " (the steady ones are fcalc amplitudes' peaks of the same point)" if scene.kind != "platform" else ""
    out.print(DISPLACEMENT.format(", ".join(report.directions)) + f"; per direction: the largest |component|{same}")
    if report.judged:
        out.print(f"Verdict: {verdict_text(report.outcome.value)}")
    else:
        missing = "no [limits] transient_amplitude, no " + ("[machines.drive]" if scene.kind == "block_foundation" else "[drive]")
        out.print(f"Verdict: {NOT_JUDGED} ({escape(missing)})")


def _directions_table(report: RunupReport) -> Table:
    """Steady and transient peaks of every point along each direction [m]."""
    table = Table(title=escape("Peaks by direction [m]"), title_justify="left")
    table.add_column("point", justify="left")
    table.add_column("run", justify="left")
    for name in report.directions:
        table.add_column(escape(name), justify="right")
    runs = [("steady", report.steady_directions)]
    runs += [(run_title(key), r.transient_directions) for key, r in report.runs.items()]
    for k, name in enumerate(report.points):
        for title, peaks in runs:
            table.add_row(escape(name), title, *(fmt(float(v), 5) for v in peaks[k]))
    return table


__all__ = ["plot_runup", "print_runup_report", "print_warnings", "runup_document"]


#: Points of the envelope drawn per run [-].
ENVELOPE_POINTS = 2000


def _envelope(t, values, period):
    """(times, envelope) of a record: the running maximum over one ``period`` [s] (the operating
    speed's), thinned to about :data:`ENVELOPE_POINTS` points."""
    import numpy as np

    step = float(np.median(np.diff(t))) if len(t) > 1 else 1.0
    width = max(1, int(round(period / step)))
    stride = max(1, len(values) // ENVELOPE_POINTS)
    kept = np.arange(0, len(values), stride)
    if width == 1:
        return t[kept], values[kept]
    # the maximum of the trailing window of one period ending at each kept sample; before the first
    # full period the record is mirrored at its start (scipy.ndimage's "reflect"). After the pass of
    # length L, block[j] is the maximum of padded[j : j + L]; two blocks of the largest L <= width
    # cover a window: O(n log width).
    padded = np.pad(values, (width - 1, 0), mode="symmetric")
    block, length = padded.copy(), 1
    while 2 * length <= width:
        block[:-length] = np.maximum(block[:-length], block[length:])
        length *= 2
    return t[kept], np.maximum(block[kept], block[kept + width - length])


def plot_runup(report: RunupReport, path, title: str, limit: float | None) -> None:
    """The envelope of the largest displacement against time for every run, the shaft speed, the
    resonances passed marked, the steady amplitude and the limit drawn (``--plot``)."""
    import numpy as np

    from foundation_calc.output.plots import new_figure, save

    records = []
    for key, r in report.runs.items():
        speed = r.omega * (r.response.t / r.duration if r.direction > 0 else 1.0 - r.response.t / r.duration)
        records.append((run_title(key), r.response.t, r.response.magnitude, np.clip(speed, 0.0, r.omega),
                        [(p.time, p) for p in r.passages], r.steady))
    for machine, m in report.motors.items():
        marks = []
        for t in (t for t in report.torques if t.machine == machine):
            crossed = np.nonzero(m.speed >= t.speed)[0]
            if crossed.size:
                marks.append((float(m.t[crossed[0]]), t))
        records.append((run_title(f"motor:{machine}" if machine else "motor"), m.t, m.magnitude, m.speed, marks, float(report.steady_points.max())))
    fig, _ = new_figure(9.0, 1.0 + 3.0 * len(records))
    fig.clf()
    axes = fig.subplots(len(records), 1, squeeze=False)[:, 0]
    period = 2.0 * np.pi / report.omega
    keys = [*report.runs, *(f"motor:{machine}" for machine in report.motors if machine)]
    alone = {run_title(key) for key in keys if key.partition(":")[2] not in ("", TOGETHER)}  # one machine's runs
    for ax, (name, t, values, speed, marks, steady) in zip(axes, records):
        et, ev = _envelope(t, values, period)
        own = " (the machine alone; the tables add the others' steady peaks)" if name in alone else ""
        ax.plot(et, ev * 1e3, color="tab:blue", lw=1.2, label="largest displacement of any point (envelope)" + own)
        ax.axhline(steady * 1e3, color="tab:green", ls="--", lw=1, label="steady, operating speed" + own)
        if limit is not None:
            ax.axhline(limit * 1e3, color="tab:red", ls=":", lw=1.2, label="transient limit")
        for k, (when, p) in enumerate(marks):
            ax.axvline(when, color="0.6", lw=0.8)
            ax.annotate(f"mode {mode_label(p.mode, report.names)}, {p.ratio:g}ω", (when, 1.0), xycoords=("data", "axes fraction"),
                        xytext=(2, -10 - 9 * (k % 3)), textcoords="offset points", fontsize=7, color="0.3")
        twin = ax.twinx()
        twin.plot(t, speed, color="0.45", lw=0.9, ls="-.", label="shaft speed")
        twin.set_ylabel("shaft speed [rad/s]", color="0.35")
        twin.set_ylim(bottom=0.0)
        ax.set_title(name, fontsize=10, loc="left")
        ax.set_xlabel("time [s]")
        ax.set_ylabel("displacement |u| [mm]")
        ax.set_ylim(bottom=0.0, top=max(float(ev.max()) * 1e3, (limit or 0.0) * 1e3) * 1.25)
        ax.grid(alpha=0.3)
    handles = axes[0].get_legend_handles_labels()
    speed_line = twin.get_legend_handles_labels()
    fig.legend(handles[0] + speed_line[0], handles[1] + speed_line[1], loc="outside lower center", ncol=2, fontsize=8)
    fig.suptitle(title, fontsize=11)
    save(fig, path)
