"""``fcalc check`` on many scenes, measured in one run: the marginal cost of a platform scene, the
scaling with ``--jobs`` and the peak memory of a large batch.

Every figure is a whole ``fcalc check`` process (start-up included, as a CI job runs it) on copies
of the given scenes written to a temporary folder, never into the project. The small runs (one
platform scene; N platform scenes with one job and with two) are repeated interleaved and compared
by their medians; the large batch (all given scenes, copied round-robin) runs once with the default
jobs (the core count), its memory sampled over the whole process tree.
"""

from __future__ import annotations

import os
import shutil
import statistics
import sys
import tempfile
from collections.abc import Callable, Sequence
from dataclasses import dataclass
from pathlib import Path

from foundation_calc.benchmarks.processes import ProcessRun, bytecode_env, run_process


@dataclass(frozen=True)
class BatchRow:
    """One ``fcalc check`` command line: scenes, jobs and its median measurements (seconds), the
    largest peaks over its runs (bytes; see :class:`~foundation_calc.benchmarks.processes.ProcessRun`)."""

    label: str
    scenes: int
    jobs: int
    seconds: float
    cpu_seconds: float
    peak_bytes_largest_process: int
    peak_bytes_all_processes: int | None
    runs: int


@dataclass(frozen=True)
class BatchBenchmark:
    """The rows and the ratios between them, all measured in this run.

    Attributes
    ----------
    one, many, many_two_jobs, large : the rows (``large`` None when not run)
    marginal_seconds : (t(N) - t(1)) / (N - 1), one job: what one more platform scene costs [s]
    marginal_cpu_seconds : the same in CPU time, which other work on the machine disturbs less [s]
    many_over_one : t(N) / t(1), one job [-]
    cpu_many_over_one : the same in CPU time [-]
    many_two_jobs_over_one : t(N) with two jobs / t(1) [-]
    jobs_speedup : t(N, one job) / t(N, two jobs) [-]
    """

    one: BatchRow
    many: BatchRow
    many_two_jobs: BatchRow
    large: BatchRow | None

    @property
    def marginal_seconds(self) -> float:
        return (self.many.seconds - self.one.seconds) / (self.many.scenes - 1)

    @property
    def marginal_cpu_seconds(self) -> float:
        return (self.many.cpu_seconds - self.one.cpu_seconds) / (self.many.scenes - 1)

    @property
    def many_over_one(self) -> float:
        return self.many.seconds / self.one.seconds

    @property
    def cpu_many_over_one(self) -> float:
        return self.many.cpu_seconds / self.one.cpu_seconds

    @property
    def many_two_jobs_over_one(self) -> float:
        return self.many_two_jobs.seconds / self.one.seconds

    @property
    def jobs_speedup(self) -> float:
        return self.many.seconds / self.many_two_jobs.seconds


def _copies(sources: Sequence[Path], count: int, folder: Path) -> Path:
    """``count`` copies of ``sources`` (round-robin) in ``folder``, named so that a folder search
    finds them in the order written."""
    folder.mkdir()
    for i in range(count):
        source = sources[i % len(sources)]
        shutil.copyfile(source, folder / f"{i:06d}_{source.name}")
    return folder


def _row(label: str, scenes: int, jobs: int, runs: list[ProcessRun]) -> BatchRow:
    tree = [r.tree_peak_bytes for r in runs if r.tree_peak_bytes is not None]
    return BatchRow(
        label,
        scenes,
        jobs,
        statistics.median(r.seconds for r in runs),
        statistics.median(r.cpu_seconds for r in runs),
        max(r.peak_bytes for r in runs),
        max(tree) if tree else None,
        len(runs),
    )


def batch_benchmark(
    platform_scene: Path,
    scenes: Sequence[Path],
    many: int = 100,
    large: int = 10_000,
    repeats: int = 5,
    on_step: Callable[[str], None] = lambda text: None,
) -> BatchBenchmark:
    """Measure ``fcalc check`` on 1 and ``many`` copies of ``platform_scene`` (one job, then two)
    ``repeats`` times interleaved, and once on ``large`` copies of ``scenes`` (0: not run)."""
    check = (sys.executable, "-m", "foundation_calc", "check")
    with tempfile.TemporaryDirectory(prefix="fcalc-bench-batch-") as tmp:
        root = Path(tmp)
        env = bytecode_env(str(root / "bytecode"))
        one = _copies([platform_scene], 1, root / "one")
        batch = _copies([platform_scene], many, root / "many")
        commands = {
            "one": (*check, str(one), "--jobs", "1"),
            "many": (*check, str(batch), "--jobs", "1"),
            "many_two_jobs": (*check, str(batch), "--jobs", "2"),
        }
        samples: dict[str, list[ProcessRun]] = {key: [] for key in commands}
        on_step(f"batch: fcalc check of 1 and {many} platform scenes, 1 and 2 jobs, {repeats} rounds")
        for round_ in range(repeats + 1):  # round 0 fills the bytecode cache
            for key, command in commands.items():
                run = run_process(command, env, sample_memory=True)
                if round_:
                    samples[key].append(run)
        large_row = None
        if large:
            on_step(f"batch: fcalc check of {large} scenes, {os.cpu_count() or 1} jobs")
            big = _copies(list(scenes), large, root / "large")
            run = run_process((*check, str(big)), env, sample_memory=True)
            large_row = _row(f"{large} scenes (given scenes, round-robin)", large, os.cpu_count() or 1, [run])
    name = platform_scene.name
    return BatchBenchmark(
        _row(f"1 × {name}", 1, 1, samples["one"]),
        _row(f"{many} × {name}", many, 1, samples["many"]),
        _row(f"{many} × {name}", many, 2, samples["many_two_jobs"]),
        large_row,
    )
