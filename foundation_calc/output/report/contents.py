"""What a calculation sheet says, read from the JSON documents of the single-scene commands.

This module is the only place of the report package that reads JSON keys, so a renamed key is
fixed here once. Numbers are shown with 6 significant figures in the chosen display units.
"""

from __future__ import annotations

import math

from dataclasses import dataclass

from foundation_calc.output.display_units import DisplayUnits
from foundation_calc.output.report import equations
from foundation_calc.output.report.model import Figure, Paragraph, Section, table
from foundation_calc.output.report.numbers import column, echoed, figure, percent, share
from foundation_calc.output.report.resonance_text import crank_rule_paragraph, margin_definition
from foundation_calc.output.report.verdict import resonance_verdict, sensitivity_label
from foundation_calc.solvers.crank.frequencies import stability_margin_formula

DIGITS = 4
#: A harmonic smaller than this fraction of its coordinate's largest one is left out of the table.
NEGLIGIBLE = 1e-9


@dataclass(frozen=True)
class SweepSeries:
    """What the sweep plot draws, from the ``sweep`` JSON document (SI units)."""

    omega: list[float]
    peaks: dict[str, list[float | None]]
    amplitude_limit: float | None
    detuning: float | dict
    critical: list[tuple[str, str, float, float]]
    method: str


def sweep_series(doc: dict) -> SweepSeries:
    """The plotted series of a speed sweep: speeds, peaks of y and x of C, limits, critical speeds."""
    rows = doc["points"]
    return SweepSeries(
        omega=[r["omega"] for r in rows],
        peaks={"y of C": [r["y_peak"] for r in rows], "x of C": [r["x_peak"] for r in rows]},
        amplitude_limit=doc["limits"]["amplitude"],
        detuning=doc["limits"]["detuning"],
        critical=[(c["condition"], c["source"], c["zero_order"], c["band"]) for c in doc["critical_speeds"]],
        method=doc["method"],
    )


def operating_speed(resonance: dict) -> float:
    """The crank speed ω [rad/s] of the ``resonance`` JSON document."""
    return resonance["speed"]["omega"]


def num(value: float | None, digits: int = DIGITS, scale: float | None = None) -> str:
    """A number with ``digits`` significant figures in the sheet's format (``-`` for a missing
    one, 0 below round-off of ``scale``): :func:`~foundation_calc.output.report.numbers.figure`."""
    return figure(value, digits, scale)


def pct(value: float) -> str:
    """A fraction as a percentage to one decimal, as every margin on a sheet."""
    return percent(value)


def truncation(error: float) -> str:
    """An error estimate: two figures, or "less than 10⁻⁹" when it is round-off (never 0: it is a bound)."""
    return "less than 10⁻⁹" if error < 1e-9 else figure(error, 2)


def _columns(rows: list[tuple], digits: int, groups) -> list[tuple]:
    """Rows ``(label, *values)`` with each value column formatted in one notation per group of
    rows (``groups``: a key per row, e.g. the unit), round-off below 1e-9 of the group's largest as 0."""
    out = [[row[0]] for row in rows]
    for j in range(1, len(rows[0]) if rows else 1):
        for key in dict.fromkeys(groups):
            members = [i for i, g in enumerate(groups) if g == key]
            values = [rows[i][j] for i in members]
            scale = max((abs(v) for v in values if v is not None), default=0.0) or None
            for i, text in zip(members, column(values, digits, scale)):
                out[i].append(text)
    return [tuple(row) for row in out]


def _speed(units: DisplayUnits, omega: float) -> str:
    return num(units.convert("speed", omega))


def _equation_section(eqs) -> Section:
    return Section("Equations used", tuple(eqs))


# --------------------------------------------------------------------------- crank foundation


