"""Table, CSV, JSON and plot of ``fcalc sweep``. Resonant points (undamped only) carry no amplitude
(empty / null); a damped sweep adds each harmonic's amplitude and phase lag."""

from __future__ import annotations

import csv
import io
import math
from collections.abc import Iterable
from pathlib import Path

import numpy as np

from foundation_calc.checks.limits import QUANTITIES, RMS_QUANTITIES, display_quantity
from foundation_calc.checks.resonance_rule import bands_text
from foundation_calc.checks.sweep_status import status_text as row_status_text
from foundation_calc.output.console import (JSON_SCHEMA_VERSION, OUTCOME_STYLE, Hanging, fmt, natural_width, stdout,
                                            two_lines_for)
from foundation_calc.units import hz_from_omega, rpm_from_omega

METHOD = "corrected first approximation (Krichever & Makarov (4.11)-(4.14))"
#: The mechanism's method on a support coupling sway with rocking, where the first approximation does not apply.
COUPLED_METHOD = "averaged operator, exact forcing (the plane's one model, the support's sway-rocking coupling K_xφ, C_xφ)"
#: The mechanism's method on a frequency-dependent soil where, at some speeds, a harmonic's rocking spring
#: does not exceed P h and the first approximation steps aside.
STEPPED_ASIDE_METHOD = (f"{METHOD}; at the speeds where it does not apply (a harmonic's rocking spring K_φ(nω) <= P·h),"
                        " averaged operator, exact forcing")
LOADS_METHOD = "vendor loads, linear steady state"
STATUS_STYLE = {**OUTCOME_STYLE, "resonant": "bold magenta"}


def method(report) -> str:
    """What computed the sweep's amplitudes: the mechanism's closed form, the loads' steady state or both."""
    sources = {c.source for c in report.conditions}
    mechanism = COUPLED_METHOD if report.coupled else STEPPED_ASIDE_METHOD if report.not_applicable else METHOD
    parts = ([mechanism] if sources - {"loads"} else []) + ([LOADS_METHOD] if "loads" in sources else [])
    return " + ".join(parts)


#: The head of a sweep table's status column, its full wording (a file, a pipe, a wide terminal).
STATUS_HEAD = "status: governing resonance, margin; limits"


def status_text(row: dict, compact: bool = False, swept: str | None = None) -> str:
    """Why a point has its status (:func:`~foundation_calc.checks.sweep_status.status_text`, the
    words of every kind's sweep), from a row of the document; ``compact``: the short form of a
    narrow terminal, without the ``swept`` machine's name before its own conditions."""
    condition = row["governing_condition"]
    if compact and swept is not None and condition is not None:
        condition = condition.removeprefix(f"{swept}: ")
    return row_status_text(row["status"], condition, row["margin"], row["needed"], row["resonance_status"],
                           row["over_limits"], compact)


def print_status_table(make_table, rows: list[dict], swept: str | None = None) -> None:
    """Print a sweep's table, built by ``make_table(status head, status cells)``, each row's status
    in full where the table fits the console with no column wrapped (a file, a pipe, a wide
    terminal: one line a row), else compact (:func:`status_text`) with a legend under the table,
    so that a row takes one or two lines of an 80-column terminal (docs/sweep.md)."""
    from rich.markup import escape

    out = stdout()

    def cells(texts: list[str]) -> list[str]:
        return [f"[{STATUS_STYLE[row['status']]}]{escape(text)}[/]" for row, text in zip(rows, texts)]

    table = make_table(STATUS_HEAD, cells([status_text(row) for row in rows]))
    if natural_width(table) <= out.width:
        out.print(table)
        return
    compact = [status_text(row, True, swept) for row in rows]
    short = make_table("status", cells(compact))
    two_lines_for(short, -1, compact, out.width)
    out.print(short)
    own = f" ({escape(swept)}'s without its name)" if swept is not None else ""
    out.print(Hanging(
        "status: verdict; over u, v, a: the displacement, velocity, acceleration (_rms: their RMS) over their limits;"
        f" the governing resonance condition{own}, its margin/the margin it needs (docs/resonance-rule.md). Full"
        f" words: --json, --csv or a {natural_width(table)}-column terminal."
    ))


