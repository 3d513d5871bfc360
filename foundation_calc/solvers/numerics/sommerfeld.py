"""Start-up by a motor of limited torque: the speed follows the torque against the load.

The structure of :mod:`~.runup` and the shaft, coupled (Lagrange; loads as in
:mod:`~.sweep_response`, U(φ) = Σ Re(A_h e^{i r_h φ}), V(φ) = Σ Re((i/r_h) A_h e^{i r_h φ}))::

    M q'' + C q' + K q = Ω² U(φ) - Ω' V(φ) + Σ Re(B_h e^{i r_h φ})
    J Ω' = T - V(φ)·q''                    φ' = Ω

V·q'' is the reaction torque of the structure's acceleration on the unbalances (exact for point
unbalances, whose A_h = m l r_h² × direction; for the crank mechanism the same form gives the
mean torque exactly, by the power balance, and its fluctuation approximately). J is the
inertia of everything the shaft turns, the unbalances included; substituting q'' gives
(J - V·M⁻¹V) Ω' = T - V·M⁻¹(Ω² U + B - C q' - K q). The motor gives the constant torque T until
the operating speed is reached; then its control holds the speed (the run goes on for
:data:`~.runup.HOLD_FRACTION` of the run-up time, so that the last passage's peak is in the record).

Sommerfeld: in the steady state at speed Ω the shaft needs the mean torque

    T_s(Ω) = Σ_h ½ Re(-i r_h Ω² A_h·conj(Z_h(Ω))),   Z_h = (K - r_h²Ω² M + i r_h Ω C)⁻¹ F_h(Ω)

(the power the dashpots dissipate over Ω; for one mode near its resonance (m e)² ω_n²/(4 ζ M),
the note's estimate). A motor with T below the peak of T_s near a resonance sticks there when it
approaches slowly; a fast approach can carry the shaft through on its kinetic energy, which the
integration shows.

On a frequency-dependent soil (``Structure.at_frequency``) each harmonic h moves on the springs
and dashpots at its own frequency r_h Ω, as in :mod:`~.runup`: Z_h of T_s with K(r_h Ω), C(r_h Ω),
and in the integration each harmonic's motion q_h (q = Σ q_h) with M⁻¹K and M⁻¹C interpolated
linearly in frequency between the nodes of :func:`~.runup.soil_nodes` (every mode's own frequency
among them), at the speed Ω the integration has reached.
"""

from __future__ import annotations

from dataclasses import dataclass

import numpy as np
from scipy.integrate import solve_ivp

from foundation_calc.solvers.numerics.runup import (
    HOLD_FRACTION,
    HOLD_PERIODS,
    Structure,
    _moving,
    matrices_at,
    modal_damping,
    modes,
    soil_nodes,
)
from foundation_calc.solvers.numerics.sweep_response import point_displacements

#: Speeds of the steady torque curve from rest to the operating speed, and around every
#: resonance [-].
CURVE_SAMPLES = 2000
RESONANCE_SAMPLES = 401

#: The motor run stops, stuck, after this many times the unloaded run-up time J Ω_op / T [-]:
#: a drive that needs longer than that at full torque overheats in practice.
PATIENCE = 3.0

#: Relative and absolute tolerance of the integration (DOP853) [-].
RTOL = 1e-8


@dataclass(frozen=True)
class TorqueNeed:
    """Peak of the steady torque T_s near one resonance (mode ``mode``, harmonic ``ratio``).

    Attributes
    ----------
    mode, ratio : the passage
    speed : shaft speed of the peak [rad/s]
    torque : T_s there [N m]
    """

    mode: int
    ratio: float
    speed: float
    torque: float


@dataclass(frozen=True)
class MotorRun:
    """A start-up by the motor.

    Attributes
    ----------
    torque : T [N m];  inertia : J [kg m²]
    needs : peak steady torque near each resonance passed
    reached : the shaft reached the operating speed
    time : when it did, or the end of the run [s]
    stuck_speed : mean speed over the last tenth of a stuck run [rad/s] (None when reached)
    t, speed, magnitude : the record (times [s], Ω [rad/s], largest point displacement [m])
    transient_points : peak displacement of each point [m]
    """

    torque: float
    inertia: float
    needs: tuple
    reached: bool
    time: float
    stuck_speed: float | None
    t: np.ndarray
    speed: np.ndarray
    magnitude: np.ndarray
    transient_points: np.ndarray


