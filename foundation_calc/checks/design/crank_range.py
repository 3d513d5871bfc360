"""The crank batch's checks over the soil's ``modulus_range``, as :mod:`~foundation_calc.checks.soil_range` does them.

For every candidate block, as the full path does for one scene:

- **resonance** at the :data:`~foundation_calc.checks.soil_range.GRID_POINTS` factors of
  :func:`~foundation_calc.checks.soil_range.modulus_factors`, and at every factor where a
  condition's zero-order critical speed crosses the speed between two of them (bisection in the
  factor to 1e-13 of it, where the full path uses Brent's method to 1e-12), when the rule judges
  that condition there;
- **amplitudes** at the :data:`~foundation_calc.checks.soil_range.AMPLITUDE_GRID_POINTS` factors
  and at those crossings.

The verdict of each check is the worst of the scene's soil as given and of every factor; its
utilisation stays the one on the soil as given, as the full path's evaluator reads it
(:mod:`~foundation_calc.checks.design.reference`). A candidate that tips over at any factor
fails, as the full path finds its scene invalid.

One difference, stated: a crossing is searched for a condition the rule lists at both grid
factors around it (it is a source's condition, judged, or inside its band), where the full path
takes the conditions its reports show (the same, but for information conditions outside the
three nearest); a harmonic whose forcing share passes 1 % only between two grid factors and
nowhere at them is missed by both.
"""

from __future__ import annotations

import numpy as np

#: Bisection steps of a crossing: the grid's factors are at most a factor 3^(1/40) apart for a
#: range of 1:3, so 44 halvings of the logarithm leave 1e-15 of the factor.
CROSSING_STEPS = 44

#: Appended to a reason when the soil's modulus range governs the check.
OVER_RANGE = " (over the soil's modulus range)"


def _judged(scene, L, B, H, sizes, factor, mech, harmonics, resonance: bool, amplitudes: bool, chunk: int):
    """``judge_physics`` of elements (block, the support's sizes, factor), ``chunk`` at a time: the Verdicts' arrays and,
    with ``resonance``, each element's zero-order frequencies, judgement and conditions."""
    from foundation_calc.checks.design.crank_physics import Verdicts, judge_physics

    outs, zero, judged, status = [], [], [], []
    conditions = ()
    for i in range(0, len(L), chunk):
        part = slice(i, i + chunk)
        out = Verdicts()
        _, found = judge_physics(out, scene, L[part], B[part], H[part], mech, harmonics, factor[part], resonance, amplitudes,
                                 _take(sizes, part))
        outs.append(out)
        if found is not None:
            frequencies, _, verdict, conditions = found
            zero.append(np.stack([np.broadcast_to(getattr(frequencies, m), L[part].shape) for m in ("k0", "p1", "p2")], -1))
            judged.append(verdict.judged)
            status.append(verdict.status)
    checks = outs[0].outcome.keys() if outs else ()
    merged = {c: tuple(np.concatenate([getattr(o, a)[c] for o in outs]) for a in ("outcome", "utilisation", "governing"))
              for c in checks}
    extra = None if not resonance else (np.concatenate(zero), np.concatenate(judged), np.concatenate(status), conditions)
    return merged, extra, (outs[0].reasons if outs else {})


def _take(sizes, index) -> dict:
    """The support's sizes (key -> (N,)) of the elements ``index`` (a slice or indices)."""
    return {key: values[index] for key, values in sizes.items()}


def _worst(owner, outcome, utilisation, governing, n):
    """Per owner (0 ... n - 1): the element with the worst outcome and, among those, the largest
    utilisation; (outcome, utilisation, governing) of each owner (-1 outcome where it has none)."""
    key = np.where(np.isnan(utilisation), -np.inf, utilisation)
    order = np.lexsort((key, outcome, owner))
    last = np.r_[owner[order][1:] != owner[order][:-1], True]
    chosen = order[last]
    result = (np.full(n, -1, np.int8), np.full(n, np.nan), np.zeros(n, np.intp))
    for array, values in zip(result, (outcome, utilisation, governing)):
        array[owner[chosen]] = values[chosen]
    return result


