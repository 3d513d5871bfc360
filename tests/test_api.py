"""The Python API (``import foundation_calc as fc``) gives what the commands give: for every
shipped scene and every command with ``--json``, ``fc.<command>(scene).to_dict()`` is the very
document the command prints (run in this process by typer's runner, so fcalc's version is the
same), its exit code the command's, and an invalid scene raises ``fc.SceneError`` whose
``problems`` are the document's. Exact equality throughout: both come from one function."""

from __future__ import annotations

import json
import sys

import pytest

import foundation_calc as fc
from foundation_calc.cli.app import app
from foundation_calc.scenes import read_toml
from tests.conftest import CONFIGS

SCENES = sorted(CONFIGS.glob("*.toml"))
#: A short sweep of every crank and block scene: 5 points from 100 to 1500 rpm.
SPEED = "100:1500:5"


def _cli(runner, *args: str) -> tuple[int, dict]:
    """Exit code and JSON document of ``fcalc ARGS --json``, in this process."""
    run = runner.invoke(app, [*args, "--json"])
    assert run.exit_code in (0, 1, 3), run.output
    return run.exit_code, json.loads(run.stdout)


def _commands(path) -> list[tuple[str, tuple[str, ...], dict]]:
    """(command, its CLI options, the API's keyword arguments) of every command with --json that
    takes a scene of the kind of ``path``."""
    document = read_toml(path)
    kind = document["kind"]
    if kind == "platform":
        return [("platform", (), {}), ("runup", (), {})]
    machine = document["machines"][0]["name"] if kind == "block_foundation" else None
    sweep = ("--speed", SPEED) + (("--machine", machine) if machine else ())
    return [("resonance", (), {}), ("amplitudes", (), {}), ("soil", (), {}), ("runup", (), {}),
            ("sweep", sweep, {"speed": SPEED, "machine": machine})]


CASES = [(path, *command) for path in SCENES for command in _commands(path)]


@pytest.mark.parametrize(("path", "command", "options", "keywords"), CASES,
                         ids=[f"{p.stem}-{c}" for p, c, _, _ in CASES])
def test_a_command_and_its_function_give_one_document(path, command, options, keywords, runner):
    code, document = _cli(runner, command, str(path), *options)
    scene = fc.load(str(path))
    function = getattr(fc, command)
    if code == 3:  # e.g. a run-up of a scene without a run time
        with pytest.raises((fc.SceneError, fc.PhysicsError)) as raised:
            function(scene, **keywords)
        assert raised.value.problems == document["problems"]
        return
    result = function(scene, **keywords)
    assert result.to_dict() == document
    assert result.exit_code == code
    assert result.verdict == document["verdict"] if "verdict" in document else result.verdict == "pass"


@pytest.mark.parametrize("path", SCENES, ids=lambda p: p.stem)
def test_check_gives_the_scene_entry_of_check_json(path, runner):
    code, document = _cli(runner, "check", str(path))
    result = fc.check(str(path))
    assert result.to_dict() == document["scenes"][0]
    assert result.exit_code == code == document["scenes"][0]["exit_code"]
    order = ["pass", "warn", "fail", "invalid", "internal"]
    assert result.verdict == max((c["verdict"] for c in document["scenes"][0]["checks"]), key=order.index)


def _bad_scenes(tmp_path) -> dict:
    """Scenes that cannot be used: name -> (file, the same as a mapping or None)."""
    good = read_toml(CONFIGS / "frame_saw.toml")
    negative = json.loads(json.dumps(good))
    negative["foundation"]["mass"] = -1.0
    wrong_unit = json.loads(json.dumps(good))
    wrong_unit["mechanism"]["rod_length"] = "72 MPa"
    no_kind = {key: value for key, value in good.items() if key != "kind"}
    import tomli_w

    files = {}
    for name, document in (("negative", negative), ("wrong_unit", wrong_unit), ("no_kind", no_kind)):
        files[name] = (tmp_path / f"{name}.toml", document)
        files[name][0].write_text(tomli_w.dumps(document), encoding="utf-8")
    files["not_toml"] = (tmp_path / "not_toml.toml", None)
    files["not_toml"][0].write_text("kind = \n", encoding="utf-8")
    return files


def test_an_invalid_scene_raises_scene_error_with_the_documents_problems(runner, tmp_path):
    for name, (path, mapping) in _bad_scenes(tmp_path).items():
        code, document = _cli(runner, "check", str(path))
        expected = document["scenes"][0]["checks"][0]["problems"]
        assert code == 3 and expected, name
        with pytest.raises(fc.SceneError) as raised:
            fc.load(str(path))
        assert raised.value.problems == expected, name
        code, single = _cli(runner, "resonance", str(path))
        assert code == 3 and single["problems"] == expected, name
        with pytest.raises(fc.SceneError) as raised:
            fc.resonance(str(path))
        assert raised.value.problems == expected, name
        if mapping is not None:  # the same keys as a mapping: validated the same way
            with pytest.raises(fc.SceneError) as raised:
                fc.load(mapping)
            assert raised.value.problems == expected, name


