"""Time response of a damped linear structure to rotating loads whose speed changes.

Equations (SI units)::

    M q'' + C q' + K q = Σ_h Re[ ((Ω² - i Ω'/r_h) A_h + B_h) e^{i r_h φ} ],   φ' = Ω(t)

Harmonic h turns at r_h times the shaft speed Ω; A_h [N s², per unit Ω²] is the inertial part
(an unbalance m l at speed ratio r: A = m l r² × direction; a point mass's tangential force
m l Ω'_h gives the -iΩ'/r_h term), B_h [N] the part that does not depend on the speed (the
rotating weight of the unbalances). r_h = 0 is a steady load (A_0 Ω², no Ω' term).

Integrator: exponential (exact for the linear structure, first-order hold on the load). The
state s = (q, q') obeys s' = A s + b(t); with the complex Schur form A = Z T Zᴴ each component of
z = Zᴴ s is a scalar equation z_k' = T_kk z_k + Σ_{j>k} T_kj z_j + g_k, solved from the last to
the first as a first-order recursion (:func:`first_order_recursion`, a prefix scan in numpy: no
scipy.signal, whose import alone takes about a second), exact for inputs linear over a step::

    z_{k+1} = e^{λh} z_k + h (φ1 - φ2)(λh) u_k + h φ2(λh) u_{k+1},
    φ1(x) = (e^x - 1)/x,   φ2(x) = (e^x - 1 - x)/x²

The only error is the hold's: relative (ωh)²/12 at frequency ω; with :data:`STEPS_PER_PERIOD`
steps per shortest period (natural or forcing) it is 5e-5, and halving the step moves a peak by
less than 1e-4 (tested). The Schur form needs no distinct eigenvalues (equal natural frequencies
of a symmetric platform) and no proportional damping. The run is processed in chunks of
:data:`CHUNK` steps; the record keeps, per step, the largest point displacement and the observed
magnitudes (modal coordinates), so a run is limited to :data:`MAX_STEPS` steps.
"""

from __future__ import annotations

from dataclasses import dataclass

import numpy as np
from scipy.linalg import schur

#: Steps per shortest period of the run (natural period or forcing period) [-].
STEPS_PER_PERIOD = 256

#: Steps processed at once [-]: each chunk holds about a dozen complex arrays of 12 states by CHUNK
#: steps (with 1 << 16 they peaked at 107 MB and took a one-scene `fcalc check` to 242 MB).
CHUNK = 1 << 12


@dataclass(frozen=True)
class RotatingLoad:
    """Harmonic loads of a rotating machine (module docstring).

    Attributes
    ----------
    ratio : r_h, speed of each harmonic over the shaft speed [-], shape (H,), ≥ 0
    inertial : A_h [N s² per unit Ω², N m s² for moments], shape (H, n), complex
    constant : B_h [N, N m], shape (H, n), complex
    """

    ratio: np.ndarray
    inertial: np.ndarray
    constant: np.ndarray

    def at(self, omega, domega, phi) -> np.ndarray:
        """Load at speeds Ω [rad/s], accelerations Ω' [rad/s²], angles φ [rad], shape (n, N)."""
        r = self.ratio[:, None]
        turn = np.exp(1j * r * phi)  # e^{i r_h φ}, shape (H, N)
        safe = np.where(r > 0.0, r, 1.0)
        tangential = np.where(r > 0.0, -1j * domega / safe, 0.0)  # -i Ω'/r_h; none at r_h = 0
        return (self.inertial.T @ (turn * (omega * omega + tangential)) + self.constant.T @ turn).real

    def steady(self, M, C, K, omega):
        """Complex amplitudes Z_h of the steady state at constant speed Ω [rad/s], shape (H, n):
        q(t) = Σ_h Re(Z_h e^{i r_h Ω t})."""
        w = self.ratio * omega
        D = K[None] - (w * w)[:, None, None] * M[None] + 1j * w[:, None, None] * C[None]
        return np.linalg.solve(D, (self.inertial * omega * omega + self.constant)[..., None])[..., 0]


