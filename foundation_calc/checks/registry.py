"""Which checks each scene kind supports, as used by ``fcalc check``.

:data:`CHECKS` maps a scene kind to its checks, by name; each check is a function
``scene -> Finding``. A :class:`Finding` carries the outcome and a one-line reason. The reason is
a sequence of parts: literal text (which may hold user text, such as a point's name, and is never
interpreted) and ``(quantity, SI value)`` pairs that the output layer shows in the user's units,
so tables can show speeds in rpm or amplitudes in mm without any check knowing about display
units. ``values`` names the same numbers for the JSON document.

The functions here adapt the per-topic checks (``checks/resonance/`` ...); they import
those modules only when called, so ``fcalc check`` loads the physics of the kinds it meets and
nothing else. Each finding keeps the check's report, from which the output layer writes the same
JSON document as the single-scene command. A check that several kinds run is one function for all
of them: the kinds differ below it (``scene_resonances``, ``scene_amplitudes``, ``scene_office``),
and it words each report as the report says, never by the scene's kind. Adding a check to a kind is
one function and one entry in :data:`CHECKS` (and its document in ``output/check_report.py``).
"""

from __future__ import annotations

from collections.abc import Callable, Mapping
from dataclasses import dataclass, field
from typing import Any

from foundation_calc.checks.outcomes import Outcome, worst


#: A reason: literal text parts and ``(quantity, SI value)`` parts, in reading order.
Reason = tuple[str | tuple[str, float], ...]


@dataclass(frozen=True)
class Finding:
    """The outcome of one check on one scene.

    Attributes
    ----------
    check : name of the check, e.g. ``"resonance"``
    outcome : pass, warn or fail
    reason : one line as parts: literal text, or ``(quantity, SI value)`` to show in display units
    values : name -> (quantity, value in SI units), quantity as in ``output.display_units``
    report : the per-topic check's report (SI units), for the output layer's JSON document
    details : further lines (SI units) for the JUnit report and JSON, too long for the table
    """

    check: str
    outcome: Outcome
    reason: Reason
    values: Mapping[str, tuple[str, float]] = field(default_factory=dict)
    report: Any = None
    details: tuple[str, ...] = ()


def inputs(scene) -> Finding | None:
    """The scene's plausibility warnings (values probably typed in another unit) as a check that
    warns, so that the table, JUnit and ``--strict`` treat them as every other warning; None for
    a scene without any."""
    warnings = scene.plausibility_warnings()
    if not warnings:
        return None
    count = f"{len(warnings)} input value{'s' * (len(warnings) > 1)} outside the plausible ranges"
    reason = (f"{count}: {warnings[0]}" + (f" (+{len(warnings) - 1} more, on stderr)" if len(warnings) > 1 else ""),)
    return Finding("inputs", Outcome.WARN, reason, details=tuple(f"WARN {w}" for w in warnings))


def soil_notes(validity) -> tuple[Reason, tuple[str, ...]]:
    """The soil model's validity (:mod:`~foundation_calc.checks.soil_validity`) as a reason's
    tail and details, the same on every kind's resonance and amplitudes: said when an a0 lies
    beyond the method's range or a judged frequency below a stratum's cutoff, neither of which
    changes the verdict."""
    if validity is None or not validity.warns:
        return (), ()
    return (f"; {validity.brief}",), validity.details()


def support_details(rows) -> tuple[str, ...]:
    """The code's support class of the zone ``rows`` (:mod:`~foundation_calc.checks.support`), as
    details: a line per direction and class."""
    from foundation_calc.checks.support import CLAUSE, support_lines

    return tuple(f"SUPPORT {line} ({CLAUSE})" for line in support_lines({r.point: r.support for r in rows if r.support}))


def zone_notes(rows) -> tuple[str, ...]:
    """``NOTE`` the caveat of a code's zones applied to predicted motions
    (:data:`~foundation_calc.checks.codes.ZONE_CAVEAT`), when any zone ``rows`` were judged."""
    from foundation_calc.checks.codes import ZONE_CAVEAT

    return (f"NOTE {ZONE_CAVEAT}",) if rows else ()


def _support(row) -> str:
    """`` (support ...)`` of a zone row's governing direction (:func:`~foundation_calc.checks.support.governing_support`)."""
    from foundation_calc.checks.support import governing_support

    phrase = governing_support(row)
    return f"; {phrase}" if phrase else ""


