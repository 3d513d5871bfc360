"""The office's own rules (``fcalc.toml`` ``[require]``, or a scene's ``[require]``) as a check.

- ``soil_bracketing``: a scene on soil gives ``[soil] modulus_range``, so that its checks hold over
  a range of the soil's stiffness, not at one value. ACI 351.3R-18 (Foundations for Dynamic
  Equipment), ch. 3 and 4: the soil's dynamic properties are uncertain and the response should be
  computed for a range of them (upper and lower bounds). Without the range the check **fails**.
"""

from __future__ import annotations

from dataclasses import dataclass

from foundation_calc.checks.outcomes import Outcome

#: Where the rule comes from, as the check's row names it.
RULE = "[require] soil_bracketing"
SOURCE = "ACI 351.3R-18, ch. 3-4 (a range of soil properties)"


@dataclass(frozen=True)
class RequirementRow:
    """One office rule on one scene: the rule, what the scene gives, the outcome."""

    rule: str
    given: str
    outcome: Outcome
    source: str


def requirement_rows(scene) -> list[RequirementRow]:
    """The office rules in force on ``scene`` and whether it meets them (empty without any)."""
    require = getattr(scene, "require", None)
    soil = getattr(scene, "soil", None)
    if require is None or not require.soil_bracketing or soil is None:
        return []
    bracket = soil.modulus_range
    given = "[soil] modulus_range not given" if bracket is None else f"[soil] modulus_range = [{bracket[0]:g}, {bracket[1]:g}]"
    return [RequirementRow(RULE, given, Outcome.FAIL if bracket is None else Outcome.PASS, SOURCE)]
