"""The block foundation's 6-DOF equations as the sheet's own calculation.

Equation (1) of :mod:`foundation_calc.solvers.block.model` about O (centre of the base at base
level, x along the length, y along the width, z up)::

    M q'' + C q' + K q = Σ_machines Σ_n Re(Q_n e^{i nωt}),    q = (u_x, u_y, u_z, θ_x, θ_y, θ_z)

The sheet prints M, K, C with their numbers, finds the modes from them itself (K v = p² M v by an
eigen-solve of M⁻¹K, ζ = vᵀ C v / (2 p vᵀ M v)), prints each machine's generalised loads Q_n
about O, solves (K − Ω² M + i Ω C) Z = Q_n at Ω = nω, and carries Z to every point by
u_P = T_P Z (T_P = [I, −[r_P]×]): the peak of each machine's series, added over the machines,
and the r.m.s. velocity √(Σ |nω u_P,n|²/2) over every harmonic of every machine (and, where the
scene limits them, the peak and r.m.s. acceleration of −(nω)² u_P,n).
``tests/test_report_block_methods.py`` compares the modes, Z and the points' values with the
checks'.
"""

from __future__ import annotations

from dataclasses import dataclass

import numpy as np

from foundation_calc.output.display_units import DisplayUnits
from foundation_calc.output.report.block_soil import block_soil_blocks, order_springs_table, orders_of
from foundation_calc.output.report.handcalc import Definitions
from foundation_calc.output.report.harmonic_solve import (BODY, harmonic_table, matrix_table, point_columns,
                                                          points_table, solve_harmonic)
from foundation_calc.output.report.model import Paragraph, Table, table
from foundation_calc.output.report.numbers import figure

DIRECTIONS = ("x", "y", "z")


@dataclass(frozen=True)
class BlockSolve:
    """The sheet's modes and harmonic response of the block (SI)."""

    frequencies: np.ndarray
    damping: np.ndarray
    machines: tuple[str, ...]
    omegas: tuple[float, ...]
    orders: tuple[np.ndarray, ...]
    loads: tuple[np.ndarray, ...]
    responses: tuple[np.ndarray, ...]


def modes_of(M, K, C) -> tuple[np.ndarray, np.ndarray, np.ndarray]:
    """The sheet's own modes: p ascending [rad/s] from an eigen-solve of M⁻¹K, the shapes
    mass-normalised (columns, vᵀ M v = 1) and ζ = vᵀ C v / (2 p) [-]."""
    squared, shapes = np.linalg.eig(np.linalg.solve(M, K))
    order = np.argsort(squared.real)
    p = np.sqrt(squared.real[order])
    v = shapes.real[:, order]
    v = v / np.sqrt(np.einsum("ni,nm,mi->i", v, M, v))
    return p, v, np.einsum("ni,nm,mi->i", v, C, v) / (2.0 * p)


def block_solve(model, excitations, impedance=None, own=None) -> BlockSolve:
    """Modes from an eigen-solve of M⁻¹K and Z of every machine's orders by one complex solve each.

    On a frequency-dependent soil (``impedance``: Ω -> (springs, dashpots) at O, the scene's
    ``soil_impedance``) order n takes K(nω), C(nω), and mode j is the j-th of the eigen-solve on
    K(ω_j*), ω_j* its own frequency as the resonance check found it (``own``, rad/s): it returns
    ω_j* when ω* = p(K(ω*)) holds."""

    def matrices(frequency):
        if impedance is None:
            return model.K, model.C
        return model.soil_matrices(*impedance(np.asarray(frequency, dtype=float)))

    if impedance is None:
        p, _, zeta = modes_of(model.M, model.K, model.C)
    else:
        pairs = [modes_of(model.M, *matrices(w)) for w in own]
        p = np.array([pair[0][j] for j, pair in enumerate(pairs)])
        zeta = np.array([pair[2][j] for j, pair in enumerate(pairs)])
    responses = []
    for exc in excitations:
        Z = []
        for n, q in zip(exc.orders, exc.Q):
            K, C = matrices(n * exc.omega)
            Z.append(solve_harmonic(model.M, C, K, q, n * exc.omega))
        responses.append(np.array(Z).reshape(len(exc.orders), 6))
    return BlockSolve(p, zeta, tuple(e.name for e in excitations), tuple(e.omega for e in excitations),
                      tuple(e.orders for e in excitations), tuple(e.Q for e in excitations), tuple(responses))


