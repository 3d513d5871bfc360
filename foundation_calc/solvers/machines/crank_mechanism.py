"""Crank-slider mechanisms (Krichever & Makarov [1]_'s mechanism, in 3-D, any number of throws) on
a rigid body: their mean mass properties, their periodic inertia and their forcing harmonics.

A throw (body axes of :mod:`foundation_calc.solvers.rigid_body`, O the body's reference point):
crank centre A, shaft axis n, slider axis s ⊥ n (from A towards the slider), t = n × s. The crank
turns at constant ω relative to the body by the right-hand rule about n; its angle from its own
top dead centre (pin towards the slider) is φ_c = ωt + α (α the throw's ``crank_angle``)::

    crank pin  M'  = A + r (cos φ_c s + sin φ_c t)
    slider pin M'' = A + (r cos φ_c + l cos ψ) s,       sin ψ = λ sin φ_c,  λ = r/l
    rod axis   e   = (M'' - M')/l = cos ψ s - λ sin φ_c t
    rod's centre of mass C1 = M' + l' e

cos ψ and its derivatives by :func:`foundation_calc.solvers.crank.mechanism.rod_angle_cosine` (the
crank foundation's). The rod (mass m, radius of gyration ρ about every axis through C1 normal to
it, none about its length) is dynamically the two point masses m/2 at C1 ± ρ e (same mass, centre
of mass and inertia tensor m ρ² (I - e eᵀ)); the slider is a point mass m1 at M''; an optional
rotating unbalance is a point mass m_r at A + r_r (cos(φ_c + β) s + sin(φ_c + β) t). So the
mechanism is point masses m_k at body positions r_k(φ), φ = ωt, moving at r_k' = ω dr_k/dφ,
r_k'' = ω² d²r_k/dφ².

Equations of the body with the mechanism, linearised in its small motion q = (u, θ) about O
(Lagrange's equations, the attitude R = exp([θ]×); virtual work of the point masses with
∂(R r)/∂θ = -[R r]× (I + ½[θ]× + ...)), per point mass::

    u-rows:  m (u'' + θ''×r + 2 θ'×r' + θ×r'') + m r''
    θ-rows:  m r × (u'' + θ''×r + 2 θ'×r' + θ×r'') + m (θ×r)×r'' - ½ m θ×(r×r'') + m r × r''

that is  M(φ) q'' + D(φ) q' + S(φ) q = f(φ) with (summed over the point masses; [v]× the cross
product matrix)::

    M = [[m I, -m[r]×], [m[r]×, m(|r|² I - r rᵀ)]]                 the mass matrix at φ  (1)
    D_uθ = -2 m [r']×,   D_θθ = -2 m [r]×[r']×                      Coriolis              (2)
    S_uθ = -m [r'']×,    S_θθ = -½ m [r × r'']×  - m g z (about x and y)                   (3)
    f = -(m r'', m r × r'') + (0, m g (-r_y, r_x, 0))              inertia and weight     (4)

The weight enters as the block model does it (:func:`~foundation_calc.solvers.rigid_body.kinematics.weight_tilt`,
W z_G about x and y; the rotation's off-diagonal terms m g r_x θ_x θ_z of the exact potential are
left out there and here). The time average of (1) is the mean mass properties; of (3) the weight
tilt of the mean positions (the inertia terms average to zero); (4) without its mean is the
forcing on a fixed body at constant ω (its mean is static). The mean of (2) is the mechanism's
mean gyroscopic coupling (zero for a plane throw's own plane; two throws at different angles on
one shaft give the rotations normal to it a skew coupling ∝ ω), which the block's averaged
operator keeps in its C (:meth:`CrankMechanism.gyroscopic`).

References
----------
.. [1] M.F. Krichever, S.M. Makarov, "Application of the small-parameter method to the problem
   of forced vibrations of the foundation of a crank-slider mechanism".
"""

from __future__ import annotations

from dataclasses import dataclass

import numpy as np

from foundation_calc.solvers.crank.mechanism import rod_angle_cosine
from foundation_calc.solvers.machines.part import LoadRow, MachinePart, Number, Triple
from foundation_calc.solvers.numerics.trig_series import phases
from foundation_calc.solvers.rigid_body.inertia import centre_of_mass, mass_matrix, parallel_axis, skews