def _crank_derived(res: dict, units: DisplayUnits) -> Section:
    d, s = res["derived"], res["speed"]
    named = (  # a machine given by its loads has no mechanism: μ, λ, m, κ are absent
        ("mu", "μ = m/M_tot, moving-mass ratio", "-"),
        ("lambda", "λ = r/l, crank-to-rod ratio", "-"),
        ("total_mass", "M_tot, total mass", "kg"),
        ("moving_mass", "m, moving mass", "kg"),
        ("rho1", "ρ1 = sqrt(I_c/M_tot)", "m"),
        ("kappa", "κ = l'l'' − ρ²", "m²"),
        ("K_xphi", "K_xφ, the support's sway-rocking coupling", "N/rad"),
        ("rocking_stability_margin", f"rocking stability margin {stability_margin_formula('K_xphi' in d, '−')}", "-"),
    )
    rows = (
        ("ω, speed", _speed(units, s["omega"]), units.label("speed")),
        *((text, num(d[key]), unit) for key, text, unit in named if key in d),
    )
    return Section("Derived quantities", (table("", ("quantity", "value", "unit"), rows, (False, True, False)),))


def _crank_frequencies(res: dict, units: DisplayUnits) -> Section:
    sp = units.label("speed")
    zero, avg = res["natural_frequencies"], res["natural_frequencies_averaged_inertia"]
    hz = sp != "Hz"  # the frequency in Hz beside a speed in rad/s or rpm
    freqs = table(
        "Natural frequencies",
        ("mode", f"ω [{sp}]", *(("f [Hz]",) if hz else ()), f"averaged inertia, ω [{sp}]"),
        ((mode, _speed(units, zero[mode]), *((figure(zero[mode] / (2.0 * math.pi), 4),) if hz else ()), _speed(units, avg[mode]))
         for mode in zero),
    )
    shares = [share(r["forcing_share"]) for r in res["resonances"]]  # the largest share is 100 %
    rows = (
        (
            r["condition"] + {"extra": " (extra)", "loads": " (loads)"}.get(r["source"], ""),
            r["mode_name"],
            _speed(units, r["critical_speed"]["omega"]),
            _speed(units, r["critical_speed_averaged_inertia"]["omega"]),
            pct(r["margin"]),
            pct(r["required"]) if r["required"] > 0 else "none",
            share,
            resonance_verdict(r).upper(),
        )
        for r, share in zip(res["resonances"], shares)
    )
    resonances = table(
        "Resonances: critical speeds and margins",
        ("condition", "mode", f"critical [{sp}]", f"avg. inertia [{sp}]", "margin", "required", "forcing share", "verdict"),
        rows,
        (False, False, True, True, True, True, True, False),
    )
    rule = Paragraph(crank_rule_paragraph(res, lambda w: units.convert("speed", w), sp))
    return Section("Natural frequencies and resonances", (freqs, resonances, rule))


def _largest_harmonics(approximation: dict) -> dict[str, float]:
    """The largest harmonic magnitude of each coordinate x, y, theta of one method."""
    largest: dict[str, float] = {}
    for name, harmonic in approximation["harmonics"].items():
        dof = name.rstrip("0123456789")
        largest[dof] = max(largest.get(dof, 0.0), harmonic["magnitude"])
    return largest


