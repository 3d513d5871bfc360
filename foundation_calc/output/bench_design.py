"""The design section of ``fcalc bench``: the vectorised search against the loop over fcalc check's path."""

from __future__ import annotations

from foundation_calc.benchmarks.design import TARGET_SECONDS


def design_bench_document(timings) -> list[dict]:
    """Seconds of the vectorised search and of the loop (scaled to the grid), their ratio, peak memory."""
    return [
        {"scene": t.source, "kind": t.kind, "candidates": t.candidates,
         "vectorised_seconds": None if t.vectorised is None else t.vectorised.seconds,
         "vectorised_peak_bytes": None if t.vectorised is None else t.vectorised.peak_bytes,
         "loop_candidates_timed": t.loop_candidates, "loop_seconds_per_candidate": t.loop_per_candidate,
         "loop_seconds_scaled": t.loop_seconds, "speedup": t.speedup, "target_seconds": TARGET_SECONDS}
        for t in timings
    ]


def print_design_bench(timings) -> None:
    """The table of the design section."""
    from rich.table import Table

    from foundation_calc.output.console import stdout

    table = Table(title="Sizing (fcalc design): a search over ~10⁵ candidates, vectorised against a loop over fcalc check",
                  title_justify="left")
    for col in ("scene", "candidates", "search, s", "target", "peak MiB", "loop, ms each", "loop, s scaled", "ratio"):
        table.add_column(col, justify="left" if col == "scene" else "right")
    for t in timings:
        v = t.vectorised
        table.add_row(t.source, f"{t.candidates:,}", "no evaluator" if v is None else f"{v.seconds:.3g}", f"{TARGET_SECONDS:g} s",
                      "-" if v is None else f"{v.peak_bytes / 2**20:.3g}", f"{t.loop_per_candidate * 1e3:.3g}",
                      f"{t.loop_seconds:.4g}", "-" if t.speedup is None else f"{t.speedup:.3g}×")
    stdout().print(table)
