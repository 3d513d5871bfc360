"""Cost of many points: whole ``fcalc`` processes on one scene with 10, 1 000 and 15 000 points.

For a crank scene, copies with ``count`` points spread over the foundation's section are written to
a temporary folder, and ``fcalc amplitudes --json``, ``fcalc amplitudes`` (tables) and
``fcalc check`` are run on each, interleaved, several times. Each row gives the median wall time,
the process's own peak resident memory (:func:`~foundation_calc.benchmarks.processes.run_process`)
and both as a ratio to the fewest points, measured in the same run.
"""

from __future__ import annotations

import math
import statistics
import sys
import tempfile
from dataclasses import dataclass
from pathlib import Path

from foundation_calc.benchmarks.processes import run_process

#: Points per scene, the first one the base of the ratios.
POINT_COUNTS = (10, 1_000, 15_000)

#: Command lines timed, by label (the scene file follows the command's name).
COMMANDS = {"amplitudes --json": ("amplitudes", "--json"), "amplitudes": ("amplitudes",), "check": ("check",)}


@dataclass(frozen=True)
class PointsRow:
    """One command on one scene size: median wall time [s], largest resident memory [bytes]."""

    command: str
    points: int
    seconds: float
    peak_rss_bytes: int
    time_ratio: float
    memory_ratio: float


def scene_with_points(text: str, count: int, size: float, height: float) -> str:
    """``text`` (a crank scene's TOML without points) with ``count`` points on a grid over the
    section: ``size`` [m] wide around C, from ``height`` [m] below C to as far above, in mm; one
    inline table per point keeps 15 000 points well under the 1 MB a scene file may have."""
    side = max(1, math.isqrt(count))
    points = []
    for i in range(count):
        u = size * ((i % side) / max(side - 1, 1) - 0.5)
        h = height * (2.0 * ((i // side) % side) / max(side - 1, 1) - 1.0)
        points.append(f'{{name="p{i}",horizontal={round(u, 3)},height={round(h, 3)}}},')
    return "points = [\n" + "\n".join(points) + "\n]\n" + text  # root keys come before the tables


def _run(args: tuple[str, ...]) -> tuple[float, int]:
    """Wall time [s] and own peak resident memory [bytes] of one process."""
    run = run_process(args)
    if run.returncode not in (0, 1):
        raise RuntimeError(f"{' '.join(args[2:])} exited {run.returncode}")
    return run.seconds, run.peak_bytes


def points_scaling(scene: str, runs: int = 3, counts: tuple[int, ...] = POINT_COUNTS) -> list[PointsRow]:
    """Median time and largest memory of each command at each point count, interleaved.

    ``scene``: a crank_foundation scene file; its own points are replaced.
    """
    import tomli_w

    from foundation_calc.scenes import load_scene, read_toml

    loaded = load_scene(scene, expect="crank_foundation")
    document = read_toml(scene)
    document.pop("points", None)
    base = tomli_w.dumps(document)
    size = math.sqrt(loaded.foundation.base_area)
    samples: dict[tuple[str, int], list[tuple[float, int]]] = {}
    with tempfile.TemporaryDirectory(prefix="fcalc-points-") as folder:
        paths = {}
        for count in counts:
            paths[count] = Path(folder) / f"points_{count}.toml"
            paths[count].write_text(scene_with_points(base, count, size, loaded.foundation.cog_height), "utf-8")
        for _ in range(runs):
            for count in counts:
                for label, (command, *options) in COMMANDS.items():
                    args = (sys.executable, "-m", "foundation_calc", command, str(paths[count]), *options)
                    samples.setdefault((label, count), []).append(_run(args))
    rows = []
    for label in COMMANDS:
        base_time = statistics.median(t for t, _ in samples[label, counts[0]])
        base_memory = max(m for _, m in samples[label, counts[0]])
        for count in counts:
            seconds = statistics.median(t for t, _ in samples[label, count])
            memory = max(m for _, m in samples[label, count])
            rows.append(PointsRow(label, count, seconds, memory, seconds / base_time, memory / base_memory))
    return rows


__all__ = ["COMMANDS", "POINT_COUNTS", "PointsRow", "points_scaling", "scene_with_points"]
