"""The sheet's own steady-state solve (K − Ω² M + i Ω C) Z = F and its tables, for every scene kind.

A crank foundation (3 plane coordinates x, y, θ about C; :mod:`~.damped_response`) and a block
(6 coordinates u_x ... θ_z about O; :mod:`~.block_methods`) print the same three tables of their
damped steady state, which differ only in the data read here:

* the matrices M, K, C row by row with each row's units (:func:`matrix_table`);
* each harmonic's forcing F_n and response Z_n = (K − Ω² M + i Ω C)⁻¹ F_n at Ω = n ω, every entry
  its magnitude ∠ phase lag φ, that is |Z| cos(Ωt − φ) (:func:`solve_harmonic`, :func:`harmonic_table`);
* the points' peaks (and r.m.s. values), each quantity's columns in one notation
  (:func:`point_columns`, :func:`points_table`).

Which operator, which loads and how a point moves with the body are the kind's own (the crank's
averaged operator and its points' exact rotation, the block's Eq. (1) and T_P = [I, −[r_P]×]).
"""

from __future__ import annotations

from dataclasses import dataclass

import numpy as np

from foundation_calc.output.report.model import Table, table
from foundation_calc.output.report.numbers import column, one_notation, phased


@dataclass(frozen=True)
class Coordinates:
    """A kind's generalised coordinates as the tables show them: ``names`` (rows and columns of the
    matrices), ``forcing`` and ``response`` (heads of F_n's and Z_n's columns) and ``row_units``
    (matrix name -> the units of each row's entries)."""

    names: tuple[str, ...]
    forcing: tuple[str, ...]
    response: tuple[str, ...]
    row_units: dict


#: The crank's plane coordinates about C: x, y (down), θ.
PLANE = Coordinates(
    ("x", "y", "θ"), ("F_x [N]", "F_y [N]", "M_θ [N m]"), ("x_n [m]", "y_n [m]", "θ_n [rad]"),
    {"M": ("kg, kg, kg m", "kg, kg, kg m", "kg m, kg m, kg m²"),
     "C": ("N s/m, N s/m, N s", "N s/m, N s/m, N s", "N s, N s, N m s"),
     "K": ("N/m, N/m, N", "N/m, N/m, N", "N, N, N m")})

#: The block's six coordinates about O: u_x, u_y, u_z, θ_x, θ_y, θ_z (Eq. (1) of
#: :mod:`foundation_calc.solvers.block.model`).
BODY = Coordinates(
    ("u_x", "u_y", "u_z", "θ_x", "θ_y", "θ_z"), ("F_x", "F_y", "F_z", "M_x", "M_y", "M_z"),
    ("u_x", "u_y", "u_z", "θ_x", "θ_y", "θ_z"),
    {"M": ("kg, kg m", "kg, kg m", "kg, kg m", "kg m, kg m²", "kg m, kg m²", "kg m, kg m²"),
     "K": ("N/m, N", "N/m, N", "N/m, N", "N, N m/rad", "N, N m/rad", "N, N m/rad"),
     "C": ("N s/m, N s", "N s/m, N s", "N s/m, N s", "N s, N m s/rad", "N s, N m s/rad", "N s, N m s/rad")})


def solve_harmonic(M, C, K, F, w: float) -> np.ndarray:
    """Z of (K − w² M + i w C) Z = F at the circular frequency ``w`` = n ω [rad/s] (SI)."""
    return np.linalg.solve(K - w * w * M + 1j * w * C, F)


def matrix_table(title: str, matrices, coordinates, units: dict) -> Table:
    """Matrices (``matrices``: (name, array) pairs) row by row with their numbers, each row's
    entries' units from ``units[name]``; round-off below 1e-9 of a matrix's largest entry is 0,
    and each column of the table, every matrix's rows in it, is in one notation
    (:func:`~.numbers.one_notation`)."""
    scales = [np.abs(matrix).max() or None for _, matrix in matrices]
    shown = [one_notation([float(v) for _, matrix in matrices for v in matrix[:, j]], 4,
                          [scale for scale, (_, matrix) in zip(scales, matrices) for _ in matrix[:, j]])
             for j in range(len(coordinates))]
    rows = [(f"{key}, row {coordinate}", *(entries[m * len(coordinates) + i] for entries in shown), units[key][i])
            for m, (key, _) in enumerate(matrices) for i, coordinate in enumerate(coordinates)]
    return table(title, ("row", *coordinates, "units"), rows, (False, *(True,) * len(coordinates), False))


def phased_columns(values, digits: int) -> list[list[str]]:
    """Each coordinate's column of the complex ``values`` (rows, coordinates): the magnitudes in one
    notation (:func:`~.numbers.column`, round-off below 1e-9 of the column's largest is 0), each
    with its phase lag (:func:`~.numbers.phased`)."""
    values = np.asarray(values)
    size = np.abs(values)
    shown = [column(list(size[:, j]), digits, size[:, j].max() or None) for j in range(values.shape[1])]
    return [[phased(shown[j][k], complex(values[k, j])) for k in range(len(values))] for j in range(values.shape[1])]


def harmonic_table(title: str, head, labels, speeds, groups) -> Table:
    """Rows of harmonics: each row's ``labels`` (text), its Ω = n ω [rad/s] of ``speeds`` (4 figures),
    then the complex columns of each (values (rows, coordinates), digits) of ``groups``
    (:func:`phased_columns`)."""
    speed = column(list(speeds), 4)
    cols = [c for values, digits in groups for c in phased_columns(values, digits)]
    rows = [(*label, speed[k], *(c[k] for c in cols)) for k, label in enumerate(labels)]
    return table(title, tuple(head), rows, (False,) * len(labels[0]) + (True,) * (1 + len(cols)))


def point_columns(columns, digits: int = 3) -> list[list[str]]:
    """Each (values, quantity) of ``columns`` at ``digits`` figures, the columns of one quantity
    (a peak and an r.m.s. velocity) in one notation together (:func:`~.numbers.column`)."""
    shown: dict[str, list[str]] = {}
    for quantity in dict.fromkeys(q for _, q in columns):
        shown[quantity] = column([x for values, q in columns if q == quantity for x in values], digits)
    out, used = [], dict.fromkeys(shown, 0)
    for values, quantity in columns:
        out.append(shown[quantity][used[quantity]:used[quantity] + len(values)])
        used[quantity] += len(values)
    return out


def points_table(title: str, head, labels, texts) -> Table:
    """The points' table: each row's (point, direction) of ``labels``, then its entry of each
    column of ``texts`` (:func:`point_columns`)."""
    rows = [(*label, *(t[k] for t in texts)) for k, label in enumerate(labels)]
    return table(title, tuple(head), rows, (False, False, *(True,) * len(texts)))


__all__ = ["BODY", "PLANE", "Coordinates", "harmonic_table", "matrix_table", "phased_columns", "point_columns",
           "points_table", "solve_harmonic"]
