"""Start-up and run-down of a linear structure under rotating loads: every resonance passed.

A speed ramp from rest to the operating speed Ω_op in a time T (or back) passes mode i with
harmonic h (speed ratio r_h) at the shaft speed Ω* = ω_i/r_h, with the sweep rate

    η = r_h |Ω'| / ω_i² = r_h Ω_op / (T ω_i²)   [-]

For each passage this module gives the closed-form peak (:func:`~.passage.passage_peak` on the
undamped mode i with its modal damping ratio ζ_i = φ_iᵀ C φ_i / (2 ω_i), φ_i mass-normalised,
the force of harmonic h projected on the mode, f(ν) = |φ_iᵀ(A_h Ω*² ν² + B_h)|, and the
physical amplitude |T_p φ_i| q_max at the point p where it is largest), Lewis' undamped peak, and
the yardstick: the peak of the time integration (:mod:`~.sweep_response`) of the whole linear
model inside the passage's window (from half-way after the previous passage to half-way to the
next). The closed form leaves out the other modes and the off-diagonal modal damping; the
integration has both.
"""

from __future__ import annotations

from dataclasses import dataclass, replace

import numpy as np
from scipy.linalg import eigh

from foundation_calc.errors import PhysicsError
from foundation_calc.solvers.numerics.passage import lewis_peak, passage_peak
from foundation_calc.solvers.numerics.sweep_response import (
    Ramp,
    RotatingLoad,
    SweepResponse,
    integrate,
    refined_peak,
    time_step,
)

#: The run continues at the final speed for this fraction of the ramp time, and at least
#: :data:`HOLD_PERIODS` periods of the lowest mode, so that a mode passed just before the end
#: (or the free vibration of a sudden start) reaches its peak inside the run [-].
HOLD_FRACTION = 0.25
HOLD_PERIODS = 20

#: A harmonic, or a mode's share of it, smaller than this fraction of the largest is not a
#: load: it is round-off of the loads' assembly (the static tilt's coupling at 2ω is 1e-20 of
#: the unbalance on a balanced platform) [-].
NEGLIGIBLE = 1e-9

#: A passage whose closed-form peak (Lewis' when undamped) is below this fraction of the steady
#: operating amplitude is not listed: the harmonic barely drives the mode [-].
INSIGNIFICANT = 1e-3

#: Samples of the steady state at the operating speed (over :data:`STEADY_PERIODS` periods of
#: its slowest harmonic) from which its peak is taken [-].
STEADY_SAMPLES = 16384
STEADY_PERIODS = 16


@dataclass(frozen=True)
class Structure:
    """A linear structure, its rotating loads and the points whose motion is measured.

    Attributes
    ----------
    mass, damping, stiffness : M [kg], C [N s/m], K [N/m] (n, n), mixed units for rotations
    load : the rotating loads (:class:`~.sweep_response.RotatingLoad`); harmonics with
        ratio 0 and no inertial part are static and left out of the motion
    points : maps from q to each point's displacement, shape (P, d, n) [m per unit of q]
    """

    mass: np.ndarray
    damping: np.ndarray
    stiffness: np.ndarray
    load: RotatingLoad
    points: np.ndarray

    @property
    def damped(self) -> bool:
        """True when any damping coefficient is non-zero."""
        return bool(np.any(self.damping != 0.0))


@dataclass(frozen=True)
class Passage:
    """One mode passed by one harmonic.

    Attributes
    ----------
    mode : index of the mode (ascending natural frequency)
    ratio : speed ratio r_h of the harmonic [-]
    natural : ω_i [rad/s]
    speed : shaft speed Ω* = ω_i / r_h at the passage [rad/s]
    time : time of the passage on the ramp [s]
    eta : sweep rate r_h |Ω'|/ω_i² [-]
    zeta : modal damping ratio [-]
    closed_form : closed-form peak of the mode's motion at the point ``point`` [m]
    lewis : undamped peak (Lewis), same point [m]
    point : index of the point where the mode's motion is largest
    integrated : peak of the mode's motion at that point in the passage's window, time
        integration (|φ_iᵀ M q(t)| |T_p φ_i|) [m]
    peak_time : time of that peak [s]
    total : peak displacement magnitude over all points in the window, every mode [m]
    window : (start, end) of the window [s]
    """

    mode: int
    ratio: float
    natural: float
    speed: float
    time: float
    eta: float
    zeta: float
    closed_form: float
    lewis: float
    point: int
    integrated: float | None
    peak_time: float | None
    total: float | None
    window: tuple | None


