"""Closed form with the mechanism's time-averaged operator and the exact zero-order forcing.

An improvement of the paper's first approximation ([1]_, Eqs. (4.11)-(4.14)) at the same cost
class (microseconds to a millisecond): the exact equations of
:mod:`~foundation_calc.solvers.crank.dynamics` are linearised about the static position,

    r(q, q', q'', t) ≈ r0(t) + K(t) q + C(t) q' + M(t) q'',

their coefficient matrices are averaged over one revolution (M̄ is the mass matrix of block and
mechanism with the rod's mean position, M̄_xθ = m (a - l'⟨cos ψ⟩), M̄_θθ = I_c + m (ρ² + ⟨|p|²⟩);
K̄ adds the rod weight's mean moment to the soil's stiffness), and the exact forcing -r0(t) is
expanded in a Fourier series by sampling one revolution (this brings the exact slider motion,
e.g. the vertical 4ω harmonic, and, with the motor off the foundation, the drive's reaction).
Each harmonic then solves (K̄ + i nω C̄ - n²ω² M̄) Z_n = F_n. C̄ holds the soil's base dashpots
(and the mechanism's mean gyroscopic terms), so a damped design has a finite response at and
through every resonance; only a mode the dashpots leave undamped is "resonant" (no steady state)
when a harmonic falls on it.

What is left out is the periodic part of K, C, M acting on the response. It couples the
harmonics (for instance the vertical 2ω motion drives rocking at ω through the rod's horizontal
offset, m p_u y''), so the error is still of first order in μ at some speeds, but with a
coefficient 20 to 10⁴ times smaller than the first approximation's in the cases tested; near
2ω = p1, p2 the exact solution also has x and θ harmonics at 2ω that no linear form gives.

References
----------
.. [1] M.F. Krichever, S.M. Makarov, "Application of the small-parameter method to the problem
   of forced vibrations of the foundation of a crank-slider mechanism".
"""

from __future__ import annotations

from dataclasses import dataclass, replace

import numpy as np

from foundation_calc.errors import PhysicsError
from foundation_calc.solvers.crank.dynamics import drive_reaction, mechanism_motion, residual
from foundation_calc.solvers.crank.first_approximation import RESONANT_MARGIN, UNDAMPED_RATIO
from foundation_calc.solvers.crank.frequencies import NaturalFrequencies, require_stable_design
from foundation_calc.solvers.crank.mechanism import CrankDesign
from foundation_calc.solvers.crank.plane import in_plane, plane_foundation, plane_samples, plane_throw, sway_rocking
from foundation_calc.solvers.crank.response import PeriodicMotion
from foundation_calc.solvers.numerics.trig_series import analyse, phases

#: Samples of one revolution for the forcing's Fourier coefficients, and the harmonics kept.
FORCING_SAMPLES = 256
FORCING_HARMONICS = 48

_STEP = 1e-30  # complex step: the derivative is exact to round-off for any step this small


@dataclass(frozen=True)
class LinearOperator:
    """Linearisation of the exact equations about q = 0 on a grid of phases.

    ``mass``, ``damping``, ``stiffness``: shape (3, 3, N), entry [i, j] = ∂r_i/∂(q_j'', q_j', q_j);
    ``forcing``: -r0, shape (3, N) [N, N, N m]; rows and columns in the order x, y, θ.
    """

    mass: np.ndarray
    damping: np.ndarray
    stiffness: np.ndarray
    forcing: np.ndarray


def linearise(design: CrankDesign, phi, equations=residual) -> LinearOperator:
    """Linearise the exact equations (or a part of them, ``equations``: a function like
    :func:`~foundation_calc.solvers.crank.dynamics.residual`) about the static position at phases
    ``phi`` (complex step)."""
    motion = mechanism_motion(phi, design.omega, design.r, design.l, design.rod.l1)
    zero = np.zeros((3, np.size(phi)))
    r0 = equations(design, motion, zero, zero, zero)
    blocks = []
    for order in range(3):
        columns = []
        for j in range(3):
            state = [zero.astype(complex) for _ in range(3)]
            state[order][j] = 1j * _STEP
            columns.append(equations(design, motion, *state).imag / _STEP)
        blocks.append(np.stack(columns, axis=1))
    return LinearOperator(mass=blocks[2], damping=blocks[1], stiffness=blocks[0], forcing=-r0.real)


