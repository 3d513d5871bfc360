"""Linearised 6-DOF dynamics of a rigid platform on twelve springs, driven by rotating unbalances.

Source: the model of section 1 of [1]_ (Eqs. (1.1)-(1.9)), re-derived here because the printed
rotational equations are omitted and the rotor matrix A_j(φ) is garbled (its entry (3,2) is
-sin δ2 cos φ; (1.7) itself is right).

Model. Coordinates q = (x, y, z, α, β, γ): displacement R of corner O1 and the small rotation Φ
of the platform. Isolator i at corner r_i is three springs c_i1, c_i2, c_i3 along the fixed axes
(the paper's potential (1.2)). Rotor j is a point mass m_j at body position S_j(t) = ρ_j + L_j(t),
with L_j = l_j (t1 cos φ_j + t2 sin φ_j), t1 = (sin δ1, -cos δ1, 0),
t2 = (cos δ1 cos δ2, sin δ1 cos δ2, -sin δ2), axis e = t1 × t2 (1.3), (1.7), and φ_j = ω_j t + φ_j0
(ω_j may be negative: a two-shaft directional exciter is two rotors with ω and -ω).

Newton-Euler for platform and rotors (Σ r×m a about O1 = moment of external forces), kept to first
order in q with L_j finite, and linearised about the static equilibrium gives
M(t) q'' + G(t) q' + K(t) q = F(t) with, S_tot = M r_c + Σ m_j S_j and [v]× the cross matrix::

    M = [[M_Σ I, -[S_tot]×], [[S_tot]×, J_O1 + Σ m (|S|² I - S Sᵀ)]]
    G = [[0, -Σ 2m [L']×], [0, Σ 2m ((S·L') I - L' Sᵀ)]]
    K = K_springs + [[0, -Σ m [L'']×], [0, Σ m (S L''ᵀ - L'' Sᵀ) + g m (L e3ᵀ - (L·e3) I)
                                        - g (Mζ + Σ m c_j) diag(1, 1, 0)]]
    F = [-Σ m L'',  -Σ m S × L'' - g Σ m L × e3]

K_springs = Σ_i T_iᵀ diag(c_i1, c_i2, c_i3) T_i with T_i = [I, -[r_i]×]; the last term of K is
the weight's tilt stiffness about the static equilibrium (the weight's moment and the springs'
preload combined). Damping of the isolators: a hysteretic loss factor η multiplies K_springs by
(1 + iη sign Ω) at frequency Ω; dashpots β c_ij in parallel with the springs add β K_springs q'.
The rotor's own inertia about its axis is neglected (point masses), as in the paper's design
(e × J e = 0).

Every coefficient is a trigonometric polynomial in the φ_j (harmonic vectors 0, ±e_j, ±2e_j);
:func:`periodic_system` returns their Fourier coefficients and
:mod:`~foundation_calc.solvers.platform.harmonic_balance` solves for the steady state.

References
----------
.. [1] N.N. Bolotnik, B.V. Gusev, Nguyen Truong, I.E. Kholmin, F.L. Chernousko, "Calculation of
   the parameters of a vibration mechanism with unbalanced vibration exciters", Izv. AN SSSR,
   MTT, 1986.
"""

from __future__ import annotations

from collections import defaultdict
from dataclasses import dataclass, field, replace

import numpy as np

from foundation_calc.errors import ConvergenceError, PhysicsError

E3 = np.array([0.0, 0.0, 1.0])

#: A mode whose squared natural frequency is within this fraction of the stiffest one from zero
#: has no restraint: double precision cannot tell its stiffness from nothing [-].
UNRESTRAINED = 1e-12

#: Names of the six coordinates, in order.
COORDINATES = ("x", "y", "z", "alpha", "beta", "gamma")


@dataclass(frozen=True)
class Rotor:
    """One single-shaft unbalanced exciter (SI units).

    Attributes
    ----------
    m : rotor mass [kg]
    l : eccentricity, axis to rotor's centre of mass [m]
    rho : (a, b, c), the axis point O^j in the platform frame [m]
    delta1, delta2 : axis angles of (1.3) [rad]; (0, 0) is a vertical axis
    omega : signed speed about the axis e [rad/s]
    phi0 : angle at t = 0 [rad]
    """

    m: float
    l: float
    rho: tuple
    delta1: float
    delta2: float
    omega: float
    phi0: float

    def axes(self):
        """(t1, t2, e) of (1.3), (1.7) in the platform frame."""
        s1, c1, s2, c2 = np.sin(self.delta1), np.cos(self.delta1), np.sin(self.delta2), np.cos(self.delta2)
        t1 = np.array([s1, -c1, 0.0])
        t2 = np.array([c1 * c2, s1 * c2, -s2])
        return t1, t2, np.cross(t1, t2)

    def eccentric_phasor(self) -> np.ndarray:
        """λ with L(t) = λ e^{iφ} + conj: λ = l (t1 - i t2) e^{iφ0} / 2 [m]."""
        t1, t2, _ = self.axes()
        return 0.5 * self.l * (t1 - 1j * t2) * np.exp(1j * self.phi0)


