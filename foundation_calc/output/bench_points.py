"""The points-scaling rows of ``fcalc bench``: a rich table and their part of the JSON document."""

from __future__ import annotations

from dataclasses import asdict

from foundation_calc.output.bench_report import bytes_text, seconds_text
from foundation_calc.output.console import stdout


def points_document(rows) -> list[dict]:
    """One entry per command and point count (seconds, bytes, ratios to the fewest points)."""
    return [asdict(row) for row in rows]


def print_points(rows) -> None:
    """The rows as one table, a command's point counts one under another."""
    from rich.table import Table

    fewest = min(row.points for row in rows)
    table = Table(
        title=f"Many points: whole processes, median wall time and largest resident memory, × {fewest} points, same run",
        title_justify="left",
    )
    for name in ("command", "points", "time", f"× {fewest} points", "memory", f"memory × {fewest} points"):
        table.add_column(name, justify="left" if name == "command" else "right")
    for row in rows:
        table.add_row(
            f"fcalc {row.command}", f"{row.points:,}".replace(",", " "), seconds_text(row.seconds), f"{row.time_ratio:.2f}",
            bytes_text(row.peak_rss_bytes), f"{row.memory_ratio:.2f}",
        )
    stdout().print()
    stdout().print(table)
