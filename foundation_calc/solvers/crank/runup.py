"""The crank foundation as a linear structure for start-up and run-down.

The exact equations linearised about rest with their coefficients averaged over a revolution
(M̄, C̄ of :func:`~foundation_calc.solvers.crank.averaged.averaged_operator`; C̄ holds the base dashpots),
the stiffness of the block on its soil with the weight's -P h (Krichever & Makarov (3.2)-(3.4),
:func:`~foundation_calc.solvers.crank.averaged.block_matrices`): the operator whose natural
frequencies the resonance check reports as the averaged-inertia k0, p1, p2, so that the start-up
passes those very modes (:func:`crank_modes`). The exact linearisation's K̄ also holds the rod's
weight at its mean height above C, -m g (a - l'⟨cos ψ⟩) in K̄_θθ, which that operator leaves out:
a relative 10⁻⁶ on the frequencies of the shipped scenes; it still decides whether the rest
position is stable (:func:`require_stable_rest`).

The mechanism's exact forcing -r0(φ) is expanded in harmonics n = 0 ... N of the crank angle
φ(t) = ∫Ω dt. Each harmonic splits into a part ∝ Ω² (the mechanism's inertia) and a
constant part (the weight of rod and slider), found from the forcing at ω and 2ω; the split is
checked at 3ω. Points: the centre of mass C and the scene's points, displaced (x + H θ, y + u θ)
to first order (docs/crank-foundation.md, "The model").

A machine given by its vendor's loads (``[[loads]]``, :mod:`~foundation_calc.solvers.crank.loads`)
adds each load F cos(nφ + φ_F) as an unbalanced force: its amplitude grows as (Ω/ω)², the vendor's
F being the amplitude at the operating speed ω. Without a mechanism the structure is the rigid
block of :func:`~foundation_calc.solvers.crank.loads.matrices`.

On a frequency-dependent soil the structure carries the springs and dashpots at any frequency
(``Structure.at_frequency``, built by the caller from the scene) and each mode its own frequency
(:func:`crank_modes`); :mod:`~foundation_calc.solvers.numerics.runup` integrates each harmonic on
the soil at its own frequency.

A support that couples sway with rocking (a pile group: K_xφ, C_xφ of u_x with θ_y at O) enters
K and C whole (:func:`~foundation_calc.solvers.crank.averaged.block_matrices`), at rest and at every frequency, as the block's run-up
takes its support's 6 × 6 springs and dashpots at each harmonic's frequency
(:mod:`~foundation_calc.solvers.block.runup`), never the static springs: a pile group always
depends on frequency (its dynamic interaction), and on the shipped crank_on_piles.toml its
springs at the modes' own frequencies move k0 and p2 by 11 % and 37 % from the static springs'.
The modes are then the plane model's eigen-solve, named by rank as ``fcalc resonance`` names them.
"""

from __future__ import annotations

from dataclasses import replace

import numpy as np

from foundation_calc.errors import ConvergenceError, PhysicsError
from foundation_calc.solvers.crank.averaged import averaged_operator, block_matrices, mechanism_operator
from foundation_calc.solvers.crank.dynamics import mechanism_motion
from foundation_calc.solvers.crank.frequencies import require_stable_design, require_stable_rocking
from foundation_calc.solvers.crank.loads import HarmonicLoads, RigidBlock, matrices
from foundation_calc.solvers.crank.mechanism import CrankDesign
from foundation_calc.solvers.crank.frequencies import NaturalFrequencies
from foundation_calc.solvers.numerics.runup import NEGLIGIBLE, Modes, Structure, matrices_at
from foundation_calc.solvers.numerics.sweep_response import RotatingLoad
from foundation_calc.solvers.numerics.trig_series import analyse, phases

#: Samples of a revolution and the harmonics of the forcing kept (the slider's series falls
#: by about λ per order; harmonics under :data:`NEGLIGIBLE` of the largest are dropped) [-].
SAMPLES = 128
HARMONICS = 8

#: Largest relative mismatch of the split F(Ω) = Ω² A + B at 3ω before it counts as a bug [-].
SPLIT_TOLERANCE = 1e-9


