"""The crank engine of the one batch checker (:mod:`.batch`): the checks of ``fcalc check`` on a
batch of crank foundations whose ``[foundation.block]`` varies.

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
  (:func:`~foundation_calc.checks.resonance.report.judge_conditions`), as one design's check;
- **amplitudes**: the averaged-operator steady state (:mod:`~foundation_calc.solvers.crank.batch`),
  the peaks and RMS values of C and every point (:func:`~foundation_calc.solvers.crank.response.point_series`,
  :func:`~foundation_calc.solvers.numerics.trig_series.peak`) against ``[limits]`` and a code's zones;
- **office**: the static bearing pressure W/S; **inputs**: the plausibility ranges that the
  block's dimensions enter (the rest are the scene's own).

The search this serves re-checks its front-runners by the full path. What the batch does not
judge: a run-up (``runup`` is reported PASS with utilisation NaN and the reason
:data:`NOT_EVALUATED`); a scene with ``[[loads]]`` is refused (:class:`NotImplementedError`) so
that the caller uses the full path. ``[soil] modulus_range``: :mod:`.modulus_range` with :mod:`.crank_range`.
"""

from __future__ import annotations

import numpy as np

from foundation_calc.checks.design.candidates import Batch, CandidateVerdicts
from foundation_calc.checks.design.crank_physics import VARIED, Verdicts, judge_inputs, judge_office, judge_physics

#: Candidates judged in one array operation; bounds the working memory (about 40 kB a candidate).
CHUNK = 4096

#: The reason of a check the batch does not evaluate (the search re-checks by the full path).
NOT_EVALUATED = "not evaluated in the batch (a time integration): the full check re-judges the chosen designs"


def _dimensions(scene, batch):
    """(the block's keys -> the scene's values; the batch with a block's key also accepted without
    the ``foundation.`` prefix). Raises ValueError for a scene without ``[foundation.block]``."""
    block = scene.foundation.block
    if block is None:
        raise ValueError("the scene gives no [foundation.block]: there is no block to size")
    full = {("foundation." + key if key.startswith("block.") else key): values for key, values in batch.items()}
    return {f"foundation.block.{k}": getattr(block, k) for k in VARIED}, full


def _refuse(scene) -> None:
    """A scene with ``[[loads]]`` or without a ``[mechanism]`` is judged by the full path."""
    if scene.mechanism is None or scene.loads:
        raise NotImplementedError("the batch judges a crank foundation's [mechanism] alone; a scene with [[loads]]"
                                  " is judged by the full path")


def _mechanism(scene):
    """The mechanism's averaged operator (:class:`~foundation_calc.solvers.crank.batch.MechanismOperator`): any support."""
    from foundation_calc.solvers.crank.batch import MechanismOperator

    return MechanismOperator.of(scene.design())


def _judge(scene, mech, support, L, B, H, sizes) -> dict:
    """check -> (outcome, utilisation, governing, reasons) of the resonance, amplitude, inputs and
    (with ``[limits] bearing_pressure``) office checks of the blocks (L, B, H) at the support's ``sizes``."""
    out = Verdicts()
    given, _ = judge_physics(out, scene, L, B, H, mech, mech.harmonics, sizes=sizes)
    if scene.soil.modulus_range is not None:
        from foundation_calc.checks.design.crank_range import judged
        from foundation_calc.checks.design.modulus_range import over_range

        as_given = {check: (out.outcome[check], out.utilisation[check], out.governing[check], out.reasons[check])
                    for check in ("resonance", "amplitudes")}
        for check, merged in over_range(scene, as_given, judged(scene, L, B, H, sizes, mech, mech.harmonics, CHUNK)).items():
            out.put(check, *merged)
    judge_inputs(out, scene, given, support.size_warnings(sizes, L, B), sizes)
    if scene.limits.bearing_pressure is not None:
        judge_office(out, scene, given)
    return {check: (out.outcome[check], out.utilisation[check], out.governing[check], out.reasons[check])
            for check in out.outcome}


#: Factors on the scene's block length, width and height between which :func:`sample_batch` draws.
SAMPLE_SPREAD = {"length": (0.6, 1.6), "width": (0.6, 1.6), "height": (0.4, 2.0)}


def sample_batch(scene, n: int, seed: int = 0) -> dict[str, np.ndarray]:
    """``n`` candidate blocks drawn uniformly around the scene's own (:data:`SAMPLE_SPREAD`), for
    tests and the bench: ``{"foundation.block.length": (n,), ...}`` [m]."""
    rng = np.random.default_rng(seed)
    block = scene.foundation.block
    return {f"foundation.block.{k}": getattr(block, k) * rng.uniform(*SAMPLE_SPREAD[k], n) for k in VARIED}


def evaluate(scene, batch: Batch) -> CandidateVerdicts:
    """Every check of ``fcalc check`` on every candidate of ``batch`` (module docstring), by the one
    batch checker (:func:`~foundation_calc.checks.design.batch.evaluate`) with this kind's engine."""
    from foundation_calc.checks.design.batch import Engine, evaluate as checked

    engine = Engine(kind="crank_foundation", piece=CHUNK, runup=NOT_EVALUATED, dimensions=_dimensions, refuse=_refuse,
                    density=lambda scene: scene.foundation.block.density, prepare=_mechanism, judge=_judge)
    return checked(scene, batch, engine)


__all__ = ["CHUNK", "NOT_EVALUATED", "SAMPLE_SPREAD", "VARIED", "evaluate", "sample_batch"]
