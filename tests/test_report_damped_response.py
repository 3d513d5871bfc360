"""The sheet's own solve of the damped steady state ends in the numbers the check judged.

The sheet prints M, C, K and F_n and solves (K − n²ω² M + i nω C) Z_n = F_n itself, one
harmonic at a time, as one complex 3 × 3 solve per source; the check's harmonics come from the
solvers (``averaged_response`` vectorised over all harmonics, ``loads_response``, spliced per
harmonic on a frequency-dependent soil, superposed with the loads). Agreement to 1e-9 relative
to the coordinate's largest harmonic: the same linear algebra in double precision, in another
order. The peaks are the check's ``point_peaks`` of the sheet's motion, so they agree to 1e-9.
"""

from __future__ import annotations

import pytest

from foundation_calc.scenes import load_scene
from tests.conftest import CONFIGS

TOLERANCE = 1e-9

DAMPED = ["compressor_damped_near_resonance.toml", "compressor_vendor_loads.toml", "frame_saw_soft_soil_runup.toml",
          "compressor_medium_sand_lysmer.toml"]


def _amplitudes(scene) -> dict:
    from foundation_calc.checks.amplitudes.approximations import check_scene_amplitudes
    from foundation_calc.output.amplitudes import amplitudes_document

    return amplitudes_document(check_scene_amplitudes(scene), scene, "")


def _agrees(scene, amplitudes) -> None:
    from foundation_calc.output.report.damped_response import damped_solve

    checked = amplitudes["approximations"][amplitudes["checked_with"]]
    solve = damped_solve(scene)
    largest = {dof: max(h["magnitude"] for k, h in checked["harmonics"].items() if k.rstrip("0123456789") == dof)
               for dof in ("x", "y", "theta")}
    for i, n in enumerate(solve.harmonics):
        if f"x{n}" not in checked["harmonics"]:  # the document lists the leading harmonics
            continue
        Z = solve.total(i)
        for j, dof in enumerate(("x", "y", "theta")):
            h = checked["harmonics"][f"{dof}{n}"]
            expected = complex(h["cos"], -h["sin"])
            assert abs(Z[j] - expected) <= TOLERANCE * largest[dof], (n, dof, Z[j], expected)
    _peaks_agree(scene, solve, checked["points"])


def _peaks_agree(scene, solve, judged) -> None:
    """The peaks of the sheet's motion (all harmonics) at C and every point are the judged ones."""
    import numpy as np

    from foundation_calc.solvers.crank.response import point_peaks

    horizontal = np.array([0.0, *(p.horizontal for p in scene.points)])
    height = np.array([0.0, *(p.height for p in scene.points)])
    peaks = point_peaks(solve.motion(), horizontal, height)
    for i, name in enumerate(["C", *(p.name for p in scene.points)]):
        for j, direction in enumerate(("horizontal", "vertical")):
            for q in ("displacement", "velocity", "acceleration"):
                a, b = float(getattr(peaks, q)[i][j]), judged[name][direction][q]
                assert abs(a - b) <= TOLERANCE * abs(b), (name, direction, q)


@pytest.mark.parametrize("name", DAMPED, ids=lambda n: n.removesuffix(".toml"))
def test_the_sheets_solve_is_the_checked_response(name):
    scene = load_scene(CONFIGS / name)
    _agrees(scene, _amplitudes(scene))


def test_gazetas_harmonics_take_their_own_matrices():
    """Each harmonic with the springs at n ω (spliced by the check) and the mechanism's forcing."""
    from tests.test_report_methods import _gazetas_scene

    scene = _gazetas_scene(6.0, 4.0, 1.5)
    _agrees(scene, _amplitudes(scene))


def test_the_sheet_prints_the_peaks_it_solved():
    from foundation_calc.output.report.damped_response import damped_response_blocks
    from foundation_calc.output.report.numbers import figure

    scene = load_scene(CONFIGS / "compressor_vendor_loads.toml")
    amplitudes = _amplitudes(scene)
    blocks = damped_response_blocks(scene, amplitudes)
    peaks = next(b for b in blocks if getattr(b, "title", "").startswith("Peaks"))
    judged = amplitudes["approximations"]["loads"]["points"]
    assert [(r[0], r[1]) for r in peaks.rows] == [(p, d) for p in judged for d in ("horizontal", "vertical")]
    for row in peaks.rows:
        assert row[2] == figure(judged[row[0]][row[1]]["displacement"], 3)


def test_a_resonant_undamped_scene_shows_no_solve():
    from foundation_calc.output.report.damped_response import damped_response_blocks

    scene = load_scene(CONFIGS / "compressor_near_resonance.toml")
    amplitudes = _amplitudes(scene)
    resonant = amplitudes["approximations"][amplitudes["checked_with"]]["resonant"]
    assert (damped_response_blocks(scene, amplitudes) == ()) == resonant
