"""A 6-DOF block's sections of ``fcalc amplitudes`` (:mod:`~foundation_calc.output.amplitudes`
writes the rest): its heading and modes, every machine's harmonics at G and the points in x, y,
z, the points' peaks, the periodic inertia of its machines, its office checks for information
(SI units in JSON: m, rad, rad/s)."""

from __future__ import annotations

import numpy as np

from foundation_calc.checks.amplitudes.machines import DIRECTIONS
from foundation_calc.output.console import fmt_scaled, names_whole, stdout, verdict_text
from foundation_calc.output.console import titled_table as _table
from foundation_calc.output.display_units import DisplayUnits
from foundation_calc.units import speed_triplet

#: The code document's per-direction values: none on a block.
CODE_DIRECTIONS = None

#: How several machines' amplitudes combine, said once wherever they are shown.
COMBINATION = (
    "several machines: peaks add (the sum of each machine's peak, an upper bound that unrelated speeds"
    " reach in time); RMS values add as the root-sum-square of every harmonic"
)

#: The rotations of the block about x, y, z.
ROTATIONS = ("rx", "ry", "rz")

#: How the block's machines with periodic inertia are solved.
PERIODIC_SOLUTION = "exact periodic solution with the angle-dependent inertia of the machine's parts (harmonic balance)"

#: What judges the limits, by the report's ``checked`` (``--exact``: ``"exact"``), as said after the
#: periodic inertia's table and in its JSON ``method``.
JUDGED_BY = {"first_approximation": "the limits judge the first approximation",
             "exact": "the limits judge the exact periodic solution"}

#: The JSON ``method`` of a machine with periodic inertia when the first approximation is judged.
PERIODIC_METHOD = f"{PERIODIC_SOLUTION}; {JUDGED_BY['first_approximation']} (averaged operator)"


def periodic_method(report) -> str:
    """The JSON ``method`` of ``report``'s machines with periodic inertia: how they are solved and
    what judges the limits (:data:`JUDGED_BY`)."""
    if report.checked == "first_approximation":
        return PERIODIC_METHOD
    return f"{PERIODIC_SOLUTION}; {JUDGED_BY[report.checked]}"


def document_parts(report, scene, source: str) -> tuple[dict, dict, dict, dict]:
    """The block's parts of the JSON document, around the common keys: the resonance document's
    (modes, resonances, the soil's notes) with the machines' harmonics and the points' peaks; the
    office checks' rows for information (``fcalc check`` judges them); the periodic inertia."""
    from foundation_calc.output.amplitudes.office import office_rows_document
    from foundation_calc.output.resonance import resonance_document

    head = resonance_document(report.resonance, scene, source, "amplitudes")
    head.pop("verdict")
    motion = report.motion
    head["resonant"] = report.resonant
    head["combination"] = COMBINATION
    if report.checked != "first_approximation":  # --exact: which solution judges, as a crank's document says it
        head["checked_with"] = report.checked
    if motion is not None:
        head["harmonics"] = _harmonics_document(motion)
        head["points"] = {
            p: {"at": [float(v) for v in at], **{field: dict(zip(DIRECTIONS, map(float, getattr(motion, name)[i])))
                                                  for field, name in _POINT_FIELDS}}
            for i, (p, at) in enumerate(zip(motion.names, [report.cog] + [pt.at for pt in scene.points]))
        }
        head["rotation_peak"] = dict(zip(ROTATIONS, map(float, motion.rotation_peak)))
    names = () if motion is None else motion.names
    return (head, {"office": office_rows_document(report)},
            {"periodic_inertia": [_periodic_document(c, names, periodic_method(report)) for c in report.periodic]}, {})


#: A point's JSON keys and the :class:`~foundation_calc.solvers.block.response.PointMotion` fields they read.
_POINT_FIELDS = (("displacement_peak", "peak"), ("velocity_peak", "velocity_peak"), ("displacement_rms", "displacement_rms"),
                 ("velocity_rms", "velocity_rms"), ("acceleration_peak", "acceleration_peak"),
                 ("acceleration_rms", "acceleration_rms"))


def _harmonics_document(motion) -> list[dict]:
    """Every machine's every order: the complex amplitude of each point along x, y, z and of the
    rotations (amplitude and phase)."""
    harmonics = []
    for name, w, orders, U, R in zip(motion.machines, motion.omegas, motion.orders, motion.displacement, motion.rotation):
        for h, n in enumerate(orders):
            harmonics.append({
                "machine": name, "order": int(n), "frequency": speed_triplet(float(n * w)),
                "points": {p: {d: {"amplitude": float(abs(U[i, k, h])), "phase": float(np.angle(U[i, k, h]))}
                               for k, d in enumerate(DIRECTIONS)} for i, p in enumerate(motion.names)},
                "rotation": {d: {"amplitude": float(abs(R[k, h])), "phase": float(np.angle(R[k, h]))}
                             for k, d in enumerate(ROTATIONS)},
            })
    return harmonics


