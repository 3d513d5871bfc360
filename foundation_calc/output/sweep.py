"""``fcalc sweep`` of a scene of any kind: its JSON document, table and CSV
(:class:`~foundation_calc.checks.sweep.report.SweepReport`; the plot: :mod:`~foundation_calc.output.sweep_plot`).

Every kind's rows carry the same verdict cells (:func:`verdict_cells`, worded by
:func:`~foundation_calc.checks.sweep.status.status_text`), the same limits, CSV cells and verdict;
what differs by kind is data the one layout reads: a crank scene's rows the peaks of C in x, y,
θ, of its points and, damped, the harmonics, with the method that computed them; a block's the
largest peak and RMS values over G and its points in x, y, z along a machine's speed or a factor
on its soil (:data:`VALUES`). Resonant points of an undamped crank sweep carry no amplitude
(empty / null)."""

from __future__ import annotations

import csv
import io
import math

import numpy as np

from foundation_calc.checks.limits import QUANTITIES, RMS_QUANTITIES, display_quantity
from foundation_calc.checks.resonance.rule import bands_text
from foundation_calc.checks.sweep.status import status_text as row_status_text
from foundation_calc.output.console import (JSON_SCHEMA_VERSION, OUTCOME_STYLE, Hanging, fmt, natural_width, stdout,
                                            two_lines_for)
from foundation_calc.units import hz_from_omega, rpm_from_omega

#: The largest values over G and the points a block's row gives, by key: (JSON/CSV name, SI unit in the CSV).
VALUES = {"peak": ("peak", "m"), "velocity_peak": ("velocity_peak", "m_s"), "displacement_rms": ("displacement_rms", "m"),
          "velocity_rms": ("velocity_rms", "m_s"), "acceleration_peak": ("acceleration_peak", "m_s2"),
          "acceleration_rms": ("acceleration_rms", "m_s2")}

#: What a block's soil sweep's factor scales, for titles and labels.
FACTORED = "factor on the soil's stiffness data"

#: The verdict cells every kind's CSV ends with, in order.
VERDICT_COLUMNS = ("governing_condition", "margin", "needed", "resonance_status", "over_limit", "status")

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
    mechanism = COUPLED_METHOD if report.setup["coupled"] else STEPPED_ASIDE_METHOD if report.setup["not_applicable"] else METHOD
    parts = ([mechanism] if sources - {"loads"} else []) + ([LOADS_METHOD] if "loads" in sources else [])
    return " + ".join(parts)


#: The head of a sweep table's status column, its full wording (a file, a pipe, a wide terminal).
STATUS_HEAD = "status: governing resonance, margin; limits"


def status_text(row: dict, compact: bool = False, swept: str | None = None) -> str:
    """Why a point has its status (:func:`~foundation_calc.checks.sweep.status.status_text`, the
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
    """The verdict of each row of every kind's sweep, one dict a row: its governing condition (its
    own label, as resonance, amplitudes and check name it), the rule's status, its margin and the
    margin it needs, the limits exceeded and the status (SI)."""
    rows = report.rows
    over = rows.over_limit
    for i in range(len(rows.status)):
        yield {
            "governing_condition": report.governing_condition(i),
            "resonance_status": str(rows.resonance_status[i]),
            "margin": float(rows.margin[i]),
            "needed": float(rows.needed[i]),
            "over_limit": bool(over[i]),
            "over_limits": rows.over_limits(i),
            "status": str(rows.status[i]),
        }


def limits_document(limits: dict, detuning) -> dict:
    """The ``limits`` part of every kind's sweep document: ``limits`` (by their ``[limits]``
    keys) and the detuning band(s), by order."""
    return {**limits, "detuning": {str(k): v for k, v in detuning.items()} if isinstance(detuning, dict) else detuning}


def _harmonics(report, i: int) -> dict | None:
    """Amplitude [m or rad] and phase lag [rad] of each harmonic of a crank scene's row i; None where resonant."""
    if report.resonant[i]:
        return None
    return {
        key: {"amplitude": float(abs(z[i])), "phase": float(-np.angle(z[i]))}
        for key, z in report.columns["harmonics"].items()
    }


