"""The sheet's run-up columns end in the ``runup`` check's passages.

The sheet finds the modes by an eigen-solve of M⁻¹K (the solver uses ``scipy.linalg.eigh``),
mass-normalises them itself, forms the modal force and the point's reach, and evaluates the
printed formulas; the closed-form factor R is the one given input taken from ``passage_peak``
(the Faddeeva envelope, validated against time integration in ``tests/test_runup_passage``).
Agreement to 1e-9 relative: the same numbers by other routines in double precision.
"""

from __future__ import annotations

import functools

import pytest

from foundation_calc.scenes import load_scene
from tests.conftest import CONFIGS

TOLERANCE = 1e-9


@functools.lru_cache(maxsize=None)
def _scene_and_runup(name: str):
    """A shipped scene and its ``runup`` document (the time integration runs once per scene)."""
    from foundation_calc.checks.runup import check_runup, run_times
    from foundation_calc.output.runup import runup_document

    scene = load_scene(CONFIGS / name)
    return scene, runup_document(check_runup(scene, *run_times(scene)), scene, "")


def _close(a: float, b: float) -> bool:
    return abs(a - b) <= TOLERANCE * max(abs(a), abs(b), 1e-300)


@pytest.mark.parametrize("name", ["frame_saw_soft_soil_runup.toml", "platform_damped.toml"])
def test_every_passage_column_is_the_checks(name):
    from foundation_calc.output.report.runup_methods import runup_columns

    scene, doc = _scene_and_runup(name)
    tables = runup_columns(scene, doc)
    runs = [run for run in doc["runs"].values() if run["passages"]]
    assert tables and len(tables) == len(runs)
    for columns, run in zip(tables, runs):
        for values, passage in zip(columns.values, run["passages"]):
            for ours, judged in (("Omega_r", "speed"), ("t_r", "time"), ("eta_s", "sweep_rate"), ("zeta", "damping_ratio"),
                                 ("x_L", "lewis_peak"), ("x_cf", "closed_form_peak")):
                assert _close(values[ours], passage[judged]), (name, passage["mode"], ours)


def test_every_symbol_of_the_runup_columns_is_in_the_nomenclature():
    from foundation_calc.output.report.methods import methods_section
    from tests.test_report_methods import assert_every_symbol_defined

    scene, doc = _scene_and_runup("frame_saw_soft_soil_runup.toml")
    assert_every_symbol_defined(methods_section(scene, {"runup": doc}))
