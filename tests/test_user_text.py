"""User text is data: scene and point names never act as format templates or markup, in the
table, the JSON document or the JUnit report, and one odd name never stops a batch."""

from __future__ import annotations

import json
import xml.etree.ElementTree as ET

import pytest
import tomli_w

from foundation_calc.cli.app import app
from foundation_calc.scenes import read_toml
from tests.conftest import CONFIGS

HOSTILE = [
    "{}",
    "{x}",
    "{0!r}",
    "{speed:>9}",
    "{speed:>50000000}",
    "%s %d",
    "[b]bold[/b] [de]",
    "Compressor [k-101]",
    "Pump :fire: line",
    "\x1b[31mred\x1b[0m",
    "\u202eright-to-left\u202c",
]


def _folder(tmp_path, name: str):
    crank = read_toml(CONFIGS / "frame_saw.toml")
    crank["name"] = name
    crank["points"] = [{"name": name[:80], "horizontal": 0.5, "height": 0.5}]
    platform = read_toml(CONFIGS / "platform_paper_example.toml")
    platform["name"] = name
    (tmp_path / "crank.toml").write_text(tomli_w.dumps(crank), encoding="utf-8")
    (tmp_path / "platform.toml").write_text(tomli_w.dumps(platform), encoding="utf-8")
    (tmp_path / "good.toml").write_text((CONFIGS / "crank_press.toml").read_text(encoding="utf-8"), encoding="utf-8")
    return tmp_path


@pytest.mark.parametrize("name", HOSTILE, ids=repr)
def test_hostile_names_are_printed_verbatim_everywhere(runner, tmp_path, name):
    folder = _folder(tmp_path, name)
    junit = tmp_path / "out.xml"
    table = runner.invoke(app, ["check", str(folder), "--junit", str(junit)])
    assert table.exit_code in (0, 1), table.output
    document = runner.invoke(app, ["check", str(folder), "--json"])
    assert document.exit_code == table.exit_code
    assert len(document.stdout) < 200_000  # a format spec in a name cannot inflate the output
    parsed = json.loads(document.stdout)
    assert sum(s["name"] == name for s in parsed["scenes"]) == 2
    crank = next(s for s in parsed["scenes"] if s["source"].endswith("crank.toml"))
    amplitudes = next(c for c in crank["checks"] if c["check"] == "amplitudes")
    assert name[:80] in amplitudes["result"]["approximations"]["averaged_operator"]["points"]
    ET.parse(junit)  # well-formed XML
    for command in (["amplitudes", str(folder / "crank.toml")], ["resonance", str(folder / "crank.toml")]):
        result = runner.invoke(app, command)
        assert result.exit_code in (0, 1), result.output
        if "\x1b" not in name:
            assert name[:80] in result.stdout


def test_a_name_too_long_is_an_invalid_scene_and_the_rest_still_run(runner, tmp_path):
    folder = _folder(tmp_path, "n" * 10_000)
    result = runner.invoke(app, ["check", str(folder), "--json"])
    assert result.exit_code == 3
    verdicts = {s["source"].rsplit("/", 1)[-1]: s["exit_code"] for s in json.loads(result.stdout)["scenes"]}
    assert verdicts == {"crank.toml": 3, "good.toml": 0, "platform.toml": 3}


def test_one_folder_of_every_hostile_case_gives_a_verdict_for_each_scene(runner, tmp_path):
    """A format-template name, a name too long, a number too long to read, frequencies double
    precision cannot resolve, and good scenes, in one folder: a verdict for every scene in the
    table, the JSON document and JUnit."""
    good = read_toml(CONFIGS / "frame_saw.toml")
    named = {**good, "name": "{speed:>50000000}", "points": [{"name": "{x} [b] %s", "horizontal": 0.5, "height": 0.5}]}
    extreme = json.loads(json.dumps(good))
    extreme["foundation"] |= {"moment_of_inertia": 1e-13, "cog_height": 1e-13}
    extreme["soil"] = {"c_z": 4e-5, "c_x": 2.8e-5}
    del extreme["mechanism"]["speed_rpm"]
    extreme["mechanism"] |= {"omega": 7e13, "crank_radius": 1e-13, "rod_length": 1.2e-13, "rod_cog_to_crank_pin": 1e-13,
                             "rod_radius_of_gyration": 1e-13, "crank_axis_to_cog": 1e-13}
    files = {
        "a_named.toml": tomli_w.dumps(named),
        "b_long_name.toml": tomli_w.dumps({**good, "name": "n" * 10_000}),
        "c_big_int.toml": 'kind = "crank_foundation"\n[foundation]\nmass = ' + "9" * 5000 + "\n",
        "d_extreme.toml": tomli_w.dumps(extreme),
        "e_good.toml": tomli_w.dumps(good),
        "f_platform.toml": (CONFIGS / "platform_paper_example.toml").read_text(encoding="utf-8"),
    }
    for name, text in files.items():
        (tmp_path / name).write_text(text, encoding="utf-8")
    junit = tmp_path / "report.xml"
    table = runner.invoke(app, ["check", str(tmp_path), "--junit", str(junit)])
    assert table.exit_code == 3
    for name in files:
        assert name in table.stdout
    document = json.loads(runner.invoke(app, ["check", str(tmp_path), "--json"]).stdout)
    codes = {s["source"].rsplit("/", 1)[-1]: s["exit_code"] for s in document["scenes"]}
    assert codes == {"a_named.toml": 0, "b_long_name.toml": 3, "c_big_int.toml": 3, "d_extreme.toml": 3,
                     "e_good.toml": 0, "f_platform.toml": 0}
    suites = {s.get("name").rsplit("/", 1)[-1] for s in ET.parse(junit).getroot()}
    assert suites == set(files)