@dataclass(frozen=True)
class AveragedResponse:
    """Steady state of the averaged operator.

    Attributes
    ----------
    motion : x, y, θ series up to :data:`FORCING_HARMONICS` (0 where resonant)
    natural : natural frequencies of (K̄, M̄) [rad/s], ascending (3,)
    margin : smallest relative distance |nω - p|/p over harmonics and modes [-]
    nearest : (n, index of the mode in ``natural``) of that smallest margin
    resonant : margin < :data:`~foundation_calc.solvers.crank.first_approximation.RESONANT_MARGIN`
        and that mode's damping ratio below :data:`UNDAMPED_RATIO`
    damping_ratios : modal damping ratio of each mode from the base dashpots [-] (3,)
    mass, damping, stiffness : the averaged matrices (3, 3), order x, y, θ
    """

    motion: PeriodicMotion
    natural: np.ndarray
    margin: float
    nearest: tuple[int, int]
    resonant: bool
    damping_ratios: np.ndarray
    mass: np.ndarray
    damping: np.ndarray
    stiffness: np.ndarray


#: Smallest ratio of the lowest to the highest natural frequency that double precision resolves
#: [-]: the eigenvalues ω² then span 14 decades, the limit of 16-digit arithmetic with margin.
RESOLVED_FREQUENCY_RATIO = 1e-7

#: Scene fields whose values set the natural frequencies, named when they cannot be resolved.
FREQUENCY_FIELDS = (
    "foundation.mass, foundation.moment_of_inertia, foundation.cog_height, foundation.base_area,"
    " foundation.base_second_moment, soil.c_z, soil.c_x, soil.c_phi"
)


def base_dashpot_matrix(design: CrankDesign) -> np.ndarray:
    """Damping matrix [N s/m, N s, N m s] of the base dashpots in the order x, y, θ (soil note;
    u_x = x - h θ at O, and a pile group's coupling C_xφ of u_x with θ_y)::

        [[C_x, 0, C_xφ - h C_x], [0, C_z, 0], [C_xφ - h C_x, 0, C_φ - 2 h C_xφ + h² C_x]]
    """
    d = design
    xt = d.C_xphi - d.h * d.C_x
    return np.array(
        [[d.C_x, 0.0, xt], [0.0, d.C_z, 0.0], [xt, 0.0, d.C_phi - 2.0 * d.h * d.C_xphi + d.h * d.h * d.C_x]],
        dtype=float,
    )


def natural_modes(M, K, at_rest: bool = True) -> tuple[np.ndarray, np.ndarray]:
    """Ascending natural frequencies [rad/s] of (K, M) and their mode shapes (columns), for one
    (3, 3) pair or stacks (..., 3, 3); a singular M gives frequencies 0 and unit shapes.

    ``at_rest``: the springs are static (the default): the frequencies are sqrt|λ| of the
    eigenvalues λ of M⁻¹K, ascending. False for a frequency-dependent support's springs at a
    frequency ω ≠ 0, the real part of an impedance, which may make K indefinite (a pile group's
    K_z at ω): the modes are then ranked by the signed λ and a mode with λ < 0 is 0. Its
    frequency there is imaginary: the springs at ω are softer than the inertia and there is no free
    vibration at ω, so it is no root of ω = p(K(ω)); sqrt|λ| would report a real frequency that
    does not exist and let the root search take a spurious crossing. With 0, p(ω) - ω = -ω < 0
    there; p(ω) stays continuous in ω (λ passes through 0) and its roots ω > 0 are those of the
    signed sqrt(λ), while the root search's first bracket end p(p_s) stays a frequency >= 0,
    where the springs are defined; the closed forms take a tipping determinant the same way
    (:func:`~foundation_calc.solvers.crank.frequencies.zero_order_frequencies` with ``at_rest``
    False), and the block's modes a negative p² (:func:`~foundation_calc.solvers.block.response.batch_modes`).
    The rank by the signed λ is the one under which each λ_j(ω) is continuous in ω (by |λ| a mode
    whose λ crosses 0 would trade ranks with the others)."""
    try:
        squared, shapes = np.linalg.eig(np.linalg.solve(M, K))
    except np.linalg.LinAlgError:
        squared, shapes = np.zeros(np.shape(M)[:-1]), np.broadcast_to(np.eye(3), np.shape(M))
    squared = squared.real
    order = np.argsort(np.abs(squared) if at_rest else squared, axis=-1)
    squared = np.take_along_axis(squared, order, axis=-1)
    natural = np.sqrt(np.abs(squared) if at_rest else np.maximum(squared, 0.0))
    return natural, np.take_along_axis(shapes.real, order[..., None, :], axis=-1)


