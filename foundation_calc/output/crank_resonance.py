"""Report of ``fcalc resonance``: rich tables and the JSON document (SI units)."""

from __future__ import annotations

from collections.abc import Mapping

from foundation_calc.checks.crank_resonance import ResonanceReport
from foundation_calc.checks.outcomes import RESONANCE_FAIL_MARGIN
from foundation_calc.checks.resonance_rule import FORCING_SHARE, INFORMATION, STATUS_NAMES, bands_text
from foundation_calc.output.console import JSON_SCHEMA_VERSION, fmt, stdout, verdict_text
from foundation_calc.output.display_units import DisplayUnits
from foundation_calc.output.notes import print_soil_validity, soil_validity_document
from foundation_calc.solvers.crank.resonance import MODE_NAMES
from foundation_calc.units import hz_from_omega, rpm_from_omega, speed_triplet


#: How the table marks a condition's source.
SOURCE_TAGS = {"paper": "", "extra": " (extra)", "loads": " (loads)", "harmonic": "", "speed": ""}


def _frequencies(freqs) -> dict:
    return {"k0": freqs.k0, "p1": freqs.p1, "p2": freqs.p2}


def summary_line(report: ResonanceReport, strict: bool = False, units: DisplayUnits = DisplayUnits()) -> str:
    """One sentence: the verdict, the speed (in ``units``) and the governing resonance, as every
    command words it; then the near conditions that are not judged, as information."""
    speed = units.show("speed", report.omega)
    line = f"{verdict_text(report.outcome.value, strict)}: speed {speed}, {report.statement}"
    if report.modulus_range is not None:
        line += f" with the soil data as given; {report.modulus_range.text}"
    if report.information:
        line += "; information, not the verdict: " + ", ".join(row.phrase for row in report.information)
    return line


def rule_document(report: ResonanceReport) -> dict:
    """The rule as the scene set it (JSON): the forcing share a higher harmonic needs to be judged,
    the detuning (one band, or a band per order), and the governing condition."""
    detuning = report.detuning
    g = report.governing
    return {
        "forcing_share": FORCING_SHARE,
        "fail_margin": RESONANCE_FAIL_MARGIN,
        "detuning": {str(k): v for k, v in detuning.items()} if isinstance(detuning, Mapping) else detuning,
        "conditions_checked": report.conditions_checked,
        "governing": None if g is None else {"condition": g.condition.label, "margin": g.margin, "required": g.needed,
                                             "verdict": g.outcome.value},
    }


def resonance_document(report: ResonanceReport, scene, source: str) -> dict:
    """The JSON document of ``fcalc resonance`` (every number SI: rad/s, kg, m)."""
    d = report.design
    if d is None:  # a machine given by its loads: no mechanism
        block = scene.block()
        derived = {
            "total_mass": block.M_tot,
            "rho1": (block.I_c / block.M_tot) ** 0.5,
            "rocking_stability_margin": report.stability_margin,
        }
    else:
        derived = {
            "mu": d.mu,
            "lambda": d.lam,
            "total_mass": d.M_tot,
            "moving_mass": d.rod.m,
            "rho1": d.rho1_sq**0.5,
            "kappa": d.rod.kappa,
            "rocking_stability_margin": report.stability_margin,
        }
    return {
        "schema_version": JSON_SCHEMA_VERSION,
        "command": "resonance",
        "scene": {"source": source, "kind": scene.kind, "name": scene.name},
        "speed": {**speed_triplet(report.omega), "given_as": scene.speed.speed_given_as},
        "derived": derived,
        "natural_frequencies": _frequencies(report.zero_order),
        "natural_frequencies_averaged_inertia": _frequencies(report.averaged),
        "natural_frequencies_static_springs": None if report.static is None else _frequencies(report.static),
        "resonances": [
            {
                "condition": row.condition.label,
                "harmonic": row.condition.harmonic,
                "mode": row.condition.mode,
                "mode_name": MODE_NAMES[row.condition.mode],
                "source": row.condition.source,
                "excitation": row.condition.excitation,
                "critical_speed": speed_triplet(row.critical_zero_order),
                "critical_speed_averaged_inertia": speed_triplet(row.critical_averaged),
                "margin": row.margin,
                "required": row.required,
                "forcing_share": row.share,
                "judged": row.judged,
                "status": STATUS_NAMES[row.status],
                "verdict": row.outcome.value,
            }
            for row in report.rows
        ],
        "rule": rule_document(report),
        "modulus_range": None if report.modulus_range is None else report.modulus_range.document(),
        "soil_validity": soil_validity_document(report.soil_validity),
        "warnings": scene.plausibility_warnings(),
        "verdict": report.outcome.value,
    }


