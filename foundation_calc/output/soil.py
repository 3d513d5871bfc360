"""Report of ``fcalc soil``: the soil methods side by side (rich table) and the JSON document (SI)."""

from __future__ import annotations

import math

from foundation_calc.checks.soil_methods import MethodResult, SoilComparison
from foundation_calc.output.console import JSON_SCHEMA_VERSION, fmt, stdout
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

_JSON_KEYS = (
    "K_z", "K_x", "K_phi", "c_z", "c_x", "c_phi", "xi_z", "xi_x", "xi_phi", "C_z", "C_x", "C_phi",
    "omega_z", "omega_x", "omega_phi", "k0", "p1", "p2", "rocking_stability_margin",
)


def _cell(result: MethodResult, attribute: str, scale: float | None) -> str:
    value = getattr(result, attribute)
    if math.isnan(value):
        return "tips over"
    return fmt(hz_from_omega(value) if scale is None else value * scale)


def _finite(value: float) -> float | None:
    return None if math.isnan(value) else value


def soil_document(comparison: SoilComparison, scene, source: str) -> dict:
    """The JSON document of ``fcalc soil``: every method's numbers in SI (frequencies in rad/s;
    null where the block tips over in rocking)."""
    return {
        "schema_version": JSON_SCHEMA_VERSION,
        "command": "soil",
        "scene": {"source": source, "kind": scene.kind, "name": scene.name},
        "method": comparison.used,
        "total_mass": scene.total_mass,
        "base": dict(zip(("length", "width"), scene.foundation.dimensions), area=scene.foundation.base_area,
                     second_moment=scene.foundation.base_second_moment, embedment=scene.foundation.embedment or 0.0),
        "methods": {
            r.method: {key: _finite(getattr(r, key)) for key in _JSON_KEYS} for r in comparison.results
        },
        "warnings": [*comparison.input_warnings, *comparison.findings],
    }


def print_soil_report(comparison: SoilComparison, scene, source: str) -> None:
    """Print the methods side by side; the scene's own method is marked with *."""
    from rich.markup import escape
    from rich.table import Table

    out = stdout()
    f = scene.foundation
    L, B = f.dimensions
    out.print(f"[bold]{escape(scene.name or source)}[/]", soft_wrap=True)
    derived = "" if f.base_length is not None or f.block is not None else ", from S and I1"
    out.print(
        f"base {fmt(L)} m × {fmt(B)} m{derived} (S = {fmt(f.base_area)} m², I1 = {fmt(f.base_second_moment)} m⁴,"
        f" embedment {fmt(f.embedment or 0.0)} m), M_tot = {fmt(scene.total_mass, 7)} kg", soft_wrap=True,
    )
    table = Table(title="Springs and damping by soil method (* the scene's)", title_justify="left")
    table.add_column("quantity")
    table.add_column("unit")
    for r in comparison.results:
        table.add_column(r.method + (" *" if r.method == comparison.used else ""), justify="right")
    for label, unit, attribute, scale in ROWS:
        table.add_row(label, unit, *(_cell(r, attribute, scale) for r in comparison.results))
    out.print(table)
    for text in comparison.findings:
        out.print(f"[bold yellow]note[/]: {escape(text)}", soft_wrap=True)