#: Fewest phases per revolution at which the mechanism is sampled for its means and Fourier
#: coefficients (harmonics up to 127 resolved); :func:`samples_for` takes more for a rod barely
#: longer than its crank.
SAMPLES = 256

#: Most phases per revolution :func:`samples_for` takes: 2^14 resolve the kinematics to round-off
#: up to λ = r/l ≈ 1 - 1e-5; a throw nearer λ = 1 (a rod hardly longer than the crank, no real
#: machine) keeps this many, its series cut where its terms are q^8192 of the first.
MAX_SAMPLES = 1 << 14
#: Largest |cos| of the angle between a throw's slider and shaft axes (0.06°: directions as typed).
PERPENDICULAR = 1e-3
#: Size, relative to the largest harmonic of the same kind (force or moment), below which a
#: forcing order is left out of a machine's orders.
ORDER_TOLERANCE = 1e-6


@dataclass(frozen=True)
class CrankThrow:
    """One throw (cylinder) of a crank machine, in SI units (module docstring).

    Attributes
    ----------
    A : crank centre from O [m], (3,)
    n : shaft axis, unit (3,)
    s : slider axis, unit, ⊥ n (3,)
    alpha : crank angle at t = 0 from the throw's top dead centre, about n [rad]
    r : crank radius [m]
    l : rod length [m]
    m : rod mass [kg]
    l1 : l', rod's centre of mass to the crank pin [m]
    rho : rod's radius of gyration about its centre of mass, normal to the rod [m]
    m1 : slider mass [kg]
    m_rot, r_rot, beta : rotating unbalance mass [kg], its radius [m] and angle from the pin [rad]
    """

    A: np.ndarray
    n: np.ndarray
    s: np.ndarray
    alpha: float
    r: float
    l: float
    m: float
    l1: float
    rho: float
    m1: float
    m_rot: float
    r_rot: float
    beta: float

    @property
    def t(self) -> np.ndarray:
        """t = n × s: the direction of the pin a quarter turn after top dead centre."""
        return np.cross(self.n, self.s)


def crank_throw(crank_centre, shaft_axis, slider_axis, crank_angle, r, l, m, l1, rho, m1,
                m_rot=0.0, r_rot=0.0, beta=0.0) -> CrankThrow:
    """A :class:`CrankThrow` with its axes made unit vectors, the slider axis made exactly normal to
    the shaft (typed directions are normal to :data:`PERPENDICULAR`).

    Raises
    ------
    ValueError
        when an axis is zero, the slider axis is not normal to the shaft (|cos| of their angle above
        :data:`PERPENDICULAR`), l <= r, or a mass or length is negative.
    """
    n, s = (np.asarray(v, dtype=float) for v in (shaft_axis, slider_axis))
    if not np.hypot.reduce(n) > 0.0 or not np.hypot.reduce(s) > 0.0:
        raise ValueError("shaft_axis and slider_axis must not be [0, 0, 0]")
    n, s = n / np.hypot.reduce(n), s / np.hypot.reduce(s)
    if abs(n @ s) > PERPENDICULAR:
        raise ValueError(f"slider_axis must be normal to shaft_axis (cos of their angle {n @ s:.3g})")
    s = s - (n @ s) * n
    s = s / np.hypot.reduce(s)
    if not l > r > 0.0:
        raise ValueError(f"need rod_length l > crank_radius r > 0 (got l = {l:g} m, r = {r:g} m)")
    if min(m, l1, rho, m1, m_rot, r_rot) < 0.0:
        raise ValueError("masses, lengths and radii must be >= 0")
    return CrankThrow(np.asarray(crank_centre, dtype=float), n, s, float(crank_angle), float(r), float(l), float(m),
                      float(l1), float(rho), float(m1), float(m_rot), float(r_rot), float(beta))


@dataclass(frozen=True)
class PointMasses:
    """The mechanism as point masses at phases φ (module docstring).

    Attributes
    ----------
    masses : (P,) [kg]
    r, r1, r2 : positions from O and their first and second derivatives with respect to φ,
        (P, N, 3) [m, m/rad, m/rad²]
    """

    masses: np.ndarray
    r: np.ndarray
    r1: np.ndarray
    r2: np.ndarray


