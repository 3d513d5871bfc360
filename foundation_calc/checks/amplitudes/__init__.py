"""The amplitude check of a scene of any kind (``fcalc amplitudes``): the periodic steady state of
its points against ``[limits]`` and a vibration code, judged by one set of rules.

Every kind's report is assembled from what its motion gives: the names of its points (the centre
of mass first), their directions and their peaks and RMS values per direction as arrays (points,
directions) [m, m/s, m/s²]; :func:`~foundation_calc.checks.amplitudes.report.judge` turns them into
the limit rows (:func:`~foundation_calc.checks.limits.limit_rows`), the code's zone rows
(:func:`~foundation_calc.checks.codes.zone_rows`) and the code's warnings
(:func:`~foundation_calc.checks.codes.code_warnings`), and
:class:`~foundation_calc.checks.amplitudes.report.AmplitudeVerdict` gives every report the same
verdict (:func:`~foundation_calc.checks.limits.amplitude_outcome`). A kind adds its own sections as
data: a crank scene's report (:class:`~foundation_calc.checks.amplitudes.approximations.AmplitudeReport`) the
paper's approximations of its mechanism, a block's (:class:`~foundation_calc.checks.amplitudes.machines.BlockReport`)
its six modes, every machine's harmonics and its machines' periodic inertia. Both give
``limit_rows``, ``zone_rows``, ``code_warnings``, ``amplitude_range``, ``soil_validity``,
``resonant`` and ``amplitude_outcome``, and the ``wording``
(:class:`~foundation_calc.checks.limits.AmplitudeWording`) in which ``fcalc check`` states them.
"""

from __future__ import annotations


def scene_amplitudes(scene, exact: bool = False):
    """The amplitude report of ``scene``; ``exact``: a crank's mechanism also by the exact periodic
    solution, which then judges the limits; a block's machines with periodic inertia always get
    theirs beside the first approximation, and ``exact`` judges the limits with it in place of
    those machines' first approximation."""
    if scene.kind == "block_foundation":
        from foundation_calc.checks.amplitudes.machines import check_block

        return check_block(scene, periodic=True, exact=exact)
    from foundation_calc.checks.amplitudes.approximations import check_scene_amplitudes

    return check_scene_amplitudes(scene, exact=exact)


__all__ = ["scene_amplitudes"]
