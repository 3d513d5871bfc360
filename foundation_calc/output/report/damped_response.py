"""The damped steady state that judged a crank foundation's limits, as the sheet's own solve.

The amplitudes check solves each harmonic n of the averaged operator (mechanism) and of the
block's equations (vendor loads) by

    (K − n²ω² M + i nω C) Z_n = F_n,    q(t) = Σ_n Re(Z_n e^{i nωt})

(:mod:`~foundation_calc.solvers.crank.averaged`: M̄, C̄, K̄ of the exact equations linearised
about rest and averaged over a revolution, F_n the Fourier coefficients of the exact forcing;
:mod:`~foundation_calc.solvers.crank.loads`: the rigid block's M, K, C and F_n = Σ Q e^{iφ}).
The sheet prints the matrices with their numbers, solves each harmonic that carries the response
itself, and takes the peaks of C and of every point from its own Z_n; on Gazetas' soil harmonic
n takes the matrices with the springs at n ω. ``tests/test_report_damped_response.py`` compares
Z_n and the peaks with the check's numbers.

The error estimate printed beside the peaks is the spread between the two closed forms (the
paper's first approximation and the averaged operator): both leave out terms of first order in
μ, so their difference is the scale of what the checked one leaves out; ``--exact`` replaces the
estimate by the errors against the exact periodic solution (the sheet's Accuracy section).
"""

from __future__ import annotations

from dataclasses import dataclass

import numpy as np

from foundation_calc.output.report.harmonic_solve import (PLANE, harmonic_table, matrix_table, point_columns,
                                                          points_table, solve_harmonic)
from foundation_calc.output.report.model import Paragraph, Table
from foundation_calc.output.report.numbers import column

#: Significant figures of the matrices, forcing and harmonics.
DIGITS = 4

#: A harmonic is listed on the sheet when a coordinate's magnitude reaches this fraction of that
#: coordinate's largest harmonic in the checked response [-]; the rest add less than this.
SOLVED_FRACTION = 1e-3


@dataclass(frozen=True)
class Operator:
    """One source's equations at one harmonic: matrices (3, 3) and forcing F_n (3,) complex."""

    source: str
    mass: np.ndarray
    damping: np.ndarray
    stiffness: np.ndarray
    forcing: np.ndarray

    def solve(self, w: float) -> np.ndarray:
        """Z_n of (K − w² M + i w C) Z_n = F_n at the harmonic's frequency ``w`` = n ω [rad/s]."""
        return solve_harmonic(self.mass, self.damping, self.stiffness, self.forcing, w)


def operators(scene, harmonics) -> list[list[Operator]]:
    """The sources' equations of each harmonic n of ``harmonics`` as the amplitudes check solves
    them (on a frequency-independent soil the matrices are one for all harmonics)."""
    from foundation_calc.solvers.crank.averaged import averaged_operator
    from foundation_calc.solvers.crank.loads import matrices

    loads = scene.harmonic_loads()
    cache: dict[float, tuple] = {}
    out = []
    for n in harmonics:
        soil_frequency = n * scene.speed.omega_rad_s if scene.support().frequency_dependent else 0.0
        if soil_frequency not in cache:
            mechanism = None if scene.mechanism is None else averaged_operator(scene.design(soil_frequency))
            block = None if loads is None else matrices(scene.block(soil_frequency))
            cache[soil_frequency] = (mechanism, block)
        mechanism, block = cache[soil_frequency]
        group = []
        if mechanism is not None:
            M, C, K, fc, fs = mechanism
            F = fc[:, n] - 1j * fs[:, n] if n < fc.shape[1] else np.zeros(3, complex)
            group.append(Operator("mechanism (averaged operator)", M, C, K, F))
        if block is not None:
            M, K, C = block
            orders = np.asarray(loads.order, dtype=int)
            group.append(Operator("vendor loads (rigid block)", M, C, K, loads.generalized()[orders == n].sum(0)))
        out.append(group)
    return out


def solved_harmonics(amplitudes: dict) -> list[int]:
    """The harmonics n of the checked response with a coordinate at least :data:`SOLVED_FRACTION`
    of that coordinate's largest (the mean n = 0 included when it is)."""
    checked = amplitudes["approximations"][amplitudes["checked_with"]]
    largest: dict[str, float] = {}
    for name, h in checked["harmonics"].items():
        dof = name.rstrip("0123456789")
        largest[dof] = max(largest.get(dof, 0.0), h["magnitude"])
    return sorted({int(name[len(name.rstrip("0123456789")):]) for name, h in checked["harmonics"].items()
                   if h["magnitude"] >= SOLVED_FRACTION * largest[name.rstrip("0123456789")] > 0.0})


