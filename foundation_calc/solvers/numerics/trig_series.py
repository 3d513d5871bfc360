"""Real trigonometric series of one period: sampling, analysis, derivatives and peaks.

A periodic signal of the crank speed ω is stored as its cosine and sine coefficients,
arrays ``cos``, ``sin`` of shape ``(..., K + 1)`` for the harmonics n = 0 ... K::

    q(t) = Σ_n cos[n] cos(nωt) + sin[n] sin(nωt)        (sin[0] is ignored)

Leading dimensions are batches (designs, degrees of freedom, points); every function
broadcasts over them.
"""

from __future__ import annotations

import numpy as np

#: Newton steps that refine a sampled extremum at most; from the parabola through the samples
#: round the extremum, two or three reach round-off.
_NEWTON_STEPS = 8

#: Fraction of a series' slope bound Σ n|c_n| below which its highest harmonics are left out of
#: the search for its peak. The value at the peak is taken from the whole series, so the tail
#: only shifts the phase found, by about its slope over q'', and the value by the square of that:
#: below 1e-17 relative (the highest harmonics of every solver's series are round-off anyway).
_TAIL = 1e-9

#: Samples per period of the highest harmonic searched, and at least this many samples.
_SAMPLES_PER_PERIOD = 8
_MIN_SAMPLES = 64


def phases(N: int) -> np.ndarray:
    """N equally spaced phases ωt_j = 2πj/N over one period [rad]."""
    return 2.0 * np.pi * np.arange(N) / N


def basis(K: int, phi) -> tuple[np.ndarray, np.ndarray]:
    """cos(nφ) and sin(nφ) for n = 0 ... K, shape ``(len(phi), K + 1)``."""
    arg = np.multiply.outer(np.asarray(phi, dtype=float), np.arange(K + 1))
    return np.cos(arg), np.sin(arg)


def sample(cos, sin, N: int):
    """Values of the series at the N phases of :func:`phases`, shape ``(..., N)``."""
    K = np.shape(cos)[-1] - 1
    cb, sb = basis(K, phases(N))
    return cos @ cb.T + sin @ sb.T


def analyse(values, K: int):
    """Cosine and sine coefficients (n = 0 ... K) of samples taken at :func:`phases`.

    Exact for a series of degree < N/2 (discrete orthogonality); ``values`` may be complex
    (the complex-step derivative of the Jacobian passes through unchanged).
    """
    N = np.shape(values)[-1]
    if 2 * K >= N:
        raise ValueError(f"{N} samples resolve harmonics below {N // 2}, not {K}")
    cb, sb = basis(K, phases(N))
    weights = np.full(K + 1, 2.0 / N)
    weights[0] = 1.0 / N
    return (values @ cb) * weights, (values @ sb) * weights


def derivative(cos, sin, omega, order: int = 1):
    """Coefficients of the ``order``-th time derivative (d/dt = ω d/dφ)."""
    n_omega = np.arange(np.shape(cos)[-1]) * np.asarray(omega)[..., None]
    for _ in range(order):
        cos, sin = n_omega * sin, -n_omega * cos
    return cos, sin


def magnitude(cos, sin):
    """Amplitude of each harmonic, sqrt(cos² + sin²)."""
    return np.hypot(cos, sin)


def rms(cos, sin):
    """RMS over one period of the oscillating part of a series [unit of q]: sqrt(Σ_{n≥1} (c_n² + s_n²)/2).

    The mean (n = 0) is left out: it is a static offset, not vibration (ISO 10816-1, 3.3: the
    r.m.s. of the vibration). Parseval's identity over one period.

    >>> round(float(rms(np.array([5.0, 3.0, 0.0]), np.array([0.0, 0.0, 4.0]))), 12)  # 3 cos φ + 4 sin 2φ
    3.535533905933
    """
    cos, sin = np.asarray(cos, dtype=float), np.asarray(sin, dtype=float)
    return np.sqrt(0.5 * (cos[..., 1:] ** 2 + sin[..., 1:] ** 2).sum(-1))


def _horner(coefficients, z):
    """Σ_n coefficients[n] z^n for every column: ``coefficients`` (K + 1, C), ``z`` (C,).
    Horner's scheme: its rounding error is about 1e-16 Σ_n (n + 1)|coefficients[n]|."""
    total = coefficients[-1].copy()
    for row in coefficients[-2::-1]:
        total *= z
        total += row
    return total


def _values(a, phi):
    """q, dq/dφ and d²q/dφ² of series at one phase each: ``a`` = cos - i sin, shape (K + 1, C)
    (a column per series), ``phi`` (C,). q = Re Σ a_n e^{inφ}, and each φ-derivative brings i n."""
    z = np.exp(1j * phi)
    n = np.arange(a.shape[0])[:, None]
    return _horner(a, z).real, -_horner(n * a, z).imag, -_horner(n * n * a, z).real


def _searched(slopes) -> int:
    """:func:`searched_harmonics` from n |c_n|, shape (K + 1, B): a column per series."""
    total = slopes.sum(0)
    # the largest share of each harmonic over the batch: a tail of these shares bounds every
    # series' tail; summed from the top so that small terms add first
    share = (slopes / np.where(total > 0.0, total, 1.0)).max(1, initial=0.0)
    tail = np.zeros_like(share)
    tail[:-1] = np.cumsum(share[:0:-1])[::-1]
    return int(np.argmax(tail <= _TAIL))


