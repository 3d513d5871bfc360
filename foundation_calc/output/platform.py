"""Report of ``fcalc platform``: rich tables and the JSON document (SI units)."""

from __future__ import annotations

from rich.markup import escape
from rich.table import Table

from foundation_calc.checks.platform import MODE_NAMES, PlatformReport, damping_text, mode_margins
from foundation_calc.output.console import JSON_SCHEMA_VERSION, fmt, fmt_scaled, stdout, verdict_text
from foundation_calc.units import hz_from_omega, rpm_from_omega, speed_triplet

AXES = ("x", "y", "z")
ISOLATORS = ("O1", "O2", "O3", "O4")


def _stiffness_names() -> list[tuple[str, int, int]]:
    return [(f"c{i + 1}{j + 1}", i, j) for i in range(4) for j in range(3)]


def design_section(report: PlatformReport) -> dict:
    """The design numbers by their paper names (N/m, m)."""
    d = report.design
    s = d.stiffness
    doc = {
        "M_sigma": float(d.M_sigma),
        "c0": float(d.c0),
        "c1": float(s[:, 0].sum()),
        "c2": float(s[:, 1].sum()),
        "c3": float(d.c3),
        "horizontal_sums": {k: float(v) for k, v in d.horizontal_sums.items()},
        **{k: float(v) for k, v in d.horizontal_sums.items()},
        "a": float(d.a),
        "b": float(d.b),
        "c": float(d.c),
        "static_deflection": float(d.static_deflection),
        **{name: float(s[i, j]) for name, i, j in _stiffness_names()},
        "stiffness_table": [[float(x) for x in row] for row in s],
        "translation_frequency": float(d.translation_frequency),
        "regime_margin": float(d.regime_margin),
        "singularity_distance": float(d.singularity_distance),
    }
    return doc


def verification_section(report: PlatformReport) -> dict:
    """The 6-DOF steady state of the design (m, rad, % of u)."""
    v, m = report.verification, report.model
    return {
        "inertia": {"central_moments": [float(x) for x in m.J_c], "source": "scene" if report.inertia_given else "estimate"},
        "loss_factor": m.eta,
        "damping_ratio": m.damping_ratio,
        "product_height": m.product_height,
        "amplitudes": dict(zip(AXES, map(float, v.amplitudes))),
        "amplitudes_over_u": {k: float(a) / v.u for k, a in zip(AXES, v.amplitudes)},
        "rotations": dict(zip(("alpha", "beta", "gamma"), map(float, v.rotations))),
        "static": dict(zip(("x", "y", "z", "alpha", "beta", "gamma"), map(float, v.static))),
        "static_tilt": v.static_tilt,
        "static_offset_percent": v.static_offset_percent,
        "mean": dict(zip(("x", "y", "z", "alpha", "beta", "gamma"), map(float, v.mean))),
        "rocking": v.rocking,
        "rocking_percent": v.rocking_percent,
        "spread_percent": v.spread_percent,
        "corners": [
            {"position": [float(x) for x in p], "peak": float(a), "peak_over_u": float(a) / v.u}
            for p, a in zip(v.corners, v.corner_peaks)
        ],
        "harmonic_balance": {
            "order": v.order,
            "frequencies": v.harmonics,
            "truncation_error": v.truncation_error,
            "truncation_error_over_u": v.truncation_error / v.u,
        },
    }


def platform_document(report: PlatformReport, scene, source: str, given_as: str) -> dict:
    """The JSON document of ``fcalc platform`` (every number SI: kg, m, N/m, rad, rad/s)."""
    d = report.design
    return {
        "schema_version": JSON_SCHEMA_VERSION,
        "command": "platform",
        "scene": {"source": source, "kind": scene.kind, "name": scene.name},
        "speed": {**speed_triplet(float(d.omega)), "given_as": given_as},
        "inputs": {
            "M": d.M, "m": d.m, "l": d.l, "u": d.u, "regime": scene.operation.regime,
            "xi": d.xi, "eta": d.eta, "zeta": d.zeta, "A": d.A, "B": d.B, "g": d.g,
        },
        "design": design_section(report),
        "verification": verification_section(report),
        "natural_frequencies": [
            {"dominant": dom, "mode": MODE_NAMES[dom], **speed_triplet(float(p)), "margin": mg}
            for p, dom, mg in zip(report.modes.frequencies, report.modes.dominant, mode_margins(report.modes, d.omega))
        ],
        "sensitivity_with_damping": report.model.damped,
        "sensitivity": [
            {
                "parameter": r.parameter,
                "tolerance": r.tolerance,
                "rocking_percent_plus": r.rocking_plus,
                "rocking_percent_minus": r.rocking_minus,
                "static_offset_percent_plus": r.static_plus,
                "static_offset_percent_minus": r.static_minus,
                "resonance": r.resonance,
            }
            for r in report.sensitivity
        ],
        "checks": [{"name": f.name, "verdict": f.outcome.value, "message": f.message} for f in report.findings],
        "warnings": scene.plausibility_warnings(),
        "verdict": report.outcome.value,
    }


#: The columns of numbers, right-justified so that their digits line up.
NUMBERS = ("value", "rad/s", "Hz", "rpm", "margin", "x (c_i1)", "y (c_i2)", "z (c_i3)", "rocking +", "rocking -",
           "static +", "static -")


