"""``fcalc sweep`` of a block scene: one row per speed of the swept machine."""

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
