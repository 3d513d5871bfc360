"""What every kind's batch evaluator asks the scene's support alike (:mod:`.block`, :mod:`.crank`):
which candidates it can judge at all, each candidate's values of the block's dimensions and of the
support's own sizes, and the ``scene`` check of the candidates whose sizes ``fcalc check`` refuses.

The support answers through its interface only (:class:`~foundation_calc.solvers.supports.base.Support`
and its sizing hooks, :class:`~foundation_calc.solvers.supports.base.Sizing`): no evaluator asks
which support or soil method it is.
"""

from __future__ import annotations

import numpy as np

from foundation_calc.checks.design.candidates import FAIL, PASS, Batch

#: Why the batch leaves a support whose springs do not scale with one factor over the soil's
#: modulus range to fcalc check's path.
OVER_RANGE = "over soil.modulus_range the batch scales the support's springs by one factor, which does not hold for"


def refuse_unsized(support) -> None:
    """Raise PhysicsError (exit 3) naming the key of a ``support`` that ``fcalc design`` cannot size
    a block on (:func:`~foundation_calc.solvers.supports.base.unsized`: the isolators, whose places
    and springs a resized block does not carry along)."""
    from foundation_calc.errors import PhysicsError
    from foundation_calc.solvers.supports.base import unsized

    found = unsized(support)
    if found is not None:
        raise PhysicsError(found[1], field=found[0])


def refuse_unjudged(scene, support) -> None:
    """Raise NotImplementedError for what the batch leaves to the full path: the soil's modulus
    range on a ``support`` whose springs do not scale with one factor
    (:attr:`~foundation_calc.solvers.supports.base.Support.unscaled`; a pile group's, EN 1998-5
    Table C.1, K ∝ E_s^(1 - n)), and a vibration code whose support class each candidate's modes
    decide (no ``[limits] foundation``)."""
    if support.unscaled is not None and getattr(scene.soil, "modulus_range", None) is not None:
        raise NotImplementedError(f"{OVER_RANGE} a block on {support.unscaled}")
    if scene.limits.code is not None and scene.limits.foundation is None:
        from foundation_calc.checks.support import PER_CANDIDATE

        raise NotImplementedError(PER_CANDIDATE)


def candidate_values(batch: Batch, dimensions: dict, sizes: dict, kind: str):
    """((L, B, H) of every candidate, (N,) each [m]; the support's sizes, key -> (N,)): the batch's
    values, the scene's where a key is not varied. ``dimensions``: the block's keys -> the scene's
    values, in the order L, B, H; ``sizes``: the support's (:attr:`~foundation_calc.solvers.supports.base.Sizing.sizes`).

    Raises ValueError naming a key that cannot vary in a scene of ``kind`` and the keys that can."""
    n = len(next(iter(batch.values()))) if batch else 1
    unknown = sorted(set(batch) - set(dimensions) - set(sizes))
    if unknown:
        raise ValueError(f"{', '.join(unknown)} cannot vary for a {kind} scene; the keys that can:"
                         f" {', '.join((*dimensions, *sizes))}")
    values = {key: np.broadcast_to(np.asarray(batch.get(key, value), dtype=float), (n,))
              for key, value in (dimensions | sizes).items()}
    return [values.pop(key) for key in dimensions], values


def sizes_outside(sizes: dict, shape) -> np.ndarray:
    """(shape) True where a candidate's size of the support (key -> (N,)) lies outside the plausible
    range of its key (:data:`~foundation_calc.scenes.plausibility.KEYS`; a key without one is not judged)."""
    from foundation_calc.scenes.plausibility import KEYS, RANGES

    outside = np.zeros(shape, dtype=bool)
    for key, values in sizes.items():
        if key in KEYS:
            outside |= RANGES[KEYS[key]].outside(values)
    return outside


def fixed_findings(scene, base, candidate_key, sizes: dict, warned) -> list:
    """The scene's plausibility findings that no candidate changes (the soil's, the machines', the
    limits'): not under a key each candidate's scene judges anew (``candidate_key(key)`` true: the
    block's dimensions, the positions that move with it, ...; the support's ``sizes`` and the keys of
    its own warnings of them, ``warned``: :meth:`~foundation_calc.solvers.supports.base.Sizing.size_warnings`),
    nor a stratum remark on the scene's own ``base`` (L, B) [m], which each candidate's base is judged
    by instead (:func:`~foundation_calc.scenes.stratum.shallow`)."""
    from foundation_calc.scenes.stratum import stratum_remarks

    on_base = {str(remark) for remark in stratum_remarks(scene.soil, *base)}
    judged = {*sizes, *warned.keys}
    return [finding for finding in scene.plausibility_findings()
            if not candidate_key(finding.key) and finding.key not in judged and str(finding) not in on_base]


def with_scene_check(refused, outcome: dict, utilisation: dict, governing: dict, reasons: dict, order: list) -> None:
    """Add the ``scene`` check to the verdicts (check -> (N,) each; ``order`` the checks' names):
    a candidate whose sizes make a scene ``fcalc check`` refuses (``refused``, the support's
    :meth:`~foundation_calc.solvers.supports.base.Sizing.size_errors`) fails it (utilisation inf)
    and passes every other check with no number, as the reference evaluator judges a scene it cannot
    build (:mod:`.reference`). Nothing changes where the support refuses no size."""
    if not refused.reasons:
        return
    bad = refused.which > 0
    for check in order:
        outcome[check] = np.where(bad, PASS, outcome[check]).astype(np.int8)
        utilisation[check] = np.where(bad, np.nan, utilisation[check])
    outcome["scene"], utilisation["scene"] = np.where(bad, FAIL, PASS).astype(np.int8), np.where(bad, np.inf, np.nan)
    governing["scene"], reasons["scene"] = refused.which, ("the scene is valid", *refused.reasons)
    order.append("scene")


__all__ = ["OVER_RANGE", "candidate_values", "fixed_findings", "refuse_unjudged", "refuse_unsized", "sizes_outside", "with_scene_check"]
