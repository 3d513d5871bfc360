"""The checks of ``fcalc check`` on a batch of crank foundations whose ``[foundation.block]`` varies.

Each candidate replaces the block's length, width and/or height (keys ``foundation.block.length``,
``.width``, ``.height``, or without the ``foundation.`` prefix; the base is the block's footprint,
L × B); everything else is the scene's. Per candidate, in array operations over the batch:

- mass, moment of inertia and height of C (:func:`~foundation_calc.solvers.crank.block.block_with_machine`),
  base area L B and second moment B L³/12, the soil's springs and dashpots by the scene's method
  (:meth:`~foundation_calc.scenes.crank.CrankScene.base_springs`; a frequency-dependent soil at
  each frequency it is needed at);
- **resonance**: k0, p1, p2 of the zero-order and averaged-inertia operators (each mode at its
  own frequency, ω = p(K(ω)), on a frequency-dependent soil), the forcing shares of the
  mechanism's harmonics on the averaged operator, and the resonance rule
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

from foundation_calc.checks.design.candidates import PASS, Batch, CandidateVerdicts, in_pieces
from foundation_calc.checks.design.crank_physics import VARIED, CandidateDesigns, Verdicts, judge_inputs, judge_office, judge_physics
from foundation_calc.checks.design.crank_range import over_range, with_range

#: Candidates judged in one array operation; bounds the working memory (about 40 kB a candidate).
CHUNK = 4096

#: The reason of a check the batch does not evaluate (the search re-checks by the full path).
NOT_EVALUATED = "not evaluated in the batch (a time integration): the full check re-judges the chosen designs"


def block_dimensions(scene, batch: Batch) -> tuple[np.ndarray, np.ndarray, np.ndarray]:
    """(L, B, H) [m] of every candidate: the batch's values, the scene's block for a key it leaves out.

    Raises ValueError naming a key that cannot vary, and for a scene without ``[foundation.block]``.
    """
    block = scene.foundation.block
    if block is None:
        raise ValueError("the scene gives no [foundation.block]: there is no block to size")
    given = {}
    for key, values in batch.items():
        short = key.removeprefix("foundation.").removeprefix("block.")
        if not key.removeprefix("foundation.").startswith("block.") or short not in VARIED:
            raise ValueError(f"{key} cannot vary here; a crank foundation varies "
                             + ", ".join(f"foundation.block.{k}" for k in VARIED))
        given[short] = np.asarray(values, dtype=float)
    size = np.broadcast_shapes((1,) if not given else (), *(v.shape for v in given.values()))
    return tuple(np.atleast_1d(np.broadcast_to(given.get(k, getattr(block, k)), size)).astype(float) for k in VARIED)


def _chunk(scene, L, B, H, mech, harmonics, checks) -> Verdicts:
    out = Verdicts()
    given, _ = judge_physics(out, scene, L, B, H, mech, harmonics)
    if scene.soil.modulus_range is not None:
        for check, ranged in over_range(scene, L, B, H, mech, harmonics, CHUNK).items():
            out.put(check, *with_range(out.outcome[check], out.utilisation[check], out.governing[check],
                                       out.reasons[check], ranged))
    if "inputs" in checks:
        judge_inputs(out, scene, given)
    if "runup" in checks:
        n = len(L)
        out.put("runup", np.full(n, PASS), np.full(n, np.nan), np.zeros(n), [NOT_EVALUATED])
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
    """Every check of ``fcalc check`` on every candidate block of ``batch`` (module docstring)."""
    from foundation_calc.solvers.crank.batch import MechanismOperator

    if scene.mechanism is None or scene.loads:
        raise NotImplementedError("the batch judges a crank foundation's [mechanism] alone; a scene with [[loads]]"
                                  " is judged by the full path")
    if scene.limits.code is not None and scene.limits.foundation is None:
        from foundation_calc.checks.support import PER_CANDIDATE

        raise NotImplementedError(PER_CANDIDATE)
    L, B, H = block_dimensions(scene, batch)
    if not len(L):  # an empty batch: the verdicts' arrays of a batch of one, emptied
        one = evaluate(scene, {f"foundation.block.{k}": np.array([getattr(scene.foundation.block, k)]) for k in VARIED})
        return CandidateVerdicts(*(v[:0] for v in (one.volume, one.mass)),
                                 *({c: a[:0] for c, a in d.items()} for d in (one.outcome, one.utilisation, one.governing)),
                                 one.reasons, one.deferred)
    mech = MechanismOperator.of(scene.design())
    harmonics = mech.harmonics
    checks = checks_judged(scene)
    def judge(start, stop):
        parts = L[start:stop], B[start:stop], H[start:stop]
        found = _chunk(scene, *parts, mech, harmonics, checks)
        order = [c for c in checks if c in found.outcome]
        volume = parts[0] * parts[1] * parts[2]
        return CandidateVerdicts(
            volume=volume, mass=scene.foundation.block.density * volume,
            outcome={c: found.outcome[c] for c in order}, utilisation={c: found.utilisation[c] for c in order},
            governing={c: found.governing[c] for c in order}, reasons={c: found.reasons[c] for c in order},
            deferred=("runup",) if "runup" in order else (),
        )

    return in_pieces(judge, len(L), CHUNK)


__all__ = ["CHUNK", "NOT_EVALUATED", "SAMPLE_SPREAD", "VARIED", "CandidateDesigns", "block_dimensions", "checks_judged",
           "evaluate", "sample_batch"]
