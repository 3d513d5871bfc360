"""Periodic steady state of a rigid body whose machines have angle-dependent inertia.

Source: the linear equations with T-periodic coefficients (T = 2π/ω, φ = ωt)

    (M + ΔM(φ)) q'' + (C + D(φ)) q' + (K + ΔS(φ)) q = Σ_n Re(Q_n e^{inφ})                 (1)

(M, C, K the body's constant matrices with its machines' mean mass and weight; ΔM, D, ΔS a
machine's periodic inertia, Coriolis and stiffness terms, e.g.
:mod:`foundation_calc.solvers.machines.crank_mechanism`) have, away from their resonances, one
T-periodic solution q = Σ_{j=-H}^{H} X_j e^{ijφ}. Harmonic balance: with the Fourier coefficients
A_k = (1/N) Σ A(φ_i) e^{-ikφ_i} of ΔM, D, ΔS on N > 4H phases, harmonic n of (1) reads

    Σ_j [-(jω)² ΔM_{n-j} + i jω D_{n-j} + ΔS_{n-j}] X_j + (K_j - (jω)² M + i jω C_j) X_n = F_n    (2)

(F_n = Q_n/2, F_{-n} = conj F_n; K_j, C_j the supports at |j|ω when they depend on frequency),
one linear solve of 6(2H + 1) unknowns, exact for the truncated series. H = 8, 16, ... doubles
until the solution changes by less than :data:`HARMONIC_TOLERANCE` relative to each coordinate's
largest harmonic (or :data:`FLOOR` of the largest of all; the coefficients of a crank mechanism fall geometrically with n).

The first approximation drops ΔM, D, ΔS (the averaged operator: mean mass and weight, and with
the block's C the mean of D, :mod:`foundation_calc.solvers.block.model`, so that D here is then
D(φ) less its mean); each order then solves alone, (K - (nω)² M + i nω C) Z_n = Q_n
(:func:`~foundation_calc.solvers.rigid_body.harmonic.harmonic_response`).
"""

from __future__ import annotations

from dataclasses import dataclass

import numpy as np

from foundation_calc.errors import ConvergenceError

#: Relative change of the solution, from H to 2H harmonics, below which the series is accepted.
HARMONIC_TOLERANCE = 1e-9
#: A coordinate smaller than this fraction of the largest (a direction the machine barely drives)
#: is measured against that fraction of the largest: its own digits are round-off.
FLOOR = 1e-8
FIRST_HARMONICS = 8
MAX_HARMONICS = 128


@dataclass(frozen=True)
class PeriodicSolution:
    """The T-periodic solution of Eq. (1): q(t) = mean + Σ_n Re(Z_n e^{inωt}).

    Attributes
    ----------
    omega : ω [rad/s]
    orders : (H,) orders n = 1 ... H
    Z : (H, 6) complex amplitudes [m, rad] (the block's convention, as the first approximation's)
    mean : (6,) constant part [m, rad] (a static offset the periodic inertia adds; not vibration)
    harmonic_change : largest relative change from H/2 to H harmonics [-]
    """

    omega: float
    orders: np.ndarray
    Z: np.ndarray
    mean: np.ndarray
    harmonic_change: float


class HarmonicCapReached(ConvergenceError):
    """:data:`MAX_HARMONICS` harmonics change the solution by more than :data:`HARMONIC_TOLERANCE`
    from half as many (a rod barely longer than its crank: slowly falling harmonics); ``solution``
    is the one at the cap, its ``harmonic_change`` the estimate of its truncation error [-]."""

    def __init__(self, message: str, solution: PeriodicSolution):
        super().__init__(message)
        self.solution = solution


def _sampling(H: int) -> int:
    """Phases on which the coefficients of Eq. (2) are exact: a power of two above 4H + 2."""
    return max(64, 1 << int(np.ceil(np.log2(4 * H + 4))))


