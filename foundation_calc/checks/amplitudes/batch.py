"""The amplitude check on a batch of N candidate designs at once (``fcalc design``), for every
scene kind: what :func:`~foundation_calc.checks.amplitudes.report.judge` judges of one steady
state, as the arrays of the batch's verdicts (:class:`~foundation_calc.checks.design.candidates.CandidateVerdicts`).

A kind's engine hands in its values (each limited quantity of every point and direction, one
array over the batch) and which candidates have no steady state; the judging is done here once:

- each ``[limits]`` quantity (:func:`~foundation_calc.checks.limits.limited_quantities`) of every
  point and direction against its limit, a value above it failing
  (:func:`~foundation_calc.checks.limits.exceeds`), the ratio value/limit its utilisation;
- ``[limits] code``: each point's zone by the larger of its RMS velocity and RMS displacement
  over the directions (:func:`code_zones`);
- the code's application (:func:`~foundation_calc.checks.codes.code_warnings`: a machine's speed
  or power outside the code's group warns, the zones may not apply);
- a candidate without a steady state fails with utilisation inf
  (:func:`~foundation_calc.checks.design.candidates.failing`).

The utilisation is the largest ratio over the rows, the governing index its row's
(:func:`~foundation_calc.checks.design.candidates.largest_ratio`).
"""

from __future__ import annotations

from collections.abc import Callable, Sequence

import numpy as np


def code_zones(limits, velocity, displacement):
    """(the code's table, zone outcome int8 of :data:`~foundation_calc.checks.design.candidates.PASS`
    ... ``FAIL``, utilisation [-]) of the points' largest RMS ``velocity`` [m/s] and ``displacement``
    [m] (arrays of one shape, e.g. (N, points)) under ``limits`` (``[limits] code``).

    Each point's zone is the worse of its velocity's and its displacement's
    (:func:`~foundation_calc.checks.codes.code_zone_index`, the more restrictive decides), its
    outcome the zone's (:func:`~foundation_calc.checks.codes.zone_verdicts`: beyond the acceptable
    zone fails; with none given, zone B warns, C and D fail) and its utilisation the deciding
    quantity over the boundary of the highest acceptable zone (B by default)."""
    from foundation_calc.checks.codes import TABLES, ZONES, code_zone_index, zone_verdicts
    from foundation_calc.checks.design.candidates import FAIL, PASS, WARN

    table = TABLES[limits.code, limits.machine_group, limits.foundation]
    highest = ZONES.index(limits.acceptable_zone or "B")
    index, by_displacement = code_zone_index(velocity, displacement, table)
    codes = {"pass": PASS, "warn": WARN, "fail": FAIL}
    verdicts = np.array([codes[v.value] for v in zone_verdicts(limits.acceptable_zone)], dtype=np.int8)
    ratio = np.where(by_displacement, displacement / table.displacement_boundaries[highest],
                     velocity / table.boundaries[highest])
    return table, verdicts[index], ratio


def judge_batch(names: Sequence[str], directions: Sequence[str], values: Callable, limits, speeds,
                unsteady: Sequence[tuple[np.ndarray, str]]) -> tuple:
    """(outcome int8, utilisation [-], governing index, reasons) of the amplitude check of N
    candidates (module docstring).

    Parameters
    ----------
    names : the points, the centre of mass first
    directions : the names of the last axis of every array (the crank's horizontal, vertical; the
        block's x, y, z)
    values : limited quantity (``displacement``, ``velocity_rms`` ..., as
        :func:`~foundation_calc.checks.limits.limited_quantities` names them) -> its values, an array
        (N, points, directions) in SI units; -inf where a row cannot govern (a kind that finds only
        the largest value of a quantity exactly). Asked only for the quantities judged: the limited
        ones and, with a code, ``velocity_rms`` and ``displacement_rms``.
    limits : the scene's ``[limits]``
    speeds : (label, ω [rad/s]) of every machine (:func:`~foundation_calc.checks.codes.code_warnings`)
    unsteady : (mask (N,), reason) of the candidates without a steady state, each failing with its
        reason governing; a later one governs where several hold (at least one, which gives N)

    Each limit row's reason is ``"QUANTITY at POINT (DIRECTION)"``, each zone's ``"TITLE zone at
    POINT"``, in that order, then the ``unsteady`` reasons.

    >>> from types import SimpleNamespace
    >>> limits = SimpleNamespace(amplitude=1e-5, code=None)  # a 10 µm peak displacement limit
    >>> peaks = np.array([[[4e-6, 8e-6]], [[2e-5, 1e-6]]])  # two candidates, one point, (x, z)
    >>> outcome, utilisation, governing, reasons = judge_batch(["G"], ["x", "z"], lambda q: peaks, limits, [],
    ...                                                        [(np.array([False, False]), "no steady state")])
    >>> outcome.tolist(), utilisation.round(9).tolist(), [reasons[g] for g in governing]
    ([0, 2], [0.8, 2.0], ['displacement at G (z)', 'displacement at G (x)'])
    """
    from foundation_calc.checks.codes import code_warnings
    from foundation_calc.checks.design.candidates import FAIL, PASS, WARN, failing, largest_ratio
    from foundation_calc.checks.limits import exceeds, limited_quantities

    n = len(unsteady[0][0])
    outcome = np.full(n, PASS, dtype=np.int8)
    ratios, reasons = [], []
    for quantity, limit in limited_quantities(limits).items():
        value = values(quantity).reshape(n, -1)  # (N, points · directions)
        ratios.append(value / limit)
        outcome = np.maximum(outcome, np.where(exceeds(value, limit).any(axis=-1), FAIL, PASS))
        reasons += [f"{quantity} at {name} ({direction})" for name in names for direction in directions]
    if limits.code is not None:  # each point's largest direction, (N, points)
        table, zone, ratio = code_zones(limits, values("velocity_rms").max(axis=-1), values("displacement_rms").max(axis=-1))
        outcome = np.maximum(outcome, zone.max(axis=-1))
        ratios.append(ratio)
        reasons += [f"{table.title} zone at {name}" for name in names]
    if code_warnings(limits, speeds):  # the code may not apply: warns
        outcome = np.maximum(outcome, WARN)
    utilisation, governing = largest_ratio(ratios, n)
    for mask, reason in unsteady:
        outcome, utilisation, governing = failing(mask, outcome, utilisation, governing, len(reasons))
        reasons.append(reason)
    return outcome, utilisation, governing, tuple(reasons)


__all__ = ["code_zones", "judge_batch"]