def test_a_command_refuses_a_scene_of_another_kind_as_it_does_on_the_command_line(runner):
    path = CONFIGS / "platform_paper_example.toml"
    code, document = _cli(runner, "design", str(path), "--vary", "block.length=2:4")
    with pytest.raises(fc.SceneError) as raised:
        fc.design(fc.load(str(path)), vary=["block.length=2:4"])
    assert code == 3 and raised.value.problems == document["problems"]
    assert raised.value.problems[0].field == "kind"


def test_a_mapping_gives_the_files_results():
    """A scene given as a mapping (unit strings included) is the file's scene: the same entry but
    for the source, which names no file."""
    path = CONFIGS / "frame_saw.toml"
    mapping = read_toml(path)
    mapping["foundation"]["mass"] = f"{mapping['foundation']['mass'] / 1000} t"
    from_file, from_mapping = fc.check(str(path)).to_dict(), fc.check(mapping).to_dict()
    assert from_mapping.pop("source") == "<scene>"
    from_file.pop("source")
    assert from_mapping == from_file


def test_options_are_keyword_arguments_with_the_commands_meaning(runner):
    path = str(CONFIGS / "compressor_near_resonance.toml")
    code, document = _cli(runner, "sweep", path, "--soil", "0.5:1.5:3")
    assert fc.sweep(path, soil="0.5:1.5:3").to_dict() == document
    code, document = _cli(runner, "resonance", path, "--strict")
    assert fc.resonance(path, strict=True).exit_code == code
    with pytest.raises(fc.UsageError, match="exactly one of --speed and --soil"):
        fc.sweep(path)
    with pytest.raises(fc.UsageError) as raised:
        fc.soil(path, modulus_cov=3.0)
    assert raised.value.option == "'--modulus-cov'"
    platform = str(CONFIGS / "platform_paper_example.toml")
    code, document = _cli(runner, "platform", platform, "--rpm", "1450")
    result = fc.platform(platform, rpm=1450)
    assert result.to_dict() == document and result.exit_code == code


def test_design_gives_the_document_of_design_json_but_its_clock(runner):
    """The search's own time (``grid.seconds``) is the run's; everything else is equal."""
    path = str(CONFIGS / "block_two_machines.toml")
    code, document = _cli(runner, "design", path, "--vary", "block.height=1.5:2.5", "--points", "3")
    result = fc.design(path, vary=["block.height=1.5:2.5"], points=3)
    mine = result.to_dict()
    for one in (mine, document):
        one["grid"]["seconds"] = None
    assert mine == document and result.exit_code == code


def test_a_sweep_gives_arrays():
    result = fc.sweep(str(CONFIGS / "frame_saw.toml"), speed=SPEED)
    points = result.to_dict()["points"]
    assert result.values.tolist() == [p["omega"] for p in points]
    assert result.columns["x_peak"].dtype.name == "float64"
    assert result.columns["status"].tolist() == [p["status"] for p in points]


def test_to_frame_is_a_data_frame_with_pandas():
    pandas = pytest.importorskip("pandas")
    frame = fc.sweep(str(CONFIGS / "frame_saw.toml"), speed=SPEED).to_frame()
    assert isinstance(frame, pandas.DataFrame) and len(frame) == 5


def test_to_frame_without_pandas_says_how_to_get_it(monkeypatch):
    monkeypatch.setitem(sys.modules, "pandas", None)  # import pandas then fails, installed or not
    result = fc.sweep(str(CONFIGS / "frame_saw.toml"), speed=SPEED)
    with pytest.raises(ImportError, match=r"foundation_calc\[frame\]"):
        result.to_frame()


def test_every_public_name_resolves():
    for name in fc.__all__:
        assert getattr(fc, name) is not None
    assert fc.SceneError is __import__("foundation_calc.errors").errors.SceneError
    with pytest.raises(AttributeError):
        fc.no_such_name  # noqa: B018


def test_the_python_api_page_runs(monkeypatch, capsys):
    """Every python block of docs/python-api.md runs as it stands, from the repository's root."""
    import re

    from tests.conftest import ROOT

    text = (ROOT / "docs" / "python-api.md").read_text(encoding="utf-8")
    blocks = re.findall(r"^```python\n(.*?)^```", text, re.S | re.M)
    assert blocks
    monkeypatch.chdir(ROOT)
    for block in blocks:
        exec(compile(block, "docs/python-api.md", "exec"), {})  # noqa: S102 - the page's own example
    assert "machines.0.mass - must be >= 0" in capsys.readouterr().out