@dataclass(frozen=True)
class RigidPlatform:
    """The platform, its isolators and its loss factor (SI units).

    Attributes
    ----------
    M : platform mass without rotors [kg]
    r_c : (ξ, η, ζ) centre of mass from corner O1 [m]
    J_O1 : inertia tensor about O1 in the platform frame, 3×3 [kg m²]
    A, B : sides O1O2 (x') and O1O4 (y') [m]
    stiffness : c_ij, 4×3, rows O1..O4, columns x, y, z [N/m]
    eta : hysteretic loss factor of the isolators [-]
    g : acceleration of gravity [m/s²]
    beta : time constant of viscous dashpots β c_ij in parallel with the springs [s]
    """

    M: float
    r_c: tuple
    J_O1: np.ndarray
    A: float
    B: float
    stiffness: np.ndarray
    eta: float
    g: float
    beta: float = 0.0

    @property
    def corners(self) -> np.ndarray:
        """r_1..r_4 of (1.3) [m], shape (4, 3)."""
        A, B = self.A, self.B
        return np.array([[0.0, 0.0, 0.0], [A, 0.0, 0.0], [A, B, 0.0], [0.0, B, 0.0]])


def skew(v) -> np.ndarray:
    """Cross-product matrix: skew(v) @ w == v × w (complex v allowed)."""
    v = np.asarray(v)
    return np.array([[0 * v[0], -v[2], v[1]], [v[2], 0 * v[0], -v[0]], [-v[1], v[0], 0 * v[0]]])


def point_map(p) -> np.ndarray:
    """T with T q = displacement of body point p, R + Φ × p, shape 3×6."""
    return np.hstack([np.eye(3), -skew(p)])


def block_inertia(M, A, B, H):
    """Central principal moments of a homogeneous block A × B × H of mass M [kg m²].

    >>> block_inertia(12.0, 1.0, 2.0, 3.0)
    (13.0, 10.0, 5.0)
    """
    return M * (B * B + H * H) / 12.0, M * (A * A + H * H) / 12.0, M * (A * A + B * B) / 12.0


def inertia_about_corner(M, r_c, J_c) -> np.ndarray:
    """J_O1 = J_c + M (|r_c|² I - r_c r_cᵀ) (parallel axes) [kg m²]."""
    r = np.asarray(r_c, dtype=float)
    return np.diag(np.asarray(J_c, dtype=float)) + M * (r @ r * np.eye(3) - np.outer(r, r))


def spring_stiffness(platform: RigidPlatform) -> np.ndarray:
    """K_springs = Σ_i T_iᵀ diag(c_i) T_i, 6×6 [N/m, N, N m]."""
    K = np.zeros((6, 6))
    for r_i, c_i in zip(platform.corners, platform.stiffness):
        T = point_map(r_i)
        K += T.T @ np.diag(c_i) @ T
    return K


# ---- trigonometric polynomials: dict {harmonic vector (tuple of ints): complex coefficient} ----


def _series_product(a: dict, b: dict, op) -> dict:
    out: dict = defaultdict(lambda: 0)
    for ka, va in a.items():
        for kb, vb in b.items():
            out[tuple(x + y for x, y in zip(ka, kb))] = out[tuple(x + y for x, y in zip(ka, kb))] + op(va, vb)
    return dict(out)


def _series_add(*terms) -> dict:
    out: dict = defaultdict(lambda: 0)
    for scale, series in terms:
        for k, v in series.items():
            out[k] = out[k] + scale * v
    return dict(out)


def _series_map(a: dict, fn) -> dict:
    return {k: fn(v) for k, v in a.items()}


