"""Report of ``fcalc soil``: the soil methods side by side (rich table) and the JSON document (SI)."""

from __future__ import annotations

import math

from foundation_calc.checks.soil_methods import MethodResult, SoilComparison
from foundation_calc.output.console import JSON_SCHEMA_VERSION, Hanging, fmt, stdout
from foundation_calc.units import hz_from_omega

#: Rows of the table: (label, unit, attribute, scale from SI to the unit shown).
ROWS = (
    ("K_z, vertical spring", "MN/m", "K_z", 1e-6),
    ("K_x, horizontal spring", "MN/m", "K_x", 1e-6),
    ("K_φ, rocking spring", "MN m/rad", "K_phi", 1e-6),
    ("c_z = K_z/S", "MN/m³", "c_z", 1e-6),
    ("c_x = K_x/S", "MN/m³", "c_x", 1e-6),
    ("c_phi = K_φ/I1", "MN/m³", "c_phi", 1e-6),
    ("ξ_z, vertical damping ratio", "-", "xi_z", 1.0),
    ("ξ_x, horizontal damping ratio", "-", "xi_x", 1.0),
    ("ξ_φ, rocking damping ratio", "-", "xi_phi", 1.0),
    ("C_z, vertical dashpot", "kN s/m", "C_z", 1e-3),
    ("C_x, horizontal dashpot", "kN s/m", "C_x", 1e-3),
    ("C_φ, rocking dashpot", "kN m s/rad", "C_phi", 1e-3),
    ("f_z, vertical (uncoupled)", "Hz", "omega_z", None),
    ("f_x, horizontal (uncoupled)", "Hz", "omega_x", None),
    ("f_φ, rocking (uncoupled)", "Hz", "omega_phi", None),
    ("k0, vertical", "Hz", "k0", None),
    ("p1, sliding-rocking, lower", "Hz", "p1", None),
    ("p2, sliding-rocking, upper", "Hz", "p2", None),
)

#: Rows added for a frequency-dependent method: the frequencies on its static springs.
STATIC_ROWS = (
    ("f_φ, rocking, static springs", "Hz", "omega_phi"),
    ("k0, static springs", "Hz", "k0"),
    ("p1, static springs", "Hz", "p1"),
    ("p2, static springs", "Hz", "p2"),
)

#: Rows of the table of a frequency-dependent method at each frequency (label, unit, attribute, scale).
DYNAMIC_ROWS = (
    ("f, frequency", "Hz", "omega", None),
    ("a0 = ω B'/V_s", "-", "a0", 1.0),
    ("K_z(ω)", "MN/m", "K_z", 1e-6),
    ("K_x(ω)", "MN/m", "K_x", 1e-6),
    ("K_φ(ω)", "MN m/rad", "K_phi", 1e-6),
    ("C_z(ω)", "kN s/m", "C_z", 1e-3),
    ("C_x(ω)", "kN s/m", "C_x", 1e-3),
    ("C_φ(ω)", "kN m s/rad", "C_phi", 1e-3),
)

_JSON_KEYS = (
    "K_z", "K_x", "K_phi", "c_z", "c_x", "c_phi", "xi_z", "xi_x", "xi_phi", "C_z", "C_x", "C_phi",
    "omega_z", "omega_x", "omega_phi", "k0", "p1", "p2", "rocking_stability_margin",
)


def _cell(result: MethodResult, attribute: str, scale: float | None) -> str:
    value = getattr(result, attribute)
    if math.isnan(value):
        return "tips over"
    return fmt(hz_from_omega(value) if scale is None else value * scale)


def _static_cell(value: float) -> str:
    return "tips over" if math.isnan(value) else fmt(hz_from_omega(value))


def _finite(value: float) -> float | None:
    return None if math.isnan(value) else value


def soil_document(comparison: SoilComparison, scene, source: str) -> dict:
    """The JSON document of ``fcalc soil``: every method's numbers in SI (frequencies in rad/s;
    null where the block tips over in rocking)."""
    return heading_document(scene, source, comparison.used) | {
        "methods": {
            r.method: {key: _finite(getattr(r, key)) for key in _JSON_KEYS} | _dynamic_document(r)
            for r in comparison.results
        },
        "warnings": [*comparison.input_warnings, *comparison.findings],
    } | section_of(scene).document


