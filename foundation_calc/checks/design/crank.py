"""The checks of ``fcalc check`` on a batch of crank foundations whose ``[foundation.block]`` varies.

Each candidate replaces the block's length, width and/or height (keys ``foundation.block.length``,
``.width``, ``.height``, or without the ``foundation.`` prefix; the base is the block's footprint,
L × B); everything else is the scene's. Per candidate, in array operations over the batch:

- mass, moment of inertia and height of C (:func:`~foundation_calc.solvers.crank.block.block_with_machine`),
  base area L B and second moment B L³/12, and the springs and dashpots at O of what carries the
  block, asked of the scene's support (:meth:`~foundation_calc.scenes.crank.CrankScene.support`)
  under the candidate's base and body at the candidate's sizes of the support's own (its sizing
  hooks, :class:`~foundation_calc.solvers.supports.base.Sizing`: the concrete it adds, the
  warnings and refusals of its sizes), read in the plane with its sway-rocking coupling K_xφ, C_xφ
  (a pile group's; any other coupling of the plane's motions is refused by name, as the crank's
  checks refuse it); a frequency-dependent support at each frequency it is needed at;
- **resonance**: k0, p1, p2 of the zero-order and averaged-inertia operators (each mode at its
  own frequency, ω = p(K(ω)), on a frequency-dependent soil; on a coupled support both are the
  averaged operator's eigen-solve stacked over the candidates, as ``fcalc resonance`` takes them),
  the forcing shares of the mechanism's harmonics on the averaged operator, and the resonance rule
  (:func:`~foundation_calc.checks.crank_resonance.judge_conditions`), as one design's check;
- **amplitudes**: the averaged-operator steady state (:mod:`~foundation_calc.solvers.crank.batch`),
  the peaks and RMS values of C and every point (:func:`~foundation_calc.solvers.crank.response.point_series`,
  :func:`~foundation_calc.solvers.numerics.trig_series.peak`) against ``[limits]`` and a code's zones;
- **office**: the static bearing pressure W/S; **inputs**: the plausibility ranges that the
  block's dimensions enter (the rest are the scene's own).

The search this serves re-checks its front-runners by the full path. What the batch does not
judge: a run-up (``runup`` is reported PASS with utilisation NaN and the reason
:data:`NOT_EVALUATED`); a scene with ``[[loads]]`` is refused (:class:`NotImplementedError`) so
that the caller uses the full path. ``[soil] modulus_range``: :mod:`.crank_range`.
"""

from __future__ import annotations

import numpy as np

from foundation_calc.checks.design.candidates import Batch, CandidateVerdicts, in_pieces, not_evaluated, ordered
from foundation_calc.checks.design.crank_physics import VARIED, CandidateDesigns, Verdicts, judge_inputs, judge_office, judge_physics
from foundation_calc.checks.design.crank_range import over_range, with_range

#: Candidates judged in one array operation; bounds the working memory (about 40 kB a candidate).
CHUNK = 4096

#: The reason of a check the batch does not evaluate (the search re-checks by the full path).
NOT_EVALUATED = "not evaluated in the batch (a time integration): the full check re-judges the chosen designs"


def block_dimensions(scene, batch: Batch, sizes=None):
    """((L, B, H) [m] of every candidate, (N,) each; the support's sizes, key -> (N,)): the batch's
    values, the scene's block and the support's ``sizes`` (its own, by default) for a key it leaves
    out; a block's key also without the ``foundation.`` prefix.

    Raises ValueError naming a key that cannot vary, and for a scene without ``[foundation.block]``.
    """
    from foundation_calc.checks.design.supported import candidate_values

    block = scene.foundation.block
    if block is None:
        raise ValueError("the scene gives no [foundation.block]: there is no block to size")
    full = {("foundation." + key if key.startswith("block.") else key): values for key, values in batch.items()}
    given = {f"foundation.block.{k}": getattr(block, k) for k in VARIED}
    if sizes is None:
        from foundation_calc.checks.design.apply import sizing_of

        sizes = sizing_of(scene).sizes
    return candidate_values(full, given, sizes, "crank_foundation")