def harmonic_balance(omega, M, K, C, periodic, Q, H: int, soil=None) -> np.ndarray:
    """X_j, j = -H ... H, of Eq. (2), shape (2H + 1, 6) complex [m, rad].

    Parameters
    ----------
    omega : ω [rad/s]
    M, K, C : (6, 6) constant mass, stiffness and damping about O
    periodic : function N -> (ΔM, D, ΔS), each (N, 6, 6), sampled at φ_i = 2πi/N
    Q : (H_Q, 6) complex load amplitudes of orders 1 ... H_Q [N, N m]
    H : harmonics kept
    soil : None, or a function Ω (2H + 1,) [rad/s] -> (K, C) stacks (2H + 1, 6, 6) replacing K, C
        harmonic by harmonic
    """
    n, d = np.arange(-H, H + 1), np.shape(M)[-1]
    N = _sampling(H)
    dM, D, dS = (np.fft.fft(A, axis=0) / N for A in periodic(N))
    offset = (n[:, None] - n[None, :]) % N
    w = (n * omega)[None, :, None, None]
    A = -w * w * dM[offset] + 1j * w * D[offset] + dS[offset]  # (row n, column j, 6, 6)
    if soil is None:
        Kj, Cj = np.broadcast_to(K, (2 * H + 1, d, d)), np.broadcast_to(C, (2 * H + 1, d, d))
    else:
        Kj, Cj = soil(np.abs(n * omega))
    wj = (n * omega)[:, None, None]
    A[n + H, n + H] += Kj - wj * wj * M + 1j * wj * Cj
    F = np.zeros((2 * H + 1, d), dtype=complex)
    k = min(H, len(Q))
    F[H + 1:H + 1 + k] = Q[:k] / 2.0
    F[H - k:H][::-1] = np.conj(Q[:k]) / 2.0
    size = d * (2 * H + 1)
    return np.linalg.solve(A.transpose(0, 2, 1, 3).reshape(size, size), F.ravel()).reshape(2 * H + 1, d)


def _solution(omega, X, change) -> PeriodicSolution:
    H = (len(X) - 1) // 2
    return PeriodicSolution(float(omega), np.arange(1, H + 1), 2.0 * X[H + 1:], X[H].real.copy(), change)


def periodic_solution(omega, M, K, C, periodic, Q, soil=None) -> PeriodicSolution:
    """The T-periodic solution of Eq. (1), harmonics doubled until converged (module docstring).

    Raises
    ------
    HarmonicCapReached
        when :data:`MAX_HARMONICS` harmonics change the solution by more than
        :data:`HARMONIC_TOLERANCE` from half as many; it carries the solution at the cap.
    ConvergenceError
        when the system is singular (a speed on a resonance of the periodic system without damping).
    """
    H = min(max(FIRST_HARMONICS, 1 << int(np.ceil(np.log2(max(len(Q), 1))))), MAX_HARMONICS // 2)
    try:
        X = harmonic_balance(omega, M, K, C, periodic, Q, H, soil)
        while True:
            X2 = harmonic_balance(omega, M, K, C, periodic, Q, 2 * H, soil)
            coarse = np.zeros_like(X2)
            coarse[H:3 * H + 1] = X
            scale = np.abs(X2).max(axis=0)
            scale = np.maximum(scale, FLOOR * scale.max() + 1e-300)
            change = float((np.abs(X2 - coarse).max(axis=0) / scale).max())
            X, H = X2, 2 * H
            if change < HARMONIC_TOLERANCE:
                return _solution(omega, X, change)
            if H >= MAX_HARMONICS:
                raise HarmonicCapReached(
                    f"harmonic balance: {H} harmonics change the periodic solution by {change:.2g} relative from"
                    f" {H // 2} (wanted < {HARMONIC_TOLERANCE:g})", _solution(omega, X, change))
    except np.linalg.LinAlgError:
        raise ConvergenceError(
            f"harmonic balance at ω = {omega:.6g} rad/s: the periodic system is singular (the speed is on one of its"
            " resonances, without damping)") from None


__all__ = ["HARMONIC_TOLERANCE", "HarmonicCapReached", "MAX_HARMONICS", "PeriodicSolution", "harmonic_balance", "periodic_solution"]
