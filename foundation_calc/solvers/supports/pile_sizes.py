"""The sizes of a pile group (``[piles]``) a design may vary, and what they change: the concrete
the piles add, where their heads go under a resized base, and where the piles leave the ranges
their closed forms hold over (the warnings ``fcalc check`` gives of a scene, and of each candidate
of a design's batch, by the same functions).

Ranges (:data:`VALIDITY`): E_p/E_s, Gazetas 1991 fitted EN 1998-5 Table C.1 over 300-10 000
(fcalc warns from 100); L/d, Randolph & Wroth compared their vertical stiffness with the continuum
for L/d 10-100; the spacing S/d, Dobry & Gazetas verified their interaction factors from 2
against Kaynia & Kausel (wider spacings tend to independent piles, which their form keeps); and the
length against the active length l_a (Table C.1 holds for flexible piles, L >= l_a:
:func:`~foundation_calc.solvers.piles.single.active_length`).
"""

from __future__ import annotations

import numpy as np

from foundation_calc.solvers.supports.base import SizeFindings, Variable

#: The ranges the single pile's closed forms and the group's factors were fitted or verified over
#: (module docstring): E_p/E_s, L/d and the least S/d.
VALIDITY = {"stiffness_ratio": (100.0, 1.0e4), "slenderness": (10.0, 100.0), "spacing": 2.0}

#: The scenes that have the piles' sizes.
WHERE = "a scene with [piles]"

#: The sizes of the piles a design may vary [m], bounded by their plausible ranges.
VARIABLES = (Variable("piles.length", "pile length", WHERE), Variable("piles.diameter", "pile diameter", WHERE))

#: The warnings of a candidate's piles: (the scene key ``fcalc check`` gives it under, what it warns of).
WARNINGS = (
    ("piles.length", "piles.length/piles.diameter outside the range Randolph & Wroth's vertical stiffness was compared over"),
    ("piles.length", "piles.length shorter than the active length (Table C.1 holds for flexible piles)"),
    ("piles.positions", "the closest piles nearer than the spacing Dobry & Gazetas' factors were verified from"),
)


def concrete(count, d, length):
    """n π d²/4 L [m³] of ``count`` piles of diameter ``d`` and length ``length`` [m] (arrays broadcast).

    >>> round(float(concrete(6, 0.6, 16.0)), 4)
    27.1434
    """
    return count * np.pi * d * d / 4.0 * length


def heads(positions, plan, L, B):
    """(x, y) [m] of the heads ``positions`` ([x, y] each, given under a base ``plan`` (L, B) [m]) under
    a base L × B [m] (floats, or arrays over a batch: the heads' axis last): they keep their place
    in the plan, x scaled with L and y with B."""
    xy = np.array(positions, dtype=float)
    L0, B0 = plan
    return xy[:, 0] * (np.asarray(L, dtype=float)[..., None] / L0), xy[:, 1] * (np.asarray(B, dtype=float)[..., None] / B0)


def slenderness_outside(d, length):
    """Whether L/d lies outside :data:`VALIDITY`'s ``"slenderness"`` (arrays broadcast)."""
    low, high = VALIDITY["slenderness"]
    ratio = np.asarray(length) / d
    return (ratio < low) | (ratio > high)


def shorter_than_active(d, length, E_s, E_p, profile):
    """(whether L < l_a, l_a [m]) of piles d × L [m], E_p [Pa], in a soil of E_s [Pa] at depth d
    with the modulus ``profile`` (:func:`~foundation_calc.solvers.piles.single.active_length`)."""
    from foundation_calc.solvers.piles.single import active_length

    l_a = active_length(E_s, E_p, d, profile)
    return np.asarray(length) < l_a, l_a


def closest(x, y):
    """The least distance between two heads (x, y) [m], the heads' axis last; inf for one pile."""
    x, y = np.asarray(x, dtype=float), np.asarray(y, dtype=float)
    S = np.hypot(x[..., :, None] - x[..., None, :], y[..., :, None] - y[..., None, :])
    n = S.shape[-1]
    S[..., np.arange(n), np.arange(n)] = np.inf
    return S.min(axis=(-2, -1))


def too_close(S_min, d):
    """Whether the closest heads, S_min [m] apart, are nearer than :data:`VALIDITY`'s spacing × d."""
    return np.asarray(S_min) < VALIDITY["spacing"] * d


#: Why ``fcalc check`` refuses a candidate's scene (:meth:`~foundation_calc.scenes.block_piles.BlockPiles._do_not_overlap`).
OVERLAP = "the piles overlap (the closest heads less than piles.diameter apart)"


def _first(found) -> np.ndarray:
    """Per candidate, 0 where none of ``found`` (boolean arrays, in order) applies, else 1 + the first's index."""
    which = np.zeros(np.broadcast_shapes(*(np.shape(f) for f in found)), dtype=int)
    for code, flags in reversed(list(enumerate(found, start=1))):
        which = np.where(flags, code, which)
    return which


def warnings(piles, E_s, plan, d, length, L, B) -> SizeFindings:
    """The warnings (:data:`WARNINGS`) of candidate piles d × L [m] of the ``[piles]`` table
    ``piles`` (its heads given under ``plan``) on bases L × B [m], in a soil of E_s [Pa] at depth d;
    arrays (N,) each."""
    x, y = heads(piles.positions, plan, L, B)
    found = (slenderness_outside(d, length), shorter_than_active(d, length, E_s, piles.modulus, piles.soil_profile)[0],
             too_close(closest(x, y), d))
    return SizeFindings(_first(found), tuple(text for _, text in WARNINGS), tuple(dict.fromkeys(key for key, _ in WARNINGS)))


def errors(piles, plan, d, L, B) -> SizeFindings:
    """The candidates d [m] on bases L × B [m] whose piles overlap (:data:`OVERLAP`), arrays (N,) each."""
    return SizeFindings(_first([closest(*heads(piles.positions, plan, L, B)) < d]), (OVERLAP,))


__all__ = ["OVERLAP", "VALIDITY", "VARIABLES", "WARNINGS", "WHERE", "closest", "concrete", "errors", "heads",
           "shorter_than_active", "slenderness_outside", "too_close", "warnings"]
