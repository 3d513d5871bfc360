"""A single-shaft unbalanced exciter (paper 001's rotor, Bolotnik et al. [1]_) on a rigid body: its
mean mass properties, its periodic inertia over one revolution and its forcing harmonics.

The rotor is a point mass m at an eccentricity l from its axis, which passes through the body
point ρ = (a, b, c) (from the body's reference point O; the platform's O is its corner O1) along
e = t1 × t2, Eqs. (1.3), (1.7) of [1]_::

    t1 = (sin δ1, -cos δ1, 0),   t2 = (cos δ1 cos δ2, sin δ1 cos δ2, -sin δ2)

It turns in the sense σ = ±1 about e at the machine's speed ω > 0: its angle is
θ = σ φ + φ0, φ = ωt, so the rotor of paper 001 turning at the signed speed ω_j is the part with
σ = sign ω_j at the machine's speed |ω_j| (a two-shaft directional exciter is two parts of one
machine, σ = +1 and -1). Its position on the body is S(t) = ρ + L(t), L = l (t1 cos θ + t2 sin θ)
= λ e^{iσφ} + conj, λ = l (t1 - i t2) e^{iφ0}/2, and L' = iσω (λ e^{iσφ} - conj), L'' = -ω² L.

Equations of the body with the rotor, linearised in the body's small motion q = (u, θ) about O by
Newton-Euler in the fixed axes (Σ r × m a about O = the moment of the external forces about O,
the form of :mod:`foundation_calc.solvers.platform.dynamics`), per rotor::

    M(φ) = [[m I, -m [S]×], [m [S]×, m (|S|² I - S Sᵀ)]]                                   (1)
    D(φ) = [[0, -2m [L']×], [0, 2m ((S·L') I - L' Sᵀ)]]                                   (2)
    S(φ) = [[0, -m [L'']×], [0, m (S L''ᵀ - L'' Sᵀ) + g m (L e3ᵀ - (L·e3) I)]]
           - g m c diag(0, 0, 0, 1, 1, 0)                                                    (3)
    f(φ) = (-m L'', -m S × L'' - g m L × e3)                                                 (4)

(4) is a force m ω² L(t) rotating at ω through ρ (inertial, ∝ ω²) and the moment -g m L × e3 of
the rotor's weight about its axis point (not inertial: the ``weight``, which no speed changes): two loads of order 1 a quarter period
apart for each. The last term of (3) is the weight's tilt of the rotor's mean position
(:func:`~foundation_calc.solvers.rigid_body.kinematics.weight_tilt`); the rest of (3) and (4)
average to zero over a revolution, and (2) to the rotor's gyroscopic coupling
-2m mean(L' Lᵀ) = -σ ω m l² (t2 t1ᵀ - t1 t2ᵀ) = -[σ ω m l² e]× in the rotations (its angular
momentum about its axis; two rotors of opposite sense cancel it), which the block's averaged
operator keeps in its C (:meth:`~foundation_calc.solvers.machines.part.MachinePart.gyroscopic`). These differ from the crank mechanism's Lagrange
form (:mod:`.crank_mechanism`, rotation-vector coordinates) by terms of second order in the
motion: the inertia moment's stiffness -m [S × L'']× here against -½ m [r × r'']× there (the
Lagrange equations are these multiplied by the rotation's Jacobian), and the weight's off-diagonal
tilt terms g m L_x, g m L_y about z, kept here.

Every coefficient is a trigonometric polynomial of degree 2 in σφ: :meth:`UnbalancedExciter.series`
gives its Fourier coefficients at the offsets -2..2 (the platform's harmonic-balance input), and
:meth:`~UnbalancedExciter.periodic_inertia` evaluates them at phases. The rotor's own inertia about
its axis is neglected (a point mass), as in [1]_.

References
----------
.. [1] N.N. Bolotnik, B.V. Gusev, Nguyen Truong, I.E. Kholmin, F.L. Chernousko, "Calculation of
   the parameters of a vibration mechanism with unbalanced vibration exciters", Izv. AN SSSR,
   MTT, 1986, Eqs. (1.3), (1.7).
"""

from __future__ import annotations

from dataclasses import dataclass
from functools import lru_cache

import numpy as np