@dataclass(frozen=True)
class DampedSolve:
    """The sheet's solve: the harmonics, each source's operator and Z_n, and their sum."""

    omega: float
    harmonics: tuple[int, ...]
    by_harmonic: tuple[tuple[Operator, ...], ...]
    responses: tuple[tuple[np.ndarray, ...], ...]

    def total(self, index: int) -> np.ndarray:
        """Z_n of all sources of the ``index``-th harmonic (linear superposition)."""
        return sum(self.responses[index])

    def motion(self):
        """The periodic motion of the solved harmonics (the check's convention: cos Re Z, sin −Im Z)."""
        from foundation_calc.solvers.crank.response import PeriodicMotion

        width = max(self.harmonics) + 1
        Z = np.zeros((3, width), complex)
        for i, n in enumerate(self.harmonics):
            Z[:, n] = self.total(i)
        return PeriodicMotion(self.omega, Z.real, -Z.imag)


def damped_solve(scene) -> DampedSolve:
    """Solve every harmonic the check solves (the mechanism's forcing series, the loads' orders);
    the table shows those of :func:`solved_harmonics`, the peaks take them all."""
    from foundation_calc.solvers.crank.averaged import FORCING_HARMONICS

    omega = scene.speed.omega_rad_s
    loads = scene.harmonic_loads()
    width = max(FORCING_HARMONICS + 1 if scene.mechanism is not None else 0,
                0 if loads is None else int(max(loads.order)) + 1)
    harmonics = tuple(range(width))
    ops = tuple(tuple(group) for group in operators(scene, harmonics))
    responses = tuple(tuple(op.solve(n * omega) for op in group) for n, group in zip(harmonics, ops))
    return DampedSolve(omega, harmonics, ops, responses)


def _matrix_table(op: Operator, title: str) -> Table:
    """M, C, K of one operator (a bar over a mechanism's averaged ones), each column of the table in
    one notation (:func:`~foundation_calc.output.report.harmonic_solve.matrix_table`)."""
    bar = "\u0304" if op.source.startswith("mechanism") else ""
    named = [(f"{key}{bar}", matrix) for key, matrix in (("M", op.mass), ("C", op.damping), ("K", op.stiffness))]
    return matrix_table(title, named, PLANE.names, {f"{key}{bar}": units for key, units in PLANE.row_units.items()})


def _harmonics_table(solve: DampedSolve, shown: list[int]) -> Table:
    many = len(solve.by_harmonic[0]) > 1
    raw = []
    for i, n in enumerate(solve.harmonics):
        if n not in shown:
            continue
        entries = [(op.source, op.forcing, z) for op, z in zip(solve.by_harmonic[i], solve.responses[i])]
        if many:
            entries.append(("sum", sum(e[1] for e in entries), solve.total(i)))
        raw += [(n, source, F, Z) for source, F, Z in entries]
    labels = [(str(n), source) if many else (str(n),) for n, source, *_ in raw]
    head = ("n", *(("source",) if many else ()), "nω [rad/s]", *PLANE.forcing, *PLANE.response)
    return harmonic_table("Each harmonic: forcing F_n and Z_n = (K − n²ω² M + i nω C)⁻¹ F_n (magnitude ∠ phase lag φ: each entry is A cos(nωt − φ))",
                          head, labels, [n * solve.omega for n, *_ in raw],
                          [(np.array([F for *_, F, _ in raw]), DIGITS), (np.array([Z for *_, Z in raw]), DIGITS)])


def _peaks_table(solve: DampedSolve, scene, amplitudes: dict) -> Table:
    from foundation_calc.solvers.crank.response import point_peaks

    approximations = amplitudes["approximations"]
    first = approximations.get("first_approximation")
    first = None if first is None or first["resonant"] else first["points"]
    names = ["C", *(p.name for p in scene.points)]
    horizontal = np.array([0.0, *(p.horizontal for p in scene.points)])
    height = np.array([0.0, *(p.height for p in scene.points)])
    pk = point_peaks(solve.motion(), horizontal, height)
    labels, columns = [], [[], [], [], []]
    for i, name in enumerate(names):
        for j, direction in enumerate(("horizontal", "vertical")):
            labels.append((name, direction))
            values = [float(getattr(pk, q)[i][j]) for q in ("displacement", "velocity", "acceleration")]
            for k, v in enumerate(values):
                columns[k].append(v)
            if first is not None:
                other = first[name][direction]["displacement"]
                columns[3].append(abs(other - values[0]) / values[0] if values[0] else 0.0)
    texts = point_columns([(c, q) for c, q in zip(columns[:3], ("displacement", "velocity", "acceleration"))])
    texts += [column(columns[3], 2, 1.0)] if first is not None else []
    head = ("point", "direction", "displacement [m]", "velocity [m/s]", "acceleration [m/s²]")
    head += ("spread to first approx.",) if first is not None else ()
    return points_table("Peaks over one revolution from the sheet's Z_n: max over t of |Σ_n Re(Z_n e^{i nωt})| at C and each point",
                        head, labels, texts)


