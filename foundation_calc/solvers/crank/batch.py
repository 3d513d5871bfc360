"""The averaged-operator closed form (:mod:`~foundation_calc.solvers.crank.averaged`) for a batch
of blocks that carry one mechanism at one speed, in array operations over the batch.

The averaged operator is the mechanism's part, the same for every block
(:func:`~foundation_calc.solvers.crank.averaged.mechanism_operator`), plus the block's
(:func:`~foundation_calc.solvers.crank.averaged.block_matrices`, arrays over the batch); the
forcing is the mechanism's alone. Each harmonic n then solves

    (K̄ + i nω C̄ - n²ω² M̄) Z_n = F_n

for every block at once (Cramer's rule on the 3 × 3 systems, stacked), and a mode the base
dashpots leave undamped is resonant within
:data:`~foundation_calc.solvers.crank.first_approximation.RESONANT_MARGIN` of any harmonic
1 ... :data:`~foundation_calc.solvers.crank.averaged.FORCING_HARMONICS`, as for one design.
"""

from __future__ import annotations

import numpy as np

from dataclasses import dataclass, replace

from foundation_calc.solvers.crank.averaged import (
    FORCING_HARMONICS,
    mechanism_operator,
    modal_damping_ratios,
    natural_modes,
)
from foundation_calc.solvers.crank.first_approximation import RESONANT_MARGIN, UNDAMPED_RATIO

#: Relative size [-] of a forcing harmonic (to the largest of its row: x, y or θ) below which the
#: harmonic and all above it are left out of a batch's response. The forcing's Fourier
#: coefficients fall as λⁿ to round-off (about 1e-15) and stay there; a harmonic of relative size
#: f changes a peak acceleration by about f times its resonance magnification, the displacement
#: by f/n² of that: below 1e-12 of every peak for a damping ratio above 0.1 %.
FORCING_FLOOR = 1e-15


def forcing_harmonics(fc, fs) -> int:
    """The highest harmonic K_b whose forcing reaches :data:`FORCING_FLOOR` of its row's
    largest: the response of a batch keeps harmonics 0 ... K_b (at least 1). Stacks (..., 3, K + 1)
    of forcings take the highest over the stack.

    >>> forcing_harmonics(np.array([[0.0, 1.0, 1e-3, 1e-16]]), np.zeros((1, 4)))
    2
    """
    size = np.hypot(fc, fs)
    largest = size.max(axis=-1, keepdims=True)
    above = size > FORCING_FLOOR * np.where(largest > 0.0, largest, 1.0)
    return max(1, int(np.nonzero(above.reshape(-1, size.shape[-1]).any(axis=0))[0].max(initial=1)))


@dataclass(frozen=True)
class MechanismOperator:
    """The mechanism's part of the averaged operator (:func:`~foundation_calc.solvers.crank.averaged.mechanism_operator`)
    as a function of one of the design's fields, :attr:`field`: the distance ``a`` from the crank
    axis to C [m], for blocks whose C moves, or the speed ``omega`` [rad/s], for a speed sweep.

    The exact equations hold the rod's position p = (p_u, p_v - a) in products of at most two
    factors (m |p|² θ'', m p × (...)); the drive's torque takes the arm M' - C1, free of a. The
    mechanism's velocities go as ω and its accelerations as ω² at every phase φ = ω t (the
    Coriolis terms as ω, the inertia forcing and the centrifugal stiffness as ω², the weight's
    terms free of it). So every averaged matrix and forcing coefficient is a polynomial of degree 2
    in a and in ω, given exactly by its values at x0 - Δ, x0, x0 + Δ (:attr:`samples`: (M, C, K,
    fc, fs) at each, the forcing's harmonics 0 ... :attr:`harmonics`; x0 = :attr:`centre`, Δ =
    :attr:`step`: 1 m for a, ω0 for ω, so samples at 0, ω0, 2 ω0).
    """

    centre: float
    samples: tuple

    harmonics: int
    field: str = "a"
    step: float = 1.0

    @classmethod
    def of(cls, design, field: str = "a") -> "MechanismOperator":
        """The samples of ``design``'s mechanism about its own ``field`` (``"a"`` or ``"omega"``),
        the forcing kept to the highest harmonic :func:`forcing_harmonics` finds in any of them
        (:attr:`harmonics`)."""
        centre = float(getattr(design, field))
        step = 1.0 if field == "a" else centre
        samples = [mechanism_operator(replace(design, **{field: centre + k * step})) for k in (-1.0, 0.0, 1.0)]
        kept = max(forcing_harmonics(fc, fs) for *_, fc, fs in samples)
        return cls(centre, tuple((*s[:3], s[3][:, : kept + 1], s[4][:, : kept + 1]) for s in samples), kept, field, step)

    @property
    def decoupled(self) -> bool:
        """Whether the vertical motion is uncoupled from sliding and rocking: the mechanism's
        averaged entries between y and (x, θ) are round-off (below 1e-12 of the matrix's scale:
        max |M|, max |K|, and sqrt(max |M| max |K|) for C) in every sample. The block's own
        matrices never couple them. Then each harmonic solves a 2 × 2 system and a scalar."""
        for M, C, K, *_ in self.samples:
            scales = (np.abs(M).max(), np.sqrt(np.abs(M).max() * np.abs(K).max()), np.abs(K).max())
            for A, scale in zip((M, C, K), scales):
                if np.abs(A[[0, 1, 1, 2], [1, 0, 2, 1]]).max() > 1e-12 * scale:
                    return False
        return True

    def at(self, value) -> tuple[np.ndarray, ...]:
        """M, C, K (..., 3, 3) and fc, fs (..., 3, K + 1) at the values ``value`` of :attr:`field`
        [m or rad/s] (any shape)."""
        t = ((np.asarray(value, dtype=float) - self.centre) / self.step).reshape(np.shape(value) + (1, 1))
        low, mid, high = self.samples
        return tuple(m + t * (h - lo) / 2.0 + t * t * (h - 2.0 * m + lo) / 2.0 for lo, m, h in zip(low, mid, high))


