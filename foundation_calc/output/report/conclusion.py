"""The conclusion of a calculation sheet in words, and on a failure what to change.

Read from the check results (the JSON documents of ``fcalc check --json``), never from the
sheet's text:

- a resonance condition n ω = p that fails or warns (docs/resonance-rule.md: margin
  |ω − ω_c|/ω_c with ω_c = p/n, needed d = its band, at least
  :data:`~foundation_calc.checks.outcomes.RESONANCE_FAIL_MARGIN`): with the mode below the forcing
  (ω_c < ω) p must fall to n ω/(1 + d), a softer support or a heavier block; with the mode above,
  p must rise to n ω/(1 − d), a stiffer support or a lighter block (p ∝ √(k/m));
- a limit that fails: the governing row (largest demand/limit) and the factor by which the
  demand must fall;
- every other failing or warning check: its own reason.

The scene file's leading comment goes on the sheet when it says the data are not real.
"""

from __future__ import annotations

import re

from foundation_calc.checks.outcomes import RESONANCE_FAIL_MARGIN
from foundation_calc.output.report.model import Paragraph, Section
from foundation_calc.output.report.numbers import percent, quantity
from foundation_calc.output.report.resonance_text import measured_to
from foundation_calc.output.report.verdict import check_reason, quantity_name, scene_verdict

#: Words by which a scene's leading comment says that its data are not real.
NOT_REAL = re.compile(r"\b(contrived|fictitious|not real|invented|made[- ]up)\b", re.IGNORECASE)


def leading_comment(text: str) -> str:
    """The comment block at the top of a TOML file, its ``#`` marks removed, lines joined."""
    lines = []
    for line in text.splitlines():
        stripped = line.strip()
        if not stripped.startswith("#"):
            break
        lines.append(stripped.lstrip("#").strip())
    return " ".join(x for x in lines if x)


def not_real_note(text: str) -> str | None:
    """The scene's leading comment when it says the data are not real ("contrived"), else None."""
    comment = leading_comment(text)
    return comment if NOT_REAL.search(comment) else None


def resonance_change(row: dict, omega: float, units) -> str:
    """What a failing or warning condition n ω = p needs: the side of the forcing its mode lies on
    and the change of p [%] that reaches the margin needed (module docstring)."""
    critical = measured_to(row, omega)
    needed = max(row["required"], RESONANCE_FAIL_MARGIN)
    below = critical < omega
    target = omega / (1.0 + needed) if below else omega / (1.0 - needed)
    change = target / critical - 1.0
    side = (
        "below the forcing: lower p (a softer support or a heavier block, p ∝ √(k/m))" if below
        else "above the forcing: raise p (a stiffer support or a lighter block, p ∝ √(k/m))"
    )
    return (
        f"{row['condition']} ({row['mode_name']}): critical speed {quantity(units, 'speed', critical)} against"
        f" {quantity(units, 'speed', omega)}, margin {percent(row['margin'])}, needs {percent(needed)}; the mode lies"
        f" {side} by {percent(abs(change))}, to a critical speed of {quantity(units, 'speed', target)} or"
        f" {'lower' if below else 'higher'}."
    )


def _resonance_advice(doc: dict, units) -> list[str]:
    crank = doc.get("speed", {}).get("omega")
    machines = doc.get("machines", {})
    out = []
    for row in doc.get("resonances", ()):
        if row["verdict"] in ("fail", "warn") and (row["judged"] or row["status"] in ("warn", "fail")):
            omega = crank if crank is not None else machines.get(row.get("machine"), {}).get("omega")
            if omega is not None:
                out.append(resonance_change(row, omega, units))
    return out


def _limit_advice(doc: dict, units) -> list[str]:
    from foundation_calc.checks.limits import display_quantity

    failing = [r for r in doc.get("limits", ()) if r["verdict"] in ("fail", "warn") and r.get("limit")]
    if not failing:
        return []
    r = max(failing, key=lambda row: row["ratio"])
    kind = display_quantity(r["quantity"]) if "quantity" in r else "amplitude"
    what = f"{r['point']}, {r['direction']}: {quantity_name(r['quantity'])}" if "quantity" in r else f"{r['point']} ({r.get('run', 'run')})"
    return [
        f"Governing limit: {what} = {quantity(units, kind, r['value'])} against {quantity(units, kind, r['limit'])},"
        f" ratio {r['ratio']:.2f}: the demand must fall by a factor {r['ratio']:.2f} (by {percent(1.0 - 1.0 / r['ratio'])});"
        " move the modes further from the forcing orders, add mass or damping, or reduce the forcing"
        " (balance grade, the vendor's loads)."
    ]


def conclusion_section(runs, documents: dict, units, note: str | None = None, unbracketed: bool = False,
                       sizing: tuple = ()) -> Section:
    """The verdict in words, what to change on a failure (with ``sizing``, the blocks of the sizing
    the scene asks for, :func:`~foundation_calc.output.report.sizing.sizing_blocks`), and the
    scene's own note on its data."""
    verdict = scene_verdict(runs)
    failing = [run for run in runs if run.verdict == "fail"]
    warning = [run for run in runs if run.verdict == "warn"]
    if verdict == "fail":
        words = (f"The foundation does not satisfy the checks: {', '.join(r.check for r in failing)} fail"
                 f"{'s' * (len(failing) == 1)}. It is not adequate as calculated; what to change follows.")
    elif verdict == "warn":
        words = (f"The foundation satisfies every check that can fail; {', '.join(r.check for r in warning)}"
                 " warn" + "s" * (len(warning) == 1) + ": the engineer judges each warning (listed under Checks).")
    else:
        words = "The foundation satisfies every check fcalc check runs on the scene, with the limits and data given."
    blocks = [Paragraph(words)]
    if unbracketed:
        blocks.append(Paragraph(
            "The soil was not bracketed: the scene gives no [soil] modulus_range, so the checks hold for its"
            " single soil stiffness only; ACI 351.3R-18 asks for the dynamic response over a range of the soil's"
            " properties (a lower and an upper bound)."
        ))
    for run in failing + warning:
        doc = documents.get(run.check, {})
        advice = []
        if run.check == "resonance":
            advice = _resonance_advice(doc, units)
        elif run.check in ("amplitudes", "runup"):
            advice = _limit_advice(doc, units)
        if not advice:
            advice = [check_reason(run, units)]
        blocks += [Paragraph(f"{run.check} ({run.verdict.upper()}): {a}") for a in advice]
    blocks += sizing
    if note:
        blocks.append(Paragraph(f"The scene file says of its data: \"{note}\""))
    return Section("Conclusion", tuple(blocks))
