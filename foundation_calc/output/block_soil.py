"""``fcalc soil`` of a block scene: the six springs and dashpots at O of the scene's support, and
its own part (:meth:`~foundation_calc.solvers.supports.base.Support.soil_section`: a stratum's
factors, a pile group's single pile and efficiency); on a frequency-dependent support also at each
machine's speed and at each mode's own frequency (:mod:`foundation_calc.checks.block_soil`), in
the crank foundation's layout (:func:`~foundation_calc.output.soil.frequency_table`)."""

from __future__ import annotations

import numpy as np

from foundation_calc.output.console import JSON_SCHEMA_VERSION, fmt, stdout
from foundation_calc.solvers.rigid_body.modes import MOTIONS
from foundation_calc.units import hz_from_omega

UNITS = {"K": ("N/m",) * 3 + ("N m/rad",) * 3, "C": ("N s/m",) * 3 + ("N m s/rad",) * 3}

#: Rows of the tables at each frequency: (label, unit, scale from SI) of each spring, then of each
#: dashpot (units that keep four significant figures short).
SPRINGS_AT = tuple((f"K_{m}(ω)", "MN/m" if i < 3 else "MN m/rad", 1e-6) for i, m in enumerate(MOTIONS))
DASHPOTS_AT = tuple((f"C_{m}(ω)", "MN s/m" if i < 3 else "MN m s/rad", 1e-6) for i, m in enumerate(MOTIONS))


def _rows(model) -> list[dict]:
    """Per motion at O: spring, dashpot, damping ratio C/(2 sqrt(K m_i)), uncoupled frequency
    sqrt(K/m_i) with m_i the total mass (translations) or the moment of inertia about the axis
    through O (rotations; the weight's tilt left out)."""
    m = np.diag(model.M)
    K, C = model.springs, np.diag(model.C)
    return [
        {"motion": name, "K": float(K[i]), "C": float(C[i]), "xi": float(C[i] / (2.0 * np.sqrt(K[i] * m[i]))),
         "omega_uncoupled": float(np.sqrt(K[i] / m[i]))}
        for i, name in enumerate(MOTIONS)
    ]


def _at_document(column) -> dict:
    """One frequency's springs and dashpots (SI), named as the table's column is."""
    return {
        "at": column.at, "machine": column.name if column.at == "speed" else None,
        "mode": column.mode, "mode_name": column.name if column.at == "mode" else None,
        "omega": column.omega, "a0": column.a0,
        "springs": dict(zip(MOTIONS, map(float, column.springs))),
        "dashpots": dict(zip(MOTIONS, map(float, column.dashpots))),
    }


def soil_document(model, scene, source: str, columns=()) -> dict:
    """JSON (SI) of ``fcalc soil`` for a block scene; ``columns``: the springs and dashpots at each
    frequency of a frequency-dependent support (:func:`~foundation_calc.checks.block_soil.soil_at_frequencies`)."""
    support = scene.support()
    return {
        "schema_version": JSON_SCHEMA_VERSION,
        "command": "soil",
        "scene": {"source": source, "kind": scene.kind, "name": scene.name},
        "method": support.method,
        "frequency_dependent": support.frequency_dependent,
        "total_mass": model.mass,
        "base": {"length": scene.block.length, "width": scene.block.width},
        "springs": _rows(model),
        "warnings": scene.plausibility_warnings(),
        "at_frequencies": [_at_document(c) for c in columns],
    } | support.soil_section(_speeds(scene)).document


def _speeds(scene) -> dict[str, float]:
    """Every machine's speed [rad/s] by its name."""
    return {m.name: m.omega_rad_s for m in scene.machines}


def _frequency_rows(columns) -> list:
    """The rows of a table at the frequencies of ``columns``: f [Hz], a0 (where the support has one),
    then every spring and dashpot."""
    rows = [("f", "Hz", [hz_from_omega(c.omega) for c in columns])]
    rows += [("a0", "-", [c.a0 for c in columns])] if all(c.a0 is not None for c in columns) else []
    rows += [(label, unit, [c.springs[i] * scale for c in columns]) for i, (label, unit, scale) in enumerate(SPRINGS_AT)]
    return rows + [(label, unit, [c.dashpots[i] * scale for c in columns]) for i, (label, unit, scale) in enumerate(DASHPOTS_AT)]


def print_soil(model, scene, source: str, columns=()) -> None:
    """The tables of ``fcalc soil`` for a block scene: the springs and dashpots at O (at rest on a
    frequency-dependent soil), then at each machine's speed and at each mode's own frequency."""
    from rich.markup import escape
    from rich.table import Table

    from foundation_calc.output.soil import print_section

    out = stdout()
    support = scene.support()
    rest = ", static (ω = 0)" if support.frequency_dependent else ""
    table = Table(title=f"{escape(scene.name or source)}: springs and dashpots at O, method {support.label}{rest}",
                  title_justify="left")
    for col in ("motion", "K", "unit", "C", "unit", "ξ", "uncoupled, Hz"):
        table.add_column(col, justify="left" if col in ("motion", "unit") else "right")
    for i, row in enumerate(_rows(model)):
        table.add_row(row["motion"], fmt(row["K"], 4), UNITS["K"][i], fmt(row["C"], 4), UNITS["C"][i], fmt(row["xi"], 3),
                      fmt(row["omega_uncoupled"] / (2 * np.pi), 4))
    out.print(table)
    print_section(support.soil_section(_speeds(scene)))
    speeds = [c for c in columns if c.at != "mode"]
    modes = [c for c in columns if c.at == "mode"]
    if speeds:
        print_frequencies("Springs and dashpots at O at rest and at each machine's speed ω", speeds)
    if modes:
        print_frequencies("Springs and dashpots at O at each mode's own frequency p_j = p_j(K(p_j)) (mode j of fcalc"
                          " resonance, its dominant motion)", modes)
        print_rest_note(support)


def print_rest_note(support) -> None:
    """What a0 is and at which frequencies the commands take a frequency-dependent support's springs."""
    stdout().print(support.a0(0.0)[1] + ". The modes and the checks take the soil at these"
                   " frequencies: each mode at its own, each order n of a machine at n ω; the static springs hold at"
                   " rest only.")


def print_frequencies(title: str, columns, rows=_frequency_rows) -> None:
    """The springs and dashpots at the frequencies of ``columns`` (:class:`~foundation_calc.checks.block_soil.SoilAt`;
    ``rows`` of some columns the table's rows, by default the six springs and dashpots at O): one
    table, or as few tables of fewer frequencies each as fit the console's width (a terminal's; a
    file takes one)."""
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
