"""The verdict of a calculation sheet: every row of every check ``fcalc check`` runs for the scene.

The checks are those of :func:`foundation_calc.checks.batch.run_checks` (the one registry,
``checks/registry.py``), so the sheet and ``fcalc check`` cannot disagree. Each check's rows are
read from its JSON document (the ``result`` of the ``fcalc check --json`` entry); a check this
module has no row reader for (a new scene kind's) still gets one row: its verdict and reason.
"""

from __future__ import annotations

from collections.abc import Callable

from foundation_calc.output.display_units import DisplayUnits
from foundation_calc.output.report.chain import CHECKS_TABLE, check_cell
from foundation_calc.output.report.model import Cell, Link, Paragraph, Section, table
from foundation_calc.output.report.resonance_text import measured_to
from foundation_calc.output.report.numbers import Measure, cells, measure, percent, quantity, ratio, share

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
    judged, is of order 1 (the speed itself, which the rule always judges: it fails within 5 % and
    warns inside its band whatever its forcing share, as ``fcalc resonance`` shows it) or sets a
    warning or failure; else "information" (inside its band, but its harmonic's forcing share is
    under 1 %) or "not judged". A row of neither kind is never a PASS beside a margin smaller than
    its band."""
    order = row.get("order", row.get("harmonic"))  # a block's row names its order, a crank's its harmonic
    if row["judged"] or order == 1 or row["status"] in ("warn", "fail"):
        return row["verdict"]
    return "information" if row["status"] == "information" else "not judged"


#: The check row's own item cell (its row filled in by :func:`checks_section`).
ITEM = Cell(CHECKS_TABLE, (), "item")


def _detuning_inputs(r: dict, doc: dict, units: DisplayUnits) -> tuple:
    """The printed inputs of a resonance row's margin |ω − ω_c|/ω_c: the condition (its order n), the
    speed and the natural frequencies it is measured to (a crank's zero-order and averaged ones)."""
    sp = units.label("speed")
    if "speed" in doc:  # a crank foundation: ω under Derived quantities, p1, p2, k0 in Natural frequencies
        mode = r["condition"].split("= ", 1)[1]
        return (("condition", ITEM), ("ω", Cell("", ("ω, speed",), "value", section="Derived quantities")),
                ("p", Cell("Natural frequencies", (mode,), f"ω [{sp}]")),
                ("p", Cell("Natural frequencies", (mode,), f"averaged inertia, ω [{sp}]")))
    from foundation_calc.output.report.block_methods import MODES_TITLE

    machine = list(doc["machines"]).index(r["machine"]) + 1
    return (("condition", ITEM), ("n_rpm", Cell(f"[[machines]] {machine}", ("speed_rpm",), "value")),
            ("p", Cell(MODES_TITLE, (str(r["mode"]),), "p [rad/s]")))


def _resonance_rows(doc: dict, scene, units: DisplayUnits):
    omega = doc.get("speed", {}).get("omega")  # a crank foundation's: its margins are to the nearer critical speed
    for r in doc["resonances"]:
        critical = quantity(units, "speed", r["critical_speed"]["omega"] if omega is None else measured_to(r, omega))
        shown = resonance_verdict(r)
        decides = shown == r["verdict"]
        yield (  # a block's condition names its mode's motion: "ω = mode 1 (y)"
            f"{r['condition']}, critical {critical}" if r.get("dominant") else f"{r['condition']} ({r['mode_name']}, critical {critical})",
            "margin " + percent(r["margin"]),
            ("≥ " + percent(r["required"]) if r["required"] > 0 else "no band") if decides
            else f"share {share(r['forcing_share'])} < 1 %",
            (ratio(r["required"] / r["margin"]) if r["margin"] > 0 else "inf") if decides and r["required"] > 0 else "-",
            shown,
            limit_source(scene, "detuning") if decides else "resonance rule",
            ("detuning", _detuning_inputs(r, doc, units)),
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


def _amplitude_inputs(crank: bool, point: str) -> tuple:
    """The printed inputs of a point's peak or RMS value: the complex amplitudes of every order
    (a block's Z table, a ``crank`` foundation's Z_n table) and where the point is (a block's G:
    from M's first moments)."""
    from foundation_calc.output.report.block_methods import MATRICES_TITLE, RESPONSE_TITLE

    if crank:
        where = () if point == "C" else (("horizontal", Cell("[[points]]", (point,), "horizontal [m]")),
                                         ("height", Cell("[[points]]", (point,), "height [m]")))
        return (("item", ITEM), ("Z", Cell("Each harmonic: forcing F_n", ("*",), "*")), *where)
    if point == "G":
        def m(row, column):
            return Cell(MATRICES_TITLE, (f"M, row {row}",), column)
        where = (("M", m("u_x", "u_x")), ("M x_G", m("u_y", "θ_z")), ("−M y_G", m("u_x", "θ_z")), ("M z_G", m("u_x", "θ_y")))
    else:
        where = tuple((f"r_{axis}", Cell("[[points]]", (point,), "at [m]", index=j)) for j, axis in enumerate("xyz"))
    return (("item", ITEM), ("Z", Cell(RESPONSE_TITLE, ("*",), "*")), *where)


def _amplitude_rows(doc: dict, scene, units: DisplayUnits):
    from foundation_calc.checks.limits import display_quantity, limit_key

    crank = "machines" not in doc  # a block's document lists its machines
    for row in doc["limits"]:
        kind = display_quantity(row["quantity"])
        formula = "crank peak" if crank else "block rms" if row["quantity"].endswith("_rms") else "block peak"
        yield (
            f"{row['point']}, {row['direction']}: {quantity_name(row['quantity'])}",
            measure(units, kind, row["value"], row["limit"]),
            measure(units, kind, row["limit"], prefix="≤ "),
            ratio(row["ratio"]),
            row["verdict"],
            limit_source(scene, limit_key(row["quantity"])),
            (formula, _amplitude_inputs(crank, row["point"])),
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
            ("crank rms" if crank else "block rms", _amplitude_inputs(crank, row["point"])),
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
            ("integration", (("peaks", Cell(f"{run_title(row['run']).capitalize()} in", ("*",), "all modes")),)),
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
                ("integration", (("torque", Cell(f"Motor start-up{of} (Sommerfeld", ("*",), "torque needed [N m]")),)),
            )


def _ratio(demand: float, limit: float) -> str:
    return ratio(demand / limit) if limit > 0 else "-"


def sensitivity_label(row: dict) -> str:
    """A row of the platform's sensitivity table as the sheet names it: the parameter, and the
    resonance its tolerance reaches."""
    return row["parameter"] + (f" (resonant: {row['resonance']})" if row["resonance"] else "")


def _platform_cells(doc: dict, units: DisplayUnits) -> dict[str, tuple]:
    """The printed inputs of each platform design finding's value (see :data:`chain.FORMULAS`)."""
    omega = ("ω", Cell("", ("ω, speed",), "value", section="Inputs as the design uses them"))
    sp = units.label("speed")
    keys = ("rocking +", "rocking −", "static +", "static −")
    rows = [sensitivity_label(s) for s in doc["sensitivity"]]
    return {
        "exciter height": ("quotient", (("a", Cell("Design", ("c (3.11)",), "value")),
                                        ("b", Cell("", ("ξ, η, ζ, centre of mass",), "value", section="Inputs as the design uses them", index=2)))),
        "regime margin": ("detuning", (omega, ("p", Cell("Design", ("translational resonance",), "value")))),
        "natural frequencies": ("closest detuning", (omega, *(("p", Cell("Natural frequencies (6-DOF", (f["mode"],), f"[{sp}]"))
                                                               for f in doc["natural_frequencies"]))),
        "rocking": ("harmonic balance", (("rocking", Cell("6-DOF verification (", ("rocking of the corners",), "value")),)),
        "tolerances": ("maximum", tuple(("x", Cell("Sensitivity to build tolerances", (row,), k)) for row in rows for k in keys)),
    }


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
    measures, printed = _design_measures(doc, scene), _platform_cells(doc, units)
    for c in doc["checks"]:
        value, limit, shown_ratio, source = measures.get(c["name"], (c["message"], "-", "-", "design rule"))
        if c["name"] == "exciter height" and isinstance(limit, str):  # c < 0: c itself is the value
            printed["exciter height"] = ("quotient", printed["exciter height"][1][:1])
        yield (c["name"], value, limit, shown_ratio, c["verdict"], source, printed.get(c["name"]))


#: check name (as in the registry) -> rows (item, value, limit, ratio, verdict, source) of its document.
def _office_rows(doc: dict, scene, units: DisplayUnits):
    def shown(row, v, prefix):
        if row["unit"] == "Pa":
            return Measure(v / 1e3, 4, "kPa", prefix=prefix)
        if row["unit"] == "m":
            return Measure(v * 1e3, 3, "mm", prefix=prefix)
        return prefix + percent(v) if row["check"].startswith("eccentricity") else Measure(v, 3, prefix=prefix)

    eccentricities = {r["check"][-1]: r["text"] for r in doc["office"] if r["check"].startswith("eccentricity")}
    for row in doc["office"]:
        above = row["check"] == "mass ratio"  # a ratio that must stay at or above its limit
        if row["value"] is None:  # a check that does not apply: its text says why
            yield (row["text"], "-", shown(row, row["limit"], "≤ "), ratio(None), row["verdict"],
                   limit_source(scene, row["source"].removeprefix(SCENE_LIMIT)), None)
            continue
        yield (
            row["text"],
            shown(row, row["value"], ""),
            shown(row, row["limit"], "≥ " if above else "≤ "),
            ratio(row["limit"] / row["value"] if above else row["value"] / row["limit"]),
            row["verdict"],
            limit_source(scene, row["source"].removeprefix(SCENE_LIMIT)) if row["source"].startswith(SCENE_LIMIT)
            else row["source"].replace("ACI 351.3R-18", "[ACI]"),  # the full entry under References
            _office_inputs(row, eccentricities),
        )


def _office_inputs(row: dict, eccentricities: dict[str, str]):
    """The printed inputs of an office row's value, most in its own text (checks/office.py)."""
    def said(after: str, item: str | None = None):
        return Cell(CHECKS_TABLE, () if item is None else ("office", item), "item", after=after)

    check = row["check"]
    if check.startswith("eccentricity"):
        return ("quotient", (("a", said(f"e_{check[-1]} = ")), ("b", said("the base's length " if check[-1] == "x" else "the base's width "))))
    if check == "mass ratio":
        return ("quotient", (("a", said("block ")), ("b", said("machines "))))
    if check == "settlement":
        return ("quotient", (("a", said("W/K_z = ")), ("b", said("kN / "))))
    if check == "bearing pressure" and "S = " in row["text"]:
        return ("quotient", (("a", said("W = ")), ("b", said("S = "))))
    if check == "bearing pressure":
        return ("bearing pressure", (("W", said("W = ")), ("L", Cell("[block]", ("length",), "value")),
                                     ("B", Cell("[block]", ("width",), "value")),
                                     ("e_x", said("e_x = ", eccentricities["x"])), ("e_y", said("e_y = ", eccentricities["y"]))))
    return None


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
    rows, links = [], []
    for run in runs:
        reader = ROWS.get(run.check)
        found = list(reader(documents[run.check], scene, units)) if reader is not None else []
        if not found:  # a check with nothing tabulated (or unknown here): its own verdict and reason
            found = [(check_reason(run, units), "-", "-", "-", run.verdict, "fcalc check")]
        for item, value, limit, r, verdict, source, *derived in found:
            rows.append((run.check, item, value, limit, r, verdict.upper(), source))
            links += _links(run.check, item, r, derived[0] if derived else None)
    if rows:  # value and limit: one notation per quantity in each column
        columns = list(zip(*rows))
        columns[2], columns[3] = cells(columns[2]), cells(columns[3])
        columns[6] = as_above(columns[6])
        rows = list(zip(*columns))
    checks = table(
        "Every check (ratio = demand/limit; above 1 fails)",
        ("check", "item", "value", "limit", "ratio", "verdict", "limit's source"),
        rows,
        (False, False, True, True, True, False, False),
    )
    return Section("Checks", (checks, Paragraph(verdict_line(runs))), tuple(links))


def as_above(texts) -> list[str]:
    """A column with each text that repeats the row above as "as above", so a long source is
    printed once per run of rows and the table does not wrap every row.

    >>> as_above(["[limits] amplitude: report", "[limits] amplitude: report", "rule", "rule"])
    ['[limits] amplitude: report', 'as above', 'rule', 'as above']
    """
    return [text if k == 0 or text != texts[k - 1] else "as above" for k, text in enumerate(texts)]


def _links(check: str, item: str, shown_ratio: str, derived) -> list[Link]:
    """The chain of a check row: its value from its ``derived`` (formula, inputs) and its ratio from
    its value and limit; a cell of this row (row ``()``) gets the row's keys."""
    def here(cell: Cell) -> Cell:
        return Cell(cell.table, (check, item), cell.column, cell.section, cell.after, cell.index) if cell.table == CHECKS_TABLE and not cell.row else cell

    links = []
    if derived is not None:
        formula, inputs = derived
        links.append(Link(formula, check_cell(check, item, "value"), tuple((name, here(cell)) for name, cell in inputs)))
    if shown_ratio not in ("-", "inf"):
        links.append(Link("ratio", check_cell(check, item, "ratio"),
                          (("value", check_cell(check, item, "value")), ("limit", check_cell(check, item, "limit")))))
    return links
