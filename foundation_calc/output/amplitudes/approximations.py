"""A crank mechanism's sections of ``fcalc amplitudes`` (:mod:`~foundation_calc.output.amplitudes`
writes the rest): its heading, its approximations of C in x, y, θ (the paper's first
approximation, the averaged operator, the exact solution with the closed forms' errors), their
harmonics and the points' peaks (SI units in JSON: m, rad, s)."""

from __future__ import annotations

import math

from rich.markup import escape
from rich.table import Table
from rich.text import Text

from foundation_calc.checks.amplitudes.approximations import HARMONICS, QUANTITIES, AmplitudeReport, Approximation
from foundation_calc.checks.governing import governing_points, tally
from foundation_calc.output.console import JSON_SCHEMA_VERSION, Hanging, fmt, fmt_scaled, stdout, verdict_text
from foundation_calc.output.display_units import DisplayUnits
from foundation_calc.output.limits import EVERY_ROW, summarised
from foundation_calc.output.resonance import rule_document
from foundation_calc.solvers.crank.first_approximation import RESONANT_MARGIN
from foundation_calc.solvers.crank.response import DIRECTIONS, DOFS
from foundation_calc.units import rpm_from_omega, speed_triplet

UNITS = {"x": "m", "y": "m", "theta": "rad"}
RATE_UNITS = {"displacement": "", "velocity": "/s", "acceleration": "/s²"}
#: display quantity of each peak of a displacement (m); rotations stay in rad
DISPLAY_QUANTITY = {"displacement": "amplitude", "velocity": "velocity", "acceleration": "acceleration"}
FIRST_KEYS = (("y", 1, "cos"), ("y", 2, "cos"), ("x", 1, "sin"), ("x", 3, "sin"), ("theta", 1, "sin"), ("theta", 3, "sin"))


def _approximation_document(approx: Approximation, harmonics: int = 5) -> dict:
    """One approximation's part of the JSON document: harmonics 0 ... ``harmonics`` - 1."""
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
        for dof, n in ((d, n) for d in DOFS for n in range(0, harmonics))
    }
    doc["peaks"] = {
        dof: {q: float(getattr(approx.peaks, q)[i]) for q in QUANTITIES} for i, dof in enumerate(DOFS)
    }
    doc["points"] = {}
    for name, pk in approx.points.items():
        values = {q: getattr(pk, q).tolist() for q in QUANTITIES}  # per direction, as Python floats
        doc["points"][name] = {d: {q: values[q][i] for q in QUANTITIES} for i, d in enumerate(DIRECTIONS)}
    doc["points_rms"] = {}
    for name, rm in approx.rms.items():
        values = {q: getattr(rm, q).tolist() for q in QUANTITIES}
        doc["points_rms"][name] = {d: {q: values[q][i] for q in QUANTITIES} for i, d in enumerate(DIRECTIONS)}
    return doc


def loads_document(vendor) -> dict:
    """The scene's loads as generalised forces about C (Q_x, Q_y [N], Q_θ [N m]) and the block's matrices."""
    from foundation_calc.solvers.crank.loads import matrices

    q = vendor.loads.generalized()
    M, K, C = matrices(vendor.block)
    return {
        "model": "(K - n²ω²M + i nωC) Z_n = Σ Q e^{iφ}; loads F cos(nωt + φ); Q_θ = H F_x + u F_y + M",
        "generalized_forces": [
            {"order": int(n), "x": {"re": v[0].real, "im": v[0].imag}, "y": {"re": v[1].real, "im": v[1].imag},
             "theta": {"re": v[2].real, "im": v[2].imag}}
            for n, v in zip(vendor.loads.order, q)
        ],
        "mass_matrix": M.tolist(),
        "stiffness_matrix": K.tolist(),
        "damping_matrix": C.tolist(),
    }


#: The code document's per-direction values: the governing table's boundaries and each point's RMS
#: velocity and displacement by these names.
CODE_DIRECTIONS = DIRECTIONS


def document_parts(report: AmplitudeReport, scene, source: str) -> tuple[dict, dict, dict, dict]:
    """The crank's parts of the JSON document, around the common keys: its speed, mass ratios,
    loads, damping and approximations; the resonance rule's verdict; nothing before the verdict;
    the exact solver's record and the closed forms' errors after it."""
    
    d = report.design
    shown = 5 if report.vendor is None else max(5, int(report.vendor.loads.order.max()) + 1)
    derived = (
        {"total_mass": report.vendor.block.M_tot}
        if d is None
        else {"mu": d.mu, "lambda": d.lam, "total_mass": d.M_tot, "moving_mass": d.rod.m}
    )
    head = {
        "schema_version": JSON_SCHEMA_VERSION,
        "command": "amplitudes",
        "scene": {"source": source, "kind": scene.kind, "name": scene.name},
        "speed": {**speed_triplet(report.omega), "given_as": scene.speed.speed_given_as},
        "derived": derived,
        "loads": None if report.vendor is None else loads_document(report.vendor),
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
        "approximations": {key: _approximation_document(a, shown) for key, a in report.approximations.items()},
        **({"not_applicable": dict(report.not_applicable)} if report.not_applicable else {}),
    }
    judged = {"resonance_rule": None if report.resonance is None else rule_document(report.resonance)}
    solver = {}
    if report.exact_info is not None:
        info = report.exact_info
        solver["exact_solver"] = {
            "harmonics": info.harmonics,
            "newton_iterations": info.newton_iterations,
            "harmonic_change": info.harmonic_change,
            "relative_residual": info.residual,
            "seconds": info.seconds,
            "converged": info.capped is None,
            "note": info.capped,
        }
        solver["errors"] = report.errors
    return head, judged, {}, solver


