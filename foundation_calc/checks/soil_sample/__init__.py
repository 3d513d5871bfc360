"""The uncertain soil as a distribution (``fcalc soil SCENE --sample N``): percentiles of the
sampled frequencies, margins, peaks or utilisations, and the probability that each check fails,
for every scene kind.

The draw and the summary are written here once; each kind hands in its engine (:data:`ENGINES`),
which computes and judges every sample in array operations:
:mod:`~foundation_calc.checks.soil_sample.crank` (the mechanism's closed forms) and
:mod:`~foundation_calc.checks.soil_sample.block` (the batch evaluator of ``fcalc design``).

Distributions (independent):

- soil stiffness factor F ~ lognormal with median 1 and coefficient of variation ``cov_modulus``
  (ln F ~ N(0, s²), s² = ln(1 + cov²)): every spring is F times the scene's (K ∝ G or E), the
  damping ratios stay, so the dashpots C = 2 ξ sqrt(K m) go as sqrt(F). A lognormal keeps the
  modulus positive and makes 1/F as likely as F; site moduli scatter with a COV of about 0.2-0.5.
- speed factor ~ normal with mean 1 and standard deviation ``cov_speed`` (0: the speed as given;
  drawn after F), for a machine whose speed drifts or is not yet fixed (a crank scene's only).

The percentiles are taken over the samples that stand and have a steady state (all of them when
none does); the probabilities over all samples.
"""

from __future__ import annotations

import importlib
import math
from dataclasses import dataclass

import numpy as np

#: Percentiles reported [%].
PERCENTILES = (5.0, 50.0, 95.0)

#: Scene kind -> module of its engine, ``engine(scene, factor, speed) -> (values, ok, tips_over,
#: fails_resonance, fails_amplitude)``: sampled quantity name -> (n,) in SI, and bool (n,) each
#: (``ok``: the samples the percentiles are taken over).
ENGINES = {
    "crank_foundation": "foundation_calc.checks.soil_sample.crank",
    "block_foundation": "foundation_calc.checks.soil_sample.block",
}


@dataclass(frozen=True)
class SoilSample:
    """The sample's distributions and failure probabilities.

    ``percentiles``: name -> values at :data:`PERCENTILES` (SI: rad/s, -, m);
    ``failure_probability``: check -> fraction of samples that fail it [-].
    """

    samples: int
    cov_modulus: float
    cov_speed: float
    seed: int
    percentiles: dict[str, tuple[float, ...]]
    failure_probability: dict[str, float]


def lognormal_factors(rng: np.random.Generator, n: int, cov: float) -> np.ndarray:
    """``n`` factors of a lognormal with median 1 and coefficient of variation ``cov`` [-].

    >>> f = lognormal_factors(np.random.default_rng(0), 400_000, 0.3)
    >>> round(float(np.median(f)), 3), round(float(f.std() / f.mean()), 3)
    (1.0, 0.3)
    """
    return np.exp(rng.normal(0.0, math.sqrt(math.log1p(cov * cov)), n))


#: Scene kind -> the foundation as :func:`refuse_unscaled` names it.
NOUNS = {"crank_foundation": "crank foundation", "block_foundation": "block"}


def refuse_unscaled(scene) -> None:
    """Raise UsageError on ``--sample`` (exit 2) when the support of ``scene`` has springs that do
    not scale with one factor on the soil's modulus, which the sample draws
    (:attr:`~foundation_calc.solvers.supports.base.Support.unscaled`: a pile group, EN 1998-5
    Table C.1, K ∝ E_s^(1 - n))."""
    from foundation_calc.errors import UsageError

    if (unscaled := scene.support().unscaled) is not None:
        judged = ("give soil.modulus_range and fcalc check judges the range" if getattr(scene, "soil", None) is not None
                  else "fcalc check judges the block on the rates given")  # isolators: no [soil] to bracket
        raise UsageError(f"not sampled, a {NOUNS[scene.kind]} on {unscaled}; {judged}", "'--sample'")


def sample_scene(scene, n: int, cov_modulus: float, cov_speed: float = 0.0, seed: int = 0) -> SoilSample:
    """Sample ``scene``'s soil ``n`` times (module docstring) by its kind's engine (:data:`ENGINES`).

    Raises UsageError for a support the sample cannot scale (:func:`refuse_unscaled`)."""
    refuse_unscaled(scene)
    rng = np.random.default_rng(seed)
    factor = lognormal_factors(rng, n, cov_modulus)
    speed = np.maximum(1.0 + cov_speed * rng.normal(size=n), 1e-3) if cov_speed > 0.0 else np.ones(n)
    values, ok, tips_over, fails_resonance, fails_amplitude = importlib.import_module(ENGINES[scene.kind]).engine(
        scene, factor, speed)

    def pct(sampled):
        sampled = np.asarray(sampled, dtype=float)
        kept = sampled[ok] if ok.any() else sampled
        return tuple(float(v) for v in np.percentile(kept, PERCENTILES))

    return SoilSample(
        n, cov_modulus, cov_speed, seed,
        percentiles={key: pct(sampled) for key, sampled in {"modulus_factor": factor, **values}.items()},
        failure_probability={
            "tips_over": float(np.mean(tips_over)),
            "resonance": float(np.mean(fails_resonance)),
            "amplitudes": float(np.mean(fails_amplitude)),
            "any": float(np.mean(fails_resonance | fails_amplitude)),
        },
    )


__all__ = ["ENGINES", "NOUNS", "PERCENTILES", "SoilSample", "lognormal_factors", "refuse_unscaled", "sample_scene"]
