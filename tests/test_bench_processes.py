"""The bench's process measurements: each process's own peak memory, workers summed.

The reference is what the measured programs allocate: numpy arrays of known size, touched so that
every page is resident; the interpreter's own ~10-30 MB is the tolerance.
"""

from __future__ import annotations

import sys

import numpy as np

from foundation_calc.benchmarks.processes import run_process

MB = 1 << 20


def test_a_small_process_started_from_a_large_one_reads_its_own_peak():
    ballast = np.ones(400 * MB // 8)  # the measuring process holds 400 MB
    run = run_process((sys.executable, "-c", "pass"))
    assert ballast.sum() > 0 and run.returncode == 0
    assert run.peak_bytes < 100 * MB


def test_workers_are_summed_with_their_parent():
    worker = "import numpy as np, time; a = np.ones(80 * 2**20 // 8); time.sleep(0.5)"
    parent = f"import subprocess, sys; subprocess.run([sys.executable, '-c', {worker!r}])"
    run = run_process((sys.executable, "-c", parent), sample_memory=True)
    assert run.returncode == 0
    assert run.peak_bytes >= 80 * MB  # the largest process: the worker with its 80 MB array
    assert run.tree_peak_bytes >= run.peak_bytes + 5 * MB  # and the parent interpreter beside it
