"""Timing and peak-memory measurement of one callable."""

from __future__ import annotations

import statistics
import time
import tracemalloc
from collections.abc import Callable
from dataclasses import dataclass


@dataclass(frozen=True)
class Measurement:
    """Median wall time of one call [s] and peak traced memory of one call [bytes]."""

    seconds: float
    peak_bytes: int
    calls: int


def measure(
    fn: Callable[[], object], *, min_time: float = 0.2, max_calls: int = 10_000, min_calls: int = 3, warm_up: bool = True
) -> Measurement:
    """Time ``fn`` by repeated calls (at least ``min_time`` s and ``min_calls`` calls in all, after
    one untimed call when ``warm_up``) and trace one call's memory.

    The median of the per-call times is reported, so a stray slow call (garbage collection,
    another process) does not move the figure.
    """
    if warm_up:
        fn()  # imports, caches
    times: list[float] = []
    start = time.perf_counter()
    while len(times) < max_calls and (time.perf_counter() - start < min_time or len(times) < min_calls):
        t0 = time.perf_counter()
        fn()
        times.append(time.perf_counter() - t0)
    tracemalloc.start()
    try:
        fn()
        _, peak = tracemalloc.get_traced_memory()
    finally:
        tracemalloc.stop()
    return Measurement(seconds=statistics.median(times), peak_bytes=peak, calls=len(times))
