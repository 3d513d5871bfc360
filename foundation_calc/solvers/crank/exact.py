"""Exact periodic steady state of the crank-mechanism foundation by harmonic balance.

Solves the full nonlinear equations of :mod:`~foundation_calc.solvers.crank.dynamics` (no
small-parameter expansion) for the T-periodic motion, T = 2π/ω:

1. x, y, θ are truncated Fourier series with harmonics 0 ... K; the residual of the equations
   is sampled at N = 4K + 4 phases and projected back on the same harmonics (Galerkin).
2. Newton's method on the 3(2K + 1) coefficients, starting from the averaged-operator closed
   form; the Jacobian is assembled from the exact pointwise derivatives of the residual with
   respect to q, q', q'' (complex step, nine batched evaluations per iteration).
3. K = 8, 16, 32, ... is doubled until the solution changes by less than
   :data:`HARMONIC_TOLERANCE` relative to each coordinate's largest coefficient.

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
        for order, E in enumerate(self.E):
            for j in range(3):
                states[order][j] += 1j * _STEP
                partial = residual(self.design, self.motion, *states).imag / _STEP  # (3, N)
                states[order][j] -= 1j * _STEP
                J[:, :, j, :] += np.einsum("kn,in,nl->ikl", self.A, partial, E)
        return J.reshape(3 * size, 3 * size)


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
        when the averaged operator is resonant, when Newton's method does not converge, or when
        :data:`MAX_HARMONICS` harmonics are not enough; the message says how far it got.
    """
    K = FIRST_HARMONICS
    z, iterations, res, force_size = _first_solve(design, K)
    change = float("inf")  # no refinement compared yet
    while True:
        K2 = 2 * K
        if K2 > MAX_HARMONICS:
            raise ConvergenceError(
                f"harmonic balance: {K} harmonics leave a change of {change:.2g} relative"
                f" (wanted < {HARMONIC_TOLERANCE:g}); the motion is not smooth enough"
            )
        galerkin = _Galerkin(design, K2)
        coarse = _unpack(z, design.omega)
        z2, iterations, res = _newton(galerkin, _pack(coarse, K2), force_size)
        change = float((np.abs(z2 - _pack(coarse, K2)).max(axis=1) / _scale(z2)).max())
        z, K = z2, K2
        if change < HARMONIC_TOLERANCE:
            return ExactSolution(
                motion=_unpack(z, design.omega),
                harmonics=K,
                newton_iterations=iterations,
                harmonic_change=change,
                residual=res,
            )


__all__ = ["DOFS", "ExactSolution", "HARMONIC_TOLERANCE", "exact_periodic_solution", "fixed_harmonics_solution"]
