"""The sizing search: the cheapest candidate that passes every check, the Pareto set of volume
against worst margin, why the cheaper candidates fail, and a finer grid around the cheapest.

Objective: the block's concrete volume (its mass is volume × density). A candidate passes when no
check fails (a warning passes, as in ``fcalc check``; with ``strict`` it fails) and, with a
reserve ``margin``, every utilisation is at most 1 - margin (:mod:`.reserve`). The grid is
walked in chunks (:meth:`~.grid.Grid.chunk`): per chunk the evaluator judges every candidate at
once, and only the running results are kept (the cheapest passing candidate, the Pareto front,
the candidate closest to passing, a thinned sample for the plot), so memory is bounded by the
chunk. A second walk tallies the governing failure of every candidate cheaper than the chosen one
(evaluating those alone; the volume needs no check).

Refinement: around the cheapest passing grid candidate, each varied key again over one grid step
either side at a :data:`REFINE` times finer step (the caller may choose a coarser factor for a
slow evaluator); of those, the candidates cheaper than it are judged (no other can be the
answer), and a cheaper passing one is the answer. The search says the step it reached; cheaper designs further from the grid's cheapest,
between its points, are not looked for.

Pareto set: among the passing candidates, those that no other passing candidate beats on both
volume (smaller) and worst margin (larger), cheapest first.

Candidates that cannot be evaluated: where the evaluator raises an error of a design's physics
(:data:`UNEVALUABLE`, what ``fcalc check`` reports as an invalid scene, or arithmetic that fails)
on a batch, the batch is halved until the candidates that raise are alone (:meth:`_Walk.judge`;
k of them in a chunk of N cost about N log2(4k) candidates' evaluations, none when every
candidate can be evaluated). Those are counted by the error's kind with an example
(``Search.unevaluated``), left out of the search and never chosen; the others are judged as
usual. One candidate never ends a search; a search of which no candidate can be evaluated raises
the first error.

Deferred checks: a check the evaluator does not evaluate (``CandidateVerdicts.deferred``, such as
a run-up integrated in time) is judged by the full path (``confirm``, one
:func:`~foundation_calc.checks.batch.run_checks` a candidate): the candidates that pass the
batch's checks are taken in order of volume and confirmed one by one until one passes every
check, at most ``bound`` of them (:data:`CONFIRM`); the refinement then looks around that one, its
cheaper batch-passing candidates confirmed the same way. The Pareto set is then the confirmed
design and the batch's front above it, which the caller re-checks by the full path.
"""

from __future__ import annotations

import math
import time
from collections.abc import Callable
from dataclasses import dataclass, field

import numpy as np

from foundation_calc.checks.design.candidates import Batch, CandidateVerdicts, concatenated
from foundation_calc.checks.design.grid import DECIMALS, Grid
from foundation_calc.checks.design.reserve import failing_checks
from foundation_calc.errors import FcalcError

#: Candidates judged at once: bounds the memory of a search (about 4 kB a candidate of a block
#: scene: 42 MiB peak; larger chunks are no faster).
CHUNK = 10_000

#: Refinement: the step around the cheapest design is the grid's step over this.
REFINE = 5

#: Points of the volume-margin sample kept for the plot.
SAMPLE = 20_000

#: Candidates confirmed by the full path at most, when the evaluator defers a check: a run-up
#: costs 0.1-10 s a candidate.
CONFIRM = 20

Evaluate = Callable[[Batch], CandidateVerdicts]

#: batch -> (n,) the candidates' concrete volume [m³].
Volume = Callable[[Batch], np.ndarray]

#: Errors by which an evaluator says that a candidate cannot be evaluated (module docstring): an
#: error fcalc reports of a design (:class:`~foundation_calc.errors.FcalcError`: a block that
#: cannot be built or computed), arithmetic that fails, a singular matrix. Any other error is a
#: bug and ends the search.
UNEVALUABLE = (FcalcError, ArithmeticError, np.linalg.LinAlgError)


