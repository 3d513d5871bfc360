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

The modes are the structure's own (an eigen-solve of K, M), or the scene's as its resonance check
found them (:class:`Modes`): a passage, its numbering and its damping ratio are then the very modes
``fcalc resonance`` reports.

**A soil whose springs and dashpots depend on frequency** (Gazetas', Pais & Kausel's impedance;
``Structure.at_frequency``) has no single K and C for a time integration. Every harmonic h is
integrated on the springs and dashpots at its own forcing frequency r_h Ω(t), updated as the speed
changes (the equations are linear: harmonic by harmonic the solutions add), tabulated every
:data:`SOIL_SPACING` of the frequency and at every mode's own frequency p_j and every harmonic's
operating frequency r_h Ω_op exactly (:func:`soil_nodes`), each step taking the node nearest its
forcing frequency. This is the frequency-domain meaning of an impedance carried
into a slow sweep: harmonic h forces the structure at r_h Ω(t), and in a sweep as slow as a
machine's start-up (η = Ω'/p² of 10⁻⁴ to 10⁻², the passage lasting about 1/sqrt(η) periods) the
forced motion at each instant is close to the steady state at that frequency, the quasi-stationary
picture of a slow passage (Lewis 1932; Markert & Seidler 2001). Two things follow exactly: at a passage of mode j the springs
are those at p_j, so the mode stands where the resonance check puts it, p_j = p_j(K(p_j)), with
its damping ratio there; and at the operating speed the steady state is ``fcalc amplitudes``', each
order n on K(nω), C(nω). What the scheme approximates is the free vibration a passage leaves
behind: it rings at the mode's own frequency but on the springs at the forcing frequency, which
moves away from p_j at the sweep rate; with the radiation damping of these soils (ζ of 0.03 to
0.6) the ringing is gone within a few periods, while the frequency has moved by ζ p_j at most.
The alternative, modal superposition with each mode on its own K(p_j), C(p_j) (the approximate
modal analysis of structures on springs and dashpots, Roesset, Whitman & Dobry, J. Struct. Div.
ASCE 99(3), 1973), gets the ringing right but not the steady state: on docs/runup.md's two-machine
block on Gazetas' soil its steady peaks at the operating speeds differ from the frequency-domain
solution by 1-8 % and, along one direction, by up to 23 % (its modes, each from a different K,
are not orthogonal).
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
    Schedule,
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

#: Spacing of the frequencies at which a frequency-dependent soil's springs and dashpots are
#: tabulated for the time integration (:func:`soil_nodes`), as a fraction of the lowest natural
#: frequency below it and of the frequency itself above [-]: a step's springs are those at a
#: frequency within half of it from its forcing frequency (halving it moves the run-up's peaks by
#: less than 1e-3, tests/test_runup_soil.py).
SOIL_SPACING = 0.01

#: Samples of the steady state at the operating speed (over :data:`STEADY_PERIODS` periods of
#: its slowest harmonic) from which its peak is taken [-].
STEADY_SAMPLES = 16384
STEADY_PERIODS = 16


@dataclass(frozen=True)
class Modes:
    """Undamped modes of a structure as its scene's resonance check finds them.

    Attributes
    ----------
    natural : natural frequencies p [rad/s], ascending
    shapes : mode shapes, mass-normalised (φᵀ M φ = 1), as columns (n, m)
    damping : modal damping ratios ζ = φᵀ C φ / (2 p) [-] (on a frequency-dependent soil, C at
        the mode's own frequency)
    names : what each mode is called where the resonance check names it (the dominant motion of
        a block's mode, k0, p1 or p2 of a crank foundation's)
    """

    natural: np.ndarray
    shapes: np.ndarray
    damping: np.ndarray
    names: tuple[str, ...]