@dataclass(frozen=True)
class PeriodicSystem:
    """Fourier coefficients of M(t), G(t), K(t) and F(t), as arrays over harmonic vectors.

    Attributes
    ----------
    speeds : signed rotor speeds ω_j [rad/s], shape (N,)
    keys : harmonic vectors k of the coefficients, shape (P, N); row 0 is k = 0
    mass, gyro, stiff : M_k, G_k, K_k, shape (P, 6, 6) [kg, kg m, ...; N s/m, ...; N/m, ...]
    force_keys, force : harmonic vectors and coefficients F_n of the forcing, shapes (F, N), (F, 6)
    springs : K_springs, 6×6 [N/m, N, N m]
    eta : hysteretic loss factor of the springs [-]
    beta : time constant of the dashpots β c_ij in parallel with the springs [s]
    static_load : weight and its moment about O1, the right side of the static equilibrium [N, N m]
    """

    speeds: np.ndarray
    keys: np.ndarray
    mass: np.ndarray
    gyro: np.ndarray
    stiff: np.ndarray
    force_keys: np.ndarray
    force: np.ndarray
    springs: np.ndarray
    eta: float
    beta: float
    static_load: np.ndarray = field(repr=False)

    @property
    def damped(self) -> bool:
        """True when the isolators dissipate energy at every frequency but 0."""
        return self.eta > 0.0 or self.beta > 0.0

    def frequencies(self, n) -> np.ndarray:
        """Ω = n·ω [rad/s] of harmonic vectors n (shape (..., N))."""
        return np.asarray(n) @ self.speeds

    def with_springs(self, springs: np.ndarray) -> "PeriodicSystem":
        """The same system on other isolators (K_springs replaced, the rotors' terms kept)."""
        stiff = self.stiff.copy()
        stiff[0] += springs - self.springs
        return replace(self, stiff=stiff, springs=springs)

    def dynamic_matrices(self, omega) -> np.ndarray:
        """D(Ω) = K_0 + i (η sgn Ω + β Ω) K_springs + iΩ G_0 - Ω² M_0 for each Ω, shape (H, 6, 6)."""
        w = np.asarray(omega, dtype=float)[:, None, None]
        loss = 1j * (self.eta * np.sign(w) + self.beta * w)
        return self.stiff[0] + loss * self.springs + 1j * w * self.gyro[0] - w * w * self.mass[0]


def periodic_system(platform: RigidPlatform, rotors) -> PeriodicSystem:
    """Assemble the Fourier coefficients of the linearised equations (module docstring)."""
    N = len(rotors)
    zero = (0,) * N
    speeds = np.array([r.omega for r in rotors], dtype=float)
    M_sigma = platform.M + sum(r.m for r in rotors)
    r_c = np.asarray(platform.r_c, dtype=float)

    def unit(j, s):
        return tuple(s if k == j else 0 for k in range(N))

    S_tot = {zero: platform.M * r_c + 0j}
    J = {zero: platform.J_O1 + 0j}
    G_R, G_P, K_R, K_P = {}, {}, {}, {}
    F_R, F_P = {}, {}
    zeta_s = platform.M * r_c[2]
    for j, rot in enumerate(rotors):
        lam, w = rot.eccentric_phasor(), rot.omega
        L = {unit(j, 1): lam, unit(j, -1): lam.conj()}
        Ld = {unit(j, 1): 1j * w * lam, unit(j, -1): -1j * w * lam.conj()}
        Ldd = _series_map(L, lambda v, w=w: -w * w * v)
        S = _series_add((1.0, {zero: np.asarray(rot.rho, dtype=float) + 0j}), (1.0, L))
        m = rot.m
        zeta_s += m * rot.rho[2]
        S_tot = _series_add((1.0, S_tot), (m, S))
        SS = _series_product(S, S, lambda a, b: (a @ b) * np.eye(3) - np.outer(a, b))
        J = _series_add((1.0, J), (m, SS))
        G_R = _series_add((1.0, G_R), (-2.0 * m, _series_map(Ld, skew)))
        G_P = _series_add((1.0, G_P), (2.0 * m, _series_product(S, Ld, lambda s, d: (s @ d) * np.eye(3) - np.outer(d, s))))
        K_R = _series_add((1.0, K_R), (-m, _series_map(Ldd, skew)))
        K_P = _series_add(
            (1.0, K_P),
            (m, _series_product(S, Ldd, lambda s, d: np.outer(s, d) - np.outer(d, s))),
            (platform.g * m, _series_map(L, lambda v: np.outer(v, E3) - v[2] * np.eye(3))),
        )
        F_R = _series_add((1.0, F_R), (-m, Ldd))
        F_P = _series_add(
            (1.0, F_P),
            (-m, _series_product(S, Ldd, np.cross)),
            (-platform.g * m, _series_map(L, lambda v: np.cross(v, E3))),
        )

    springs = spring_stiffness(platform)
    keys = [zero] + sorted((set(S_tot) | set(J) | set(G_R) | set(G_P) | set(K_R) | set(K_P)) - {zero})
    z3 = np.zeros((3, 3))
    mass = np.empty((len(keys), 6, 6), dtype=complex)
    gyro, stiff = np.empty_like(mass), np.empty_like(mass)
    for i, k in enumerate(keys):
        s = skew(S_tot.get(k, np.zeros(3)))
        mass[i] = np.block([[np.eye(3) * (M_sigma if k == zero else 0.0), -s], [s, J.get(k, z3)]])
        gyro[i] = np.block([[z3, G_R.get(k, z3)], [z3, G_P.get(k, z3)]])
        stiff[i] = np.block([[z3, K_R.get(k, z3)], [z3, K_P.get(k, z3)]])
    stiff[0] += springs - platform.g * zeta_s * np.diag([0, 0, 0, 1.0, 1.0, 0])
    force_keys = sorted(set(F_R) | set(F_P))
    force = [np.concatenate([F_R.get(k, np.zeros(3)), F_P.get(k, np.zeros(3))]) for k in force_keys]
    S_mean = S_tot[zero].real
    static = np.concatenate([[0.0, 0.0, -M_sigma * platform.g], -platform.g * np.cross(S_mean, E3)])
    return PeriodicSystem(
        speeds, np.array(keys, dtype=int).reshape(-1, N), mass, gyro, stiff,
        np.array(force_keys, dtype=int).reshape(-1, N), np.array(force, dtype=complex).reshape(-1, 6),
        springs, platform.eta, platform.beta, static,
    )