def print_resonance_report(
    report: ResonanceReport, scene, source: str, units: DisplayUnits = DisplayUnits(), strict: bool = False
) -> None:
    """Print the tables of ``fcalc resonance``."""
    from rich.markup import escape
    from rich.table import Table

    d, w = report.design, report.omega
    out = stdout()
    title = scene.name or source
    out.print(
        f"[bold]{escape(title)}[/]  speed {fmt(w)} rad/s = {fmt(hz_from_omega(w))} Hz"
        f" = {fmt(rpm_from_omega(w))} rpm (given as {scene.speed.speed_given_as})"
    )

    design = Table(title="Design", title_justify="left")
    for col in ("quantity", "value", "unit"):
        design.add_column(col, justify="right" if col == "value" else "left")
    if d is None:
        block = scene.block()
        design.add_row("M_tot, total mass (machine given by its loads)", fmt(block.M_tot), "kg")
        design.add_row("ρ1 = sqrt(I_c/M_tot)", fmt((block.I_c / block.M_tot) ** 0.5, 4), "m")
    else:
        design.add_row("μ = m/M_tot, moving-mass ratio", fmt(d.mu, 4), "-")
        design.add_row("λ = r/l, crank-to-rod ratio", fmt(d.lam, 4), "-")
        design.add_row("M_tot, total mass", fmt(d.M_tot), "kg")
        design.add_row("ρ1 = sqrt(I_c/M_tot)", fmt(d.rho1_sq**0.5, 4), "m")
    design.add_row("rocking stability margin c_φ·I1/(P·h) - 1", fmt(report.stability_margin, 4), "-")
    out.print(design)

    dependent = report.static is not None
    freqs = Table(title="Natural frequencies" + (", each on the soil's springs at its own frequency" if dependent else ""),
                  title_justify="left")
    freqs.add_column("mode")
    for col in ("rad/s", "Hz", "rpm", f"{units.label('speed')}, averaged inertia"):
        freqs.add_column(col, justify="right")
    if dependent:
        freqs.add_column(f"{units.label('speed')}, static springs", justify="right")
    for mode in ("k0", "p1", "p2"):
        w0, w1 = getattr(report.zero_order, mode), getattr(report.averaged, mode)
        static = (fmt(units.convert("speed", getattr(report.static, mode)), 6),) if dependent else ()
        freqs.add_row(
            f"{mode} ({MODE_NAMES[mode]})", fmt(w0, 6), fmt(hz_from_omega(w0)), fmt(rpm_from_omega(w0)),
            fmt(units.convert("speed", w1), 6), *static,
        )
    out.print(freqs)

    res = Table(title="Resonances (critical speeds)", title_justify="left")
    res.add_column("condition")
    res.add_column("mode")
    speed = units.label("speed")
    for col in (speed, f"{speed}, avg. inertia", "margin", "required"):
        res.add_column(col, justify="right")
    res.add_column("forcing share", justify="right")
    res.add_column("verdict")
    for row in report.rows:
        label = row.condition.label + SOURCE_TAGS[row.condition.source]
        res.add_row(
            label + (" *" if row is report.governing else ""),
            MODE_NAMES[row.condition.mode],
            fmt(units.convert("speed", row.critical_zero_order)),
            fmt(units.convert("speed", row.critical_averaged)),
            f"{row.margin:.1%}",
            f"{row.required:.0%}" if row.required > 0.0 else "none",
            f"{row.share:.2g}",
            verdict_text(row.outcome.value) if row.judged or row.status > INFORMATION else
            ("information" if row.information else "not judged"),
        )
    out.print(res)
    out.print(
        f"* governs. Judged: the paper's conditions and every harmonic whose forcing share reaches"
        f" {FORCING_SHARE:.0%}; required: the band of the condition's order (\\[limits] detuning = {bands_text(report.detuning)})."
        " The rule: docs/resonance-rule.md.", soft_wrap=True,
    )
    print_soil_validity(report.soil_validity)
    out.print(summary_line(report, strict, units), soft_wrap=True)