@dataclass(frozen=True)
class Structure:
    """A linear structure, its rotating loads and the points whose motion is measured.

    Attributes
    ----------
    mass, damping, stiffness : M [kg], C [N s/m], K [N/m] (n, n), mixed units for rotations; on a
        frequency-dependent soil C and K at rest (ω = 0)
    load : the rotating loads (:class:`~.sweep_response.RotatingLoad`); harmonics with
        ratio 0 and no inertial part are static and left out of the motion
    points : maps from q to each point's displacement, shape (P, d, n) [m per unit of q]
    modes : the scene's modes (:class:`Modes`), or None: the eigen-solve of K, M
    at_frequency : on a frequency-dependent soil, ω -> (C(ω), K(ω)): the damping and stiffness
        with the soil's springs and dashpots at the frequencies ω [rad/s] (any shape; each
        result ω.shape + (n, n)); None: C and K at every frequency
    """

    mass: np.ndarray
    damping: np.ndarray
    stiffness: np.ndarray
    load: RotatingLoad
    points: np.ndarray
    modes: Modes | None = None
    at_frequency: object = None

    @property
    def damped(self) -> bool:
        """True when any damping coefficient is non-zero, at rest or, on a frequency-dependent
        support, at a mode's own frequency (:attr:`Modes.damping`: a hysteretic loss factor's
        dashpots η K/|ω| vanish from C at rest only); of C its symmetric part (a skew-symmetric
        gyroscopic coupling dissipates nothing)."""
        modal = self.at_frequency is not None and self.modes is not None and np.any(self.modes.damping > 0.0)
        return bool(np.any(self.damping + np.swapaxes(self.damping, -1, -2) != 0.0) or modal)


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
    names : what the scene's resonance check calls each mode (:attr:`Modes.names`; empty when
        the structure's own modes are used)
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
    names: tuple[str, ...]
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


def steady_peaks(structure: Structure, omega) -> tuple[np.ndarray, np.ndarray]:
    """Peak displacement magnitude of each point in the steady state at ``omega`` [rad/s] [m],
    shape (P,), and its peak along each direction of the point [m], shape (P, d); each harmonic
    on the damping and stiffness at its own frequency (:func:`matrices_at`)."""
    load = _moving(structure.load)
    Z = _steady(structure, load, omega)
    w = load.ratio * omega
    slowest = np.min(w[w > 0.0], initial=np.inf)
    span = STEADY_PERIODS * 2.0 * np.pi / slowest if np.isfinite(slowest) else 1.0
    t = np.linspace(0.0, span, STEADY_SAMPLES, endpoint=False)
    q = (Z.T @ np.exp(1j * np.outer(w, t))).real
    vectors = np.einsum("pdn,nt->pdt", structure.points, q)
    return np.linalg.norm(vectors, axis=1).max(axis=1), np.abs(vectors).max(axis=2)


def matrices_at(structure: Structure, omega):
    """(C, K) of the structure at the frequencies ``omega`` [rad/s] (any shape), each
    omega.shape + (n, n): on a frequency-dependent soil the springs and dashpots there."""
    w = np.asarray(omega, dtype=float)
    if structure.at_frequency is not None:
        return structure.at_frequency(w)
    shape = w.shape + structure.stiffness.shape
    return np.broadcast_to(structure.damping, shape), np.broadcast_to(structure.stiffness, shape)


def _steady(structure: Structure, load: RotatingLoad, omega) -> np.ndarray:
    """Complex amplitudes (H, n) of each harmonic's steady state at the speed ``omega`` [rad/s],
    each on the damping and stiffness at its own frequency."""
    C, K = matrices_at(structure, load.ratio * omega)
    return load.steady(structure.mass, C, K, omega)


def modes(structure: Structure):
    """Undamped natural frequencies [rad/s] and mass-normalised mode shapes (columns): the
    scene's (``structure.modes``), or those of K, M.

    Raises
    ------
    PhysicsError
        when a mode has ω² ≤ 0 (or not a number): the structure has no stable rest position.
    """
    if structure.modes is not None:
        return structure.modes.natural, structure.modes.shapes
    p2, shapes = eigh(structure.stiffness, structure.mass)
    if not p2.min() > 0.0:
        raise PhysicsError(
            f"the structure has no stable rest position: its lowest mode has ω² = {p2.min():.4g} rad²/s²,"
            " not positive (a stiffness matrix that is not positive definite); its start-up cannot be computed"
        )
    return np.sqrt(p2), shapes


def modal_damping(structure: Structure, natural, shapes) -> np.ndarray:
    """ζ_i = φ_iᵀ C φ_i / (2 ω_i) of the mass-normalised undamped modes [-] (the diagonal of the
    modal damping; exact for proportional damping): the scene's modes' own when given."""
    if structure.modes is not None:
        return structure.modes.damping
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


