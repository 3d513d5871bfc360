"""``fcalc soil`` of a crank scene on a support that is no footing (a pile group): the support's
own part (:meth:`~foundation_calc.solvers.supports.base.Support.soil_section`, as a block's soil
table shows it), its springs and dashpots in the plane at O at rest, at the speed's harmonics and
at each mode's own frequency, and the plane's natural frequencies
(:mod:`foundation_calc.checks.plane_soil`); tables and the JSON document (SI)."""

from __future__ import annotations

from foundation_calc.output.console import stdout
from foundation_calc.units import hz_from_omega

#: Rows of the plane's springs and dashpots: (key, label, unit, scale from SI).
PLANE_ROWS = (
    ("K_x", "K_x(ω)", "MN/m", 1e-6), ("K_z", "K_z(ω)", "MN/m", 1e-6), ("K_phi", "K_φ(ω)", "MN m/rad", 1e-6),
    ("K_xphi", "K_xφ(ω)", "MN/rad", 1e-6),
    ("C_x", "C_x(ω)", "MN s/m", 1e-6), ("C_z", "C_z(ω)", "MN s/m", 1e-6), ("C_phi", "C_φ(ω)", "MN m s/rad", 1e-6),
    ("C_xphi", "C_xφ(ω)", "MN s/rad", 1e-6),
)


def not_compared(method: str) -> str:
    """The one line saying why no soil methods are compared."""
    return (f"The soil methods' comparison is for footings: the support {method} replaces the footing, so its own"
            " springs and dashpots at O follow.")


def _at_document(at) -> dict:
    """One frequency's springs and dashpots in the plane (SI), named as the table's column is."""
    c = at.column
    return {"at": c.at, "order": c.name if c.at == "order" else None, "mode": c.mode, "omega": c.omega, "a0": c.a0} | at.values


def soil_document(report, scene, source: str) -> dict:
    """The JSON document (SI) of ``fcalc soil`` for a crank scene on a support: the crank's keys
    (:func:`~foundation_calc.output.soil.heading_document`, ``methods`` empty, the support's own part)
    and ``comparison``, why no methods are compared; ``soil_validity``, as ``fcalc resonance``'s;
    ``in_plane``, the springs and dashpots at each frequency and the natural frequencies [rad/s]."""
    from foundation_calc.output.notes import soil_validity_document
    from foundation_calc.output.soil import heading_document, section_of

    return heading_document(scene, source, report.method) | {
        "methods": {},
        "warnings": scene.plausibility_warnings(),
    } | section_of(scene).document | {
        "comparison": not_compared(report.method),
        "soil_validity": soil_validity_document(report.validity),
        "in_plane": {
            "at_frequencies": [_at_document(a) for a in report.columns],
            "at_modes": [_at_document(a) for a in report.modes],
            "natural_frequencies": report.frequencies,
            "static_frequencies": report.static_frequencies,
        },
    }


def _rows(columns, *after_f) -> list:
    """f [Hz], the rows ``after_f``, a0 (where the support has one), then the plane's springs and
    dashpots at ``columns``."""
    rows = [("f", "Hz", [hz_from_omega(c.column.omega) for c in columns]), *after_f]
    rows += [("a0", "-", [c.column.a0 for c in columns])] if all(c.column.a0 is not None for c in columns) else []
    return rows + [(label, unit, [c.values[key] * scale for c in columns]) for key, label, unit, scale in PLANE_ROWS]


def print_plane_soil(report, scene, source: str) -> None:
    """The tables of ``fcalc soil`` for a crank scene on a support (module docstring)."""
    from foundation_calc.output.block_soil import print_frequencies, print_rest_note
    from foundation_calc.output.notes import print_soil_validity
    from foundation_calc.output.soil import print_heading, print_section, section_of

    out = stdout()
    print_heading(scene, source)
    out.print(not_compared(report.method))
    print_section(section_of(scene))
    print_frequencies(f"Springs and dashpots of the {report.method} in the plane at O (u_x, u_z, θ_y; K_xφ, C_xφ the"
                      " sway-rocking coupling) at rest and at the speed's harmonics n ω", report.columns, _rows)
    static = report.static_frequencies
    print_frequencies("Natural frequencies k0, p1, p2 of the plane's one model (fcalc resonance), each on the springs"
                      " at its own frequency p = p(K(p)), and those springs", report.modes,
                      lambda columns: _rows(columns, ("f, static K", "Hz", [hz_from_omega(static[c.column.mode]) for c in columns])))
    print_rest_note(scene.support())
    print_soil_validity(report.validity)


__all__ = ["PLANE_ROWS", "not_compared", "print_plane_soil", "soil_document"]
