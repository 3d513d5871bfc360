"""Report of ``fcalc resonance`` for every scene kind: the JSON document and the tables (SI units).

One :class:`~foundation_calc.checks.resonance.report.ResonanceReport`, one document and one set of
tables; the kinds differ only in which sections have content. A crank-mechanism foundation (the
paper's plane model) shows its derived quantities (μ, λ, ρ1, κ), the paper's closed-form k0, p1,
p2 beside the averaged-inertia ones and each condition's two critical speeds; a block foundation
shows its machines, its mass and centre of mass, the six modes with their shapes, and each
condition's machine and mode.
"""

from __future__ import annotations

from collections.abc import Mapping

import numpy as np

from foundation_calc.checks.outcomes import RESONANCE_FAIL_MARGIN
from foundation_calc.checks.resonance.report import ResonanceReport
from foundation_calc.checks.resonance.rule import FORCING_SHARE, INFORMATION, bands_text
from foundation_calc.output.console import (
    JSON_SCHEMA_VERSION, fmt, fmt_scaled, names_whole, stdout, titled_table, verdict_text,
)
from foundation_calc.output.display_units import DisplayUnits
from foundation_calc.output.notes import print_soil_validity, soil_validity_document
from foundation_calc.solvers.crank.frequencies import stability_margin_formula
from foundation_calc.solvers.crank.resonance import MODE_NAMES
from foundation_calc.units import hz_from_omega, rpm_from_omega, speed_triplet

#: What each dominant motion of a block's mode is called in tables.
MOTION_NAMES = {
    "x": "sliding x (with rocking)", "y": "sliding y (with rocking)", "z": "vertical",
    "rx": "rocking about x", "ry": "rocking about y", "rz": "torsion about z",
}

#: How the plane model's table marks a condition's source.
SOURCE_TAGS = {"paper": "", "extra": " (extra)", "loads": " (loads)", "harmonic": "", "speed": ""}


def _frequencies(freqs) -> dict:
    return {"k0": freqs.k0, "p1": freqs.p1, "p2": freqs.p2}


def modes_document(modes) -> list[dict]:
    """Each mode of a block; ``static_frequency`` on the static springs beside the
    frequency-consistent one (None on a frequency-independent soil)."""
    return [
        {"mode": j + 1, "frequency": speed_triplet(float(p)), "dominant": modes.dominant[j],
         "dominant_name": MOTION_NAMES[modes.dominant[j]], "damping_ratio": float(modes.damping[j]),
         "static_frequency": None if modes.static is None else speed_triplet(float(modes.static[j])),
         "shape": [float(v) for v in modes.shapes[:, j]]}
        for j, p in enumerate(modes.frequencies)
    ]


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
        "governing": None if g is None else {"condition": g.label, "margin": g.margin, "required": g.needed,
                                             "verdict": g.outcome.value},
    }


def _derived(report: ResonanceReport, scene) -> dict:
    """The plane model's derived quantities (a machine given by its loads: its block's)."""
    d = report.design
    if d is None:
        block = scene.block()
        return {"total_mass": block.M_tot, "rho1": (block.I_c / block.M_tot) ** 0.5,
                "rocking_stability_margin": report.stability_margin}
    coupling = {"K_xphi": d.K_xphi} if d.K_xphi != 0.0 else {}  # the margin's reduction, a coupled support only
    return {"mu": d.mu, "lambda": d.lam, "total_mass": d.M_tot, "moving_mass": d.rod.m, "rho1": d.rho1_sq**0.5,
            "kappa": d.rod.kappa, **coupling, "rocking_stability_margin": report.stability_margin}


def _row_document(row, per_machine: bool) -> dict:
    """One condition (JSON); the block's rows name their machine and mode, the plane model's their
    source and both critical speeds."""
    if per_machine:
        return {"condition": row.label, "mode_name": MOTION_NAMES[row.motion], "machine": row.machine,
                "order": row.order, "mode": row.mode, "dominant": row.motion,
                "critical_speed": speed_triplet(row.critical), "margin": row.margin, "forcing_share": row.share,
                "judged": row.judged, "required": row.required, "status": row.status_name,
                "verdict": row.outcome.value}
    c = row.condition
    return {"condition": row.label, "harmonic": row.order, "mode": row.mode, "mode_name": MODE_NAMES[row.mode],
            "source": c.source, "excitation": c.excitation, "critical_speed": speed_triplet(row.critical),
            "critical_speed_averaged_inertia": speed_triplet(row.critical_averaged), "margin": row.margin,
            "required": row.required, "forcing_share": row.share, "judged": row.judged, "status": row.status_name,
            "verdict": row.outcome.value}