@dataclass
class Front:
    """Candidates by their values, volume and worst margin (NaN margins rank lowest)."""

    values: dict[str, np.ndarray]
    volume: np.ndarray
    margin: np.ndarray

    @classmethod
    def empty(cls, keys) -> "Front":
        return cls({k: np.empty(0) for k in keys}, np.empty(0), np.empty(0))

    def take(self, index) -> "Front":
        return Front({k: v[index] for k, v in self.values.items()}, self.volume[index], self.margin[index])

    def joined(self, other: "Front") -> "Front":
        return Front({k: np.concatenate([v, other.values[k]]) for k, v in self.values.items()},
                     np.concatenate([self.volume, other.volume]), np.concatenate([self.margin, other.margin]))

    def pareto(self) -> "Front":
        """The non-dominated candidates (smaller volume, larger margin), cheapest first."""
        margin = np.nan_to_num(self.margin, nan=-np.inf)
        order = np.lexsort((-margin, self.volume))
        best_before = np.maximum.accumulate(np.concatenate([[-np.inf], margin[order]]))[:-1]
        return self.take(order[margin[order] > best_before])

    def cheapest(self) -> "Front":
        """The cheapest candidate (the larger margin among equal volumes), or an empty front."""
        return self.pareto().take(slice(0, 1))

    def by_volume(self, count: int) -> "Front":
        """The ``count`` cheapest candidates, cheapest first (the larger margin among equal volumes)."""
        order = np.lexsort((-np.nan_to_num(self.margin, nan=-np.inf), self.volume))
        return self.take(order[:count])

    def safest(self) -> "Front":
        """The candidate of the largest worst margin (the cheaper among equals)."""
        if not len(self.volume):
            return self
        margin = np.nan_to_num(self.margin, nan=-np.inf)
        order = np.lexsort((self.volume, -margin))
        return self.take(order[:1])

    def design(self, i: int) -> dict[str, float]:
        return {k: float(v[i]) for k, v in self.values.items()}


def passing(verdicts: CandidateVerdicts, strict: bool, margin: float | None = None) -> np.ndarray:
    """(N,) True where no check fails (nor warns, with ``strict``), nor exceeds the reserve ``margin``."""
    return ~np.any(np.stack(list(failing_checks(verdicts, strict, margin).values())), axis=0)


def worst_margin(verdicts: CandidateVerdicts) -> np.ndarray:
    """(N,) worst margin, NaN where no check judges a number (without a warning for those)."""
    stacked = np.stack(list(verdicts.utilisation.values()))
    judged = ~np.all(np.isnan(stacked), axis=0)
    out = np.full(stacked.shape[1], np.nan)
    out[judged] = 1.0 - np.nanmax(stacked[:, judged], axis=0)
    return out


def failure_tally(verdicts: CandidateVerdicts, strict: bool, margin: float | None = None) -> dict[str, int]:
    """How many candidates each ``"check: reason"`` governs among those that do not pass: the most
    utilised failing check of each (the first failing one in the checks' order when none has a number;
    a check short of the reserve ``margin`` fails)."""
    names = list(verdicts.outcome)
    failing = np.stack(list(failing_checks(verdicts, strict, margin).values()))
    ranked = np.where(failing, np.nan_to_num(np.stack([verdicts.utilisation[n] for n in names]), nan=-1.0), -np.inf)
    top = np.argmax(ranked, axis=0)
    columns = np.arange(top.size)
    fails = failing[top, columns]
    governing = np.stack([verdicts.governing[n] for n in names])[top, columns]
    pairs, counts = np.unique(np.stack([top[fails], governing[fails]]), axis=1, return_counts=True)
    return {f"{names[c]}: {verdicts.reasons[names[c]][g]}": int(n) for (c, g), n in zip(pairs.T, counts)}


def _add_counts(total: dict[str, int], more: dict[str, int]) -> None:
    for key, count in more.items():
        total[key] = total.get(key, 0) + count