def _table_harmonics(report: AmplitudeReport) -> tuple[tuple[str, int], ...]:
    """The harmonics the tables list: :data:`HARMONICS` and every order of the vendor's loads."""
    if report.vendor is None:
        return HARMONICS
    extra = sorted({int(n) for n in report.vendor.loads.order} - {n for _, n in HARMONICS})
    listed = HARMONICS + tuple((dof, n) for dof in DOFS for n in extra)
    return tuple(sorted(listed, key=lambda h: (DOFS.index(h[0]), h[1])))


def _noise_scales(shown, harmonics, value_of) -> dict:
    """The largest harmonic of each dof and method, ``(key, dof) -> size``: a value smaller than
    ROUNDOFF of it is noise and prints as 0."""
    return {
        (a.key, dof): max(abs(value_of(a, dof, k)) for d, k in harmonics if d == dof)
        for a in shown
        if not a.resonant
        for dof in DOFS
    }


def _harmonics_table(report: AmplitudeReport, units: DisplayUnits) -> Table:
    if report.damped:
        return _damped_harmonics_table(report, units)
    # a mechanism alone moves y as cosines and x, θ as sines; loads bring both parts: show magnitudes
    signed = report.vendor is None
    title = "signed coefficient of cos nωt for y, of sin nωt for x and θ" if signed else "magnitude of each harmonic"
    table = Table(title=f"Harmonics ({title})", title_justify="left")
    table.add_column("harmonic")
    shown = list(report.approximations.values())
    harmonics = _table_harmonics(report)

    def value_of(a, dof, n):
        return float(a.motion.coefficient(dof, n)[0 if dof == "y" else 1]) if signed else abs(a.harmonic(dof, n))

    for a in shown:
        table.add_column(a.key.replace("_", " "), justify="right")
    _error_columns(table, report)
    scales = _noise_scales(shown, harmonics, value_of)
    for dof, n in harmonics:
        unit = UNITS[dof] if dof == "theta" else units.label("amplitude")
        cells = [f"{dof}{n} \\[{unit}]"]
        for a in shown:
            if a.resonant:
                cells.append("resonant")
                continue
            value = value_of(a, dof, n)
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
    errors = ((report.errors or {}).values())
    return ["-" if err is None or f"{dof}{n}" not in err["harmonics"] else f"{err['harmonics'][f'{dof}{n}']:.2e}" for err in errors]


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
    harmonics = _table_harmonics(report)
    scales = _noise_scales(shown, harmonics, lambda a, dof, n: abs(a.harmonic(dof, n)))
    for dof, n in harmonics:
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


def _points_table(report: AmplitudeReport, units: DisplayUnits, all_points: bool = False) -> Table:
    approx = report.approximations[report.checked]
    title = f"Peaks over one revolution ({approx.title})"
    shown = list(approx.points)
    if summarised(len(approx.points) - 1, all_points):
        shown = ["C", *governing_points(approx.points)]
        title += (
            f": C and the {len(shown) - 1} points with the largest peaks,"
            f" of the scene's {len(approx.points) - 1} points ({EVERY_ROW})"
        )
    table = Table(title=title, title_justify="left")
    table.add_column("point")
    table.add_column("direction")
    for q in QUANTITIES:
        table.add_column(f"{q} \\[{units.label(DISPLAY_QUANTITY[q])}]", justify="right")
    for name in shown:
        pk = approx.points[name]
        for i, direction in enumerate(DIRECTIONS):
            table.add_row(
                Text(name), direction,
                *(fmt(units.convert(DISPLAY_QUANTITY[q], float(getattr(pk, q)[i]))) for q in QUANTITIES),
            )
    for i, dof in enumerate(DOFS):
        if dof == "theta":
            table.add_row("C", "rocking θ", *(Text(fmt(float(getattr(approx.peaks, q)[i])) + f" rad{RATE_UNITS[q]}", no_wrap=True)
                                              for q in QUANTITIES))  # a number with its unit: one line
    return table


