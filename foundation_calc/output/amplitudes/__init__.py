"""``fcalc amplitudes`` of a scene of any kind: its JSON document and its tables.

Every kind's document and tables are written here around the same judged part: the limit rows,
the code's zones and their supports, the code's warnings, the amplitudes over the soil's modulus
range, the soil model's validity and the verdict (:mod:`~foundation_calc.output.limits`,
:mod:`~foundation_calc.output.notes`). What a kind shows of its motion is its sections module's:
a crank scene's approximations of C in x, y, θ (:mod:`~foundation_calc.output.amplitudes.approximations`), a
block's modes and every machine's harmonics of G and its points in x, y, z
(:mod:`~foundation_calc.output.amplitudes.machines`). A sections module gives every name of
:data:`SECTIONS`.
"""

from __future__ import annotations

from foundation_calc.output.console import stdout
from foundation_calc.output.limits import code_document, limits_document, limits_table, summarised, zones_table
from foundation_calc.output.notes import print_soil_validity, print_supports, soil_validity_document


#: What a kind's sections module gives: its points' directions, the code document's per-direction
#: values (:func:`~foundation_calc.output.limits.code_document`), its parts of the JSON document,
#: its heading and motion, the limits table's title, what follows the zones, what follows the
#: code's warnings, the verdict line.
SECTIONS = ("DIRECTIONS", "CODE_DIRECTIONS", "document_parts", "print_motion", "limits_title", "print_after_zones",
            "print_notes", "verdict_line")


def _sections(scene):
    """The sections module of ``scene``'s kind."""
    if scene.kind == "block_foundation":
        from foundation_calc.output.amplitudes import machines

        return machines
    from foundation_calc.output.amplitudes import approximations

    return approximations


def amplitudes_document(report, scene, source: str) -> dict:
    """The JSON document of ``fcalc amplitudes`` (every number SI) of ``report``
    (:func:`~foundation_calc.checks.amplitudes.scene_amplitudes`): the kind's motion, the limit
    rows and the code's zones, the kind's judged extras (a crank's resonance rule, a block's office
    rows for information: ``fcalc check`` judges them), the amplitudes over the soil's modulus
    range, the soil's notes, the kind's further sections (a block's periodic inertia), the verdict
    (the amplitudes' alone) and a crank's exact solver's record."""
    kind = _sections(scene)
    doc, judged, further, solver = kind.document_parts(report, scene, source)
    doc["limits"] = limits_document(report.limit_rows)
    doc["code"] = code_document(scene.limits, report.zone_rows, report.code_warnings, kind.CODE_DIRECTIONS)
    doc |= judged
    doc["modulus_range"] = None if report.amplitude_range is None else report.amplitude_range.document()
    doc["soil_validity"] = soil_validity_document(report.soil_validity)
    doc["warnings"] = scene.plausibility_warnings()
    doc |= further
    doc["verdict"] = report.amplitude_outcome.value
    return doc | solver


def print_amplitudes(report, scene, source: str, units, all_points: bool = False, strict: bool = False) -> None:
    """The tables of ``fcalc amplitudes`` (numbers in ``units``; JSON stays SI): the kind's heading
    and motion, every limit row (or with more than :data:`~foundation_calc.output.limits.ALL_POINTS_UP_TO`
    points, and not ``all_points``, the largest value/limit ratios), the code's zones and
    supports, the code's warnings, the soil's notes and the verdict line."""
    kind = _sections(scene)
    out = stdout()
    if not kind.print_motion(report, scene, source, units, all_points):
        return
    if report.limit_rows:
        out.print(limits_table(report.limit_rows, units, kind.limits_title(report),
                               summarised(len(scene.points), all_points), strict, None if out.piped else out.width))
    if report.zone_rows:
        out.print(*zones_table(report.zone_rows, units, kind.DIRECTIONS, strict))
        print_supports(report.zone_rows)
    kind.print_after_zones(report, units)
    from rich.text import Text

    for warning in report.code_warnings:  # a machine's speed or power outside the code's group: the verdict warns
        out.print(Text(f"warning: {warning}", style="yellow"))
    kind.print_notes(report, strict)
    print_soil_validity(report.soil_validity)
    out.print(kind.verdict_line(report, strict))


__all__ = ["SECTIONS", "amplitudes_document", "print_amplitudes"]
