"""The uncertain soil as a distribution: percentiles of the frequencies, margins and peaks, and the
probability that a check fails, from a sample of the closed forms in one array operation.

Distributions (independent):

- soil stiffness factor F ~ lognormal with median 1 and coefficient of variation ``cov_modulus``
  (ln F ~ N(0, s²), s² = ln(1 + cov²)): every spring is F times the scene's (c_z, c_x, c_phi;
  K ∝ G or E), the damping ratios stay, so the dashpots C = 2 ξ sqrt(K m) go as sqrt(F)
  (:func:`~foundation_calc.solvers.crank.closed_form.varied`). A lognormal keeps the modulus
  positive and makes 1/F as likely as F; site moduli scatter with a COV of about 0.2-0.5.
- speed factor ~ normal with mean 1 and standard deviation ``cov_speed`` (0: the speed as given),
  for a machine whose speed drifts or is not yet fixed.

A frequency-dependent soil (Gazetas) is sampled on its springs at the operating speed: the sample
scales them; the shift of each mode's springs with its own frequency is not resampled. The
sample is of the crank mechanism's response; a scene's ``[[loads]]`` are not part of it.

Per sample: k0, p1, p2 (the paper's operator), the margin of the speed from the nearest of the
paper's six conditions (:func:`~foundation_calc.checks.crank_resonance.paper_margin`), the peak
horizontal and vertical displacement of C by the corrected first approximation (sampled at
:data:`PEAK_PHASES` phases a revolution). The resonance
check fails where that margin is below the scene's detuning (the paper's conditions fail inside
the band), the amplitude check where a peak exceeds ``[limits] amplitude`` or the sample is
resonant; a sample whose rocking spring does not exceed the weight's overturning moment tips over
and fails both.
"""

from __future__ import annotations

import math
from dataclasses import dataclass

import numpy as np

from foundation_calc.checks.crank_resonance import design_frequencies, paper_margin
from foundation_calc.solvers.crank.closed_form import first_approximation_motion, varied
from foundation_calc.solvers.crank.frequencies import rocking_stability_margin

#: Percentiles reported [%].
PERCENTILES = (5.0, 50.0, 95.0)

#: Phases per revolution at which a sample's displacement is evaluated for its peak: for the
#: first approximation's harmonics up to 3 the sampled maximum is at most 1 - cos(3π/96) = 0.48 %
#: below the true peak (the checks' own peaks are found by Newton; here 1e5 samples must cost
#: well under a second).
PEAK_PHASES = 96

#: Samples per block of the peak search (bounds its memory: 2 · 96 · 8 bytes a sample).
PEAK_CHUNK = 16_384


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
    >>> round(float(np.median(f)), 2), round(float(f.std() / f.mean()), 2)
    (1.0, 0.3)
    """
    return np.exp(rng.normal(0.0, math.sqrt(math.log1p(cov * cov)), n))


def sampled_peaks(cos: np.ndarray, sin: np.ndarray) -> tuple[np.ndarray, np.ndarray]:
    """Largest |x|, |y| [m] over one revolution of series of shape (n, 2, K + 1), sampled at
    :data:`PEAK_PHASES` phases (:data:`PEAK_PHASES` bounds the error).

    >>> c = np.zeros((1, 2, 4)); c[0, 1, 1] = 2.0
    >>> [float(v[0]) for v in sampled_peaks(c, np.zeros_like(c))]
    [0.0, 2.0]
    """
    harmonics = np.arange(cos.shape[-1])
    phase = 2.0 * np.pi * np.arange(PEAK_PHASES) / PEAK_PHASES
    basis_cos, basis_sin = np.cos(np.outer(harmonics, phase)), np.sin(np.outer(harmonics, phase))
    out = np.empty(cos.shape[:-1])
    for start in range(0, cos.shape[0], PEAK_CHUNK):
        block = slice(start, start + PEAK_CHUNK)
        values = cos[block] @ basis_cos + sin[block] @ basis_sin
        out[block] = np.abs(values).max(axis=-1)
    return out[:, 0], out[:, 1]


def sample_design(design, detuning: float, amplitude_limit: float | None, n: int, cov_modulus: float,
                  cov_speed: float = 0.0, seed: int = 0) -> SoilSample:
    """Sample ``design`` (a :class:`~foundation_calc.solvers.crank.mechanism.CrankDesign`) ``n``
    times (module docstring); ``amplitude_limit`` [m] or None."""
    rng = np.random.default_rng(seed)
    factor = lognormal_factors(rng, n, cov_modulus)
    speed = np.maximum(1.0 + cov_speed * rng.normal(size=n), 1e-3) if cov_speed > 0.0 else np.ones(n)
    d = design
    stable = rocking_stability_margin(d.c_phi * factor, d.I1, d.M_tot * d.g, d.h) > 0.0
    safe = np.where(stable, factor, 1.0)  # a tipping sample is counted, never solved
    batch = varied(d, omega=d.omega * speed, soil_factor=safe)
    zero, _ = design_frequencies(batch)
    margin = paper_margin(batch)
    motion, resonant = first_approximation_motion(batch)
    horizontal, vertical = sampled_peaks(np.nan_to_num(motion.cos[..., :2, :]), np.nan_to_num(motion.sin[..., :2, :]))
    fails_resonance = ~stable | (margin < detuning)
    fails_amplitude = ~stable | np.asarray(resonant, dtype=bool)
    if amplitude_limit is not None:
        fails_amplitude |= (horizontal > amplitude_limit) | (vertical > amplitude_limit)
    ok = stable & ~np.asarray(resonant, dtype=bool)

    def pct(values):
        kept = values[ok] if ok.any() else values
        return tuple(float(v) for v in np.percentile(kept, PERCENTILES))

    return SoilSample(
        samples=n, cov_modulus=cov_modulus, cov_speed=cov_speed, seed=seed,
        percentiles={
            "modulus_factor": pct(factor), "k0": pct(zero.k0), "p1": pct(zero.p1), "p2": pct(zero.p2),
            "resonance_margin": pct(margin), "peak_horizontal_C": pct(horizontal), "peak_vertical_C": pct(vertical),
        },
        failure_probability={
            "tips_over": float(np.mean(~stable)),
            "resonance": float(np.mean(fails_resonance)),
            "amplitudes": float(np.mean(fails_amplitude)),
            "any": float(np.mean(fails_resonance | fails_amplitude)),
        },
    )


def sample_scene(scene, n: int, cov_modulus: float, cov_speed: float = 0.0, seed: int = 0) -> SoilSample:
    """:func:`sample_design` of a ``crank_foundation`` scene's mechanism (a frequency-dependent
    soil on its springs at the operating speed)."""
    at = scene.speed.omega_rad_s if scene.soil.frequency_dependent else 0.0
    return sample_design(scene.design(at), scene.limits.detuning, scene.limits.amplitude, n, cov_modulus,
                         cov_speed, seed)


__all__ = ["PERCENTILES", "SoilSample", "lognormal_factors", "sample_design", "sample_scene"]
