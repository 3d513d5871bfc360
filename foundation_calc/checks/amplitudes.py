"""The amplitude check of a scene of any kind (``fcalc amplitudes``): the periodic steady state of
its points against ``[limits]`` and a vibration code, judged by one set of rules
(:func:`~foundation_calc.checks.limits.limit_rows`, :func:`~foundation_calc.checks.codes.zone_rows`,
:func:`~foundation_calc.checks.limits.amplitude_outcome`). A crank scene's report
(:class:`~foundation_calc.checks.crank_amplitudes.AmplitudeReport`) adds the paper's
approximations of its mechanism; a block's (:class:`~foundation_calc.checks.block.BlockReport`)
its six modes and every machine's harmonics. Both give ``limit_rows``, ``zone_rows``,
``code_warnings``, ``amplitude_range``, ``soil_validity``, ``resonant`` and ``amplitude_outcome``,
and the ``wording`` (:class:`~foundation_calc.checks.limits.AmplitudeWording`) in which
``fcalc check`` states them.
"""

from __future__ import annotations


def scene_amplitudes(scene, exact: bool = False):
    """The amplitude report of ``scene``; ``exact``: a crank's mechanism also by the exact periodic
    solution, which then judges the limits (a block's machines with periodic inertia always get
    theirs beside the first approximation that is judged)."""
    if scene.kind == "block_foundation":
        from foundation_calc.checks.block import check_block

        return check_block(scene, periodic=True)
    from foundation_calc.checks.crank_amplitudes import check_scene_amplitudes

    return check_scene_amplitudes(scene, exact=exact)


__all__ = ["scene_amplitudes"]
