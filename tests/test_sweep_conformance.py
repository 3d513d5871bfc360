"""`fcalc sweep` of every scene kind that sweeps (crank and block foundations) through one path:
each row names the governing judged condition and every limit it exceeds
(:mod:`foundation_calc.checks.sweep.status`), the row at the scene's own speed says what `fcalc
check` says, unjudged conditions draw no band, and the plot's title stays inside the picture."""

from __future__ import annotations

import json
import math

import numpy as np
import pytest
import tomli_w

from foundation_calc.checks.resonance.rule import condition_phrase
from foundation_calc.cli.app import app
from foundation_calc.scenes import parse_scene, read_toml
from tests.conftest import CONFIGS

#: (config, swept machine or None for a crank scene): one crank scene and both block scenes.
SWEPT = [("frame_saw.toml", None), ("block_two_machines.toml", "motor"), ("block_two_machines.toml", "compressor"),
         ("block_fan_torsion_near_speed.toml", "fan"), ("block_fan_torsion_near_speed.toml", "motor")]

#: Tight limits that some peaks exceed at the scene's speed: [limits] keys -> value (SI).
TIGHT = {"frame_saw.toml": {"amplitude": 1.0e-4},
         "block_two_machines.toml": {"amplitude": 1.2e-6, "velocity_rms": 5.0e-5},
         "block_fan_torsion_near_speed.toml": {"amplitude": 4.0e-6, "velocity": 1.0e-3}}


def _scene_file(tmp_path, config: str, limits: dict | None = None, name: str | None = None):
    document = read_toml(CONFIGS / config)
    if limits:
        document["limits"] = document.get("limits", {}) | limits
    if name is not None:
        document["name"] = name
    path = tmp_path / config
    path.write_text(tomli_w.dumps(document), encoding="utf-8")
    return path, parse_scene(document, str(path))


def _speed_rpm(scene, machine) -> float:
    if machine is None:
        return scene.speed.omega_rad_s * 30.0 / math.pi
    return next(m for m in scene.machines if m.name == machine).omega_rad_s * 30.0 / math.pi


def _sweep_row(runner, path, machine, rpm):
    args = ["sweep", str(path), "--speed", repr(rpm), "--json"] + ([] if machine is None else ["--machine", machine])
    result = runner.invoke(app, args)
    assert result.exit_code == 0, result.stderr
    (row,) = json.loads(result.stdout)["points"]
    return row


def _check(runner, path) -> dict:
    result = runner.invoke(app, ["check", str(path), "--json"])
    assert result.exit_code in (0, 1), result.stderr
    (scene,) = json.loads(result.stdout)["scenes"]
    return {c["check"]: c for c in scene["checks"]}


@pytest.mark.parametrize("tight", [False, True], ids=["as given", "tight limits"])
@pytest.mark.parametrize(("config", "machine"), SWEPT, ids=lambda v: v if isinstance(v, str) else "-")
def test_the_row_at_the_scenes_speed_says_what_check_says(runner, tmp_path, config, machine, tight):
    """The governing condition (its words, margin and the margin it needs), the rule's verdict and
    the limits exceeded of the sweep's row at the scene's speed are those of `fcalc check`."""
    path, scene = _scene_file(tmp_path, config, TIGHT[config] if tight else None)
    row = _sweep_row(runner, path, machine, _speed_rpm(scene, machine))
    checks = _check(runner, path)
    phrase = condition_phrase(row["governing_condition"], row["margin"], row["needed"])
    assert phrase in checks["resonance"]["reason"]
    rule = {"clear": "pass", "information": "pass", "warn": "warn", "fail": "fail"}[row["resonance_status"]]
    assert rule == checks["resonance"]["verdict"]
    failing = sorted({r["quantity"] for r in checks["amplitudes"]["result"]["limits"] if r["verdict"] == "fail"})
    assert sorted(row["over_limits"]) == failing
    assert bool(failing) == tight  # the tight limits are exceeded, the shipped ones are not
    status = "fail" if "fail" in (rule, *("fail" for _ in failing)) else rule
    assert row["status"] == status and row["status"] in _status_words(row)


def _status_words(row) -> str:
    from foundation_calc.checks.sweep.status import status_text

    text = status_text(row["status"], row["governing_condition"], row["margin"], row["needed"], row["resonance_status"],
                       row["over_limits"])
    for quantity in row["over_limits"]:
        assert quantity in text
    return text


def test_a_harmonic_the_rule_does_not_judge_never_names_a_block_row(runner):
    """The compressor of block_two_machines.toml at 930 rpm: 2ω lies 0.9 % from mode 1 (y), whose
    forcing share is under 1 % (not judged), and 8.7 % from mode 2 (x), which is judged. The row fails
    by 2ω = mode 2 and says so, with the margin |2ω - p2|/p2 from an independent eigen-solve of
    the scene's K and M (scipy.linalg.eigh; rel 1e-9, the eigen-solvers' agreement)."""
    from scipy.linalg import eigh

    path = CONFIGS / "block_two_machines.toml"
    shares = {(r["machine"], r["order"], r["mode"]): r for r in
              json.loads(runner.invoke(app, ["resonance", str(path), "--json"]).stdout)["resonances"]}
    assert not shares["compressor", 2, 1]["judged"] and shares["compressor", 2, 2]["judged"]
    row = _sweep_row(runner, path, "compressor", 930.0)
    p = np.sqrt(eigh(*(np.asarray(a, dtype=float) for a in (_model(path).K, _model(path).M)), eigvals_only=True))
    omega = 930.0 * math.pi / 30.0
    assert abs(2 * omega - p[0]) / p[0] < 0.01  # the unjudged condition is the nearest
    assert row["governing_condition"] == "compressor: 2ω = mode 2 (x)"
    assert row["margin"] == pytest.approx(abs(2 * omega - p[1]) / p[1], rel=1e-9)
    assert row["status"] == "fail" and row["resonance_status"] == "fail"


