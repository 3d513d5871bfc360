"""Report of ``fcalc amplitudes``: rich tables and the JSON document (SI units: m, rad, s)."""

from __future__ import annotations

import math

from rich.markup import escape
from rich.table import Table
from rich.text import Text

from foundation_calc.checks.crank_amplitudes import HARMONICS, QUANTITIES, AmplitudeReport, Approximation
from foundation_calc.output.console import JSON_SCHEMA_VERSION, fmt, fmt_scaled, stdout, verdict_text
from foundation_calc.output.display_units import DisplayUnits
from foundation_calc.solvers.crank.first_approximation import RESONANT_MARGIN
from foundation_calc.solvers.crank.response import DIRECTIONS, DOFS
from foundation_calc.units import rpm_from_omega, speed_triplet

UNITS = {"x": "m", "y": "m", "theta": "rad"}
RATE_UNITS = {"displacement": "", "velocity": "/s", "acceleration": "/s²"}
#: display quantity of each peak of a displacement (m); rotations stay in rad
DISPLAY_QUANTITY = {"displacement": "amplitude", "velocity": "velocity", "acceleration": "acceleration"}
FIRST_KEYS = (("y", 1, "cos"), ("y", 2, "cos"), ("x", 1, "sin"), ("x", 3, "sin"), ("theta", 1, "sin"), ("theta", 3, "sin"))


def _approximation_document(approx: Approximation) -> dict:
    doc = {
        "title": approx.title,
        "resonant": approx.resonant,
        "resonance_margin": approx.margin,
        "nearest_resonance": approx.nearest,
    }
    if approx.resonant:
        return doc
    if approx.key == "first_approximation":
        coefficients = {f"{dof}{n}": float(approx.motion.coefficient(dof, n)[part == "sin"]) for dof, n, part in FIRST_KEYS}
        doc["coefficients"] = coefficients
        doc["magnitudes"] = {f"{dof}{n}": abs(approx.harmonic(dof, n)) for dof, n, _ in FIRST_KEYS}
    doc["harmonics"] = {
        f"{dof}{n}": {
            "cos": float(approx.motion.coefficient(dof, n)[0]),
            "sin": float(approx.motion.coefficient(dof, n)[1]),
            "magnitude": abs(approx.harmonic(dof, n)),
            "phase": approx.phase(dof, n),
        }
        for dof, n in ((d, n) for d in DOFS for n in range(0, 5))
    }
    doc["peaks"] = {
        dof: {q: float(getattr(approx.peaks, q)[i]) for q in QUANTITIES} for i, dof in enumerate(DOFS)
    }
    doc["points"] = {
        name: {d: {q: float(getattr(pk, q)[i]) for q in QUANTITIES} for i, d in enumerate(DIRECTIONS)}
        for name, pk in approx.points.items()
    }
    return doc


def amplitudes_document(report: AmplitudeReport, scene, source: str) -> dict:
    """The JSON document of ``fcalc amplitudes`` (every number SI)."""
    d = report.design
    doc = {
        "schema_version": JSON_SCHEMA_VERSION,
        "command": "amplitudes",
        "scene": {"source": source, "kind": scene.kind, "name": scene.name},
        "speed": {**speed_triplet(d.omega), "given_as": scene.mechanism.speed_given_as},
        "derived": {"mu": d.mu, "lambda": d.lam, "total_mass": d.M_tot, "moving_mass": d.rod.m},
        "conventions": "y positive downward; theta turns +x toward +y; x, y of the centre of mass C;"
        " a point's displacement is the rigid-body motion X + (R(theta) - I)(horizontal, -height),"
        " to first order (x + height·theta, y + horizontal·theta)",
        "resonant_margin": RESONANT_MARGIN,
        "damping": None
        if report.damping is None
        else {
            "dashpots": report.damping.dashpots,
            "natural_frequencies": list(report.damping.natural),
            "modal_damping_ratios": list(report.damping.modal_ratios),
        },
        "checked_with": report.checked,
        "approximations": {key: _approximation_document(a) for key, a in report.approximations.items()},
        "limits": [
            {
                "point": row.point,
                "direction": row.direction,
                "quantity": row.quantity,
                "value": row.value,
                "limit": row.limit,
                "ratio": row.ratio,
                "verdict": row.outcome.value,
            }
            for row in report.rows
        ],
        "verdict": report.outcome.value,
    }
    if report.exact_info is not None:
        info = report.exact_info
        doc["exact_solver"] = {
            "harmonics": info.harmonics,
            "newton_iterations": info.newton_iterations,
            "harmonic_change": info.harmonic_change,
            "relative_residual": info.residual,
            "seconds": info.seconds,
        }
        doc["errors"] = report.errors
    return doc