def steady_torque(structure: Structure, speeds) -> np.ndarray:
    """T_s(Ω) of the module docstring at ``speeds`` [rad/s] [N m]."""
    load = _moving(structure.load)
    M = structure.mass
    W = np.asarray(speeds, dtype=float)
    total = np.zeros_like(W)
    for r, A, B in zip(load.ratio, load.inertial, load.constant):
        if r <= 0.0:
            continue
        w = r * W
        C, K = matrices_at(structure, w)
        D = K - (w * w)[:, None, None] * M[None] + 1j * w[:, None, None] * C
        F = A[None] * (W * W)[:, None] + B[None]
        Z = np.linalg.solve(D, F[..., None])[..., 0]
        total += 0.5 * np.real(-1j * r * (W * W) * (Z.conj() @ A))
    return total


def torque_needs(structure: Structure, omega) -> tuple[TorqueNeed, ...]:
    """Every peak of T_s below ``omega`` [rad/s], named after the passage nearest in speed.

    T_s is sampled on :data:`CURVE_SAMPLES` speeds from rest to ``omega`` and on
    :data:`RESONANCE_SAMPLES` speeds within ±3ζ of every passage (the half-power band is ±ζ);
    a peak is a sample higher than both neighbours.
    """
    natural, shapes = modes(structure)
    zeta = modal_damping(structure, natural, shapes)
    passages = [
        (w_i / r, i, float(r))
        for r in structure.load.ratio if r > 0.0
        for i, w_i in enumerate(natural) if w_i / r < omega
    ]
    grids = [np.linspace(0.0, omega, CURVE_SAMPLES)]
    for centre, i, _ in passages:
        half = max(3.0 * zeta[i], 1e-3) * centre
        grids.append(np.linspace(max(centre - half, 0.0), min(centre + half, omega), RESONANCE_SAMPLES))
    speeds = np.unique(np.concatenate(grids))
    T = steady_torque(structure, speeds)
    peaks = np.nonzero((T[1:-1] > T[:-2]) & (T[1:-1] >= T[2:]))[0] + 1
    centres = np.array([p[0] for p in passages])
    needs = []
    for k in peaks:
        if not passages:
            break
        _, i, r = passages[int(np.argmin(np.abs(centres - speeds[k])))]
        needs.append(TorqueNeed(i, r, float(speeds[k]), float(T[k])))
    return tuple(needs)


