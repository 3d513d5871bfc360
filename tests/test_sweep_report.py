"""One report for every kind's sweep (foundation_calc/checks/sweep/report.py): a sweep computed
in two pieces and joined row for row (``joined``) gives the rows and the verdict of the sweep
computed whole, for a crank scene's speed and soil sweeps and a block's speed and soil sweeps.
The block's soil sweep labels its conditions with the modes at each factor (one tuple of
conditions a row; on block_on_piles.toml mode 5 is dominated by z at factor 0.5 and by ry at 2),
so each joined row has to keep its own labels. Rows are compared exactly: each row is
the same arithmetic whether it is computed with the rest of the sweep or without it (no tolerance).
"""

from __future__ import annotations

import numpy as np
import pytest

from foundation_calc.checks.sweep import scene_sweep
from foundation_calc.checks.sweep.report import SweepReport, joined
from foundation_calc.output.sweep import sweep_document
from foundation_calc.scenes import load_scene
from tests.conftest import CONFIGS

CASES = [
    ("frame_saw.toml", "omega", np.linspace(20.0, 90.0, 6), None),
    ("compressor_vendor_loads.toml", "soil_factor", np.linspace(0.5, 2.0, 5), None),
    ("block_two_machines.toml", "omega", np.linspace(30.0, 100.0, 5), 0),
    ("block_on_piles.toml", "soil_factor", np.array([0.5, 1.0, 2.0]), None),
]


@pytest.mark.parametrize(("config", "variable", "values", "machine"), CASES)
def test_a_sweep_joined_from_two_pieces_is_the_sweep_computed_whole(config, variable, values, machine):
    scene = load_scene(CONFIGS / config)
    whole = scene_sweep(scene, variable, values, machine)
    parts = [scene_sweep(scene, variable, values[:2], machine), scene_sweep(scene, variable, values[2:], machine)]
    assert all(isinstance(r, SweepReport) for r in (whole, *parts))
    found, expected = (sweep_document(r, scene, config) for r in (joined(parts), whole))
    assert found["points"] == expected["points"] and found["verdict"] == expected["verdict"]


def test_the_block_soil_sweep_names_each_rows_condition_by_the_modes_at_its_factor():
    """The joined rows keep the labels of their own factor: if the labels are the same at every
    factor, the piece-by-piece comparison above cannot tell whether they are kept."""
    config, variable, values, _ = CASES[-1]
    report = scene_sweep(load_scene(CONFIGS / config), variable, values)
    labels = {tuple(c.label for c in row) for row in report.conditions}
    assert report.per_row and len(labels) > 1
