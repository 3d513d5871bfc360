"""The resonance rule as a sheet states it: the definitions that make its margins reproducible.

Source: docs/resonance-rule.md (:mod:`~foundation_calc.checks.resonance.rule`,
:func:`~foundation_calc.solvers.crank.resonance.condition_margin`). A condition n ω = p has the
critical speed ω_c = p/n and the margin |ω − ω_c|/ω_c = |nω − p|/p (relative to the natural
frequency, not to the speed); a crank foundation has two estimates of p (the paper's zero-order
operator and the operator with the mechanism's averaged inertia) and its margin is measured to the
nearer critical speed. The sheet prints that critical speed beside the margin and the governing
condition's margin with its numbers substituted.
"""

from __future__ import annotations

from foundation_calc.checks.outcomes import RESONANCE_FAIL_MARGIN
from foundation_calc.checks.resonance.rule import FORCING_SHARE
from foundation_calc.output.report.numbers import figure, percent


def critical_speeds(row: dict) -> list[float]:
    """The critical speeds [rad/s] of a resonance row: the zero-order one, and the one with the
    averaged inertia when the row has it."""
    speeds = [row["critical_speed"]["omega"]]
    if "critical_speed_averaged_inertia" in row:
        speeds.append(row["critical_speed_averaged_inertia"]["omega"])
    return speeds


def measured_to(row: dict, omega: float) -> float:
    """The critical speed [rad/s] the row's margin is measured to: the nearer one to ``omega``
    [rad/s] in the sense of |ω − ω_c|/ω_c (:func:`~foundation_calc.solvers.crank.resonance.condition_margin`)."""
    return min(critical_speeds(row), key=lambda c: abs(omega - c) / c)


def margin_definition(speed: str) -> str:
    """What a margin is, for any scene kind; ``speed``: the operating speed as printed with its unit."""
    return (
        f"Margin of a condition nω = p: |ω − ω_c|/ω_c = |nω − p|/p, relative to the critical speed"
        f" ω_c = p/n (not to the speed), ω = {speed}."
    )


def crank_rule_paragraph(res: dict, convert, unit: str) -> str:
    """The rule under a crank foundation's resonance table, with the governing condition's margin
    substituted (``res``: the resonance document; ``convert``: rad/s -> the sheet's speed unit)."""
    omega = res["speed"]["omega"]
    text = [
        margin_definition(f"{figure(convert(omega), 4)} {unit}"),
        ("Critical and avg. inertia: p of the plane model with the mechanism's inertia averaged over a revolution"
         " and the support's sway-rocking coupling K_xφ (Methods; [KM] (4.5)-(4.7) take three uncoupled springs and"
         " do not apply), one value." if "K_xphi" in res["derived"] else
         "Critical: p from the zero-order operator, [KM] (4.5)-(4.7); avg. inertia: p with the mechanism's"
         " inertia averaged over a revolution; the margin is measured to the nearer of the two."),
        f"Forcing share of harmonic n on mode j: s_nj = w_nj / max w, w_nj = |φ_jᵀ F_n|/p_j, φ_j the mode"
        f" of M̄, K̄ normalised to unit modal mass (φ_jᵀ M̄ φ_j = 1), F_n the forcing of harmonic n (Methods);"
        f" the maximum is over every harmonic and mode, so the largest share is 1.",
        f"Judged: the paper's conditions and every condition whose forcing share reaches {FORCING_SHARE:.0%};"
        f" a judged condition fails inside the band of its order and, whatever the band, within"
        f" {RESONANCE_FAIL_MARGIN:.0%}; an order-1 condition not judged fails within {RESONANCE_FAIL_MARGIN:.0%}"
        " and warns inside its band. INFORMATION: inside its band, not judged; NOT JUDGED: outside its band"
        " and not judged.",
    ]
    governing = res["rule"].get("governing")
    row = next((r for r in res["resonances"] if governing and r["condition"] == governing["condition"]), None)
    if row is not None:
        c = measured_to(row, omega)
        needed = max(governing["required"], RESONANCE_FAIL_MARGIN)
        text.append(
            f"Governing (the worst verdict, then the smallest margin over the margin needed, its band but at"
            f" least {RESONANCE_FAIL_MARGIN:.0%}): {row['condition']}, |{figure(convert(omega), 4)} −"
            f" {figure(convert(c), 4)}|/{figure(convert(c), 4)} = {percent(governing['margin'])}"
            f" (needs {percent(needed)})."
        )
    text.append("docs/resonance-rule.md.")
    return " ".join(text)


__all__ = ["critical_speeds", "crank_rule_paragraph", "margin_definition", "measured_to"]