def _along(a, b, s, t):
    """a s + b t for arrays a, b (N,) and directions s, t (3,): (N, 3)."""
    return np.multiply.outer(a, s) + np.multiply.outer(b, t)


def throw_masses(throw: CrankThrow, phi) -> PointMasses:
    """Point masses of one throw at the phases ``phi`` = ωt [rad] (N,): rod halves, slider,
    rotating unbalance (module docstring)."""
    s, t, lam = throw.s, throw.t, throw.r / throw.l
    f = np.asarray(phi, dtype=float) + throw.alpha
    sn, co = np.sin(f), np.cos(f)
    c, dc, ddc = rod_angle_cosine(f, lam)
    pin = (_along(throw.r * co, throw.r * sn, s, t), _along(-throw.r * sn, throw.r * co, s, t),
           _along(-throw.r * co, -throw.r * sn, s, t))
    axis = (_along(c, -lam * sn, s, t), _along(dc, -lam * co, s, t), _along(ddc, lam * sn, s, t))
    slider = (_along(throw.r * co + throw.l * c, 0.0 * f, s, t), _along(-throw.r * sn + throw.l * dc, 0.0 * f, s, t),
              _along(-throw.r * co + throw.l * ddc, 0.0 * f, s, t))
    g = f + throw.beta
    rot = (_along(throw.r_rot * np.cos(g), throw.r_rot * np.sin(g), s, t),
           _along(-throw.r_rot * np.sin(g), throw.r_rot * np.cos(g), s, t),
           _along(-throw.r_rot * np.cos(g), -throw.r_rot * np.sin(g), s, t))
    rod = [[p + (throw.l1 + side * throw.rho) * e for p, e in zip(pin, axis)] for side in (1.0, -1.0)]
    parts = [rod[0], rod[1], slider, rot]
    masses = np.array([throw.m / 2.0, throw.m / 2.0, throw.m1, throw.m_rot])
    r, r1, r2 = (np.stack([part[k] for part in parts]) for k in range(3))
    return PointMasses(masses, r + throw.A, r1, r2)


def point_masses(throws, phi) -> PointMasses:
    """Every throw's point masses (:func:`throw_masses`), stacked."""
    each = [throw_masses(th, phi) for th in throws]
    return PointMasses(*(np.concatenate([getattr(p, k) for p in each]) for k in ("masses", "r", "r1", "r2")))


@dataclass(frozen=True)
class MechanismSamples:
    """Eqs. (1)-(4) of the module docstring at the N phases φ_j = 2πj/N of one revolution.

    Attributes
    ----------
    omega : crank speed ω [rad/s]
    M, D, S : (N, 6, 6) mass [kg, kg m, kg m²], Coriolis [kg/s, ...], stiffness [N/m, ...] about O
    f_inertia : (N, 6) inertia forcing -(m r'', m r × r'') [N, N m] (∝ ω²)
    f_weight : (N, 6) weight's moment about O of the moving masses [N m]
    """

    omega: float
    M: np.ndarray
    D: np.ndarray
    S: np.ndarray
    f_inertia: np.ndarray
    f_weight: np.ndarray


def samples_for(throws) -> int:
    """Phases per revolution that resolve the throws' kinematics to round-off: the harmonics of
    cos ψ fall as q^n, q = (1 - sqrt(1 - λ²))/λ, below 1e-16 from n = log(1e-16)/log q (80 for
    λ = 0.9, 370 for λ = 0.995); twice that, a power of two, at least :data:`SAMPLES` and at most
    :data:`MAX_SAMPLES`.

    q is computed as λ/(1 + sqrt(1 - λ²)), the same number without the cancellation that makes
    1 - sqrt(1 - λ²) exactly 0 for a crank radius of round-off size (λ < 1e-8).

    >>> from types import SimpleNamespace as Throw
    >>> samples_for([Throw(r=0.1, l=0.4)]), samples_for([Throw(r=0.995, l=1.0)]), samples_for([Throw(r=1.0 - 1e-9, l=1.0)])
    (256, 1024, 16384)
    >>> samples_for([Throw(r=1e-15, l=0.5)])
    256
    """
    lam = max(th.r / th.l for th in throws)
    q = lam / (1.0 + np.sqrt(1.0 - lam * lam))
    n = np.log(1e-16) / np.log(max(q, np.finfo(float).tiny))
    return int(min(MAX_SAMPLES, max(SAMPLES, 2.0 ** np.ceil(np.log2(2.0 * n + 2.0)))))