@dataclass(frozen=True)
class RunupResult:
    """A run-up (``direction`` +1) or run-down (-1) of ``duration`` [s] to/from ``omega`` [rad/s].

    Attributes
    ----------
    natural : undamped natural frequencies [rad/s], ascending
    passages : every passage, in the order of time
    steady_points : peak displacement magnitude |u| of each point in the steady state at
        ``omega`` [m]
    transient_points : peak displacement magnitude |u| of each point over the whole run [m]
    steady_directions, transient_directions : the same along each direction of a point (the
        rows of its map), shape (P, d) [m]
    response : the time integration's record
    damped : the structure has damping
    """

    direction: int
    duration: float
    omega: float
    natural: np.ndarray
    passages: tuple
    steady_points: np.ndarray
    transient_points: np.ndarray
    steady_directions: np.ndarray
    transient_directions: np.ndarray
    response: SweepResponse
    damped: bool

    @property
    def steady(self) -> float:
        """Largest steady displacement over the points at the operating speed [m]."""
        return float(self.steady_points.max())


def _moving(load: RotatingLoad) -> RotatingLoad:
    """The load without its static part (ratio 0, speed-independent)."""
    constant = np.where((load.ratio > 0.0)[:, None], load.constant, 0.0)
    return RotatingLoad(load.ratio, load.inertial, constant)


def steady_peaks(structure: Structure, omega) -> tuple[np.ndarray, np.ndarray, tuple]:
    """Peak displacement magnitude of each point in the steady state at ``omega`` [rad/s] [m],
    shape (P,), its peak along each direction of the point [m], shape (P, d), and the state
    (q [m], q' [m/s]) at φ = 0."""
    load = _moving(structure.load)
    Z = load.steady(structure.mass, structure.damping, structure.stiffness, omega)
    w = load.ratio * omega
    slowest = np.min(w[w > 0.0], initial=np.inf)
    span = STEADY_PERIODS * 2.0 * np.pi / slowest if np.isfinite(slowest) else 1.0
    t = np.linspace(0.0, span, STEADY_SAMPLES, endpoint=False)
    q = (Z.T @ np.exp(1j * np.outer(w, t))).real
    vectors = np.einsum("pdn,nt->pdt", structure.points, q)
    state = (Z.sum(axis=0).real, (1j * w[:, None] * Z).sum(axis=0).real)
    return np.linalg.norm(vectors, axis=1).max(axis=1), np.abs(vectors).max(axis=2), state


def modes(structure: Structure):
    """Undamped natural frequencies [rad/s] and mass-normalised mode shapes (columns).

    Raises
    ------
    PhysicsError
        when a mode has ω² ≤ 0 (or not a number): the structure has no stable rest position.
    """
    p2, shapes = eigh(structure.stiffness, structure.mass)
    if not p2.min() > 0.0:
        raise PhysicsError(
            f"the structure has no stable rest position: its lowest mode has ω² = {p2.min():.4g} rad²/s²,"
            " not positive (a stiffness matrix that is not positive definite); its start-up cannot be computed"
        )
    return np.sqrt(p2), shapes


def modal_damping(structure: Structure, natural, shapes) -> np.ndarray:
    """ζ_i = φ_iᵀ C φ_i / (2 ω_i) of the mass-normalised undamped modes [-] (the diagonal of the
    modal damping; exact for proportional damping)."""
    return np.einsum("ni,nm,mi->i", shapes, structure.damping, shapes) / (2.0 * natural)


def _windows(times, t_end) -> np.ndarray:
    """Edges of the windows of passages at ``times`` (ascending) [s]: half-way between them."""
    times = np.asarray(times, dtype=float)
    return np.concatenate([[0.0], 0.5 * (times[1:] + times[:-1]), [t_end]])


