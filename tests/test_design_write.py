"""``fcalc design --write``: the chosen design written into the user's own scene text, its comments,
key order, blank lines and array layout kept, only the varied keys and the positions that moved
changed; a crank scene's derived keys commented out; the written file checked by ``fcalc check``
as the re-check judged the design."""

from __future__ import annotations

import difflib
import json
import re
import shutil
import tomllib

import pytest
from typer.testing import CliRunner

from foundation_calc.cli.app import app
from foundation_calc.api.design import LEFT_OUT
from foundation_calc.output.scene_edit import edited_scene
from foundation_calc.scenes import read_toml

from tests.conftest import CONFIGS

#: The template's block (fcalc init block_foundation: the shipped example) [m].
L0, B0, H0 = 7.0, 4.0, 2.2

#: A grid without the template's dimensions, on which the cheapest passing block is its lowest corner.
RANGES = ["block.length=5:6", "block.width=3:3.5", "block.height=1.6:1.8"]


def _annotate(text: str) -> str:
    """What an office adds to a template: comments beside and between keys, a blank line, an
    array laid out a number a line with a comment on each."""
    edits = [
        ("length = 7.0\n", "length = 7.0                # L: as drawn, rev. B\n"),
        ("height = 2.2\n", "height = 2.2  # H\n\n# the office keeps this block under version control\n"),
        ("at = [3.5, 2.0, 2.2]\n", "at = [\n    3.5,   # x: the corner\n    2.0,   # y\n    2.2,   # z: the top\n]\n"),
        ('name = "compressor"\n', 'name = "compressor"  # vendor drawing 4711\n'),
    ]
    for old, new in edits:
        assert text.count(old) == 1, old
        text = text.replace(old, new)
    return text


@pytest.fixture(scope="module")
def written(tmp_path_factory):
    """An annotated template, the design's JSON, the file --write wrote and fcalc check's JSON on it."""
    folder = tmp_path_factory.mktemp("write")
    scene, best = folder / "block.toml", folder / "best.toml"
    runner = CliRunner()
    assert runner.invoke(app, ["init", "block_foundation", str(scene)]).exit_code == 0
    scene.write_text(_annotate(scene.read_text()))
    args = ["design", str(scene), *[a for r in RANGES for a in ("--vary", r)], "--points", "3", "--json", "--write", str(best)]
    result = runner.invoke(app, args)
    assert result.exit_code == 0, result.output
    check = runner.invoke(app, ["check", str(best), "--json"])
    return scene.read_text(), json.loads(result.stdout), best.read_text(), check


def _changed_lines(old: str, new: str) -> list[tuple[str, str]]:
    """(old line, new line) of every line that differs; fails on a line added or removed."""
    a, b = old.splitlines(), new.splitlines()
    pairs = []
    for tag, i1, i2, j1, j2 in difflib.SequenceMatcher(None, a, b, autojunk=False).get_opcodes():
        if tag == "equal":
            continue
        assert tag == "replace" and i2 - i1 == j2 - j1, (tag, a[i1:i2], b[j1:j2])
        pairs += list(zip(a[i1:i2], b[j1:j2]))
    return pairs


def test_only_the_varied_keys_and_the_moved_positions_change(written):
    """Every line of the template stays but those of the block's dimensions and of the positions
    at or above its top (two machines' centres of mass, three loads, three points), the corner's
    three numbers of its multi-line array among them."""
    old, design, new, _ = written
    changed = [a for a, _ in _changed_lines(old, new)]
    expected = [line for line in old.splitlines() if re.match(r"(length = 7\.0|width = 4\.0|height = 2\.2|cog = \[|at = \[-?\d)", line)
                or re.match(r"    \d\.\d,   # [xyz]", line)]
    assert changed == expected and len(changed) == 3 + 2 + 3 + 2 + 3
    assert len(new.splitlines()) == len(old.splitlines())
    assert [c for c in old.splitlines() if c.lstrip().startswith("#")] == [c for c in new.splitlines() if c.lstrip().startswith("#")]
    assert "# L: as drawn, rev. B" in new and "# vendor drawing 4711" in new and re.search(r"^    [\d.]+,   # y$", new, re.M)
    assert design["written_changes"][0] == {"key": "block.length", "from": L0, "to": design["best"]["values"]["block.length"]}


