"""The verdict of a calculation sheet: every row of every check ``fcalc check`` runs for the scene.

The checks are those of :func:`foundation_calc.checks.batch.run_checks` (the one registry,
``checks/registry.py``), so the sheet and ``fcalc check`` cannot disagree. Each check's rows are
read from its JSON document (the ``result`` of the ``fcalc check --json`` entry); a check this
module has no row reader for (a new scene kind's) still gets one row: its verdict and reason.
"""

from __future__ import annotations

from collections.abc import Callable

from foundation_calc.output.display_units import DisplayUnits
from foundation_calc.output.report.model import Paragraph, Section, table
from foundation_calc.output.report.resonance_text import measured_to
from foundation_calc.output.report.numbers import Measure, cells, measure, percent, quantity, ratio

#: Exit code of ``fcalc check`` for a scene whose worst check ends in this verdict.
EXIT = {"pass": 0, "warn": 0, "fail": 1}


#: How an office row names a limit the scene gives (checks/office.py): the key follows.
SCENE_LIMIT = "scene [limits] "


def limit_source(scene, key: str) -> str:
    """The source of the scene's limit ``key`` as the checks table prints it: the document the scene
    names in ``[limits] sources``, or that it gives none."""
    return f"[limits] {key}: {scene.limits.source_of(key)}"


def resonance_verdict(row: dict) -> str:
    """What decides a resonance row (docs/resonance-rule.md): its verdict when the condition is
    judged or sets a warning or failure; else "information" (inside its band, but its harmonic's
    forcing share is under 1 %) or "not judged". A row of neither kind is never a PASS beside a
    margin smaller than its band."""
    if row["judged"] or row["status"] in ("warn", "fail"):
        return row["verdict"]
    return "information" if row["status"] == "information" else "not judged"


def _resonance_rows(doc: dict, scene, units: DisplayUnits):
    omega = doc.get("speed", {}).get("omega")  # a crank foundation's: its margins are to the nearer critical speed
    for r in doc["resonances"]:
        critical = quantity(units, "speed", r["critical_speed"]["omega"] if omega is None else measured_to(r, omega))
        shown = resonance_verdict(r)
        decides = shown == r["verdict"]
        yield (
            f"{r['condition']} ({r['mode_name']}, critical {critical})",
            "margin " + percent(r["margin"]),
            ("≥ " + percent(r["required"]) if r["required"] > 0 else "no band") if decides
            else Measure(r["forcing_share"], 2, scale=1.0, prefix="forcing share ", suffix=" < 1 %"),
            (ratio(r["required"] / r["margin"]) if r["margin"] > 0 else "inf") if decides and r["required"] > 0 else "-",
            shown,
            limit_source(scene, "detuning") if decides else "resonance rule",
        )
    yield from _range_rows(doc)


def _range_rows(doc: dict):
    """The check over the soil's ``modulus_range``, if the scene gives one: its governing factor."""
    ranged = doc.get("modulus_range")
    if ranged:
        yield (
            f"over the soil's modulus range [{ranged['low']:g}, {ranged['high']:g}]: {ranged['governing']}",
            f"governing factor {ranged['governing_factor']:.4g}", "every factor passes", "-", ranged["verdict"],
            "scene [soil] modulus_range",
        )


def quantity_name(quantity: str) -> str:
    """A limited quantity as a reader names it, not by its key.

    >>> quantity_name("velocity_rms"), quantity_name("displacement")
    ('RMS velocity', 'peak displacement')
    """
    return f"RMS {quantity.removesuffix('_rms')}" if quantity.endswith("_rms") else f"peak {quantity}"


def _amplitude_rows(doc: dict, scene, units: DisplayUnits):
    from foundation_calc.checks.limits import display_quantity, limit_key

    for row in doc["limits"]:
        kind = display_quantity(row["quantity"])
        yield (
            f"{row['point']}, {row['direction']}: {quantity_name(row['quantity'])}",
            measure(units, kind, row["value"], row["limit"]),
            measure(units, kind, row["limit"], prefix="≤ "),
            ratio(row["ratio"]),
            row["verdict"],
            limit_source(scene, limit_key(row["quantity"])),
        )
    code = doc.get("code")
    code_units = DisplayUnits(velocity="mm/s", amplitude="µm")  # the codes' zones are in mm/s and µm
    for row in (code or {}).get("points", ()):
        kind = "velocity" if row["quantity"] == "velocity" else "amplitude"
        yield (
            f"{row['point']} RMS {row['quantity']} ({row['governing']}), zone {row['zone']}",
            measure(code_units, kind, row["value"], row["limit"]),
            measure(code_units, kind, row["limit"], prefix="≤ "),
            ratio(row["ratio"]),
            row["verdict"],
            f"[ISO] {code['tables'][row['foundation']]['clause']}, group {code['machine_group']}, {row['foundation']}",
        )
    for warning in (code or {}).get("warnings", ()):
        yield ("vibration code", warning, "-", "-", "warn", code["code"])
    yield from _range_rows(doc)


