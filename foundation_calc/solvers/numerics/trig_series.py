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


def _values(cos, sin, n, phi):
    """q, dq/dφ and d²q/dφ² of C series (rows of ``cos``, ``sin``, shape (C, K + 1)) at one phase
    each (``phi``, shape (C,)). The powers e^{inφ} are repeated products of e^{iφ}: n roundings
    each, so the term of harmonic n carries a relative error of about n × 1e-16."""
    powers = np.empty(cos.shape, dtype=complex)
    powers[:, 0] = 1.0
    powers[:, 1:] = np.exp(1j * phi)[:, None]
    np.cumprod(powers[:, 1:], axis=1, out=powers[:, 1:])
    c, s = powers.real, powers.imag
    terms = cos * c + sin * s
    q = terms.sum(1)
    dq = (n * (sin * c - cos * s)).sum(1)
    ddq = -(n * n * terms).sum(1)
    return q, dq, ddq


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
    weight = (np.arange(K + 1) * np.hypot(cos, sin)).reshape(-1, K + 1)
    # tail[:, k] = Σ_{n>k} weight_n, accumulated from the top so that small terms add first
    tail = np.zeros_like(weight)
    tail[:, :-1] = np.cumsum(weight[:, :0:-1], axis=1)[:, ::-1]
    enough = (tail <= _TAIL * weight.sum(1)[:, None]).all(0)
    return int(np.argmax(enough))


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
    cos, sin = cos.reshape(-1, K + 1), sin.reshape(-1, K + 1)
    n = np.arange(K + 1)
    Ks = searched_harmonics(cos, sin)
    N = grid_size(Ks)
    step = 2.0 * np.pi / N
    spectrum = np.zeros((cos.shape[0], N // 2 + 1), dtype=complex)
    spectrum[:, : Ks + 1] = (N / 2.0) * (cos[:, : Ks + 1] - 1j * sin[:, : Ks + 1])
    spectrum[:, 0] = N * cos[:, 0]
    sampled = np.abs(np.fft.irfft(spectrum, N, axis=1))
    size = n * np.hypot(cos, sin)  # n |c_n|: Σ bounds |dq/dφ|, Σ n × bounds |d²q/dφ²|
    reach = (n * size).sum(1) * step * step / 8.0 + 2.0 * _TAIL * size.sum(1)
    left, right = np.roll(sampled, 1, 1), np.roll(sampled, -1, 1)
    # a plateau of equal samples counts once (its first sample); a constant series has none
    candidate = (sampled > left) & (sampled >= right)
    candidate &= sampled >= (sampled.max(1) - reach)[:, None]
    row, j = np.nonzero(candidate)
    below, top, above = left[row, j], sampled[row, j], right[row, j]
    bend = below - 2.0 * top + above  # < 0 at a strict local maximum
    shift = np.where(bend < 0.0, 0.5 * (below - above) / np.where(bend < 0.0, bend, -1.0), 0.0)
    phi = (j + np.clip(shift, -0.5, 0.5)) * step
    head_cos, head_sin = cos[row, : Ks + 1], sin[row, : Ks + 1]
    for _ in range(_NEWTON_STEPS):
        q, dq, ddq = _values(head_cos, head_sin, n[: Ks + 1], phi)
        concave = q * ddq < 0.0  # |q| has a maximum nearby
        move = np.clip(np.where(concave, dq / np.where(concave, ddq, 1.0), 0.0), -step, step)
        phi = phi - move
        if not np.any(np.abs(move) * max(Ks, 1) > 1e-9):
            break
    result = np.abs(cos[:, 0])  # the mean: a lower bound, and the peak of a constant series
    np.maximum.at(result, row, np.abs(_values(cos[row], sin[row], n, phi)[0]))
    return result.reshape(batch) if batch else result[0]


__all__ = ["analyse", "basis", "derivative", "grid_size", "magnitude", "peak", "phases", "sample", "searched_harmonics"]