def _model(path):
    return parse_scene(read_toml(path), str(path)).model()


def test_alone_leaves_the_other_machines_out(runner, tmp_path):
    """--alone: the swept machine's response on the block that still carries the others' mass, the
    same as `fcalc amplitudes` of the scene whose other machine's rotor weighs a milligram (rel
    1e-6: that milligram's share); and only the swept machine's conditions judge the rows."""
    document = read_toml(CONFIGS / "block_fan_torsion_near_speed.toml")
    document["machines"][1]["unbalance"]["rotor_mass"] = 1e-6
    quiet = tmp_path / "quiet_motor.toml"
    quiet.write_text(tomli_w.dumps(document), encoding="utf-8")
    amplitudes = json.loads(runner.invoke(app, ["amplitudes", str(quiet), "--json"]).stdout)
    args = ["sweep", str(CONFIGS / "block_fan_torsion_near_speed.toml"), "--speed", "300:990:3", "--machine", "fan", "--json"]
    alone = json.loads(runner.invoke(app, [*args, "--alone"]).stdout)
    both = json.loads(runner.invoke(app, args).stdout)
    at_speed = alone["points"][-1]
    for d in "xyz":
        expected = max(p["displacement_peak"][d] for p in amplitudes["points"].values())
        assert at_speed["peak"][d] == pytest.approx(expected, rel=1e-6)
    assert all(row["governing_condition"].startswith("fan: ") for row in alone["points"])
    assert alone["points"][0]["status"] == "pass" and both["points"][0]["status"] == "fail"  # the motor at 990 rpm fails
    assert both["points"][0]["governing_condition"].startswith("motor: ")
    assert alone["others"] == "left out" and both["others"] == "at their own speeds"


def test_alone_and_machine_are_a_block_scenes_options(runner):
    for extra in (["--alone"], ["--machine", "motor"]):
        result = runner.invoke(app, ["sweep", str(CONFIGS / "frame_saw.toml"), "--speed", "250", *extra])
        assert result.exit_code == 2 and "block_foundation" in result.stderr
    typo = runner.invoke(app, ["sweep", str(CONFIGS / "block_two_machines.toml"), "--speed", "600", "--machine", "compresor"])
    assert typo.exit_code == 2 and "did you mean 'compressor'" in typo.stderr


def test_a_block_plot_draws_no_band_for_a_condition_the_rule_does_not_judge(runner, tmp_path, monkeypatch):
    """Of the compressor's critical speeds in 300-1800 rpm (2ω against modes 1-4) the plot shades the
    judged ones' bands and leaves out 2ω = mode 1 (y) and mode 3 (z), whose forcing shares are under 1 %."""
    pytest.importorskip("matplotlib")
    from foundation_calc.output import plots

    drawn = []
    real = plots.mark_resonances
    monkeypatch.setattr(plots, "mark_resonances", lambda ax, marks, *a, **k: (drawn.extend(marks), real(ax, marks, *a, **k)))
    path = CONFIGS / "block_two_machines.toml"
    result = runner.invoke(app, ["sweep", str(path), "--speed", "300:1800:31", "--machine", "compressor", "--plot",
                                 str(tmp_path / "s.png")])
    assert result.exit_code == 0, result.stderr
    judged = {(r["order"], r["mode"]): r["judged"] for r in
              json.loads(runner.invoke(app, ["resonance", str(path), "--json"]).stdout)["resonances"] if r["machine"] == "compressor"}
    shown = {label: band for speed, label, _, band in drawn if 300.0 <= speed <= 1800.0}
    assert set(shown) == {"2ω = mode 2 (x)", "2ω = mode 4 (rz)"}
    assert not judged[2, 1] and not judged[2, 3] and all(band == 0.2 for band in shown.values())


@pytest.mark.parametrize(("config", "args"), [("frame_saw.toml", []), ("block_two_machines.toml", ["--machine", "compressor"])])
def test_a_long_scene_name_stays_inside_the_plot(runner, tmp_path, monkeypatch, config, args):
    """A 200-character name (the longest a scene takes) wraps: the title's box lies inside the figure."""
    pytest.importorskip("matplotlib")
    from matplotlib.backends.backend_agg import FigureCanvasAgg

    from foundation_calc.output import plots

    figures = []
    real = plots.save
    monkeypatch.setattr(plots, "save", lambda fig, p: (figures.append(fig), real(fig, p)))
    name = ("Compressor train K-101 A/B with its drive motor, gearbox and lube-oil console on one reinforced concrete"
            " block over dense gravel, revision C after the vendor's second data sheet of loads")[:200]
    path, _ = _scene_file(tmp_path, config, name=name)
    result = runner.invoke(app, ["sweep", str(path), "--speed", "200:900:11", *args, "--plot", str(tmp_path / "s.png")])
    assert result.exit_code == 0, result.stderr
    (fig,) = figures
    canvas = FigureCanvasAgg(fig)
    canvas.draw()
    box = fig.axes[0].title.get_window_extent(canvas.get_renderer())
    assert 0.0 <= box.x0 and box.x1 <= fig.bbox.x1 and box.y1 <= fig.bbox.y1
