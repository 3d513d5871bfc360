"""Natural frequencies of a block foundation on Barkan's soil springs, with a crank mechanism.

Source: Krichever & Makarov [1]_, Eqs. (4.5)-(4.7) (printed ρ1, ρ2 there are p1, p2), with the
gravity term of (3.4) taken as destabilising (-P h, not +P h), and the paper's rocking spring c I1
generalised to c_φ I1 (the paper takes c_φ = c; Barkan and SP 26 take c_φ ≈ 2 c).

Zero-order operator (foundation with the whole mass M_tot = M + m, rocking inertia I_c)::

    k0² = c S / M_tot
    a0 = c1 S / M_tot,   b0 = c1 h S / M_tot,   a1 = c1 h S / I_c
    b1 = (c1 h² S + c_φ I1 - P h) / I_c,        P = M_tot g
    p1², p2² = (a0 + b1)/2 ∓ sqrt(((a0 - b1)/2)² + a1 b0)                         (4.7)

The foundation is stable in rocking only when a0 b1 - a1 b0 = c1 S (c_φ I1 - P h)/(M_tot I_c) > 0,
that is, when the soil's rocking stiffness c_φ I1 exceeds the overturning moment of the weight P h.

Every function here uses arithmetic operators only, so its arguments may be floats or numpy arrays.

References
----------
.. [1] M.F. Krichever, S.M. Makarov, "Application of the small-parameter method to the problem
   of forced vibrations of the foundation of a crank-slider mechanism".
"""

from __future__ import annotations

from dataclasses import dataclass

from foundation_calc.errors import PhysicsError
from foundation_calc.solvers.crank.mechanism import (
    mean_cos_psi,
    mean_position_v,
    mean_square_distance,
)


@dataclass(frozen=True)
class NaturalFrequencies:
    """Natural circular frequencies [rad/s]: vertical k0 and coupled sliding-rocking p1 < p2."""

    k0: object
    p1: object
    p2: object


def _any(mask) -> bool:
    """True when a boolean (or any element of a boolean array) is true."""
    return bool(mask.any()) if hasattr(mask, "any") else bool(mask)


def rocking_stability_margin(c_phi, I1, P, h, K_x=1.0, K_xphi=0.0):
    """Relative reserve of the soil's rocking stiffness over the overturning moment, c_φ I1/(P h) - 1.

    Positive: stable. Zero or negative: the foundation tips over (p1² <= 0).

    A support coupling sway with rocking at O (a pile group's K_xφ) gives the static stiffness in
    (u_x, θ_y) [[K_x, K_xφ], [K_xφ, c_φ I1 - P h]] ((3.4) with the weight's tilt -P h), positive
    definite iff K_x > 0 and its Schur complement c_φ I1 - P h - K_xφ²/K_x > 0: the margin is then
    (c_φ I1 - K_xφ²/K_x)/(P h) - 1, the uncoupled one for K_xφ = 0.

    Parameters
    ----------
    c_phi : coefficient of elastic non-uniform compression (rocking) [N/m³]
    I1 : second moment of the base area [m⁴]
    P : total weight M_tot g [N]
    h : height of the centre of mass above the base [m]
    K_x : the support's sway spring at O [N/m] (> 0; read only with K_xphi)
    K_xphi : the support's sway-rocking coupling at O [N/rad] (0 uncoupled)

    >>> rocking_stability_margin(c_phi=4.0e7, I1=90.0, P=1.0e6, h=1.5)
    2399.0
    """
    return coupled_rocking_stiffness(c_phi * I1, K_x, K_xphi) / (P * h) - 1.0


def coupled_rocking_stiffness(K_phi, K_x, K_xphi):
    """K_φ - K_xφ²/K_x [N m/rad]: the rocking stiffness at O left when u_x, coupled to θ_y by
    K_xφ [N/rad], settles statically on its spring K_x [N/m] (the Schur complement of the
    support's static sway-rocking stiffness); K_φ itself for K_xφ = 0."""
    return K_phi - K_xphi * K_xphi / K_x