def test_the_written_numbers_are_the_moved_positions_as_typed(written):
    """The positions, moved by the rule (at or above the top: up by H - H0; on an end face: the
    face's distance kept), typed independently here; no number longer than the grid's precision."""
    old, design, new, _ = written
    L, B, H = design["best"]["values"].values()
    assert (L, B, H) != (L0, B0, H0)
    before, after = tomllib.loads(old), tomllib.loads(new)
    assert after["block"] == {**before["block"], "length": L, "width": B, "height": H}
    up = H - H0
    for m0, m1 in zip(before["machines"], after["machines"]):
        assert m1["cog"] == pytest.approx([m0["cog"][0], m0["cog"][1], m0["cog"][2] + up], abs=1e-12)
        for l0, l1 in zip(m0.get("loads", []), m1.get("loads", [])):
            assert l1["at"] == pytest.approx([l0["at"][0], l0["at"][1], l0["at"][2] + up], abs=1e-12)
    corner = after["points"][2]["at"]
    assert corner == pytest.approx([L / 2, B / 2, H], abs=1e-12)
    for a, b in _changed_lines(old, new):
        assert not re.search(r"\d{7,}", b), b  # 2.1, not 2.0999999999999996


def test_fcalc_check_judges_the_written_file_as_the_recheck(written):
    _, design, _, check = written
    assert check.exit_code == 0, check.output
    verdicts = {c["check"]: c["verdict"] for c in json.loads(check.stdout)["scenes"][0]["checks"]}
    assert verdicts == {name: c["outcome"] for name, c in design["best"]["checks"].items()}


def test_a_crank_scenes_derived_keys_are_commented_out(tmp_path):
    """The compressor on its block, its base and mass given beside [foundation.block]: the written
    file keeps their lines, commented out with their comments and a note, and fcalc check passes it."""
    scene, best = tmp_path / "compressor.toml", tmp_path / "best.toml"
    text = (CONFIGS / "compressor_medium_sand_lysmer.toml").read_text()
    mass = "mass = 106160.0              # M [kg] checked by hand\n"
    text = text.replace("[foundation.block]\n", mass + "\n[foundation.block]\n", 1)
    scene.write_text(text)
    runner = CliRunner()
    result = runner.invoke(app, ["design", str(scene), "--vary", "block.length=4.5:5", "--points", "2", "--json", "--write", str(best)])
    assert result.exit_code == 0, result.output
    new = best.read_text()
    pairs = dict(_changed_lines(text, new))
    for line in ("base_length = 6.0            # L [m]  in the plane of motion", "base_width = 4.0             # B [m]",
                 mass.rstrip("\n")):
        assert pairs[line] == f"# {line}  # {LEFT_OUT}"
    foundation = read_toml(best)["foundation"]
    assert not {"base_length", "base_width", "mass"} & set(foundation)
    assert foundation["block"]["length"] == json.loads(result.stdout)["best"]["values"]["foundation.block.length"]
    assert runner.invoke(app, ["check", str(best)]).exit_code == 0


@pytest.mark.parametrize(("text", "new", "expected"), [
    ("length = 7  # whole\n", {"length": 5.0}, "length = 5  # whole\n"),
    ("length = 7.0\r\nwidth = 4.0\r\n", {"length": 5.2, "width": 4.0}, "length = 5.2\r\nwidth = 4.0\r\n"),
    ("z = 2.9\n", {"z": 2.9 + (1.5 - 2.2)}, "z = 2.2\n"),
    ("a = 5.0          # column\nb = 1\n", {"a": 12.75, "b": 1}, "a = 12.75        # column\nb = 1\n"),
    ("at = {horizontal = 0.5}  # bearing\n", {"at": {"horizontal": 0.5, "height": -0.25}},
     "at = {horizontal = 0.5, height = -0.25}  # bearing\n"),
    ("f = {mass = 1.0, b = 2}\n", {"f": {"b": 2}}, "f = {b = 2}\n"),
    ("[f]\n  mass = 1.0e5 # by hand\nb = 2\n", {"f": {"b": 2}}, "[f]\n  # mass = 1.0e5 # by hand  # note\nb = 2\n"),
])
def test_edits_keep_the_text_around_the_value(text, new, expected):
    """Integers stay integers where the value is whole; line endings, comments and their column
    stay; a key added to an inline table joins it; a key left out is commented out (removed from
    an inline table, which holds no comment)."""
    assert edited_scene(text, new, decimals=6, note="note").text == expected