def motor_runup(structure: Structure, omega, torque, inertia) -> MotorRun:
    """Start the structure's shaft from rest with constant torque ``torque`` [N m] and inertia
    ``inertia`` [kg m²] (everything the shaft turns) until it reaches ``omega`` [rad/s] or sticks
    (module docstring).

    Raises
    ------
    ValueError
        when the inertia is smaller than the unbalances' coupling V·M⁻¹V (it must include them).
    """
    load = _moving(structure.load)
    M = structure.mass
    n = M.shape[0]
    Minv = np.linalg.inv(M)
    ratios = load.ratio
    inv_r = np.where(ratios > 0.0, 1.0 / np.where(ratios > 0.0, ratios, 1.0), 0.0)
    natural, _ = modes(structure)
    # the harmonics in groups, each group's motion on its own matrices (module docstring)
    groups = np.eye(ratios.size) if structure.at_frequency is not None else np.ones((1, ratios.size))
    G = groups.shape[0]
    if structure.at_frequency is None:
        fixed = (Minv @ structure.damping)[None], (Minv @ structure.stiffness)[None]

        def operators(w):
            """Each group's M⁻¹C and M⁻¹K (G, n, n) at the shaft speed w [rad/s]."""
            return fixed
    else:
        nodes = soil_nodes(natural, ratios * omega)
        C_t, K_t = structure.at_frequency(nodes)
        MinvC_t, MinvK_t = Minv @ C_t, Minv @ K_t

        def operators(w):
            """Each group's M⁻¹C and M⁻¹K (G, n, n) at the shaft speed w [rad/s]."""
            at = ratios * w
            k = np.clip(np.searchsorted(nodes, at) - 1, 0, nodes.size - 2)
            part = np.clip((at - nodes[k]) / (nodes[k + 1] - nodes[k]), 0.0, 1.0)[:, None, None]
            return ((1.0 - part) * MinvC_t[k] + part * MinvC_t[k + 1], (1.0 - part) * MinvK_t[k] + part * MinvK_t[k + 1])

    def parts(phi):
        e = np.exp(1j * np.outer(ratios, np.atleast_1d(phi)))  # (H, N)
        U = np.real(load.inertial.T @ e)
        V = np.real((1j * inv_r[:, None] * load.inertial).T @ e)
        B = np.real(load.constant.T @ e)
        return U, V, B

    _, V0, _ = parts(np.linspace(0.0, 2.0 * np.pi, 64))
    coupling = np.einsum("nt,nm,mt->t", V0, Minv, V0).max()
    if not inertia > coupling:
        raise ValueError(
            f"the shaft's inertia {inertia:.6g} kg m² is below the unbalances' own {coupling:.6g} kg m²:"
            " it must include every rotating part"
        )

    A, iA, Bc = load.inertial, 1j * inv_r[:, None] * load.inertial, load.constant
    size = G * n

    def rhs(t, y, held=False):
        q, v, phi, w = y[:size].reshape(G, n), y[size : 2 * size].reshape(G, n), y[2 * size], y[2 * size + 1]
        e = np.exp(1j * ratios * phi)[:, None]
        U, V, B = groups @ (A * e).real, groups @ (iA * e).real, groups @ (Bc * e).real  # (G, n) each
        MinvC, MinvK = operators(w)
        rest = (w * w * U + B) @ Minv.T - np.einsum("gij,gj->gi", MinvC, v) - np.einsum("gij,gj->gi", MinvK, q)
        total = V.sum(axis=0)
        dw = 0.0 if held else (torque - total @ rest.sum(axis=0)) / (inertia - total @ Minv @ total)
        out = np.empty_like(y)
        out[:size], out[size : 2 * size] = v.ravel(), (rest - dw * V @ Minv.T).ravel()
        out[2 * size], out[2 * size + 1] = w, dw
        return out

    def arrived(t, y):
        return y[2 * size + 1] - omega

    arrived.terminal = True
    arrived.direction = 1
    q0 = np.linalg.solve(structure.stiffness, (groups @ Bc.real).T).T  # at rest, φ = 0, on the static springs
    t_max = PATIENCE * inertia * omega / torque
    options = dict(
        method="DOP853", rtol=RTOL,
        atol=RTOL * np.concatenate([np.abs(q0).ravel() + 1e-12, np.abs(q0).ravel() * natural.max() + 1e-12, [1e-6, 1e-6]]),
        max_step=2.0 * np.pi / (4.0 * max(natural.max(), ratios.max() * omega)),
    )
    sol = solve_ivp(rhs, (0.0, t_max), np.concatenate([q0.ravel(), np.zeros(size), [0.0, 0.0]]), events=arrived, **options)
    reached = sol.status == 1
    t, y = sol.t, sol.y
    if reached:  # the control holds the speed: run on so that a mode passed last reaches its peak
        hold = max(HOLD_FRACTION * t[-1], HOLD_PERIODS * 2.0 * np.pi / natural.min())
        held = solve_ivp(lambda s, x: rhs(s, x, True), (t[-1], t[-1] + hold), y[:, -1], **options)
        t, y = np.concatenate([t, held.t[1:]]), np.concatenate([y, held.y[:, 1:]], axis=1)
    q = y[:size].reshape(G, n, -1).sum(axis=0)
    disp = point_displacements(structure.points, q)
    tail = sol.t >= 0.9 * sol.t[-1]  # the record up to arrival or the end of patience
    return MotorRun(
        torque=float(torque), inertia=float(inertia), needs=torque_needs(structure, omega), reached=bool(reached),
        time=float(sol.t[-1]), stuck_speed=None if reached else float(sol.y[2 * size + 1][tail].mean()),
        t=t, speed=y[2 * size + 1], magnitude=disp.max(axis=0), transient_points=disp.max(axis=1),
    )


__all__ = ["MotorRun", "TorqueNeed", "motor_runup", "steady_torque", "torque_needs"]