def verdict_line(report: AmplitudeReport, strict: bool) -> str:
    """The verdict with the largest value/limit ratio, the count of values over their limits, the
    worst zone, the resonance rule's statement and the soil's modulus range (the crank's summary,
    as CI scripts read it)."""
    approx = report.approximations[report.checked]
    if report.resonant:
        where = "exactly at the speed" if approx.margin == 0 else f"{approx.margin:.3g} (relative) from the speed"
        return f"{verdict_text('fail')}: resonant — {approx.nearest} is {where}; no steady state without damping"
    if not report.limit_rows and not report.zone_rows:
        return f"{verdict_text('pass')}: no amplitude, velocity or acceleration limit in \\[limits]"
    parts = []
    if report.limit_rows:
        top = max(report.limit_rows, key=lambda r: r.ratio)
        parts.append(f"largest value/limit {top.ratio:.3f} ({escape(top.point)}, {top.direction} {top.quantity})")
        count = tally(report.limit_rows)
        if count.failed_rows:
            parts.append(
                f"{count.failed_rows} of {count.rows} values over their limits,"
                f" at {count.failed_points} of {count.points} points (C included)"
            )
    if report.zone_rows:
        top = max(report.zone_rows, key=lambda r: r.ratio)
        parts.append(f"worst zone at {escape(top.point)}: {escape(top.verdict_text)}")
    if report.resonance is not None:
        parts.append(escape(report.resonance.statement) + (" (damped response)" if report.damped else ""))
    if report.amplitude_range is not None:
        parts.append(escape(report.amplitude_range.text))
    return f"{verdict_text(report.amplitude_outcome.value)}: " + "; ".join(parts)


def print_motion(report: AmplitudeReport, scene, source: str, units: DisplayUnits, all_points: bool) -> bool:
    """The heading (speed, μ, λ), each approximation's title, the resonance rule's statement, the
    damping and the exact solver's record, then the harmonics and (with a steady state) the points'
    peaks; True: the limits follow."""
    d, w = report.design, report.omega
    out = stdout()
    machine = "machine given by its loads" if d is None else f"μ = {fmt(d.mu, 4)}, λ = {fmt(d.lam, 4)}"
    out.print(Hanging(
        f"[bold]{escape(scene.name or source)}[/]  speed {units.show('speed', w)} = {fmt(rpm_from_omega(w))} rpm,"
        f" {machine}; y positive downward"
    ))
    for a in report.approximations.values():
        note = f" (resonant: {a.nearest}, margin {a.margin:.2g})" if a.resonant else ""
        out.print(Hanging(f"  {a.key.replace('_', ' ')}: {a.title}{note}"))
    for key, why in report.not_applicable.items():
        out.print(Hanging(f"  {key.replace('_', ' ')}: {escape(why)}"))
    if report.resonance is not None:
        out.print(Hanging(f"  resonance rule (as fcalc resonance): {escape(report.resonance.statement)}"))
    if report.damping is not None:
        damping = report.damping
        modes = ", ".join(f"{w:.5g} rad/s: ζ = {z:.3g}" for w, z in zip(damping.natural, damping.modal_ratios))
        coupling = f", C_xφ = {fmt(damping.dashpots['C_xphi'])} N s/rad" if "C_xphi" in damping.dashpots else ""
        out.print(Hanging(
            f"  damped (base dashpots C_x = {fmt(damping.dashpots['C_x'])} N s/m, C_z = {fmt(damping.dashpots['C_z'])} N s/m,"
            f" C_φ = {fmt(damping.dashpots['C_phi'])} N m s/rad{coupling}); modes of the averaged operator: {modes}"
        ))
    if report.exact_info is not None:
        info = report.exact_info
        out.print(Hanging(
            f"  exact: {info.harmonics} harmonics (change from {info.harmonics // 2}: {info.harmonic_change:.1e}),"
            f" {info.newton_iterations} Newton step(s), {info.seconds * 1e3:.0f} ms"
        ))
        if info.capped is not None:
            out.print(Hanging(f"  [yellow]exact: {escape(info.capped)}; its figures are good to about that change[/]"))
    out.print(_harmonics_table(report, units))
    if not report.resonant:
        out.print(_points_table(report, units, all_points))
    return True


def limits_title(report: AmplitudeReport) -> str:
    """The limits table's title: the approximation that is judged."""
    return f"Limits (checked with: {report.approximations[report.checked].title})"


def print_after_zones(report: AmplitudeReport, units: DisplayUnits) -> None:
    """Nothing between the zones and the code's warnings."""


def print_notes(report: AmplitudeReport, strict: bool) -> None:
    """Nothing after the code's warnings (the soil's range is in the verdict line)."""


__all__ = ["CODE_DIRECTIONS", "DIRECTIONS", "document_parts", "limits_title", "loads_document", "print_after_zones",
           "print_motion", "print_notes", "verdict_line", "warning"]
