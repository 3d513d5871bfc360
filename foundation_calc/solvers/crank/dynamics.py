"""Exact equations of motion of a block foundation carrying a crank-slider mechanism.

Source: Krichever & Makarov [1]_, Eqs. (3.1)-(3.7), re-derived by Lagrange's equations (the
derivation is checked against sympy in the tests). Conventions (docs/crank-foundation.md, "The model"): x horizontal,
y vertical positive downward, origin at the static equilibrium of C; θ turns +x toward +y,
R(θ) = [[cos θ, -sin θ], [sin θ, cos θ]], J = [[0, -1], [1, 0]]. Body axes (u, v) through C.
The rod's centre of mass C1 sits at body position p(φ), φ = ωt::

    p = (-(l''/l) r sin φ,  -a + r cos φ + l' cos ψ),   sin ψ = λ sin φ

Soil (Barkan, as in (3.2)-(3.4), linear, weight term destabilising; the paper's c I1 generalised
to c_φ I1), with base dashpots C_x, C_z, C_φ in parallel with the springs::

    Q_x = -c1 S (x - hθ) - C_x (x' - hθ'),   Q_y = -c S y - C_z y',   P = M_tot g
    Q_θ = -h Q_x - (c_φ I1 - P h) θ - C_φ θ'

and a support's sway-rocking coupling K_xφ, C_xφ at O (a pile group; 0 for Barkan's springs) adds
-K_xφ θ - C_xφ θ' to the base's force Q_x and -K_xφ u - C_xφ u' to its moment, u = x - hθ the sway at O.

Motor on the foundation (the crank's rheonomic constraint is ideal)::

    M_tot X'' + m R[(θ'' J - θ'² I) p + 2 θ' J p' + p''] = Q_X
    (I_c + m ρ² + m |p|²) θ'' - m ρ² ψ'' + 2 m θ' p·p' + m p × p'' + m p × R^T(X'' - g e_y) = Q_θ

Motor off the foundation: the foundation no longer takes the drive's reaction, so the torque
τ = (M' - A) × F_r that the motor applies to the crank is added to Q_θ; F_r is the force of the
crank pin on the rod, from the rod's equations of motion with a frictionless guide::

    N = [(M' - C1) × m (a_C1 - g e_y) - m ρ² (θ'' - ψ'')] / (l cos ψ),   F_r = m (a_C1 - g e_y) - N n

(n: the guide's normal, the body's u axis). Everything here is holomorphic in (q, q', q''), so
complex-step derivatives are exact to round-off.

References
----------
.. [1] M.F. Krichever, S.M. Makarov, "Application of the small-parameter method to the problem
   of forced vibrations of the foundation of a crank-slider mechanism".
"""

from __future__ import annotations

from dataclasses import dataclass

import numpy as np

from foundation_calc.solvers.crank.mechanism import CrankDesign, rod_angle_cosine


@dataclass(frozen=True)
class MechanismMotion:
    """Body-frame kinematics of the mechanism at phases φ (time derivatives, ω included).

    Attributes (arrays over φ)
    ----------
    p, dp, ddp : position of C1 relative to C and its first two time derivatives [m, m/s, m/s²],
        shape (2, N) as (u, v)
    crank_pin : M' - A, shape (2, N) [m]
    cos_psi : cos ψ [-]
    ddpsi : ψ'' [rad/s²]; the rod's absolute angular acceleration is θ'' - ψ''
    """

    p: np.ndarray
    dp: np.ndarray
    ddp: np.ndarray
    crank_pin: np.ndarray
    cos_psi: np.ndarray
    ddpsi: np.ndarray


def mechanism_motion(phi, omega, r, l, l1) -> MechanismMotion:
    """Kinematics of the crank-slider at crank angles ``phi`` [rad] (speed ω [rad/s]).

    With c = cos ψ = sqrt(1 - λ² sin² φ) (exact derivatives, checked with sympy)::

        d(cos ψ)/dφ = -λ² sin φ cos φ / c,   d²(cos ψ)/dφ² = -λ² (cos 2φ + λ² sin⁴ φ) / c³
        d²ψ/dφ² = -λ (1 - λ²) sin φ / c³
    """
    lam = r / l
    l2 = l - l1
    s, co = np.sin(phi), np.cos(phi)
    c, dc, ddc = rod_angle_cosine(phi, lam)
    w, w2 = omega, omega * omega
    p = np.array([-(l2 / l) * r * s, r * co + l1 * c])  # v without the constant -a
    dp = w * np.array([-(l2 / l) * r * co, -r * s + l1 * dc])
    ddp = w2 * np.array([(l2 / l) * r * s, -r * co + l1 * ddc])
    return MechanismMotion(
        p=p,
        dp=dp,
        ddp=ddp,
        crank_pin=np.array([-r * s, r * co]),
        cos_psi=c,
        ddpsi=-w2 * lam * (1.0 - lam * lam) * s / c**3,
    )