def heading_document(scene, source: str, method: str) -> dict:
    """The head of a crank scene's ``fcalc soil`` document: the scene, ``method`` (the scene's soil
    method or its support's label), the total mass [kg] and the base [m, m², m⁴]."""
    f = scene.foundation
    return {
        "schema_version": JSON_SCHEMA_VERSION,
        "command": "soil",
        "scene": {"source": source, "kind": scene.kind, "name": scene.name},
        "method": method,
        "total_mass": scene.total_mass,
        "base": dict(zip(("length", "width"), f.dimensions), area=f.base_area, second_moment=f.base_second_moment,
                     embedment=f.embedment or 0.0),
    }


def section_of(scene):
    """The support's own part of ``fcalc soil`` (:meth:`~foundation_calc.solvers.supports.base.Support.soil_section`:
    a stratum's factors and cutoffs, a pile group's single pile and efficiency), at the machine's speed."""
    return scene.support().soil_section({"machine": scene.speed.omega_rad_s})


def print_section(section) -> None:
    """Print a support's own part of ``fcalc soil`` (:class:`~foundation_calc.solvers.supports.base.SoilSection`):
    its lines (wrapped at a terminal's width) and its tables at several frequencies, in order."""
    from rich.markup import escape

    for part in section.printed:
        if isinstance(part, str):
            stdout().print(escape(part))
        else:
            stdout().print(frequency_table(part.title, part.heads, part.rows, part.digits))


def _dynamic_document(result: MethodResult) -> dict:
    """A frequency-dependent method's static frequencies and its K, C at each frequency (SI)."""
    if result.static_frequencies is None:
        return {"frequency_dependent": False}
    return {
        "frequency_dependent": True,
        "static_frequencies": {k: _finite(v) for k, v in result.static_frequencies.items()},
        "at_frequencies": [
            {"at": row.at} | {key: getattr(row, key) for key in ("omega", "a0", "K_z", "K_x", "K_phi", "C_z", "C_x", "C_phi")}
            for row in result.dynamic
        ],
    }


def frequency_table(title: str, heads, rows, digits: int = 5):
    """A table of a frequency-dependent soil's quantities at several frequencies: one column per
    frequency (``heads``), one row per quantity (``rows``: label, unit, the values in that unit),
    ``digits`` significant figures."""
    from rich.markup import escape
    from rich.table import Table

    table = Table(title=escape(title), title_justify="left")
    table.add_column("quantity")
    table.add_column("unit")
    for head in heads:
        table.add_column(escape(head), justify="right")
    for label, unit, values in rows:
        table.add_row(label, unit, *(fmt(v, digits) for v in values))
    return table


def _dynamic_table(result: MethodResult):
    names = {"speed": "speed", "k0": "at k0", "p1": "at p1", "p2": "at p2"}
    rows = [
        (label, unit, [hz_from_omega(getattr(row, attribute)) if scale is None else getattr(row, attribute) * scale
                       for row in result.dynamic])
        for label, unit, attribute, scale in DYNAMIC_ROWS
    ]
    return frequency_table(f"{result.method}: springs and dashpots at the operating speed and at each mode's own frequency",
                           [names[row.at] for row in result.dynamic], rows)


def print_heading(scene, source: str) -> None:
    """The scene's name, its base and total mass: the head of a crank scene's ``fcalc soil``."""
    from rich.markup import escape

    out = stdout()
    f = scene.foundation
    L, B = f.dimensions
    out.print(Hanging(f"[bold]{escape(scene.name or source)}[/]"))
    derived = "" if f.base_length is not None or f.block is not None else ", from S and I1"
    out.print(Hanging(
        f"base {fmt(L)} m × {fmt(B)} m{derived} (S = {fmt(f.base_area)} m², I1 = {fmt(f.base_second_moment)} m⁴,"
        f" embedment {fmt(f.embedment or 0.0)} m), M_tot = {fmt(scene.total_mass, 7)} kg"
    ))