def _plane_rows(report):
    """One dict per row of a crank scene's sweep, SI units; amplitudes None where resonant."""
    columns = report.columns
    for (i, value), verdict_of in zip(enumerate(report.values), verdict_cells(report)):
        resonant = bool(report.resonant[i])
        x, y, th = (None if resonant else float(v) for v in columns["peaks"][i])
        points = {
            name: None if resonant else {"horizontal": float(p[i, 0]), "vertical": float(p[i, 1])}
            for name, p in columns["points"].items()
        }
        yield {
            report.variable: float(value),
            "omega": float(columns["omega"][i]),
            "x_peak": x,
            "y_peak": y,
            "theta_peak": th,
            "harmonics": _harmonics(report, i),
            "points": points,
            "resonant": resonant,
            **verdict_of,
        }


def _value(v) -> float | None:
    """A float, None where there is none (a resonant row's NaN)."""
    return None if np.isnan(v) else float(v)


def _largest_rows(report):
    """One dict per row of a block's sweep, SI units; a soil sweep's rows say whether they are
    resonant (their values then null)."""
    soil = report.variable == "soil_factor"
    for i, (value, verdict_of) in enumerate(zip(report.values, verdict_cells(report))):
        yield {
            report.variable: float(value),
            **({"resonant": bool(report.resonant[i])} if soil else {}),
            **{key: dict(zip("xyz", map(_value, report.columns[key][i]))) for key in VALUES},
            **verdict_of,
        }


def _plane_head(report, scene, source: str) -> dict:
    """The keys of a crank scene's sweep document before its limits."""
    return {
        "scene": source,
        "name": scene.name,
        "method": method(report),
        **({"not_applicable": dict(report.setup["not_applicable"])} if report.setup["not_applicable"] else {}),
        "variable": report.variable,
        "limits": limits_document({key: report.limits.get(quantity) for quantity, key in (QUANTITIES | RMS_QUANTITIES).items()},
                                  report.detuning),
        "critical_speeds": [
            {"condition": c.label, "source": c.source, "zero_order": c.zero_order, "averaged": c.averaged, "band": c.band,
             "judged": c.judged}
            for c in report.critical
        ],
    }


def _largest_head(report, scene, source: str) -> dict:
    """The keys of a block's sweep document before its limits: the machine swept (and whether the
    others run) or, for a soil sweep, every machine's speed."""
    from foundation_calc.units import speed_triplet

    setup = report.setup
    if report.variable == "soil_factor":
        kind = {"variable": "soil_factor", "machines": {name: speed_triplet(w) for name, w in setup["speeds"].items()}}
    else:
        kind = {"machine": setup["machine"], "others": "left out" if setup["alone"] else "at their own speeds"}
    return {
        "scene": {"source": source, "kind": scene.kind, "name": scene.name},
        **kind,
        "limits": limits_document(report.limits, report.detuning),
        "critical_speeds": [{"condition": c.label, "order": c.order, "omega": c.critical, "judged": c.judged,
                             "band": c.band if c.judged else 0.0} for c in report.critical],
    }


def of_plane(report) -> bool:
    """The report is a crank scene's (the peaks of C, its points and harmonics), not a block's."""
    return "peaks" in report.columns


def rows_of(report):
    """The rows of a sweep of any kind, one dict a row (SI units), by its kind's columns."""
    return _plane_rows(report) if of_plane(report) else _largest_rows(report)


def sweep_document(report, scene, source: str) -> dict:
    """The JSON document of ``fcalc sweep`` (SI units), with the scene's plausibility warnings."""
    return {
        "schema_version": JSON_SCHEMA_VERSION,
        "command": "sweep",
        **(_plane_head if of_plane(report) else _largest_head)(report, scene, source),
        "points": list(rows_of(report)),
        "warnings": list(scene.plausibility_warnings()),
        "verdict": verdict(report.rows.status),
    }