def _crank_amplitudes(amp: dict, units: DisplayUnits) -> Section:
    approximations = amp["approximations"]
    checked = approximations[amp["checked_with"]]
    blocks = [Paragraph(f"Checked with: {checked['title']}. Signs: {amp['conventions']}.")]
    blocks += [Paragraph(f"{key.replace('_', ' ').capitalize()}: {why}.") for key, why in (amp.get("not_applicable") or {}).items()]
    if checked["resonant"]:
        blocks.append(Paragraph(f"Resonant: {checked['nearest_resonance']}; no steady state without damping."))
        return Section("Amplitudes", tuple(blocks))
    shown = [(key, a) for key, a in approximations.items() if not a["resonant"]]
    au = units.label("amplitude")
    rows, units_of_rows, phase_rows = [], [], []
    largest = [_largest_harmonics(a) for _, a in shown]
    for name in checked["harmonics"]:
        dof = name.rstrip("0123456789")
        # a harmonic below NEGLIGIBLE of its coordinate's largest is round-off: shown as 0, dropped when all are
        h = [a["harmonics"][name]["magnitude"] * (a["harmonics"][name]["magnitude"] > NEGLIGIBLE * big[dof]) for (_, a), big in zip(shown, largest)]
        if not any(h):
            continue
        unit = "rad" if dof == "theta" else au
        scale = (lambda v: v) if unit == "rad" else (lambda v: units.convert("amplitude", v))
        shown_name = name.replace("theta", "θ")  # the paper's θ1, as the rest of the sheet writes it
        rows.append((f"{shown_name} [{unit}]", *(scale(x) for x in h)))
        units_of_rows.append(unit)
        if not name.endswith("0"):  # the mean has a sign, not a phase
            phase_rows.append(
                (shown_name, *(f"{math.degrees(a['harmonics'][name]['phase']):.1f}" if x else "-" for (_, a), x in zip(shown, h)))
            )
    methods = tuple(k.replace("_", " ") for k, _ in shown)
    blocks.append(table("Amplitude per harmonic (magnitude)", ("harmonic", *methods), _columns(rows, 3, units_of_rows)))
    if amp["damping"] is not None:
        d = amp["damping"]
        modes = ", ".join(
            f"{num(w)} rad/s: ζ = {num(z, 3)}" for w, z in zip(d["natural_frequencies"], d["modal_damping_ratios"])
        )
        blocks.append(Paragraph(
            f"Damped: base dashpots C_x = {num(d['dashpots']['C_x'])} N s/m, C_z = {num(d['dashpots']['C_z'])} N s/m,"
            f" C_φ = {num(d['dashpots']['C_phi'])} N m s/rad"
            + (f", C_xφ = {num(d['dashpots']['C_xphi'])} N s/rad" if "C_xphi" in d["dashpots"] else "")
            + "; modes of the averaged operator and their damping"
            f" ratios: {modes}. Each harmonic is A cos(nωt − φ)."
        ))
        blocks.append(table("Phase lag φ per harmonic [°]", ("harmonic", *methods), phase_rows))
    quantity_units = {
        "displacement": ("amplitude", au),
        "velocity": ("velocity", units.label("velocity")),
        "acceleration": ("acceleration", units.label("acceleration")),
    }
    raw = [
        (f"{point}\t{direction}", *(units.convert(quantity_units[q][0], v) for q, v in peaks.items()))
        for point, dirs in checked["points"].items()
        for direction, peaks in dirs.items()
    ]
    point_rows = [(*row[0].split("\t"), *row[1:]) for row in _columns(raw, 3, [0] * len(raw))]
    header = ("point", "direction", *(f"{q} [{u}]" for q, (_, u) in quantity_units.items()))
    blocks.append(table("Peaks over one revolution", header, point_rows, (False, False, True, True, True)))
    return Section("Amplitudes", tuple(blocks))


def _largest_peak_errors(errors: dict) -> list[str]:
    """The largest relative error of the peaks over every point, per quantity, as table cells."""
    points = errors["points"].values()
    return [num(max(max(p[q].values()) for p in points), 3) for q in ("displacement", "velocity", "acceleration")]


def _crank_accuracy(amp: dict, exact: dict | None, mechanism: bool) -> Section:
    """How exact the checked numbers are: the method that judged the limits and, with ``--exact``
    (``exact``: the amplitudes document with the exact periodic solution), its errors."""
    approximations = amp["approximations"]
    text = [f"Limits checked with the {approximations[amp['checked_with']]['title']} (as fcalc check does)."]
    if not mechanism:
        text.append(
            "The machine is given by its loads: their steady state is the exact solution of the linear"
            " rigid-block model (one complex solve per harmonic); there is no closed form to estimate."
        )
        return Section("Accuracy", tuple(Paragraph(t) for t in text))
    solver = None if exact is None else exact.get("exact_solver")
    if solver is None:
        text.append(
            "The exact periodic solution was not computed (run with --exact to state the closed forms'"
            " errors against it)."
        )
        return Section("Accuracy", tuple(Paragraph(t) for t in text))
    text.append(
        f"Exact solution: harmonic balance with {solver['harmonics']} harmonics, {solver['newton_iterations']}"
        f" Newton step(s), change from half the harmonics {num(solver['harmonic_change'], 3)},"
        f" relative residual {num(solver['relative_residual'], 3)}."
    )
    rows = [
        (key.replace("_", " "), *_largest_peak_errors(err))
        for key, err in (exact.get("errors") or {}).items()
        if err is not None
    ]
    errors = table(
        "Largest relative error of the peaks of every point against the exact solution",
        ("method", "displacement", "velocity", "acceleration"),
        rows,
    )
    return Section("Accuracy", (*(Paragraph(t) for t in text), errors))