@dataclass(frozen=True)
class Modes:
    """Undamped natural frequencies [rad/s] (ascending), the motion with the largest share of each
    mode's kinetic energy (translation of the centre of mass or rotation), and the mode shapes
    (columns, mass-normalised)."""

    frequencies: np.ndarray
    dominant: tuple
    shapes: np.ndarray


def natural_frequencies(platform: RigidPlatform, rotors, system: PeriodicSystem | None = None) -> Modes:
    """The six natural frequencies of the mean (time-averaged) system without damping.

    Solves K0 v = p² M0 v with M0, K0 the constant parts of M(t), K(t) (rotor masses at their
    mean inertia, the weight's tilt stiffness included, gyroscopic terms left out). ``system``:
    the equations of ``platform`` and ``rotors`` when already assembled.

    Raises
    ------
    PhysicsError
        when a squared frequency vanishes (a direction without springs) or is negative (the
        platform tips over under its weight).
    """
    system = system if system is not None else periodic_system(platform, rotors)
    # rotations scaled by the platform's diagonal, so translations and rotations are alike in size
    D = np.diag([1.0, 1.0, 1.0] + [1.0 / float(np.hypot(platform.A, platform.B))] * 3)
    M0, K0 = D @ system.mass[0].real @ D, D @ system.stiff[0].real @ D
    try:
        Lc = np.linalg.cholesky(0.5 * (M0 + M0.T))
        Li = np.linalg.inv(Lc)
        p2, v = np.linalg.eigh(Li @ (0.5 * (K0 + K0.T)) @ Li.T)
    except np.linalg.LinAlgError:
        raise ConvergenceError(
            "the 6-DOF natural frequencies cannot be computed in double precision: the platform's"
            " masses, sizes and stiffnesses span too many orders of magnitude"
        ) from None
    shapes = D @ Li.T @ v
    r_c = np.asarray(platform.r_c, dtype=float)
    J_c = platform.J_O1 - platform.M * (r_c @ r_c * np.eye(3) - np.outer(r_c, r_c))
    at_cog = shapes[:3] - skew(r_c) @ shapes[3:]  # translation of the centre of mass
    energy = np.vstack([platform.M * at_cog**2, np.diag(J_c)[:, None] * shapes[3:] ** 2])
    dominant = tuple(COORDINATES[int(np.argmax(energy[:, i]))] for i in range(6))
    if p2[0] <= UNRESTRAINED * p2[-1] and p2[0] > -UNRESTRAINED * p2[-1]:
        raise PhysicsError(
            f"the platform is not restrained in {dominant[0]}: the isolators give that motion no stiffness"
            f" (squared natural frequency {float(p2[0]):.3g} rad²/s², {float(p2[0] / p2[-1]):.1e} of the stiffest mode)",
            field="isolators",
            hint="every direction needs a spring: check the horizontal stiffness sums and the vertical stiffnesses",
        )
    if p2[0] <= 0.0:
        raise PhysicsError(
            f"the platform is unstable: a squared natural frequency is {float(p2.min()):.6g} rad²/s²"
            " (the weight's tilting moment exceeds the isolators' rocking stiffness)",
            field="isolators.vertical",
            hint="stiffen the vertical isolators or lower the centre of mass ζ",
        )
    return Modes(np.sqrt(p2), dominant, shapes)
