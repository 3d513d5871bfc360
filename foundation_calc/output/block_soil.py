"""``fcalc soil`` of a block scene: the six springs and dashpots at O of the scene's soil method."""

from __future__ import annotations

import numpy as np

from foundation_calc.output.console import JSON_SCHEMA_VERSION, fmt, stdout
from foundation_calc.solvers.rigid_body.modes import MOTIONS

UNITS = {"K": ("N/m",) * 3 + ("N m/rad",) * 3, "C": ("N s/m",) * 3 + ("N m s/rad",) * 3}


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


def soil_document(model, scene, source: str) -> dict:
    """JSON (SI) of ``fcalc soil`` for a block scene."""
    return {
        "schema_version": JSON_SCHEMA_VERSION,
        "command": "soil",
        "scene": {"source": source, "kind": scene.kind, "name": scene.name},
        "method": scene.soil.method_used,
        "total_mass": model.mass,
        "base": {"length": scene.block.length, "width": scene.block.width},
        "springs": _rows(model),
        "warnings": scene.plausibility_warnings(),
    }


def print_soil(model, scene, source: str) -> None:
    """The table of ``fcalc soil`` for a block scene."""
    from rich.markup import escape
    from rich.table import Table

    table = Table(title=f"{escape(scene.name or source)}: springs and dashpots at O, method {scene.soil.method_used!r}",
                  title_justify="left")
    for col in ("motion", "K", "unit", "C", "unit", "ξ", "uncoupled, Hz"):
        table.add_column(col, justify="left" if col in ("motion", "unit") else "right")
    for i, row in enumerate(_rows(model)):
        table.add_row(row["motion"], fmt(row["K"], 4), UNITS["K"][i], fmt(row["C"], 4), UNITS["C"][i], fmt(row["xi"], 3),
                      fmt(row["omega_uncoupled"] / (2 * np.pi), 4))
    stdout().print(table)
