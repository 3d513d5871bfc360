"""Exact periodic steady state of the crank-mechanism foundation by harmonic balance.

Solves the full nonlinear equations of :mod:`~foundation_calc.solvers.crank.dynamics` (no
small-parameter expansion) for the T-periodic motion, T = 2π/ω:

1. x, y, θ are truncated Fourier series with harmonics 0 ... K; the residual of the equations
   is sampled at N = 4K + 4 phases and projected back on the same harmonics (Galerkin).
2. Newton's method on the 3(2K + 1) coefficients, starting from the averaged-operator closed
   form; the Jacobian is assembled from the exact pointwise derivatives of the residual with
   respect to q, q', q'' (complex step, nine batched evaluations per iteration); each block of
   the Galerkin Jacobian, Σ_n w_k b_k(φ_n) ∂R/∂q(φ_n) b_l(φ_n), comes from the DFT of the
   partial derivative by the product-to-sum identities (O(K²) per block instead of O(K² N)).
3. K = 8, 16, 32, ... is doubled until the solution changes by less than
   :data:`HARMONIC_TOLERANCE` relative to each coordinate's largest coefficient, up to
   :data:`MAX_HARMONICS`. A rod barely longer than the crank (λ → 1: the rod's angle turns
   fast near φ = 90°, the harmonics of sin ψ = λ sin φ and cos ψ decay as ((1 - sqrt(1 - λ²))/λ)^n)
   may need more; the solution at the cap is then given with its change from half the harmonics
   as the error estimate (:class:`HarmonicCapReached`).

This module is numpy-only; it is the reference against which the closed forms' errors are
reported.
"""

from __future__ import annotations

from dataclasses import dataclass

import numpy as np

from foundation_calc.errors import ConvergenceError
from foundation_calc.solvers.crank.averaged import averaged_response
from foundation_calc.solvers.crank.dynamics import mechanism_motion, residual
from foundation_calc.solvers.crank.mechanism import CrankDesign
from foundation_calc.solvers.crank.response import DOFS, PeriodicMotion
from foundation_calc.solvers.numerics.trig_series import basis, phases

#: Relative change of the solution, from K to 2K harmonics, below which the series is accepted.
HARMONIC_TOLERANCE = 1e-10
#: Relative size of the last Newton step below which Newton has converged.
NEWTON_TOLERANCE = 1e-12
FIRST_HARMONICS = 8
MAX_HARMONICS = 256
MAX_NEWTON = 25

_STEP = 1e-30


@dataclass(frozen=True)
class ExactSolution:
    """The periodic steady state and how it was reached.

    Attributes
    ----------
    motion : x, y, θ series with ``harmonics`` harmonics
    harmonics : K of the accepted series
    newton_iterations : Newton steps at the accepted K
    harmonic_change : largest relative change from K/2 to K harmonics [-]
    residual : largest harmonic of the residual at the solution, relative to the forcing [-]
    """

    motion: PeriodicMotion
    harmonics: int
    newton_iterations: int
    harmonic_change: float
    residual: float