def print_soil_report(comparison: SoilComparison, scene, source: str) -> None:
    """Print the methods side by side; the scene's own method is marked with *."""
    from rich.markup import escape
    from rich.table import Table

    out = stdout()
    print_heading(scene, source)
    table = Table(title="Springs and damping by soil method (* the scene's)", title_justify="left")
    table.add_column("quantity")
    table.add_column("unit")
    for r in comparison.results:
        table.add_column(r.method + (" *" if r.method == comparison.used else ""), justify="right")
    for label, unit, attribute, scale in ROWS:
        table.add_row(label, unit, *(_cell(r, attribute, scale) for r in comparison.results))
    if any(r.static_frequencies for r in comparison.results):
        for label, unit, key in STATIC_ROWS:
            table.add_row(label, unit, *(
                "-" if r.static_frequencies is None else _static_cell(r.static_frequencies[key])
                for r in comparison.results
            ))
    out.print(table)
    for r in comparison.results:
        if r.dynamic:
            out.print(_dynamic_table(r))
    if any(r.static_frequencies for r in comparison.results):
        out.print(Hanging(
            "Frequencies of a frequency-dependent method solve ω = p(K(ω)), each mode on its springs at its own"
            " frequency; its damping ratios are taken at their mode's frequency. The other methods are"
            " frequency-independent."
        ))
    print_section(section_of(scene))
    for text in comparison.findings:
        out.print(Hanging(f"[bold yellow]note[/]: {escape(text)}", len("note: ")))


#: Rows of the sample's table: (label, unit, key, scale from SI; None: rad/s to Hz).
SAMPLE_ROWS = (
    ("stiffness factor", "-", "modulus_factor", 1.0),
    ("k0, vertical", "Hz", "k0", None),
    ("p1, sliding-rocking, lower", "Hz", "p1", None),
    ("p2, sliding-rocking, upper", "Hz", "p2", None),
    ("margin from the nearest paper resonance", "%", "resonance_margin", 100.0),
    ("peak horizontal displacement of C", "mm", "peak_horizontal_C", 1e3),
    ("peak vertical displacement of C", "mm", "peak_vertical_C", 1e3),
    *((f"mode {j}" + (", lowest" if j == 1 else ""), "Hz", f"mode{j}", None) for j in range(1, 7)),
    ("resonance utilisation (needed / governing margin)", "-", "resonance_utilisation", 1.0),
    ("amplitude utilisation (largest value / limit)", "-", "amplitude_utilisation", 1.0),
)


def sample_document(drawn) -> dict | None:
    """The sample of ``fcalc soil --sample`` in SI (frequencies rad/s, margins and factors [-], m)."""
    if drawn is None:
        return None
    from foundation_calc.checks.soil_sample import PERCENTILES

    return {
        "samples": drawn.samples, "modulus_cov": drawn.cov_modulus, "speed_cov": drawn.cov_speed, "seed": drawn.seed,
        "distributions": "stiffness factor lognormal (median 1); speed factor normal (mean 1)",
        "percentiles": [*PERCENTILES],
        "values": {key: list(values) for key, values in drawn.percentiles.items()},
        "failure_probability": drawn.failure_probability,
    }


def print_sample(drawn) -> None:
    """Percentiles of the sample and the probability that each check fails."""
    from rich.table import Table

    from foundation_calc.checks.soil_sample import PERCENTILES

    out = stdout()
    table = Table(title=f"Uncertain soil: {drawn.samples} samples, stiffness lognormal (median 1, COV"
                  f" {drawn.cov_modulus:g})" + (f", speed COV {drawn.cov_speed:g}" if drawn.cov_speed else ""),
                  title_justify="left")
    table.add_column("quantity")
    table.add_column("unit")
    for p in PERCENTILES:
        table.add_column(f"{p:g} %", justify="right")
    for label, unit, key, scale in (row for row in SAMPLE_ROWS if row[2] in drawn.percentiles):
        values = drawn.percentiles[key]
        table.add_row(label, unit, *(fmt(hz_from_omega(v) if scale is None else v * scale) for v in values))
    out.print(table)
    p = drawn.failure_probability
    out.print(Hanging(
        f"probability of failing: resonance {p['resonance']:.2%}, amplitudes {p['amplitudes']:.2%}, any check"
        f" {p['any']:.2%} (tips over {p['tips_over']:.2%})"
    ))
