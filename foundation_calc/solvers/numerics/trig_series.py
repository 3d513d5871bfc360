"""Real trigonometric series of one period: sampling, analysis, derivatives and peaks.

A periodic signal of the crank speed ω is stored as its cosine and sine coefficients,
arrays ``cos``, ``sin`` of shape ``(..., K + 1)`` for the harmonics n = 0 ... K::

    q(t) = Σ_n cos[n] cos(nωt) + sin[n] sin(nωt)        (sin[0] is ignored)

Leading dimensions are batches (designs, degrees of freedom, points); every function
broadcasts over them.
"""

from __future__ import annotations

import numpy as np

#: Newton steps that refine a sampled extremum; from a sample spacing of 2π/N quadratic
#: convergence reaches round-off in 4-5 steps, the rest is margin.
_NEWTON_STEPS = 8
#: A Newton step [rad] below which the extremum's phase is exact to round-off after it: the
#: error after a step of δ is about (K δ)², and |q| at the peak moves by its square.
_CONVERGED_STEP = 1e-8


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


def _values(cos, sin, n, phi):
    """q, dq/dφ and d²q/dφ² at phases ``phi`` (shape (P,)) of P series (shape (P, K + 1))."""
    arg = phi[:, None] * n
    c, s = np.cos(arg), np.sin(arg)
    terms = cos * c + sin * s
    return terms.sum(-1), (sin * c - cos * s) @ n, terms @ (-n * n)


def peak(cos, sin):
    """Largest |q(t)| over one period, to round-off (about 1e-15 relative).

    The series is sampled by an inverse FFT on a grid of at least 16 points per period of the
    highest harmonic; every sample that is a local maximum of |q| is refined by Newton steps on
    dq/dφ = 0 (each step limited to one grid spacing). The global extremum lies within one
    spacing of a local maximum of the samples, and refinement cannot lower the answer. Only the
    local maxima that can hold the global one (within Σ n²|c_n| Δφ²/8 of the best sample, Taylor's
    bound) are refined, gathered over the whole batch at once.

    >>> round(float(peak(np.array([0.0, 1.0, 0.5]), np.zeros(3))), 12)  # cos φ + cos 2φ / 2
    1.5
    >>> round(float(peak(np.array([0.0, 0.0]), np.array([0.0, 2.0]))), 12)
    2.0
    """
    cos, sin = np.asarray(cos, dtype=float), np.asarray(sin, dtype=float)
    cos, sin = np.broadcast_arrays(cos, sin)
    batch, K = cos.shape[:-1], cos.shape[-1] - 1
    N = max(64, 16 * K)
    spectrum = np.zeros(batch + (N // 2 + 1,), dtype=complex)
    spectrum[..., : K + 1] = (N / 2.0) * (cos - 1j * sin)
    spectrum[..., 0] = N * cos[..., 0]
    sampled = np.abs(np.fft.irfft(spectrum, N, axis=-1))
    best = sampled.max(-1)
    n = np.arange(K + 1)
    step = 2.0 * np.pi / N
    # The global maximum lies within step/2 of a sample, which is then at most
    # max|q''| step²/8 <= Σ n²|c_n| step²/8 below it: only local maxima within that of the best
    # sample can hold it, and only they are refined (the answer is the same, the work smaller).
    reach = (n * n * np.hypot(cos, sin)).sum(-1) * step * step / 8.0
    is_peak = (sampled >= np.roll(sampled, 1, -1)) & (sampled >= np.roll(sampled, -1, -1))
    is_peak &= sampled >= (best - reach)[..., None]
    *where, j = np.nonzero(is_peak)
    flat_cos, flat_sin = cos[tuple(where)], sin[tuple(where)]
    phi = j * step
    for _ in range(_NEWTON_STEPS):
        _, dq, ddq = _values(flat_cos, flat_sin, n, phi)
        safe = np.where(ddq == 0.0, 1.0, ddq)
        change = np.clip(np.where(ddq == 0.0, 0.0, dq / safe), -step, step)
        phi = phi - change
        if not np.any(np.abs(change) > _CONVERGED_STEP):
            break  # quadratic convergence: the next step would be below 1e-16 rad
    refined = np.abs(_values(flat_cos, flat_sin, n, phi)[0])
    flat_best = best.reshape(-1)
    owner = np.ravel_multi_index(tuple(where), batch) if batch else np.zeros(j.shape, dtype=int)
    np.maximum.at(flat_best, owner, refined)
    return flat_best.reshape(batch) if batch else flat_best[0]


__all__ = ["analyse", "basis", "derivative", "magnitude", "peak", "phases", "rms", "sample"]