class _Galerkin:
    """Synthesis and analysis matrices of K harmonics on N = 4K + 4 phases."""

    def __init__(self, design: CrankDesign, K: int):
        self.K, N = K, 4 * K + 4
        phi = phases(N)
        cb, sb = basis(K, phi)
        n = np.arange(1, K + 1) * design.omega
        self.E = [
            np.hstack([cb, sb[:, 1:]]),
            np.hstack([np.zeros((N, 1)), -sb[:, 1:] * n, cb[:, 1:] * n]),
            np.hstack([np.zeros((N, 1)), -cb[:, 1:] * n * n, -sb[:, 1:] * n * n]),
        ]
        weights = np.full(2 * K + 1, 2.0 / N)
        weights[0] = 1.0 / N
        self.A = weights[:, None] * self.E[0].T
        self.design = design
        self.motion = mechanism_motion(phi, design.omega, design.r, design.l, design.rod.l1)

    def states(self, z):
        """q, q', q'' at the phases, each (3, N), from coefficients z (3, 2K + 1)."""
        return [z @ E.T for E in self.E]

    def residual(self, z):
        """Harmonics of the residual, (3, 2K + 1)."""
        return residual(self.design, self.motion, *self.states(z)) @ self.A.T

    def jacobian(self, z):
        """d(residual harmonics)/d(coefficients), (3(2K + 1), 3(2K + 1))."""
        states = [s.astype(complex) for s in self.states(z)]
        size = 2 * self.K + 1
        J = np.zeros((3, size, 3, size))
        for order in range(3):
            for j in range(3):
                states[order][j] += 1j * _STEP
                partial = residual(self.design, self.motion, *states).imag / _STEP  # (3, N)
                states[order][j] -= 1j * _STEP
                J[:, :, j, :] += self._differentiated(product_matrix(partial, self.K), order)
        return J.reshape(3 * size, 3 * size)

    def _differentiated(self, G, order):
        """G @ D^order, D the time derivative on the coefficients [c0, c1..cK, s1..sK]:
        (c_n, s_n) -> (n ω s_n, -n ω c_n), applied as column operations."""
        if order == 0:
            return G
        K = self.K
        n = np.arange(1, K + 1) * self.design.omega
        out = np.zeros_like(G)
        cos, sin = G[..., 1 : K + 1], G[..., K + 1 :]
        if order == 1:
            out[..., 1 : K + 1], out[..., K + 1 :] = -n * sin, n * cos
        else:
            out[..., 1 : K + 1], out[..., K + 1 :] = -n * n * cos, -n * n * sin
        return out


def product_matrix(p, K: int) -> np.ndarray:
    """Galerkin matrix of the multiplication by p in the basis [1, cos nφ, sin nφ] (n = 1 ... K):
    G_kl = w_k Σ_j b_k(φ_j) p(φ_j) b_l(φ_j) over the N phases of
    :func:`~foundation_calc.solvers.numerics.trig_series.phases` (w_0 = 1/N, w_k = 2/N), from
    the DFT of p by cos a cos b = (cos(a-b) + cos(a+b))/2 and its kin; exact for 2K < N.

    ``p``: samples, shape (..., N); returns shape (..., 2K + 1, 2K + 1).
    """
    N = p.shape[-1]
    P = np.fft.rfft(p, axis=-1)[..., : 2 * K + 1] / N
    c, s = P.real, -P.imag  # (1/N) Σ p cos(mφ), (1/N) Σ p sin(mφ)

    def cosine(m):
        return c[..., np.abs(m)]

    def sine(m):
        return np.sign(m) * s[..., np.abs(m)]

    k, n = np.arange(K + 1)[:, None], np.arange(1, K + 1)[:, None]
    G = np.empty(p.shape[:-1] + (2 * K + 1, 2 * K + 1))
    G[..., : K + 1, : K + 1] = 0.5 * (cosine(k - k.T) + cosine(k + k.T))
    G[..., : K + 1, K + 1 :] = 0.5 * (sine(n.T + k) + sine(n.T - k))
    G[..., K + 1 :, : K + 1] = 0.5 * (sine(n + k.T) + sine(n - k.T))
    G[..., K + 1 :, K + 1 :] = 0.5 * (cosine(n - n.T) - cosine(n + n.T))
    G[..., 1:, :] *= 2.0
    return G


def _pack(motion: PeriodicMotion, K: int) -> np.ndarray:
    """Coefficients (3, 2K + 1) = [c0, c1..cK, s1..sK] of a motion, truncated or padded to K."""
    z = np.zeros((3, 2 * K + 1))
    k = min(K, motion.cos.shape[-1] - 1)
    z[:, : k + 1] = motion.cos[:, : k + 1]
    z[:, K + 1 : K + 1 + k] = motion.sin[:, 1 : k + 1]
    return z


def _unpack(z: np.ndarray, omega: float) -> PeriodicMotion:
    K = (z.shape[1] - 1) // 2
    sin = np.hstack([np.zeros((3, 1)), z[:, K + 1 :]])
    return PeriodicMotion(omega=omega, cos=z[:, : K + 1].copy(), sin=sin)


def _scale(z: np.ndarray) -> np.ndarray:
    """Size of each coordinate's series, with a floor so that a vanishing one stays comparable."""
    size = np.abs(z).max(axis=1)
    return np.maximum(size, 1e-12 * size.max() + 1e-300)


