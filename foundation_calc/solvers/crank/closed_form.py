"""The corrected first approximation applied to a :class:`CrankDesign`, for one design or a million.

:func:`~foundation_calc.solvers.crank.first_approximation.first_approximation` takes the paper's
symbols; this module feeds it a design (whose fields may be numpy arrays: a speed sweep, a soil
sweep, a batch of random designs) and turns its coefficients into a
:class:`~foundation_calc.solvers.crank.response.PeriodicMotion`, so that peaks, points and
errors are computed the same way for every method. Arithmetic only: no Python object per design.
"""

from __future__ import annotations

from dataclasses import replace

import numpy as np

from foundation_calc.solvers.crank.first_approximation import FirstApproximation, first_approximation
from foundation_calc.solvers.crank.mechanism import CrankDesign
from foundation_calc.solvers.crank.response import PeriodicMotion
from foundation_calc.solvers.soil.dashpots import dashpots_from_ratios


#: Why the paper's first approximation does not apply on a support coupling sway with rocking.
COUPLED_SUPPORT = ("the support couples sway with rocking (K_xφ, a pile group), and Eqs. (4.11)-(4.14) take three"
                   " uncoupled springs; the averaged operator and the exact solution take the coupling")


def require_first_approximation(design: CrankDesign) -> None:
    """Raise :class:`~foundation_calc.errors.NotApplicable` where the paper's first approximation,
    Eqs. (4.11)-(4.14), does not apply to ``design`` (fields may be arrays: any design of them):

    - on a support coupling u_x with θ_y (:attr:`CrankDesign.coupled`, a pile group): the closed
      forms take three uncoupled springs (:data:`COUPLED_SUPPORT`);
    - on a frequency-dependent support's springs at a harmonic's frequency n ω ≠ 0 (the design's
      ``soil_frequency``) where the rocking spring K_φ(nω) = c_φ I1 [N m/rad] does not exceed the
      weight's overturning moment P h = M_tot g h [N m]: the closed form's p1² = c1 S (K_φ − P h)/
      (M_tot I_c p2²) of (4.5)-(4.7) at that harmonic's soil is not positive, and the closed form
      has no meaning there. The foundation
      does not tip over for that: stability is judged on the springs at rest
      (:func:`~foundation_calc.solvers.crank.frequencies.require_stable_design`), and the steady
      state is the averaged operator's and the exact solution's, which take K(nω) as it is.

    On static springs (``soil_frequency`` 0) nothing is judged here: K_φ <= P h there is a block
    that tips over, which :func:`~foundation_calc.solvers.crank.frequencies.zero_order_frequencies`
    refuses as such.
    """
    from foundation_calc.errors import NotApplicable

    if design.coupled:
        raise NotApplicable(COUPLED_SUPPORT, field="soil")
    d = design
    fails = soft_at_harmonic(d)
    if not fails.any():
        return
    K_phi, P_h, w_soil, omega, fails = np.broadcast_arrays(d.c_phi * d.I1, d.M_tot * d.g * d.h, d.soil_frequency, d.omega,
                                                           fails)
    k = np.unravel_index(np.argmax(fails), fails.shape)
    n = w_soil[k] / omega[k]
    at, where = f"the soil's frequency ω_s = {w_soil[k]:.4g} rad/s", "ω_s"
    if abs(n - round(n)) < 1e-9:
        where = f"{'' if round(n) == 1 else round(n)}ω"
        at = f"harmonic {round(n)} (the soil at {where} = {w_soil[k]:.4g} rad/s)"
    raise NotApplicable(
        f"the paper's first approximation (4.11)-(4.14) does not apply at {at}: there the rocking spring"
        f" K_φ({where}) = c_φ·I1 = {K_phi[k]:.4g} N m/rad does not exceed the weight's overturning moment"
        f" P·h = {P_h[k]:.4g} N m, and the closed form, whose p1² (4.7) is proportional to K_φ - P·h, does not apply"
        " at this harmonic's soil; the foundation stands (stability is judged on the springs at rest), and the"
        " averaged operator and the exact solution still give the steady state", field="soil",
        hint="fcalc amplitudes and fcalc check give the averaged operator's steady state at the speed")