from foundation_calc.solvers.machines.part import LoadRow, MachinePart, Number, Triple
from foundation_calc.solvers.numerics.trig_series import phases
from foundation_calc.solvers.rigid_body.inertia import skews

E3 = np.array([0.0, 0.0, 1.0])

#: The offsets of the exciter's angle at which :meth:`UnbalancedExciter.series` gives coefficients.
OFFSETS = np.arange(-2, 3)


@dataclass(frozen=True)
class UnbalancedExciter(MachinePart):
    """A single-shaft unbalanced exciter (module docstring), SI units.

    Attributes
    ----------
    m : rotor mass [kg]
    l : eccentricity, axis to the rotor's centre of mass [m]
    rho : (a, b, c), the axis point from O [m]
    delta1, delta2 : axis angles of Eq. (1.3) [rad]; (0, 0) is a vertical axis
    phi0 : the rotor's angle at t = 0 [rad]
    sense : σ, +1 turning positively about e (right-hand rule), -1 against it
    """

    m: float
    l: float
    rho: tuple
    delta1: float
    delta2: float
    phi0: float
    sense: float = 1.0

    periodic = True

    def axes(self):
        """(t1, t2, e) of (1.3), (1.7), unit vectors in the body's axes."""
        s1, c1, s2, c2 = np.sin(self.delta1), np.cos(self.delta1), np.sin(self.delta2), np.cos(self.delta2)
        t1 = np.array([s1, -c1, 0.0])
        t2 = np.array([c1 * c2, s1 * c2, -s2])
        return t1, t2, np.array([c1 * s2, s1 * s2, c2])  # t1 × t2

    def eccentric_phasor(self) -> np.ndarray:
        """λ with L(t) = λ e^{iσφ} + conj: λ = l (t1 - i t2) e^{iφ0} / 2 [m]."""
        t1, t2, _ = self.axes()
        return 0.5 * self.l * (t1 - 1j * t2) * np.exp(1j * self.phi0)

    def series(self, omega: float, g: float) -> dict:
        """Fourier coefficients of the parts of (1)-(4) at the offsets -2..2 of the angle σφ, at the
        machine's speed ω [rad/s] and gravity g [m/s²] (:func:`rotor_series`)."""
        return rotor_series(self, float(omega), float(g))

    def mass_properties(self) -> tuple[float, np.ndarray, np.ndarray]:
        """m [kg], the mean centre of mass ρ [m] (the mean of L is zero) and the central inertia
        of the mean of (1), m l²/2 (I + e eᵀ) [kg m²] (a ring of radius l about e).

        >>> m, cog, J = UnbalancedExciter(25.0, 0.2, (1.0, 0.5, 2.6), 0.0, 0.0, 0.0).mass_properties()
        >>> m, cog.tolist(), J.diagonal().round(12).tolist()
        (25.0, [1.0, 0.5, 2.6], [0.5, 0.5, 1.0])
        """
        e = self.axes()[2]
        return float(self.m), np.asarray(self.rho, dtype=float), 0.5 * self.m * self.l**2 * (np.eye(3) + np.outer(e, e))

    def periodic_inertia(self, omega: float, g: float, N: int) -> tuple[np.ndarray, np.ndarray, np.ndarray]:
        """M(φ_j), D(φ_j), S(φ_j) of (1)-(3) at φ_j = 2πj/N, (N, 6, 6) each, from :meth:`series`."""
        terms = self.series(omega, g)
        wave = np.exp(1j * self.sense * np.multiply.outer(phases(N), OFFSETS))  # (N, 5)

        def at(name):
            return np.einsum("jo,o...->j...", wave, terms[name]).real

        M, D, S = (np.zeros((N, 6, 6)) for _ in range(3))
        s = skews(at("S"))
        M[:, :3, :3] = self.m * np.eye(3)
        M[:, :3, 3:], M[:, 3:, :3], M[:, 3:, 3:] = -s, s, at("J")
        D[:, :3, 3:], D[:, 3:, 3:] = at("G_R"), at("G_P")
        S[:, :3, 3:], S[:, 3:, 3:] = at("K_R"), at("K_P")
        S[:, 3, 3] -= g * self.m * self.rho[2]
        S[:, 4, 4] -= g * self.m * self.rho[2]
        return M, D, S

    def load_rows(self, omega: float, g: float) -> list[LoadRow]:
        """(4) as loads of order 1 at ρ: 2 Re(c e^{iσφ}) = 2 Re c cos φ + 2 Im c cos(φ + σπ/2) for the
        force's coefficient c = m ω² λ (inertial) and the weight's moment's c = -g m λ × e3 (weight)."""
        lam = self.eccentric_phasor()
        rows = []
        for c, inertial in ((self.m * omega * omega * lam, True), (-g * self.m * np.cross(lam, E3), False)):
            for part, phase in ((c.real, 0.0), (c.imag, self.sense * np.pi / 2.0)):
                if np.any(part != 0.0):
                    force, moment = (2.0 * part, np.zeros(3)) if inertial else (np.zeros(3), 2.0 * part)
                    rows.append(LoadRow(1, force.tolist(), moment.tolist(), float(phase), tuple(self.rho), inertial,
                                            not inertial))
        return rows

    def carried_inertia(self, omega: float) -> float:
        """m l²: the point mass about its axis [kg m²]."""
        return self.m * self.l**2

    def assumption(self) -> str:
        """The sheet's phrase for an exciter's rotor."""
        return ("the exciters' rotors, point masses m at the eccentricity l from their axes: the force m l ω²"
                " rotating normal to each axis and the moment of the rotor's weight about its axis point [BC]")

    def sheet_text(self, omega: float) -> tuple:
        """F = m l ω² substituted, the axis, the sense and the angle at t = 0 with its reference t1, t2."""
        t1, t2, e = (tuple(np.where(np.abs(v) < 1e-12, 0.0, v).tolist()) for v in self.axes())  # round-off of sin, cos
        return ("unbalanced exciter F = m l ω² = ", Number(self.m), " kg × ", Number(self.l), " m × (",
                Number(omega), " rad/s)² = ", Number(self.m * self.l * omega * omega), " N, turning "
                + ("positively" if self.sense > 0 else "negatively") + " about its axis e = ", Triple(e),
                " through ", Triple(tuple(float(x) for x in self.rho)), " m, from the angle φ0 = ", Number(self.phi0),
                " rad at t = 0 (from t1 = ", Triple(t1), " towards t2 = ", Triple(t2), ", Eq. (1.3)); its mass is"
                " carried as a ring m l²/2 (I + e eᵀ) at the axis point, its angle-dependent inertia by [BC]'s"
                " Eqs. (1.3), (1.7).")


