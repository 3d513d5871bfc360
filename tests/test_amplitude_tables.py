"""The limits and code-zone tables of ``fcalc amplitudes`` are one copy for every scene kind: a block
scene's read like a crank scene's (tests/test_many_points.py holds the crank's)."""

from __future__ import annotations

import json

import tomli_w

from foundation_calc.output.console import fmt
from foundation_calc.output.limits import ALL_POINTS_UP_TO
from foundation_calc.scenes import read_toml
from tests.conftest import CONFIGS

WIDE = {"COLUMNS": "400"}


def _amplitudes(runner, *args):
    from foundation_calc.cli.app import app

    return runner.invoke(app, ["amplitudes", *map(str, args)], env=WIDE)


def test_a_block_with_many_points_shows_its_largest_ratios_unless_all_points(runner, tmp_path):
    scene = read_toml(CONFIGS / "block_two_machines.toml")
    scene["points"] = [{"name": f"pt-{i:02d}", "at": [0.1 * i, 0.0, 1.0]} for i in range(ALL_POINTS_UP_TO + 1)]
    path = tmp_path / "many.toml"
    path.write_text(tomli_w.dumps(scene), "utf-8")
    summarised = _amplitudes(runner, path).stdout
    assert "largest value/limit ratios" in summarised and "--all-points or --json" in summarised
    every = _amplitudes(runner, path, "--all-points").stdout
    assert "--all-points or --json" not in every
    assert all(f"pt-{i:02d}" in every for i in range(ALL_POINTS_UP_TO + 1))


def test_a_block_zone_table_shows_the_velocity_along_each_axis(runner):
    path = CONFIGS / "block_fan_torsion_near_speed.toml"
    doc = json.loads(_amplitudes(runner, path, "--json").stdout)
    out = _amplitudes(runner, path).stdout
    table = out[out.index("RMS velocity of each point"):out.index("zones of the RMS velocity and displacement")]
    header = next(line for line in table.splitlines() if "┃ point " in line)
    assert all(f" {axis} [m/s] " in header for axis in "xyz")
    row = next(line for line in table.splitlines() if line.startswith("│ G "))
    # the velocities the JSON gives for G, independently of the zone rows (its points part)
    cells = [cell.strip() for cell in row.split("│")[2:5]]
    assert cells == [fmt(doc["points"]["G"]["velocity_rms"][axis]) for axis in "xyz"]


def test_every_kinds_sections_give_what_the_one_amplitude_layer_reads():
    """output/amplitudes/ writes every kind's document and tables around the same judged part and
    reads a kind's sections by the names of ``SECTIONS``: each kind's module gives all of them (a
    hook missing would fail only on that kind's scenes, at run time)."""
    from foundation_calc.output.amplitudes import SECTIONS, _sections
    from foundation_calc.scenes import parse_scene

    for config in ("frame_saw.toml", "block_two_machines.toml"):
        module = _sections(parse_scene(read_toml(CONFIGS / config)))
        missing = [name for name in SECTIONS if not hasattr(module, name)]
        assert not missing, (module.__name__, missing)
