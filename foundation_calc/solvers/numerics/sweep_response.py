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
        q(t) = Σ_h Re(Z_h e^{i r_h Ω t}); C and K (n, n), or one pair per harmonic (H, n, n)."""
        w = self.ratio * omega
        D = K - (w * w)[:, None, None] * M[None] + 1j * w[:, None, None] * C
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


@dataclass(frozen=True)
class Schedule:
    """Which harmonics of the load are integrated together and on which matrices.

    The equations are linear in the load, so their solution is the sum of the solutions of any
    split of the load's harmonics, each group with its own damping and stiffness: ``groups`` holds
    the harmonics (indices into the load's) of each part, and ``systems`` the (C, K) pairs (n, n)
    they may use. ``index(g, t)`` gives, for group g, the system of the step that ends at each
    time t [s] (an int array shaped as t). A structure with one C and K is one group on one system
    (:meth:`single`); a frequency-dependent soil integrates each harmonic on the springs and
    dashpots at its own forcing frequency (:mod:`~foundation_calc.solvers.numerics.runup`).
    """

    groups: tuple
    systems: tuple
    index: object

    @classmethod
    def single(cls, C, K, harmonics: int) -> Schedule:
        """Every harmonic (``harmonics`` of them) together on one damping C and stiffness K."""
        return cls((np.arange(harmonics),), ((C, K),), lambda g, t: np.zeros(np.shape(t), dtype=int))


@dataclass(frozen=True)
class _Stepper:
    """The exponential step of M s'' + C s' + K s = f with step h, in the complex Schur form of its
    state matrix A = Z T Zᴴ (module docstring): z = Zᴴ (q, q'), z-input per unit load ``to_z``."""

    T: np.ndarray
    Z: np.ndarray
    E: np.ndarray
    b0: np.ndarray
    b1: np.ndarray
    to_z: np.ndarray
    upper: np.ndarray

    @classmethod
    def of(cls, Minv, C, K, step) -> _Stepper:
        n = Minv.shape[0]
        A = np.block([[np.zeros((n, n)), np.eye(n)], [-Minv @ K, -Minv @ C]])
        T, Z = schur(A.astype(complex), output="complex")
        E, b0, b1 = _filter_coefficients(np.diag(T).copy(), step)
        return cls(T, Z, E, b0, b1, Z.conj().T[:, n:] @ Minv, np.triu(T, 1))

    def enter(self, state, force):
        """(z, u) of the physical state (q, q') and load ``force`` (n,) at one time: where the
        step after it starts."""
        z = self.Z.conj().T @ state.astype(complex)
        return z, self.to_z @ force + self.upper @ z

    def advance(self, force, z_prev, u_prev):
        """z at the times of ``force`` (n, N), the step before each one starting from
        (``z_prev``, ``u_prev``); returns z (2n, N) and the inputs u (2n, N)."""
        g = self.to_z @ force
        z, u_all = np.empty_like(g), np.empty_like(g)
        for k in range(g.shape[0] - 1, -1, -1):
            u = g[k] + self.T[k, k + 1 :] @ z[k + 1 :]
            u_all[k] = u
            z[k] = first_order_recursion(self.E[k], self.b0[k], self.b1[k], u, self.E[k] * z_prev[k] + self.b0[k] * u_prev[k])
        return z, u_all


def integrate(M, C, K, load: RotatingLoad, ramp: Ramp, t_end, step, q0, v0, points, observers,
              schedule: Schedule | None = None) -> SweepResponse:
    """Integrate the module's equations from (q0 [m], v0 [m/s]) over [0, t_end] [s].

    Parameters
    ----------
    M, C, K : mass [kg], damping [N s/m], stiffness [N/m] matrices (n, n) (mixed units for
        rotations)
    load : the rotating loads
    ramp : the shaft's speed against time
    t_end : end of the run [s]
    step : time step h [s] (:func:`time_step`)
    q0, v0 : initial displacement and velocity (n,); with a ``schedule``, one per group (G, n)
    points : maps from q to the displacement of each point, shape (P, d, n) [m per unit q]
    observers : rows W (m, n) whose |W q| is recorded at every step (modal coordinates)
    schedule : the load's harmonics in groups, each on its own damping and stiffness
        (:class:`Schedule`); None: every harmonic on C and K

    Raises
    ------
    ValueError
        when the run needs more than :data:`MAX_STEPS` steps.
    """
    if schedule is None:
        schedule = Schedule.single(C, K, load.ratio.size)
        q0, v0 = np.asarray(q0, dtype=float)[None], np.asarray(v0, dtype=float)[None]
    n = M.shape[0]
    Minv = np.linalg.inv(M)
    steps = int(np.ceil(t_end / step))
    if steps > MAX_STEPS:
        raise ValueError(
            f"the run of {t_end:.6g} s needs {steps} steps of {step:.3g} s, more than {MAX_STEPS};"
            f" the longest run this structure allows is {MAX_STEPS * step:.6g} s"
        )
    built: dict[int, _Stepper] = {}

    def stepper(k: int) -> _Stepper:
        if k not in built:
            built[k] = _Stepper.of(Minv, *schedule.systems[k], step)
        return built[k]

    loads = [RotatingLoad(load.ratio[h], load.inertial[h], load.constant[h]) for h in schedule.groups]
    t = np.arange(steps + 1) * step
    carried = []  # per group: (system, z, u, load) at the last time integrated
    for g, part in enumerate(loads):
        k = int(schedule.index(g, t[:1])[0])
        force = part.at(*ramp.speed(t[:1]))[:, 0]
        carried.append((k, *stepper(k).enter(np.concatenate([q0[g], v0[g]]), force), force))
    q_start = np.sum(q0, axis=0)
    start = np.einsum("pdn,n->pd", points, q_start)
    magnitude = np.empty(steps + 1)
    magnitude[0] = np.linalg.norm(start, axis=1).max(initial=0.0)
    point_peaks = np.linalg.norm(start, axis=1)
    direction_peaks = np.abs(start)
    observed = np.empty((observers.shape[0], steps + 1))
    observed[:, 0] = np.abs(observers @ q_start)
    for first in range(1, steps + 1, CHUNK):
        tc = t[first : first + CHUNK]
        omega, domega, phi = ramp.speed(tc)
        q = np.zeros((n, tc.size))
        for g, part in enumerate(loads):
            force = part.at(omega, domega, phi)
            index = schedule.index(g, tc)
            k, z, u, before = carried[g]
            edges = np.concatenate([[0], np.flatnonzero(np.diff(index)) + 1, [tc.size]])
            for a, b in zip(edges[:-1], edges[1:]):
                if int(index[a]) != k:  # the system changes: carry the physical state over
                    state = (stepper(k).Z @ z).real
                    k = int(index[a])
                    z, u = stepper(k).enter(state, before)
                zs, us = stepper(k).advance(force[:, a:b], z, u)
                z, u, before = zs[:, -1], us[:, -1], force[:, b - 1]
                q[:, a:b] += (stepper(k).Z[:n] @ zs).real
            carried[g] = (k, z, u, before)
        vectors = np.einsum("pdn,nt->pdt", points, q)
        disp = np.linalg.norm(vectors, axis=1)
        magnitude[first : first + tc.size] = disp.max(axis=0)
        observed[:, first : first + tc.size] = np.abs(observers @ q)
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


__all__ = ["CHUNK", "first_order_recursion", "point_displacements", "MAX_STEPS", "STEPS_PER_PERIOD", "Ramp", "RotatingLoad", "Schedule",
           "SweepResponse", "integrate", "refined_peak", "time_step"]