def searched_harmonics(cos, sin) -> int:
    """Highest harmonic K_s that the search for the peaks of a batch of series needs.

    Beyond K_s the tail of every series in the batch has a slope Σ_{n>K_s} n |c_n| of at most
    1e-9 of the series' Σ_n n |c_n| (|c_n| = sqrt(cos_n² + sin_n²)); its value Σ_{n>K_s} |c_n| is
    smaller still.

    >>> searched_harmonics(np.array([[0.0, 1.0, 1e-3, 1e-12, 1e-21]]), np.zeros((1, 5)))
    2
    """
    cos, sin = np.asarray(cos, dtype=float), np.asarray(sin, dtype=float)
    K = cos.shape[-1] - 1
    return _searched((np.arange(K + 1) * magnitude(cos, sin)).reshape(-1, K + 1).T)


def grid_size(K: int) -> int:
    """Samples per period for a search over harmonics 0 ... K: ``_SAMPLES_PER_PERIOD`` per period
    of the highest, at least ``_MIN_SAMPLES``, a multiple of 16 (cheap FFT lengths)."""
    return max(_MIN_SAMPLES, -(-_SAMPLES_PER_PERIOD * K // 16) * 16)


def peak(cos, sin):
    """Largest |q(t)| over one period, to round-off (about 1e-15 relative).

    1. The search keeps the harmonics 0 ... K_s that matter (:func:`searched_harmonics`) and
       samples them by an inverse FFT at N = :func:`grid_size` (K_s) phases, spacing Δφ = 2π/N.
    2. The global maximum of |q| lies within Δφ/2 of a sample, which is then at most
       max|q''| Δφ²/8 <= Σ n²|c_n| Δφ²/8 below it (Taylor), plus twice the tail left out. Only
       the local maxima of the samples within that bound of the best can hold it; all of them,
       over the whole batch at once, are refined: a parabola through the three samples places the
       extremum, Newton steps on dq/dφ = 0 (each at most Δφ, none where |q| is not concave) reach
       round-off in two or three steps.
    3. The peak is |q| of the whole series at the refined phases (the left-out tail moves the
       phase by about its slope over q'', and the value by the square of that).

    ``cos``, ``sin``: coefficients of harmonics 0 ... K on the last axis (batches before it);
    the result has the batch shape.

    >>> round(float(peak(np.array([0.0, 1.0, 0.5]), np.zeros(3))), 12)  # cos φ + cos 2φ / 2
    1.5
    >>> round(float(peak(np.array([0.0, 0.0]), np.array([0.0, 2.0]))), 12)
    2.0
    """
    cos, sin = np.broadcast_arrays(np.asarray(cos, dtype=float), np.asarray(sin, dtype=float))
    batch, K = cos.shape[:-1], cos.shape[-1] - 1
    # harmonics and samples on the first axis, a column per series: Horner's scheme and the
    # candidates' gather then run over contiguous rows
    a = np.empty((K + 1, int(np.prod(batch))), dtype=complex)  # a_n = cos_n - i sin_n
    a.real = cos.reshape(-1, K + 1).T
    np.negative(sin.reshape(-1, K + 1).T, out=a.imag)
    n = np.arange(K + 1)[:, None]
    slopes = n * np.abs(a)  # Σ n|c_n| bounds |dq/dφ|, Σ n²|c_n| bounds |d²q/dφ²|
    Ks = _searched(slopes)
    N = grid_size(Ks)
    step = 2.0 * np.pi / N
    spectrum = np.zeros((N // 2 + 1, a.shape[1]), dtype=complex)
    spectrum[: Ks + 1] = (N / 2.0) * a[: Ks + 1]
    spectrum[0] = N * a[0].real
    sampled = np.abs(np.fft.irfft(spectrum, N, axis=0))
    reach = (n * slopes).sum(0) * step * step / 8.0 + 2.0 * _TAIL * slopes.sum(0)
    ring = np.concatenate([sampled[-1:], sampled, sampled[:1]])  # the period closes on itself
    below, above = ring[:-2], ring[2:]
    # a plateau of equal samples counts once (its first sample); a constant series has none
    candidate = (sampled > below) & (sampled >= above) & (sampled >= sampled.max(0) - reach)
    j, col = np.nonzero(candidate)
    low, top, high = below[j, col], sampled[j, col], above[j, col]
    bend = low - 2.0 * top + high  # < 0 at a strict local maximum
    shift = np.where(bend < 0.0, 0.5 * (low - high) / np.where(bend < 0.0, bend, -1.0), 0.0)
    phi = (j + np.clip(shift, -0.5, 0.5)) * step
    a = a[:, col]  # a column per candidate
    for _ in range(_NEWTON_STEPS):
        q, dq, ddq = _values(a[: Ks + 1], phi)
        concave = q * ddq < 0.0  # |q| has a maximum nearby
        move = np.clip(np.where(concave, dq / np.where(concave, ddq, 1.0), 0.0), -step, step)
        phi = phi - move
        if not np.any(np.abs(move) * max(Ks, 1) > 1e-9):
            break
    result = np.abs(cos.reshape(-1, K + 1)[:, 0])  # the mean: a lower bound, the peak of a constant
    np.maximum.at(result, col, np.abs(_horner(a, np.exp(1j * phi)).real))
    return result.reshape(batch) if batch else result[0]


__all__ = ["analyse", "basis", "derivative", "grid_size", "magnitude", "peak", "phases", "rms", "sample", "searched_harmonics"]