def resonance(scene) -> Finding:
    """Every machine's orders against every mode by the resonance rule (``fcalc resonance``;
    :func:`~foundation_calc.checks.resonance.scene_resonances`), worded by what the report says: a
    plane model's one speed, or a block's conditions per machine."""
    from foundation_calc.checks.resonance import scene_resonances

    report = scene_resonances(scene)
    values = {} if report.per_machine else {"speed": ("speed", report.omega)}
    if report.governing is not None:
        values["critical"] = ("speed", report.governing.critical)
    reason = (report.text,) if report.per_machine else ("speed ", values["speed"], f", {report.text}")
    details = () if report.modulus_range is None else report.modulus_range.details()
    noted, notes = soil_notes(report.soil_validity)
    return Finding("resonance", report.outcome, reason + noted, values, report,
                   details + notes + report.several_roots)


def amplitudes_finding(report) -> Finding:
    """The amplitude check of every scene kind: its limit rows, code zones, code warnings and soil
    range (a report with ``limit_rows``, ``zone_rows``, ``code_warnings``, ``amplitude_range``,
    ``soil_validity``, ``resonant``, ``amplitude_outcome`` and ``wording``) as a finding, worded as
    the report itself says (:class:`~foundation_calc.checks.limits.AmplitudeWording`: its values
    first, its reason without a steady state, the resonance rule's statement, itemised or not),
    whatever the scene's kind.
    """
    from foundation_calc.checks.governing import tally
    from foundation_calc.checks.limits import display_quantity

    wording = report.wording
    values, itemised = dict(wording.values), wording.itemised
    rows, zones = report.limit_rows, report.zone_rows
    if report.resonant:
        reason = wording.resonant
    elif not rows and not zones:
        reason = ("no amplitude, velocity or acceleration limit in [limits]",)
    else:
        reason = ()
        if rows:
            top = max(rows, key=lambda row: row.ratio)
            quantity = display_quantity(top.quantity)
            values |= {"peak": (quantity, top.value), "limit": (quantity, top.limit)}
            reason = (
                f"largest {top.quantity} ", values["peak"], f" at {top.point} ({top.direction}) is {top.ratio:.0%}"
                " of the limit ", values["limit"],
            )
            count = tally(rows)
            if itemised and count.failed_rows > 1:
                reason += (f"; {count.failed_rows} of {count.rows} values over their limits, at {count.failed_points} point{'s' * (count.failed_points != 1)}",)
        if zones:
            worst_zone = max(zones, key=lambda row: row.ratio)
            if itemised:
                values |= {"velocity_rms": ("velocity", worst_zone.value), "zone_limit": ("velocity", worst_zone.limit)}
            reason += ("; " if reason else "", f"{worst_zone.point}: {worst_zone.verdict_text}{_support(worst_zone)}")
        if wording.statement is not None:
            reason += (f"; {wording.statement}",)
    if report.code_warnings:  # why the verdict warns, for every kind
        reason += ("; " + "; ".join(report.code_warnings),)
    if report.amplitude_range is not None:
        reason += (f"; {report.amplitude_range.text}",)
    details = tuple(
        f"{row.outcome.value.upper()} {row.point} {row.direction} {row.quantity}: {row.value:.4g}"
        f" {'<=' if row.outcome is Outcome.PASS else '>'} {row.limit:.4g} [SI] ({row.source})"
        for row in rows
    )
    if itemised:
        details += tuple(f"{row.outcome.value.upper()} {row.point}: {row.verdict_text} ({row.table.clause})" for row in zones)
    details += support_details(zones) + zone_notes(zones) + tuple(f"WARN {warning}" for warning in report.code_warnings)
    if report.amplitude_range is not None:
        details += report.amplitude_range.details()
    noted, notes = soil_notes(report.soil_validity)
    return Finding("amplitudes", report.amplitude_outcome, reason + noted, values, report, details + notes)


def amplitudes(scene) -> Finding:
    """Steady-state peaks and RMS values of the scene's points against [limits], and the zones of a
    vibration code (``fcalc amplitudes``; :func:`~foundation_calc.checks.amplitudes.scene_amplitudes`)."""
    from foundation_calc.checks.amplitudes import scene_amplitudes

    return amplitudes_finding(scene_amplitudes(scene))


