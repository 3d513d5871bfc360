"""Periodic steady state by time integration: shooting with scipy's ``solve_ivp``.

What an engineer without the closed forms would write, kept as a yardstick for ``fcalc bench``:
the exact equations of :mod:`~foundation_calc.solvers.crank.dynamics` are written as a first-order
system s = (q, q'), q = (x, y, θ), and integrated over one period T = 2π/ω with an explicit
Runge-Kutta method (DOP853). The periodic orbit is the root of

    F(s0) = s(T; s0) - s0,

found by Newton's method from the state of rest; the Jacobian dF/ds0 is built from six
trajectories started at s0 + ε e_j and integrated together with the base trajectory (one ODE
system, one step-size sequence, so the differences are free of step-control noise). The orbit is
then sampled at :data:`SAMPLES` equally spaced phases and analysed into a trigonometric series.

The residual of the equations is affine in q'' (the mass matrix depends on q and t only), so
M(q, t) and the rest are read off four residual evaluations (q'' = 0, e_x, e_y, e_θ) done as one
batched call. scipy is imported inside :func:`shooting_solution` only.
"""

from __future__ import annotations

from dataclasses import dataclass

import numpy as np

from foundation_calc.errors import ConvergenceError
from foundation_calc.solvers.crank.dynamics import mechanism_motion, residual
from foundation_calc.solvers.crank.frequencies import require_stable_design
from foundation_calc.solvers.crank.mechanism import CrankDesign
from foundation_calc.solvers.crank.response import PeriodicMotion
from foundation_calc.solvers.numerics.trig_series import analyse, phases

#: Relative tolerance of the Runge-Kutta integration (DOP853).
RTOL = 1e-10
#: Absolute tolerance of the positions [m, m, rad]; velocities use ω times this [1/s].
ATOL = 1e-15
#: Newton stops when its step is below this, relative to each component's largest value.
STEP_TOLERANCE = 1e-9
MAX_NEWTON = 10
#: Phases at which the orbit is sampled; harmonics up to SAMPLES/4 are kept.
SAMPLES = 256
#: Finite-difference step of the monodromy columns [m, m, rad; velocities times ω].
PERTURBATION = 1e-7


@dataclass(frozen=True)
class ShootingSolution:
    """The periodic orbit found by shooting.

    Attributes
    ----------
    motion : x, y, θ series with SAMPLES/4 harmonics
    newton_iterations : Newton steps taken
    rhs_evaluations : evaluations of the batched right-hand side (7 trajectories each)
    """

    motion: PeriodicMotion
    newton_iterations: int
    rhs_evaluations: int


def _right_side(design: CrankDesign, trajectories: int):
    """f(t, s) for ``trajectories`` states stacked as a vector of length 6·trajectories."""
    B = trajectories
    unit = np.zeros((3, 4 * B))
    for j in range(3):
        unit[j, (j + 1) * B : (j + 2) * B] = 1.0

    def f(t, s):
        state = s.reshape(6, B)
        q, dq = np.tile(state[:3], 4), np.tile(state[3:], 4)
        motion = mechanism_motion(np.full(4 * B, design.omega * t), design.omega, design.r, design.l, design.rod.l1)
        r = residual(design, motion, q, dq, unit)
        r0 = r[:, :B]
        mass = np.stack([r[:, (j + 1) * B : (j + 2) * B] - r0 for j in range(3)], axis=1)  # (3, 3, B)
        ddq = np.linalg.solve(np.moveaxis(mass, -1, 0), -r0.T[..., None])[..., 0].T
        return np.concatenate([state[3:], ddq]).ravel()

    return f


def shooting_solution(design: CrankDesign, *, rtol: float = RTOL) -> ShootingSolution:
    """T-periodic solution of the exact equations by shooting (module docstring).

    Raises
    ------
    PhysicsError
        when the foundation is unstable in rocking.
    ConvergenceError
        when the integration fails or Newton's method does not converge (at or near a
        resonance the monodromy matrix minus the identity is singular).
    """
    from scipy.integrate import solve_ivp

    require_stable_design(design)
    w = design.omega
    period = 2.0 * np.pi / w
    scale = np.array([1.0, 1.0, 1.0, w, w, w])
    eps = PERTURBATION * scale
    atol = np.repeat(ATOL * scale, 7)
    t_eval = phases(SAMPLES) / w
    rhs = _right_side(design, 7)
    s0 = np.zeros(6)
    evaluations = 0
    for iteration in range(1, MAX_NEWTON + 1):
        start = s0[:, None] + np.hstack([np.zeros((6, 1)), np.diag(eps)])
        sol = solve_ivp(rhs, (0.0, period), start.ravel(), method="DOP853", rtol=rtol, atol=atol,
                        t_eval=np.append(t_eval, period))
        evaluations += sol.nfev
        if not sol.success:
            raise ConvergenceError(f"shooting: the time integration failed ({sol.message})")
        end = sol.y[:, -1].reshape(6, 7)
        F = end[:, 0] - s0
        jacobian = (end[:, 1:] - end[:, :1]) / eps - np.eye(6)
        try:
            step = np.linalg.solve(jacobian, -F)
        except np.linalg.LinAlgError:
            step = np.full(6, np.inf)
        if not np.all(np.isfinite(step)):
            break
        samples = sol.y[:, :-1].reshape(6, 7, -1)[:3, 0]  # base trajectory's q at the phases
        size = np.maximum(np.abs(sol.y[:, :-1].reshape(6, 7, -1)[:, 0]).max(axis=1), 1e-300)
        s0 = s0 + step
        if np.all(np.abs(step) <= STEP_TOLERANCE * size):
            cos, sin = analyse(samples, SAMPLES // 4)
            return ShootingSolution(PeriodicMotion(omega=w, cos=cos, sin=sin), iteration, evaluations)
    raise ConvergenceError(
        f"shooting: Newton's method did not converge in {MAX_NEWTON} iterations; the speed is"
        " probably at or very near a resonance (no periodic solution without damping)"
    )


__all__ = ["ShootingSolution", "shooting_solution"]