def _runup_rows(doc: dict, scene, units: DisplayUnits):
    from foundation_calc.checks.runup import run_title
    from foundation_calc.output.report.runup_section import motor_documents

    for row in doc["limits"]:
        yield (
            f"{row['point']}, largest displacement during {run_title(row['run'])}",
            measure(units, "amplitude", row["value"]),
            "-" if row["limit"] is None else measure(units, "amplitude", row["limit"], prefix="≤ "),
            ratio(row["ratio"]),
            row["verdict"],
            limit_source(scene, "transient_amplitude") if row["limit"] is not None else "not limited",
        )
    for motor in motor_documents(doc):
        of = f" of {motor['machine']}" if motor.get("machine") else ""
        for t in motor["sommerfeld"]:
            yield (
                f"motor torque{of} at mode {t['mode']} ({t['harmonic']:g}ω, {quantity(units, 'speed', t['speed'])})",
                Measure(t["torque_needed"], 4, "N m", suffix=" needed"),
                Measure(t["torque_available"], 4, "N m", prefix="≤ "),
                ratio(t["ratio"]),
                t["verdict"],
                "scene [machines.drive]" if of else "scene [drive]",
            )


def _ratio(demand: float, limit: float) -> str:
    return ratio(demand / limit) if limit > 0 else "-"


def _design_measures(doc: dict, scene) -> dict[str, tuple[str, str, str, str]]:
    """Value, limit, ratio (demand/limit; above 1 fails or warns) and the limit's source of each
    finding of the platform design check."""
    d, v, zeta = doc["design"], doc["verification"], doc["inputs"]["zeta"]
    limits = scene.limits
    detuning, height = limits.detuning, limits.exciter_height_ratio
    closest = min(f["margin"] for f in doc["natural_frequencies"])
    worst = max(
        (x for s in doc["sensitivity"] for k, x in s.items() if k.startswith(("rocking_percent", "static_offset")) and x is not None),
        default=0.0,
    )
    resonant = [s["parameter"] for s in doc["sensitivity"] if s["resonance"]]
    rocking = limits.rocking_percent
    return {
        "exciter height": (
            (Measure(d["c"] / zeta, 3, prefix="c/ζ = "), Measure(height, 3, prefix="≤ "), _ratio(d["c"] / zeta, height), limit_source(scene, "exciter_height_ratio"))
            if d["c"] >= 0 and zeta > 0
            else (Measure(d["c"], 4, "m", prefix="c = "), "c ≥ 0 (above the support plane)", "-", "design rule")
        ),
        "regime margin": (percent(d["regime_margin"]), "≥ " + percent(detuning), _ratio(detuning, d["regime_margin"]), limit_source(scene, "detuning")),
        "natural frequencies": ("closest " + percent(closest), "≥ " + percent(detuning), _ratio(detuning, closest), limit_source(scene, "detuning")),
        "rocking": (
            Measure(v["rocking_percent"], 3, "% of u", 100), Measure(rocking, 3, "% of u", prefix="≤ "),
            _ratio(v["rocking_percent"], rocking), limit_source(scene, "rocking_percent"),
        ),
        "tolerances": (
            ("resonant: " + ", ".join(resonant)) if resonant else Measure(worst, 3, "% of u", 100, prefix="worst "),
            Measure(rocking, 3, "% of u", prefix="no resonance, ≤ "),
            "-" if resonant else _ratio(worst, rocking),
            limit_source(scene, "rocking_percent"),
        ),
    }


def _design_rows(doc: dict, scene, units: DisplayUnits):
    measures = _design_measures(doc, scene)
    for c in doc["checks"]:
        value, limit, shown_ratio, source = measures.get(c["name"], (c["message"], "-", "-", "design rule"))
        yield (c["name"], value, limit, shown_ratio, c["verdict"], source)


