"""The engine of a ``block_foundation`` scene's sample (:mod:`~foundation_calc.checks.soil_sample`):
the six natural frequencies and the checks' utilisations of the scene's own block on its soil with
the stiffness data × F, built in one array operation by Eqs. (1) and (2) of
:mod:`~foundation_calc.checks.design.block_range` (springs × F, dashpots × sqrt F; a
frequency-dependent soil at ω / sqrt F), and judged by the batch evaluator of ``fcalc design``
(:func:`~foundation_calc.checks.design.block.dynamics`): the resonance rule over every order of
every machine against every mode (each mode at its own frequency on a frequency-dependent soil),
the damped steady state against ``[limits]`` and the code zones, the whole machinery of
``fcalc check`` (which the evaluator matches candidate by candidate). The machines keep their
speeds (a block's speed is not sampled).

Utilisation, as ``fcalc design`` reports it: resonance, the margin the governing condition needs
over its margin; amplitudes, the largest limited value (or code-zone quantity) over its limit.
Above 1 the check fails.
"""

from __future__ import annotations

import numpy as np

#: Keys of the six natural frequencies in the sample's percentiles [rad/s], lowest first.
MODES = tuple(f"mode{j}" for j in range(1, 7))


def _piece(scene, factor) -> dict[str, np.ndarray]:
    """The sampled quantities of the samples ``factor`` (N,): frequencies, utilisations, outcomes.

    Raises PhysicsError, naming the culprit, when the scene's own block tips over (every
    sample but the stiffer ones would, and none gives a percentile), as ``fcalc check`` refuses it."""
    from foundation_calc.checks.design.block import Built, dynamics
    from foundation_calc.checks.design.block_range import on_factors, scaled_impedance
    from foundation_calc.checks.design.candidates import FAIL
    from foundation_calc.solvers.block.response import batch_modes, consistent_batch

    model = on_factors(scene.stable_model(), factor)  # the scene's own block tipping over is refused, as by check
    impedance = scaled_impedance(scene.soil_impedance, factor) if scene.support().frequency_dependent else None
    points = np.array([p.at for p in scene.points], dtype=float).reshape(-1, 3)
    built = Built(model, scene.excitations(), points, impedance, None)
    with np.errstate(divide="ignore", invalid="ignore"):  # a block that tips over has p = 0: judged by dynamics
        modes = batch_modes(model) if impedance is None else consistent_batch(model, impedance)
        found = dynamics(scene, built, modes=modes)
    taken = {key: modes.frequencies[:, j] for j, key in enumerate(MODES)}
    for check, name in (("resonance", "resonance"), ("amplitudes", "amplitude")):
        outcome, utilisation, _, _ = found[check]
        taken[f"{name}_utilisation"] = utilisation
        taken[f"fails_{check}"] = outcome >= FAIL
    taken["stable"] = modes.stable
    return taken


def engine(scene, factor, _speed):
    """The sampled frequencies and utilisations and the outcomes of the samples ``factor`` (n,)
    (:data:`~foundation_calc.checks.soil_sample.ENGINES`; the machines keep their speeds), in pieces
    of the evaluator's size (:data:`~foundation_calc.checks.design.block.PIECE`) so that memory stays bounded."""
    from foundation_calc.checks.design.block import PIECE

    pieces = [_piece(scene, factor[i : i + PIECE]) for i in range(0, len(factor), PIECE)]
    taken = {key: np.concatenate([p[key] for p in pieces]) for key in pieces[0]}
    stable = taken.pop("stable")
    fails = {check: taken.pop(f"fails_{check}") for check in ("resonance", "amplitudes")}
    if np.isnan(taken["amplitude_utilisation"]).all():  # no limit and no code: nothing to utilise
        del taken["amplitude_utilisation"]
    ok = stable.copy()  # percentiles over the samples that stand and have a steady state
    for key in ("resonance_utilisation", "amplitude_utilisation"):
        ok &= ~np.isinf(taken.get(key, 0.0))
    return taken, ok, ~stable, fails["resonance"], fails["amplitudes"]


__all__ = ["MODES", "engine"]