def stability_margin_formula(coupled: bool, minus: str = "-") -> str:
    """The formula of :func:`rocking_stability_margin` as a calc sheet names it: with the
    sway-rocking coupling's reduction when ``coupled``, ``minus`` the sign printed."""
    rocking = f"(K_φ {minus} K_xφ²/K_x)" if coupled else "c_φ·I1"
    return f"{rocking}/(P·h) {minus} 1"


def stability_arguments(design) -> tuple:
    """The arguments of :func:`rocking_stability_margin` of a design
    (:class:`~foundation_calc.solvers.crank.mechanism.CrankDesign`): c_φ, I1, P = M_tot g, h,
    K_x = c1 S and its support's K_xφ."""
    d = design
    return d.c_phi, d.I1, d.M_tot * d.g, d.h, d.c1 * d.S, d.K_xphi


def require_stable_rocking(c_phi, I1, P, h, K_x=1.0, K_xphi=0.0):
    """Raise :class:`PhysicsError` when ``rocking_stability_margin`` is not positive."""
    margin, coupled = rocking_stability_margin(c_phi, I1, P, h, K_x, K_xphi), _any(K_xphi != 0.0)
    if _any(margin <= 0.0):
        raise PhysicsError(
            "the foundation is unstable in rocking: the soil's rocking stiffness"
            f" {'reduced by the sway coupling, c_φ·I1 - K_xφ²/K_x,' if coupled else 'c_φ·I1'} does not"
            f" exceed the overturning moment of the weight P·h ({stability_margin_formula(coupled)} ="
            f" {_first(margin):.4g})",
            field="foundation.base_second_moment",
            hint="increase soil.c_phi (default soil.c_z) or the base's second moment I1, or lower the"
            " centre of mass h",
        )
    return margin


def require_stable_design(design):
    """:func:`require_stable_rocking` of a design (:func:`stability_arguments`) whose springs are
    static (its ``soil_frequency`` 0); None, judging nothing, for one on a frequency-dependent
    support's springs at ω ≠ 0. Stability in rocking (paper (3.4)) is a statement about the static
    equilibrium; the springs at ω are the real part of an impedance (a pile group's K_x(ω) may dip
    near zero, making K_xφ²/K_x explode), and its scene judged the springs at rest
    (:meth:`~foundation_calc.scenes.crank.CrankScene.in_plane`)."""
    if _any(design.soil_frequency != 0.0):
        return None
    return require_stable_rocking(*stability_arguments(design))


def _positive(x):
    """max(x, 0) of a float or an array: a determinant of the springs that is not positive (a
    tipping block's, on springs at ω ≠ 0) gives p1 = 0, not a NaN."""
    return (x + abs(x)) / 2.0


def _first(values):
    """The smallest element of an array, or the value itself."""
    return float(values.min()) if hasattr(values, "min") else float(values)


def zero_order_frequencies(M_tot, I_c, h, S, I1, c, c1, c_phi, g, at_rest: bool = True) -> NaturalFrequencies:
    """k0, p1, p2 of the zero-order operator, Eqs. (4.5)-(4.7) of [1]_ (c I1 → c_φ I1).

    The smaller root is taken as p1² = (a0 b1 - a1 b0)/p2², and a0 b1 - a1 b0 is evaluated as
    c1 S (c_φ I1 - P h)/(M_tot I_c), so neither root suffers cancellation.

    Parameters
    ----------
    M_tot : total mass M + m (block, rod and slider) [kg]
    I_c : moment of inertia of the block about its centre of mass [kg m²]
    h : height of the centre of mass above the base [m]
    S : base area [m²]
    I1 : second moment of the base area about its centroidal axis [m⁴]
    c : coefficient of elastic uniform compression [N/m³]
    c1 : coefficient of elastic uniform shear [N/m³]
    c_phi : coefficient of elastic non-uniform compression (rocking spring c_φ I1) [N/m³]
    g : acceleration of gravity [m/s²]
    at_rest : the springs are static (the default): stability in rocking is judged on them. False
        for a frequency-dependent support's springs at ω ≠ 0 (the real part of an impedance, its
        scene judged at rest): where c_φ I1 <= P h there, p1² <= 0 and p1 is 0, no positive
        frequency, as a root search ω = p(K(ω)) takes it.

    Raises
    ------
    PhysicsError
        when the foundation is unstable in rocking (c_φ I1 <= M_tot g h) on static springs.

    >>> f = zero_order_frequencies(1.015e5, 4.5e5, 1.5, 30.0, 90.0, 4.0e7, 2.8e7, 4.0e7, 9.81)
    >>> round(f.k0, 6), round(f.p1, 6), round(f.p2, 6)
    (108.732056, 63.428974, 128.254857)
    """
    P = M_tot * g
    if at_rest:
        require_stable_rocking(c_phi, I1, P, h)
    a0 = c1 * S / M_tot
    b0 = c1 * h * S / M_tot
    a1 = c1 * h * S / I_c
    b1 = (c1 * h * h * S + c_phi * I1 - P * h) / I_c
    det = c1 * S * (c_phi * I1 - P * h) / (M_tot * I_c)
    p2_sq = (a0 + b1) / 2.0 + (((a0 - b1) / 2.0) ** 2 + a1 * b0) ** 0.5
    return NaturalFrequencies(k0=(c * S / M_tot) ** 0.5, p1=(_positive(det) / p2_sq) ** 0.5, p2=p2_sq**0.5)