def _chunk(scene, L, B, H, sizes, mech, harmonics, checks, sizing) -> Verdicts:
    out = Verdicts()
    given, _ = judge_physics(out, scene, L, B, H, mech, harmonics, sizes=sizes)
    if scene.soil.modulus_range is not None:
        for check, ranged in over_range(scene, L, B, H, sizes, mech, harmonics, CHUNK).items():
            out.put(check, *with_range(out.outcome[check], out.utilisation[check], out.governing[check],
                                       out.reasons[check], ranged))
    if "inputs" in checks:
        judge_inputs(out, scene, given, sizing.size_warnings(sizes, L, B), sizes)
    if "runup" in checks:
        out.put("runup", *not_evaluated(len(L), NOT_EVALUATED))
    if "office" in checks:
        judge_office(out, scene, given)
    return out


#: Factors on the scene's block length, width and height between which :func:`sample_batch` draws.
SAMPLE_SPREAD = {"length": (0.6, 1.6), "width": (0.6, 1.6), "height": (0.4, 2.0)}


def sample_batch(scene, n: int, seed: int = 0) -> dict[str, np.ndarray]:
    """``n`` candidate blocks drawn uniformly around the scene's own (:data:`SAMPLE_SPREAD`), for
    tests and the bench: ``{"foundation.block.length": (n,), ...}`` [m]."""
    rng = np.random.default_rng(seed)
    block = scene.foundation.block
    return {f"foundation.block.{k}": getattr(block, k) * rng.uniform(*SAMPLE_SPREAD[k], n) for k in VARIED}


def checks_judged(scene) -> tuple[str, ...]:
    """The checks ``fcalc check`` runs on ``scene`` (those of ``CHECKS["crank_foundation"]`` that
    do not return None for it), in their order; ``inputs`` always (a candidate may warn)."""
    from foundation_calc.checks.runup import judged

    found = ["inputs", "resonance", "amplitudes"]
    if judged(scene):
        found.append("runup")
    if scene.limits.bearing_pressure is not None:
        found.append("office")
    return tuple(found)


def evaluate(scene, batch: Batch) -> CandidateVerdicts:
    """Every check of ``fcalc check`` on every candidate of ``batch`` (module docstring): the block's
    dimensions and the sizes of its support's own (:class:`~foundation_calc.solvers.supports.base.Sizing`)."""
    from foundation_calc.checks.design.supported import refuse_unjudged, with_scene_check
    from foundation_calc.solvers.crank.batch import MechanismOperator
    from foundation_calc.solvers.supports.base import sizing

    if scene.mechanism is None or scene.loads:
        raise NotImplementedError("the batch judges a crank foundation's [mechanism] alone; a scene with [[loads]]"
                                  " is judged by the full path")
    support = scene.support()
    refuse_unjudged(scene, support)
    support = sizing(support)
    (L, B, H), sizes = block_dimensions(scene, batch, support.sizes)
    if not len(L):  # an empty batch: the verdicts' arrays of a batch of one, emptied
        one = evaluate(scene, {f"foundation.block.{k}": np.array([getattr(scene.foundation.block, k)]) for k in VARIED})
        return CandidateVerdicts(*(v[:0] for v in (one.volume, one.mass)),
                                 *({c: a[:0] for c, a in d.items()} for d in (one.outcome, one.utilisation, one.governing)),
                                 one.reasons, one.deferred)
    mech = MechanismOperator.of(scene.design())  # the mechanism alone: any support
    harmonics = mech.harmonics
    checks = checks_judged(scene)

    def judge(start, stop):
        parts = L[start:stop], B[start:stop], H[start:stop]
        own = {key: values[start:stop] for key, values in sizes.items()}
        found = _chunk(scene, *parts, own, mech, harmonics, checks, support)
        order = [c for c in checks if c in found.outcome]
        with_scene_check(support.size_errors(own, parts[0], parts[1]), found.outcome, found.utilisation, found.governing,
                         found.reasons, order)
        volume = parts[0] * parts[1] * parts[2]
        return ordered(volume + support.concrete(own), scene.foundation.block.density * volume, found.outcome,
                       found.utilisation, found.governing, found.reasons, order, ("runup",) if "runup" in order else ())

    return in_pieces(judge, len(L), CHUNK)


__all__ = ["CHUNK", "NOT_EVALUATED", "SAMPLE_SPREAD", "VARIED", "CandidateDesigns", "block_dimensions", "checks_judged",
           "evaluate", "sample_batch"]