def _forcing(design: CrankDesign, scale: float) -> np.ndarray:
    """Complex harmonics c_n of -r0 = Σ Re(c_n e^{inφ}) at ``scale`` × ω, shape (N + 1, 3)
    (:func:`~foundation_calc.solvers.crank.averaged.mechanism_operator`'s forcing)."""
    *_, fc, fs = mechanism_operator(replace(design, omega=design.omega * scale))
    return (fc[:, : HARMONICS + 1] - 1j * fs[:, : HARMONICS + 1]).T


def structure(design: CrankDesign, horizontal, height) -> Structure:
    """The foundation of ``design`` as a :class:`Structure`; points: C, then those at
    ``horizontal`` [m] from C and ``height`` [m] above it.

    Raises
    ------
    PhysicsError
        when the foundation is unstable in rocking, alone or with the rod's weight
        (:func:`require_stable_rest`).
    """
    require_stable_design(design)
    M, C, exact, *_ = averaged_operator(design)
    require_stable_rest(exact, design.a)
    K = block_matrices(design)[2]
    if design.C_x == 0.0 and design.C_z == 0.0 and design.C_phi == 0.0 and design.C_xphi == 0.0:
        C = np.zeros_like(C)  # the mechanism's mean velocity terms vanish: what is left is round-off
    f1, f2, f3 = (_forcing(design, s) for s in (1.0, 2.0, 3.0))
    w2 = design.omega**2
    A = (f2 - f1) / (3.0 * w2)
    B = f1 - w2 * A
    mismatch = np.abs(9.0 * w2 * A + B - f3).max()
    if mismatch > SPLIT_TOLERANCE * np.abs(f3).max():
        raise ConvergenceError(f"the crank's forcing is not Ω² A + B (mismatch {mismatch:.3g} at 3ω)")
    size = np.abs(A * w2).max(axis=1) + np.abs(B).max(axis=1)
    keep = size > NEGLIGIBLE * size.max()
    keep[0] = True
    n = np.arange(HARMONICS + 1)[keep]
    load = RotatingLoad(n.astype(float), A[keep], B[keep])
    return Structure(mass=M, damping=C, stiffness=K, load=load, points=_point_maps(horizontal, height))


def require_stable_rest(K, a) -> float:
    """The rocking stiffness left once the base slides, K̄θθ - K̄xθ K̄θx / K̄xx [N m/rad], of the
    averaged stiffness ``K`` (order x, y, θ) of a crank axis at ``a`` [m] from the centre of mass.

    It is c_φ I1 - P h (:func:`~foundation_calc.solvers.crank.frequencies.require_stable_rocking`)
    with the mean overturning moment of the rod's weight added; when it is not positive the rest
    position is unstable, the start-up has no oscillation to follow (ω² < 0 for a mode).

    Raises
    ------
    PhysicsError
        when that stiffness is not positive, naming the crank axis's height.
    """
    rocking = float(K[2, 2] - K[0, 2] * K[2, 0] / K[0, 0]) if K[0, 0] > 0.0 else float(K[2, 2])
    if not rocking > 0.0:
        raise PhysicsError(
            "the foundation with its mechanism is unstable in rocking about rest: the rocking stiffness"
            " left once the base slides (c_φ·I1 - P·h with the mean overturning moment of the rod's weight,"
            f" crank axis {a:.4g} m from the centre of mass) is {rocking:.4g} N m/rad, not positive;"
            " its start-up cannot be computed",
            field="mechanism.crank_axis_to_cog",
            hint="bring the crank axis nearer the centre of mass, lighten the rod (mechanism.rod_mass), or"
            " stiffen the base in rocking (soil.c_phi, foundation.base_second_moment)",
        )
    return rocking


def _point_maps(horizontal, height) -> np.ndarray:
    """Maps from (x, y, θ) to the displacement (x + H θ, y + u θ) of C and of the points at
    ``horizontal`` u [m] from C and ``height`` H [m] above it, shape (P, 2, 3)."""
    u = np.concatenate([[0.0], np.asarray(horizontal, dtype=float)])
    H = np.concatenate([[0.0], np.asarray(height, dtype=float)])
    return np.array([[[1.0, 0.0, h], [0.0, 1.0, x]] for x, h in zip(u, H)])