#: Column orders k0, p1, p2 of ascending modes, by the column of k0.
_ORDERS = np.array([[0, 1, 2], [1, 0, 2], [2, 0, 1]])


def mode_order(M, shapes) -> np.ndarray:
    """Columns of ``shapes`` (ascending frequencies) in the order k0, p1, p2: k0 is the mode whose
    motion is most vertical (largest share of its kinetic energy in y), p1 and p2 the others.
    Stacks (..., 3, 3) give (..., 3)."""
    vertical = shapes[..., 1, :] ** 2 * M[..., 1, 1, None]
    return _ORDERS[np.argmax(vertical, axis=-1)]


def _modes(M, K, at_rest: bool = True) -> tuple[np.ndarray, np.ndarray]:
    """:func:`natural_modes` of one design, or :class:`PhysicsError` when double precision cannot
    resolve them (a singular mass matrix, or frequencies more than
    1/:data:`RESOLVED_FREQUENCY_RATIO` apart, where the smallest is round-off). On springs at a
    frequency (``at_rest`` False) the modes without a positive frequency there (0) are left out of
    that comparison: their 0 is no round-off."""
    natural, shapes = natural_modes(M, K, at_rest)
    resolved = natural if at_rest else natural[natural > 0.0]
    if not np.all(np.isfinite(natural)) or (resolved.size and resolved[0] <= RESOLVED_FREQUENCY_RATIO * resolved[-1]):
        raise PhysicsError(
            f"the natural frequencies of the averaged operator ({', '.join(f'{w:.3g}' for w in natural)} rad/s)"
            f" span more than {1 / RESOLVED_FREQUENCY_RATIO:.0e}: outside the range double precision resolves;"
            " the masses, lengths and soil stiffness of the scene are orders of magnitude apart",
            field=FREQUENCY_FIELDS,
        )
    return natural, shapes


def modal_damping_ratios(M, C, natural, shapes) -> np.ndarray:
    """ζ_j = v_j·C v_j / (2 p_j v_j·M v_j) [-] of each mode shape v_j (columns of ``shapes``);
    0 for a shape of no modal mass (round-off), never NaN. Stacks (..., 3, 3) welcome."""
    damping = np.einsum("...ij,...ik,...kj->...j", shapes, C, shapes)
    inertia = 2.0 * natural * np.einsum("...ij,...ik,...kj->...j", shapes, M, shapes)
    return np.where(inertia > 0.0, damping / np.where(inertia > 0.0, inertia, 1.0), 0.0)


def block_matrices(design: CrankDesign) -> tuple[np.ndarray, np.ndarray, np.ndarray]:
    """M, C, K (..., 3, 3) of the block on its soil with the moving mass m lumped at C (the
    paper's zero-order operator): the block model of one body M_tot, I_c at C on the base's springs
    and dashpots and a support's sway-rocking coupling K_xφ, C_xφ (0: the paper's base), in the
    crank's coordinates (:mod:`~foundation_calc.solvers.crank.plane`; fields may be arrays: a
    batch of blocks)."""
    from foundation_calc.solvers.crank.loads import RigidBlock, matrices

    d = design
    M, K, C = matrices(RigidBlock(M_tot=d.M_tot, I_c=d.I_c, h=d.h, K_x=d.c1 * d.S, K_z=d.c * d.S,
                                  K_phi=d.c_phi * d.I1, C_x=d.C_x, C_z=d.C_z, C_phi=d.C_phi, g=d.g))
    coupling = sway_rocking(d.K_xphi, d.C_xphi)
    if coupling is not None:  # a support's K_xφ, C_xφ of u_x with θ_y (a pile group)
        K, C = K + in_plane(coupling[0], d.h), C + in_plane(coupling[1], d.h)
    return M, C, K