def soft_at_harmonic(design: CrankDesign) -> np.ndarray:
    """Where (bool, the shape of ``design``'s fields) the first approximation steps aside on a
    frequency-dependent support's springs at a harmonic's frequency (the design's ``soil_frequency``
    ≠ 0): the rocking spring K_φ = c_φ I1 [N m/rad] there does not exceed P h = M_tot g h [N m]
    (:func:`require_first_approximation`). False everywhere on static springs."""
    d = design
    K_phi, P_h, w_soil = np.broadcast_arrays(d.c_phi * d.I1, d.M_tot * d.g * d.h, np.asarray(d.soil_frequency, dtype=float))
    return (K_phi <= P_h) & (w_soil != 0.0)


def design_first_approximation(design: CrankDesign) -> FirstApproximation:
    """Coefficients of the corrected first approximation of ``design`` (fields may be arrays).

    ``g* = g`` when the motor's reaction acts on the foundation, 0 otherwise (the paper's (3.7)).
    Raises :class:`~foundation_calc.errors.NotApplicable` where the closed form does not apply
    (:func:`require_first_approximation`: a support coupling sway with rocking, a harmonic's soil
    whose rocking spring does not exceed P h), PhysicsError for a block that tips over.

    >>> from foundation_calc.solvers.crank.mechanism import lump_slider
    >>> d = CrankDesign(M=1e5, I_c=4.5e5, h=1.5, S=30.0, I1=90.0, c=4e7, c1=2.8e7, c_phi=4e7, C_x=0.0, C_z=0.0, C_phi=0.0,
    ...                 omega=np.array([31.41592653589793, 40.0]), r=0.3, l=1.2, a=2.0,
    ...                 rod=lump_slider(1.5e3, 1.2, 1.0, 0.35, 0.0), drive_on_foundation=True, g=9.81)
    >>> design_first_approximation(d).y1.real
    array([0.00040382, 0.00069391])
    """
    require_first_approximation(design)
    d, rod = design, design.rod
    g_star = d.g if d.drive_on_foundation else 0.0
    return first_approximation(
        d.M_tot, d.I_c, d.h, d.S, d.I1, d.c, d.c1, d.c_phi, d.C_x, d.C_z, d.C_phi, d.g, g_star, d.omega,
        rod.m, d.r, d.l, rod.l1, rod.rho, d.a,
    )


def first_approximation_motion(design: CrankDesign) -> tuple[PeriodicMotion, np.ndarray]:
    """The first approximation as a series (harmonics 0 ... 3) and its ``resonant`` mask.

    ``cos``, ``sin`` have shape (..., 3, 4) with the designs' shape in front; where a design is
    resonant (within the first approximation's resonant margin of a condition) they are 0.
    """
    fa = design_first_approximation(design)
    return fa.motion(design.omega), np.asarray(fa.resonant)


def varied(design: CrankDesign, *, omega=None, soil_factor=None) -> CrankDesign:
    """``design`` with its speed replaced by ``omega`` [rad/s] and/or the soil coefficients c, c1,
    c_phi multiplied by ``soil_factor`` [-] (either may be an array: one design per element).

    The base dashpots C_x, C_z, C_phi are multiplied by sqrt(``soil_factor``): the damping ratios
    of the scene (C = 2 ξ sqrt(K m)) stay what the soil report gives.
    """
    if omega is not None:
        design = replace(design, omega=np.asarray(omega, dtype=float))
    if soil_factor is not None:
        factor = np.asarray(soil_factor, dtype=float)
        root = np.sqrt(factor)
        design = replace(
            design, c=design.c * factor, c1=design.c1 * factor, c_phi=design.c_phi * factor,
            C_x=design.C_x * root, C_z=design.C_z * root, C_phi=design.C_phi * root,
        )
    return design


def with_damping(design: CrankDesign, xi_z, xi_x, xi_phi) -> CrankDesign:
    """``design`` with the base dashpots of damping ratios ξ_z, ξ_x, ξ_φ [-] of its uncoupled
    vertical, horizontal and rocking modes (:func:`~foundation_calc.solvers.soil.dashpots.dashpots_from_ratios`,
    I_0 = I_c + M_tot h²), as the scene's ``soil.damping`` gives them."""
    d = design
    b = dashpots_from_ratios(
        xi_z, xi_x, xi_phi, K_z=d.c * d.S, K_x=d.c1 * d.S, K_phi=d.c_phi * d.I1, M_tot=d.M_tot,
        I_0=d.I_c + d.M_tot * d.h * d.h,
    )
    return replace(d, C_x=b.C_x, C_z=b.C_z, C_phi=b.C_phi)


__all__ = ["COUPLED_SUPPORT", "design_first_approximation", "first_approximation_motion", "require_first_approximation",
           "soft_at_harmonic", "varied", "with_damping"]