def resonance_document(report: ResonanceReport, scene, source: str, command: str = "resonance") -> dict:
    """The JSON document of ``fcalc resonance`` (every number SI: rad/s, kg, m); ``command``: the
    command whose document starts with it (a block's ``amplitudes``)."""
    doc = {"schema_version": JSON_SCHEMA_VERSION, "command": command,
           "scene": {"source": source, "kind": scene.kind, "name": scene.name}}
    if report.per_machine:
        doc |= {
            "machines": {name: speed_triplet(w) for name, w in report.speeds.items()},
            "total_mass": report.total_mass,
            "centre_of_mass": [float(v) for v in report.cog],
            "modes": modes_document(report.modes),
        }
    else:
        doc |= {
            "speed": {**speed_triplet(report.omega), "given_as": scene.speed.speed_given_as},
            "derived": _derived(report, scene),
            "natural_frequencies": _frequencies(report.zero_order),
            "natural_frequencies_averaged_inertia": _frequencies(report.averaged),
            "natural_frequencies_static_springs": None if report.static is None else _frequencies(report.static),
        }
    doc["resonances"] = [_row_document(row, report.per_machine) for row in report.rows]
    if not report.per_machine:
        doc["rule"] = rule_document(report)
    doc["modulus_range"] = None if report.modulus_range is None else report.modulus_range.document()
    notes = {"soil_validity": soil_validity_document(report.soil_validity), "warnings": scene.plausibility_warnings()}
    doc |= dict(reversed(notes.items())) if report.per_machine else notes  # each kind's recorded order
    if report.several_roots:  # a mode with several roots of ω = p(K(ω)): said only then
        doc["several_roots"] = list(report.several_roots)
    doc["verdict"] = report.outcome.value
    return doc


def summary_line(report: ResonanceReport, strict: bool = False, units: DisplayUnits = DisplayUnits()) -> str:
    """One sentence: the verdict and the governing resonance, as every command words it (the plane
    model: with its speed, in ``units``, and the near conditions that are not judged, as
    information)."""
    verdict = verdict_text(report.outcome.value, strict)
    if report.per_machine:
        return f"{verdict}: {report.text}"
    line = f"{verdict}: speed {units.show('speed', report.omega)}, {report.text}"
    if report.information:
        line += "; information, not the verdict: " + ", ".join(row.phrase for row in report.information)
    return line


def speeds_line(report, scene, source: str, units: DisplayUnits) -> str:
    """A block's heading: its machines' speeds and its total mass (``report``: anything with
    ``speeds`` and ``total_mass``)."""
    from rich.markup import escape

    speeds = ", ".join(f"{escape(n)} {units.show('speed', w)}" for n, w in report.speeds.items())
    return f"[bold]{escape(scene.name or source)}[/]  machines: {speeds}; total mass {fmt(report.total_mass)} kg"


def print_modes(modes, units: DisplayUnits) -> None:
    """A block's six modes: dominant motion, frequency, damping ratio (and on the static springs)."""
    speed = units.label("speed")
    title = "Natural frequencies (6-DOF, undamped)"
    columns = ["mode", "dominant motion", "Hz", speed, "damping ratio"]
    if modes.static is not None:
        title += ": each mode with the support's springs at its own frequency, beside the static springs'"
        columns.append(f"static, {speed}")
    t = titled_table(title, columns, columns[2:])
    for j, p in enumerate(modes.frequencies):
        t.add_row(str(j + 1), MOTION_NAMES[modes.dominant[j]], fmt(p / (2 * np.pi)), fmt(units.convert("speed", p)),
                  fmt(modes.damping[j], 3), *(() if modes.static is None else (fmt(units.convert("speed", modes.static[j])),)))
    out = stdout()
    out.print(*names_whole(t, out.width, ("dominant motion",)))


def _print_plane(report: ResonanceReport, scene, source: str, units: DisplayUnits) -> None:
    """The plane model's heading, derived quantities and frequencies k0, p1, p2."""
    from rich.markup import escape

    d, w = report.design, report.omega
    out = stdout()
    out.print(
        f"[bold]{escape(scene.name or source)}[/]  speed {fmt(w)} rad/s = {fmt(hz_from_omega(w))} Hz"
        f" = {fmt(rpm_from_omega(w))} rpm (given as {scene.speed.speed_given_as})"
    )
    design = titled_table("Design", ("quantity", "value", "unit"), ("value",))
    if d is None:
        block = scene.block()
        design.add_row("M_tot, total mass (machine given by its loads)", fmt(block.M_tot), "kg")
        design.add_row("ρ1 = sqrt(I_c/M_tot)", fmt((block.I_c / block.M_tot) ** 0.5, 4), "m")
    else:
        design.add_row("μ = m/M_tot, moving-mass ratio", fmt(d.mu, 4), "-")
        design.add_row("λ = r/l, crank-to-rod ratio", fmt(d.lam, 4), "-")
        design.add_row("M_tot, total mass", fmt(d.M_tot), "kg")
        design.add_row("ρ1 = sqrt(I_c/M_tot)", fmt(d.rho1_sq**0.5, 4), "m")
    coupled = d is not None and d.K_xphi != 0.0
    if coupled:
        design.add_row("K_xφ, the support's sway-rocking coupling", fmt(d.K_xphi, 4), "N/rad")
    design.add_row(f"rocking stability margin {stability_margin_formula(coupled)}", fmt(report.stability_margin, 4), "-")
    out.print(design)

    dependent = report.static is not None
    columns = ["mode", "rad/s", "Hz", "rpm", f"{units.label('speed')}, averaged inertia"]
    if dependent:
        columns.append(f"{units.label('speed')}, static springs")
    freqs = titled_table("Natural frequencies" + (", each on the support's springs at its own frequency" if dependent else ""),
                         columns, columns[1:])
    for mode in ("k0", "p1", "p2"):
        w0, w1 = getattr(report.zero_order, mode), getattr(report.averaged, mode)
        static = (fmt(units.convert("speed", getattr(report.static, mode)), 6),) if dependent else ()
        freqs.add_row(f"{mode} ({MODE_NAMES[mode]})", fmt(w0, 6), fmt(hz_from_omega(w0)), fmt(rpm_from_omega(w0)),
                      fmt(units.convert("speed", w1), 6), *static)
    out.print(freqs)