def crank_sections(docs: dict, figures: tuple[Figure, ...], units: DisplayUnits, exact: dict | None) -> tuple[Section, ...]:
    """The sections of a crank foundation's sheet from the ``resonance`` and ``amplitudes``
    documents of its checks (``exact``: the amplitudes document of ``--exact``, or None)."""
    res, amp = docs["resonance"], docs["amplitudes"]
    mechanism = "mu" in res["derived"]
    return (
        _crank_derived(res, units),
        _crank_frequencies(res, units),
        _crank_amplitudes(amp, units),
        _equation_section(((equations.PLANE if "K_xphi" in res["derived"] else equations.CRANK) if mechanism else ())
                          + (equations.LOADS if amp.get("loads") else ())),
        Section("Plots", figures),
        _crank_accuracy(amp, exact, mechanism),
    )


# --------------------------------------------------------------------------- platform


def _platform_inputs(doc: dict, units: DisplayUnits) -> Section:
    i = doc["inputs"]
    rows = (
        ("ω, speed", _speed(units, doc["speed"]["omega"]), units.label("speed")),
        ("M, platform and product mass", num(i["M"]), "kg"),
        ("m, unbalanced mass", num(i["m"]), "kg"),
        ("l, eccentricity", num(i["l"]), "m"),
        ("u, required circular amplitude", num(units.convert("amplitude", i["u"])), units.label("amplitude")),
        ("regime", str(i["regime"]), "-"),
        ("ξ, η, ζ, centre of mass", ", ".join(num(i[k]) for k in ("xi", "eta", "zeta")), "m"),
        ("A, B, isolator spacing", ", ".join(num(i[k]) for k in ("A", "B")), "m"),
        ("g", num(i["g"]), "m/s²"),
    )
    return Section("Inputs as the design uses them", (table("", ("quantity", "value", "unit"), rows, (False, True, False)),))


def _platform_design(doc: dict, units: DisplayUnits) -> Section:
    d = doc["design"]
    rows = [
        ("M_Σ, moving mass", num(d["M_sigma"]), "kg"),
        ("c0 = c1 = c2 (3.14)", num(d["c0"]), "N/m"),
        ("c3, summed vertical stiffness", num(d["c3"]), "N/m"),
        *((f"{k} (3.16)-(3.20)", num(v), "N/m") for k, v in d["horizontal_sums"].items()),
        ("a (3.9)", num(d["a"]), "m"),
        ("b (3.10)", num(d["b"]), "m"),
        ("c (3.11)", num(d["c"]), "m"),
        ("static deflection", num(units.convert("amplitude", d["static_deflection"])), units.label("amplitude")),
        ("translational resonance", _speed(units, d["translation_frequency"]), units.label("speed")),
    ]
    design = table("Design", ("quantity", "value", "unit"), rows, (False, True, False))
    stiff = table(
        "Isolator stiffnesses c_ij [N/m]",
        ("isolator", "x", "y", "z"),
        ((f"O{n + 1}", *(num(x) for x in row)) for n, row in enumerate(d["stiffness_table"])),
    )
    return Section("Platform design", (design, stiff))