def _periodic_document(c, names, method: str) -> dict:
    """One machine's exact peaks, first-approximation peaks and error (JSON); ``method``: how it is
    solved and what judges the limits (:func:`periodic_method`)."""
    def points(peaks):
        return {p: dict(zip(DIRECTIONS, map(float, peaks[i]))) for i, p in enumerate(names)}

    return {"machine": c.name, "method": method, "harmonics": c.harmonics,
            "first_approximation_error": c.error, "harmonic_change": c.harmonic_change,
            "exact": {"displacement_peak": points(c.exact_peak), "rotation_peak": dict(zip(ROTATIONS, map(float, c.rotation_exact)))},
            "first_approximation": {"displacement_peak": points(c.first_peak),
                                    "rotation_peak": dict(zip(ROTATIONS, map(float, c.rotation_first)))}}


def print_motion(report, scene, source: str, units: DisplayUnits, all_points: bool) -> bool:
    """The heading (machines' speeds, total mass), the six modes, then every machine's harmonics
    and the points' peak displacement and RMS velocity; False, with the verdict said, when an
    order is resonant with an undamped mode (no steady state, nothing more to show)."""
    from rich.markup import escape

    from foundation_calc.output.resonance import print_modes, speeds_line

    out = stdout()
    out.print(speeds_line(report, scene, source, units))
    print_modes(report.modes, units)
    motion = report.motion
    if motion is None:
        out.print(f"{verdict_text('fail')}: a machine's order is resonant with an undamped mode: no steady state")
        return False
    amp = units.label("amplitude")
    h = _table(f"Steady state per machine and order: amplitude [{amp}] and phase [°], u = A cos(nωt + phase)",
               ("machine", "order", "point", "x", "y", "z"), ("x", "y", "z"))
    for name, orders, U in zip(motion.machines, motion.orders, motion.displacement):
        scale = float(np.max(np.abs(U), initial=0.0))  # the machine's largest amplitude: below ROUNDOFF of it is noise
        for k, n in enumerate(orders):
            for i, p in enumerate(motion.names):
                cells = [_phasor(U[i, d, k], scale, units) for d in range(3)]
                h.add_row(escape(name), str(n), escape(p), *cells)
    out.print(*names_whole(h, out.width, ("machine", "point"), grouped=True))
    if len(motion.machines) > 1:
        out.print(COMBINATION[0].upper() + COMBINATION[1:] + ".")
    for title, quantity, values in ((f"Peak displacement [{amp}]", "amplitude", motion.peak),
                                    (f"RMS velocity [{units.label('velocity')}]", "velocity", motion.velocity_rms)):
        t = _table(title, ("point", "x", "y", "z"), ("x", "y", "z"))  # one table each: 80 columns
        for i, p in enumerate(motion.names):
            t.add_row(escape(p), *_cells(values[i], values, quantity, units, 4))
        out.print(*names_whole(t, out.width, ("point",)))
    return True


def _cells(row, table, quantity: str, units: DisplayUnits, digits: int) -> list[str]:
    """The cells of one row of a table of ``quantity`` in ``units``; a value below
    :data:`~foundation_calc.output.console.ROUNDOFF` of the table's largest is the solver's round-off
    and prints as ``0`` (:func:`fmt_scaled`), as a motion the machines do not drive."""
    scale = units.convert(quantity, float(np.max(np.abs(table), initial=0.0)))
    return [fmt_scaled(units.convert(quantity, v), scale, digits) for v in row]


def _phasor(value: complex, scale: float, units: DisplayUnits) -> str:
    """An amplitude and its phase, ``"3.543e-05 ∠28°"``; ``"0"`` for the solver's round-off
    (:func:`fmt_scaled`); a phase that rounds to zero is ``0°``, never ``-0°``."""
    shown = fmt_scaled(units.convert("amplitude", abs(value)), units.convert("amplitude", scale), 4)
    return shown if shown == "0" else f"{shown} ∠{round(float(np.degrees(np.angle(value)))) + 0}°"


def limits_title(report) -> str:
    """The limits table's title."""
    return "Limits"


def print_after_zones(report, units: DisplayUnits) -> None:
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
                          *_cells(peaks[i], c.exact_peak, "amplitude", units, 5))
        out = stdout()
        out.print(*names_whole(t, out.width, ("point",)))
        capped = (f"; the exact solution reached the cap of {c.harmonics} harmonics, its own error"
                  f" {c.harmonic_change:.2g}" if c.harmonic_change > HARMONIC_TOLERANCE else "")
        stdout().print(f"{escape(c.name)}: first approximation's error {c.error:.2g} (largest relative difference of the"
                       f" peaks from the exact solution's){capped}; {JUDGED_BY[report.checked]}")


def print_notes(report, strict: bool) -> None:
    """The amplitudes over the soil's modulus range, and the office checks for information."""
    from rich.markup import escape

    from foundation_calc.output.amplitudes.office import print_office

    if report.amplitude_range is not None:
        stdout().print(f"Amplitudes {escape(report.amplitude_range.text)}")
    print_office(report, strict)


def verdict_line(report, strict: bool) -> str:
    """The amplitudes' verdict."""
    return f"{verdict_text(report.amplitude_outcome.value, strict)}: amplitudes"


__all__ = ["CODE_DIRECTIONS", "COMBINATION", "DIRECTIONS", "JUDGED_BY", "PERIODIC_METHOD", "PERIODIC_SOLUTION", "document_parts",
           "limits_title", "periodic_method", "print_after_zones", "print_motion", "print_notes", "verdict_line", "warning"]
