"""A batch of crank-foundation candidates in array operations: each candidate block's mass,
moment of inertia and centre of mass with the machine (paper (3.1)-(3.3)), its support's springs
and dashpots at O read in the plane, the averaged-operator steady state and the peaks and RMS
values of the motion of C and the points.

What the candidates are (the block's dimensions, the positions moved with the block, the support
under each) is handed in by the caller: this module reads no scene file. Judging the numbers
against limits and the resonance rule is the checks' job
(:mod:`~foundation_calc.checks.design.crank`).
"""

from __future__ import annotations

from dataclasses import replace

import numpy as np


class CandidateDesigns:
    """The scene's design for each block (L, B, H) of a batch: ``at(soil_frequency)`` is a
    :class:`~foundation_calc.solvers.crank.mechanism.CrankDesign` whose block and support fields
    are arrays over the batch (``soil_frequency`` [rad/s] a scalar or one per candidate).

    ``base``: the scene's own design (the mechanism and speed); ``density`` of the block
    [kg/m³]; ``machine``: (mass [kg], centre-of-mass height above the base (N,) [m], moment of
    inertia [kg m²]) or None; ``axis_height``: the crank axis's height above the base (N,) [m];
    ``points``: each point's (x, z) from the base's centre (N,) each [m] — the positions already
    moved with each candidate's block. The points are kept as ``points_u``, ``points_H``:
    (points, N) [m] from the new C; the crank axis as ``a`` [m] from C.

    ``support_on(masses)``: what carries the blocks, asked with the plane's body (M_tot,
    I_0 = I_c + M_tot h², :func:`~foundation_calc.solvers.supports.plane_footing.plane_masses`);
    read in the plane (:func:`~foundation_calc.solvers.supports.plane_footing.plane`: a pile
    group's sway-rocking K_xφ, C_xφ taken, any other coupling of the plane's motions a
    PhysicsError naming it).
    """

    def __init__(self, base, L, B, H, density, machine, axis_height, points, support_on):
        from foundation_calc.solvers.crank.block import block_with_machine
        from foundation_calc.solvers.supports.plane_footing import plane_masses

        self.base = base
        self.L, self.B, self.H = L, B, H
        self.machine_height = None if machine is None else machine[1]
        self.props = p = block_with_machine(L, B, H, density, *((0.0, 0.0, 0.0) if machine is None else machine))
        self.S, self.I1 = L * B, B * L**3 / 12.0
        self.M_tot = p.M + self.base.rod.m
        self.a = axis_height - p.h
        shape = (len(points), *np.shape(L))
        self.points_u = np.array([np.broadcast_to(u, np.shape(L)) for u, _ in points]).reshape(shape)
        self.points_H = np.array([z - p.h for _, z in points]).reshape(shape)
        self.support = support_on(plane_masses(self.M_tot, p.I_c + self.M_tot * p.h**2))
        self._last = None  # (frequency, springs at O): :meth:`in_plane`'s last

    def in_plane(self, soil_frequency=0.0) -> tuple:
        """((K_x, K_z, K_φ), (C_x, C_z, C_φ), (K_xφ, C_xφ)) at O of every candidate's support at
        ``soil_frequency`` [rad/s] (class docstring), (N,) each: the plane's springs and dashpots and
        the support's sway-rocking coupling (a pile group's; 0 on an uncoupled support), as
        ``fcalc check`` reads them (:meth:`~foundation_calc.scenes.crank.CrankScene.design`). The
        last frequency's are kept: the designs and the stability at one frequency ask the support
        once."""
        from foundation_calc.solvers.supports.plane_footing import plane

        asked = np.array(soil_frequency, dtype=float)
        if self._last is None or self._last[0].shape != asked.shape or not np.array_equal(self._last[0], asked):
            self._last = asked, plane(self.support.impedance(soil_frequency), self.support.label)
        return self._last[1]

    def at(self, soil_frequency=0.0):
        """The candidates' designs on the support at ``soil_frequency`` [rad/s], its springs as
        c = K_z/S, c1 = K_x/S, c_φ = K_φ/I1 of each candidate's base (as ``scene.design``), with the
        support's K_xφ, C_xφ (:attr:`~foundation_calc.solvers.crank.mechanism.CrankDesign.coupled`
        when it couples sway with rocking)."""
        (K_x, K_z, K_phi), (C_x, C_z, C_phi), (K_xphi, C_xphi) = self.in_plane(soil_frequency)
        p, ones = self.props, np.ones_like(self.L)
        return replace(self.base, M=p.M, I_c=p.I_c, h=p.h, S=self.S, I1=self.I1, c=K_z / self.S * ones,
                       c1=K_x / self.S * ones, c_phi=K_phi / self.I1 * ones, C_x=C_x * ones, C_z=C_z * ones,
                       C_phi=C_phi * ones, a=self.a, K_xphi=K_xphi * ones, C_xphi=C_xphi * ones,
                       soil_frequency=soil_frequency)

    def rocking_stable(self, soil_frequency=0.0) -> np.ndarray:
        """The candidates whose rocking stiffness at O on the support's springs at ``soil_frequency``
        [rad/s], net of its sway-rocking coupling, K_φ - K_xφ²/K_x
        (:func:`~foundation_calc.solvers.crank.frequencies.coupled_rocking_stiffness`; K_φ
        uncoupled), exceeds the weight's overturning moment P h (paper (3.4))."""
        from foundation_calc.solvers.constants import GRAVITY
        from foundation_calc.solvers.crank.frequencies import coupled_rocking_stiffness

        (K_x, _, K_phi), _, (K_xphi, _) = self.in_plane(soil_frequency)
        return coupled_rocking_stiffness(K_phi, K_x, K_xphi) > self.M_tot * GRAVITY * self.props.h

    def stable(self) -> np.ndarray:
        """The candidates ``fcalc check`` does not refuse as tipping over: those that stand
        (:meth:`rocking_stable`) on the support's springs at rest (ω = 0), as the scene judges them
        (:meth:`~foundation_calc.scenes.crank.CrankScene.in_plane`). Stability is a statement about
        the static equilibrium: a frequency-dependent support's springs at a harmonic or at a mode's
        own frequency are the real part of an impedance (a pile group's K_x(ω) may dip near zero,
        making K_xφ²/K_x explode), on which the steady state is solved and the modes are found, but
        no stability judged."""
        return self.rocking_stable(0.0)




