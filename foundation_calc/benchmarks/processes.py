"""Wall time, CPU time and peak memory of one child process (and the workers it starts).

Shared by the start-up and the batch benchmarks: each figure is a whole ``fcalc`` process, as a
user or a CI job runs it.
"""

from __future__ import annotations

import os
import subprocess
import threading
import time
from dataclasses import dataclass
from pathlib import Path

#: Interval of the memory sampling of a process tree [s].
SAMPLE_INTERVAL = 0.02


@dataclass(frozen=True)
class ProcessRun:
    """One finished process.

    Attributes
    ----------
    seconds : wall time from start to exit [s]
    cpu_seconds : user + system time of the process and of the workers it waited for [s]
    peak_bytes : peak resident memory of the largest of them (exact, from the kernel) [bytes]
    tree_peak_bytes : largest sum of the resident memory of the process and its workers, sampled
        every :data:`SAMPLE_INTERVAL` s (pages shared by forked workers count once per process, so
        this bounds the whole from above); None where /proc is not available [bytes]
    returncode : exit code
    """

    seconds: float
    cpu_seconds: float
    peak_bytes: int
    tree_peak_bytes: int | None
    returncode: int


def _rss(pid: int) -> int:
    """Resident memory of ``pid`` and its descendants now [bytes] (0 for a process that is gone)."""
    total = 0
    try:
        with open(f"/proc/{pid}/status", encoding="ascii") as status:
            for line in status:
                if line.startswith("VmRSS:"):
                    total += int(line.split()[1]) * 1024
        for task in Path(f"/proc/{pid}/task").iterdir():
            for child in (task / "children").read_text(encoding="ascii").split():
                total += _rss(int(child))
    except (OSError, ValueError):
        pass
    return total


def run_process(command, env=None, sample_memory: bool = False) -> ProcessRun:
    """Run ``command`` (stdout and stderr discarded) and measure it; with ``sample_memory`` the
    resident memory of its whole process tree is sampled while it runs."""
    peak = [0]
    start = time.perf_counter()
    child = subprocess.Popen(command, stdout=subprocess.DEVNULL, stderr=subprocess.DEVNULL, env=env)
    sampler = None
    if sample_memory and Path("/proc/self/status").exists():
        done = threading.Event()

        def sample() -> None:
            while not done.wait(SAMPLE_INTERVAL):
                peak[0] = max(peak[0], _rss(child.pid))

        sampler = threading.Thread(target=sample, daemon=True)
        sampler.start()
    _, status, usage = os.wait4(child.pid, 0)
    seconds = time.perf_counter() - start
    if sampler is not None:
        done.set()
        sampler.join()
    child.returncode = os.waitstatus_to_exitcode(status)
    return ProcessRun(
        seconds=seconds,
        cpu_seconds=usage.ru_utime + usage.ru_stime,
        peak_bytes=usage.ru_maxrss * 1024,
        tree_peak_bytes=peak[0] if sampler is not None else None,
        returncode=child.returncode,
    )


def bytecode_env(folder: str) -> dict[str, str]:
    """The environment with Python's bytecode cache in ``folder``: the runs measure fcalc as
    installed (modules compiled once), also where PYTHONDONTWRITEBYTECODE is set, without writing
    into the source tree."""
    env = {k: v for k, v in os.environ.items() if k != "PYTHONDONTWRITEBYTECODE"}
    env["PYTHONPYCACHEPREFIX"] = folder
    return env