def mechanism_samples(throws, omega, g, N: int | None = None) -> MechanismSamples:
    """Eqs. (1)-(4) of the module docstring for the throws at speed ω [rad/s], gravity g [m/s²],
    at N phases (default :func:`samples_for`)."""
    N = samples_for(throws) if N is None else N
    pm = point_masses(throws, phases(N))
    m = np.broadcast_to(pm.masses[:, None], pm.r.shape[:2])
    mm = m[..., None, None]
    r, v, a = pm.r, omega * pm.r1, omega * omega * pm.r2
    M = mass_matrix(m, r, parallel_axis(m, r, np.zeros(3))).sum(axis=0)
    D = np.zeros(r.shape[:2] + (6, 6))
    D[..., :3, 3:] = -2.0 * mm * skews(v)
    D[..., 3:, 3:] = -2.0 * mm * (skews(r) @ skews(v))
    S = np.zeros_like(D)
    S[..., :3, 3:] = -mm * skews(a)
    S[..., 3:, 3:] = -0.5 * mm * skews(np.cross(r, a))
    S[..., 3, 3] -= m * g * r[..., 2]
    S[..., 4, 4] -= m * g * r[..., 2]
    f_inertia = -np.concatenate([m[..., None] * a, m[..., None] * np.cross(r, a)], axis=-1).sum(axis=0)
    weight = m[..., None] * g * np.stack([0.0 * r[..., 0], 0.0 * r[..., 0], 0.0 * r[..., 0], -r[..., 1], r[..., 0],
                                          0.0 * r[..., 0]], axis=-1)
    return MechanismSamples(float(omega), M, D.sum(axis=0), S.sum(axis=0), f_inertia, weight.sum(axis=0))


def mean_mass_properties(throws) -> tuple[float, np.ndarray, np.ndarray]:
    """Time-averaged mass properties of the throws' moving parts: mass [kg], mean centre of mass
    from O [m] (3,), central inertia tensor of the time-averaged mass matrix (1) [kg m²] (3, 3)."""
    M = mechanism_samples(throws, 0.0, 0.0).M.mean(axis=0)
    return centre_of_mass(M)


@dataclass(frozen=True)
class ForcingHarmonics:
    """The mechanism's forcing (4) on a fixed body at constant ω, as Re(Q_n e^{inωt}) about O.

    Attributes
    ----------
    orders : (H,) orders n = 1 ... H (the higher ones below :data:`ORDER_TOLERANCE`)
    inertial : (H, 6) complex amplitudes of the inertia forces [N, N m] (grow as ω²)
    weight : (H, 6) complex amplitudes of the moving weight's moment [N m] (independent of ω)
    """

    orders: np.ndarray
    inertial: np.ndarray
    weight: np.ndarray


def harmonics(samples) -> np.ndarray:
    """Q_n (n = 0 ... N/2) of real samples (N, ...) taken at φ_j = 2πj/N, so that the samples are
    Q_0/2 + Σ_n Re(Q_n e^{inφ}) — i.e. twice the complex Fourier coefficients."""
    return 2.0 * np.fft.rfft(samples, axis=0) / np.shape(samples)[0]


def forcing_harmonics(throws, omega, g) -> ForcingHarmonics:
    """Forcing harmonics of the throws at speed ω [rad/s], gravity g [m/s²] (Eq. (4)), the orders
    up to the last with a force or moment above :data:`ORDER_TOLERANCE` of the largest inertia
    force (moment, with the weight's) of a single point mass: the measure of what the throws would
    give if they did not balance each other."""
    sm = mechanism_samples(throws, omega, g)
    Qi, Qw = harmonics(sm.f_inertia)[1:], harmonics(sm.f_weight)[1:]
    pm = point_masses(throws, phases(len(sm.M)))
    r, a = pm.r, omega * omega * pm.r2
    force = pm.masses[:, None] * np.hypot.reduce(a, axis=-1)
    moment = pm.masses[:, None] * (np.hypot.reduce(np.cross(r, a), axis=-1) + g * np.hypot.reduce(r, axis=-1))
    size = np.abs(Qi + Qw)
    kept = (size[:, :3] > ORDER_TOLERANCE * force.max()).any(axis=1) | (size[:, 3:] > ORDER_TOLERANCE * moment.max()).any(axis=1)
    H = int(np.nonzero(kept)[0].max()) + 1 if kept.any() else 1
    return ForcingHarmonics(np.arange(1, H + 1), Qi[:H], Qw[:H])


