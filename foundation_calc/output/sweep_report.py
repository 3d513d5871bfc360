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
from foundation_calc.checks.resonance_rule import condition_phrase
from foundation_calc.output.console import JSON_SCHEMA_VERSION, OUTCOME_STYLE, fmt, stdout
from foundation_calc.units import hz_from_omega, rpm_from_omega

METHOD = "corrected first approximation (Krichever & Makarov (4.11)-(4.14))"
LOADS_METHOD = "vendor loads, linear steady state"
STATUS_STYLE = {**OUTCOME_STYLE, "resonant": "bold magenta"}


def method(report) -> str:
    """What computed the sweep's amplitudes: the mechanism's closed form, the loads' steady state or both."""
    sources = {c.source for c in report.conditions}
    parts = ([METHOD] if sources - {"loads"} else []) + ([LOADS_METHOD] if "loads" in sources else [])
    return " + ".join(parts)


def _condition_label(condition) -> str:
    """A condition's label, with "(loads)" for a harmonic of the scene's [[loads]]."""
    return condition.label + (" (loads)" if condition.source == "loads" else "")


def _governing(report, i: int) -> str | None:
    """The label of the condition that governs point i's resonance verdict (None: no condition)."""
    g = int(report.governing[i])
    return None if g < 0 else _condition_label(report.conditions[g])


def status_text(row: dict) -> str:
    """Why a point has its status, the failing causes first: the governing resonance condition
    when the rule fails or warns there, every limit the point exceeds; then, when the resonance
    rule is satisfied, the governing condition and its margin, e.g.
    ``"fail: inside 3ω = p1 at 15.7% (needs 20%); over displacement limit"`` or
    ``"fail: over displacement limit; resonances clear, governing 3ω = p1 at 30.9% (needs 20%)"``."""
    phrase = None
    if row["governing_condition"] is not None:
        phrase = condition_phrase(row["governing_condition"], row["margin"], row["needed"])
    causes = []
    if phrase is not None and row["resonance_status"] in ("warn", "fail"):
        causes.append(f"inside {phrase}")
    if row["over_limits"]:
        causes.append(f"over {', '.join(row['over_limits'])} limit")
    if phrase is not None and row["resonance_status"] not in ("warn", "fail"):
        causes.append(f"resonances clear, governing {phrase}")
    return f"{row['status']}: " + "; ".join(causes) if causes else row["status"]


def _harmonics(report, i: int) -> dict | None:
    """Amplitude [m or rad] and phase lag [rad] of each harmonic at point i; None where resonant."""
    if report.resonant[i]:
        return None
    return {
        key: {"amplitude": float(abs(z[i])), "phase": float(-np.angle(z[i]))} for key, z in report.harmonics.items()
    }


def _rows(report):
    """One dict per point, SI units; amplitudes None where resonant."""
    for i, value in enumerate(report.values):
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
            "governing_condition": _governing(report, i),
            "resonance_status": str(report.resonance_status[i]),
            "margin": float(report.margin[i]),
            "needed": float(report.needed[i]),
            "over_limit": bool(report.over_limit[i]),
            "over_limits": [q for q, mask in report.over_quantities.items() if mask[i]],
            "status": str(report.status[i]),
        }


def sweep_document(report, scene_path: str, name: str, warnings: Iterable[str] = ()) -> dict:
    """The sweep as one JSON-ready dict (SI units: rad/s, m, rad); ``warnings``: the scene's
    plausibility warnings."""
    return {
        "schema_version": JSON_SCHEMA_VERSION,
        "scene": scene_path,
        "name": name,
        "method": method(report),
        "variable": report.variable,
        "limits": {
            **{key: report.limits.get(quantity) for quantity, key in (QUANTITIES | RMS_QUANTITIES).items()},
            "detuning": {str(k): v for k, v in report.detuning.items()} if isinstance(report.detuning, dict) else report.detuning,
        },
        "critical_speeds": [
            {"condition": c.label, "source": c.source, "zero_order": c.zero_order, "averaged": c.averaged, "band": c.band}
            for c in report.critical
        ],
        "points": list(_rows(report)),
        "warnings": list(warnings),
    }


