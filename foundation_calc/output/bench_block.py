"""The block section of ``fcalc bench``: a table and its JSON part."""

from __future__ import annotations

from foundation_calc.benchmarks.block import SWEEP_SPEEDS

#: Targets of the block's run time [s]: one scene, one sweep of SWEEP_SPEEDS speeds.
TARGETS = {"scene": 0.010, "sweep": 1.0}


def block_document(timings) -> list[dict]:
    """Seconds per call, wall (median) and CPU, with the targets."""
    return [
        {"scene": t.source, "check_seconds": t.scene_wall.seconds, "check_cpu_seconds": t.scene_cpu,
         "check_target_seconds": TARGETS["scene"], "sweep_speeds": SWEEP_SPEEDS, "sweep_seconds": t.sweep_wall.seconds,
         "sweep_cpu_seconds": t.sweep_cpu, "sweep_target_seconds": TARGETS["sweep"],
         "sweep_peak_bytes": t.sweep_wall.peak_bytes}
        for t in timings
    ]


def print_block(timings) -> None:
    """The table of the block section."""
    from rich.table import Table

    from foundation_calc.output.console import stdout

    table = Table(title=f"Block foundation: one scene's check, and a sweep of {SWEEP_SPEEDS:,} speeds", title_justify="left")
    for col in ("scene", "check, ms wall", "check, ms CPU", "target", "sweep, s wall", "sweep, s CPU", "target"):
        table.add_column(col, justify="left" if col == "scene" else "right")
    for t in timings:
        table.add_row(t.source, f"{t.scene_wall.seconds * 1e3:.2f}", f"{t.scene_cpu * 1e3:.2f}", f"{TARGETS['scene'] * 1e3:g} ms",
                      f"{t.sweep_wall.seconds:.3f}", f"{t.sweep_cpu:.3f}", f"{TARGETS['sweep']:g} s")
    stdout().print(table)
