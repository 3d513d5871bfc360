"""Errors and summaries that tell the user what to do: the nearest key for a misspelt one, the
keys a missing table needs, the command for a scene of the other kind, fcalc check for a folder;
non-scene TOML skipped by a folder check; scenes and checks counted apart; --strict says FAIL."""

from __future__ import annotations

import json

import pytest
import tomli_w

from foundation_calc.cli.app import app
from foundation_calc.scenes import read_toml
from tests.conftest import CONFIGS


def _write(tmp_path, name: str, text: str):
    path = tmp_path / name
    path.write_text(text, encoding="utf-8")
    return path


@pytest.mark.parametrize(
    ("old", "new", "hint"),
    [
        ("cog_height", "cog_heigth", "did you mean cog_height?"),
        ("rod_mass", "rod_mas", "did you mean rod_mass?"),
        ("[limits]", "[limit]", "did you mean limits?"),
    ],
)
def test_a_misspelt_key_gets_the_nearest_one(runner, tmp_path, old, new, hint):
    text = (CONFIGS / "frame_saw.toml").read_text(encoding="utf-8").replace(old, new, 1)
    result = runner.invoke(app, ["resonance", str(_write(tmp_path, "s.toml", text))])
    assert result.exit_code == 3 and hint in result.stderr


def test_a_missing_table_lists_the_keys_it_needs(runner, tmp_path):
    scene = read_toml(CONFIGS / "frame_saw.toml")
    del scene["soil"]
    result = runner.invoke(app, ["resonance", str(_write(tmp_path, "s.toml", tomli_w.dumps(scene)))])
    assert result.exit_code == 3 and "soil: missing (a table with c_z, c_x" in result.stderr and "method" in result.stderr


@pytest.mark.parametrize(
    ("command", "config", "hint"),
    [
        ("design", "platform_paper_example.toml", "use fcalc platform or fcalc resonance"),
        ("platform", "frame_saw.toml", "use fcalc resonance or fcalc amplitudes or fcalc sweep"),
    ],
)
def test_a_scene_of_the_other_kind_names_its_command(runner, command, config, hint):
    result = runner.invoke(app, [command, str(CONFIGS / config)])
    assert result.exit_code == 3 and hint in result.stderr.replace("\n  ", " ").replace("\n", " ")


def test_a_folder_given_to_a_single_scene_command_suggests_check(runner):
    result = runner.invoke(app, ["resonance", str(CONFIGS)])
    assert result.exit_code == 3 and "fcalc check" in result.stderr


def test_check_skips_toml_that_is_no_scene(runner, tmp_path):
    _write(tmp_path, ".taplo.toml", '[[rule]]\ninclude = ["*.toml"]\n')
    _write(tmp_path, "frame_saw.toml", (CONFIGS / "frame_saw.toml").read_text(encoding="utf-8"))
    result = runner.invoke(app, ["check", str(tmp_path)])
    assert result.exit_code == 0, result.output
    assert "skipped" in result.stdout and ".taplo.toml" in result.stdout
    document = json.loads(runner.invoke(app, ["check", str(tmp_path), "--json"]).stdout)
    assert [s["source"].rsplit("/", 1)[-1] for s in document["scenes"]] == ["frame_saw.toml"]
    assert document["skipped"][0].endswith(".taplo.toml")
    named = runner.invoke(app, ["check", str(tmp_path / ".taplo.toml")])  # named explicitly: checked
    assert named.exit_code == 3


def test_summary_counts_scenes_and_checks_apart(runner):
    result = runner.invoke(app, ["check", str(CONFIGS / "frame_saw.toml"), str(CONFIGS / "platform_paper_example.toml")])
    last = result.stdout.strip().splitlines()[-1]
    assert last.startswith("2 scenes: 1 pass, 1 warn (3 checks: 2 pass, 1 warn)")
    document = json.loads(
        runner.invoke(app, ["check", str(CONFIGS / "frame_saw.toml"), str(CONFIGS / "platform_paper_example.toml"), "--json"]).stdout
    )
    assert document["scene_counts"]["pass"] == 1 and document["counts"]["pass"] == 2


def test_strict_prints_a_failure_not_a_warning(runner):
    result = runner.invoke(app, ["platform", "--strict"])  # the paper example warns (exciter height)
    assert result.exit_code == 1
    assert result.stdout.strip().splitlines()[-1].startswith("FAIL (a warning, failing with --strict)")


