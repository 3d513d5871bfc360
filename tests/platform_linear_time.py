"""Independent reference for the harmonic balance: the linearised 6-DOF equations integrated in time.

M(t), G(t), K(t) and F(t) are evaluated at each instant from the rotor positions (the formulas of
the model in ``solvers/platform/dynamics.py``, typed here in the time domain: no Fourier series,
no harmonic sets), and the motion d = q - q_s about the static equilibrium is integrated from
rest with ``solve_ivp``::

    M(t) d'' + (G(t) + β K_springs) d' + K(t) d = F(t) - K_rot(t) q_s,

K_rot being the rotor part of K(t) (zero mean), q_s the static equilibrium K_springs q_s = weight.
"""

from __future__ import annotations

import numpy as np
from scipy.integrate import solve_ivp

from tests.platform_rigid_body import hat

E3 = np.array([0.0, 0.0, 1.0])


def springs(platform) -> np.ndarray:
    K = np.zeros((6, 6))
    for r_i, c_i in zip(platform.corners, platform.stiffness):
        T = np.hstack([np.eye(3), -hat(r_i)])
        K += T.T @ np.diag(c_i) @ T
    return K


class _Rotors:
    """The rotors' constants as arrays, for a fast evaluation of their paths."""

    def __init__(self, rotors) -> None:
        d1, d2 = np.array([r.part.delta1 for r in rotors]), np.array([r.part.delta2 for r in rotors])
        self.t1 = np.stack([np.sin(d1), -np.cos(d1), 0 * d1], axis=1)
        self.t2 = np.stack([np.cos(d1) * np.cos(d2), np.sin(d1) * np.cos(d2), -np.sin(d2)], axis=1)
        self.l = np.array([r.part.l for r in rotors])[:, None]
        self.omega = np.array([r.omega for r in rotors])
        self.phi0 = np.array([r.part.phi0 for r in rotors])
        self.m = np.array([r.part.m for r in rotors])
        self.rho = np.array([r.part.rho for r in rotors], dtype=float)

    def paths(self, t, clock=None):
        """S, L, L', L'' of every rotor at time t, shapes (R, 3). Rotor j turns by ω_j τ(t) + φ_j0:
        τ = t at constant speed; ``clock(t)`` gives (τ, τ', τ'') of a speed ramp, whose angular
        acceleration ω_j τ'' adds the tangential term ω_j τ'' dL/dφ to L''."""
        tau, rate, accel = (t, 1.0, 0.0) if clock is None else clock(t)
        phi = self.omega * tau + self.phi0
        c, s = np.cos(phi)[:, None], np.sin(phi)[:, None]
        L = self.l * (self.t1 * c + self.t2 * s)
        dL = self.l * (self.t2 * c - self.t1 * s)  # dL/dφ
        w, a = (self.omega * rate)[:, None], (self.omega * accel)[:, None]
        return self.rho + L, L, w * dL, -(w**2) * L + a * dL


def _hat(v) -> np.ndarray:
    return np.array([[0.0, -v[2], v[1]], [v[2], 0.0, -v[0]], [-v[1], v[0], 0.0]])


def _cross(a, b) -> np.ndarray:
    """Row-wise a × b for arrays of shape (R, 3)."""
    a0, a1, a2, b0, b1, b2 = a[:, 0], a[:, 1], a[:, 2], b[:, 0], b[:, 1], b[:, 2]
    return np.stack([a1 * b2 - a2 * b1, a2 * b0 - a0 * b2, a0 * b1 - a1 * b0], axis=1)


def static_equilibrium(platform, rotors) -> np.ndarray:
    M_sigma = platform.M + sum(r.part.m for r in rotors)
    first = platform.M * np.asarray(platform.r_c, dtype=float) + sum(r.part.m * np.asarray(r.part.rho, dtype=float) for r in rotors)
    load = np.concatenate([[0.0, 0.0, -M_sigma * platform.g], -platform.g * np.cross(first, E3)])
    return np.linalg.solve(springs(platform), load)


def equations(platform, rotors: _Rotors, t, clock=None):
    """M, G, K_rot, F at time t (``clock``: see :meth:`_Rotors.paths`); K = K_springs + tilt + K_rot."""
    g, m, I = platform.g, rotors.m, np.eye(3)
    S, L, Ld, Ldd = rotors.paths(t, clock)
    mS, mL = S.T * m, m @ L  # Σ m S (columns), Σ m L
    S_tot = platform.M * np.asarray(platform.r_c, dtype=float) + mS.sum(axis=1)
    M = np.zeros((6, 6))
    M[:3, :3] = (platform.M + m.sum()) * I
    M[3:, :3] = _hat(S_tot)
    M[:3, 3:] = -M[3:, :3]
    M[3:, 3:] = platform.J_O1 + np.sum(mS * S.T) * I - mS @ S
    G, K, F = np.zeros((6, 6)), np.zeros((6, 6)), np.zeros(6)
    G[:3, 3:] = -2 * _hat(m @ Ld)
    G[3:, 3:] = 2 * (np.sum(mS * Ld.T) * I - (Ld.T * m) @ S)
    K[:3, 3:] = -_hat(m @ Ldd)
    X = mS @ Ldd
    K[3:, 3:] = X - X.T + g * (np.outer(mL, E3) - mL[2] * I)
    F[:3] = -m @ Ldd
    F[3:] = -_cross(S, Ldd).T @ m - g * np.array([mL[1], -mL[0], 0.0])  # (Σ m L) × e3
    return M, G, K, F


def tilt(platform, rotors) -> np.ndarray:
    zeta_sum = platform.M * platform.r_c[2] + sum(r.part.m * r.part.rho[2] for r in rotors)
    return -platform.g * zeta_sum * np.diag([0, 0, 0, 1.0, 1.0, 0])


def integrate_from_rest(platform, rotors, t_eval):
    """d(t) (shape (6, len(t_eval))) from d = d' = 0 at t = 0."""
    Ks = springs(platform)
    K0 = Ks + tilt(platform, rotors)
    C = platform.beta * Ks
    q_s = static_equilibrium(platform, rotors)
    arrays = _Rotors(rotors)

    def rhs(t, y):
        M, G, K_rot, F = equations(platform, arrays, t)
        d, v = y[:6], y[6:]
        acc = np.linalg.solve(M, F - K_rot @ q_s - (G + C) @ v - (K0 + K_rot) @ d)
        return np.concatenate([v, acc])

    sol = solve_ivp(rhs, (0.0, t_eval[-1]), np.zeros(12), method="DOP853", t_eval=t_eval, rtol=1e-10, atol=1e-15)
    assert sol.success, sol.message
    return sol.y[:6]


def harmonic_history(state, t) -> np.ndarray:
    """d(t) = Σ Q(Ω) e^{iΩt} of a harmonic-balance steady state, shape (6, len(t))."""
    return np.real(state.amplitudes.T @ np.exp(1j * np.outer(state.omega, t)))