def test_the_edited_scene_must_hold_the_new_document(monkeypatch):
    """The read-back is no formality: an edit that does not reach the text (here tomlkit's output
    replaced by the old text) raises, naming the key, instead of writing a file that holds another design."""
    from foundation_calc.output import scene_edit

    monkeypatch.setattr(scene_edit.tomlkit, "dumps", lambda document: "a = 1.0\n")
    with pytest.raises(RuntimeError, match="does not hold the new values at a"):
        edited_scene("a = 1.0\n", {"a": 2.0}, decimals=6, note="")


def test_write_over_the_scene_itself(tmp_path):
    """The office's workflow: --write onto the scene file it read (atomically replaced)."""
    scene = tmp_path / "fan.toml"
    shutil.copy(CONFIGS / "block_fan_torsion_near_speed.toml", scene)
    before = scene.read_text()
    result = CliRunner().invoke(app, ["design", str(scene), "--vary", "block.length=5:8", "--vary", "block.width=5:7",
                                      "--vary", "block.height=3:4", "--points", "3", "--write", str(scene)])
    assert result.exit_code == 0, result.output
    assert len(_changed_lines(before, scene.read_text())) > 3


def test_a_written_scene_judged_otherwise_is_not_written(tmp_path, monkeypatch):
    """The guard after the edit: a written text that fcalc check's path judges otherwise than the
    re-check (here the edit's height replaced by one on which the fan's modes fail) is a bug,
    exit 4, and the file is not written."""
    from foundation_calc.output import scene_edit

    edit = scene_edit.edited_scene

    def wrong_height(*args, **kwargs):
        done = edit(*args, **kwargs)
        return scene_edit.EditedScene(re.sub(r"^height = [\d.]+", "height = 0.5", done.text, flags=re.M), done.changes)

    monkeypatch.setattr(scene_edit, "edited_scene", wrong_height)
    best = tmp_path / "best.toml"
    result = CliRunner().invoke(app, ["design", str(CONFIGS / "block_fan_torsion_near_speed.toml"), "--vary", "block.length=5:8",
                                      "--vary", "block.width=5:7", "--vary", "block.height=3:4", "--points", "3",
                                      "--write", str(best)])
    assert result.exit_code == 4, result.output
    assert "judged" in result.output and not best.exists()


@pytest.mark.parametrize(("config", "heights"), [("block_two_throw_compressor.toml", "1.5:1.8"),  # H = 2.0 m
                                                 ("block_opposed_compressor.toml", "1.8:2.1")])  # H = 1.5 m
def test_a_written_crank_block_is_the_design_the_search_judged(config, heights, tmp_path):
    """A block with crank mechanisms sized over its height: the written file's crank centres move
    with their machine (by the height's change, the machine standing on the top), as the search's
    model moves the mechanism, and fc.check of the file gives each check the verdict and the
    utilisation the search reported for the design (1e-9: the same path; they were 0.1 % apart
    on the two-throw compressor, its crank centres left where they were)."""
    import foundation_calc as fc
    from foundation_calc.checks.design.recheck import OUTCOME_NAMES
    from foundation_calc.checks.design.reference import judged

    scene, best = tmp_path / config, tmp_path / "best.toml"
    shutil.copy(CONFIGS / config, scene)
    before = read_toml(scene)
    result = fc.design(scene, vary=[f"block.height={heights}"], points=4, write=best)
    assert result.exit_code == 0, result.to_dict()["recheck"]
    found = result.to_dict()["best"]
    rise = found["values"]["block.height"] - before["block"]["height"]
    assert abs(rise) >= 0.3
    after = read_toml(best)
    for machine, written in zip(before["machines"], after["machines"]):
        for crank, moved in zip(machine.get("cranks", []), written.get("cranks", [])):
            assert moved["crank_centre"] == pytest.approx([*crank["crank_centre"][:2], crank["crank_centre"][2] + rise], abs=1e-9)
    for run in fc.check(best).report.runs:
        outcome, utilisation, _ = judged(run)
        said = found["checks"].get(run.check, {"outcome": "pass", "utilisation": None})
        assert OUTCOME_NAMES[outcome] == said["outcome"], run.check
        if said["utilisation"] is not None:
            assert utilisation == pytest.approx(said["utilisation"], rel=1e-9), run.check