def platform_design(scene) -> Finding:
    """Design of the isolators and exciter, verified on the 6-DOF model (``fcalc platform``)."""
    from foundation_calc.checks.platform import check_platform

    report = check_platform(scene.design(), scene.model(), scene.limits, scene.inertia_given)
    shown = [f for f in report.findings if f.outcome is report.outcome]
    speed = ("speed", report.design.omega)
    if report.outcome is Outcome.PASS:
        reason = ("at ", speed, ": the design moves translationally and every check passes")
    else:
        kinds = {Outcome.WARN: "warnings", Outcome.FAIL: "failures"}[report.outcome]
        reason = ("at ", speed, f": {kinds} from " + "; ".join(f"{f.name} ({f.brief})" for f in shown))
    details = tuple(f"{f.outcome.value.upper()} {f.name}: {f.message}" for f in report.findings)
    values = {"speed": speed}
    return Finding("design", report.outcome, reason, values, report, details)


def runup(scene) -> Finding | None:
    """Largest displacement during start-up and run-down, and a motor that may stick (``fcalc
    runup``), for a scene that gives something to judge them by (:func:`checks.runup.judged`);
    None (not run) otherwise: a run-up costs 0.5-10 s of time integration."""
    from foundation_calc.checks.runup import check_runup, judged, run_times, run_title

    if not judged(scene):
        return None
    report = check_runup(scene, *run_times(scene))
    parts: list = []
    limited = [row for row in report.rows if row.ratio is not None]
    values = {}
    if limited:
        top = max(limited, key=lambda row: row.ratio)
        values = {"transient": ("amplitude", top.value), "limit": ("amplitude", top.limit)}
        parts += [f"largest displacement during {run_title(top.run)} ", values["transient"], f" at {top.point} is"
                  f" {top.ratio:.0%} of the limit ", values["limit"]]
    stuck = [t for t in report.torques if t.outcome is not Outcome.PASS]
    if stuck:
        worst_torque = max(stuck, key=lambda t: t.needed / t.available)
        of = f" of {worst_torque.machine}" if worst_torque.machine else ""
        parts += [("; " if parts else "") + f"the motor{of} {'sticks' if worst_torque.outcome is Outcome.FAIL else 'barely passes'}"
                  f" at mode {worst_torque.mode + 1}: it needs {worst_torque.needed:.4g} N m, has {worst_torque.available:.4g} N m"]
    elif report.motors:
        parts += [("; " if parts else "") + ("the motor" if len(report.motors) == 1 else "every motor") + " passes every resonance"]
    details = tuple(
        f"{'NOT JUDGED' if row.outcome is None else row.outcome.value.upper()} {row.point} {run_title(row.run)}:"
        f" |u| {row.value:.4g} m"
        + ("" if row.limit is None else f" {'<=' if row.outcome is Outcome.PASS else '>'} {row.limit:.4g} m")
        for row in report.rows
    ) + tuple(f"WARN {warning}" for warning in report.warnings)
    return Finding("runup", report.outcome, tuple(parts), values, report, details)


def office(scene) -> Finding | None:
    """The office checks (:func:`~foundation_calc.checks.office.scene_office`): static bearing
    pressure and settlement against [limits], and a block's eccentricity and mass ratio (ACI 351.3R
    rules of thumb); None (not run) for a scene without any row (a crank without either limit)."""
    from foundation_calc.checks.office import scene_office

    report = scene_office(scene)
    if not report.office:
        return None
    shown = [o for o in report.office if o.outcome is report.office_outcome]
    reason = ("; ".join(f"{o.name}: {o.text}" for o in shown),)
    details = tuple(f"{o.outcome.value.upper()} {o.name}: {o.text} ({o.source})" for o in report.office)
    return Finding("office", report.office_outcome, reason, {}, report, details)


def requirements(scene) -> Finding | None:
    """The office's rules (:mod:`~foundation_calc.checks.requirements`); None (not run) without any."""
    from foundation_calc.checks.requirements import requirement_rows

    rows = requirement_rows(scene)
    if not rows:
        return None
    outcome = worst(r.outcome for r in rows)
    reason = ("; ".join(f"{r.rule}: {r.given}" for r in rows if r.outcome is outcome),)
    return Finding("requirements", outcome, reason, {}, tuple(rows),
                   tuple(f"{r.outcome.value.upper()} {r.rule}: {r.given} ({r.source})" for r in rows))


#: The checks of a crank and of a block foundation, one function each whatever the kind.
_FOUNDATION = {"inputs": inputs, "resonance": resonance, "amplitudes": amplitudes, "runup": runup, "office": office,
               "requirements": requirements}

#: scene kind -> {check name: function scene -> Finding or None (not run)}, in the order they are reported.
CHECKS: dict[str, dict[str, Callable[[Any], Finding | None]]] = {
    "crank_foundation": dict(_FOUNDATION),
    "platform": {"inputs": inputs, "design": platform_design, "runup": runup},
    "block_foundation": dict(_FOUNDATION),
}
