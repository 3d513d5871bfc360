"""The block sheet's 6-DOF calculation ends in the checks' modes, amplitudes and point values.

The sheet solves from the printed M, K, C: the modes by an eigen-solve of M⁻¹K (the solvers use a
scaled symmetric eigen-solve, ``symmetric_modes``), each order by one complex 6 × 6 solve
(the solvers' ``harmonic_response`` is vectorised over the orders), and carries Z to the points
itself. Agreement to 1e-9 relative: the same linear algebra by other routines in double
precision, on matrices whose frequencies span one decade.
"""

from __future__ import annotations

import numpy as np
import pytest

from foundation_calc.scenes import load_scene
from tests.conftest import CONFIGS

TOLERANCE = 1e-9

BLOCK = sorted(p for p in CONFIGS.glob("*.toml") if load_scene(p).kind == "block_foundation")


def _amplitudes(scene) -> dict:
    from foundation_calc.checks.amplitudes.machines import check_block
    from foundation_calc.output.amplitudes import amplitudes_document

    return amplitudes_document(check_block(scene), scene, "")


@pytest.mark.parametrize("path", BLOCK, ids=lambda p: p.stem)
def test_the_sheets_6dof_solve_is_the_checks(path):
    from foundation_calc.output.report.block_methods import block_solve, point_values
    from foundation_calc.solvers.block.response import complex_amplitudes

    scene = load_scene(path)
    doc = _amplitudes(scene)
    model, excitations = scene.model(), scene.excitations()
    impedance = scene.soil_impedance if scene.support().frequency_dependent else None  # as the sheet takes it
    own = [m["frequency"]["omega"] for m in doc["modes"]] if impedance is not None else None
    solve = block_solve(model, excitations, impedance, own)
    for mode, p, zeta in zip(doc["modes"], solve.frequencies, solve.damping):
        assert abs(p - mode["frequency"]["omega"]) <= TOLERANCE * p
        assert abs(zeta - mode["damping_ratio"]) <= TOLERANCE * max(zeta, 1e-3)
    for exc, Z in zip(excitations, solve.responses):
        expected = complex_amplitudes(model, exc, impedance=impedance)
        assert np.abs(Z - expected).max() <= TOLERANCE * np.abs(expected).max()
    names = ["G", *(p.name for p in scene.points)]
    at = [doc["points"][name]["at"] for name in names]
    displacement, velocity, rms, rms_u = point_values(solve, at)
    for i, name in enumerate(names):
        judged = doc["points"][name]
        for j, d in enumerate(("x", "y", "z")):
            for ours, key in ((displacement, "displacement_peak"), (velocity, "velocity_peak"), (rms, "velocity_rms"),
                              (rms_u, "displacement_rms")):
                assert abs(ours[i, j] - judged[key][d]) <= TOLERANCE * max(judged[key][d], 1e-15), (name, d, key)


def test_block_sheet_has_its_methods_and_every_symbol_defined():
    from foundation_calc.output.report.methods import methods_section

    scene = load_scene(CONFIGS / "block_two_machines.toml")
    section = methods_section(scene, {"amplitudes": _amplitudes(scene)})
    titles = [getattr(b, "title", "") for b in section.blocks]
    assert any(t.startswith("Matrices of Eq. (1)") for t in titles) and any(t.startswith("Modes") for t in titles)
    defined = {row[0] for row in section.blocks[-1].rows}
    assert {"M, K, C", "Q_n", "Z", "T_P", "ζ", "Ω"} <= defined


def test_block_code_zones_are_the_checks():
    from foundation_calc.output.report.block_methods import POINT_UNITS, block_sections_blocks

    scene = load_scene(CONFIGS / "block_fan_torsion_near_speed.toml")
    doc = _amplitudes(scene)
    blocks = block_sections_blocks(scene, doc, POINT_UNITS)
    found = next(b for b in blocks if getattr(b, "title", "").startswith("Code zone"))
    assert [(r[0], r[1], r[3], r[5], r[6], r[7].lower()) for r in found.rows] == [
        (p["point"], p["governing"], p["velocity_zone"], p["displacement_zone"], p["zone"], p["verdict"])
        for p in doc["code"]["points"]]
    assert any("Table A.2" in getattr(b, "title", "") for b in blocks)


def test_a_frequency_dependent_block_soil_takes_each_order_and_mode_at_its_frequency():
    """The fan block on Gazetas' soil: Z of order n with K(nω), C(nω), and the j-th mode on
    K(ω_j*) returning the check's ω_j* (the fixed point, iterated to 1e-10 by the solver)."""
    from foundation_calc.output.report.block_methods import block_solve, point_values
    from foundation_calc.scenes import parse_scene, read_toml

    data = read_toml(CONFIGS / "block_fan_torsion_near_speed.toml")
    data["soil"]["method"] = "gazetas"
    scene = parse_scene(data)
    assert scene.soil.frequency_dependent
    doc = _amplitudes(scene)
    own = [m["frequency"]["omega"] for m in doc["modes"]]
    solve = block_solve(scene.model(), scene.excitations(), scene.soil_impedance, own)
    for p, judged in zip(solve.frequencies, own):
        assert abs(p - judged) <= 1e-8 * judged  # the fixed point's own tolerance, 1e-10, with margin
    names = ["G", *(p.name for p in scene.points)]
    _, _, rms, _ = point_values(solve, [doc["points"][name]["at"] for name in names])
    for i, name in enumerate(names):
        for j, d in enumerate(("x", "y", "z")):
            judged = doc["points"][name]["velocity_rms"][d]
            assert abs(rms[i, j] - judged) <= TOLERANCE * judged, (name, d)


def test_each_matrix_column_is_in_one_notation():
    """A column of one matrix holds one quantity: its entries are all plain or all a.bc·10ⁿ (the
    sheet's number format), not "213624" above "1.052·10⁶" (M of block_two_machines, column θ_y)."""
    from foundation_calc.output.report.harmonic_solve import matrix_table

    scene = load_scene(CONFIGS / "block_two_machines.toml")
    model = scene.model()
    names = ("u_x", "u_y", "u_z", "θ_x", "θ_y", "θ_z")
    units = {k: ("-",) * 6 for k in "MKC"}
    rows = matrix_table("t", (("M", model.M), ("K", model.K), ("C", model.C)), names, units).rows
    for block in range(3):
        for j in range(1, 7):
            entries = [row[j] for row in rows[6 * block: 6 * block + 6] if row[j] != "0"]
            assert len({"·10" in e for e in entries}) <= 1, (block, j, entries)
