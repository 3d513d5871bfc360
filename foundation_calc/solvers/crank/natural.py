"""Natural frequencies k0, p1, p2 of the plane crank model at a design, as the resonance check
takes them: of the paper's zero-order operator and of the operator with the mechanism's averaged
inertia (closed forms (4.5)-(4.7), :mod:`~foundation_calc.solvers.crank.frequencies`), or on a
support coupling sway with rocking the one model's eigen-solve in the plane
(:func:`~foundation_calc.solvers.crank.averaged.plane_frequencies`); on a frequency-dependent
support each mode re-solved at its own frequency, ω = p(K(ω))
(:func:`~foundation_calc.solvers.soil.impedance.consistent_frequency`). Units: rad/s.
"""

from __future__ import annotations

import numpy as np

from foundation_calc.solvers.crank.frequencies import (
    NaturalFrequencies,
    averaged_inertia_frequencies,
    zero_order_frequencies,
)
from foundation_calc.solvers.crank.mechanism import CrankDesign

#: The crank foundation's modes in the plane, by name: vertical k0, sliding-rocking p1 < p2.
MODES = ("k0", "p1", "p2")


def design_frequencies(design: CrankDesign) -> tuple[NaturalFrequencies, NaturalFrequencies]:
    """Zero-order and averaged-inertia natural frequencies of a design (fields may be arrays); on a
    frequency-dependent support's springs at ω ≠ 0 (its ``soil_frequency``) no stability is judged
    and a mode the springs there leave without a positive frequency is 0 (the scene judged the
    springs at rest, :meth:`~foundation_calc.scenes.crank.CrankScene.in_plane`). On a
    support coupling u_x with θ_y (a pile group) the closed forms do not apply: both are the one
    model's eigen-solve in the plane (:func:`~foundation_calc.solvers.crank.averaged.plane_frequencies`,
    one design)."""
    at_rest = not np.any(np.asarray(design.soil_frequency) != 0.0)  # stability is judged on static springs only
    if design.coupled:
        from foundation_calc.solvers.crank.averaged import plane_frequencies

        found = plane_frequencies(design, at_rest)
        return found, found
    d, rod = design, design.rod
    soil_args = (d.M_tot, d.I_c, d.h, d.S, d.I1, d.c, d.c1, d.c_phi, d.g)
    zero = zero_order_frequencies(*soil_args, at_rest=at_rest)
    averaged = averaged_inertia_frequencies(*soil_args, rod.m, d.a, d.r, d.l, rod.l1, rod.rho, at_rest=at_rest)
    return zero, averaged


def consistent_frequencies(static: NaturalFrequencies, frequencies_at, rootless: str = "raise",
                           several: dict | None = None) -> NaturalFrequencies:
    """Each mode of ``static`` re-solved as ω = p(K(ω)), ``frequencies_at(ω)`` giving the
    NaturalFrequencies on the springs taken at ω; a mode without a root raises the PhysicsError
    naming it, or with ``rootless="nan"`` (a batch of candidates) is NaN
    (:func:`~foundation_calc.solvers.soil.impedance.consistent_frequency`). ``several`` (one
    design): receives mode -> every root [rad/s] of a mode whose scan found more than one."""
    from foundation_calc.solvers.soil.impedance import consistent_frequency

    found = {}
    for mode in MODES:
        every = [] if several is not None else None
        found[mode] = consistent_frequency(lambda w, mode=mode: getattr(frequencies_at(w), mode), getattr(static, mode),
                                           mode=mode, rootless=rootless, every=every)
        if every is not None and len(every) > 1:
            several[mode] = tuple(every)
    return NaturalFrequencies(**found)


def by_static_rank(static: NaturalFrequencies):
    """A function giving k0, p1, p2 at a frequency named by their rank in ``static``: the j-th
    lowest there takes the name of the j-th lowest at rest. A mode then follows its rank, as
    :func:`~foundation_calc.solvers.soil.impedance.consistent_frequency` needs it (its root exists
    and is bracketed), not its dominant motion, which a pile group's springs at frequency reorder.
    Fields may be arrays (a batch of designs): each design's modes by their own ranks."""
    rank = np.argsort(np.argsort(_stacked(static), axis=-1, kind="stable"), axis=-1)

    def ranked(found: NaturalFrequencies) -> NaturalFrequencies:
        values = np.take_along_axis(np.sort(_stacked(found), axis=-1), np.broadcast_to(rank, np.shape(_stacked(found))), -1)
        return NaturalFrequencies(*(values[..., j] for j in range(len(MODES))))

    return ranked


def _stacked(found: NaturalFrequencies) -> np.ndarray:
    """k0, p1, p2 of ``found`` stacked on a last axis, (..., 3)."""
    return np.stack(np.broadcast_arrays(*(np.asarray(getattr(found, mode), dtype=float) for mode in MODES)), axis=-1)


__all__ = ["MODES", "by_static_rank", "consistent_frequencies", "design_frequencies"]
