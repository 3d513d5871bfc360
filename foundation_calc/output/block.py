"""Reports of a block foundation (``fcalc resonance``, ``amplitudes`` and ``check``): rich
tables and JSON documents (SI units: m, rad, rad/s, Pa)."""

from __future__ import annotations

import numpy as np

from foundation_calc.checks.block import DIRECTIONS, BlockReport
from foundation_calc.output.console import Hanging, fmt, fmt_scaled, natural_width, stdout, two_lines_for, verdict_text
from foundation_calc.output.console import titled_table as _table
from foundation_calc.output.display_units import DisplayUnits
from foundation_calc.output.limits import ALL_POINTS_UP_TO, code_document, limits_document, limits_table, zones_table
from foundation_calc.output.notes import print_soil_validity, print_supports
from foundation_calc.output.resonance import print_modes, resonance_document, speeds_line
from foundation_calc.units import speed_triplet

#: How several machines' amplitudes combine, said once wherever they are shown.
COMBINATION = (
    "several machines: peaks add (the sum of each machine's peak, an upper bound that unrelated speeds"
    " reach in time); RMS values add as the root-sum-square of every harmonic"
)


def _header(scene, source: str) -> dict:
    return {"source": source, "kind": scene.kind, "name": scene.name}


def _office(report) -> list[dict]:
    """The rows of ``report`` (a :class:`BlockReport` or an :class:`~foundation_calc.checks.office.OfficeReport`)."""
    return [
        {"check": o.name, "value": o.value, "limit": o.limit, "unit": o.unit, "verdict": o.outcome.value,
         "source": o.source, "text": o.text}
        for o in report.office
    ]


def office_document(report, scene, source: str) -> dict:
    """The office checks of a scene of any kind as a JSON document (``report``: its
    :class:`~foundation_calc.checks.office.OfficeReport`, :func:`~foundation_calc.checks.office.scene_office`)."""
    return {"scene": _header(scene, source), "office": _office(report), "verdict": report.office_outcome.value}


def amplitudes_document(report: BlockReport, scene, source: str) -> dict:
    """The JSON document of ``fcalc amplitudes`` for a block scene: its ``verdict`` is the
    amplitudes' alone; ``office`` lists the office checks' rows for information (``fcalc check``
    judges them, in its office check)."""
    doc = resonance_document(report.resonance, scene, source, "amplitudes")
    doc.pop("verdict")
    motion = report.motion
    doc["resonant"] = report.resonant
    doc["combination"] = COMBINATION
    if motion is not None:
        harmonics = []
        for name, w, orders, U, R in zip(motion.machines, motion.omegas, motion.orders, motion.displacement, motion.rotation):
            for h, n in enumerate(orders):
                harmonics.append({
                    "machine": name, "order": int(n), "frequency": speed_triplet(float(n * w)),
                    "points": {p: {d: {"amplitude": float(abs(U[i, k, h])), "phase": float(np.angle(U[i, k, h]))}
                                   for k, d in enumerate(DIRECTIONS)} for i, p in enumerate(motion.names)},
                    "rotation": {d: {"amplitude": float(abs(R[k, h])), "phase": float(np.angle(R[k, h]))}
                                 for k, d in enumerate(("rx", "ry", "rz"))},
                })
        doc["harmonics"] = harmonics
        doc["points"] = {
            p: {"at": [float(v) for v in at],
                "displacement_peak": dict(zip(DIRECTIONS, map(float, motion.peak[i]))),
                "velocity_peak": dict(zip(DIRECTIONS, map(float, motion.velocity_peak[i]))),
                "displacement_rms": dict(zip(DIRECTIONS, map(float, motion.displacement_rms[i]))),
                "velocity_rms": dict(zip(DIRECTIONS, map(float, motion.velocity_rms[i]))),
                "acceleration_peak": dict(zip(DIRECTIONS, map(float, motion.acceleration_peak[i]))),
                "acceleration_rms": dict(zip(DIRECTIONS, map(float, motion.acceleration_rms[i])))}
            for i, (p, at) in enumerate(zip(motion.names, [report.cog] + [pt.at for pt in scene.points]))
        }
        doc["rotation_peak"] = dict(zip(("rx", "ry", "rz"), map(float, motion.rotation_peak)))
    doc["limits"] = limits_document(report.limit_rows)
    doc["code"] = code_document(scene.limits, report.zone_rows, report.code_warnings)
    doc["office"] = _office(report)
    doc["modulus_range"] = None if report.amplitude_range is None else report.amplitude_range.document()
    doc["periodic_inertia"] = [_periodic_document(c, motion.names) for c in report.periodic]
    doc["verdict"] = report.amplitude_outcome.value
    return doc


#: How the block's machines with periodic inertia are solved, in the JSON and under the table.
PERIODIC_METHOD = ("exact periodic solution with the angle-dependent inertia of the machine's parts (harmonic"
                   " balance); the limits judge the first approximation (averaged operator)")


def _periodic_document(c, names) -> dict:
    """One machine's exact peaks, first-approximation peaks and error (JSON)."""
    def points(peaks):
        return {p: dict(zip(DIRECTIONS, map(float, peaks[i]))) for i, p in enumerate(names)}

    rotations = ("rx", "ry", "rz")
    return {"machine": c.name, "method": PERIODIC_METHOD, "harmonics": c.harmonics,
            "first_approximation_error": c.error, "harmonic_change": c.harmonic_change,
            "exact": {"displacement_peak": points(c.exact_peak), "rotation_peak": dict(zip(rotations, map(float, c.rotation_exact)))},
            "first_approximation": {"displacement_peak": points(c.first_peak),
                                    "rotation_peak": dict(zip(rotations, map(float, c.rotation_first)))}}