@dataclass(frozen=True)
class Ramp:
    """Shaft speed changing linearly from ``start`` to ``end`` [rad/s] in ``duration`` [s] and
    held at ``end`` afterwards; φ(0) = 0."""

    start: float
    end: float
    duration: float

    def speed(self, t):
        """(Ω [rad/s], Ω' [rad/s²], φ [rad]) at times t [s]."""
        t = np.asarray(t, dtype=float)
        T, w0, w1 = self.duration, self.start, self.end
        rate = (w1 - w0) / T
        tr = np.minimum(t, T)
        omega = w0 + rate * tr
        phi = w0 * tr + 0.5 * rate * tr * tr + w1 * (t - tr)
        return omega, np.where(t < T, rate, 0.0), phi


@dataclass(frozen=True)
class SweepResponse:
    """What a run keeps of the motion.

    Attributes
    ----------
    t : times [s], shape (N,)
    magnitude : largest displacement magnitude over the points at each time [m], shape (N,)
    point_peaks : largest displacement magnitude of each point over the run [m], shape (P,)
    direction_peaks : largest |displacement| of each point along each of its directions (the
        rows of its map) over the run [m], shape (P, d)
    observed : |W q| of the observer rows W at each time, shape (m, N)
    step : time step [s]
    """

    t: np.ndarray
    magnitude: np.ndarray
    point_peaks: np.ndarray
    direction_peaks: np.ndarray
    observed: np.ndarray
    step: float


def point_displacements(points, q) -> np.ndarray:
    """|T_p q| of every point at every time [m], shape (P, N), for maps ``points`` (P, d, n)
    and states ``q`` (n, N)."""
    return np.linalg.norm(np.einsum("pdn,nt->pdt", points, q), axis=1)


def time_step(M, K, load: RotatingLoad, omega_max, steps_per_period=STEPS_PER_PERIOD) -> float:
    """Step [s]: ``steps_per_period`` per shortest period, natural or forcing (at ``omega_max``
    [rad/s])."""
    w_n = np.sqrt(np.max(np.abs(np.linalg.eigvals(np.linalg.solve(M, K)))))
    w_f = float(np.max(load.ratio, initial=0.0)) * omega_max
    return 2.0 * np.pi / (steps_per_period * max(w_n, w_f))


def _filter_coefficients(lam, h):
    x = lam * h
    e1 = np.expm1(x)
    phi1 = e1 / x
    phi2 = (e1 - x) / (x * x)
    return np.exp(x), h * (phi1 - phi2), h * phi2


#: Largest number of steps of one run: its record (a few values per step) then stays under
#: about 300 MB [-].
MAX_STEPS = 4_000_000