def soil_nodes(natural, tops) -> np.ndarray:
    """Frequencies [rad/s], ascending, at which a frequency-dependent soil is tabulated for a run
    whose harmonics reach the frequencies ``tops`` [rad/s]: from rest every :data:`SOIL_SPACING`
    of the lowest of the ``natural`` frequencies p_1 [rad/s], above p_1 every :data:`SOIL_SPACING`
    of the frequency itself (the impedances are functions of a0 = ω B'/V_s, smooth in a0: a
    relative step moves them by a like fraction at most), and exactly each natural frequency and
    each top (module docstring)."""
    tops = np.asarray(tops, dtype=float)
    top, lowest = float(tops.max(initial=0.0)), float(np.min(natural))
    uniform = np.arange(int(np.ceil(1.0 / SOIL_SPACING))) * SOIL_SPACING * lowest
    geometric = lowest * (1.0 + SOIL_SPACING) ** np.arange(int(np.ceil(np.log(max(top, lowest) / lowest) / np.log1p(SOIL_SPACING))))
    grid = np.concatenate([uniform, geometric])
    return np.unique(np.concatenate([grid[grid < top], np.asarray(natural, dtype=float), tops, [0.0]]))


def _schedule(structure: Structure, load: RotatingLoad, ramp: Ramp, omega, natural, step) -> Schedule | None:
    """None for a structure whose C and K do not depend on frequency; else every harmonic in a
    group of its own, each step on the node (:func:`soil_nodes`) nearest the harmonic's forcing
    frequency at the middle of the step (module docstring)."""
    if structure.at_frequency is None:
        return None
    nodes = soil_nodes(natural, load.ratio * omega)
    C, K = structure.at_frequency(nodes)
    edges = 0.5 * (nodes[1:] + nodes[:-1])

    def index(g, t):
        speed, _, _ = ramp.speed(np.maximum(np.asarray(t, dtype=float) - 0.5 * step, 0.0))
        return np.searchsorted(edges, load.ratio[g] * speed)

    return Schedule(tuple(np.array([h]) for h in range(load.ratio.size)), tuple(zip(C, K)), index)


def runup(structure: Structure, omega, duration, direction) -> RunupResult:
    """Run the structure up from rest to ``omega`` [rad/s] in ``duration`` [s] (``direction``
    +1), or down from the steady state at ``omega`` to rest (-1); module docstring.

    The run-up starts at rest in the static equilibrium (the rotating weight at φ = 0); the run
    continues at the final speed (:func:`run_end`). On a frequency-dependent soil each harmonic is
    integrated on the springs and dashpots at its own forcing frequency (module docstring).
    """
    load = _moving(structure.load)
    M = structure.mass
    natural, shapes = modes(structure)
    steady_points, steady_directions = steady_peaks(structure, omega)
    ramp = Ramp(0.0, omega, duration) if direction > 0 else Ramp(omega, 0.0, duration)
    t_end = run_end(duration, natural)
    tops = load.ratio * omega
    step = time_step(M, matrices_at(structure, np.concatenate([[0.0], tops]))[1], load, omega)
    schedule = _schedule(structure, load, ramp, omega, natural, step)
    if direction > 0:  # at rest in the static equilibrium, each harmonic's Re(B_h) on the static springs
        q0 = np.linalg.solve(structure.stiffness, load.constant.real.T).T
        v0 = np.zeros_like(q0)
    else:  # the steady state at the operating speed
        Z = _steady(structure, load, omega)
        q0, v0 = Z.real, (1j * tops[:, None] * Z).real
    if schedule is None:  # one group: the harmonics together
        q0, v0 = q0.sum(axis=0), v0.sum(axis=0)
    response = integrate(M, structure.damping, structure.stiffness, load, ramp, t_end, step, q0, v0, structure.points,
                         shapes.T @ M, schedule)
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
        names=() if structure.modes is None else structure.modes.names,
        passages=tuple(shown), steady_points=steady_points, transient_points=response.point_peaks,
        steady_directions=steady_directions, transient_directions=response.direction_peaks, response=response, damped=structure.damped,
    )


__all__ = ["HOLD_FRACTION", "HOLD_PERIODS", "INSIGNIFICANT", "NEGLIGIBLE", "SOIL_SPACING", "Modes", "Passage", "RunupResult",
           "Structure", "closed_form", "matrices_at", "modal_damping", "modes", "run_end", "runup", "soil_nodes", "steady_peaks"]