def _harmonics_table(report: AmplitudeReport, units: DisplayUnits) -> Table:
    if report.damped:
        return _damped_harmonics_table(report, units)
    table = Table(title="Harmonics (signed coefficient of cos nωt for y, of sin nωt for x and θ)", title_justify="left")
    table.add_column("harmonic")
    shown = [a for a in report.approximations.values()]
    for a in shown:
        table.add_column(a.key.replace("_", " "), justify="right")
    _error_columns(table, report)
    scales = {  # the largest harmonic of each dof and method: smaller than ROUNDOFF of it is noise
        (a.key, dof): max(abs(float(a.motion.coefficient(dof, k)[0 if dof == "y" else 1])) for d, k in HARMONICS if d == dof)
        for a in shown
        if not a.resonant
        for dof in DOFS
    }
    for dof, n in HARMONICS:
        part = 0 if dof == "y" else 1
        unit = UNITS[dof] if dof == "theta" else units.label("amplitude")
        cells = [f"{dof}{n} \\[{unit}]"]
        for a in shown:
            if a.resonant:
                cells.append("resonant")
                continue
            value = float(a.motion.coefficient(dof, n)[part])
            scale = scales[a.key, dof]
            if dof != "theta":
                value, scale = units.convert("amplitude", value), units.convert("amplitude", scale)
            cells.append(fmt_scaled(value, scale, 6))
        table.add_row(*cells, *_error_cells(report, dof, n))
    return table


def _error_columns(table: Table, report: AmplitudeReport) -> None:
    for key in report.errors or ():
        table.add_column(f"error, {key.replace('_', ' ')}", justify="right")


def _error_cells(report: AmplitudeReport, dof: str, n: int) -> list[str]:
    return ["-" if err is None else f"{err['harmonics'][f'{dof}{n}']:.2e}" for err in (report.errors or {}).values()]


def _damped_harmonics_table(report: AmplitudeReport, units: DisplayUnits) -> Table:
    """Amplitude A and phase lag φ of each harmonic, q_n(t) = A cos(nωt - φ), for every method."""
    table = Table(
        title="Harmonics, damped: amplitude A and phase lag φ, q_n(t) = A cos(nωt − φ)", title_justify="left"
    )
    table.add_column("harmonic")
    shown = list(report.approximations.values())
    for a in shown:
        name = a.key.replace("_", " ")
        table.add_column(f"A, {name}", justify="right")
        table.add_column(f"φ [°], {name}", justify="right")
    _error_columns(table, report)
    scales = {
        (a.key, dof): max(abs(a.harmonic(d, k)) for d, k in HARMONICS if d == dof)
        for a in shown
        if not a.resonant
        for dof in DOFS
    }
    for dof, n in HARMONICS:
        unit = UNITS[dof] if dof == "theta" else units.label("amplitude")
        cells = [f"{dof}{n} \\[{unit}]"]
        for a in shown:
            if a.resonant:
                cells += ["resonant", "-"]
                continue
            value, scale = abs(a.harmonic(dof, n)), scales[a.key, dof]
            if dof != "theta":
                value, scale = units.convert("amplitude", value), units.convert("amplitude", scale)
            amplitude = fmt_scaled(value, scale, 6)
            cells += [amplitude, "-" if amplitude == "0" else f"{math.degrees(a.phase(dof, n)):.1f}"]
        table.add_row(*cells, *_error_cells(report, dof, n))
    return table


