"""``fcalc sweep`` of a block scene: one row per speed of the swept machine
(:class:`~foundation_calc.checks.block_sweep.BlockSweep`); table, JSON, CSV and plot. Each row's
status names the governing judged condition and every limit exceeded in the words of every kind's
sweep (:func:`~foundation_calc.checks.sweep_status.status_text`)."""

from __future__ import annotations

import numpy as np

from foundation_calc.output.console import JSON_SCHEMA_VERSION, fmt
from foundation_calc.output.sweep_report import csv_cell, csv_text, limits_document, print_status_table, verdict, verdict_cells

#: The largest values over G and the points a row gives, by key: (JSON/CSV name, SI unit in the CSV).
VALUES = {"peak": ("peak", "m"), "velocity_peak": ("velocity_peak", "m_s"), "displacement_rms": ("displacement_rms", "m"),
          "velocity_rms": ("velocity_rms", "m_s"), "acceleration_peak": ("acceleration_peak", "m_s2"),
          "acceleration_rms": ("acceleration_rms", "m_s2")}


def _others(sweep) -> str:
    return "the others left out" if sweep.alone else "the others at their own"


def _rows(sweep):
    """One dict per speed, SI units."""
    for i, (w, verdict_of) in enumerate(zip(sweep.omega, verdict_cells(sweep))):
        yield {
            "omega": float(w),
            **{key: dict(zip("xyz", map(float, getattr(sweep, key)[i]))) for key in VALUES},
            **verdict_of,
        }


def _critical(sweep, lo: float, hi: float):
    """The swept machine's conditions that can decide a row, their critical speeds within [lo, hi] [rad/s]."""
    return [c for c in sweep.conditions if c.machine == sweep.machine and c.deciding and lo <= c.critical <= hi]


def sweep_document(sweep, scene, source: str, warnings=()) -> dict:
    """JSON of a block sweep (SI)."""
    return {
        "schema_version": JSON_SCHEMA_VERSION,
        "command": "sweep",
        "scene": {"source": source, "kind": scene.kind, "name": scene.name},
        "machine": sweep.machine,
        "others": "left out" if sweep.alone else "at their own speeds",
        "limits": limits_document(sweep.limits, sweep.detuning),
        "critical_speeds": [{"condition": c.label, "order": c.order, "omega": c.critical, "judged": c.judged,
                             "band": c.band if c.judged else 0.0} for c in _critical(sweep, sweep.omega.min(), sweep.omega.max())],
        "points": list(_rows(sweep)),
        "warnings": list(warnings),
        "verdict": verdict(sweep.rows.status),
    }


def print_sweep(sweep, scene, source: str, units) -> None:
    """The table of a block sweep."""
    from rich.markup import escape

    amp, vel, speed = units.label("amplitude"), units.label("velocity"), units.label("speed")
    title = escape(f"{scene.name or source}: sweep of {sweep.machine}'s speed ({_others(sweep)}; largest over"
                   f" G and the points): peak displacement x, y, z [{amp}], RMS velocity v [{vel}] (largest"
                   " direction)")
    rows = list(_rows(sweep))
    speeds = [fmt(units.convert("speed", row["omega"])) for row in rows]
    print_status_table(largest_values_table(title, speed, speeds, sweep, units), rows, sweep.machine)


def largest_values_table(title: str, head: str, swept: list[str], sweep, units):
    """``make_table(status head, status cells)`` of a block's sweep
    (:func:`~foundation_calc.output.sweep_report.print_status_table`): a row per value of the swept
    variable (``head``, its cells ``swept``), the largest peaks x, y, z and RMS velocity over G and
    the points in ``units`` ("-" where a row is resonant), then the status."""
    from rich.markup import escape
    from rich.table import Table

    def cell(quantity: str, value) -> str:
        return "-" if np.isnan(value) else fmt(units.convert(quantity, float(value)), 4)

    def make_table(status_head: str, statuses: list[str]) -> Table:
        table = Table(title=title, title_justify="left")
        for col in (head, "x", "y", "z", "v"):
            table.add_column(escape(col), justify="right")
        table.add_column(status_head)
        for i, (first, status) in enumerate(zip(swept, statuses)):
            table.add_row(first, *(cell("amplitude", v) for v in sweep.peak[i]),
                          cell("velocity", np.max(sweep.velocity_rms[i])), status)
        return table

    return make_table


