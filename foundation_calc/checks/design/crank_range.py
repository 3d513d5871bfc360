"""The crank's engine of the one modulus-range checker (:mod:`.modulus_range`): the crank batch's
checks over the soil's ``modulus_range``, as :mod:`~foundation_calc.checks.soil_range` does them.

For every candidate block, as the full path does for one scene:

- **resonance** at the :data:`~foundation_calc.checks.soil_range.GRID_POINTS` factors of
  :func:`~foundation_calc.checks.soil_range.modulus_factors`, and at every factor where a
  condition's zero-order critical speed crosses the speed between two of them (bisection in the
  factor to 1e-13 of it, where the full path uses Brent's method to 1e-12), when the rule judges
  that condition there;
- **amplitudes** at the :data:`~foundation_calc.checks.soil_range.AMPLITUDE_GRID_POINTS` factors
  and at those crossings.

How the crank's engine differs from the block's (:mod:`.block_range`): the crank's critical speeds
are the closed forms' (zero-order k0 and averaged p1, p2), not an eigenvalue problem linear in the
factor, so a crossing is found by bisection between the grid factors where the offset of a listed
condition changes sign; and every candidate is judged at every factor in one array operation over
(candidate, factor) pairs. The worst verdict and its merge with the soil as given are
:mod:`.modulus_range`'s.

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


def _crossings(scene, L, B, H, sizes, grid, zero, judged, status, conditions, stable, omega, mech):
    """(candidate index, factor) of every crossing of a listed condition between two grid
    factors (module docstring), found by bisection in log(factor); ``mech`` the
    :class:`~foundation_calc.solvers.crank.batch.MechanismOperator`."""
    from foundation_calc.checks.design.crank_physics import candidate_designs, candidate_frequencies
    from foundation_calc.checks.resonance.rule import INFORMATION

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
        designs = candidate_designs(scene, L[who], B[who], H[who], np.exp(mid), _take(sizes, who))
        frequencies = candidate_frequencies(designs, mech.at(designs.a))[0]
        value = np.stack([getattr(frequencies, m) * np.ones(len(who)) for m in ("k0", "p1", "p2")], -1)
        same = np.sign(value[np.arange(len(who)), mode[c]] / order[c] - omega) == sign
        low, high = np.where(same, mid, low), np.where(same, high, mid)
    return who, np.exp(0.5 * (low + high)), c


def judged(scene, L, B, H, sizes, mech, harmonics, chunk: int):
    """The crank's engine of :func:`~foundation_calc.checks.design.modulus_range.over_range` for the
    candidate blocks (L, B, H) at the support's ``sizes`` (key -> (N,)): a generator of the elements
    (candidate, factor) it judges (module docstring), each candidate at every grid factor (it judges
    every candidate: its elements are one array operation, ``chunk`` at a time)."""

    def elements(grids, _):
        n = len(L)
        grid = grids["resonance"]
        who = np.repeat(np.arange(n), len(grid))
        factor = np.tile(grid, n)
        resonance, (zero, judged, status, conditions), reasons = _judged(
            scene, L[who], B[who], H[who], _take(sizes, who), factor, mech, harmonics, True, False, chunk)
        yield ("resonance", who, *resonance["resonance"], reasons["resonance"])
        stable = resonance["resonance"][2] != len(conditions)  # the last reason: the block tips over
        at, crossed, c = _crossings(scene, L, B, H, sizes, grid, zero, judged, status, conditions, stable,
                                    scene.mechanism.omega_rad_s, mech)
        if len(at):  # the crossings where the rule judges the crossed condition
            found, extra, _ = _judged(scene, L[at], B[at], H[at], _take(sizes, at), crossed, mech, harmonics, True, False, chunk)
            kept = extra[1][np.arange(len(at)), c]
            at, crossed = at[kept], crossed[kept]
            yield ("resonance", at, *(a[kept] for a in found["resonance"]), reasons["resonance"])
        grid = grids["amplitudes"]
        owner = np.concatenate([np.repeat(np.arange(n), len(grid)), at])
        factor = np.concatenate([np.tile(grid, n), crossed])
        amplitudes, _, reasons = _judged(scene, L[owner], B[owner], H[owner], _take(sizes, owner), factor, mech, harmonics,
                                         False, True, chunk)
        yield ("amplitudes", owner, *amplitudes["amplitudes"], reasons["amplitudes"])

    return elements


__all__ = ["CROSSING_STEPS", "judged"]
