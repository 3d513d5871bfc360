"""A scene with many points: the tables show the governing points and count the failures, JSON
lists every point and row, and each point's peaks equal those of a scene with that point alone."""

from __future__ import annotations

import json
import os
import subprocess
import sys

import numpy as np
import pytest
import tomli_w

from foundation_calc.output.limits import ALL_POINTS_UP_TO
from foundation_calc.scenes import read_toml
from tests.conftest import CONFIGS, on_terminal

POINTS = 40


def _points(count: int) -> list[dict]:
    """Points on a 8 m × 3 m section around C, named so that no name holds another."""
    rng = np.random.default_rng(17)
    return [
        {"name": f"pt-{i:03d}", "horizontal": float(u), "height": float(h)}
        for i, (u, h) in enumerate(zip(rng.uniform(-4.0, 4.0, count), rng.uniform(-1.5, 1.5, count)))
    ]


@pytest.fixture
def frame_saw():
    """configs/frame_saw.toml (passes: peaks 0.14 mm of 0.2 mm) as a dict."""
    return read_toml(CONFIGS / "frame_saw.toml")


@pytest.fixture
def many_points(frame_saw, tmp_path):
    """The frame saw with 40 points and limits that some of them break (vertical peaks of the
    points are 0.141-0.144 mm, their velocities 4.3-4.5 mm/s)."""
    scene = dict(frame_saw, points=_points(POINTS))
    scene["limits"] = dict(scene["limits"], amplitude=1.42e-4, velocity=4.4e-3, acceleration=0.3)
    path = tmp_path / "many_points.toml"
    path.write_text(tomli_w.dumps(scene), "utf-8")
    return path


def _amplitudes(runner, *args):
    return runner.invoke(__import__("foundation_calc.cli.app", fromlist=["app"]).app, ["amplitudes", *map(str, args)])


def test_json_lists_every_point_and_limit_row(runner, many_points):
    result = _amplitudes(runner, many_points, "--json")
    doc = json.loads(result.stdout)
    assert result.exit_code == 1
    for approx in doc["approximations"].values():
        assert list(approx["points"]) == ["C", *(f"pt-{i:03d}" for i in range(POINTS))]
    assert len(doc["limits"]) == 3 * 2 * (POINTS + 1)


def test_the_table_names_the_worst_point_and_counts_the_failures(runner, many_points):
    assert POINTS > ALL_POINTS_UP_TO
    doc = json.loads(_amplitudes(runner, many_points, "--json").stdout)
    rows = doc["limits"]
    worst = max(rows, key=lambda r: r["ratio"])
    failed = [r for r in rows if r["verdict"] == "fail"]
    assert 1 < len(failed) < len(rows)  # the scene is built to fail at some points, not all
    result = _amplitudes(runner, many_points)
    assert result.exit_code == 1
    out = result.stdout
    assert f"largest value/limit {worst['ratio']:.3f} ({worst['point']}, {worst['direction']} {worst['quantity']})" in out
    failed_points = {r["point"] for r in failed}
    assert f"{len(failed)} of {len(rows)} values over their limits, at {len(failed_points)} of {POINTS + 1} points" in out
    assert f"of the scene's {POINTS} points" in out
    # the governing points: the largest of each quantity and direction, and no more
    points = doc["approximations"][doc["checked_with"]]["points"]
    governing = {
        max((name for name in points if name != "C"), key=lambda n: points[n][d][q])
        for d in ("horizontal", "vertical") for q in ("displacement", "velocity", "acceleration")
    }
    shown = {name for name in points if name != "C" and name in out}
    assert governing <= shown
    assert len(shown) < POINTS / 2


def test_all_points_lists_every_row(runner, many_points):
    out = _amplitudes(runner, many_points, "--all-points").stdout
    assert all(f"pt-{i:03d}" in out for i in range(POINTS))
    assert "--all-points or --json" not in out


def test_few_points_list_every_row_without_being_asked(runner, frame_saw, tmp_path):
    path = tmp_path / "few.toml"
    path.write_text(tomli_w.dumps(dict(frame_saw, points=_points(ALL_POINTS_UP_TO))), "utf-8")
    out = _amplitudes(runner, path).stdout
    assert all(f"pt-{i:03d}" in out for i in range(ALL_POINTS_UP_TO))
    assert "--all-points" not in out


