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

A frequency-dependent soil (Gazetas) is sampled as the checks take it: the factor scales G (so
V_s by sqrt F and every a0 with it), every mode of every sample solves ω = p(K(ω)) (a bracketed root,
the whole array at once), and each harmonic n of the response takes the springs at n ω; a sample
stands or tips over on its springs at rest, and where its rocking spring at one of the first
approximation's harmonics does not exceed P h the first approximation steps aside for the
averaged operator (:func:`_dependent_motion`), as ``fcalc amplitudes`` judges that soil.
The sample is of the crank mechanism's response; a scene's ``[[loads]]`` are not part of it.

Per sample: k0, p1, p2 (the paper's operator), the margin of the speed from the nearest of the
paper's six conditions (measured, as the check does, to the nearer of the zero-order and the
averaged-inertia critical speed), the peak
horizontal and vertical displacement of C by the corrected first approximation (sampled at
:data:`PEAK_PHASES` phases a revolution). The resonance
check fails where that margin is below the scene's detuning (the paper's conditions fail inside
the band), the amplitude check where a peak exceeds ``[limits] amplitude`` or the sample is
resonant; a sample whose rocking spring does not exceed the weight's overturning moment tips over
and fails both.
"""

from __future__ import annotations

import math
from dataclasses import dataclass, replace

import numpy as np

from foundation_calc.solvers.crank.closed_form import first_approximation_motion, soft_at_harmonic, varied
from foundation_calc.solvers.crank.frequencies import NaturalFrequencies, rocking_stability_margin
from foundation_calc.solvers.crank.natural import design_frequencies
from foundation_calc.solvers.crank.resonance import CONDITIONS, condition_margin
from foundation_calc.solvers.crank.response import splice_harmonics
from foundation_calc.solvers.soil.impedance import consistent_frequency

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
    >>> round(float(np.median(f)), 3), round(float(f.std() / f.mean()), 3)
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


def _designs_at(scene):
    """``at(soil_frequency, factor, speed)``: the scene's design as arrays, speed ω × ``speed``, soil
    stiffness × ``factor``, a frequency-dependent soil's springs and dashpots taken at
    ``soil_frequency`` [rad/s] (arrays alike), which the design carries (its ``soil_frequency``:
    stability is judged at rest, and the first approximation steps aside where a harmonic's
    rocking spring does not exceed P h, as the checks take that soil)."""
    base = scene.design()
    if not scene.support().frequency_dependent:
        return lambda soil_frequency, factor, speed: varied(base, omega=base.omega * speed, soil_factor=factor)
    from foundation_calc.solvers.soil.dashpots import dashpots_from_ratios

    f = scene.foundation
    h, I_c, M_rod = f.cog_height, f.moment_of_inertia, base.M_tot  # the dashpots' body as scene.design takes it

    def at(soil_frequency, factor, speed):  # the scene's own method (and stratum) on the soil × factor
        k = scene.with_modulus_factor(factor).soil_springs(omega=soil_frequency)
        c = dashpots_from_ratios(k.xi_z, k.xi_x, k.xi_phi, k.K_z, k.K_x, k.K_phi, M_rod, I_c + M_rod * h * h)
        return replace(base, omega=base.omega * speed, c=k.K_z / f.base_area, c1=k.K_x / f.base_area,
                       c_phi=k.K_phi / f.base_second_moment, C_x=c.C_x, C_z=c.C_z, C_phi=c.C_phi,
                       soil_frequency=np.asarray(soil_frequency, dtype=float))

    return at


def _consistent(at, factor, speed, which: int) -> NaturalFrequencies:
    """k0, p1, p2 of every sample, each on the springs at its own frequency (ω = p(K(ω)));
    ``which`` 0: the paper's operator, 1: the averaged inertia."""
    static = design_frequencies(at(0.0, factor, speed))[which]
    return NaturalFrequencies(**{
        mode: consistent_frequency(lambda w, mode=mode: getattr(design_frequencies(at(w, factor, speed))[which], mode),
                                   getattr(static, mode))
        for mode in ("k0", "p1", "p2")
    })