@pytest.mark.parametrize(
    ("config", "change", "warning"),
    [
        ("frame_saw.toml", ("mechanism", "crank_radius", 300.0), "mechanism.crank_radius = 300 m"),
        ("frame_saw.toml", ("mechanism", "omega", 300.0), "write speed_rpm = 300"),
        ("platform_paper_example.toml", ("operation", "amplitude", 0.02), "was it typed in mm?"),
        ("platform_paper_example.toml", ("operation", "omega", 3000.0), "write speed_rpm = 3000"),
    ],
)
def test_a_probably_wrong_unit_is_warned_about(runner, tmp_path, config, change, warning):
    scene = read_toml(CONFIGS / config)
    table, key, value = change
    if key == "omega" and "speed_rpm" in scene[table]:
        del scene[table]["speed_rpm"]
    if key == "crank_radius":
        scene["mechanism"]["rod_length"] = 1200.0
        scene["mechanism"]["rod_cog_to_crank_pin"] = 1000.0
    scene[table][key] = value
    path = _write(tmp_path, "s.toml", tomli_w.dumps(scene))
    command = "platform" if config.startswith("platform") else "resonance"
    single = runner.invoke(app, [command, str(path)])
    assert warning in single.stderr.replace("\n", " ") and single.exit_code != 4
    batch = json.loads(runner.invoke(app, ["check", str(path), "--json"]).stdout)
    assert any(warning in w for w in batch["scenes"][0]["warnings"])


def test_a_plausible_scene_has_no_warning(runner):
    for config in ("frame_saw.toml", "platform_paper_example.toml"):
        assert "warning" not in runner.invoke(app, ["check", str(CONFIGS / config)]).stderr


def test_units_rpm_converts_every_speed_column(runner):
    table = runner.invoke(app, ["resonance", str(CONFIGS / "frame_saw.toml"), "--units", "rpm"]).stdout
    header = next(line for line in table.splitlines() if "averaged inertia" in line and "mode" in line)
    assert "rpm, averaged inertia" in header


def test_the_methods_name_one_resonance_the_rules(runner):
    """The closed forms no longer name their own nearest resonance (3ω = p1 against 6ω = k0): the
    header names the governing condition of the resonance rule, as `fcalc resonance` does."""
    lines = runner.invoke(app, ["amplitudes", str(CONFIGS / "frame_saw.toml")], env={"COLUMNS": "300"}).stdout.splitlines()[1:4]
    assert not any("nearest resonance" in line for line in lines)
    assert "resonance rule (as fcalc resonance): governing resonance 3ω = p1 at 30.9% (needs 20%)" in lines[2]


def test_a_number_too_long_to_read_is_an_invalid_scene_naming_its_line(runner, tmp_path):
    text = 'kind = "crank_foundation"\n[foundation]\nmass = ' + "9" * 5000 + "\n"
    result = runner.invoke(app, ["resonance", str(_write(tmp_path, "big.toml", text))])
    assert result.exit_code == 3
    assert "line 3, key mass: a number with 5000 digits" in result.stderr.replace("\n  ", " ")


def test_frequencies_double_precision_cannot_resolve_are_an_invalid_scene(runner, tmp_path):
    """Lengths of 1e-13 m against a 1e5 kg block on c_z = 4e-5 N/m³: one natural frequency of
    the averaged operator is round-off. Exit 3 naming the fields, never a crash or a NaN."""
    scene = read_toml(CONFIGS / "frame_saw.toml")
    scene["foundation"] |= {"moment_of_inertia": 1e-13, "base_area": 30.0, "cog_height": 1e-13}
    scene["soil"] = {"c_z": 4e-5, "c_x": 2.8e-5}
    del scene["mechanism"]["speed_rpm"]
    scene["mechanism"] |= {
        "omega": 7e13, "crank_radius": 1e-13, "rod_length": 1.2e-13, "rod_cog_to_crank_pin": 1e-13,
        "rod_radius_of_gyration": 1e-13, "crank_axis_to_cog": 1e-13,
    }
    path = _write(tmp_path, "extreme.toml", tomli_w.dumps(scene))
    result = runner.invoke(app, ["amplitudes", str(path)])
    assert result.exit_code == 3, result.output
    assert "double precision" in result.stderr and "foundation.moment_of_inertia" in result.stderr
    batch = runner.invoke(app, ["check", str(path), str(CONFIGS / "frame_saw.toml"), "--json"])
    assert batch.exit_code == 3 and [s["exit_code"] for s in json.loads(batch.stdout)["scenes"]] == [3, 0]


def test_validation_messages_read_as_written_for_an_engineer(runner, tmp_path, frame_saw):
    """No pydantic wording, no "- [-]:" of a field without symbol or unit, one "got" per line."""
    frame_saw["project"] = {"job": 5}
    frame_saw["foundation"]["mass"] = -1
    frame_saw["foundation"]["moment_of_inertia"] = "a"
    frame_saw["soil"]["damping"] = [0.1, 0.1]
    frame_saw["limits"]["detuning"] = 2
    result = runner.invoke(app, ["resonance", str(_write(tmp_path, "s.toml", tomli_w.dumps(frame_saw)))])
    assert result.exit_code == 3
    lines = {line.split(":", 1)[0].strip(): line for line in result.stderr.splitlines()[1:]}
    assert "foundation.mass: must be > 0 (got -1;" in lines["foundation.mass"]
    assert "must be a number (got 'a'" in lines["foundation.moment_of_inertia"]
    assert "must be text" in lines["project.job"] and "- [-]" not in lines["project.job"]
    assert "must have 3 items (got [0.1, 0.1]" in lines["soil.damping"]
    assert lines["limits.detuning"].count("got") + lines["limits.detuning"].count("= 2 ") == 1
    assert "Input should" not in result.stderr and "should have" not in result.stderr