def _terms():
    """The symbols of the solve for the sheet's nomenclature."""
    from foundation_calc.output.report.handcalc import Definitions

    return Definitions({
        "M, C, K": ("mass, damping and stiffness matrices about C, order x, y, θ (M̄, C̄, K̄: averaged over a revolution)", "SI"),
        "n": ("order of the harmonic", "-"),
        "F_n": ("complex amplitude of harmonic n of the forcing (F_x, F_y, M_θ)", "N, N, N m"),
        "Z_n": ("complex amplitude of harmonic n of the motion (x_n, y_n, θ_n), q = Σ Re(Z_n e^{i nωt})", "m, m, rad"),
        "φ": ("phase lag of a harmonic, q_n = |Z_n| cos(nωt − φ)", "°"),
        "μ": ("moving-mass ratio m/M_tot", "-"),
    })


def damped_response_blocks(scene, amplitudes: dict | None) -> tuple:
    """The damped solve of a crank scene's checked response as sheet blocks; () when the check
    took no closed form (resonant, or no amplitudes document)."""
    if amplitudes is None or amplitudes["checked_with"] not in ("averaged_operator", "loads"):
        return ()
    if amplitudes["approximations"][amplitudes["checked_with"]]["resonant"]:
        return ()
    solve = damped_solve(scene)
    dependent = scene.support().frequency_dependent
    soil = " with the springs and dashpots at n ω (frequency-dependent soil)" if dependent else ""
    sources = {op.source for group in solve.by_harmonic for op in group}
    how = []
    if "mechanism (averaged operator)" in sources:
        from foundation_calc.solvers.crank.averaged import FORCING_SAMPLES

        how.append("the mechanism by its averaged operator (M̄, C̄, K̄ of the exact equations linearised about rest and"
                   " averaged over one revolution, F_n the Fourier coefficients of its exact forcing:"
                   f" F_n = (2/N) Σ_k F(φ_k) e^{{−i n φ_k}}, φ_k = 2πk/N, N = {FORCING_SAMPLES} samples of a revolution, F(φ) the"
                   " forces F_x, F_y and moment M_θ that rod and slider exert on the block at rest, the drive's reaction"
                   " included when it acts on the foundation; to leading order in λ, F_y1, F_y2, F_x1 and M_θ1 of the"
                   " first approximation above)")
    if "vendor loads (rigid block)" in sources:
        how.append("the vendor loads by the rigid block (K of [KM] (3.2)-(3.4) corrected, C the base dashpots,"
                   " F_n = Σ Q e^{iφ} about C)" + (", added to it" if how else ""))
    blocks = [Paragraph(
        f"The limits were judged on the steady state of (K − n²ω² M + i nω C) Z_n = F_n, harmonic by harmonic{soil}: "
        + "; ".join(how) + ". Order x, y (down), θ; SI."
        f" The table lists the harmonics carrying at least {SOLVED_FRACTION:g} of their coordinate's largest; the peaks"
        " sum all of them, as the check does.")]
    first = solve.by_harmonic[solve.harmonics.index(1)] if 1 in solve.harmonics else solve.by_harmonic[0]
    at = "n = 1" if 1 in solve.harmonics else f"n = {solve.harmonics[0]}"
    for op in first:
        blocks.append(_matrix_table(op, f"Matrices of the {op.source}" + (f" at {at}" if soil else "")))
    blocks.append(_harmonics_table(solve, solved_harmonics(amplitudes)))
    blocks.append(_peaks_table(solve, scene, amplitudes))
    blocks.append(_terms())
    if "first_approximation" in amplitudes["approximations"]:
        blocks.append(Paragraph(
            "Error estimate for this design: the spread column is |peak of the first approximation − peak here| / peak"
            " here. Both closed forms leave out terms of first order in μ = m/M_tot; their spread is the scale of what"
            " the averaged operator leaves out (run with --exact for its errors against the exact periodic solution)."))
    from foundation_calc.output.report.code_zone import code_zone_blocks

    blocks += code_zone_blocks(scene, amplitudes.get("code"), solve.motion())
    return tuple(blocks)


__all__ = ["DampedSolve", "Operator", "damped_response_blocks", "damped_solve", "operators", "solved_harmonics"]