def _crossings(scene, L, B, H, sizes, grid, zero, judged, status, conditions, stable, omega, mech):
    """(candidate index, factor) of every crossing of a listed condition between two grid
    factors (module docstring), found by bisection in log(factor); ``mech`` the
    :class:`~foundation_calc.solvers.crank.batch.MechanismOperator`."""
    from foundation_calc.checks.design.crank_physics import CandidateDesigns, candidate_frequencies
    from foundation_calc.checks.resonance_rule import INFORMATION

    n, f = len(L), len(grid)
    modes = {"k0": 0, "p1": 1, "p2": 2}
    mode = np.array([modes[c.mode] for c in conditions])
    order = np.array([c.harmonic for c in conditions])
    source = np.array([c.source != "harmonic" for c in conditions])
    offset = (zero.reshape(n, f, 3)[:, :, mode] / order - omega)  # (n, f, C)
    listed = (source | judged | (status >= INFORMATION)).reshape(n, f, -1)
    steady = stable.reshape(n, f)
    change = (offset[:, :-1] * offset[:, 1:] < 0.0) & listed[:, :-1] & listed[:, 1:]
    change &= (steady[:, :-1] & steady[:, 1:])[..., None]
    who, j, c = np.nonzero(change)
    low, high = np.log(np.asarray(grid)[j]), np.log(np.asarray(grid)[j + 1])
    sign = np.sign(offset[who, j, c])
    for _ in range(CROSSING_STEPS if len(who) else 0):
        mid = 0.5 * (low + high)
        designs = CandidateDesigns(scene, L[who], B[who], H[who], np.exp(mid), _take(sizes, who))
        frequencies = candidate_frequencies(designs, mech.at(designs.a))[0]
        value = np.stack([getattr(frequencies, m) * np.ones(len(who)) for m in ("k0", "p1", "p2")], -1)
        same = np.sign(value[np.arange(len(who)), mode[c]] / order[c] - omega) == sign
        low, high = np.where(same, mid, low), np.where(same, high, mid)
    return who, np.exp(0.5 * (low + high)), c


def over_range(scene, L, B, H, sizes, mech, harmonics, chunk: int) -> dict:
    """check -> (outcome, utilisation, governing, reasons) over the soil's modulus range of every
    candidate (module docstring), its support at ``sizes`` (key -> (N,)); governing indexes the check's reasons, then the same with
    :data:`OVER_RANGE`."""
    from foundation_calc.checks.soil_range import AMPLITUDE_GRID_POINTS, modulus_factors

    low, high = scene.soil.modulus_range
    n = len(L)
    omega = scene.mechanism.omega_rad_s
    grid = modulus_factors(low, high)
    who = np.repeat(np.arange(n), len(grid))
    factor = np.tile(grid, n)
    resonance, (zero, judged, status, conditions), reasons = _judged(
        scene, L[who], B[who], H[who], _take(sizes, who), factor, mech, harmonics, True, False, chunk)
    stable = resonance["resonance"][2] != len(conditions)  # the last reason: the block tips over
    at, crossed, c = _crossings(scene, L, B, H, sizes, grid, zero, judged, status, conditions, stable, omega, mech)
    if len(at):  # the crossings where the rule judges the crossed condition
        found, extra, _ = _judged(scene, L[at], B[at], H[at], _take(sizes, at), crossed, mech, harmonics, True, False, chunk)
        kept = extra[1][np.arange(len(at)), c]
        at, crossed = at[kept], crossed[kept]
        outcome, utilisation, governing = (np.concatenate([a, b[kept]]) for a, b in zip(resonance["resonance"], found["resonance"]))
        owner = np.concatenate([who, at])
    else:
        outcome, utilisation, governing = resonance["resonance"]
        owner = who
    result = {"resonance": (*_worst(owner, outcome, utilisation, governing, n), reasons["resonance"])}
    grid = modulus_factors(low, high, AMPLITUDE_GRID_POINTS)
    owner = np.concatenate([np.repeat(np.arange(n), len(grid)), at])
    factor = np.concatenate([np.tile(grid, n), crossed])
    amplitudes, _, reasons = _judged(scene, L[owner], B[owner], H[owner], _take(sizes, owner), factor, mech, harmonics, False, True, chunk)
    result["amplitudes"] = (*_worst(owner, *amplitudes["amplitudes"], n), reasons["amplitudes"])
    return result


def with_range(outcome, utilisation, governing, reasons, ranged):
    """The check's verdicts with those over the range: the worse outcome of the two, and where
    the range's is worse, what governs there (the range's reasons follow the check's own, with
    :data:`OVER_RANGE`). The utilisation stays the soil's as given, as the full path reads it
    (:mod:`~foundation_calc.checks.design.reference`: the range judged in the outcome only)."""
    r_outcome, _, r_governing, r_reasons = ranged
    worse = r_outcome > outcome
    return (np.maximum(outcome, r_outcome).astype(np.int8), utilisation,
            np.where(worse, r_governing + len(reasons), governing), (*reasons, *(r + OVER_RANGE for r in r_reasons)))


__all__ = ["CROSSING_STEPS", "OVER_RANGE", "over_range", "with_range"]
