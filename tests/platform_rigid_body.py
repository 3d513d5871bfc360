"""Independent reference for the platform: the full nonlinear rigid-body equations, integrated.

Nothing here uses the linearised matrices or the Fourier machinery of foundation_calc: the
platform is a rigid body (orientation matrix C, angular velocity Ω in the fixed frame), each
rotor a point mass on its prescribed path ρ + L(t) in the body, springs along the fixed axes
(the paper's potential (1.2)), gravity on every mass. Newton's law for the total momentum and
Σ (p - R) × m p'' = moment about O1 give R'' and Ω' from a 6×6 solve at each instant.
"""

from __future__ import annotations

import numpy as np
from scipy.integrate import solve_ivp
from scipy.linalg import expm

E3 = np.array([0.0, 0.0, 1.0])


def hat(v):
    return np.array([[0.0, -v[2], v[1]], [v[2], 0.0, -v[0]], [-v[1], v[0], 0.0]])


def rotor_path(rotor, t):
    """Body-frame position, velocity, acceleration of the rotor's mass at time t."""
    w, rotor = rotor.omega, rotor.part
    s1, c1 = np.sin(rotor.delta1), np.cos(rotor.delta1)
    s2, c2 = np.sin(rotor.delta2), np.cos(rotor.delta2)
    t1 = np.array([s1, -c1, 0.0])
    t2 = np.array([c1 * c2, s1 * c2, -s2])
    phi = w * t + rotor.phi0
    L = rotor.l * (t1 * np.cos(phi) + t2 * np.sin(phi))
    Ld = rotor.l * w * (-t1 * np.sin(phi) + t2 * np.cos(phi))
    return np.asarray(rotor.rho, dtype=float) + L, Ld, -w * w * L


def rhs(t, y, platform, rotors):
    R, V, C, W = y[0:3], y[3:6], y[6:15].reshape(3, 3), y[15:18]
    M, g = platform.M, platform.g
    rc = C @ np.asarray(platform.r_c, dtype=float)
    Jf = C @ platform.J_O1 @ C.T
    A = np.zeros((6, 6))
    b_f = np.zeros(3)
    b_m = np.zeros(3)
    total = M
    first = M * rc
    A[3:, 3:] = Jf
    b_f -= M * np.cross(W, np.cross(W, rc))
    b_m -= np.cross(W, Jf @ W)
    for rot in rotors:
        s, sd, sdd = rotor_path(rot, t)
        p, pd, pdd = C @ s, C @ sd, C @ sdd
        m = rot.part.m
        total += m
        first = first + m * p
        A[3:, 3:] += m * (p @ p * np.eye(3) - np.outer(p, p))
        extra = np.cross(W, np.cross(W, p)) + 2.0 * np.cross(W, pd) + pdd
        b_f -= m * extra
        b_m -= m * np.cross(p, extra)
    A[:3, :3] = total * np.eye(3)
    A[:3, 3:] = -hat(first)
    A[3:, :3] = hat(first)
    F = -total * g * E3
    Mo = np.cross(first, -g * E3)
    for r_i, c_i in zip(platform.corners, platform.stiffness):
        d = R + C @ r_i - r_i
        f = -c_i * d
        F = F + f
        Mo = Mo + np.cross(C @ r_i, f)
    acc = np.linalg.solve(A, np.concatenate([F + b_f, Mo + b_m]))
    return np.concatenate([V, acc[:3], (hat(W) @ C).ravel(), acc[3:]])


def integrate(platform, rotors, q0, qd0, t_end, samples):
    """Integrate from the linear state (q0, q0') and return times, R(t), rotation vectors Φ(t)."""
    C0 = expm(hat(q0[3:]))
    y0 = np.concatenate([q0[:3], qd0[:3], C0.ravel(), qd0[3:]])
    t_eval = np.linspace(0.0, t_end, samples)
    sol = solve_ivp(rhs, (0.0, t_end), y0, method="DOP853", t_eval=t_eval, rtol=1e-11, atol=1e-15,
                    args=(platform, rotors))
    assert sol.success, sol.message
    R = sol.y[0:3]
    phi = []
    for k in range(sol.y.shape[1]):
        C = sol.y[6:15, k].reshape(3, 3)
        S = 0.5 * (C - C.T)
        phi.append([S[2, 1], S[0, 2], S[1, 0]])  # small-angle rotation vector
    return sol.t, R, np.array(phi).T


def linear_history(state, t):
    """q(t) and q'(t) of a foundation_calc steady state, summed from its harmonics."""
    q = np.repeat(state.static[:, None], len(t), axis=1).astype(complex)
    qd = np.zeros_like(q)
    for w, Q in zip(state.omega, state.amplitudes):
        e = np.exp(1j * w * t)
        q += Q[:, None] * e
        qd += 1j * w * Q[:, None] * e
    return q.real, qd.real