def axis_angles(axis) -> tuple[float, float]:
    """δ1, δ2 of Eq. (1.3) of [1]_ for an axis given as a vector e (any length, not zero).

    e/|e| = (cos δ1 sin δ2, sin δ1 sin δ2, cos δ2): δ2 = arccos(e_z/|e|) ∈ [0, π] is the axis's
    angle from the vertical z, δ1 = atan2(e_y, e_x) its azimuth about z (0 for an axis along ±z,
    where the azimuth is free). Then t1 = (sin δ1, -cos δ1, 0) is horizontal and normal to e
    (e × e3 / |e × e3| for an axis off the vertical; -y for one along ±z) and t2 = e × t1, the
    directions of the rotor's eccentricity at the angles 0 and π/2 about e.

    Parameters
    ----------
    axis : the axis direction (3,) [-]

    Returns
    -------
    (δ1, δ2) [rad]

    >>> [round(d, 12) for d in axis_angles((0.0, 0.0, 2.0))], [round(d, 12) for d in axis_angles((0.0, 1.0, 0.0))]
    ([0.0, 0.0], [1.570796326795, 1.570796326795])
    """
    x, y, z = (float(c) for c in axis)
    r = float(np.hypot(x, y))
    return (float(np.arctan2(y, x)) if r > 0.0 else 0.0), float(np.arctan2(r, z))


