"""``fcalc sweep`` of a block scene: one row per speed of the swept machine; table, JSON, CSV and
plot."""

from __future__ import annotations

from dataclasses import dataclass

import numpy as np

from foundation_calc.checks.limits import exceeds
from foundation_calc.checks.outcomes import Outcome
from foundation_calc.output.console import JSON_SCHEMA_VERSION, fmt, stdout


@dataclass(frozen=True)
class SweepRow:
    """One speed: nearest mode of the swept machine's orders, largest peak and RMS velocity over
    G and the points, and the status by the resonance rule and [limits] amplitude / velocity_rms."""

    omega: float
    order: int
    mode: int
    motion: str
    margin: float
    peak: tuple[float, float, float]
    velocity_rms: tuple[float, float, float]
    status: Outcome


def sweep_rows(result, modes, scene, swept: int) -> list[SweepRow]:
    """The rows of a :class:`~foundation_calc.solvers.block.sweep.SpeedSweep`."""
    from foundation_calc.checks.resonance_rule import FAIL, WARN, judge, required_detuning
    from foundation_calc.solvers.block.response import resonances

    exc = scene.excitations()[swept]
    share = resonances(modes, exc).share.ravel()  # at the scene's speed: the loads' shape
    orders = np.repeat(exc.orders, len(modes.frequencies))
    N = len(result.omega)
    verdict = judge(result.margin.reshape(N, -1), orders, share, required_detuning(scene.limits.detuning, orders),
                    np.zeros(orders.shape, dtype=bool))
    fails, inside = verdict.status == FAIL, verdict.status == WARN
    peak, rms = result.peak.max(axis=1), result.velocity_rms.max(axis=1)  # (N, 3)
    over = np.zeros(len(result.omega), dtype=bool)
    if scene.limits.amplitude is not None:
        over |= exceeds(peak, scene.limits.amplitude).any(axis=1)
    if scene.limits.velocity_rms is not None:
        over |= exceeds(rms, scene.limits.velocity_rms).any(axis=1)
    rows = []
    for i, w in enumerate(result.omega):
        h, j = np.unravel_index(int(np.argmin(result.margin[i])), result.margin[i].shape)
        status = Outcome.FAIL if fails[i].any() or over[i] else Outcome.WARN if inside[i].any() else Outcome.PASS
        rows.append(SweepRow(float(w), int(exc.orders[h]), int(j) + 1, modes.dominant[j], float(result.margin[i, h, j]),
                             tuple(map(float, peak[i])), tuple(map(float, rms[i])), status))
    return rows


def sweep_document(rows, scene, source: str, machine: str) -> dict:
    """JSON of a block sweep (SI)."""
    return {
        "schema_version": JSON_SCHEMA_VERSION,
        "command": "sweep",
        "scene": {"source": source, "kind": scene.kind, "name": scene.name},
        "machine": machine,
        "points": [
            {"omega": r.omega, "nearest": {"order": r.order, "mode": r.mode, "dominant": r.motion, "margin": r.margin},
             "peak": dict(zip("xyz", r.peak)), "velocity_rms": dict(zip("xyz", r.velocity_rms)), "status": r.status.value}
            for r in rows
        ],
    }


def print_sweep(rows, scene, source: str, machine: str, units) -> None:
    """The table of a block sweep."""
    from rich.markup import escape
    from rich.table import Table

    from foundation_calc.output.console import verdict_text

    amp, vel, speed = units.label("amplitude"), units.label("velocity"), units.label("speed")
    table = Table(title=f"{escape(scene.name or source)}: sweep of {escape(machine)}'s speed (others at their own;"
                  " largest over G and the points)", title_justify="left")
    for col in (speed, "nearest", "margin", f"peak x, {amp}", f"peak y, {amp}", f"peak z, {amp}", f"RMS v (largest), {vel}", "status"):
        table.add_column(col, justify="left" if col in ("nearest", "status") else "right")
    for r in rows:
        table.add_row(fmt(units.convert("speed", r.omega)), f"{r.order}ω = mode {r.mode} ({r.motion})", f"{r.margin:.1%}",
                      *(fmt(units.convert("amplitude", v), 4) for v in r.peak), fmt(units.convert("velocity", max(r.velocity_rms)), 4),
                      verdict_text(r.status.value))
    stdout().print(table)


#: Columns of a block sweep's CSV (SI units, the speed also in Hz and rpm).
CSV_HEADER = ("omega_rad_s", "speed_hz", "speed_rpm", "nearest_order", "nearest_mode", "nearest_dominant", "margin",
              "peak_x_m", "peak_y_m", "peak_z_m", "velocity_rms_x_m_s", "velocity_rms_y_m_s", "velocity_rms_z_m_s", "status")


def sweep_csv(rows) -> str:
    """The rows as CSV text (:data:`CSV_HEADER`; cells as the crank sweep writes them)."""
    from foundation_calc.output.sweep_report import _cell, _csv_text
    from foundation_calc.units import hz_from_omega, rpm_from_omega

    lines = [[_cell(c) for c in (r.omega, hz_from_omega(r.omega), rpm_from_omega(r.omega), r.order, r.mode, r.motion, r.margin,
                                 *r.peak, *r.velocity_rms, r.status.value)] for r in rows]
    return _csv_text([list(CSV_HEADER), *lines])


def plot_sweep(rows, modes, scene, swept: int, path, units, name: str) -> None:
    """Largest peaks along x, y, z over G and the points against the swept machine's speed (log
    scale), the amplitude limit, its speed in the scene, and each critical speed p_j / n of its
    orders inside the range with its detuning band (:func:`~foundation_calc.output.plots.mark_resonances`)."""
    from foundation_calc.checks.resonance_rule import required_detuning
    from foundation_calc.output.plots import mark_resonances, new_figure, save

    exc = scene.excitations()[swept]
    fig, ax = new_figure()
    xs = np.asarray(units.convert("speed", np.array([r.omega for r in rows])), dtype=float)
    marker = "o" if len(xs) == 1 else None
    for d, direction in enumerate("xyz"):
        ax.semilogy(xs, units.convert("amplitude", np.array([r.peak[d] for r in rows])), label=f"peak {direction}",
                    marker=marker)
    if scene.limits.amplitude is not None:
        ax.axhline(units.convert("amplitude", scene.limits.amplitude), color="red", linestyle="--", label="amplitude limit")
    bands = required_detuning(scene.limits.detuning, exc.orders)
    marks = [(units.convert("speed", float(p) / n), f"{n if n > 1 else ''}ω = mode {j + 1} ({modes.dominant[j]})", "extra",
              float(band)) for n, band in zip(exc.orders, bands) for j, p in enumerate(modes.frequencies)]
    lo, hi = float(xs.min()), float(xs.max())
    if hi == lo:
        lo, hi = 0.9 * lo, 1.1 * hi
    mark_resonances(ax, marks, units.convert("speed", exc.omega), lo, hi, f"{exc.name}'s speed")
    ax.set_xlabel(f"speed of {exc.name} [{units.label('speed')}]")
    ax.set_ylabel(f"largest peak displacement over G and the points [{units.label('amplitude')}]")
    ax.set_title(f"{name}: sweep of {exc.name}'s speed (others at their own)\nshaded: the detuning band of each"
                 " critical speed p_j / n", fontsize=9)
    ax.legend(fontsize=8, loc="lower right")
    save(fig, path)