def _header() -> list[str]:
    values = [f"{name}_{d}_{unit}" for name, unit in VALUES.values() for d in "xyz"]
    return ["omega_rad_s", "speed_hz", "speed_rpm", *values, "governing_condition", "margin", "needed", "resonance_status",
            "over_limit", "status"]


def sweep_csv(sweep) -> str:
    """The rows as CSV text (SI units, the speed also in Hz and rpm; cells as the crank sweep writes them)."""
    from foundation_calc.units import hz_from_omega, rpm_from_omega

    lines = [[csv_cell(c) for c in (r["omega"], hz_from_omega(r["omega"]), rpm_from_omega(r["omega"]),
                                 *(r[key][d] for key in VALUES for d in "xyz"), r["governing_condition"], r["margin"],
                                 r["needed"], r["resonance_status"], r["over_limit"], r["status"])] for r in _rows(sweep)]
    return csv_text([_header(), *lines])


def plot_sweep(sweep, path, units, name: str) -> None:
    """Largest peaks along x, y, z over G and the points against the swept machine's speed (log
    scale), the amplitude limit, its speed in the scene, and the critical speed p_j / n of each of
    its conditions that can decide a row: a judged one with its detuning band, an order-1 one the
    rule does not judge as a grey line (:func:`~foundation_calc.output.plots.mark_resonances`);
    conditions that never decide are left out."""
    from foundation_calc.checks.resonance_rule import bands_text

    marks = [(units.convert("speed", c.critical), c.label.removeprefix(f"{c.machine}: "), "extra", c.band if c.judged else 0.0)
             for c in _critical(sweep, 0.0, np.inf)]
    plot_largest_peaks(
        sweep, np.asarray(units.convert("speed", sweep.omega), dtype=float), path, units, marks,
        (units.convert("speed", sweep.speed), f"{sweep.machine}'s speed"), f"speed of {sweep.machine} [{units.label('speed')}]",
        f"{name}: sweep of {sweep.machine}'s speed ({_others(sweep)})\nshaded: the detuning band of each judged"
        f" critical speed $p_j/n$ ([limits] detuning = {bands_text(sweep.detuning)}); grey: order 1, not judged",
    )


def plot_largest_peaks(sweep, xs, path, units, marks, operating, xlabel: str, heading: str, shaded=()) -> None:
    """The plot of every block sweep: the largest peaks along x, y, z over G and the points
    (``sweep.peak`` (N, 3) [m]) against ``xs`` (N,) (log scale), the amplitude limit of
    ``sweep.limits``, ``marks`` and ``operating`` (the scene's own value, its label) as
    :func:`~foundation_calc.output.plots.mark_resonances` draws them, and the x-ranges ``shaded``
    [(lo, hi)], labelled as inside a detuning band."""
    from foundation_calc.output.plots import mark_resonances, new_figure, save, title

    fig, ax = new_figure()
    marker = "o" if len(xs) == 1 else None
    for d, direction in enumerate("xyz"):
        ax.semilogy(xs, units.convert("amplitude", sweep.peak[:, d]), label=f"peak {direction}", marker=marker)
    if "displacement" in sweep.limits:
        ax.axhline(units.convert("amplitude", sweep.limits["displacement"]), color="red", linestyle="--", label="amplitude limit")
    for k, (lo, hi) in enumerate(shaded):
        ax.axvspan(lo, hi, color="orange", alpha=0.25, lw=0, label=None if k else "inside a detuning band")
    lo, hi = float(xs.min()), float(xs.max())
    if hi == lo:
        lo, hi = 0.9 * lo, 1.1 * hi
    mark_resonances(ax, marks, operating[0], lo, hi, operating[1])
    ax.set_xlabel(xlabel)
    ax.set_ylabel(f"largest peak displacement over G and the points [{units.label('amplitude')}]")
    title(ax, heading)
    ax.grid(True, which="both", alpha=0.3)
    ax.legend(fontsize=8, loc="lower right")
    save(fig, path)


__all__ = ["largest_values_table", "plot_largest_peaks", "plot_sweep", "print_sweep", "sweep_csv", "sweep_document"]