def averaged_inertia_frequencies(M_tot, I_c, h, S, I1, c, c1, c_phi, g, m, a, r, l, l1, rho, at_rest: bool = True) -> NaturalFrequencies:
    """k0, p1, p2 with the mechanism's inertia averaged over one revolution.

    The zero-order operator of [1]_ gives the rod's mass to x and y but no rocking inertia, so
    the true sliding-rocking resonances lie O(μ) away from (4.7). Averaging the exact mass matrix
    of block + rod over φ (its periodic part has zero mean) gives

        M_xx = M_tot,  M_xθ = m (a - l' ⟨cos ψ⟩),  M_θθ = I_c + m (ρ² + ⟨|p|²⟩)

    with ⟨|p|²⟩ from :func:`~foundation_calc.solvers.crank.mechanism.mean_square_distance`;
    the vertical mass stays M_tot exactly, so k0 is unchanged. p² are the roots of
    det(K - p² M) = 0 with K the soil stiffness matrix of (3.2)-(3.4).

    Parameters (besides those of :func:`zero_order_frequencies`)
    ----------
    m : rod mass, slider lumped in [kg]
    a : signed distance from the crank axis A to C, positive when A is above C [m]
    r : crank radius [m]
    l : rod length [m]
    l1 : l', rod centre of mass to crank pin (slider lumped in) [m]
    rho : rod radius of gyration about its centre of mass (slider lumped in) [m]
    at_rest : as :func:`zero_order_frequencies`

    >>> f = averaged_inertia_frequencies(1.015e5, 4.5e5, 1.5, 30.0, 90.0, 4.0e7, 2.8e7, 4.0e7, 9.81,
    ...                                  1.5e3, 2.0, 0.3, 1.2, 1.0, 0.35)
    >>> round(f.p1, 6), round(f.p2, 6)
    (63.172362, 128.522152)
    """
    P = M_tot * g
    if at_rest:
        require_stable_rocking(c_phi, I1, P, h)
    mean_cos = mean_cos_psi(r / l)
    m12 = -m * mean_position_v(a, l1, mean_cos)
    m22 = I_c + m * (rho * rho + mean_square_distance(a, r, l, l1, mean_cos))
    k11 = c1 * S
    k12 = -c1 * h * S
    k22 = c1 * h * h * S + c_phi * I1 - P * h
    det_m = M_tot * m22 - m12 * m12
    det_k = c1 * S * (c_phi * I1 - P * h)
    trace = k11 * m22 + k22 * M_tot - 2.0 * k12 * m12
    disc = trace * trace - 4.0 * det_m * det_k
    disc = (disc + abs(disc)) / 2.0  # rounding can make it -0 when p1 ≈ p2
    p2_sq = (trace + disc**0.5) / (2.0 * det_m)
    return NaturalFrequencies(
        k0=(c * S / M_tot) ** 0.5, p1=(_positive(det_k) / (det_m * p2_sq)) ** 0.5, p2=p2_sq**0.5
    )
