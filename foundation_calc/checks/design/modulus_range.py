"""The one modulus-range checker of ``fcalc design``: the resonance and amplitude checks of a batch
of candidates over the soil's ``modulus_range``, as ``fcalc check`` judges one scene there
(:mod:`~foundation_calc.checks.soil_range`), for every scene kind.

What every kind shares is done here once (:func:`over_range`):

- the stiffness factors: the resonances at the
  :data:`~foundation_calc.checks.soil_range.GRID_POINTS` factors of
  :func:`~foundation_calc.checks.soil_range.modulus_factors`, the amplitudes at the
  :data:`~foundation_calc.checks.soil_range.AMPLITUDE_GRID_POINTS` ones, and both at every
  factor where a critical speed crosses a machine's speed between them and the resonance rule
  judges the crossed condition there;
- the worst verdict of each candidate over all of them (:class:`Worst`: the worst outcome, and
  among equal outcomes the largest utilisation);
- that verdict merged into the candidate's on the soil as given (:meth:`Worst.merged`): the worse
  outcome of the two, and where the range's is worse, what governs there; the utilisation stays
  the one on the soil as given, as the full path's evaluator reads it
  (:mod:`~foundation_calc.checks.design.reference`). A candidate that tips over at any factor
  fails, as the full path finds its scene invalid.

What a kind does differently is its engine's, handed in as a generator (:func:`over_range`): how it
judges candidates at a factor, and how it finds the crossings (in closed form by ``eigvalsh`` for
the block, :mod:`.block_range`; by bisection for the crank's closed-form frequencies,
:mod:`.crank_range`).
"""

from __future__ import annotations

import numpy as np

#: Appended to a reason when the soil's modulus range governs the check (a kind that names the
#: range's own reasons: :meth:`Worst.merged` without a ``summary``).
OVER_RANGE = " (over the soil's modulus range)"


def factor_grids(scene) -> dict[str, np.ndarray]:
    """check -> the stiffness factors [-] of the scene's ``soil.modulus_range`` where ``fcalc check``
    judges it (module docstring; the crossings between them are the engine's)."""
    from foundation_calc.checks.soil_range import AMPLITUDE_GRID_POINTS, modulus_factors

    low, high = scene.soil.modulus_range
    return {"resonance": modulus_factors(low, high), "amplitudes": modulus_factors(low, high, AMPLITUDE_GRID_POINTS)}


class Worst:
    """The worst verdict of each of ``n`` candidates per check over the elements judged so far: an
    element is one candidate (its owner) at one stiffness factor. Per check of ``checks``: outcome (-1 where no
    element was judged), utilisation and governing index of the worst element (the worst outcome,
    then the largest utilisation; of equals, the last judged), and the reasons it indexes."""

    def __init__(self, n: int, checks):
        self.n = n
        self.outcome = {check: np.full(n, -1, np.int8) for check in checks}
        self.utilisation = {check: np.full(n, np.nan) for check in checks}
        self.governing = {check: np.zeros(n, np.intp) for check in checks}
        self.reasons = {check: () for check in checks}

    def add(self, check, owner, outcome, utilisation, governing, reasons) -> None:
        """The elements ``owner`` (N_e,) candidate indices with their verdicts (N_e,) each."""
        everyone = np.arange(self.n)  # the worst so far first: of equals, the element judged later wins
        owner = np.concatenate([everyone, owner])
        outcome, utilisation, governing = (np.concatenate([old[check], new]) for old, new in (
            (self.outcome, outcome), (self.utilisation, utilisation), (self.governing, governing)))
        key = np.where(np.isnan(utilisation), -np.inf, utilisation)
        order = np.lexsort((key, outcome, owner))
        chosen = order[np.r_[owner[order][1:] != owner[order][:-1], True]]
        self.outcome[check][owner[chosen]] = outcome[chosen]
        self.utilisation[check][owner[chosen]] = utilisation[chosen]
        self.governing[check][owner[chosen]] = governing[chosen]
        self.reasons[check] = tuple(reasons)

    def open(self, given: dict, checks) -> np.ndarray:
        """The candidates that do not yet fail every one of ``checks`` on the soil as ``given`` (check ->
        (outcome, ...)) nor at a factor judged so far: those a further factor can make worse."""
        from foundation_calc.checks.design.candidates import FAIL

        worst = [np.maximum(given[check][0], self.outcome[check]) for check in checks]
        return np.flatnonzero(np.any([w < FAIL for w in worst], axis=0))

    def merged(self, given: dict, summary: str | None = None) -> dict:
        """check -> (outcome, utilisation, governing, reasons): ``given``'s verdicts (check -> the
        same, on the soil as given) with the range's (module docstring). Where the range's outcome is
        worse, what governs is the range's own reason with :data:`OVER_RANGE` (the check's reasons
        gain them all), or, with a ``summary``, that one text (the kind names no factor's reason)."""
        found = {}
        for check, (outcome, utilisation, governing, reasons) in given.items():
            r_outcome, r_governing, r_reasons = self.outcome[check], self.governing[check], self.reasons[check]
            worse = r_outcome > outcome
            extra = (summary,) if summary is not None else tuple(r + OVER_RANGE for r in r_reasons)
            at = len(reasons) if summary is not None else r_governing + len(reasons)
            found[check] = (np.maximum(outcome, r_outcome).astype(np.int8), utilisation, np.where(worse, at, governing),
                            (*reasons, *extra))
        return found


def over_range(scene, given: dict, judged, summary: str | None = None) -> dict:
    """check -> (outcome, utilisation, governing, reasons) of the resonance and amplitude checks of
    the candidates over the soil as ``given`` (check -> the same) and over the scene's
    ``soil.modulus_range`` (module docstring).

    ``judged(grids, open)``: the kind's engine, a generator of (check, owner, outcome, utilisation,
    governing, reasons) of the elements it judges, at the factors ``grids`` (:func:`factor_grids`)
    and at the crossings it finds between them; ``open(checks)`` names the candidates a further
    factor can still make worse (:meth:`Worst.open`: an engine may leave the others out).
    ``summary``: :meth:`Worst.merged`'s."""
    n = len(next(iter(given.values()))[0])
    worst = Worst(n, given)
    for check, *element in judged(factor_grids(scene), lambda checks: worst.open(given, checks)):
        worst.add(check, *element)
    return worst.merged(given, summary)


__all__ = ["OVER_RANGE", "Worst", "factor_grids", "over_range"]
