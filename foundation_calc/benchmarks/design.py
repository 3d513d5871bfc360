"""Sizing (``fcalc design``): the search over 10⁵ candidates with the kind's vectorised evaluator,
against a loop over ``fcalc check``'s path (the reference evaluator), measured side by side.

On the first scene of each kind that ``fcalc design`` sizes: a grid of :data:`CANDIDATES`
candidates, the scene's length, width and height each from 0.7 to 1.5 times the given one. The
vectorised side is the whole search (chunks, refinement, the tally of the cheaper failures: what
``fcalc design`` pays before its re-check), wall time (median) and peak traced memory of one
search. The loop side is the reference evaluator on :data:`LOOP_CANDIDATES` of the same
candidates, its time per candidate scaled to the grid. Target: 10⁵ candidates in under 2 s.
"""

from __future__ import annotations

import functools
import importlib
from dataclasses import dataclass

import numpy as np

from foundation_calc.benchmarks.measure import Measurement, measure

#: Candidates of the timed grid, about: 47 values of each dimension, 47³ = 103 823.
CANDIDATES = 100_000

#: Candidates timed through the loop over fcalc check's path.
LOOP_CANDIDATES = 200

#: Target of the vectorised search over :data:`CANDIDATES` [s].
TARGET_SECONDS = 2.0


@dataclass(frozen=True)
class DesignTiming:
    """One scene: the vectorised search (None without a vectorised evaluator) and the loop."""

    source: str
    kind: str
    candidates: int
    vectorised: Measurement | None
    loop_per_candidate: float
    loop_candidates: int

    @property
    def loop_seconds(self) -> float:
        """The loop's time scaled to the whole grid [s]."""
        return self.loop_per_candidate * self.candidates

    @property
    def speedup(self) -> float | None:
        return None if self.vectorised is None else self.loop_seconds / self.vectorised.seconds


def _grid(kind: str, given: dict[str, float]):
    from foundation_calc.checks.design.grid import Range, grid

    side = round(CANDIDATES ** (1 / 3))
    return grid(kind, [Range(key, round(0.7 * value, 3), round(1.5 * value, 3)) for key, value in given.items()],
                points=side + 1)


def benchmark_design(source: str, scene, document, min_time: float) -> DesignTiming:
    """Time the vectorised search and the loop on ``scene`` (module docstring)."""
    from foundation_calc.checks.design import reference
    from foundation_calc.checks.design.apply import given_dimensions, volumes
    from foundation_calc.checks.design.candidates import EVALUATORS
    from foundation_calc.checks.design.search import search

    given = given_dimensions(document)
    searched = _grid(scene.kind, given)
    vectorised = None
    if scene.kind in EVALUATORS:
        evaluate = functools.partial(importlib.import_module(EVALUATORS[scene.kind]).evaluate, scene)
        volume = volumes(scene, given)
        vectorised = measure(lambda: search(searched, evaluate, given, volume=volume), min_time=min_time, min_calls=1,
                             max_calls=3)
    picked = np.linspace(0, searched.size - 1, LOOP_CANDIDATES).astype(int)
    index = np.unravel_index(picked, searched.shape)
    sample = {a.variable.key: a.values[i] for a, i in zip(searched.axes, index)}
    loop = measure(lambda: reference.evaluate(document, sample, source), min_time=0.0, min_calls=1, max_calls=1)
    return DesignTiming(source, scene.kind, searched.size, vectorised, loop.seconds / LOOP_CANDIDATES, LOOP_CANDIDATES)


__all__ = ["CANDIDATES", "LOOP_CANDIDATES", "TARGET_SECONDS", "DesignTiming", "benchmark_design"]
