"""``fcalc soil`` of a support is one layer for every scene kind (:mod:`foundation_calc.checks.soil_support`,
:mod:`foundation_calc.output.soil_support`): what differs by kind is data, and the data of each kind
agree with one another — every kind the command reads has its frequencies and its layout, and each
layout tables exactly the values its kind's reading of the six springs and dashpots at O gives
(a value read but never shown, or a row with no value, fails here rather than on a user's scene).

The values are read from configs/block_on_piles.toml's pile group at rest and at 20 rad/s (a
support coupling u_x with θ_y, so the plane's K_xφ, C_xφ are not 0)."""

from __future__ import annotations

import numpy as np
import pytest

from foundation_calc.api.resonance import KINDS as COMMAND_KINDS
from foundation_calc.api.scene import load
from foundation_calc.checks import soil_support
from foundation_calc.output.soil_support import LAYOUTS
from foundation_calc.solvers.supports.base import AtO
from tests.conftest import CONFIGS


@pytest.fixture(scope="module")
def columns():
    """The pile group's six at O at rest and at 20 rad/s, read by each kind."""
    support = load(CONFIGS / "block_on_piles.toml").model.support()
    at = support.impedance(np.array([0.0, 20.0]))
    six = [AtO(at.springs[i], at.dashpots[i], (at.coupling[0][i], at.coupling[1][i])) for i in range(2)]
    readings = {"block_foundation": soil_support.by_motion, "crank_foundation": soil_support.in_plane(support.label)}
    return {kind: [read(a) for a in six] for kind, read in readings.items()}


def test_every_kind_of_the_command_has_its_frequencies_and_its_layout():
    assert set(soil_support.KINDS) == set(LAYOUTS) == set(COMMAND_KINDS)


@pytest.mark.parametrize("kind", sorted(LAYOUTS))
def test_each_layout_tables_exactly_what_its_kind_reads(columns, kind):
    rows = [key for key, *_ in LAYOUTS[kind].rows]
    assert len(rows) == len(set(rows))
    for values in columns[kind]:
        assert list(values) == rows
        assert all(np.isfinite(v) for v in values.values())


def test_the_plane_is_the_six_at_o_picked_by_motion(columns):
    """A crank's plane reads the block's u_x, u_z, θ_y of the same six (exactly: a projection, no
    arithmetic), and the group's sway-rocking coupling is there."""
    for block, plane in zip(columns["block_foundation"], columns["crank_foundation"]):
        for q in "KC":
            assert (plane[f"{q}_x"], plane[f"{q}_z"], plane[f"{q}_phi"]) == (block[f"{q}_x"], block[f"{q}_z"], block[f"{q}_ry"])
        assert plane["K_xphi"] < 0.0
