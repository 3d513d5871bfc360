"""``fcalc bench``'s points rows: scenes of the sizes asked for, every command at every size, the
ratios taken in the same run. No test looks at the measured times."""

from __future__ import annotations

import math

import pytest

from foundation_calc.benchmarks.points import COMMANDS, POINT_COUNTS, points_scaling, scene_with_points
from foundation_calc.scenes import load_scene, read_toml
from foundation_calc.scenes.files import MAX_SCENE_BYTES
from tests.conftest import CONFIGS

SCENE = CONFIGS / "frame_saw.toml"


def test_the_largest_scene_is_a_valid_scene_file(tmp_path):
    text = SCENE.read_text("utf-8")
    path = tmp_path / "many.toml"
    path.write_text(scene_with_points(text, max(POINT_COUNTS), 6.32, 1.5), "utf-8")
    assert path.stat().st_size < MAX_SCENE_BYTES
    scene = load_scene(path, expect="crank_foundation")
    assert len(scene.points) == max(POINT_COUNTS)
    assert len({(p.horizontal, p.height) for p in scene.points}) == math.isqrt(max(POINT_COUNTS)) ** 2


def test_every_command_at_every_size_with_ratios_to_the_fewest():
    rows = points_scaling(str(SCENE), runs=1, counts=(1, 30))
    assert [(r.command, r.points) for r in rows] == [(c, n) for c in COMMANDS for n in (1, 30)]
    for row in rows:
        assert row.seconds > 0 and row.peak_rss_bytes > 0
    for fewest, more in zip(rows[::2], rows[1::2]):
        assert fewest.time_ratio == 1.0 and fewest.memory_ratio == 1.0
        assert more.time_ratio == pytest.approx(more.seconds / fewest.seconds)
        assert more.memory_ratio == pytest.approx(more.peak_rss_bytes / fewest.peak_rss_bytes)
