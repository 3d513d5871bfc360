"""``fcalc soil`` of a scene on a support (:mod:`foundation_calc.checks.soil_support`): the support's
own part (:meth:`~foundation_calc.solvers.supports.base.Support.soil_section`: a stratum's factors,
a pile group's single pile and efficiency) and its springs and dashpots at rest, at the machines'
speeds or harmonics and at each mode's own frequency, in the crank foundation's layout
(:func:`~foundation_calc.output.soil.frequency_table`); tables and the JSON document (SI).

One report for every scene kind; what differs is data (:data:`LAYOUTS`): the rows a kind reads
the support by, the tables' titles, the keys of a column's JSON, and what precedes the support's
part (a block's springs at rest by motion; a crank's heading and why no soil methods are compared).
"""

from __future__ import annotations

from dataclasses import dataclass
from typing import Callable

from foundation_calc.output.console import JSON_SCHEMA_VERSION, fmt, stdout
from foundation_calc.solvers.rigid_body.modes import MOTIONS
from foundation_calc.units import hz_from_omega

#: A block's units of its springs and dashpots by motion, at rest.
UNITS = {"K": ("N/m",) * 3 + ("N m/rad",) * 3, "C": ("N s/m",) * 3 + ("N m s/rad",) * 3}

#: A block's rows at each frequency: (key, label, unit, scale from SI) of each spring, then of each
#: dashpot (units that keep four significant figures short).
BLOCK_ROWS = tuple((f"{q}_{m}", f"{q}_{m}(ω)", ("MN/m" if i < 3 else "MN m/rad") if q == "K" else
                    ("MN s/m" if i < 3 else "MN m s/rad"), 1e-6) for q in "KC" for i, m in enumerate(MOTIONS))

#: A crank's rows of the plane's springs and dashpots: (key, label, unit, scale from SI).
PLANE_ROWS = (
    ("K_x", "K_x(ω)", "MN/m", 1e-6), ("K_z", "K_z(ω)", "MN/m", 1e-6), ("K_phi", "K_φ(ω)", "MN m/rad", 1e-6),
    ("K_xphi", "K_xφ(ω)", "MN/rad", 1e-6),
    ("C_x", "C_x(ω)", "MN s/m", 1e-6), ("C_z", "C_z(ω)", "MN s/m", 1e-6), ("C_phi", "C_φ(ω)", "MN m s/rad", 1e-6),
    ("C_xphi", "C_xφ(ω)", "MN s/rad", 1e-6),
)


@dataclass(frozen=True)
class Layout:
    """What a scene kind's ``fcalc soil`` of a support shows its own way: ``rows`` the values at each
    frequency (key, label, unit, scale from SI); ``titles`` of the tables at rest and the machines'
    speeds, and at the modes (``{method}``: the support's label); ``keys`` of a column's JSON before
    its values (``machine``, ``order``, ``mode_name``: its name where it is at a speed, a harmonic,
    a mode); ``values`` a column's values in JSON; ``head`` prints and ``document`` gives what the
    kind shows around the support's part."""

    rows: tuple
    titles: tuple[str, str]
    keys: tuple[str, ...]
    values: Callable[[dict], dict]
    head: Callable
    document: Callable


def not_compared(method: str) -> str:
    """The one line saying why no soil methods are compared."""
    return (f"The soil methods' comparison is for footings: the support {method} replaces the footing, so its own"
            " springs and dashpots at O follow.")


def _at_rest(model) -> list[dict]:
    """A block's springs at rest per motion at O: spring, dashpot, damping ratio C/(2 sqrt(K m_i)),
    uncoupled frequency sqrt(K/m_i) with m_i the total mass (translations) or the moment of inertia
    about the axis through O (rotations; the weight's tilt left out)."""
    import numpy as np

    m = np.diag(model.M)
    K, C = model.springs, np.diag(model.C)
    return [
        {"motion": name, "K": float(K[i]), "C": float(C[i]), "xi": float(C[i] / (2.0 * np.sqrt(K[i] * m[i]))),
         "omega_uncoupled": float(np.sqrt(K[i] / m[i]))}
        for i, name in enumerate(MOTIONS)
    ]