def solve3(A, b):
    """x of A x = b for stacks of 3 × 3 systems (Cramer's rule): ``A`` (3, 3, ...), ``b`` (3, ...),
    matrix and vector indices first (each entry a contiguous array over the stack), complex or
    real; a singular system gives inf or NaN.

    >>> A = np.array([[2.0, 1.0, 0.0], [1.0, 3.0, 1.0], [0.0, 1.0, 4.0]])
    >>> np.allclose(solve3(A, np.array([1.0, 2.0, 3.0])), np.linalg.solve(A, [1.0, 2.0, 3.0]))
    True
    """
    def cofactor(i, j):
        (r0, r1), (c0, c1) = [k for k in range(3) if k != i], [k for k in range(3) if k != j]
        return A[r0][c0] * A[r1][c1] - A[r0][c1] * A[r1][c0]

    cof = [[cofactor(i, j) * (-1.0 if (i + j) % 2 else 1.0) for j in range(3)] for i in range(3)]
    det = A[0][0] * cof[0][0] + A[0][1] * cof[0][1] + A[0][2] * cof[0][2]
    return np.stack([(cof[0][i] * b[0] + cof[1][i] * b[1] + cof[2][i] * b[2]) / det for i in range(3)])


def resonant_blocks(M, C, K, omega):
    """Which blocks of a batch have an undamped mode within the resonant margin of a harmonic
    1 ... :data:`FORCING_HARMONICS` of ω [rad/s] (no steady state), and their natural
    frequencies [rad/s] (..., 3), ascending. ``C``: the base dashpots' matrix."""
    natural, shapes = natural_modes(M, K)
    ratios = modal_damping_ratios(M, C, natural, shapes)
    # |nω - p|/p over n = 1 ... FORCING_HARMONICS is smallest at the n nearest p/ω
    nearest = np.clip(np.rint(natural / omega), 1, FORCING_HARMONICS)
    margin = np.abs(nearest * omega - natural) / np.where(natural > 0.0, natural, 1.0)
    return ((ratios < UNDAMPED_RATIO) & (margin < RESONANT_MARGIN)).any(axis=-1), natural


def harmonic_response(M, C, K, omega, fc, fs, harmonics: int, per_harmonic: bool = False, decoupled: bool = False):
    """Complex harmonics Z_n (n = 0 ... ``harmonics``) of x, y, θ, shape (..., 3, harmonics + 1):
    cos = Z.real, sin = -Z.imag. ``M``, ``C``, ``K``: (..., 3, 3), or with ``per_harmonic``
    (..., harmonics + 1, 3, 3), an operator per harmonic (springs that depend on frequency);
    ``fc``, ``fs``: the forcing's coefficients (..., 3, > ``harmonics``), one per system or shared.
    ``decoupled`` (:attr:`MechanismOperator.decoupled`): y solved alone, x and θ as a 2 × 2 system,
    the y-(x, θ) entries (round-off) left out."""
    w = np.arange(harmonics + 1) * omega
    if not per_harmonic:
        M, C, K = (np.asarray(x)[..., None, :, :] for x in (M, C, K))
    # matrix indices first: every entry of the stacked systems is one contiguous array
    M, C, K = (np.moveaxis(np.asarray(x, dtype=float), (-2, -1), (0, 1)) for x in (M, C, K))
    force = np.moveaxis(fc[..., : harmonics + 1] - 1j * fs[..., : harmonics + 1], -2, 0)  # (3, ..., harmonics + 1)
    shape = np.broadcast_shapes(K.shape[2:], w.shape)

    def entry(i, j):
        e = np.empty(shape, dtype=complex)
        e.real = K[i, j] - (w * w) * M[i, j]
        e.imag = w * C[i, j]
        return e

    if decoupled:
        a, b, c, d = entry(0, 0), entry(0, 2), entry(2, 0), entry(2, 2)
        det = a * d - b * c
        Z = [(d * force[0] - b * force[2]) / det, force[1] / entry(1, 1), (a * force[2] - c * force[0]) / det]
        return np.moveaxis(np.stack(np.broadcast_arrays(*Z)), 0, -2)
    ops = np.empty(K.shape[:2] + shape, dtype=complex)
    ops.real = K - (w * w) * M
    ops.imag = w * C
    return np.moveaxis(solve3(ops, force), 0, -2)


__all__ = ["FORCING_FLOOR", "MechanismOperator", "forcing_harmonics", "harmonic_response", "resonant_blocks", "solve3"]