@dataclass(frozen=True)
class CrankMechanism(MachinePart):
    """A machine's crank throws as one part of it (:class:`~foundation_calc.solvers.machines.part.MachinePart`).

    Attributes
    ----------
    throws : the :class:`CrankThrow` s, turning together at the machine's speed
    at : the machine's centre of mass from O (3,) [m]: the forcing harmonics are given as loads
        there, so that they move with the machine
    """

    throws: tuple
    at: tuple

    periodic = True

    def mass_properties(self) -> tuple[float, np.ndarray, np.ndarray]:
        """The moving parts' time-averaged mass properties (:func:`mean_mass_properties`)."""
        return mean_mass_properties(self.throws)

    def periodic_inertia(self, omega: float, g: float, N: int) -> tuple[np.ndarray, np.ndarray, np.ndarray]:
        """Eqs. (1)-(3) at N phases (:func:`mechanism_samples`)."""
        s = mechanism_samples(self.throws, omega, g, N)
        return s.M, s.D, s.S

    def gyroscopic(self, omega: float) -> np.ndarray:
        """The mean of Eq. (2) over a revolution on the throws' own sampling (:func:`samples_for`):
        -[h]× in the rotations, h = Σ m mean(r × r') the moving parts' mean angular momentum
        relative to the body [N m s]; 0 in the u-rows (r' has no mean)."""
        return mechanism_samples(self.throws, omega, 0.0).D.mean(axis=0)

    def load_rows(self, omega: float, g: float) -> list[LoadRow]:
        """The forcing harmonics Q_n (Eq. (4), :func:`forcing_harmonics`) as loads at :attr:`at`:
        per order, the real part of Q_n at phase 0 and its imaginary part at phase π/2; the
        inertia forces ``inertial``, the moving weight's moment ``weight``."""
        fh = forcing_harmonics(self.throws, omega, g)
        c = np.asarray(self.at, dtype=float)
        rows = []
        for Q, inertial in ((fh.inertial, True), (fh.weight, False)):
            for n, q in zip(fh.orders, Q):
                for part, phase in ((q.real, 0.0), (q.imag, np.pi / 2.0)):
                    if np.any(part != 0.0):
                        F, M = part[:3], part[3:] - np.cross(c, part[:3])  # the moment about the point
                        rows.append(LoadRow(int(n), F.tolist(), M.tolist(), phase, self.at, inertial, not inertial))
        return rows

    def assumption(self) -> str:
        """The sheet's phrase for crank mechanisms."""
        return ("the crank mechanisms' inertia forces, every order of the sliders' and rods' motion at the"
                " machine's speed ([KM] for one throw)")

    def sheet_text(self, omega: float) -> tuple:
        """The throws' moving mass and mean centre of mass, and how Q_n is taken."""
        m, cog, _ = self.mass_properties()
        cog = np.where(np.abs(cog) < 1e-9 * np.abs(cog).max(), 0.0, cog)  # round-off of a symmetric arrangement
        throws = f"{len(self.throws)} crank throw{'s' * (len(self.throws) != 1)}"
        return (f"{throws} ([KM]'s crank-slider mechanism, each rod as m/2 at C1 ± ρ e, the"
                " slider and any rotating mass as points): moving mass ", Number(m), " kg, mean centre of mass ",
                Triple(cog), " m, added to M as a body of the time-averaged inertia; Q_n = the inertia forces"
                " -(Σ m r'', Σ m r × r'') of the throws turning at ω on a fixed block and the moving weight's moment,"
                " Fourier harmonics of one revolution.")


__all__ = [
    "CrankMechanism",
    "CrankThrow",
    "ForcingHarmonics",
    "MechanismSamples",
    "ORDER_TOLERANCE",
    "PERPENDICULAR",
    "PointMasses",
    "SAMPLES",
    "crank_throw",
    "forcing_harmonics",
    "harmonics",
    "mean_mass_properties",
    "mechanism_samples",
    "point_masses",
    "samples_for",
    "throw_masses",
]