def vendor_load(loads: HarmonicLoads, omega: float) -> RotatingLoad:
    """The vendor's loads as unbalanced forces ∝ Ω² (module docstring): one harmonic per order n,
    inertial part Σ Q e^{iφ_F} / ω² [N s², N m s²] (loads of one order summed)."""
    orders = np.unique(loads.order)
    generalized = loads.generalized()
    inertial = np.array([generalized[loads.order == n].sum(axis=0) for n in orders]) / omega**2
    return RotatingLoad(orders.astype(float), inertial, np.zeros_like(inertial))


def with_vendor_loads(built: Structure, loads: HarmonicLoads, omega: float) -> Structure:
    """``built`` with the vendor's loads (:func:`vendor_load`) added to its mechanism's."""
    extra = vendor_load(loads, omega)
    load = RotatingLoad(
        np.concatenate([built.load.ratio, extra.ratio]),
        np.concatenate([built.load.inertial, extra.inertial]),
        np.concatenate([built.load.constant, extra.constant]),
    )
    return replace(built, load=load)


def block_structure(block: RigidBlock, loads: HarmonicLoads, omega: float, horizontal, height) -> Structure:
    """A machine given by its loads alone: the rigid block on its soil (M, C, K of
    :func:`~foundation_calc.solvers.crank.loads.matrices`) under :func:`vendor_load`.

    Raises
    ------
    PhysicsError
        when the foundation is unstable in rocking.
    """
    require_stable_rocking(block.K_phi, 1.0, block.M_tot * block.g, block.h)
    M, K, C = matrices(block)
    return Structure(mass=M, damping=C, stiffness=K, load=vendor_load(loads, omega), points=_point_maps(horizontal, height))


#: The crank foundation's modes in the order of :class:`~foundation_calc.solvers.crank.frequencies.NaturalFrequencies`.
MODE_NAMES = ("k0", "p1", "p2")


def crank_modes(built: Structure, frequencies: NaturalFrequencies) -> Modes:
    """The modes k0, p1, p2 of ``built`` at the natural frequencies ``frequencies`` [rad/s] its
    scene's resonance check reports, ascending: mode j's shape is the eigenvector of
    K(p_j) v = p² M v whose p is nearest p_j, with K, C at p_j on a frequency-dependent support,
    and its damping ratio φᵀ C(p_j) φ / (2 p_j). p_j is a root of that very problem (ω = p(K(ω)),
    to the fixed point's tolerance; on static springs p_j of K, M̄ itself), so the shape is the
    mode's whichever way the check names it: by its dominant motion on the paper's three springs
    (:func:`~foundation_calc.solvers.crank.averaged.mode_order`), by its rank on a support that
    couples sway with rocking (as the resonance check names a pile group's modes)."""
    from scipy.linalg import eigh

    p = np.array([float(getattr(frequencies, name)) for name in MODE_NAMES])
    C, K = matrices_at(built, p)
    shapes = np.empty((3, 3))
    for j in range(3):
        squared, v = eigh(K[j], built.mass)
        shapes[:, j] = v[:, np.argmin(np.abs(squared - p[j] ** 2))]
    zeta = np.einsum("nj,jnm,mj->j", shapes, C, shapes) / (2.0 * p)
    order = np.argsort(p)
    return Modes(p[order], shapes[:, order], zeta[order], tuple(MODE_NAMES[j] for j in order))


def mechanism_inertia(design: CrankDesign) -> float:
    """Mean inertia of the rod (slider lumped in) referred to the crank shaft [kg m²]:
    ⟨m |∂p/∂φ|² + m ρ² (∂ψ/∂φ)²⟩ over a revolution, ∂ψ/∂φ = λ cos φ / cos ψ (twice its mean
    kinetic energy at unit speed)."""
    phi = phases(SAMPLES)
    motion = mechanism_motion(phi, 1.0, design.r, design.l, design.rod.l1)
    rod = design.rod
    dpsi = design.lam * np.cos(phi) / motion.cos_psi
    return float(np.mean(rod.m * (motion.dp**2).sum(axis=0) + rod.m * rod.rho**2 * dpsi**2))


__all__ = ["MODE_NAMES", "block_structure", "crank_modes", "mechanism_inertia", "require_stable_rest", "structure",
           "vendor_load", "with_vendor_loads"]
