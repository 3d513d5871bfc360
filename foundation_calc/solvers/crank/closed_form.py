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


def design_first_approximation(design: CrankDesign) -> FirstApproximation:
    """Coefficients of the corrected first approximation of ``design`` (fields may be arrays).

    ``g* = g`` when the motor's reaction acts on the foundation, 0 otherwise (the paper's (3.7)).

    >>> from foundation_calc.solvers.crank.mechanism import lump_slider
    >>> d = CrankDesign(M=1e5, I_c=4.5e5, h=1.5, S=30.0, I1=90.0, c=4e7, c1=2.8e7, c_phi=4e7, C_x=0.0, C_z=0.0, C_phi=0.0,
    ...                 omega=np.array([31.41592653589793, 40.0]), r=0.3, l=1.2, a=2.0,
    ...                 rod=lump_slider(1.5e3, 1.2, 1.0, 0.35, 0.0), drive_on_foundation=True, g=9.81)
    >>> design_first_approximation(d).y1.real
    array([0.00040382, 0.00069391])
    """
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


__all__ = ["design_first_approximation", "first_approximation_motion", "varied", "with_damping"]