def verdict_cells(report):
    """The verdict of each point of every kind's sweep, one dict a point (a report with ``rows``,
    the :class:`~foundation_calc.checks.sweep_status.RowVerdicts`, and their ``conditions``, or
    ``row_conditions``, one tuple a row, where the labels change along the sweep): its governing
    condition (its own label, as resonance, amplitudes and check name it), the rule's status, its
    margin and the margin it needs, the limits exceeded and the status (SI)."""
    rows = report.rows
    over = rows.over_limit
    per_row = getattr(report, "row_conditions", None)
    for i in range(len(rows.status)):
        yield {
            "governing_condition": rows.condition(i, report.conditions if per_row is None else per_row[i]),
            "resonance_status": str(rows.resonance_status[i]),
            "margin": float(rows.margin[i]),
            "needed": float(rows.needed[i]),
            "over_limit": bool(over[i]),
            "over_limits": rows.over_limits(i),
            "status": str(rows.status[i]),
        }


def not_applicable(report) -> dict:
    """The approximations a crank sweep leaves out and why, as ``fcalc amplitudes`` words it: the
    paper's first approximation on a support coupling sway with rocking, or at the speeds where a
    harmonic's rocking spring does not exceed P h; empty otherwise."""
    return dict(getattr(report, "not_applicable", {}))


def limits_document(limits: dict, detuning) -> dict:
    """The ``limits`` part of every kind's sweep document: ``limits`` (by their ``[limits]``
    keys) and the detuning band(s), by order."""
    return {**limits, "detuning": {str(k): v for k, v in detuning.items()} if isinstance(detuning, dict) else detuning}


def _harmonics(report, i: int) -> dict | None:
    """Amplitude [m or rad] and phase lag [rad] of each harmonic at point i; None where resonant."""
    if report.resonant[i]:
        return None
    return {
        key: {"amplitude": float(abs(z[i])), "phase": float(-np.angle(z[i]))} for key, z in report.harmonics.items()
    }


def _rows(report):
    """One dict per point, SI units; amplitudes None where resonant."""
    for (i, value), verdict_of in zip(enumerate(report.values), verdict_cells(report)):
        resonant = bool(report.resonant[i])
        x, y, th = (None if resonant else float(v) for v in report.peaks[i])
        points = {
            name: None if resonant else {"horizontal": float(p[i, 0]), "vertical": float(p[i, 1])}
            for name, p in report.points.items()
        }
        yield {
            report.variable: float(value),
            "omega": float(report.omega[i]),
            "x_peak": x,
            "y_peak": y,
            "theta_peak": th,
            "harmonics": _harmonics(report, i),
            "points": points,
            "resonant": resonant,
            **verdict_of,
        }


def sweep_document(report, scene_path: str, name: str, warnings: Iterable[str] = ()) -> dict:
    """The sweep as one JSON-ready dict (SI units: rad/s, m, rad); ``warnings``: the scene's
    plausibility warnings."""
    return {
        "schema_version": JSON_SCHEMA_VERSION,
        "command": "sweep",
        "scene": scene_path,
        "name": name,
        "method": method(report),
        **({"not_applicable": not_applicable(report)} if not_applicable(report) else {}),
        "variable": report.variable,
        "limits": limits_document({key: report.limits.get(quantity) for quantity, key in (QUANTITIES | RMS_QUANTITIES).items()},
                                  report.detuning),
        "critical_speeds": [
            {"condition": c.label, "source": c.source, "zero_order": c.zero_order, "averaged": c.averaged, "band": c.band,
             "judged": c.judged}
            for c in report.critical
        ],
        "points": list(_rows(report)),
        "warnings": list(warnings),
        "verdict": verdict(report.status),
    }


def csv_cell(value) -> str:
    """A CSV cell: ``true``/``false`` for booleans, the shortest round-trip text of a float with
    -0.0 written as 0.0, an empty cell for None.

    >>> [csv_cell(v) for v in (True, -0.0, 1e-300, None, "3ω = p1")]
    ['true', '0.0', '1e-300', '', '3ω = p1']
    """
    if value is None:
        return ""
    if isinstance(value, (bool, np.bool_)):
        return "true" if value else "false"
    if isinstance(value, float):
        return repr(value + 0.0)
    return str(value)


def csv_header(report) -> str:
    """The header line of the sweep's CSV (SI units, plus the speed in Hz and rpm)."""
    header = [report.variable if report.variable != "omega" else "omega_rad_s", "speed_hz", "speed_rpm",
              "x_peak_m", "y_peak_m", "theta_peak_rad",
              *(f"{key}_{part}" for key in report.harmonics for part in ("amplitude", "phase_rad")),
              *(f"{name}_{d}_peak_m" for name in report.points for d in ("horizontal", "vertical")),
              "resonant", "governing_condition", "margin", "needed", "resonance_status", "over_limit", "status"]
    if report.variable != "omega":
        header.insert(1, "omega_rad_s")
    return csv_text([header])


