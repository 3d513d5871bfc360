"""The resonance check of a scene of any kind (``fcalc resonance``): one report,
:class:`~foundation_calc.checks.resonance.ResonanceReport`, judged by the one rule, whose
sections the kinds fill differently (:mod:`~foundation_calc.checks.resonance`). Above both kinds'
modules, which build on ``checks/resonance.py``: the one place the resonance check tells them apart.
"""

from __future__ import annotations


def scene_resonances(scene):
    """The resonance report of a crank or block scene, with its soil's modulus range and soil
    validity: a block's six modes (:func:`~foundation_calc.checks.block.check_block`), the plane
    model's (:func:`~foundation_calc.checks.crank_resonance.check_scene_resonances`)."""
    if scene.kind == "block_foundation":
        from foundation_calc.checks.block import check_block

        return check_block(scene).resonance
    from foundation_calc.checks.crank_resonance import check_scene_resonances

    return check_scene_resonances(scene)


__all__ = ["scene_resonances"]