def _table(title: str, *columns: str) -> Table:
    table = Table(title=title, title_justify="left")
    for col in columns:
        table.add_column(col, justify="right" if col in NUMBERS else "left")
    return table


def print_platform_report(report: PlatformReport, scene, source: str, given_as: str, strict: bool = False) -> None:
    """Print the tables of ``fcalc platform``."""
    d, v = report.design, report.verification
    out = stdout()
    out.print(
        f"[bold]{escape(scene.name or source)}[/]  speed {fmt(d.omega)} rad/s = {fmt(hz_from_omega(d.omega))} Hz"
        f" = {fmt(rpm_from_omega(d.omega))} rpm (given as {given_as}); amplitude u = {fmt(d.u)} m,"
        f" {scene.operation.regime} resonance"
    )

    t = _table("Design (Eqs. (3.8)-(3.21), corrected)", "quantity", "value", "unit")
    rows = [
        ("c0 = c1 = c2, summed horizontal stiffness (3.14)", d.c0, "N/m"),
        ("c3, summed vertical stiffness", d.c3, "N/m"),
        *((f"{k} (3.16)-(3.20)", val, "N/m") for k, val in d.horizontal_sums.items()),
        ("a, exciter axis point along x' (3.9)", d.a, "m"),
        ("b, exciter axis point along y' (3.10)", d.b, "m"),
        ("c, exciter height above the support plane (3.11)", d.c, "m"),
        ("static deflection z = -M_Σ g / c3", d.static_deflection, "m"),
        ("translational resonance sqrt(c0/M_Σ)", d.translation_frequency, "rad/s"),
    ]
    for label, value, unit in rows:
        t.add_row(label, fmt(float(value), 6), unit)
    out.print(t)

    st = _table("Isolator stiffnesses c_ij [N/m]", "isolator", "x (c_i1)", "y (c_i2)", "z (c_i3)")
    for name, row in zip(ISOLATORS, d.stiffness):
        st.add_row(name, *(fmt(float(x), 6) for x in row))
    out.print(st)

    inertia = "scene" if report.inertia_given else "estimated: homogeneous block A × B × H"
    vt = _table(f"6-DOF verification (inertia {inertia}; damping: {damping_text(report.model)})", "quantity", "value", "unit")
    size = max(float(d.A), float(d.B))  # rotations are compared with u over the platform's size
    for axis, amp in zip(AXES, v.amplitudes):
        vt.add_row(f"amplitude of {axis}", fmt_scaled(amp, v.u, 6), f"m ({fmt_scaled(amp / v.u, 1.0, 6)} u)")
    for axis, rot in zip(("α", "β", "γ"), v.rotations):
        vt.add_row(f"rotation amplitude {axis}", fmt_scaled(rot, v.u / size, 4), "rad")
    vt.add_row("static tilt |(α, β, γ)|", fmt_scaled(v.static_tilt, v.u / size, 4), "rad")
    vt.add_row("static corner offset from the tilt", fmt_scaled(v.static_offset_percent, 100.0, 4), "% of u")
    vt.add_row("rocking: corner motion relative to the centre of mass", fmt_scaled(v.rocking_percent, 100.0, 4), "% of u")
    vt.add_row("spread of corner amplitudes (max - min)", fmt_scaled(v.spread_percent, 100.0, 4), "% of u")
    vt.add_row(f"harmonic balance: order K = {v.order}, frequencies", str(v.harmonics), "-")
    vt.add_row("truncation error of the harmonic balance (estimate)", fmt(v.truncation_error / v.u, 2), "u")
    out.print(vt)

    ft = _table("Natural frequencies (6-DOF, undamped)", "mode", "rad/s", "Hz", "rpm", "margin")
    for p, dom, mg in zip(report.modes.frequencies, report.modes.dominant, mode_margins(report.modes, d.omega)):
        ft.add_row(MODE_NAMES[dom], fmt(p), fmt(hz_from_omega(p)), fmt(rpm_from_omega(p)), f"{mg:.1%}")
    out.print(ft)

    damping = f"with the isolators' damping, {damping_text(report.model)}" if report.model.damped else "undamped"
    resonant = any(r.resonance for r in report.sensitivity)
    se = _table(
        f"Sensitivity to build tolerances (largest first; {damping}) [% of u]",
        "parameter", "tolerance", "rocking +", "rocking -", "static +", "static -", *(("resonance",) if resonant else ()),
    )
    nominal = (v.rocking_percent, v.rocking_percent, v.static_offset_percent, v.static_offset_percent)
    se.add_row("none (the design)", "-", *(fmt_scaled(x, 100.0, 3) for x in nominal), *(("",) if resonant else ()))
    for r in report.sensitivity:
        se.add_row(
            escape(r.parameter), r.tolerance,
            *("-" if x is None else fmt_scaled(x, 100.0, 3) for x in (r.rocking_plus, r.rocking_minus, r.static_plus, r.static_minus)),
            *((escape(r.resonance),) if resonant else ()),
        )
    out.print(se)

    for f in report.findings:
        out.print(f"{verdict_text(f.outcome.value)} {escape(f.name)}: {escape(f.message)}")
    out.print(f"{verdict_text(report.outcome.value, strict)}: {summary(report)}")


def summary(report: PlatformReport) -> str:
    """One sentence on the whole design."""
    bad = [f.name for f in report.findings if f.outcome.value == report.outcome.value and f.outcome.value != "pass"]
    if not bad:
        return "the design moves translationally and every check passes"
    return "see " + ", ".join(bad)