def _block_head(report, scene, source: str) -> None:
    """A block's table of its springs and dashpots at O by motion (at rest on a frequency-dependent soil)."""
    import numpy as np
    from rich.markup import escape
    from rich.table import Table

    rest = ", static (ω = 0)" if scene.support().frequency_dependent else ""
    table = Table(title=f"{escape(scene.name or source)}: springs and dashpots at O, method {report.method}{rest}",
                  title_justify="left")
    for col in ("motion", "K", "unit", "C", "unit", "ξ", "uncoupled, Hz"):
        table.add_column(col, justify="left" if col in ("motion", "unit") else "right")
    for i, row in enumerate(_at_rest(report.body)):
        table.add_row(row["motion"], fmt(row["K"], 4), UNITS["K"][i], fmt(row["C"], 4), UNITS["C"][i], fmt(row["xi"], 3),
                      fmt(row["omega_uncoupled"] / (2 * np.pi), 4))
    stdout().print(table)


def _crank_head(report, scene, source: str) -> None:
    """A crank's heading (its base and mass) and why no soil methods are compared."""
    from foundation_calc.output.soil import print_heading

    print_heading(scene, source)
    stdout().print(not_compared(report.method))


def _block_document(report, scene, source: str, column) -> dict:
    """A block's keys: the support's method, its springs at rest by motion and every column."""
    support = scene.support()
    return {
        "schema_version": JSON_SCHEMA_VERSION,
        "command": "soil",
        "scene": {"source": source, "kind": scene.kind, "name": scene.name},
        "method": support.method,
        "frequency_dependent": support.frequency_dependent,
        "total_mass": report.body.mass,
        "base": {"length": scene.block.length, "width": scene.block.width},
        "springs": _at_rest(report.body),
        "warnings": scene.plausibility_warnings(),
        "at_frequencies": [column(c) for c in report.columns + report.modes],
    } | support.soil_section(report.speeds).document


def _crank_document(report, scene, source: str, column) -> dict:
    """A crank's keys (:func:`~foundation_calc.output.soil.heading_document`, ``methods`` empty, the
    support's own part) and ``comparison``, why no methods are compared; ``soil_validity``, as
    ``fcalc resonance``'s; ``in_plane``, the springs and dashpots at each frequency and the natural
    frequencies [rad/s]."""
    from foundation_calc.output.notes import soil_validity_document
    from foundation_calc.output.soil import heading_document

    return heading_document(scene, source, report.method) | {
        "methods": {},
        "warnings": scene.plausibility_warnings(),
    } | scene.support().soil_section(report.speeds).document | {
        "comparison": not_compared(report.method),
        "soil_validity": soil_validity_document(report.validity),
        "in_plane": {
            "at_frequencies": [column(c) for c in report.columns],
            "at_modes": [column(c) for c in report.modes],
            "natural_frequencies": report.frequencies,
            "static_frequencies": report.static_frequencies,
        },
    }


def _named(at: str):
    """A column's ``name`` where it is ``at`` (a speed, a harmonic, a mode), else None."""
    return lambda c: c.name if c.at == at else None


#: A column's JSON keys before its values, each read from the column (:class:`~foundation_calc.checks.soil_support.SoilAt`).
_KEYS = {"at": lambda c: c.at, "machine": _named("speed"), "order": _named("order"), "mode": lambda c: c.mode,
         "mode_name": _named("mode"), "omega": lambda c: c.omega, "a0": lambda c: c.a0}

LAYOUTS = {
    "block_foundation": Layout(
        BLOCK_ROWS,
        ("Springs and dashpots at O at rest and at each machine's speed ω",
         "Springs and dashpots at O at each mode's own frequency p_j = p_j(K(p_j)) (mode j of fcalc resonance, its"
         " dominant motion)"),
        ("at", "machine", "mode", "mode_name", "omega", "a0"),
        lambda v: {"springs": {m: v[f"K_{m}"] for m in MOTIONS}, "dashpots": {m: v[f"C_{m}"] for m in MOTIONS}},
        _block_head, _block_document),
    "crank_foundation": Layout(
        PLANE_ROWS,
        ("Springs and dashpots of the {method} in the plane at O (u_x, u_z, θ_y; K_xφ, C_xφ the sway-rocking coupling)"
         " at rest and at the speed's harmonics n ω",
         "Natural frequencies k0, p1, p2 of the plane's one model (fcalc resonance), each on the springs at its own"
         " frequency p = p(K(p)), and those springs"),
        ("at", "order", "mode", "omega", "a0"),
        dict, _crank_head, _crank_document),
}


