"""Wall time, CPU time and peak memory of one child process (and the workers it starts).

Shared by the start-up, points and batch benchmarks: each figure is a whole ``fcalc`` process, as
a user or a CI job runs it.

Each process's own peak. Linux's ``ru_maxrss`` of a process is the larger of its own peak and
the resident size of the process it was forked from at the fork (the kernel keeps the old
memory's high-water mark across ``exec``): a command started from the bench, whose own memory
grows to hundreds of MB, would read that size whatever it did. So a command is started by a
small launcher (a fresh interpreter, about 10 MB), which reports the command's ``wait4`` usage;
the figure is then the largest own peak of the command and of the workers it waited for (``wait4``
reports the largest of them), or the launcher's 10 MB, below any Python process. The sum over
the processes is read while they run from ``/proc/PID/status`` (``VmHWM``, each process's own
high-water mark).
"""

from __future__ import annotations

import json
import os
import subprocess
import sys
import threading
from dataclasses import dataclass
from pathlib import Path

#: Interval of the sampling of the workers' peaks [s].
SAMPLE_INTERVAL = 0.02

#: Runs the command of argv[1:] (output discarded), prints its pid at once, then its wall time
#: [s], exit code, CPU time [s] (its own and that of the workers it waited for) and ru_maxrss [kB].
LAUNCHER = """
import json, os, subprocess, sys, time
start = time.perf_counter()
child = subprocess.Popen(sys.argv[1:], stdout=subprocess.DEVNULL, stderr=subprocess.DEVNULL)
print(child.pid, flush=True)
_, status, usage = os.wait4(child.pid, 0)
seconds = time.perf_counter() - start
print(json.dumps([seconds, os.waitstatus_to_exitcode(status), usage.ru_utime + usage.ru_stime, usage.ru_maxrss]))
"""


@dataclass(frozen=True)
class ProcessRun:
    """One finished process.

    Attributes
    ----------
    seconds : wall time from start to exit [s]
    cpu_seconds : user + system time of the process and of the workers it waited for [s]
    peak_bytes : the largest own peak resident memory of the process and of the workers it
        waited for (exact, from the kernel) [bytes]
    tree_peak_bytes : the sum of the own peaks of the process and of every worker it started
        (each one's ``VmHWM`` as last read, every :data:`SAMPLE_INTERVAL` s, the largest one
        raised to ``peak_bytes``): at least ``peak_bytes``, and an upper bound of their
        simultaneous total (pages shared by forked workers count once per process; workers
        that do not overlap in time count all); None where /proc is not available [bytes]
    returncode : exit code
    """

    seconds: float
    cpu_seconds: float
    peak_bytes: int
    tree_peak_bytes: int | None
    returncode: int


def _high_water(pid: int) -> int:
    """``VmHWM`` of ``pid`` [bytes] (0 for a process that is gone)."""
    try:
        with open(f"/proc/{pid}/status", encoding="ascii") as status:
            for line in status:
                if line.startswith("VmHWM:"):
                    return int(line.split()[1]) * 1024
    except (OSError, ValueError):
        pass
    return 0


def _descendants(pid: int) -> list[int]:
    """The processes started by ``pid`` and by them, now."""
    found = []
    try:
        for task in Path(f"/proc/{pid}/task").iterdir():
            for child in (task / "children").read_text(encoding="ascii").split():
                found += [int(child), *_descendants(int(child))]
    except (OSError, ValueError):
        pass
    return found


def run_process(command, env=None, sample_memory: bool = False) -> ProcessRun:
    """Run ``command`` (stdout and stderr discarded) through the launcher and measure it; with
    ``sample_memory`` the peaks of the workers it starts are read while it runs."""
    with subprocess.Popen((sys.executable, "-c", LAUNCHER, *command), stdout=subprocess.PIPE, env=env, text=True) as launcher:
        pid = int(launcher.stdout.readline())
        seen: dict[int, int] = {}
        sampler = None
        if sample_memory and Path("/proc/self/status").exists():
            done = threading.Event()

            def sample() -> None:
                while not done.wait(SAMPLE_INTERVAL):
                    for process in (pid, *_descendants(pid)):
                        seen[process] = max(seen.get(process, 0), _high_water(process))

            sampler = threading.Thread(target=sample, daemon=True)
            sampler.start()
        seconds, returncode, cpu, max_rss = json.loads(launcher.stdout.read())
    if sampler is not None:  # the launcher has exited (the with block waits for it and closes its pipe)
        done.set()
        sampler.join()
    largest = max_rss * 1024  # Linux reports kilobytes
    tree = None
    if sampler is not None:  # the largest process's peak may have come after its last reading
        tree = sum(seen.values()) + max(0, largest - max(seen.values(), default=0))
    return ProcessRun(seconds=seconds, cpu_seconds=cpu, peak_bytes=largest, tree_peak_bytes=tree, returncode=returncode)


def bytecode_env(folder: str) -> dict[str, str]:
    """The environment with Python's bytecode cache in ``folder``: the runs measure fcalc as
    installed (modules compiled once), also where PYTHONDONTWRITEBYTECODE is set, without writing
    into the source tree."""
    env = {k: v for k, v in os.environ.items() if k != "PYTHONDONTWRITEBYTECODE"}
    env["PYTHONPYCACHEPREFIX"] = folder
    return env
