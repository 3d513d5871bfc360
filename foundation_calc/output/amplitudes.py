"""``fcalc amplitudes`` of a scene of any kind: its JSON document and its tables. Every kind's
document and tables hold the same limit rows and code zones (:mod:`~foundation_calc.output.limits`);
a crank scene's add its approximations (the paper's first approximation, the averaged operator,
the exact solution with the closed forms' errors) of C in x, y, θ
(:mod:`~foundation_calc.output.crank_amplitudes`), a block's its modes and the harmonics of G and
its points in x, y, z per machine (:mod:`~foundation_calc.output.block`)."""

from __future__ import annotations


def amplitudes_document(report, scene, source: str) -> dict:
    """The JSON document of ``fcalc amplitudes`` (every number SI) of ``report``
    (:func:`~foundation_calc.checks.amplitudes.scene_amplitudes`)."""
    if scene.kind == "block_foundation":
        from foundation_calc.output import block as kind
    else:
        from foundation_calc.output import crank_amplitudes as kind
    return kind.amplitudes_document(report, scene, source)


def print_amplitudes(report, scene, source: str, units, all_points: bool = False, strict: bool = False) -> None:
    """The tables of ``fcalc amplitudes`` (numbers in ``units``); with more than
    :data:`~foundation_calc.output.limits.ALL_POINTS_UP_TO` points (and not ``all_points``) the
    governing points and the largest value/limit ratios."""
    if scene.kind == "block_foundation":
        from foundation_calc.output.block import print_amplitudes as tables

        tables(report, scene, source, units, strict, all_points)
    else:
        from foundation_calc.output.crank_amplitudes import print_amplitudes_report

        print_amplitudes_report(report, scene, source, units, all_points)


__all__ = ["amplitudes_document", "print_amplitudes"]