def _newton(galerkin: _Galerkin, z: np.ndarray, force_size: float) -> tuple[np.ndarray, int, float]:
    for iteration in range(1, MAX_NEWTON + 1):
        r = galerkin.residual(z)
        try:
            step = np.linalg.solve(galerkin.jacobian(z), -r.ravel()).reshape(z.shape)
        except np.linalg.LinAlgError:
            step = np.full_like(z, np.inf)
        if not np.all(np.isfinite(step)):
            break
        z = z + step
        if np.all(np.abs(step).max(axis=1) <= NEWTON_TOLERANCE * _scale(z)):
            return z, iteration, float(np.abs(galerkin.residual(z)).max() / force_size)
    raise ConvergenceError(
        f"harmonic balance with {galerkin.K} harmonics: Newton's method did not converge in"
        f" {MAX_NEWTON} iterations; the speed is probably at or very near a resonance of the exact"
        " equations (no periodic solution without damping)"
    )


class HarmonicCapReached(ConvergenceError):
    """:data:`MAX_HARMONICS` harmonics change the solution by more than :data:`HARMONIC_TOLERANCE`
    from half as many; ``solution`` is the one at the cap, its ``harmonic_change`` the estimate of
    its truncation error [-]."""

    def __init__(self, message: str, solution: ExactSolution):
        super().__init__(message)
        self.solution = solution


def _first_solve(design: CrankDesign, K: int) -> tuple[np.ndarray, int, float, float]:
    """Newton with K harmonics from the averaged closed form: (z, iterations, residual, force size)."""
    start = averaged_response(design)
    if start.resonant:
        n, mode = start.nearest
        raise ConvergenceError(
            f"no periodic solution: {n}ω is {start.margin:.3g} (relative) from the natural"
            f" frequency {start.natural[mode]:.8g} rad/s of the averaged operator"
        )
    galerkin = _Galerkin(design, K)
    force_size = float(np.abs(galerkin.residual(np.zeros((3, 2 * K + 1)))).max())
    return (*_newton(galerkin, _pack(start.motion, K), force_size), force_size)


def fixed_harmonics_solution(design: CrankDesign, harmonics: int) -> PeriodicMotion:
    """Harmonic balance truncated at ``harmonics`` harmonics, without the convergence test.

    The same Newton solve as the first step of :func:`exact_periodic_solution`, for any K >= 1;
    ``fcalc bench`` uses it to show the truncation error against K.

    Raises
    ------
    PhysicsError, ConvergenceError
        as :func:`exact_periodic_solution`.
    """
    z, _, _, _ = _first_solve(design, harmonics)
    return _unpack(z, design.omega)


def exact_periodic_solution(design: CrankDesign) -> ExactSolution:
    """T-periodic solution of the exact equations of motion (module docstring).

    Raises
    ------
    PhysicsError
        when the foundation is unstable in rocking.
    ConvergenceError
        when the averaged operator is resonant or when Newton's method does not converge; the
        message says how far it got.
    HarmonicCapReached
        when :data:`MAX_HARMONICS` harmonics are not enough; it carries the solution at the cap.
    """
    K = FIRST_HARMONICS
    z, iterations, res, force_size = _first_solve(design, K)
    while True:
        K2 = 2 * K
        galerkin = _Galerkin(design, K2)
        coarse = _unpack(z, design.omega)
        z2, iterations, res = _newton(galerkin, _pack(coarse, K2), force_size)
        change = float((np.abs(z2 - _pack(coarse, K2)).max(axis=1) / _scale(z2)).max())
        z, K = z2, K2
        solution = ExactSolution(
            motion=_unpack(z, design.omega), harmonics=K, newton_iterations=iterations, harmonic_change=change,
            residual=res,
        )
        if change < HARMONIC_TOLERANCE:
            return solution
        if 2 * K > MAX_HARMONICS:
            raise HarmonicCapReached(
                f"harmonic balance: {K} harmonics (the cap) change the solution by {change:.2g} relative from"
                f" {K // 2} (wanted < {HARMONIC_TOLERANCE:g}): the motion is not smooth enough (a rod barely"
                f" longer than the crank, λ = r/l = {design.r / design.l:.4g})",
                solution,
            )


__all__ = ["DOFS", "ExactSolution", "HARMONIC_TOLERANCE", "HarmonicCapReached", "MAX_HARMONICS", "exact_periodic_solution", "fixed_harmonics_solution"]