def phase_from_angles(delta1: float, delta2: float) -> float:
    """ψ [rad]: what to add to a rotor's angle φ0 at t = 0 given with the axis angles δ1, δ2 of
    Eq. (1.3) of [1]_ so that the rotor on the axis vector e of those angles, whose angles
    :func:`axis_angles` takes from e alone, stands where it stood: the turn about e from that
    t1' to the paper's t1 = (sin δ1, -cos δ1, 0), ψ = atan2(t1·t2', t1·t1').

    The vector fixes δ1 = 0 on a vertical axis (ψ = δ1 for δ2 = 0) and keeps δ2 within [0, π]
    (ψ = π for δ2 < 0, which reverses t1 and t2).

    Parameters
    ----------
    delta1, delta2 : the axis angles of Eq. (1.3) [rad]

    Returns
    -------
    ψ [rad], within (-π, π]

    >>> [round(phase_from_angles(*d), 12) + 0.0 for d in ((0.3, 0.0), (0.3, 1.0), (0.3, -1.0))]
    [0.3, 0.0, 3.14159265359]
    """
    paper = UnbalancedExciter(0.0, 0.0, (0.0, 0.0, 0.0), delta1, delta2, 0.0)
    t1, _, e = paper.axes()
    t1v, t2v, _ = UnbalancedExciter(0.0, 0.0, (0.0, 0.0, 0.0), *axis_angles(e), 0.0).axes()
    return float(np.arctan2(t1 @ t2v, t1 @ t1v))


@lru_cache(maxsize=256)
def rotor_series(part: UnbalancedExciter, omega: float, g: float) -> dict:
    """The Fourier coefficients of one exciter's parts of (1)-(4) (module docstring) at the offsets
    -2..2 of its angle σφ, each of shape (5, ...), read-only: ``S`` (m S), ``J`` (m (|S|² I - S Sᵀ)),
    ``G_R``, ``G_P`` (the blocks of (2)), ``K_R``, ``K_P`` (of (3), without the mean weight tilt)
    and ``F_R``, ``F_P`` (of (4)). Kept for the next system with this part (the tolerance variants
    of a platform's design change one exciter at most)."""
    lam, w, m = part.eccentric_phasor(), part.sense * omega, part.m
    L = np.array([lam.conj(), np.zeros(3), lam])  # offsets -1, 0, 1
    Ld = np.array([-1j * w * lam.conj(), np.zeros(3), 1j * w * lam])
    Ldd = -w * w * L
    S = L + np.array([0.0, 1.0, 0.0])[:, None] * np.asarray(part.rho, dtype=float)

    def wide(x):  # offsets -1..1 -> -2..2
        return np.concatenate([np.zeros((1,) + x.shape[1:], dtype=complex), x, np.zeros((1,) + x.shape[1:], dtype=complex)])

    L5, Ldd5 = wide(L), wide(Ldd)
    tilt = np.einsum("oi,j->oij", L5, E3) - L5[:, 2, None, None] * np.eye(3)
    terms = {
        "S": m * wide(S),
        "J": m * _product(S, S, "inertia"),
        "G_R": -2.0 * m * skews(wide(Ld)),
        "G_P": 2.0 * m * _product(S, Ld, "gyro"),
        "K_R": -m * skews(Ldd5),
        "K_P": m * _product(S, Ldd, "moment") + g * m * tilt,
        "F_R": -m * Ldd5,
        "F_P": -m * _product(S, Ldd, "cross") - g * m * (skews(L5) @ E3),
    }
    for value in terms.values():
        value.setflags(write=False)
    return terms


def _product(a, b, kind: str) -> np.ndarray:
    """The coefficients at offsets -2..2 (shape (5, ...)) of the product of two series a, b given at
    offsets -1..1 (shape (3, 3) each) with the bilinear ``kind``: "inertia" (a·b) I - a bᵀ,
    "gyro" (a·b) I - b aᵀ, "moment" a bᵀ - b aᵀ, "cross" a × b."""
    if kind == "cross":
        pairs = np.einsum("ikl,jl->ijk", skews(a), b)
    else:
        dot = np.einsum("ik,jk->ij", a, b)[..., None, None] * np.eye(3)
        ab, ba = np.einsum("ik,jl->ijkl", a, b), np.einsum("jk,il->ijkl", b, a)
        pairs = {"inertia": dot - ab, "gyro": dot - ba, "moment": ab - ba}[kind]
    out = np.zeros((5,) + pairs.shape[2:], dtype=complex)
    for i in range(3):
        out[i : i + 3] += pairs[i]
    return out


__all__ = ["OFFSETS", "UnbalancedExciter", "axis_angles", "phase_from_angles", "rotor_series"]
