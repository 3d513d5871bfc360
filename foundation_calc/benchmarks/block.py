"""Run time of a block foundation: one scene's whole computation, and a sweep of 10⁴ speeds.

Measured on each block scene given: :func:`~foundation_calc.checks.amplitudes.machines.check_block` (model,
modes, resonance margins, steady state of every machine at G and every point, peaks, RMS, limits,
zones, office checks), and :func:`~foundation_calc.solvers.block.sweep.speed_sweep` of its first
machine over 10⁴ speeds from 0.2 to 2 times its own. Targets: 10 ms and 1 s. Wall time (median)
and the process's CPU time per call (the machine may be shared: CPU time is what fcalc costs).
"""

from __future__ import annotations

import time
from dataclasses import dataclass

import numpy as np

from foundation_calc.benchmarks.measure import Measurement, measure

#: Speeds of the sweep measured.
SWEEP_SPEEDS = 10_000


@dataclass(frozen=True)
class BlockTiming:
    """Times of one block scene [s]."""

    source: str
    scene_wall: Measurement
    scene_cpu: float
    sweep_wall: Measurement
    sweep_cpu: float


def _cpu_per_call(fn, calls: int) -> float:
    start = time.process_time()
    for _ in range(calls):
        fn()
    return (time.process_time() - start) / calls


def benchmark_block(source: str, scene, min_time: float) -> BlockTiming:
    """Time ``scene``'s check and a sweep of its first machine's speed (module docstring)."""
    from foundation_calc.checks.amplitudes.machines import check_block
    from foundation_calc.solvers.block.response import block_modes
    from foundation_calc.solvers.block.sweep import speed_sweep

    model = scene.model()
    excitations = scene.excitations()
    modes = block_modes(model)
    points = [p.at for p in scene.points]
    omega = np.linspace(0.2, 2.0, SWEEP_SPEEDS) * excitations[0].omega

    def whole():
        check_block(scene.model_copy())  # a new scene object: check_block keeps the last one's report

    def sweep():
        speed_sweep(model, modes, excitations, 0, omega, points)

    scene_wall = measure(whole, min_time=min_time)
    sweep_wall = measure(sweep, min_time=min_time, max_calls=20)
    return BlockTiming(source, scene_wall, _cpu_per_call(whole, scene_wall.calls), sweep_wall, _cpu_per_call(sweep, 3))


__all__ = ["SWEEP_SPEEDS", "BlockTiming", "benchmark_block"]