def point_values(solve: BlockSolve, points) -> tuple[np.ndarray, ...]:
    """(peak displacement, peak velocity, r.m.s. velocity, r.m.s. displacement), each (P, 3), of
    the body points ``points`` (P, 3) [m] from O: each machine's series' peak (trig_series.peak),
    added over the machines; an r.m.s. value the root-sum-square of every harmonic."""
    (displacement, square_u), (velocity, square) = _rates(solve, points, 2)
    return displacement, velocity, np.sqrt(square), np.sqrt(square_u)


def acceleration_values(solve: BlockSolve, points) -> tuple[np.ndarray, np.ndarray]:
    """(peak acceleration, r.m.s. acceleration) [m/s²], each (P, 3), as :func:`point_values`:
    a = (i nω)² u_P,n = −(nω)² u_P,n at each harmonic."""
    top, square = _rates(solve, points, 3)[2]
    return top, np.sqrt(square)


def _rates(solve: BlockSolve, points, count: int) -> list[tuple[np.ndarray, np.ndarray]]:
    """(peak, mean square) (P, 3) of the displacement and its first ``count`` − 1 time derivatives."""
    from foundation_calc.solvers.numerics.trig_series import peak
    from foundation_calc.solvers.rigid_body.kinematics import point_maps

    T = point_maps(np.asarray(points, dtype=float))
    found = [(np.zeros((len(points), 3)), np.zeros((len(points), 3))) for _ in range(count)]
    for omega, orders, Z in zip(solve.omegas, solve.orders, solve.responses):
        series = np.einsum("pij,hj->pih", T, Z)
        for top, square in found:
            a = np.zeros(series.shape[:-1] + (int(orders.max()) + 1,), complex)
            a[..., orders] = series
            top += peak(a.real, -a.imag)
            square += (np.abs(series) ** 2).sum(-1) / 2.0
            series = series * (1j * omega * orders)
    return found


#: Titles of the tables a judged number's chain cites.
MODES_TITLE = "Modes: K v = p² M v (eigen-solve of M⁻¹K), ζ = vᵀ C v / (2 p vᵀ M v)"
RESPONSE_TITLE = "Z = (K − Ω² M + i Ω C)⁻¹ Q_n ([m], [rad]) as magnitude ∠ phase lag φ"
MATRICES_TITLE = "Matrices of Eq. (1) about O (order u_x, u_y, u_z, θ_x, θ_y, θ_z)"


def _matrices(model) -> Table:
    return matrix_table(MATRICES_TITLE,
                        (("M", model.M), ("K", model.K), ("C", model.C)), BODY.names, BODY.row_units)


def _modes(solve: BlockSolve, dominant: list[str]) -> Table:
    rows = [(str(j + 1), dominant[j], figure(p, 4), figure(p / (2 * np.pi), 4), figure(z, 3, 1.0))
            for j, (p, z) in enumerate(zip(solve.frequencies, solve.damping))]
    return table(MODES_TITLE,
                 ("mode", "dominant motion", "p [rad/s]", "f [Hz]", "ζ"), rows, (False, False, True, True, True))


def _harmonics(solve: BlockSolve) -> tuple[Table, Table]:
    labels, speeds, loads, amplitudes = [], [], [], []
    for name, omega, orders, Q, Z in zip(solve.machines, solve.omegas, solve.orders, solve.loads, solve.responses):
        for h, n in enumerate(orders):
            labels.append((name, str(int(n))))
            speeds.append(n * omega)
            loads.append(Q[h])
            amplitudes.append(Z[h])
    head = ("machine", "n", "Ω = nω [rad/s]")
    forcing = harmonic_table("Generalised loads about O: Q_n (F [N], M + r_F × F [N m]) as magnitude ∠ phase lag φ,"
                             " each entry |Q| cos(Ωt − φ)", (*head, *BODY.forcing), labels, speeds, [(np.array(loads), 4)])
    response = harmonic_table(RESPONSE_TITLE, (*head, *BODY.response), labels, speeds, [(np.array(amplitudes), 3)])
    return forcing, response