def csv_rows(report) -> str:
    """The rows of a sweep (or of one chunk of it) as CSV text; empty amplitudes where resonant."""
    lines = []
    for row in _rows(report):
        cells = [row[report.variable]]
        if report.variable != "omega":
            cells.append(row["omega"])
        cells += [hz_from_omega(row["omega"]), rpm_from_omega(row["omega"])]
        cells += [row[k] for k in ("x_peak", "y_peak", "theta_peak")]
        for key in report.harmonics:
            h = row["harmonics"]
            cells += [None, None] if h is None else [h[key]["amplitude"], h[key]["phase"]]
        for name in report.points:
            p = row["points"][name]
            cells += [None, None] if p is None else [p["horizontal"], p["vertical"]]
        cells += [row["resonant"], row["governing_condition"], row["margin"], row["needed"], row["resonance_status"],
                  row["over_limit"], row["status"]]
        lines.append([csv_cell(c) for c in cells])
    return csv_text(lines)


def csv_text(lines) -> str:
    buffer = io.StringIO()
    csv.writer(buffer, lineterminator="\n").writerows(lines)
    return buffer.getvalue()


def sweep_csv(report) -> str:
    """The sweep as CSV text: :func:`csv_header` and :func:`csv_rows`."""
    return csv_header(report) + csv_rows(report)


def verdict(statuses) -> str:
    """The verdict of a sweep (JSON ``verdict``): its worst point, a resonant point counting as a
    failure. A sweep is a picture: the exit code does not follow it.

    >>> verdict(["pass", "warn"]), verdict(["pass", "resonant"])
    ('warn', 'fail')
    """
    found = set(map(str, statuses))
    if found & {"fail", "resonant"}:
        return "fail"
    return "warn" if "warn" in found else "pass"


def print_sweep(report, scene_path: str, name: str, units) -> None:
    """The sweep as a rich table; speeds and amplitudes in the chosen display units."""
    from rich.markup import escape
    from rich.table import Table

    speed_unit, amp_unit = units.label("speed"), units.label("amplitude")
    rows = list(_rows(report))
    values = []
    for row in rows:
        cells = [] if report.variable == "omega" else [fmt(row["soil_factor"], 4)]
        cells.append(fmt(units.convert("speed", row["omega"]), 6))
        if row["resonant"]:
            cells += ["resonant"] * (3 + len(report.points))
        else:
            cells += [fmt(units.convert("amplitude", row["x_peak"]), 4), fmt(units.convert("amplitude", row["y_peak"]), 4),
                      fmt(row["theta_peak"], 4)]
            cells += [
                " / ".join(fmt(units.convert("amplitude", p[k]), 4) for k in ("horizontal", "vertical"))
                for p in row["points"].values()
            ]
        if report.damped:
            h = row["harmonics"]
            cells.append("-" if h is None else f"{math.degrees(h['x1']['phase']):.1f} / {math.degrees(h['y1']['phase']):.1f}")
        values.append(cells)

    def make_table(status_head: str, statuses: list[str]) -> Table:
        table = Table(title=f"{escape(name or scene_path)} — {method(report)}", title_justify="left")
        if report.variable == "soil_factor":
            table.add_column("soil factor (c_z, c_x, c_phi)", justify="right")
        table.add_column(escape(f"speed [{speed_unit}]"), justify="right")
        for dof, unit in (("x", amp_unit), ("y", amp_unit), ("θ", "rad")):
            table.add_column(escape(f"{dof} peak [{unit}]"), justify="right")
        for point in report.points:
            table.add_column(escape(f"{point} peak h/v [{amp_unit}]"), justify="right")
        if report.damped:
            table.add_column(escape("phase lag x1 / y1 [°]"), justify="right")
        table.add_column(status_head)
        for cells, status in zip(values, statuses):
            table.add_row(*cells, status)
        return table

    print_status_table(make_table, rows)
    _print_footer(report, units)


def _print_footer(report, units) -> None:
    """The critical speeds inside the sweep and the limits, under the rows or the summary."""
    from rich.markup import escape
    from rich.table import Table

    out = stdout()
    speed_unit = units.label("speed")
    for key, why in not_applicable(report).items():
        out.print(Hanging(f"{key.replace('_', ' ')}: {escape(why)}"))
    if report.critical:
        crit = Table(title="Critical speeds inside the sweep (zero-order / averaged-inertia operator)", title_justify="left")
        for col in ("condition", "source", "judged", f"zero-order [{speed_unit}]", f"averaged [{speed_unit}]"):
            crit.add_column(escape(col), justify="left" if col in ("condition", "source", "judged") else "right")
        for c in report.critical:
            crit.add_row(c.label, c.source, "yes" if c.judged else "no (information)",
                         fmt(units.convert("speed", c.zero_order), 6), fmt(units.convert("speed", c.averaged), 6))
        out.print(crit)
    limits = "; ".join(f"{q} {units.show(display_quantity(q), v)}" for q, v in report.limits.items()) or "none"
    out.print(Hanging(
        f"limits (x, y of C and of every point): {limits}; \\[limits] detuning = {bands_text(report.detuning)}"
        " (docs/resonance-rule.md)"
    ))