def _plane_columns(report) -> list:
    """(CSV head, cell of a row) of a crank scene's sweep: the swept value, the speed (also in Hz
    and rpm), the peaks of C, the harmonics, the points' peaks, whether resonant."""
    soil = report.variable != "omega"
    columns = [("soil_factor" if soil else "omega_rad_s", lambda r: r[report.variable])]
    columns += [("omega_rad_s", lambda r: r["omega"])] if soil else []
    columns += [("speed_hz", lambda r: hz_from_omega(r["omega"])), ("speed_rpm", lambda r: rpm_from_omega(r["omega"])),
                ("x_peak_m", lambda r: r["x_peak"]), ("y_peak_m", lambda r: r["y_peak"]),
                ("theta_peak_rad", lambda r: r["theta_peak"])]
    columns += [(f"{key}_{head}", _nested("harmonics", key, part)) for key in report.columns["harmonics"]
                for head, part in (("amplitude", "amplitude"), ("phase_rad", "phase"))]
    columns += [(f"{name}_{d}_peak_m", _nested("points", name, d)) for name in report.columns["points"]
                for d in ("horizontal", "vertical")]
    return columns + [("resonant", lambda r: r["resonant"])]


def _nested(group: str, key: str, part: str):
    """The cell of a row's ``row[group][key][part]``, None where the row has no ``row[group]`` (a
    resonant row's harmonics) or no ``row[group][key]`` (its points)."""

    def cell(row: dict):
        found = row[group]
        found = None if found is None else found[key]
        return None if found is None else found[part]

    return cell


def _largest_columns(report) -> list:
    """(CSV head, cell of a row) of a block's sweep: the speed (also in Hz and rpm) or the factor
    and whether resonant, then every largest value along x, y, z."""
    if report.variable == "soil_factor":
        columns = [("soil_factor", lambda r: r["soil_factor"]), ("resonant", lambda r: r["resonant"])]
    else:
        columns = [("omega_rad_s", lambda r: r["omega"]), ("speed_hz", lambda r: hz_from_omega(r["omega"])),
                   ("speed_rpm", lambda r: rpm_from_omega(r["omega"]))]
    return columns + [(f"{name}_{d}_{unit}", lambda r, key=key, d=d: r[key][d])
                      for key, (name, unit) in VALUES.items() for d in "xyz"]


def _csv_columns(report) -> list:
    """(CSV head, cell of a row) of every column of a sweep of any kind: its kind's, then the verdict's."""
    kind = _plane_columns(report) if of_plane(report) else _largest_columns(report)
    return kind + [(key, lambda r, key=key: r[key]) for key in VERDICT_COLUMNS]


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
    """The header line of the sweep's CSV (SI units, the speed also in Hz and rpm)."""
    return csv_text([[head for head, _ in _csv_columns(report)]])


def csv_rows(report) -> str:
    """The rows of a sweep (or of one chunk of it) as CSV text; empty cells where a row has no value."""
    columns = _csv_columns(report)
    return csv_text([[csv_cell(value(row)) for _, value in columns] for row in rows_of(report)])


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


def print_sweep(report, scene, source: str, units) -> None:
    """The sweep's table, speeds and amplitudes in ``units``."""
    if of_plane(report):
        _print_plane(report, source, scene.name, units)
    else:
        _print_largest(report, scene, source, units)


def _print_table(title: str, heads: list[str], cells: list[list[str]], rows: list[dict], swept: str | None = None) -> None:
    """Print the table of every kind's sweep (:func:`print_status_table`): a column per head
    (right-justified), a row per row's ``cells``, then the status of each of ``rows`` (the
    document's rows, ``swept``: the swept machine's name)."""
    from rich.markup import escape
    from rich.table import Table

    def make_table(status_head: str, statuses: list[str]) -> Table:
        table = Table(title=title, title_justify="left")
        for head in heads:
            table.add_column(escape(head), justify="right")
        table.add_column(status_head)
        for row, status in zip(cells, statuses):
            table.add_row(*row, status)
        return table

    print_status_table(make_table, rows, swept)