def _machine_parts(scene, periodic) -> list[Paragraph]:
    """Each machine part's derivation (:meth:`~foundation_calc.solvers.machines.part.MachinePart.sheet_text`),
    kind by kind: an unbalance as the loads it becomes, a crank mechanism's mean mass and Q_n; for a
    part with periodic inertia also the exact periodic solution's check of the first approximation
    (the ``periodic_inertia`` entries of the amplitudes document)."""
    from foundation_calc.solvers.machines.part import Number, Triple

    def shown(item) -> str:
        if isinstance(item, Number):
            return figure(item.value, item.digits)
        return vec_m(item.values) if isinstance(item, Triple) else item

    errors = {c["machine"]: c for c in periodic or ()}
    out = []
    for kind in zip(*(machine.parts_by_kind for machine in scene.machines)):
        for machine, parts in zip(scene.machines, kind):
            for part in parts:
                items = part.sheet_text(machine.omega_rad_s)
                if items is None:
                    continue
                text = f"{machine.name}: " + "".join(map(shown, items))
                found = errors.get(machine.name) if part.periodic else None
                if found is not None:
                    text += (f" Exact periodic solution with the angle-dependent mass matrix M(ωt) (harmonic balance,"
                             f" {found['harmonics']} harmonics): the first approximation judged here differs from it by"
                             f" at most {figure(100.0 * found['first_approximation_error'], 2)} % of a peak.")
                out.append(Paragraph(text))
    return out


def _gyroscopic_text(D) -> str:
    """What C holds besides the dashpots: the machines' mean gyroscopic coupling D̄ (the mean over a
    revolution of their Coriolis matrix D(ωt), skew-symmetric), its entries named; "" without."""
    if D is None:
        return ""
    names = ("u_x", "u_y", "u_z", "θ_x", "θ_y", "θ_z")
    pairs = [f"D̄({names[i]}, {names[j]}) = −D̄({names[j]}, {names[i]}) = {figure(float(D[i, j]), 4)}"
             f" {'N m s/rad' if i >= 3 else 'N s'}" for i in range(6) for j in range(i + 1, 6) if D[i, j] != 0.0]
    return (", plus the machines' mean gyroscopic coupling D̄ at their speeds (the mean over a revolution of"
            " their crank mechanisms' and rotors' Coriolis matrix D(ωt), skew-symmetric: −[h]× of their mean"
            " angular momentum h; it does no work and leaves ζ as it is): " + ", ".join(pairs))


def vec_m(v) -> str:
    """A vector as printed: (x, y, z), 4 figures, no −0."""
    return "(" + ", ".join(figure(float(c) + 0.0, 4) for c in v) + ")"


def _zones(code: dict, names, rms: np.ndarray, rms_u: np.ndarray) -> tuple:
    """The code check of every point from the sheet's r.m.s. velocities and displacements: the
    largest direction's values placed in the zone table, the worse zone deciding."""
    from foundation_calc.checks.codes import zone_outcome
    from foundation_calc.output.report.code_zone import judged_zone, support_blocks, zone_tables

    rows = []
    for name, v, u, point in zip(names, rms, rms_u, code["points"]):
        z, zones, d = judged_zone(code, point, v, u)
        rows.append((name, DIRECTIONS[d], figure(v.max() * 1e3, 3), z.velocity_zone, figure(u.max() * 1e6, 3),
                     z.displacement_zone, z.zone, zone_outcome(z.zone, code["acceptable_zone"]).value.upper(), zones.foundation))
    found = table("Code zone of each point: its largest v_rms and d_rms = √(Σ |u_P,n|²/2), the worse zone deciding;"
                  " each direction in the table of its support class",
                  ("point", "direction", "v_rms [mm/s]", "v zone", "d_rms [µm]", "d zone", "zone", "verdict", "support"),
                  rows, (False, False, True, False, True, False, False, False, False))
    return (found, *zone_tables(code), *support_blocks(code))


def _points(solve: BlockSolve, names, points, accelerations: bool, units: DisplayUnits) -> Table:
    """The points' peaks and r.m.s. velocity in the sheet's ``units`` (those of its Checks table);
    with ``accelerations`` (the scene limits them) also the peak and r.m.s. acceleration,
    a_n = −(nω)² u_P,n."""
    displacement, velocity, rms, _ = point_values(solve, points)
    labels = [(name, d) for name in names for d in DIRECTIONS]
    values = [(displacement, "amplitude"), (velocity, "velocity"), (rms, "velocity")]
    head = ["point", "direction", f"peak displacement [{units.amplitude}]", f"peak velocity [{units.velocity}]",
            f"v_rms [{units.velocity}]"]
    title = "Points: u_P = T_P Z; peaks of each machine's series added; v_rms = √(Σ |nω u_P,n|²/2)"
    if accelerations:
        values += [(a, "acceleration") for a in acceleration_values(solve, points)]
        head += [f"peak acceleration [{units.acceleration}]", f"a_rms [{units.acceleration}]"]
        title += "; a_rms = √(Σ |(nω)² u_P,n|²/2)"
    cols = point_columns([([units.convert(quantity, float(x)) for x in v.ravel()], quantity) for v, quantity in values])
    return points_table(title, head, labels, cols)