def print_periodic_inertia(report: BlockReport, units: DisplayUnits) -> None:
    """Per machine with periodic inertia: peaks of the exact periodic solution beside the first approximation's."""
    from rich.markup import escape

    from foundation_calc.solvers.rigid_body.periodic import HARMONIC_TOLERANCE

    amp = units.label("amplitude")
    for c in report.periodic:
        t = _table(f"{escape(c.name)}: peak displacement [{amp}], exact periodic solution (harmonic balance,"
                   f" {c.harmonics} harmonics) and first approximation", ("point", "solution", "x", "y", "z"),
                   ("x", "y", "z"))  # a row per solution: 80 columns
        for i, p in enumerate(report.motion.names):
            for solution, peaks in (("exact", c.exact_peak), ("first", c.first_peak)):
                t.add_row(escape(p) if solution == "exact" else "", solution,
                          *(fmt(units.convert("amplitude", v), 5) for v in peaks[i]))
        stdout().print(t)
        capped = (f"; the exact solution reached the cap of {c.harmonics} harmonics, its own error"
                  f" {c.harmonic_change:.2g}" if c.harmonic_change > HARMONIC_TOLERANCE else "")
        stdout().print(f"{escape(c.name)}: first approximation's error {c.error:.2g} (largest relative difference of the"
                       f" peaks from the exact solution's){capped}; the limits judge the first approximation")


def _phasor(value: complex, scale: float, units: DisplayUnits) -> str:
    """An amplitude and its phase, ``"3.543e-05 ∠28°"``; ``"0"`` for the solver's round-off (:func:`fmt_scaled`)."""
    shown = fmt_scaled(units.convert("amplitude", abs(value)), units.convert("amplitude", scale), 4)
    return shown if shown == "0" else f"{shown} ∠{np.degrees(np.angle(value)):.0f}°"


def print_amplitudes(report: BlockReport, scene, source: str, units: DisplayUnits, strict: bool,
                     all_points: bool = False) -> None:
    """Tables of ``fcalc amplitudes`` for a block scene; with more than
    :data:`~foundation_calc.output.limits.ALL_POINTS_UP_TO` points (and not ``all_points``) the
    limits table shows the largest value/limit ratios."""
    from rich.markup import escape

    out = stdout()
    out.print(speeds_line(report, scene, source, units))
    print_modes(report.modes, units)
    motion = report.motion
    if motion is None:
        out.print(f"{verdict_text('fail')}: a machine's order is resonant with an undamped mode: no steady state")
        return
    amp = units.label("amplitude")
    h = _table(f"Steady state per machine and order: amplitude [{amp}] and phase [°], u = A cos(nωt + phase)",
               ("machine", "order", "point", "x", "y", "z"), ("x", "y", "z"))
    for name, orders, U in zip(motion.machines, motion.orders, motion.displacement):
        scale = float(np.max(np.abs(U), initial=0.0))  # the machine's largest amplitude: below ROUNDOFF of it is noise
        for k, n in enumerate(orders):
            for i, p in enumerate(motion.names):
                cells = [_phasor(U[i, d, k], scale, units) for d in range(3)]
                h.add_row(escape(name), str(n), escape(p), *cells)
    out.print(h)
    if len(motion.machines) > 1:
        out.print(COMBINATION[0].upper() + COMBINATION[1:] + ".")
    for title, quantity, values in ((f"Peak displacement [{amp}]", "amplitude", motion.peak),
                                    (f"RMS velocity [{units.label('velocity')}]", "velocity", motion.velocity_rms)):
        t = _table(title, ("point", "x", "y", "z"), ("x", "y", "z"))  # one table each: 80 columns
        for i, p in enumerate(motion.names):
            t.add_row(escape(p), *(fmt(units.convert(quantity, v), 4) for v in values[i]))
        out.print(t)
    if report.limit_rows:
        out.print(limits_table(report.limit_rows, units, "Limits",
                               not all_points and len(motion.names) - 1 > ALL_POINTS_UP_TO, strict))
    if report.zone_rows:
        out.print(*zones_table(report.zone_rows, units, DIRECTIONS, strict))
        print_supports(report.zone_rows)
    print_periodic_inertia(report, units)
    for w in report.code_warnings:
        out.print(f"note: {escape(w)}")
    if report.amplitude_range is not None:
        out.print(f"Amplitudes {escape(report.amplitude_range.text)}")
    print_office(report, strict)
    print_soil_validity(report.soil_validity)
    out.print(f"{verdict_text(report.amplitude_outcome.value, strict)}: amplitudes")


def print_office(report: BlockReport, strict: bool = False) -> None:
    """The office checks' table, for information: ``fcalc check`` judges them. Where the table
    does not fit the console with no column wrapped (a narrow terminal), the sources leave it for
    a line under it, each named once with its checks, and a result takes one or two lines."""
    from rich.markup import escape

    out = stdout()

    def table(sources: bool):
        t = _table("Office checks, for information: fcalc check judges them",
                   ("check", "result", *(("source",) if sources else ()), "verdict"))
        for o in report.office:
            t.add_row(o.name, escape(o.text), *((escape(o.source),) if sources else ()), verdict_text(o.outcome.value, strict))
        return t

    whole = table(sources=True)
    if natural_width(whole) <= out.width:  # a file, a pipe, a wide terminal
        out.print(whole)
        return
    narrow = table(sources=False)
    two_lines_for(narrow, 1, [o.text for o in report.office], out.width)
    sources = {}
    for o in report.office:
        sources.setdefault(o.source, []).append(o.name)
    out.print(narrow, Hanging(escape("sources: " + "; ".join(f"{', '.join(names)}: {source}" for source, names in sources.items())),
                              len("sources: ")))


__all__ = ["COMBINATION", "amplitudes_document", "office_document", "print_amplitudes"]
