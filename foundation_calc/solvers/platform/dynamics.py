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

The model is the one of every foundation: a rigid body (the platform: M, r_c, J_O1, about its
reference point O1) on a support, its isolators (:class:`~foundation_calc.solvers.supports.isolators.Isolators`:
K_springs, η, β), carrying machines, its exciters (each a
:class:`~foundation_calc.solvers.machines.exciter.UnbalancedExciter`, whose module gives the rotor's
terms of M, G, K and F above, Eqs. (1)-(4) there, as Fourier coefficients); the rigid-body parts
(parallel axes, the springs carried from the corners, the weight's tilt, the modes) are those of
:mod:`foundation_calc.solvers.rigid_body`, shared with the block foundation (``block_inertia`` is
re-exported from there). A rotor at its own speed is its own machine (:class:`Rotor`: the part and
its speed), so that exciters at different speeds make the system quasi-periodic.

Every coefficient is a trigonometric polynomial in the φ_j (harmonic vectors 0, ±e_j, ±2e_j);
:func:`periodic_system` assembles the parts' Fourier coefficients and the support's springs and
:mod:`~foundation_calc.solvers.platform.harmonic_balance` solves for the steady state with the
isolators' exact complex stiffness K_springs (1 + iη sgn Ω) + iΩβ K_springs.

References
----------
.. [1] N.N. Bolotnik, B.V. Gusev, Nguyen Truong, I.E. Kholmin, F.L. Chernousko, "Calculation of
   the parameters of a vibration mechanism with unbalanced vibration exciters", Izv. AN SSSR,
   MTT, 1986.
"""

from __future__ import annotations

from dataclasses import dataclass, field, replace
from typing import NamedTuple

import numpy as np

from foundation_calc.errors import PhysicsError
from foundation_calc.solvers.machines.exciter import UnbalancedExciter
from foundation_calc.solvers.rigid_body.inertia import block_inertia, parallel_axis, skews
from foundation_calc.solvers.rigid_body.kinematics import weight_tilt
from foundation_calc.solvers.rigid_body.modes import dominant_motions, eigen
from foundation_calc.solvers.supports.isolators import Isolators, loss

E3 = np.array([0.0, 0.0, 1.0])

#: A mode whose squared natural frequency is within this fraction of the stiffest one from zero
#: has no restraint: double precision cannot tell its stiffness from nothing [-].
UNRESTRAINED = 1e-12

#: Names of the six coordinates, in order.
COORDINATES = ("x", "y", "z", "alpha", "beta", "gamma")


class Rotor(NamedTuple):
    """One exciter turning on the platform: the machine part
    (:class:`~foundation_calc.solvers.machines.exciter.UnbalancedExciter`) and its machine's speed.

    Attributes
    ----------
    part : the exciter (mass, eccentricity, axis, phase, sense σ)
    speed : its machine's speed ω > 0 [rad/s]
    """

    part: UnbalancedExciter
    speed: float

    @property
    def omega(self) -> float:
        """The signed speed ω_j = σ ω about the axis e [rad/s] (the paper's)."""
        return self.part.sense * self.speed


def rotor(m, l, rho, delta1, delta2, omega, phi0) -> Rotor:
    """A :class:`Rotor` in the paper's symbols: rotor mass m [kg], eccentricity l [m], axis point
    ρ = (a, b, c) [m], axis angles δ1, δ2 of (1.3) [rad], signed speed ω_j [rad/s] (negative:
    turning against e; not 0), angle φ_j0 at t = 0 [rad]."""
    sense = 1.0 if omega > 0 else -1.0
    return Rotor(UnbalancedExciter(m, l, tuple(rho), delta1, delta2, phi0, sense), abs(omega))


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

    @property
    def isolators(self) -> Isolators:
        """The support: the twelve springs at the corners from O1, the loss factor and the dashpots."""
        return Isolators(self.corners, self.stiffness, self.eta, self.beta)


def inertia_about_corner(M, r_c, J_c) -> np.ndarray:
    """J_O1 = J_c + M (|r_c|² I - r_c r_cᵀ) (parallel axes) [kg m²]."""
    return parallel_axis(M, r_c, J_c)


def spring_stiffness(platform: RigidPlatform) -> np.ndarray:
    """K_springs = Σ_i T_iᵀ diag(c_i) T_i, 6×6 [N/m, N, N m], the isolators' at O1."""
    return platform.isolators.springs


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
        """D(Ω) = K_0 + i (η sgn Ω + β Ω) K_springs + iΩ G_0 - Ω² M_0 for each Ω, shape (H, 6, 6)
        (of a stack of systems: (V, H, 6, 6))."""
        w = np.asarray(omega, dtype=float)[:, None, None]
        K0, G0, M0 = (x[..., :1, :, :] for x in (self.stiff, self.gyro, self.mass))
        return K0 + 1j * loss(self.eta, self.beta, w) * self.springs[..., None, :, :] + 1j * w * G0 - w * w * M0


def stack(systems) -> PeriodicSystem:
    """Systems of equal rotors and speeds as one: every coefficient array gains a leading axis
    (V, ...) over the systems; ``speeds`` and the harmonic vectors are those of the first."""
    first = systems[0]
    arrays = {
        name: np.stack([getattr(s, name) for s in systems])
        for name in ("mass", "gyro", "stiff", "force", "springs", "static_load")
    }
    return replace(first, **arrays)


def periodic_system(platform: RigidPlatform, rotors) -> PeriodicSystem:
    """Assemble the Fourier coefficients of the linearised equations (module docstring).

    Rotor j contributes at the harmonic vectors 0, ±e_j and ±2e_j only; ``keys`` are 0 followed by
    the others in ascending order, ``force_keys`` all of them in ascending order.
    """
    N = len(rotors)
    offsets = [(j, o) for j in range(N) for o in (-2, -1, 1, 2)]
    vectors = sorted(tuple(o if k == j else 0 for k in range(N)) for j, o in offsets)
    keys = np.array([(0,) * N] + vectors, dtype=int).reshape(-1, N)
    row = {tuple(k): i for i, k in enumerate(keys.tolist())}
    P = len(keys)
    speeds = np.array([r.omega for r in rotors], dtype=float)
    M_sigma = platform.M + sum(r.part.m for r in rotors)
    r_c = np.asarray(platform.r_c, dtype=float)
    S_tot = np.zeros((P, 3), dtype=complex)
    S_tot[0] = platform.M * r_c
    parts = {name: np.zeros((P, 3, 3), dtype=complex) for name in ("J", "G_R", "G_P", "K_R", "K_P")}
    parts["J"][0] = platform.J_O1
    F = np.zeros((P, 6), dtype=complex)
    zeta_s = platform.M * r_c[2]
    for j, rot in enumerate(rotors):
        at = [row[tuple(o if k == j else 0 for k in range(N))] for o in (-2, -1, 0, 1, 2)]
        terms = rot.part.series(rot.speed, platform.g)
        zeta_s += rot.part.m * rot.part.rho[2]
        S_tot[at] += terms["S"]
        for name, total in parts.items():
            total[at] += terms[name]
        F[at, :3] += terms["F_R"]
        F[at, 3:] += terms["F_P"]

    support = platform.isolators
    springs = support.springs
    s = skews(S_tot)
    mass = np.zeros((P, 6, 6), dtype=complex)
    mass[0, :3, :3] = M_sigma * np.eye(3)
    mass[:, :3, 3:], mass[:, 3:, :3], mass[:, 3:, 3:] = -s, s, parts["J"]
    gyro, stiff = np.zeros_like(mass), np.zeros_like(mass)
    gyro[:, :3, 3:], gyro[:, 3:, 3:] = parts["G_R"], parts["G_P"]
    stiff[:, :3, 3:], stiff[:, 3:, 3:] = parts["K_R"], parts["K_P"]
    stiff[0] += springs + weight_tilt(platform.g, zeta_s)  # W z_G = g Σ m z
    by_key = np.lexsort(keys.T[::-1])
    S_mean = S_tot[0].real
    static = np.array([0.0, 0.0, -M_sigma * platform.g, -platform.g * S_mean[1], platform.g * S_mean[0], 0.0])  # -g S × e3
    return PeriodicSystem(
        speeds, keys, mass, gyro, stiff, keys[by_key], F[by_key],
        springs, support.eta, support.beta, static,
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
    p2, shapes = _mean_eigen(system, float(np.hypot(platform.A, platform.B)))
    r_c = np.asarray(platform.r_c, dtype=float)
    J_c = platform.J_O1 - platform.M * (r_c @ r_c * np.eye(3) - np.outer(r_c, r_c))
    dominant = tuple(COORDINATES[int(i)] for i in dominant_motions(shapes, platform.M, r_c, np.diag(J_c)))
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


def _mean_eigen(system: PeriodicSystem, length: float):
    """p² (ascending) and mass-normalised shapes of K0 v = p² M0 v (:func:`natural_frequencies`), for
    one system or a stack; ``length``: the platform's diagonal [m]."""
    return eigen(system.stiff[..., 0, :, :].real, system.mass[..., 0, :, :].real, length)


def stacked_frequencies(system: PeriodicSystem, length: float) -> np.ndarray:
    """Natural frequencies [rad/s] of each system of a :func:`stack` (as :func:`natural_frequencies`,
    without mode shapes); ``length``: the platform's diagonal [m].

    Raises
    ------
    PhysicsError
        when a system has a vanishing or negative squared frequency (:func:`natural_frequencies`
        says which and why).
    """
    p2 = _mean_eigen(system, length)[0]
    if not np.all(p2[..., 0] > UNRESTRAINED * p2[..., -1]):
        raise PhysicsError("a squared natural frequency vanishes or is negative", field="isolators")
    return np.sqrt(p2)
