"""A sample of crank-mechanism designs on the soil × a factor, in one array operation: per sample
whether it stands, k0, p1, p2 (the paper's operator), the margin of the speed from the nearest of
the paper's six conditions, whether it is resonant and the peak horizontal and vertical
displacement of C (``fcalc soil --sample`` of a crank scene,
:mod:`~foundation_calc.checks.soil_sample.crank` judges them).

The designs come from ``at(soil_frequency, factor, speed)`` (arrays alike): the design with speed
ω × ``speed`` and soil stiffness × ``factor``, a frequency-dependent soil's springs and dashpots
taken at ``soil_frequency`` [rad/s]. A sample stands or tips over on its springs at rest (the
rocking spring must exceed the weight's overturning moment P h); a tipping sample is counted, never
solved. The margin is measured, as the resonance check does, to the nearer of the zero-order and
the averaged-inertia critical speed. The peaks are those of the corrected first approximation,
sampled at :data:`PEAK_PHASES` phases a revolution.

A frequency-dependent soil (Gazetas) is taken as the checks take it: every mode of every sample
solves ω = p(K(ω)) (a bracketed root, the whole array at once), each harmonic n of the response
takes the springs at n ω, and where the rocking spring at one of the first approximation's
harmonics does not exceed P h the first approximation steps aside for the averaged operator
(:func:`dependent_motion`), as ``fcalc amplitudes`` judges that soil.
"""

from __future__ import annotations

from dataclasses import dataclass

import numpy as np

from foundation_calc.solvers.crank.closed_form import first_approximation_motion, soft_at_harmonic
from foundation_calc.solvers.crank.frequencies import NaturalFrequencies, rocking_stability_margin
from foundation_calc.solvers.crank.mechanism import CrankDesign
from foundation_calc.solvers.crank.natural import design_frequencies
from foundation_calc.solvers.crank.resonance import CONDITIONS, condition_margin
from foundation_calc.solvers.crank.response import splice_harmonics
from foundation_calc.solvers.soil.impedance import consistent_frequency

#: Phases per revolution at which a sample's displacement is evaluated for its peak: for the
#: first approximation's harmonics up to 3 the sampled maximum is at most 1 - cos(3π/96) = 0.48 %
#: below the true peak (the checks' own peaks are found by Newton; here 1e5 samples must cost
#: well under a second).
PEAK_PHASES = 96

#: Samples per block of the peak search (bounds its memory: 2 · 96 · 8 bytes a sample).
PEAK_CHUNK = 16_384


@dataclass(frozen=True)
class SampledMechanism:
    """Per sample (n,): ``stable`` (stands on its springs at rest), ``frequencies`` k0, p1, p2 of
    the paper's operator [rad/s], ``margin`` from the nearest paper condition [-], ``resonant``
    (no steady state), ``horizontal`` and ``vertical`` peak displacement of C [m]."""

    stable: np.ndarray
    frequencies: NaturalFrequencies
    margin: np.ndarray
    resonant: np.ndarray
    horizontal: np.ndarray
    vertical: np.ndarray


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


def _consistent(at, factor, speed, which: int) -> NaturalFrequencies:
    """k0, p1, p2 of every sample, each on the springs at its own frequency (ω = p(K(ω)));
    ``which`` 0: the paper's operator, 1: the averaged inertia."""
    static = design_frequencies(at(0.0, factor, speed))[which]
    return NaturalFrequencies(**{
        mode: consistent_frequency(lambda w, mode=mode: getattr(design_frequencies(at(w, factor, speed))[which], mode),
                                   getattr(static, mode))
        for mode in ("k0", "p1", "p2")
    })


def dependent_motion(design: CrankDesign, at, factor, speed):
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
        parts.append((aside, *coupled_motion(design, w, lambda frequencies: block_matrices(at(frequencies, f, s)))))
    return side_by_side(omega, parts)


def sample_mechanism(design: CrankDesign, at, factor, speed, frequency_dependent: bool) -> SampledMechanism:
    """The samples ``factor``, ``speed`` (n,) of ``design`` built by ``at`` (module docstring)."""
    d = at(0.0, factor, speed)
    stable = rocking_stability_margin(d.c_phi, d.I1, d.M_tot * d.g, d.h) > 0.0  # at rest, as the checks judge it
    safe = np.where(stable, factor, 1.0)  # a tipping sample is counted, never solved
    static = at(0.0, safe, speed)
    omega = static.omega
    if frequency_dependent:
        zero, averaged = _consistent(at, safe, speed, 0), _consistent(at, safe, speed, 1)
        motion, resonant = dependent_motion(design, at, safe, speed)
    else:
        zero, averaged = design_frequencies(static)
        motion, resonant = first_approximation_motion(static)
    margins = [condition_margin(omega, zero, averaged, c) for c in CONDITIONS if c.source == "paper"]
    horizontal, vertical = sampled_peaks(np.nan_to_num(motion.cos[..., :2, :]), np.nan_to_num(motion.sin[..., :2, :]))
    return SampledMechanism(stable, zero, np.min(np.stack(margins), axis=0), np.asarray(resonant, dtype=bool),
                            horizontal, vertical)


__all__ = ["PEAK_PHASES", "SampledMechanism", "dependent_motion", "sample_mechanism", "sampled_peaks"]