def soil_document(report, scene, source: str) -> dict:
    """The JSON document (SI) of ``fcalc soil`` of ``scene`` on a support: ``report``
    (:class:`~foundation_calc.checks.soil_support.SupportSoil`) in its kind's layout."""
    layout = LAYOUTS[scene.kind]

    def column(c) -> dict:
        return {key: _KEYS[key](c) for key in layout.keys} | layout.values(c.values)

    return layout.document(report, scene, source, column)


def _rows(layout, columns, *after_f) -> list:
    """f [Hz], the rows ``after_f``, a0 (where the support has one), then the kind's springs and
    dashpots at ``columns``."""
    rows = [("f", "Hz", [hz_from_omega(c.omega) for c in columns]), *after_f]
    rows += [("a0", "-", [c.a0 for c in columns])] if all(c.a0 is not None for c in columns) else []
    return rows + [(label, unit, [c.values[key] * scale for c in columns]) for key, label, unit, scale in layout.rows]


def print_support_soil(report, scene, source: str) -> None:
    """The tables of ``fcalc soil`` of ``scene`` on a support (module docstring): what its kind shows
    first, the support's own part, its springs and dashpots at rest and at the machines' speeds, then
    at each mode's own frequency (on the springs at rest too, where the report has them), and the
    support's validity where it is judged."""
    from foundation_calc.output.notes import print_soil_validity
    from foundation_calc.output.soil import print_section

    layout = LAYOUTS[scene.kind]
    layout.head(report, scene, source)
    print_section(scene.support().soil_section(report.speeds))
    rest, at_modes = layout.titles
    if report.columns:
        print_frequencies(rest.format(method=report.method), report.columns, lambda columns: _rows(layout, columns))
    if report.modes:
        static = report.static_frequencies

        def mode_rows(columns) -> list:
            on_static = [] if static is None else [("f, static K", "Hz", [hz_from_omega(static[c.mode]) for c in columns])]
            return _rows(layout, columns, *on_static)

        print_frequencies(at_modes, report.modes, mode_rows)
        print_rest_note(scene.support())
    if report.validity is not None:
        print_soil_validity(report.validity)


def print_rest_note(support) -> None:
    """What a0 is and at which frequencies the commands take a frequency-dependent support's springs."""
    stdout().print(support.a0(0.0)[1] + ". The modes and the checks take the soil at these"
                   " frequencies: each mode at its own, each order n of a machine at n ω; the static springs hold at"
                   " rest only.")


def print_frequencies(title: str, columns, rows) -> None:
    """The springs and dashpots at the frequencies of ``columns`` (:class:`~foundation_calc.checks.soil_support.SoilAt`;
    ``rows`` of some columns the table's rows): one table, or as few tables of fewer frequencies each
    as fit the console's width (a terminal's; a file takes one)."""
    from math import ceil

    from foundation_calc.output.console import fits
    from foundation_calc.output.soil import frequency_table

    out = stdout()
    for parts in range(1, len(columns) + 1):
        size = ceil(len(columns) / parts)
        groups = [columns[k:k + size] for k in range(0, len(columns), size)]
        tables = [frequency_table(title if k == 0 else f"{title} (continued)", [c.label for c in group],
                                  rows(group), 4) for k, group in enumerate(groups)]
        if all(fits(t, out.width) for t in tables) or size == 1:
            out.print(*tables)
            return


__all__ = ["BLOCK_ROWS", "LAYOUTS", "PLANE_ROWS", "Layout", "not_compared", "print_frequencies", "print_rest_note",
           "print_support_soil", "soil_document"]
