"""The one batch checker of ``fcalc design``: every check of ``fcalc check`` on every candidate of a
batch, for every scene kind, the kind's physics handed in as an :class:`Engine`.

What every kind shares is done here once (:func:`evaluate`): what the batch leaves to the full
path (:func:`~.supported.refuse_unjudged`), each candidate's block dimensions and support sizes
(:func:`~.supported.candidate_values`), the batch in pieces on the cores
(:func:`~.candidates.in_pieces`), the checks in the order ``fcalc check`` reports them
(:data:`ORDER`), the run-up left to the full path (PASS, utilisation NaN, the engine's reason:
a time integration), the ``scene`` check of sizes ``fcalc check`` refuses
(:func:`~.supported.with_scene_check`), the concrete volume (L B H and what the support adds) and
the block's mass ρ L B H. What a kind computes and judges differently (its model of the candidates,
their resonance and amplitude verdicts, over the soil's modulus range, its plausibility warnings
and office rules) is its engine's: :mod:`.block`, :mod:`.crank`.
"""

from __future__ import annotations

from collections.abc import Callable
from dataclasses import dataclass

from foundation_calc.checks.design.candidates import Batch, CandidateVerdicts, in_pieces, not_evaluated, ordered

#: The checks in the order ``fcalc check`` reports them (those a scene runs).
ORDER = ("inputs", "resonance", "amplitudes", "runup", "office")


@dataclass(frozen=True)
class Engine:
    """What a scene kind hands the batch checker.

    Attributes
    ----------
    kind : the scene kind, named in the message of a key that cannot vary
    piece : candidates judged in one array operation (bounds the working memory)
    runup : the reason the run-up is not evaluated in the batch
    dimensions : scene -> (the varied block keys -> the scene's values, in the order L, B, H; the batch
        with its keys as those name them); raises ValueError for a scene without a block to size
    refuse : scene -> None, raising NotImplementedError for a scene the kind's batch does not judge
    density : scene -> the block's density [kg/m³]
    prepare : scene -> what every piece of the batch shares (e.g. the mechanism's operator)
    judge : (scene, prepared, support, L, B, H, sizes) -> check -> (outcome, utilisation, governing,
        reasons) of the checks ``resonance``, ``amplitudes``, ``inputs`` and, where the kind judges it,
        ``office`` on the candidates (L, B, H (N,) each [m]) on ``support`` (its sizing hooks) at
        their ``sizes`` (key -> (N,))
    """

    kind: str
    piece: int
    runup: str
    dimensions: Callable
    refuse: Callable
    density: Callable
    prepare: Callable
    judge: Callable


def evaluate(scene, batch: Batch, engine: Engine) -> CandidateVerdicts:
    """Every check of ``fcalc check`` on every candidate of ``batch`` (module docstring): the block's
    dimensions and the sizes of its support's own (:class:`~foundation_calc.solvers.supports.base.Sizing`).

    Raises PhysicsError (exit 3) for a support no design sizes a block on (:func:`~.supported.refuse_unsized`:
    the isolators), as ``fcalc design`` does; ValueError for a key that cannot vary; NotImplementedError
    for what the batch leaves to the full path (:func:`~.supported.refuse_unjudged`, the engine's ``refuse``)."""
    from foundation_calc.checks.design.supported import candidate_values, refuse_unjudged, refuse_unsized, with_scene_check
    from foundation_calc.checks.runup import judged
    from foundation_calc.solvers.supports.base import sizing

    support = scene.support()
    refuse_unsized(support)
    engine.refuse(scene)
    refuse_unjudged(scene, support)
    support = sizing(support)
    given, batch = engine.dimensions(scene, batch)
    (L, B, H), sizes = candidate_values(batch, given, support.sizes, engine.kind)
    if not len(L):  # an empty batch: the verdicts' arrays of the scene's own block, emptied
        one = evaluate(scene, {}, engine)
        return CandidateVerdicts(one.volume[:0], one.mass[:0], *({c: a[:0] for c, a in d.items()}
                                 for d in (one.outcome, one.utilisation, one.governing)), one.reasons, one.deferred)
    prepared = engine.prepare(scene)
    runup = judged(scene)
    density = engine.density(scene)

    def judge(start, stop):
        parts = L[start:stop], B[start:stop], H[start:stop]
        own = {key: values[start:stop] for key, values in sizes.items()}
        found = engine.judge(scene, prepared, support, *parts, own)
        if runup:
            found["runup"] = not_evaluated(len(parts[0]), engine.runup)
        outcome, utilisation, governing, reasons = ({c: v[i] for c, v in found.items()} for i in range(4))
        order = [c for c in ORDER if c in found]
        with_scene_check(support.size_errors(own, parts[0], parts[1]), outcome, utilisation, governing, reasons, order)
        volume = parts[0] * parts[1] * parts[2]
        return ordered(volume + support.concrete(own), density * volume, outcome, utilisation, governing, reasons,
                       order, ("runup",) if runup else ())

    return in_pieces(judge, len(L), engine.piece)


__all__ = ["ORDER", "Engine", "evaluate"]