def _forcing(samples) -> tuple[np.ndarray, np.ndarray]:
    """Cosine and sine coefficients (3, :data:`FORCING_HARMONICS` + 1) of the mechanism's forcing,
    Eq. (4) of crank_mechanism, from its samples in the crank's coordinates."""
    return analyse((samples.f_inertia + samples.f_weight).T, FORCING_HARMONICS)


def _drive_reaction(design: CrankDesign) -> tuple[np.ndarray, ...]:
    """M̄, C̄, K̄, fc, fs of the drive's reaction with the motor off the foundation
    (:func:`~foundation_calc.solvers.crank.dynamics.drive_reaction`, linearised and averaged), all 0
    with the motor on it."""
    if design.drive_on_foundation:
        return (np.zeros((3, 3)),) * 3 + (np.zeros((3, FORCING_HARMONICS + 1)),) * 2
    lin = linearise(design, phases(FORCING_SAMPLES), drive_reaction)
    return (*(block.mean(axis=-1) for block in (lin.mass, lin.damping, lin.stiffness)),
            *analyse(lin.forcing, FORCING_HARMONICS))


def mechanism_operator(design: CrankDesign) -> tuple[np.ndarray, ...]:
    """The mechanism's part of :func:`averaged_operator`: M̄, C̄, K̄ (3, 3), the means of Eqs.
    (1)-(3) of :mod:`~foundation_calc.solvers.machines.crank_mechanism` about C less the moving
    mass m at C that :func:`block_matrices` holds, and the forcing's coefficients (Eq. (4), and
    the drive's reaction with the motor off the foundation). They depend on the mechanism and the
    speed alone: one call serves every block that carries the same machine."""
    s = plane_samples(plane_throw(replace(design, h=0.0)), 0.0, design.omega, design.g, FORCING_SAMPLES)
    M, C, K = (A.mean(axis=0) for A in (s.M, s.D, s.S))
    M = M - np.diag([design.rod.m, design.rod.m, 0.0])
    fc, fs = _forcing(s)
    drive = _drive_reaction(design)
    return M + drive[0], C + drive[1], K + drive[2], fc + drive[3], fs + drive[4]


def averaged_operator(design: CrankDesign) -> tuple[np.ndarray, ...]:
    """M̄, C̄, K̄ (3, 3) of the exact equations linearised about rest and averaged over a
    revolution, and the cosine and sine coefficients (3, :data:`FORCING_HARMONICS` + 1) of the
    exact forcing -r0 (module docstring); order x, y, θ. The one rigid-body model
    (:func:`~foundation_calc.solvers.crank.plane.plane_foundation`: the block, the mechanism's mean
    mass and weight, the base's springs and dashpots) in the crank's coordinates, with the
    mechanism's mean Coriolis terms and its forcing (and the drive's reaction with the motor off
    the foundation)."""
    found = plane_foundation(design)
    s = plane_samples(found.throw, design.h, design.omega, design.g, FORCING_SAMPLES)
    M, C, K = (in_plane(A, design.h) for A in (found.model.M, found.model.C, found.model.K))
    fc, fs = _forcing(s)
    drive = _drive_reaction(design)
    return (M + drive[0], C + s.D.mean(axis=0) + drive[1], K + drive[2], fc + drive[3], fs + drive[4])