@dataclass
class Search:
    """What a search found (module docstring). ``best`` and ``closest`` are one-candidate fronts
    (empty when there is none); ``fails_everywhere``: checks that fail on every candidate;
    ``cheaper_failures``: ``"check: reason"`` -> count over the candidates cheaper than ``best``
    (every candidate when none passes); ``refined_steps``: key -> the refined step (empty without
    refinement); ``sample``: a thinned (volume, margin, passes) of the grid for the plot;
    ``deferred``: the checks the evaluator left to the full path, ``confirmations`` how many
    candidates that path judged (at most ``bound``), ``deferred_failures`` the ``"check: reason"``
    governing those it failed (``deferred_failed`` of them; those on the grid are also in
    ``cheaper_failures``), ``unconfirmed`` how many candidates that pass the batch's checks it never
    judged when none it judged passes (0 otherwise); ``margin``: the reserve asked of every
    utilisation (None: none, fcalc check's rule); ``unevaluated``: the kind of error ->
    (how many candidates raised it, the first one's values, its message) of the candidates that
    could not be evaluated (module docstring), each counted once."""

    grid: Grid
    strict: bool
    evaluated: int = 0
    best: Front | None = None
    pareto: Front | None = None
    closest: Front | None = None
    fail_counts: dict[str, int] = field(default_factory=dict)
    cheaper_failures: dict[str, int] = field(default_factory=dict)
    cheaper_count: int = 0
    refined_steps: dict[str, float] = field(default_factory=dict)
    refined_candidates: int = 0
    improved_by_refinement: bool = False
    sample: tuple[np.ndarray, np.ndarray, np.ndarray] | None = None
    seconds: float = 0.0
    chunks: int = 0
    deferred: tuple[str, ...] = ()
    bound: int = CONFIRM
    confirmations: int = 0
    deferred_failed: int = 0
    deferred_failures: dict[str, int] = field(default_factory=dict)
    unconfirmed: int = 0
    margin: float | None = None
    unevaluated: dict[str, tuple[int, dict[str, float], str]] = field(default_factory=dict)
    first_error: Exception | None = field(default=None, repr=False)

    def passes(self, verdicts: CandidateVerdicts) -> np.ndarray:
        """(N,) True where a candidate passes (:func:`passing` with this search's rule)."""
        return passing(verdicts, self.strict, self.margin)

    def tally(self, verdicts: CandidateVerdicts) -> dict[str, int]:
        """:func:`failure_tally` with this search's rule."""
        return failure_tally(verdicts, self.strict, self.margin)

    @property
    def unevaluated_count(self) -> int:
        """How many candidates could not be evaluated."""
        return sum(count for count, _, _ in self.unevaluated.values())

    def skipped(self, batch: Batch, error: Exception) -> None:
        """Count the one candidate ``batch`` that raised ``error`` (module docstring)."""
        kind = type(error).__name__
        count, example, message = self.unevaluated.get(kind, (0, {k: float(v[0]) for k, v in batch.items()}, str(error)))
        self.unevaluated[kind] = (count + 1, example, message)
        self.first_error = self.first_error or error

    @property
    def found(self) -> bool:
        return self.best is not None and len(self.best.volume) > 0

    @property
    def at_range_end(self) -> dict[str, str]:
        """Varied key -> ``"low"`` or ``"high"``: the ends of their ranges the cheapest design takes.
        A cheaper design may lie beyond them (below a low end plainly; above a high end when more
        of one dimension lets the others shrink)."""
        if not self.found:
            return {}
        best = self.best.design(0)
        ends = {}
        for a in self.grid.axes:
            value = best[a.variable.key]
            if len(a.values) > 1 and value in (a.values[0], a.values[-1]):
                ends[a.variable.key] = "low" if value == a.values[0] else "high"
        return ends

    @property
    def fails_everywhere(self) -> list[str]:
        return [name for name, count in self.fail_counts.items() if count == self.evaluated]


def _front(batch: Batch, verdicts: CandidateVerdicts, mask: np.ndarray) -> Front:
    return Front({k: np.asarray(v)[mask] for k, v in batch.items()}, verdicts.volume[mask], worst_margin(verdicts)[mask])