def _dependent_motion(scene, at, factor, speed):
    """The mechanism's steady state of every sample on a frequency-dependent soil, and where it is
    resonant, as ``fcalc amplitudes`` takes that soil: the first approximation, each harmonic n at
    n ω (the mean on the static springs); a sample where it steps aside (the rocking spring at one
    of its harmonics' soil does not exceed P h, :func:`~foundation_calc.solvers.crank.closed_form.soft_at_harmonic`)
    gets the averaged operator with the exact forcing, each harmonic n at n ω
    (:func:`~foundation_calc.solvers.crank.sweep.coupled_motion`), which the check judges there."""
    from foundation_calc.solvers.crank.sweep import FIRST_APPROXIMATION_HARMONICS, coupled_motion, side_by_side
    from foundation_calc.solvers.crank.averaged import block_matrices

    omega = at(0.0, factor, speed).omega
    harmonics = range(1, FIRST_APPROXIMATION_HARMONICS + 1)
    aside = np.logical_or.reduce([soft_at_harmonic(at(k * omega, factor, speed)) for k in harmonics])
    parts = []
    if not aside.all():
        f, s, w = factor[~aside], speed[~aside], omega[~aside]
        motions = [first_approximation_motion(at(k * w, f, s)) for k in (0, *harmonics)]
        parts.append((~aside, splice_harmonics([m for m, _ in motions]), motions[1][1]))
    if aside.any():
        f, s, w = factor[aside], speed[aside], omega[aside]
        parts.append((aside, *coupled_motion(scene.design(), w, lambda frequencies: block_matrices(at(frequencies, f, s)))))
    return side_by_side(omega, parts)


def sample_scene(scene, n: int, cov_modulus: float, cov_speed: float = 0.0, seed: int = 0) -> SoilSample:
    """Sample a ``crank_foundation`` scene's mechanism ``n`` times (module docstring)."""
    rng = np.random.default_rng(seed)
    factor = lognormal_factors(rng, n, cov_modulus)
    speed = np.maximum(1.0 + cov_speed * rng.normal(size=n), 1e-3) if cov_speed > 0.0 else np.ones(n)
    at = _designs_at(scene)
    d = at(0.0, factor, speed)
    stable = rocking_stability_margin(d.c_phi, d.I1, d.M_tot * d.g, d.h) > 0.0  # at rest, as the checks judge it
    safe = np.where(stable, factor, 1.0)  # a tipping sample is counted, never solved
    static = at(0.0, safe, speed)
    omega = static.omega
    if scene.support().frequency_dependent:
        zero, averaged = _consistent(at, safe, speed, 0), _consistent(at, safe, speed, 1)
        motion, resonant = _dependent_motion(scene, at, safe, speed)
    else:
        zero, averaged = design_frequencies(static)
        motion, resonant = first_approximation_motion(static)
    margins = [condition_margin(omega, zero, averaged, c) for c in CONDITIONS if c.source == "paper"]
    margin = np.min(np.stack(margins), axis=0)
    resonant = np.asarray(resonant, dtype=bool)
    horizontal, vertical = sampled_peaks(np.nan_to_num(motion.cos[..., :2, :]), np.nan_to_num(motion.sin[..., :2, :]))
    fails_resonance = ~stable | (margin < scene.limits.detuning)
    fails_amplitude = ~stable | resonant
    if scene.limits.amplitude is not None:
        fails_amplitude |= (horizontal > scene.limits.amplitude) | (vertical > scene.limits.amplitude)
    values = {"modulus_factor": factor, "k0": zero.k0, "p1": zero.p1, "p2": zero.p2, "resonance_margin": margin,
              "peak_horizontal_C": horizontal, "peak_vertical_C": vertical}
    return summary(SoilSample(n, cov_modulus, cov_speed, seed, {}, {}), values, stable & ~resonant, ~stable, fails_resonance,
                   fails_amplitude)


def summary(drawn: SoilSample, values: dict, ok, tips_over, fails_resonance, fails_amplitude) -> SoilSample:
    """``drawn`` with the :data:`PERCENTILES` of every sampled quantity in ``values`` (name -> (n,),
    over the samples ``ok``: those that stand and have a steady state, or all when none does) and
    the fraction of the samples that tip over and that fail each check (bool (n,) each); every
    kind's sample reports through here."""

    def pct(sampled):
        sampled = np.asarray(sampled, dtype=float)
        kept = sampled[ok] if ok.any() else sampled
        return tuple(float(v) for v in np.percentile(kept, PERCENTILES))

    return replace(
        drawn,
        percentiles={key: pct(sampled) for key, sampled in values.items()},
        failure_probability={
            "tips_over": float(np.mean(tips_over)),
            "resonance": float(np.mean(fails_resonance)),
            "amplitudes": float(np.mean(fails_amplitude)),
            "any": float(np.mean(fails_resonance | fails_amplitude)),
        },
    )


__all__ = ["PERCENTILES", "SoilSample", "lognormal_factors", "sample_scene", "sampled_peaks", "summary"]
