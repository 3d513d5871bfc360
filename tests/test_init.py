"""`fcalc init`: a documented starting scene that loads back, atomic writes, never an overwrite."""

from __future__ import annotations

import re

import os
import tomllib

import pytest
from pydantic import BaseModel

from foundation_calc.cli.app import app
from foundation_calc.scenes import KINDS, load_scene, read_toml
from foundation_calc.scenes.kinds import model_for_kind
from foundation_calc.scenes.template import example_path, scene_template
from tests.conftest import CONFIGS


def _keys(model: type[BaseModel], prefix: str = "") -> list[tuple[str, str]]:
    """(dotted key, "symbol [unit]" of its description) of every key, nested models included."""
    from foundation_calc.scenes.template import _nested_model

    keys = []
    for name, info in model.model_fields.items():
        nested, _ = _nested_model(info.annotation)
        keys.append((prefix + name, "" if nested else (info.description or "").split(": ")[0]))
        if nested is not None:
            keys.extend(_keys(nested, f"{prefix}{name}."))
    return keys


@pytest.mark.parametrize("kind", sorted(KINDS))
def test_written_scene_loads_back_to_the_example(runner, tmp_path, kind):
    target = tmp_path / "new.toml"
    result = runner.invoke(app, ["init", kind, str(target)])
    assert result.exit_code == 0, result.output
    assert load_scene(target) == load_scene(example_path(kind))
    assert oct(target.stat().st_mode & 0o777) != oct(0o600)  # a normal file, not mkstemp's private mode
    assert [p.name for p in tmp_path.iterdir()] == ["new.toml"]  # no temporary file left
    check = runner.invoke(app, ["check", str(target)])
    assert check.exit_code in (0, 1), check.output


@pytest.mark.parametrize("kind", sorted(KINDS))
def test_every_key_is_written_under_its_description(kind):
    """Each key of the model appears (set, or commented out) right after its "symbol [unit]: text"."""
    lines = scene_template(kind).splitlines()
    model = model_for_kind(kind)
    assert len(_keys(model)) > 20
    for dotted, symbol_unit in _keys(model):
        section, _, key = dotted.rpartition(".")
        start = next(i for i, line in enumerate(lines) if not section or line.lstrip("# ").strip("[]") == section)
        at = [i for i, line in enumerate(lines) if i >= start and line.lstrip("# ").startswith((f"{key} =", f"[{dotted}]", f"[[{dotted}]]"))]
        assert at, dotted
        above = lines[at[0] - 1]
        assert above.startswith("# ") and len(above) > 8, (dotted, above)
        if symbol_unit not in ("", "- [-]"):
            assert above.startswith(f"# {symbol_unit}: "), (dotted, above)


def test_crank_template_names_symbols_units_and_ranges():
    text = scene_template("crank_foundation")
    for fragment in (
        "# M [kg]: block and machine frame, without rod and slider (or from [foundation.block]); allowed > 0;"
        " optional\nmass = 100000.0",
        "# c [N/m³]: coefficient of elastic uniform compression; allowed > 0; optional\nc_z = 70000000.0",
        '# method = "lysmer"',
        "# [foundation.block]",
        "speed_rpm = 250.0",
        "# omega = 26.179939",  # the alternatives, commented out, with the same speed
        "# frequency_hz = 4.166667",
        "each band > 0 and < 1",  # [limits] detuning: one band or a band per order
    ):
        assert fragment in text


def test_default_example_matches_the_shipped_config():
    assert read_toml(example_path("crank_foundation")) == read_toml(CONFIGS / "frame_saw.toml")


def test_refuses_to_overwrite_without_force(runner, tmp_path):
    target = tmp_path / "mine.toml"
    target.write_text("precious = true\n", encoding="utf-8")
    result = runner.invoke(app, ["init", "crank_foundation", str(target)])
    assert result.exit_code == 2
    assert "exists" in result.output and "--force" in result.output
    assert target.read_text(encoding="utf-8") == "precious = true\n"
    forced = runner.invoke(app, ["init", "crank_foundation", str(target), "--force"])
    assert forced.exit_code == 0
    assert tomllib.loads(target.read_text(encoding="utf-8"))["kind"] == "crank_foundation"


def test_default_path_and_folder_and_stdout(runner, tmp_path, monkeypatch):
    monkeypatch.chdir(tmp_path)
    assert runner.invoke(app, ["init", "platform"]).exit_code == 0
    assert (tmp_path / "platform.toml").is_file()
    sub = tmp_path / "scenes"
    sub.mkdir()
    assert runner.invoke(app, ["init", "crank_foundation", str(sub)]).exit_code == 0
    assert (sub / "crank_foundation.toml").is_file()
    printed = runner.invoke(app, ["init", "crank_foundation", "-"])
    assert printed.exit_code == 0 and printed.stdout == scene_template("crank_foundation")
    assert not (tmp_path / "-").exists()


def test_unknown_kind_and_unwritable_path(runner, tmp_path):
    bad = runner.invoke(app, ["init", "chimney", str(tmp_path / "x.toml")])
    assert bad.exit_code == 2 and "crank_foundation" in bad.output
    missing = runner.invoke(app, ["init", "platform", str(tmp_path / "no" / "x.toml")])
    assert missing.exit_code == 2 and "Traceback" not in missing.output


def test_an_interrupted_write_leaves_the_old_file(tmp_path, monkeypatch):
    from foundation_calc.output import files

    target = tmp_path / "scene.toml"
    target.write_text("old\n", encoding="utf-8")

    def fail(*args):
        raise OSError(28, "No space left on device")

    monkeypatch.setattr(os, "replace", fail)
    with pytest.raises(OSError):
        files.write_atomically(target, "new\n")
    assert target.read_text(encoding="utf-8") == "old\n"
    assert [p.name for p in tmp_path.iterdir()] == ["scene.toml"]


@pytest.mark.parametrize("kind", ["crank_foundation", "platform"])
def test_every_commented_out_key_is_valid_toml(kind):
    """A user uncomments a key of the template: it must parse, with a value of the right type."""
    keys = [line[2:] for line in scene_template(kind).splitlines() if re.match(r"# \w+ = ", line)]
    assert keys, "the template has commented-out keys"
    for line in keys:
        assert "..." not in line
        tomllib.loads(line)  # raises on invalid TOML
    uncommented = "\n".join(
        line[2:] if re.match(r"# (\w+ = |\[)", line) and "omega" not in line and "frequency_hz" not in line else line
        for line in scene_template(kind).splitlines()
    )
    tomllib.loads(uncommented)