def _cross(a, b):
    """2-D cross product a_u b_v - a_v b_u over the first axis."""
    return a[0] * b[1] - a[1] * b[0]


def _kinematics(design: CrankDesign, motion: MechanismMotion, q, dq, ddq):
    """C1 from C (p), C1's acceleration relative to C (rel) and X'' - g e_y (ext), in body axes."""
    th, dth, ddth = q[2], dq[2], ddq[2]
    ct, st = np.cos(th), np.sin(th)
    p = motion.p + np.array([[0.0], [-design.a]])
    rel = np.array(
        [
            -ddth * p[1] - dth * dth * p[0] - 2.0 * dth * motion.dp[1] + motion.ddp[0],
            ddth * p[0] - dth * dth * p[1] + 2.0 * dth * motion.dp[0] + motion.ddp[1],
        ]
    )
    # X'' - g e_y in body axes: R^T (x'', y'' - g)
    ax, ay = ddq[0], ddq[1] - design.g
    ext = np.array([ct * ax + st * ay, -st * ax + ct * ay])
    return p, rel, ext


def residual(design: CrankDesign, motion: MechanismMotion, q, dq, ddq):
    """Residual of the exact equations of motion (module docstring) at each phase [N, N, N m].

    ``q``, ``dq``, ``ddq``: (x, y, θ) and their time derivatives, arrays of shape (3, N) matching
    ``motion`` (complex values allowed). Zero where the motion satisfies the equations.
    """
    d, rod = design, design.rod
    m, rho2 = rod.m, rod.rho**2
    x, y, th = q
    dth, ddth = dq[2], ddq[2]
    ct, st = np.cos(th), np.sin(th)
    p, rel, ext = _kinematics(d, motion, q, dq, ddq)
    P = d.M_tot * d.g
    dx, dy = dq[0], dq[1]
    u, du = x - d.h * th, dx - d.h * dth  # the base's sway u_x at O
    soil_x = -d.c1 * d.S * u - d.C_x * du - d.K_xphi * th - d.C_xphi * dth
    soil_y = -d.c * d.S * y - d.C_z * dy
    soil_th = -d.h * soil_x - (d.c_phi * d.I1 - P * d.h) * th - d.C_phi * dth - d.K_xphi * u - d.C_xphi * du
    res_x = d.M_tot * ddq[0] + m * (ct * rel[0] - st * rel[1]) - soil_x
    res_y = d.M_tot * ddq[1] + m * (st * rel[0] + ct * rel[1]) - soil_y
    res_th = (
        (d.I_c + m * rho2 + m * (p[0] * p[0] + p[1] * p[1])) * ddth
        - m * rho2 * motion.ddpsi
        + 2.0 * m * dth * (p[0] * motion.dp[0] + p[1] * motion.dp[1])
        + m * _cross(p, motion.ddp)
        + m * _cross(p, ext)
        - soil_th
    )
    res = np.array([res_x, res_y, res_th])
    return res if d.drive_on_foundation else res + drive_reaction(d, motion, q, dq, ddq)


def drive_reaction(design: CrankDesign, motion: MechanismMotion, q, dq, ddq):
    """What the motor off the foundation adds to the residual [N, N, N m], (3, N): -τ in the θ
    row (:func:`drive_torque`), 0 in x and y (module docstring)."""
    p, rel, ext = _kinematics(design, motion, q, dq, ddq)
    tau = drive_torque(design, motion, p, rel + ext, ddq[2])
    return np.array([0.0 * tau, 0.0 * tau, -tau])


def drive_torque(design: CrankDesign, motion: MechanismMotion, p, a_minus_g, ddth):
    """τ = (M' - A) × F_r [N m]: torque of the motor on the crank (module docstring).

    ``a_minus_g``: a_C1 - g e_y in body axes; ``p``: C1 relative to C in body axes.
    """
    rod = design.rod
    m = rod.m
    pin = motion.crank_pin + np.array([[0.0], [-design.a]])  # M' relative to C
    arm = pin - p  # M' - C1
    force = m * a_minus_g
    N = (_cross(arm, force) - m * rod.rho**2 * (ddth - motion.ddpsi)) / (design.l * motion.cos_psi)
    F_r = force - N * np.array([np.ones_like(motion.cos_psi), np.zeros_like(motion.cos_psi)])
    return _cross(motion.crank_pin, F_r)


__all__ = ["MechanismMotion", "drive_reaction", "drive_torque", "mechanism_motion", "residual"]
