"""The sheet's validity of the models, evaluated: the soil method's a0 at every judged mode and
harmonic against the range it was fitted over, and the caveat of a vibration code's zones.

Read from the documents the checks judged: the ``resonance`` document's ``soil_validity``
(:mod:`~foundation_calc.checks.soil_validity`: a0 = ω b/V_s of every motion whose spring matters
at each judged frequency, the method's definition of b, its range and the range's source) and the
scene's ``[limits] code`` (:data:`~foundation_calc.checks.codes.ZONE_CAVEAT`, the same words as
``fcalc check``'s note). Each a0 is printed with the values it is formed of, so that a checker
repeats it from the sheet.
"""

from __future__ import annotations

from foundation_calc.output.report.model import Paragraph, Section, table
from foundation_calc.output.report.numbers import figure

#: Significant figures of the a0 table's numbers.
DIGITS = 4


def _soil_blocks(validity: dict) -> list:
    """The a0 table (or why no range applies) of a ``soil_validity`` document."""
    if validity["a0_max"] is None:
        return [Paragraph(f"Soil model {validity['method']!r}: {validity['source']}.")]
    top, V_s = validity["a0_max"], validity["shear_wave_velocity"]
    rows = [
        (v["at"], v["motion"], figure(v["omega"], DIGITS), figure(v["length"], DIGITS),
         f"{figure(v['omega'], DIGITS)} × {figure(v['length'], DIGITS)} / {figure(V_s, DIGITS)}", figure(v["a0"], DIGITS),
         "within" if v["a0"] <= top else "BEYOND")
        for v in validity["values"]
    ]
    head = (f"Soil model {validity['method']!r}: {validity['definition']}, V_s = {figure(V_s, DIGITS)} m/s; fitted for"
            f" a0 ≤ {top:g} ({validity['source']}). a0 at every judged mode (the motions holding ≥ 1 % of its strain"
            " energy) and every judged order nω (every motion)")
    verdict = ("every a0 lies within the fitted range." if not validity["beyond"] else
               f"{len(validity['beyond'])} a0 beyond the fitted range: the springs and dashpots there are extrapolated;"
               " the verdict does not change, the margin of those frequencies is uncertain.")
    return [table(head, ("at", "motion", "ω [rad/s]", "b [m]", "ω × b / V_s", "a0 [-]", "range"), rows,
                  (False, False, True, True, False, True, False)), Paragraph(f"Soil model: {verdict}")]


def validity_section(scene, documents: dict) -> Section | None:
    """The section, or None when the scene has neither a soil model's range nor a code's zones."""
    from foundation_calc.checks.codes import ZONE_CAVEAT

    blocks: list = []
    validity = (documents.get("resonance") or {}).get("soil_validity")
    if validity is not None:
        blocks += _soil_blocks(validity)
    code = getattr(scene.limits, "code", None)
    if code:
        blocks.append(Paragraph(f"Vibration code ({code}): caveat. {ZONE_CAVEAT}. [ISO]"))
    return Section("Validity of the models", tuple(blocks)) if blocks else None


__all__ = ["validity_section"]
