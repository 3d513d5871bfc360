"""The ``[soil] stratum_depth`` of a scene against its base: what no single key can say.

The stratum (:mod:`~foundation_calc.solvers.soil.stratum`) must reach below the base (an error
otherwise: bedrock above the footing's underside is another foundation), and its static factors
were fitted for layers at least :data:`~foundation_calc.solvers.soil.stratum.H_OVER_R_MIN` times
as deep as the base's equivalent radius R = sqrt(L B/π) (a warning below that).
"""

from __future__ import annotations

import math

from foundation_calc.scenes.plausibility import Remark


def stratum_error(soil, D: float, embedment_key: str) -> str | None:
    """The message when the stratum does not reach below the base of embedment ``D`` [m] (the scene's
    key ``embedment_key``), else None."""
    H = soil.stratum_depth
    if H is None or H > D:
        return None
    return (f"soil.stratum_depth = {H:g} m must exceed {embedment_key} = {D:g} m: the bedrock lies below the"
            " base (give the depth from the ground surface to bedrock, in m)")


def shallow(soil, L, B):
    """Where the stratum is shallower than H_OVER_R_MIN × R, R = sqrt(L B/π), under a base L × B [m]
    (floats, or arrays over a batch of candidate blocks: the result broadcasts); False everywhere
    without a stratum (or without soil: ``soil`` None, a block on isolators).

    >>> from types import SimpleNamespace
    >>> import numpy as np
    >>> shallow(SimpleNamespace(stratum_depth=6.0), np.array([5.0, 5.28]), np.array([3.0, 5.54])).tolist()
    [False, True]
    """
    import numpy as np

    from foundation_calc.solvers.soil.stratum import H_OVER_R_MIN

    H = getattr(soil, "stratum_depth", None)
    if H is None:
        return np.zeros(np.broadcast(L, B).shape, dtype=bool)
    return H < H_OVER_R_MIN * np.sqrt(np.asarray(L, dtype=float) * B / math.pi)


def stratum_remarks(soil, L: float, B: float) -> list[Remark]:
    """A :class:`~foundation_calc.scenes.plausibility.Remark` when the stratum is shallower than
    H_OVER_R_MIN × R for the base L × B [m] (:func:`shallow`), else none."""
    if not shallow(soil, L, B):
        return []
    from foundation_calc.solvers.soil.stratum import H_OVER_R_MIN, KAUSEL_COEFFICIENTS

    H, R = soil.stratum_depth, math.sqrt(L * B / math.pi)
    key = "soil.stratum_depth"
    return [Remark(key, f"{key} = {H:g} m is {H / R:.3g} × the base's equivalent radius R = sqrt(L B/π) = {R:.3g} m,"
                        f" less than {H_OVER_R_MIN:g} R: the stratum's static factors are extrapolated there (vertical"
                        f" 1 + {KAUSEL_COEFFICIENTS[0]:g} R/H = {1.0 + KAUSEL_COEFFICIENTS[0] * R / H:.3g})")]


__all__ = ["shallow", "stratum_error", "stratum_remarks"]