def _points_table(report: AmplitudeReport, units: DisplayUnits) -> Table:
    approx = report.approximations[report.checked]
    table = Table(title=f"Peaks over one revolution ({approx.title})", title_justify="left")
    table.add_column("point")
    table.add_column("direction")
    for q in QUANTITIES:
        table.add_column(f"{q} \\[{units.label(DISPLAY_QUANTITY[q])}]", justify="right")
    for name, pk in approx.points.items():
        for i, direction in enumerate(DIRECTIONS):
            table.add_row(
                Text(name), direction,
                *(fmt(units.convert(DISPLAY_QUANTITY[q], float(getattr(pk, q)[i]))) for q in QUANTITIES),
            )
    for i, dof in enumerate(DOFS):
        if dof == "theta":
            table.add_row("C", "rocking θ", *(fmt(float(getattr(approx.peaks, q)[i])) + f" rad{RATE_UNITS[q]}" for q in QUANTITIES))
    return table


def _limits_table(report: AmplitudeReport, units: DisplayUnits) -> Table:
    table = Table(title=f"Limits (checked with: {report.approximations[report.checked].title})", title_justify="left")
    for col in ("point", "direction", "quantity", "peak", "limit", "peak/limit", "verdict"):
        table.add_column(col, justify="right" if col in ("peak", "limit", "peak/limit") else "left")
    for row in report.rows:
        shown = DISPLAY_QUANTITY[row.quantity]
        table.add_row(
            Text(row.point), row.direction, row.quantity, units.show(shown, row.value), units.show(shown, row.limit),
            f"{row.ratio:.3f}", verdict_text(row.outcome.value),
        )
    return table


def summary_line(report: AmplitudeReport) -> str:
    approx = report.approximations[report.checked]
    if report.resonant:
        where = "exactly at the speed" if approx.margin == 0 else f"{approx.margin:.3g} (relative) from the speed"
        return f"{verdict_text('fail')}: resonant — {approx.nearest} is {where}; no steady state without damping"
    if not report.rows:
        return f"{verdict_text('pass')}: no amplitude, velocity or acceleration limit in \\[limits]"
    top = max(report.rows, key=lambda r: r.ratio)
    damped = f"; damped response, {approx.margin:.2%} from {approx.nearest}" if report.damped else ""
    return (
        f"{verdict_text(report.outcome.value)}: largest peak/limit {top.ratio:.3f}"
        f" ({escape(top.point)}, {top.direction} {top.quantity}){damped}"
    )


def print_amplitudes_report(
    report: AmplitudeReport, scene, source: str, units: DisplayUnits = DisplayUnits()
) -> None:
    """Print the tables of ``fcalc amplitudes`` (numbers in ``units``; JSON stays SI)."""
    d = report.design
    out = stdout()
    out.print(
        f"[bold]{escape(scene.name or source)}[/]  speed {units.show('speed', d.omega)} = {fmt(rpm_from_omega(d.omega))} rpm,"
        f" μ = {fmt(d.mu, 4)}, λ = {fmt(d.lam, 4)}; y positive downward"
    )
    for a in report.approximations.values():
        note = f"resonant: {a.nearest}, margin {a.margin:.2g}" if a.resonant else f"nearest resonance {a.nearest}, margin {a.margin:.1%}"
        out.print(f"  {a.key.replace('_', ' ')}: {a.title} ({note})")
    if report.damping is not None:
        damping = report.damping
        modes = ", ".join(f"{w:.5g} rad/s: ζ = {z:.3g}" for w, z in zip(damping.natural, damping.modal_ratios))
        out.print(
            f"  damped (base dashpots C_x = {fmt(damping.dashpots['C_x'])} N s/m, C_z = {fmt(damping.dashpots['C_z'])} N s/m,"
            f" C_φ = {fmt(damping.dashpots['C_phi'])} N m s/rad); modes of the averaged operator: {modes}"
        )
    if report.exact_info is not None:
        info = report.exact_info
        out.print(
            f"  exact: {info.harmonics} harmonics (change from {info.harmonics // 2}: {info.harmonic_change:.1e}),"
            f" {info.newton_iterations} Newton step(s), {info.seconds * 1e3:.0f} ms"
        )
    out.print(_harmonics_table(report, units))
    if not report.resonant:
        out.print(_points_table(report, units))
    if report.rows:
        out.print(_limits_table(report, units))
    out.print(summary_line(report))