def sweep_csv(report) -> str:
    """The sweep as CSV text: SI columns plus the speed in Hz and rpm; empty amplitude where resonant."""
    buffer = io.StringIO()
    writer = csv.writer(buffer, lineterminator="\n")
    header = [report.variable if report.variable != "omega" else "omega_rad_s", "speed_hz", "speed_rpm",
              "x_peak_m", "y_peak_m", "theta_peak_rad",
              *(f"{key}_{part}" for key in report.harmonics for part in ("amplitude", "phase_rad")),
              *(f"{name}_{d}_peak_m" for name in report.points for d in ("horizontal", "vertical")),
              "resonant", "governing_condition", "margin", "needed", "over_limit", "status"]
    if report.variable != "omega":
        header.insert(1, "omega_rad_s")
    writer.writerow(header)
    for row in _rows(report):
        cells = [row[report.variable]]
        if report.variable != "omega":
            cells.append(row["omega"])
        cells += [hz_from_omega(row["omega"]), rpm_from_omega(row["omega"])]
        cells += ["" if row[k] is None else repr(row[k]) for k in ("x_peak", "y_peak", "theta_peak")]
        for key in report.harmonics:
            h = row["harmonics"]
            cells += ["", ""] if h is None else [repr(h[key]["amplitude"]), repr(h[key]["phase"])]
        for name in report.points:
            p = row["points"][name]
            cells += ["", ""] if p is None else [repr(p["horizontal"]), repr(p["vertical"])]
        cells += [row["resonant"], row["governing_condition"] or "", repr(row["margin"]), repr(row["needed"]),
                  row["over_limit"], row["status"]]
        writer.writerow(cells)
    return buffer.getvalue()


def print_sweep(report, scene_path: str, name: str, units) -> None:
    """The sweep as a rich table; speeds and amplitudes in the chosen display units."""
    from rich.markup import escape
    from rich.table import Table

    out = stdout()
    speed_unit, amp_unit = units.label("speed"), units.label("amplitude")
    title = f"{escape(name or scene_path)} — {method(report)}"
    table = Table(title=title, title_justify="left")
    if report.variable == "soil_factor":
        table.add_column("soil factor (c_z, c_x, c_phi)", justify="right")
    table.add_column(escape(f"speed [{speed_unit}]"), justify="right")
    for dof, unit in (("x", amp_unit), ("y", amp_unit), ("θ", "rad")):
        table.add_column(escape(f"{dof} peak [{unit}]"), justify="right")
    for name in report.points:
        table.add_column(escape(f"{name} peak h/v [{amp_unit}]"), justify="right")
    if report.damped:
        table.add_column(escape("phase lag x1 / y1 [°]"), justify="right")
    table.add_column("status: governing resonance, margin; limits")
    for row in _rows(report):
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
        cells.append(f"[{STATUS_STYLE[row['status']]}]{escape(status_text(row))}[/]")
        table.add_row(*cells)
    out.print(table)
    if report.critical:
        crit = Table(title="Critical speeds inside the sweep (zero-order / averaged-inertia operator)", title_justify="left")
        for col in ("condition", "source", f"zero-order [{speed_unit}]", f"averaged [{speed_unit}]"):
            crit.add_column(escape(col), justify="left" if col in ("condition", "source") else "right")
        for c in report.critical:
            crit.add_row(c.label, c.source, fmt(units.convert("speed", c.zero_order), 6), fmt(units.convert("speed", c.averaged), 6))
        out.print(crit)
    limits = "; ".join(f"{q} {units.show(display_quantity(q), v)}" for q, v in report.limits.items()) or "none"
    out.print(
        f"limits (x, y of C and of every point): {limits}; required detuning {report.detuning if isinstance(report.detuning, dict) else format(report.detuning, '.0%')}", soft_wrap=True
    )


def plot_sweep(report, path: str | Path, units, name: str) -> None:
    """x, y peaks against the swept variable (log scale), critical speeds and the limit marked."""
    import numpy as np

    from foundation_calc.output.plots import new_figure, save

    fig, ax = new_figure()
    if report.variable == "omega":
        xs = np.array([units.convert("speed", w) for w in report.values])
        ax.set_xlabel(f"speed [{units.label('speed')}]")
    else:
        xs = report.values
        ax.set_xlabel("factor on the soil coefficients c_z, c_x, c_phi [-]")
    ok = ~report.resonant
    for i, dof in enumerate(("x", "y")):
        amps = np.where(ok, [units.convert("amplitude", v) for v in report.peaks[:, i]], np.nan)
        ax.semilogy(xs, amps, label=f"{dof} peak of C")
    if report.amplitude_limit is not None:
        ax.axhline(units.convert("amplitude", report.amplitude_limit), color="red", linestyle="--", label="amplitude limit")
    for c in report.critical:
        style = "-" if c.source == "paper" else ":"
        ax.axvline(units.convert("speed", c.zero_order), color="grey", linestyle=style, alpha=0.6)
        ax.text(units.convert("speed", c.zero_order), 1.0, c.label, rotation=90, va="top", ha="right", fontsize=7,
                transform=ax.get_xaxis_transform())
    ax.set_ylabel(f"peak displacement [{units.label('amplitude')}]")
    ax.set_title(f"{name}: {method(report)}", fontsize=9)
    ax.grid(True, which="both", alpha=0.3)
    ax.legend(fontsize=8)
    save(fig, path)


__all__ = ["plot_sweep", "print_sweep", "sweep_csv", "sweep_document"]
