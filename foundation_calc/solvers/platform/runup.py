"""The vibrating platform as a linear structure for start-up and run-down.

The linearised 6-DOF equations of :mod:`~foundation_calc.solvers.platform.dynamics` with the
rotors' time-periodic coefficients averaged (M_0, K_0: rotor masses at their mean inertia, the
weight's tilt stiffness; the mean gyroscopic term, of order m l² ω against the platform's
inertia, left out), every exciter's load at its speed ratio r_j and phase, and the periodic
stiffness acting on the static tilt (-K_k q_s, as in the harmonic balance). Each harmonic vector
k of the load, at speed ratio r = Σ k_j r_j, splits into a part ∝ Ω² and a constant part (the
rotating weight), found from the loads at two speeds.

Damping, from the support (:class:`~foundation_calc.solvers.supports.isolators.Isolators`): the
dashpots β c_ij (β = 2 D/ω) as the matrix β K_springs; the hysteretic loss factor η, which has no
time-domain form, as modal damping ζ_i = η/2 on every undamped mode (it keeps the hysteretic
model's resonant peak at every mode), C = M Φ diag(η ω_i) Φᵀ M with Φ mass-normalised. So
Φ_iᵀ C Φ_i = η ω_i = η Φ_iᵀ K Φ_i/ω_i: the isolators' equivalent dashpots η K/|Ω| (Eq. (2)
there) at each mode's own frequency, on the whole mean stiffness K (the weight's tilt and the
rotors' mean terms, a small share, included).
"""

from __future__ import annotations

from dataclasses import replace

import numpy as np
from scipy.linalg import eigh

from foundation_calc.solvers.numerics.runup import Structure
from foundation_calc.solvers.numerics.sweep_response import RotatingLoad
from foundation_calc.solvers.platform.design import PlatformDesign
from foundation_calc.solvers.platform.dynamics import natural_frequencies, periodic_system
from foundation_calc.solvers.rigid_body.kinematics import point_map
from foundation_calc.solvers.platform.verification import PlatformModel, build, product_corners

#: Two speed ratios are one harmonic when they differ by less than this [-].
RATIO_TOLERANCE = 1e-9


def _loads(design: PlatformDesign, model: PlatformModel, scale: float):
    """Speed ratios r and complex coefficients c of Re(c e^{i r φ}) at ``scale`` × ω [N, N m]."""
    platform, rotors = build(replace(design, omega=design.omega * scale), model)
    system = periodic_system(platform, rotors)
    static = np.linalg.solve(system.springs, system.static_load)
    keys = np.concatenate([system.force_keys, system.keys[1:]])
    values = np.concatenate([system.force, -(system.stiff[1:] @ static)])
    ratios = keys @ (system.speeds / (design.omega * scale))
    return ratios, values, system


def structure(design: PlatformDesign, model: PlatformModel) -> tuple[Structure, tuple[str, ...]]:
    """The platform of ``design`` and ``model`` as a :class:`Structure`, and the names of its
    points: the centre of mass and the eight corners of the product box (module docstring).

    Raises
    ------
    PhysicsError
        when the platform has no stable rest position to start from (a squared natural frequency
        not positive: it tips over under its weight, or a direction has no spring), from
        :func:`~foundation_calc.solvers.platform.dynamics.natural_frequencies`.
    """
    ratios, at_1, system = _loads(design, model, 1.0)
    platform, rotors = build(design, model)
    natural_frequencies(platform, rotors, system)  # raises before the modal damping's sqrt(p²)
    _, at_2, _ = _loads(design, model, 2.0)
    w2 = design.omega**2
    inertial_k = (at_2 - at_1) / (3.0 * w2)  # F(s ω) = s² ω² A + B
    constant_k = at_1 - w2 * inertial_k
    distinct: list[float] = []
    for r in np.abs(ratios):
        if not any(abs(r - d) <= RATIO_TOLERANCE * max(1.0, r) for d in distinct):
            distinct.append(float(r))
    distinct.sort()
    A = np.zeros((len(distinct), 6), dtype=complex)
    B = np.zeros_like(A)
    for r, a, b in zip(ratios, inertial_k, constant_k):
        if r < -RATIO_TOLERANCE:
            continue  # the conjugate of the key with ratio -r
        h = int(np.argmin([abs(r - d) for d in distinct]))
        factor = 2.0 if r > RATIO_TOLERANCE else 1.0
        A[h] += factor * a
        B[h] += factor * b
    M = system.mass[0].real
    K = system.stiff[0].real
    M, K = 0.5 * (M + M.T), 0.5 * (K + K.T)
    isolators = platform.isolators
    C = isolators.beta * isolators.springs
    if isolators.eta > 0.0:
        p2, shapes = eigh(K, M)
        MP = M @ shapes
        C = C + MP @ np.diag(isolators.eta * np.sqrt(p2)) @ MP.T
    r_c = np.asarray((design.xi, design.eta, design.zeta))
    places = [r_c, *product_corners(design.A, design.B, model.product_height)]
    names = ("centre of mass",) + tuple(
        f"product corner ({x:g}, {y:g}, {z:g}) m" for x, y, z in product_corners(design.A, design.B, model.product_height)
    )
    points = np.array([point_map(p) for p in places])
    load = RotatingLoad(np.array(distinct), A, B)
    return Structure(mass=M, damping=C, stiffness=K, load=load, points=points), names


def unbalance_inertia(design: PlatformDesign, model: PlatformModel) -> float:
    """Σ_j J_j (ω_j/ω)², J_j = m_j l_j² the inertia each exciter's motor carries
    (:meth:`~foundation_calc.solvers.machines.exciter.UnbalancedExciter.carried_inertia`), referred
    to the main shaft by its speed ratio [kg m²]."""
    _, rotors = build(design, model)
    return sum(r.part.carried_inertia(r.speed) * (r.speed / design.omega) ** 2 for r in rotors)


__all__ = ["structure", "unbalance_inertia"]