#: Units of the Points table when the caller names none: those the sheet showed before it took its
#: own (displacements in µm, velocities in mm/s).
POINT_UNITS = DisplayUnits(amplitude="µm", velocity="mm/s")


def block_sections_blocks(scene, amplitudes: dict | None, units: DisplayUnits) -> tuple:
    """The 6-DOF calculation of a block scene as sheet blocks (the ``amplitudes`` document gives
    the modes' names and whether a steady state exists; ``units``, the sheet's, those of the points'
    peaks)."""
    model = scene.model()
    excitations = scene.excitations()
    support = scene.support()
    dependent = support.frequency_dependent and amplitudes is not None
    own = [m["frequency"]["omega"] for m in amplitudes["modes"]] if dependent else None
    solve = block_solve(model, excitations, scene.soil_impedance if dependent else None, own)
    coupling = support.impedance(0.0).coupling
    springs = (("the six springs at O", "O (given, or 2 ξ √(K m) of each uncoupled motion, [RHW] ch. 10)")
               if coupling is None or not any(np.any(X) for X in coupling) else
               ("the support's springs at O, coupled off the diagonal (the soil section shows how),", "O, coupled likewise"))
    blocks: list = [Paragraph(
        "Rigid block in six degrees of freedom about O (centre of the base at base level, x along the length, y along"
        " the width, z up): M q'' + C q' + K q = Σ_machines Σ_n Re(Q_n e^{i nωt}). M: every body by parallel axes;"
        f" K: {springs[0]} less the weight's tilt W z_G about x and y ([KM] (3.4)'s −P h); C: the dashpots at"
        f" {springs[1]}{_gyroscopic_text(model.gyroscopic)}; Q_n: each load (F, M + r_F × F) e^{{iφ}}.")]
    from foundation_calc.output.report.stratum import stratum_blocks

    stratum = stratum_blocks(getattr(support, "soil", None), *scene.base, True, amplitudes)  # a footing's stratum
    for chain in [*block_soil_blocks(scene, model, own), *stratum]:
        blocks += chain.blocks() if hasattr(chain, "nomenclature") else [chain]
        if hasattr(chain, "nomenclature"):
            blocks.append(Definitions(chain.nomenclature))
    blocks.append(_matrices(model))
    if dependent:
        blocks.append(Paragraph(
            "The soil's springs and dashpots depend on frequency (soil.method = \"" + support.method + "\"): the matrices"
            " above hold the static springs; each order n is solved with K(nω), C(nω) at O, and each mode j is the j-th"
            " of K(ω_j*) v = p² M v at its own frequency ω_j* = p_j(K(ω_j*)), as the resonance check takes it."))
    dominant = [m["dominant_name"] for m in amplitudes["modes"]] if amplitudes else ["-"] * 6
    blocks.append(_modes(solve, dominant))
    if amplitudes is not None and not amplitudes.get("resonant", False):
        blocks += _machine_parts(scene, amplitudes.get("periodic_inertia"))
        forcing, response = _harmonics(solve)
        blocks.append(forcing)
        if dependent:
            blocks += order_springs_table(scene, model, orders_of(scene, own))
        blocks.append(response)
        names = ["G", *(p.name for p in scene.points)]
        points = [model.cog, *(p.at for p in scene.points)]
        limits = scene.limits
        blocks.append(_points(solve, names, points, limits.acceleration is not None or limits.acceleration_rms is not None,
                              units))
        if amplitudes.get("code"):
            blocks += _zones(amplitudes["code"], names, *point_values(solve, points)[2:])
    blocks.append(Definitions({
        "O": ("centre of the base at base level, origin of q", "-"),
        "q": ("displacement u_x, u_y, u_z of O and rotation θ_x, θ_y, θ_z of the block", "m, rad"),
        "M, K, C": ("mass, stiffness and damping matrices about O", "SI"),
        "p, v": ("natural frequency and mode shape of K v = p² M v", "rad/s, -"),
        "ζ": ("modal damping ratio", "-"),
        "Q_n": ("generalised load of order n about O (forces and moments)", "N, N m"),
        "Ω": ("frequency of a load's order, nω of its machine", "rad/s"),
        "Z": ("complex amplitude of q at Ω", "m, rad"),
        "T_P": ("map of q to the displacement of point P, [I, −[r_P]×]", "-"),
        "d_rms": ("r.m.s. displacement of a point, the root-sum-square of every harmonic", "µm"),
        "G": ("centre of mass of block and machines", "-"),
    }))
    return tuple(blocks)


__all__ = ["POINT_UNITS", "BlockSolve", "acceleration_values", "block_sections_blocks", "block_solve", "modes_of",
           "point_values"]