def plane_frequencies(design: CrankDesign, at_rest: bool = True) -> NaturalFrequencies:
    """k0, p1, p2 [rad/s] of the one model in the plane: the eigen-solve of :func:`averaged_operator`'s
    M̄, K̄ (the support's coupling K_xφ included), each mode named by its dominant motion as the
    closed forms name them (:func:`mode_order`: k0 the most vertical, p1 < p2 the others). The
    frequencies of a coupled support (a pile group), where (4.5)-(4.7) do not apply; on an
    uncoupled one they are :func:`~foundation_calc.solvers.crank.frequencies.averaged_inertia_frequencies`'
    to round-off. A dynamic pile group's springs at a frequency past its interaction peaks may make a
    K̄ indefinite: with ``at_rest`` False (the springs at ω ≠ 0, the root search ω = p(K(ω))) a mode
    with p² < 0 there is 0, as :func:`natural_modes` takes it, no real frequency (the static
    stability is the scene's :meth:`~foundation_calc.scenes.crank.CrankScene.require_stable_rocking`).
    """
    M, _, K, _, _ = averaged_operator(design)
    natural, shapes = _modes(M, K, at_rest)
    k0, p1, p2 = natural[mode_order(M, shapes)]
    return NaturalFrequencies(k0=float(k0), p1=float(p1), p2=float(p2))


def averaged_response(design: CrankDesign) -> AveragedResponse:
    """Forced steady state with the time-averaged operator and the exact forcing (module docs).

    Raises
    ------
    PhysicsError
        when the foundation is unstable in rocking.

    >>> from foundation_calc.solvers.crank.mechanism import lump_slider
    >>> d = CrankDesign(M=1e5, I_c=4.5e5, h=1.5, S=30.0, I1=90.0, c=4e7, c1=2.8e7, c_phi=4e7,
    ...                 C_x=0.0, C_z=0.0, C_phi=0.0, omega=31.4159,
    ...                 r=0.3, l=1.2, a=2.0, rod=lump_slider(1.5e3, 1.2, 1.0, 0.35, 0.0),
    ...                 drive_on_foundation=True, g=9.81)
    >>> res = averaged_response(d)
    >>> f"{res.motion.cos[1, 1]:.6e} {res.motion.sin[0, 1]:.6e}"
    '4.038206e-04 -2.451694e-04'
    """
    require_stable_design(design)
    M, C, K, fc, fs = averaged_operator(design)
    natural, shapes = _modes(M, K)
    ratios = modal_damping_ratios(M, base_dashpot_matrix(design), natural, shapes)
    n = np.arange(FORCING_HARMONICS + 1)
    w = n * design.omega
    margins = np.abs(w[1:, None] - natural) / natural
    flat = int(np.argmin(margins))
    nearest = (flat // 3 + 1, flat % 3)
    margin = float(margins.min())
    undamped = margins[:, ratios < UNDAMPED_RATIO]
    resonant = bool(undamped.size) and float(undamped.min()) < RESONANT_MARGIN
    if resonant:
        Z = np.zeros((3, FORCING_HARMONICS + 1), dtype=complex)
    else:
        ops = K + 1j * w[:, None, None] * C - (w * w)[:, None, None] * M
        try:
            Z = np.linalg.solve(ops, (fc - 1j * fs).T[..., None])[..., 0].T
        except np.linalg.LinAlgError:  # singular in double precision: a resonance to round-off
            resonant, margin = True, 0.0
            Z = np.zeros((3, FORCING_HARMONICS + 1), dtype=complex)
    return AveragedResponse(
        motion=PeriodicMotion(omega=design.omega, cos=Z.real, sin=-Z.imag),
        natural=natural,
        margin=margin,
        nearest=nearest,
        resonant=resonant,
        damping_ratios=ratios,
        mass=M,
        damping=C,
        stiffness=K,
    )


__all__ = [
    "FORCING_HARMONICS",
    "FORCING_SAMPLES",
    "AveragedResponse",
    "LinearOperator",
    "averaged_operator",
    "averaged_response",
    "base_dashpot_matrix",
    "block_matrices",
    "linearise",
    "mechanism_operator",
    "modal_damping_ratios",
    "mode_order",
    "natural_modes",
    "plane_frequencies",
]
