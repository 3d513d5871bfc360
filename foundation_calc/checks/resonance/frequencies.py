"""The natural frequencies and mode shapes of a ``crank_foundation`` scene, as its checks read
them: the scene's design or block on its support, on a frequency-dependent support each mode at
its own frequency (ω = p(K(ω))). The computation is the solvers'
(:mod:`~foundation_calc.solvers.crank.natural`, :mod:`~foundation_calc.solvers.crank.modes`,
:func:`~foundation_calc.solvers.crank.loads.block_frequencies`); this module only reads the scene.
"""

from __future__ import annotations

from collections.abc import Mapping
from typing import TYPE_CHECKING

if TYPE_CHECKING:
    from foundation_calc.solvers.crank.frequencies import NaturalFrequencies
    from foundation_calc.solvers.crank.modes import PlaneModes


def scene_design_frequencies(scene, several: dict | None = None):
    """(zero-order, averaged, static) frequencies of a scene's mechanism on a frequency-dependent
    soil, each mode at its own frequency (ω = p(K(ω))); None on a frequency-independent soil.
    ``several``: receives mode -> every root of a mode with more than one
    (:func:`~foundation_calc.solvers.crank.natural.consistent_frequencies`; the averaged operator's,
    which the rule judges)."""
    if not scene.support().frequency_dependent:
        return None
    from foundation_calc.solvers.crank.natural import by_static_rank, consistent_frequencies, design_frequencies

    design = scene.design()
    static, static_averaged = design_frequencies(design)
    if design.coupled:  # the one model's modes, by rank as the block's are: one root of each
        ranked = by_static_rank(static)
        found = consistent_frequencies(static, lambda w: ranked(design_frequencies(scene.design(w))[1]),
                                       several=several)
        return found, found, static
    zero = consistent_frequencies(static, lambda w: design_frequencies(scene.design(w))[0])
    averaged = consistent_frequencies(static_averaged, lambda w: design_frequencies(scene.design(w))[1],
                                      several=several)
    return zero, averaged, static


def scene_frequencies(scene) -> NaturalFrequencies:
    """k0, p1, p2 [rad/s] of a ``crank_foundation`` scene's operator with the mechanism's inertia
    averaged, as its resonance check reports them (a machine given by its loads: its block's), on
    a frequency-dependent soil each at its own frequency: the modes its start-up passes."""
    if scene.mechanism is None:
        from foundation_calc.solvers.crank.loads import block_frequencies

        found = scene_block_frequencies(scene)
        return block_frequencies(scene.block()) if found is None else found[0]
    from foundation_calc.solvers.crank.natural import design_frequencies

    found = scene_design_frequencies(scene)
    return design_frequencies(scene.design())[1] if found is None else found[1]


def scene_block_frequencies(scene):
    """(frequencies, static) of a machine given by its loads on a frequency-dependent soil, each
    mode at its own frequency; None on a frequency-independent soil."""
    if not scene.support().frequency_dependent:
        return None
    from foundation_calc.solvers.crank.loads import block_frequencies
    from foundation_calc.solvers.crank.natural import consistent_frequencies

    static = block_frequencies(scene.block())
    return consistent_frequencies(static, lambda w: block_frequencies(scene.block(w))), static


def scene_plane_modes(scene, frequencies: Mapping[str, float]) -> PlaneModes:
    """The modes ``frequencies`` (name -> p [rad/s]) of a ``crank_foundation`` scene: of its block
    (:func:`~foundation_calc.solvers.crank.modes.plane_modes`), or, on a support coupling sway with
    rocking, of its one model in the plane (:func:`~foundation_calc.solvers.crank.modes.coupled_plane_modes`)."""
    from foundation_calc.solvers.crank.modes import coupled_plane_modes, plane_modes

    if scene.mechanism is not None and scene.design().coupled:
        return coupled_plane_modes(frequencies, lambda w: scene.design(w))
    return plane_modes(frequencies, scene.block)


__all__ = ["scene_block_frequencies", "scene_design_frequencies", "scene_frequencies", "scene_plane_modes"]