def print_sweep_summary(count: int, statuses: dict, report, csv_path: str, units) -> None:
    """What a long sweep written to CSV prints instead of its rows: how many points, their
    statuses, the critical speeds inside the range and the limits."""
    out = stdout()
    tally = ", ".join(f"{statuses[s]} {s}" for s in STATUS_STYLE if statuses.get(s))
    from rich.markup import escape

    out.print(Hanging(f"{count} points written to {escape(csv_path)} (CSV, SI units): {tally}"))
    _print_footer(report, units)


def plotted(part):
    """What the plot of a streamed sweep keeps of one chunk: speeds, x and y peaks, resonant."""
    return part.values.copy(), part.peaks[:, :2].copy(), part.resonant.copy()


def joined_plot(first, kept):
    """A report to plot from the first chunk and the :func:`plotted` parts of every chunk (only
    ``values``, ``peaks`` and ``resonant`` span the whole sweep)."""
    from dataclasses import replace

    values, peaks, resonant = (np.concatenate(parts) for parts in zip(*kept))
    return replace(first, values=values, peaks=peaks, resonant=resonant)


def operating(scene, variable: str) -> float:
    """Where a crank scene's sweep marks the scene itself: its speed [rad/s] on a speed sweep, the
    factor 1 on a soil sweep."""
    return scene.speed.omega_rad_s if variable == "omega" else 1.0


def plot_sweep(report, path: str | Path, units, name: str, operating: float) -> None:
    """x, y peaks of C against the swept variable (log scale), the amplitude limit, and, as on the
    calculation sheet, the operating speed (or the scene's soil, factor 1) and the detuning band
    of each critical speed inside the range (:func:`~foundation_calc.output.plots.mark_resonances`).
    ``operating``: the scene's speed [rad/s] for a speed sweep."""
    from foundation_calc.output.plots import mark_resonances, new_figure, save, title

    fig, ax = new_figure()
    speed = report.variable == "omega"
    if speed:
        xs = np.asarray(units.convert("speed", np.asarray(report.values)), dtype=float)
        ax.set_xlabel(f"speed [{units.label('speed')}]")
    else:
        xs = np.asarray(report.values, dtype=float)
        ax.set_xlabel("factor on the soil coefficients c_z, c_x, c_phi [-]")
    ok = ~np.asarray(report.resonant, dtype=bool)
    marker = "o" if len(xs) == 1 else None
    for i, dof in enumerate(("x", "y")):
        amps = np.where(ok, np.asarray(units.convert("amplitude", report.peaks[:, i]), dtype=float), np.nan)
        ax.semilogy(xs, amps, label=f"{dof} peak of C", marker=marker)
    if report.amplitude_limit is not None:
        ax.axhline(units.convert("amplitude", report.amplitude_limit), color="red", linestyle="--", label="amplitude limit")
    marks = [(units.convert("speed", c.zero_order), c.label, c.source, c.band) for c in report.critical] if speed else []
    lo, hi = float(xs.min()), float(xs.max())
    if hi == lo:  # one point: show a tenth either side
        lo, hi = 0.9 * lo, 1.1 * hi
    mark_resonances(ax, marks, units.convert("speed", operating) if speed else 1.0, lo, hi,
                    "operating speed" if speed else "the scene's soil (factor 1)")
    ax.set_ylabel(f"peak displacement [{units.label('amplitude')}]")
    title(ax, f"{name}: {method(report)}\nshaded: the detuning band of each judged resonance ([limits] detuning ="
          f" {bands_text(report.detuning)}); red: the paper's, orange: others judged, grey: not judged")
    ax.grid(True, which="both", alpha=0.3)
    ax.legend(fontsize=8)
    save(fig, path)


__all__ = [
    "csv_header",
    "csv_cell",
    "csv_rows",
    "csv_text",
    "joined_plot",
    "limits_document",
    "not_applicable",
    "operating",
    "plot_sweep",
    "plotted",
    "print_sweep",
    "print_status_table",
    "print_sweep_summary",
    "sweep_csv",
    "sweep_document",
    "verdict",
    "verdict_cells",
]
