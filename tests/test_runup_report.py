"""What `fcalc runup` says about its numbers: which displacement, which verdict, which sweep rate.

The steady values of `fcalc runup` and `fcalc amplitudes` for one scene are compared here: the
run-up's per-direction steady peak of a point must be the amplitude table's (same averaged linear
model, the harmonics summed over a revolution: agreement to the sampling of the revolution, 1e-4),
and its magnitude |u| = max over time of sqrt(x² + y²) is at least the larger of the two.
"""

from __future__ import annotations

import json
import re

import pytest

from tests.conftest import CONFIGS, ROOT

SOFT = CONFIGS / "frame_saw_soft_soil_runup.toml"


def _short(tmp_path, limit=True):
    """The scene with a 2 s start-up and no run-down (the figures asked for here do not need the
    scene's 10 s and 20 s runs), without its transient limit unless ``limit``."""
    text = SOFT.read_text().replace("run_up_time = 10.0", "run_up_time = 2.0").replace("run_down_time = 20.0", "")
    scene = tmp_path / "short.toml"
    scene.write_text(text if limit else text.replace("transient_amplitude = 2.0e-2", ""))
    return scene


def test_rows_without_a_limit_are_not_judged(runner, tmp_path):
    from foundation_calc.cli.app import app

    scene = _short(tmp_path, limit=False)
    result = runner.invoke(app, ["runup", str(scene), "--json"])
    assert result.exit_code == 0, result.output
    doc = json.loads(result.stdout)
    assert {row["verdict"] for row in doc["limits"]} == {"not judged"}
    assert doc["verdict"] == "not judged"
    text = runner.invoke(app, ["runup", str(scene)], env={"COLUMNS": "200"}).stdout
    assert "not judged" in text and "PASS" not in text
    assert "limit [m]" not in text  # no column of "none" in every row: the verdict line says why


def test_a_figure_says_which_displacement_it_is(runner, tmp_path):
    from foundation_calc.cli.app import app

    scene = _short(tmp_path)
    doc = json.loads(runner.invoke(app, ["runup", str(scene), "--json"]).stdout)
    assert "magnitude" in doc["displacement"]
    steady = doc["steady_directions"]["C"]
    amplitudes = json.loads(runner.invoke(app, ["amplitudes", str(SOFT), "--json"]).stdout)
    point = amplitudes["approximations"]["averaged_operator"]["points"]["C"]
    for direction in ("horizontal", "vertical"):
        assert steady[direction] == pytest.approx(point[direction]["displacement"], rel=1e-4)
    assert doc["steady_points"]["C"] >= max(steady.values())
    table = runner.invoke(app, ["runup", str(scene)], env={"COLUMNS": "200"}).stdout
    assert "|u|" in table and "vertical" in table


def test_sweep_rate_definition_is_the_manuals(runner):
    from foundation_calc.cli.app import app

    page = (ROOT / "docs" / "runup.md").read_text()
    row = next(line for line in page.splitlines() if line.startswith("| `sweep_rate`"))
    definition = re.search(r"η = [^\[]+", row).group(0).strip()
    assert definition == "η = r Ω'/ω_i²"  # what solvers.numerics.runup computes
    shown = runner.invoke(app, ["runup", "--help"], env={"COLUMNS": "200"}).stdout
    assert definition in " ".join(shown.replace("│", " ").split())


@pytest.mark.parametrize(("n", "width"), [(10_000, 256), (300, 256), (50, 256), (7, 3), (1_000, 1)])
def test_envelope_is_the_running_maximum_over_one_period(n, width):
    """The plot's envelope (numpy windows) against scipy.ndimage.maximum_filter1d, an independent
    running maximum, with the trailing window and the mirrored start it used before: equal exactly
    (a maximum has no round-off)."""
    import numpy as np
    from scipy.ndimage import maximum_filter1d

    from foundation_calc.output.runup import ENVELOPE_POINTS, _envelope

    values = np.random.default_rng(n).random(n)
    t = np.arange(n) * 0.01
    expected = maximum_filter1d(values, size=width, origin=(width - 1) // 2) if width > 1 else values
    stride = max(1, n // ENVELOPE_POINTS)
    times, envelope = _envelope(t, values, width * 0.01)
    assert np.array_equal(times, t[::stride]) and np.array_equal(envelope, expected[::stride])