#: check name (as in the registry) -> rows (item, value, limit, ratio, verdict, source) of its document.
def _office_rows(doc: dict, scene, units: DisplayUnits):
    def shown(row, v, prefix):
        if row["unit"] == "Pa":
            return Measure(v / 1e3, 4, "kPa", prefix=prefix)
        if row["unit"] == "m":
            return Measure(v * 1e3, 3, "mm", prefix=prefix)
        return prefix + percent(v) if row["check"].startswith("eccentricity") else Measure(v, 3, prefix=prefix)

    for row in doc["office"]:
        above = row["check"] == "mass ratio"  # a ratio that must stay at or above its limit
        yield (
            row["text"],
            shown(row, row["value"], ""),
            shown(row, row["limit"], "≥ " if above else "≤ "),
            ratio(row["limit"] / row["value"] if above else row["value"] / row["limit"]),
            row["verdict"],
            limit_source(scene, row["source"].removeprefix(SCENE_LIMIT)) if row["source"].startswith(SCENE_LIMIT)
            else row["source"].replace("ACI 351.3R-18", "[ACI]"),  # the full entry under References
        )


def _requirement_rows(doc: dict, scene, units: DisplayUnits):
    for row in doc["requirements"]:
        yield (row["rule"], row["given"], "required by the office", "-", row["verdict"], f"{row['source']}; fcalc.toml or scene [require]")


ROWS: dict[str, Callable] = {
    "requirements": _requirement_rows,
    "office": _office_rows,
    "resonance": _resonance_rows,
    "amplitudes": _amplitude_rows,
    "runup": _runup_rows,
    "design": _design_rows,
}


def scene_verdict(runs) -> str:
    """The scene's verdict as ``fcalc check`` gives it: its worst check's."""
    order = list(EXIT)
    return max((run.verdict for run in runs), key=order.index, default="pass")


def verdict_line(runs) -> str:
    """One sentence: the overall verdict, which checks set it, and the exit code."""
    verdict = scene_verdict(runs)
    setting = [run.check for run in runs if run.verdict == verdict and verdict != "pass"]
    why = f" ({', '.join(setting)})" if setting else ""
    return (
        f"Overall verdict: {verdict.upper()}{why}; {len(runs)} check{'s' * (len(runs) != 1)} as fcalc check"
        f" runs them, exit code {EXIT[verdict]}."
    )


def check_reason(run, units: DisplayUnits) -> str:
    """A check's reason as ``fcalc check`` gives it; the plausibility warnings' count only, as the
    sheet lists every warning itself (the console's reason shows the first and points to stderr)."""
    if run.check == "inputs":
        return units.render(run.reason).split(":", 1)[0] + ": each is listed under Verdict, Input warnings"
    return units.render(run.reason)


def summary_section(runs, warnings, units: DisplayUnits) -> Section:
    """Page 1: the overall verdict and each check's verdict and reason, as ``fcalc check`` prints them."""
    rows = ((run.check, run.verdict.upper(), check_reason(run, units)) for run in runs)
    blocks = [Paragraph(verdict_line(runs)), table("", ("check", "verdict", "reason"), rows, (False, False, False))]
    if warnings:
        blocks.append(table("Input warnings (values probably typed in another unit: the check inputs warns)", ("warning",), ((w,) for w in warnings), (False,)))
    return Section("Verdict", tuple(blocks))


def checks_section(runs, documents: dict, scene, units: DisplayUnits) -> Section:
    """Every row of every check: value, limit, ratio (demand/limit; above 1 fails), verdict, source."""
    rows = []
    for run in runs:
        reader = ROWS.get(run.check)
        found = list(reader(documents[run.check], scene, units)) if reader is not None else []
        if not found:  # a check with nothing tabulated (or unknown here): its own verdict and reason
            found = [(check_reason(run, units), "-", "-", "-", run.verdict, "fcalc check")]
        rows += [(run.check, item, value, limit, r, verdict.upper(), source) for item, value, limit, r, verdict, source in found]
    if rows:  # value and limit: one notation per quantity in each column
        columns = list(zip(*rows))
        columns[2], columns[3] = cells(columns[2]), cells(columns[3])
        rows = list(zip(*columns))
    checks = table(
        "Every check (ratio = demand/limit; above 1 fails)",
        ("check", "item", "value", "limit", "ratio", "verdict", "limit's source"),
        rows,
        (False, False, True, True, True, False, False),
    )
    return Section("Checks", (checks, Paragraph(verdict_line(runs))))