class _Walk:
    """The running results of one search over batches."""

    def __init__(self, found: Search, evaluate: Evaluate):
        keys = found.grid.keys
        self.found, self.evaluate = found, evaluate
        self.passed, self.all_best = Front.empty(keys), Front.empty(keys)
        self.samples: list[tuple[np.ndarray, np.ndarray, np.ndarray]] = []
        self.thin = max(1, math.ceil(found.grid.size / SAMPLE))
        self.failures: dict[str, int] = {}
        self.queue, self.queued = Front.empty(keys), 0

    def judge(self, batch: Batch, count: bool = True) -> tuple[Batch, CandidateVerdicts | None]:
        """``evaluate`` on the candidates of ``batch`` that can be evaluated, and those candidates
        (None for the verdicts when none can): a batch that raises an error of :data:`UNEVALUABLE`
        is halved until the candidates that raise it are alone, each counted in
        ``Search.unevaluated`` when ``count`` (the first time the search meets it)."""
        try:
            return batch, self.evaluate(batch)
        except UNEVALUABLE as error:
            size = len(next(iter(batch.values())))
            if size == 1:
                if count:
                    self.found.skipped(batch, error)
                return batch, None
        halves = [self.judge({k: np.asarray(v)[part] for k, v in batch.items()}, count)
                  for part in (slice(0, size // 2), slice(size // 2, None))]
        judged = [(part, verdicts) for part, verdicts in halves if verdicts is not None]
        if not judged:
            return batch, None
        return ({k: np.concatenate([part[k] for part, _ in judged]) for k in batch},
                concatenated([verdicts for _, verdicts in judged]))

    def add(self, batch: Batch) -> None:
        batch, verdicts = self.judge(batch)
        if verdicts is None:
            return
        ok = self.found.passes(verdicts)
        self.passed = self.passed.joined(_front(batch, verdicts, ok)).pareto()
        if verdicts.deferred:  # the cheapest that pass the batch's checks, for the full path
            self.found.deferred = verdicts.deferred
            self.queue = self.queue.joined(_front(batch, verdicts, ok)).by_volume(self.found.bound)
            self.queued += int(np.count_nonzero(ok))
        self.all_best = self.all_best.joined(_front(batch, verdicts, np.ones(ok.shape, bool)).safest()).safest()
        for name, fails in failing_checks(verdicts, self.found.strict, self.found.margin).items():
            self.found.fail_counts[name] = self.found.fail_counts.get(name, 0) + int(np.count_nonzero(fails))
        if not len(self.passed.volume):  # the tally over every candidate, while none passes
            _add_counts(self.failures, self.found.tally(verdicts))
        self.found.evaluated += len(ok)
        self.found.chunks += 1
        keep = slice(None, None, self.thin)
        self.samples.append((verdicts.volume[keep], worst_margin(verdicts)[keep], ok[keep]))


def _refinement_batch(grid: Grid, best: dict[str, float], factor: int) -> tuple[dict[str, np.ndarray], dict[str, float]]:
    """The finer grid around ``best``: each key over one grid step either side (within its range)."""
    columns, steps = [], {}
    for a in grid.axes:
        key, step = a.variable.key, a.step
        if step == 0:
            columns.append(np.array([best[key]]))
            continue
        fine = round(step / factor, 9)
        low, high = max(best[key] - step, a.values[0]), min(best[key] + step, a.values[-1])
        columns.append(np.round(np.linspace(low, high, int(round((high - low) / fine)) + 1), DECIMALS))
        steps[key] = fine
    mesh = np.meshgrid(*columns, indexing="ij")
    return {a.variable.key: m.ravel() for a, m in zip(grid.axes, mesh)}, steps


def block_volume(given: dict[str, float]) -> Volume:
    """The candidates' volume [m³] when ``given`` are a block's three dimensions (by varied key)
    and nothing else adds concrete: their product."""
    def volume(batch: Batch) -> np.ndarray:
        out = np.ones(len(next(iter(batch.values()))))
        for key, value in given.items():
            out = out * (batch[key] if key in batch else value)
        return out

    return volume


def _confirmed(found: Search, queue: Front, confirm: Evaluate, on_grid: dict[str, int]) -> Front:
    """The first of ``queue`` (cheapest first) that passes ``confirm`` (the full path), or an empty
    front; the failing ones it judges tallied into ``found`` and into ``on_grid``."""
    for i in range(len(queue.volume)):
        if found.confirmations >= found.bound:
            break
        one = queue.take(slice(i, i + 1))
        full = confirm({k: np.asarray(v) for k, v in one.values.items()})
        found.confirmations += 1
        if found.passes(full)[0]:
            return one
        tally = found.tally(full)
        found.deferred_failed += 1
        _add_counts(found.deferred_failures, tally)
        _add_counts(on_grid, tally)
    return queue.take(slice(0, 0))


def _refine(found: Search, walk: _Walk, around: Front, volume: Volume, chunk: int, refine: int,
            confirm: Evaluate | None) -> Front:
    """The cheapest design after the refinement around ``around`` (module docstring)."""
    grid = found.grid
    batch, found.refined_steps = _refinement_batch(grid, around.design(0), refine)
    before = around.volume[0]
    cheaper = volume(batch) < before
    batch = {k: v[cheaper] for k, v in batch.items()}
    queue = Front.empty(grid.keys)
    for first in range(0, len(next(iter(batch.values()))), chunk):
        part, verdicts = walk.judge({k: v[first:first + chunk] for k, v in batch.items()})
        if verdicts is None:
            continue
        ok = found.passes(verdicts)
        walk.passed = walk.passed.joined(_front(part, verdicts, ok)).pareto()
        queue = queue.joined(_front(part, verdicts, ok)).by_volume(found.bound)
        found.refined_candidates += len(ok)
    best = walk.passed.cheapest()
    if found.deferred and confirm is not None:
        best = _confirmed(found, queue, confirm, {})
        best = best if len(best.volume) else around
    found.improved_by_refinement = bool(best.volume[0] < before)
    return best


def search(grid: Grid, evaluate: Evaluate, given: dict[str, float], strict: bool = False, chunk: int = CHUNK,
           refine: int = REFINE, confirm: Evaluate | None = None, bound: int = CONFIRM,
           margin: float | None = None, volume: Volume | None = None) -> Search:
    """Walk ``grid`` in chunks of ``chunk`` with ``evaluate`` (module docstring). ``given``: the
    scene's block dimensions by varied key [m]; ``volume``: batch -> (n,) the candidates' volume
    [m³] as ``evaluate`` finds it, to pass over those no cheaper before judging them (default
    :func:`block_volume` of ``given``);
    ``refine``: the refinement's factor on the grid step (0 or 1: no refinement); ``confirm``: the
    full path, which judges the checks ``evaluate`` defers, on at most ``bound`` candidates;
    ``margin``: the reserve asked of every utilisation [-] (None: none)."""
    start = time.perf_counter()
    volume = block_volume(given) if volume is None else volume
    found = Search(grid, strict, bound=bound, margin=margin)
    walk = _Walk(found, evaluate)
    for first in range(0, grid.size, chunk):
        walk.add(grid.chunk(first, first + chunk))
    if not found.evaluated and found.first_error is not None:
        raise found.first_error  # nothing to report: no candidate could be evaluated
    best, on_grid = walk.passed.cheapest(), {}
    if found.deferred and confirm is not None:
        best = _confirmed(found, walk.queue, confirm, on_grid)
        if not len(best.volume):
            found.unconfirmed = walk.queued - found.confirmations
    if len(best.volume) and refine > 1 and any(a.step for a in grid.axes):
        best = _refine(found, walk, best, volume, chunk, refine, confirm)
    found.best = best
    found.pareto = walk.passed
    if found.deferred and confirm is not None and len(best.volume):  # the confirmed design, the batch's front above it
        found.pareto = best.joined(walk.passed.take(walk.passed.volume > best.volume[0]))
    unjudged = found.deferred and not found.found and len(walk.queue.volume)
    found.closest = walk.queue.take(slice(0, 1)) if unjudged else walk.all_best
    found.sample = tuple(np.concatenate(parts) for parts in zip(*walk.samples))
    if found.found or unjudged:
        _tally_cheaper(found, walk, volume, chunk, best.volume[0] if found.found else np.inf)
        _add_counts(found.cheaper_failures, on_grid)
    else:
        found.cheaper_failures, found.cheaper_count = walk.failures, found.evaluated
    found.seconds = time.perf_counter() - start
    return found


def _tally_cheaper(found: Search, walk: _Walk, volume: Volume, chunk: int, limit: float) -> None:
    """``cheaper_failures``: the governing failure of each grid candidate cheaper than ``limit``
    [m³] that fails the batch's checks (those cheaper judged again, the others skipped; those
    that cannot be evaluated, counted already, left out)."""
    grid = found.grid
    for first in range(0, grid.size, chunk):
        batch = grid.chunk(first, first + chunk)
        cheaper = volume(batch) < limit
        if not cheaper.any():
            continue
        _, verdicts = walk.judge({k: v[cheaper] for k, v in batch.items()}, count=False)
        if verdicts is not None:
            _add_counts(found.cheaper_failures, found.tally(verdicts))
            found.cheaper_count += len(verdicts.volume)


def thinned(front: Front, count: int) -> Front:
    """At most ``count`` members of a front, evenly spread over it, its first and last kept."""
    size = len(front.volume)
    if size <= count:
        return front
    return front.take(np.unique(np.round(np.linspace(0, size - 1, count)).astype(int)))


__all__ = ["CHUNK", "Front", "REFINE", "SAMPLE", "Search", "UNEVALUABLE", "Volume", "block_volume", "failure_tally", "passing",
           "search", "thinned",
           "worst_margin"]