def steady_state(designs, d0, block, mech, harmonics, decoupled):
    """The averaged-operator steady state of every candidate (harmonics 0 ... ``harmonics``) and
    its resonant mask; ``designs``: :class:`CandidateDesigns`, ``d0`` their designs at rest; ``mech``: the
    mechanism's M̄, C̄, K̄, F_c, F_s at their ``a``; ``block``: M, C, K of the blocks on the static springs; ``decoupled``: y
    apart from x and θ (:attr:`~foundation_calc.solvers.crank.batch.MechanismOperator.decoupled`); a
    frequency-dependent soil takes harmonic n on the springs at n ω."""
    from foundation_calc.solvers.crank.averaged import block_matrices
    from foundation_calc.solvers.crank.batch import harmonic_response, resonant_blocks
    from foundation_calc.solvers.crank.response import PeriodicMotion

    M_m, C_m, K_m, fc, fs = mech
    omega = d0.omega
    if designs.support.frequency_dependent:
        parts = [block_matrices(designs.at(n * omega)) for n in range(harmonics + 1)]
        M, C, K = (np.stack([p[i] for p in parts], axis=-3) for i in range(3))
        resonant, _ = resonant_blocks(M_m + M[:, 1], C[:, 1], K_m + K[:, 1], omega)
        M_m, C_m, K_m = (x[:, None] for x in (M_m, C_m, K_m))
        Z = harmonic_response(M_m + M, C_m + C, K_m + K, omega, fc, fs, harmonics, per_harmonic=True, decoupled=decoupled)
    else:
        M, C, K = block
        resonant, _ = resonant_blocks(M_m + M, C, K_m + K, omega)
        Z = harmonic_response(M_m + M, C_m + C, K_m + K, omega, fc, fs, harmonics, decoupled=decoupled)
    Z = np.where(resonant[:, None, None], 0.0, Z)
    return PeriodicMotion(omega=omega, cos=Z.real, sin=-Z.imag), resonant


#: The time derivative of each limited quantity.
_ORDER = {"displacement": 0, "velocity": 1, "acceleration": 2}

#: Phases a revolution at which a series is sampled for a lower bound of its peak.
_BOUND_PHASES = 16


def statistics(wanted, limited, series, omega) -> dict[str, np.ndarray]:
    """quantity -> (N, points, 2) values of each wanted statistic of the ``series`` (C's, the
    points'): RMS values by Parseval; peaks to round-off (:func:`~foundation_calc.solvers.numerics.trig_series.peak`)
    where they can decide the check, elsewhere their upper bound Σ|c_n|.

    A peak decides nothing when its upper bound over its limit is below the largest lower bound
    (the series sampled at :data:`_BOUND_PHASES` phases) over its limit of any row of the same
    candidate: it is not the largest ratio, and if it exceeds its limit so does that row. The
    largest ratio, every row's pass or fail that can change the verdict, and what governs are
    then those of the exact peaks."""
    from foundation_calc.solvers.numerics.trig_series import basis, derivative, peak, rms

    parts = {q: [derivative(c, s, omega, _ORDER[q.removesuffix("_rms")]) for c, s in series] for q in wanted}
    found = {q: np.concatenate([rms(c, s) for c, s in parts[q]], axis=1) for q in wanted if q.endswith("_rms")}
    bounds = {}
    for q in wanted - set(found):
        low, up = [], []
        for c, s in parts[q]:
            cb, sb = basis(c.shape[-1] - 1, 2.0 * np.pi * np.arange(_BOUND_PHASES) / _BOUND_PHASES)
            low.append(np.abs(c @ cb.T + s @ sb.T).max(axis=-1))
            up.append(np.hypot(c, s).sum(axis=-1))
        bounds[q] = (np.concatenate(low, axis=1), np.concatenate(up, axis=1))
    best = np.zeros(next(iter(parts.values()))[0][0].shape[0])
    for q, limit in limited.items():
        best = np.maximum(best, (found[q] if q in found else bounds[q][0]).max(axis=(1, 2)) / limit)
    for q, (_, up) in bounds.items():
        need = up / limited[q] >= best[:, None, None]
        values, start = up.copy(), 0
        for c, s in parts[q]:
            part = need[:, start : start + c.shape[1]]
            values[:, start : start + c.shape[1]][part] = peak(c[part], s[part]) if part.any() else []
            start += c.shape[1]
        found[q] = values
    return found


__all__ = ["CandidateDesigns", "statistics", "steady_state"]