def _status(row, strict: bool) -> str:
    """A block's condition as the rule takes it: ``info`` for a higher order under the forcing
    share inside its band, ``not judged`` for one outside it, else its verdict (rules 1-4 of
    :mod:`~foundation_calc.checks.resonance.rule`: the speed itself always decides)."""
    if row.information:
        return "info"
    return verdict_text(row.outcome.value, strict) if row.judged or row.order == 1 else "not judged"


def _conditions_table(report: ResonanceReport, units: DisplayUnits, strict: bool):
    """Every condition shown: the block's by machine, order and mode; the plane model's by its
    label, with both critical speeds."""
    from rich.markup import escape

    speed = units.label("speed")
    if report.per_machine:
        t = titled_table("Resonances: n ω of every machine against every mode (resonance rule)",
                         ("machine", "order", "mode", f"critical, {speed}", "margin", "needs", "forcing share", "status"),
                         (f"critical, {speed}", "margin", "needs", "forcing share"))
        for r in report.rows:
            t.add_row(escape(r.machine), str(r.order), f"{r.mode} ({r.motion})", fmt(units.convert("speed", r.critical)),
                      f"{r.margin:.1%}", f"{r.required:.0%}", fmt_scaled(r.share, 1.0, 3), _status(r, strict))
        return t
    columns = ("condition", "mode", speed, f"{speed}, avg. inertia", "margin", "needs", "forcing share", "verdict")
    t = titled_table("Resonances (critical speeds)", columns, columns[2:7])
    for row in report.rows:
        t.add_row(
            row.label + SOURCE_TAGS[row.condition.source] + (" *" if row is report.governing else ""),
            MODE_NAMES[row.mode],
            fmt(units.convert("speed", row.critical)),
            fmt(units.convert("speed", row.critical_averaged)),
            f"{row.margin:.1%}",
            f"{row.required:.0%}" if row.required > 0.0 else "none",
            fmt_scaled(row.share, 1.0, 2),
            verdict_text(row.outcome.value) if row.judged or row.status > INFORMATION else
            ("info" if row.information else "not judged"),
        )
    return t


def print_resonance(report: ResonanceReport, scene, source: str, units: DisplayUnits = DisplayUnits(),
                    strict: bool = False) -> None:
    """Print the tables of ``fcalc resonance``: the heading and frequencies of the scene's kind,
    every condition, the soil model's validity and the verdict."""
    out = stdout()
    if report.per_machine:
        out.print(speeds_line(report, scene, source, units))
        print_modes(report.modes, units)
    else:
        _print_plane(report, scene, source, units)
    table = _conditions_table(report, units, strict)
    out.print(*(names_whole(table, out.width, ("machine", "mode", "status"), grouped=True) if report.per_machine else [table]))
    if not report.per_machine:
        out.print(
            f"* governs. Judged: the paper's conditions and every harmonic whose forcing share reaches"
            f" {FORCING_SHARE:.0%}; needs: the band of the condition's order (\\[limits] detuning = {bands_text(report.detuning)})."
            " The rule: docs/resonance-rule.md.",
        )
    if report.per_machine:
        out.print(f"Forcing share: |φᵀF_n|/p of the order on the mode over the machine's largest; a higher order"
                  f" under {FORCING_SHARE:.0%} is not judged (info: inside its band). The rule: docs/resonance-rule.md.")
    print_soil_validity(report.soil_validity)
    if report.several_roots:
        from rich.text import Text

        for line in report.several_roots:
            out.print(Text(line, style="yellow"))
    out.print(summary_line(report, strict, units))


__all__ = ["MOTION_NAMES", "modes_document", "print_modes", "print_resonance", "resonance_document", "rule_document",
           "speeds_line", "summary_line"]