def _platform_verification(doc: dict, units: DisplayUnits) -> Section:
    v, i = doc["verification"], doc["inputs"]
    au = units.label("amplitude")
    u = i["u"]  # round-off is judged against the required amplitude and its rotation over the platform
    tilt = u / max(i["A"], i["B"], 1e-300)
    rows = [
        *((f"amplitude of {k}", num(units.convert("amplitude", a), 4, units.convert("amplitude", u)), au) for k, a in v["amplitudes"].items()),
        *((f"rotation amplitude {k}", num(r, 3, tilt), "rad") for k, r in v["rotations"].items()),
        ("static tilt", num(v["static_tilt"], 3, tilt), "rad"),
        ("static corner offset", num(v["static_offset_percent"], 3, 100), "% of u"),
        ("rocking of the corners", num(v["rocking_percent"], 3, 100), "% of u"),
        ("spread of corner amplitudes", num(v["spread_percent"], 3, 100), "% of u"),
        ("harmonic balance: truncation order K", str(v["harmonic_balance"]["order"]), "-"),
        ("harmonic balance: frequencies solved", str(v["harmonic_balance"]["frequencies"]), "-"),
        ("harmonic balance: truncation error (estimate)", truncation(v["harmonic_balance"]["truncation_error_over_u"]), "u"),
    ]
    inertia = v["inertia"]["source"]
    verification = table(
        f"6-DOF verification (inertia: {inertia}; loss factor {echoed(v['loss_factor'])},"
        f" damping ratio {echoed(v['damping_ratio'])})",  # the scene's inputs, as given
        ("quantity", "value", "unit"),
        rows,
        (False, True, False),
    )
    sp = units.label("speed")
    freqs = table(
        "Natural frequencies (6-DOF, undamped)",
        ("mode", f"[{sp}]", "margin"),
        ((f["mode"], _speed(units, f["omega"]), pct(f["margin"])) for f in doc["natural_frequencies"]),
    )
    damping = "with the isolators' damping" if doc["sensitivity_with_damping"] else "undamped"
    keys = ("rocking_percent_plus", "rocking_percent_minus", "static_offset_percent_plus", "static_offset_percent_minus")
    raw = [(sensitivity_label(s), *(s[k] for k in keys)) for s in doc["sensitivity"]]
    formatted = _columns(raw, 3, [0] * len(raw))
    sens = table(
        f"Sensitivity to build tolerances ({damping}) [% of u]",
        ("parameter", "tolerance", "rocking +", "rocking −", "static +", "static −"),
        ((row[0], str(s["tolerance"]), *row[1:]) for row, s in zip(formatted, doc["sensitivity"])),
        (False, False, True, True, True, True),
    )
    definitions = Paragraph(
        "Rocking of the corners: the largest peak over time, over the eight corners of the product box"
        f" [0, A] × [0, B] × [0, H] (H = {num(v['product_height'])} m), of a corner's displacement relative to the platform's centre of mass"
        " (its motion from the rotations α, β, γ alone, (α, β, γ) × (corner − centre of mass)), in % of u."
        " Static corner offset: the same from the static tilt. Spread of corner amplitudes: the largest"
        " minus the smallest corner peak, in % of u. "
        + margin_definition(f"{_speed(units, doc['speed']['omega'])} {sp}")
    )
    return Section("6-DOF verification", (verification, definitions, freqs, sens))


def platform_sections(docs: dict, units: DisplayUnits, figures: tuple[Figure, ...] = ()) -> tuple[Section, ...]:
    """The sections of a vibrating platform's sheet from the ``design`` check's document."""
    doc = docs["design"]
    return (
        _platform_inputs(doc, units),
        _platform_design(doc, units),
        _platform_verification(doc, units),
        *((Section("Plots", figures),) if figures else ()),
        _equation_section(equations.PLATFORM),
        Section(
            "Accuracy",
            (
                Paragraph(
                    "Design: closed forms (3.8)-(3.21), corrected. Verification: the steady state of the full"
                    " linear 6-DOF equations with periodic coefficients, solved by harmonic balance over the"
                    f" combinations of the rotor speeds up to order K = {doc['verification']['harmonic_balance']['order']};"
                    " the estimated displacement of the harmonics left out is"
                    f" {truncation(doc['verification']['harmonic_balance']['truncation_error_over_u'])} u. The rocking"
                    " figures are the difference between this solution and the intended pure translation."
                ),
            ),
        ),
    )