def integrate(M, C, K, load: RotatingLoad, ramp: Ramp, t_end, step, q0, v0, points, observers) -> SweepResponse:
    """Integrate the module's equations from (q0 [m], v0 [m/s]) over [0, t_end] [s].

    Parameters
    ----------
    M, C, K : mass [kg], damping [N s/m], stiffness [N/m] matrices (n, n) (mixed units for
        rotations)
    load : the rotating loads
    ramp : the shaft's speed against time
    t_end : end of the run [s]
    step : time step h [s] (:func:`time_step`)
    q0, v0 : initial displacement and velocity (n,)
    points : maps from q to the displacement of each point, shape (P, d, n) [m per unit q]
    observers : rows W (m, n) whose |W q| is recorded at every step (modal coordinates)

    Raises
    ------
    ValueError
        when the run needs more than :data:`MAX_STEPS` steps.
    """
    n = M.shape[0]
    Minv = np.linalg.inv(M)
    A = np.block([[np.zeros((n, n)), np.eye(n)], [-Minv @ K, -Minv @ C]])
    T, Z = schur(A.astype(complex), output="complex")
    lam = np.diag(T).copy()
    E, b0, b1 = _filter_coefficients(lam, step)
    to_z = Z.conj().T[:, n:] @ Minv  # z-input per unit load
    back = Z[:n]  # q = Re(Z[:n] z)
    steps = int(np.ceil(t_end / step))
    if steps > MAX_STEPS:
        raise ValueError(
            f"the run of {t_end:.6g} s needs {steps} steps of {step:.3g} s, more than {MAX_STEPS};"
            f" the longest run this structure allows is {MAX_STEPS * step:.6g} s"
        )
    t = np.arange(steps + 1) * step
    z_prev = Z.conj().T @ np.concatenate([q0, v0]).astype(complex)
    u_prev = None
    magnitude = np.empty(steps + 1)
    point_peaks = np.zeros(points.shape[0])
    direction_peaks = np.zeros(points.shape[:2])
    observed = np.empty((observers.shape[0], steps + 1))
    for start in range(0, steps + 1, CHUNK):
        tc = t[start : start + CHUNK]
        omega, domega, phi = ramp.speed(tc)
        g = to_z @ load.at(omega, domega, phi)
        z = np.empty_like(g)
        u_all = np.empty_like(g)
        for k in range(2 * n - 1, -1, -1):
            u = g[k] + T[k, k + 1 :] @ z[k + 1 :]
            u_all[k] = u
            if u_prev is None:  # first chunk: z_0 is the initial state
                z[k, 0] = z_prev[k]
                z[k, 1:] = first_order_recursion(E[k], b0[k], b1[k], u[1:], E[k] * z_prev[k] + b0[k] * u[0])
            else:
                z[k] = first_order_recursion(E[k], b0[k], b1[k], u, E[k] * z_prev[k] + b0[k] * u_prev[k])
        z_prev, u_prev = z[:, -1], u_all[:, -1]
        q = (back @ z).real
        vectors = np.einsum("pdn,nt->pdt", points, q)
        disp = np.linalg.norm(vectors, axis=1)
        magnitude[start : start + tc.size] = disp.max(axis=0)
        observed[:, start : start + tc.size] = np.abs(observers @ q)
        point_peaks = np.maximum(point_peaks, disp.max(axis=1))
        direction_peaks = np.maximum(direction_peaks, np.abs(vectors).max(axis=2))
    return SweepResponse(t=t, magnitude=magnitude, point_peaks=point_peaks, direction_peaks=direction_peaks,
                         observed=observed, step=step)


def first_order_recursion(E: complex, b0: complex, b1: complex, u: np.ndarray, carry: complex) -> np.ndarray:
    """z_j = E z_{j-1} + b1 u_j + b0 u_{j-1} for j = 0 … n-1, with E z_{-1} + b0 u_{-1} = ``carry``.

    The exponential integrator's step (module docstring) for one Schur component over a chunk, the
    same recursion as ``scipy.signal.lfilter([b1, b0], [1, -E], u, zi=[carry])``. Solved as an
    inclusive prefix scan (Hillis-Steele): after the pass of stride d every z_j holds the sum of
    its last 2d terms, each weighted by E to the power of its distance; log2(n) vectorised passes.
    With |E| <= 1 (a damped or undamped mode) no weight exceeds 1, so the sum is as accurate as the
    sequential recursion (rounding grows as log2(n) ε, not n ε).
    """
    z = b1 * u
    z[1:] += b0 * u[:-1]
    z[0] += carry
    weight, stride = E, 1
    while stride < z.size:
        z[stride:] = z[stride:] + weight * z[:-stride]
        weight, stride = weight * weight, 2 * stride
    return z


def refined_peak(t, values, lo, hi):
    """(peak value, time) of ``values`` over lo ≤ t ≤ hi, refined by a parabola through the
    largest sample and its neighbours (the sampled maximum of an oscillation is low by up to
    (π/N)²/2 with N samples per period; the parabola leaves O(N⁻⁴))."""
    i0, i1 = np.searchsorted(t, [lo, hi])
    i1 = max(i1, i0 + 1)
    i = i0 + int(np.argmax(values[i0:i1]))
    if 0 < i < values.size - 1:
        y0, y1, y2 = values[i - 1 : i + 2]
        c = y0 - 2.0 * y1 + y2
        if c < 0.0:
            d = 0.5 * (y0 - y2) / c
            return float(y1 - 0.25 * (y0 - y2) * d), float(t[i] + d * (t[1] - t[0]))
    return float(values[i]), float(t[i])


__all__ = ["CHUNK", "first_order_recursion", "point_displacements", "MAX_STEPS", "STEPS_PER_PERIOD", "Ramp", "RotatingLoad", "SweepResponse", "integrate", "refined_peak", "time_step"]
