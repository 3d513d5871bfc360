"""Damped steady state of a rigid body under harmonic loads, vectorised over frequencies.

Source: the linear equations M q'' + C q' + K q = Re(Q e^{iΩt}) have the steady state
q = Re(Z e^{iΩt}) with

    (K - Ω² M + i Ω C) Z = Q                                                              (1)

solved for every frequency Ω at once (one batched LU solve).
"""

from __future__ import annotations

import numpy as np


def dynamic_stiffness(K, C, M, Omega) -> np.ndarray:
    """K - Ω² M + i Ω C of Eq. (1), shape Ω.shape + (n, n); Ω [rad/s] any shape."""
    w = np.asarray(Omega, dtype=float)[..., None, None]
    real = K - w * w * M
    out = np.empty(np.broadcast_shapes(real.shape, np.shape(C)), dtype=complex)
    out.real, out.imag = real, w * C
    return out


def harmonic_response(K, C, M, Q, Omega) -> np.ndarray:
    """Complex amplitudes Z of Eq. (1) [m, rad] for loads Q (..., n) [N, N m] at the frequencies
    Ω [rad/s] (Q and Ω broadcast); shape broadcast(Ω.shape, Q.shape[:-1]) + (n,).

    >>> harmonic_response(np.eye(1) * 4.0, np.zeros((1, 1)), np.eye(1), np.array([3.0]), np.array([1.0]))
    array([[1.+0.j]])
    """
    D = dynamic_stiffness(K, C, M, Omega)
    Q = np.asarray(Q, dtype=complex)
    shape = np.broadcast_shapes(D.shape[:-2], Q.shape[:-1])
    D = np.broadcast_to(D, shape + D.shape[-2:])
    return np.linalg.solve(D, np.broadcast_to(Q, shape + Q.shape[-1:])[..., None])[..., 0]


__all__ = ["dynamic_stiffness", "harmonic_response"]