def closed_form(structure: Structure, omega, duration, direction) -> tuple[Passage, ...]:
    """Every passage of a ramp of ``duration`` [s] between rest and ``omega`` [rad/s] with its
    closed-form and Lewis peaks (one vectorised call; the integration fields are None).

    A harmonic's share of a mode at or below :data:`NEGLIGIBLE` of the largest is no passage.
    """
    load = _moving(structure.load)
    natural, shapes = modes(structure)
    zeta = modal_damping(structure, natural, shapes)
    inertial = np.einsum("ni,hn->hi", shapes, load.inertial)  # φ_iᵀ A_h
    constant = np.einsum("ni,hn->hi", shapes, load.constant)
    modal = np.abs(inertial * omega**2 + constant)
    speed = natural[None, :] / np.where(load.ratio > 0.0, load.ratio, np.inf)[:, None]
    h, i = np.nonzero((speed > 0.0) & (speed < omega) & (modal > NEGLIGIBLE * modal.max()))
    r, w, ws = load.ratio[h], natural[i], speed[h, i]
    a, b = inertial[h, i] * ws * ws, constant[h, i]
    eta = r * omega / (duration * w * w)
    peak = passage_peak(zeta[i], eta, a, b, direction).ratio
    static = np.abs(a + b) / (w * w)  # modal static deflection at the passage
    reach = np.linalg.norm(np.einsum("pdn,ni->pid", structure.points, shapes), axis=2)  # |T_p φ_i|
    point = np.argmax(reach, axis=0)[i]
    scale = static * reach[point, i]
    time = duration * (ws / omega if direction > 0 else 1.0 - ws / omega)
    passages = [
        Passage(
            mode=int(i[k]), ratio=float(r[k]), natural=float(w[k]), speed=float(ws[k]), time=float(time[k]),
            eta=float(eta[k]), zeta=float(zeta[i[k]]), closed_form=float(peak[k] * scale[k]),
            lewis=float(lewis_peak(eta[k]) * scale[k]), point=int(point[k]), integrated=None, peak_time=None,
            total=None, window=None,
        )
        for k in range(len(h))
    ]
    return tuple(sorted(passages, key=lambda p: p.time))


def run_end(duration, natural) -> float:
    """End of a run [s]: the ramp's ``duration`` [s] and the hold after it (:data:`HOLD_FRACTION`,
    :data:`HOLD_PERIODS` of the lowest of the ``natural`` frequencies [rad/s])."""
    return duration + max(HOLD_FRACTION * duration, HOLD_PERIODS * 2.0 * np.pi / float(np.min(natural)))


def runup(structure: Structure, omega, duration, direction) -> RunupResult:
    """Run the structure up from rest to ``omega`` [rad/s] in ``duration`` [s] (``direction``
    +1), or down from the steady state at ``omega`` to rest (-1); module docstring.

    The run-up starts at rest in the static equilibrium (the rotating weight at φ = 0); the run
    continues at the final speed (:func:`run_end`).
    """
    load = _moving(structure.load)
    M, C, K = structure.mass, structure.damping, structure.stiffness
    natural, shapes = modes(structure)
    steady_points, steady_directions, (q_ss, v_ss) = steady_peaks(structure, omega)
    if direction > 0:
        ramp = Ramp(0.0, omega, duration)
        q0 = np.linalg.solve(K, load.at(np.zeros(1), np.zeros(1), np.zeros(1))[:, 0])
        v0 = np.zeros_like(q0)
    else:
        ramp = Ramp(omega, 0.0, duration)
        q0, v0 = q_ss, v_ss
    t_end = run_end(duration, natural)
    step = time_step(M, K, load, omega)
    response = integrate(M, C, K, load, ramp, t_end, step, q0, v0, structure.points, shapes.T @ M)
    found = closed_form(structure, omega, duration, direction)
    edges = _windows([p.time for p in found], t_end)
    passages = []
    for k, p in enumerate(found):
        own = [f.time for f in found if f.mode == p.mode]  # the mode's coordinate sees only its passages
        lo, hi = _windows(own, t_end)[own.index(p.time) : own.index(p.time) + 2]
        modal_peak, peak_time = refined_peak(response.t, response.observed[p.mode], lo, hi)
        total, _ = refined_peak(response.t, response.magnitude, edges[k], edges[k + 1])
        reach = float(np.linalg.norm(structure.points[p.point] @ shapes[:, p.mode]))
        passages.append(
            replace(p, integrated=modal_peak * reach, peak_time=peak_time, total=total,
                    window=(float(edges[k]), float(edges[k + 1])))
        )
    shown = [p for p in passages if max(p.closed_form, p.lewis if p.zeta == 0.0 else 0.0) >= INSIGNIFICANT * steady_points.max()]
    return RunupResult(
        direction=direction, duration=float(duration), omega=float(omega), natural=natural,
        passages=tuple(shown), steady_points=steady_points, transient_points=response.point_peaks,
        steady_directions=steady_directions, transient_directions=response.direction_peaks, response=response, damped=structure.damped,
    )


__all__ = ["HOLD_FRACTION", "HOLD_PERIODS", "closed_form", "run_end", "INSIGNIFICANT", "NEGLIGIBLE", "Passage", "RunupResult", "Structure", "modal_damping", "modes", "runup", "steady_peaks"]
