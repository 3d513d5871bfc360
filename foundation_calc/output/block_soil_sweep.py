"""``fcalc sweep --soil`` of a block scene: one row per factor on the soil's stiffness data
(:class:`~foundation_calc.checks.block_soil_sweep.BlockSoilSweep`); table, JSON, CSV and plot, with
the values and the verdict cells of the block's speed sweep (:mod:`~foundation_calc.output.block_sweep`)
and the factor named as the crank foundation's soil sweep names it (``soil_factor``)."""

from __future__ import annotations

import numpy as np

from foundation_calc.output.block_sweep import VALUES, largest_values_table, plot_largest_peaks
from foundation_calc.output.console import JSON_SCHEMA_VERSION, fmt
from foundation_calc.output.sweep_report import csv_cell, csv_text, limits_document, print_status_table, verdict, verdict_cells

#: What the factor scales, for titles and labels.
FACTORED = "factor on the soil's stiffness data"


def _value(v) -> float | None:
    """A float, None where there is none (a resonant row's NaN)."""
    return None if np.isnan(v) else float(v)


def _rows(sweep):
    """One dict per factor, SI units."""
    for i, (f, verdict_of) in enumerate(zip(sweep.factor, verdict_cells(sweep))):
        yield {
            "soil_factor": float(f),
            "resonant": bool(sweep.resonant[i]),
            **{key: dict(zip("xyz", map(_value, getattr(sweep, key)[i]))) for key in VALUES},
            **verdict_of,
        }


def sweep_document(sweep, scene, source: str, warnings=()) -> dict:
    """JSON of a block's soil sweep (SI): ``variable`` ``"soil_factor"`` and each point's
    ``soil_factor``, as the crank foundation's soil sweep gives them; ``machines``: every machine's
    speed (all run at their own); a resonant point's values null."""
    from foundation_calc.units import speed_triplet

    return {
        "schema_version": JSON_SCHEMA_VERSION,
        "command": "sweep",
        "scene": {"source": source, "kind": scene.kind, "name": scene.name},
        "variable": "soil_factor",
        "machines": {name: speed_triplet(w) for name, w in sweep.speeds.items()},
        "limits": limits_document(sweep.limits, sweep.detuning),
        "critical_speeds": [],
        "points": list(_rows(sweep)),
        "warnings": list(warnings),
        "verdict": verdict(sweep.rows.status),
    }


def print_sweep(sweep, scene, source: str, units) -> None:
    """The table of a block's soil sweep, laid out as its speed sweep's
    (:func:`~foundation_calc.output.block_sweep.largest_values_table`)."""
    from rich.markup import escape

    amp, vel = units.label("amplitude"), units.label("velocity")
    title = escape(f"{scene.name or source}: sweep of the {FACTORED} (every machine at its own speed;"
                   f" largest over G and the points): peak displacement x, y, z [{amp}], RMS velocity v"
                   f" [{vel}] (largest direction)")
    rows = list(_rows(sweep))
    print_status_table(largest_values_table(title, "factor", [fmt(row["soil_factor"]) for row in rows], sweep, units), rows)


def sweep_csv(sweep) -> str:
    """The rows as CSV text (SI units; cells as every kind's sweep writes them, empty where resonant)."""
    values = [f"{name}_{d}_{unit}" for name, unit in VALUES.values() for d in "xyz"]
    header = ["soil_factor", "resonant", *values, "governing_condition", "margin", "needed", "resonance_status",
              "over_limit", "status"]
    lines = [[csv_cell(c) for c in (r["soil_factor"], r["resonant"], *(r[key][d] for key in VALUES for d in "xyz"),
                                    r["governing_condition"], r["margin"], r["needed"], r["resonance_status"],
                                    r["over_limit"], r["status"])] for r in _rows(sweep)]
    return csv_text([header, *lines])


def plot_sweep(sweep, path, units, name: str) -> None:
    """Largest peaks along x, y, z over G and the points against the factor (log scale), the
    amplitude limit, the scene's soil (factor 1), and shaded the factors where the resonance rule
    warns or fails (a judged condition inside its band), half-way to the next factors
    (:func:`~foundation_calc.output.block_sweep.plot_largest_peaks`)."""
    from foundation_calc.checks.resonance_rule import bands_text

    xs = np.asarray(sweep.factor, dtype=float)
    half = np.diff(xs).min() / 2.0 if len(xs) > 1 else 0.05 * xs[0]
    inside = np.isin(sweep.rows.resonance_status, ("warn", "fail"))
    plot_largest_peaks(sweep, xs, path, units, [], (1.0, "the scene's soil (factor 1)"), f"{FACTORED} [-]",
                       f"{name}: sweep of the {FACTORED} (every machine at its own speed)\nshaded: a judged resonance"
                       f" inside its band ([limits] detuning = {bands_text(sweep.detuning)})",
                       [(x - half, x + half) for x in xs[inside]])


__all__ = ["plot_sweep", "print_sweep", "sweep_csv", "sweep_document"]