def test_check_counts_the_failures(runner, many_points):
    from foundation_calc.cli.app import app

    doc = json.loads(runner.invoke(app, ["check", str(many_points), "--json"]).stdout)
    amplitudes = next(c for c in doc["scenes"][0]["checks"] if c["check"] == "amplitudes")
    failed = [r for r in amplitudes["result"]["limits"] if r["verdict"] == "fail"]
    assert f"{len(failed)} of {3 * 2 * (POINTS + 1)} values over their limits" in amplitudes["reason"]


def test_a_point_has_the_same_peaks_among_many_as_alone(runner, many_points, frame_saw, tmp_path):
    """All points are evaluated at once; each must come out as if it were the scene's only one."""
    together = json.loads(_amplitudes(runner, many_points, "--json", "--exact").stdout)
    for point in _points(POINTS)[::13]:
        path = tmp_path / "alone.toml"
        path.write_text(tomli_w.dumps(dict(frame_saw, points=[point])), "utf-8")
        alone = json.loads(_amplitudes(runner, path, "--json", "--exact").stdout)
        for key, approx in alone["approximations"].items():
            got = together["approximations"][key]["points"][point["name"]]
            for direction, peaks in approx["points"][point["name"]].items():
                for quantity, value in peaks.items():
                    assert got[direction][quantity] == pytest.approx(value, rel=1e-14), (key, direction, quantity)


@pytest.mark.parametrize("names", [["edge", "edge"], ["C"]], ids=["repeated", "named-C"])
def test_point_names_must_be_distinct(runner, frame_saw, tmp_path, names):
    path = tmp_path / "names.toml"
    points = [{"name": n, "horizontal": 1.0, "height": 0.5} for n in names]
    path.write_text(tomli_w.dumps(dict(frame_saw, points=points)), "utf-8")
    result = _amplitudes(runner, path)
    assert result.exit_code == 3
    assert f"point names must be distinct and not 'C' (the centre of mass): {names[0]}" in result.stderr


def test_the_summary_table_cuts_no_number_on_a_terminal(many_points):
    """At 80 columns on a terminal (a pseudo-terminal here) the summarised tables wrap their
    titles, never a number."""
    env = {**os.environ, "COLUMNS": "80", "TERM": "dumb"}
    process, out = on_terminal([sys.executable, "-m", "foundation_calc", "amplitudes", str(many_points)],
                               stderr=subprocess.PIPE, env=env)
    with process:  # closes the stderr pipe
        errors = process.stderr.read()
    assert process.returncode == 1, errors
    assert "…" not in out
    assert "values over their limits" in " ".join(out.split())  # the summary line wraps at 80
    assert max(len(line) for line in out.splitlines()) <= 90  # the tables fit (a few cells wider at most)


def test_sweep_points_among_many_have_the_peaks_they_have_alone(frame_saw):
    """fcalc sweep evaluates its points together; each must come out as if it were alone."""
    from types import SimpleNamespace

    from foundation_calc.checks.sweep.crank import sweep
    from foundation_calc.scenes.crank import CrankScene

    design = CrankScene.model_validate(frame_saw).design()
    speeds = np.linspace(15.0, 40.0, 37)
    points = [(p["name"], p["horizontal"], p["height"]) for p in _points(9)]
    limits = SimpleNamespace(amplitude=1.4e-4, velocity=4.0e-3, acceleration=None)
    together = sweep(design, "omega", speeds, limits, 0.2, points)
    over = np.zeros(speeds.shape, dtype=bool)
    for point in points:
        alone = sweep(design, "omega", speeds, limits, 0.2, [point])
        np.testing.assert_allclose(together.columns["points"][point[0]], alone.columns["points"][point[0]], rtol=1e-14, atol=0)
        over |= alone.rows.over_quantities["velocity"]
    np.testing.assert_array_equal(together.rows.over_quantities["velocity"], over)
    assert over.any() and not over.all()


def test_the_help_names_the_number_of_points_listed(runner):
    from foundation_calc.cli.app import app

    result = runner.invoke(app, ["amplitudes", "--help"], env={"COLUMNS": "200"})
    assert f"more than {ALL_POINTS_UP_TO} points" in " ".join(result.stdout.split())