def _print_plane(report, scene_path: str, name: str, units) -> None:
    """A crank scene's sweep as a rich table; speeds and amplitudes in the chosen display units."""
    from rich.markup import escape

    speed_unit, amp_unit = units.label("speed"), units.label("amplitude")
    rows = list(_plane_rows(report))
    values = []
    for row in rows:
        cells = [] if report.variable == "omega" else [fmt(row["soil_factor"], 4)]
        cells.append(fmt(units.convert("speed", row["omega"]), 6))
        if row["resonant"]:
            cells += ["resonant"] * (3 + len(report.columns["points"]))
        else:
            cells += [fmt(units.convert("amplitude", row["x_peak"]), 4), fmt(units.convert("amplitude", row["y_peak"]), 4),
                      fmt(row["theta_peak"], 4)]
            cells += [
                " / ".join(fmt(units.convert("amplitude", p[k]), 4) for k in ("horizontal", "vertical"))
                for p in row["points"].values()
            ]
        if report.setup["damped"]:
            h = row["harmonics"]
            cells.append("-" if h is None else f"{math.degrees(h['x1']['phase']):.1f} / {math.degrees(h['y1']['phase']):.1f}")
        values.append(cells)

    heads = ["soil factor (c_z, c_x, c_phi)"] if report.variable == "soil_factor" else []
    heads += [f"speed [{speed_unit}]", *(f"{dof} peak [{unit}]" for dof, unit in (("x", amp_unit), ("y", amp_unit), ("θ", "rad")))]
    heads += [f"{point} peak h/v [{amp_unit}]" for point in report.columns["points"]]
    heads += ["phase lag x1 / y1 [°]"] if report.setup["damped"] else []
    _print_table(f"{escape(name or scene_path)} — {method(report)}", heads, values, rows)
    _print_footer(report, units)


def _print_footer(report, units) -> None:
    """The critical speeds inside the sweep and the limits, under the rows or the summary."""
    from rich.markup import escape
    from rich.table import Table

    out = stdout()
    speed_unit = units.label("speed")
    for key, why in report.setup["not_applicable"].items():
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


def _print_largest(report, scene, source: str, units) -> None:
    """The table of a block's sweep: a row per value of the swept variable, the largest peaks x, y,
    z and RMS velocity over G and the points in ``units`` ("-" where a row is resonant), then the
    status."""
    from rich.markup import escape

    amp, vel = units.label("amplitude"), units.label("velocity")
    rows = list(_largest_rows(report))
    if report.variable == "soil_factor":
        swept, what = None, f"the {FACTORED} (every machine at its own speed;"
        head, cells = "factor", [fmt(row["soil_factor"]) for row in rows]
    else:
        swept = report.setup["machine"]
        what = f"{swept}'s speed ({others(report)};"
        head, cells = units.label("speed"), [fmt(units.convert("speed", row["omega"])) for row in rows]
    title = escape(f"{scene.name or source}: sweep of {what} largest over G and the points): peak displacement x, y, z"
                   f" [{amp}], RMS velocity v [{vel}] (largest direction)")

    def cell(quantity: str, value) -> str:
        return "-" if np.isnan(value) else fmt(units.convert(quantity, float(value)), 4)

    values = [[first, *(cell("amplitude", v) for v in report.columns["peak"][i]),
               cell("velocity", np.max(report.columns["velocity_rms"][i]))] for i, first in enumerate(cells)]
    _print_table(title, [head, "x", "y", "z", "v"], values, rows, swept)


def others(report) -> str:
    """How a block's speed sweep runs its other machines, in words."""
    return "the others left out" if report.setup["alone"] else "the others at their own"


__all__ = ["FACTORED", "VALUES", "csv_cell", "csv_header", "csv_rows", "csv_text", "limits_document", "method", "of_plane",
           "others", "print_status_table", "print_sweep", "print_sweep_summary", "rows_of", "status_text", "sweep_csv",
           "sweep_document", "verdict", "verdict_cells"]
