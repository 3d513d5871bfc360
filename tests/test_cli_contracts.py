"""Contracts of the command line that hostile surroundings test: a closed stdout, a terminal that
cannot encode a file name, a FIFO or an unreadable file among the scenes, a scene that lost its
kind line, an error asked for as JSON. Each ends in a documented exit code with a message."""

from __future__ import annotations

import json
import os
import subprocess
import sys
from pathlib import Path

import pytest

from foundation_calc.cli.app import app
from tests.conftest import CONFIGS

FRAME_SAW = CONFIGS / "frame_saw.toml"


def _fcalc(*args: str, **kwargs) -> subprocess.CompletedProcess:
    """``fcalc ARGS`` in a process of its own (what a shell runs), bounded in time."""
    code = "import sys; from foundation_calc.cli.app import main; sys.argv[0] = 'fcalc'; main()"
    return subprocess.run([sys.executable, "-c", code, *args], capture_output=True, timeout=60, **kwargs)


@pytest.mark.parametrize("json_flag", [[], ["--json"]])
def test_a_closed_stdout_is_exit_141_not_a_crash(json_flag):
    result = _fcalc("resonance", str(FRAME_SAW), *json_flag, stdout=None, pass_fds=(), preexec_fn=lambda: os.close(1))
    assert result.returncode == 141, result.stderr.decode()
    assert b"internal error" not in result.stderr and b"Traceback" not in result.stderr


def test_a_file_name_the_terminal_cannot_encode_is_escaped(tmp_path):
    name = os.fsdecode(b"saw\xff.toml")  # Latin-1 bytes in a UTF-8 system: undecodable
    (tmp_path / name).write_bytes(FRAME_SAW.read_bytes())
    (tmp_path / "a.toml").write_text('kind = "crank_foundation"\n')
    env = {**os.environ, "PYTHONIOENCODING": "utf-8"}  # strict, as on most terminals
    table = _fcalc("check", str(tmp_path), "--jobs", "1", env=env)
    assert table.returncode == 3, table.stderr.decode()
    assert b"saw\\udcff.toml" in table.stdout and b"a.toml" in table.stderr
    document = _fcalc("check", str(tmp_path), "--json", "--jobs", "1", env={**env, "PYTHONIOENCODING": "ascii"})
    assert document.returncode == 3, document.stderr.decode()
    assert json.loads(document.stdout)["scenes"][1]["source"].endswith(name)


def test_a_fifo_in_a_checked_folder_is_skipped_unopened(runner, tmp_path):
    (tmp_path / "saw.toml").write_bytes(FRAME_SAW.read_bytes())
    os.mkfifo(tmp_path / "pipe.toml")  # opening it would wait for a writer forever
    result = _fcalc("check", str(tmp_path), "--json")
    assert result.returncode == 0, result.stderr.decode()
    document = json.loads(result.stdout)
    assert [Path(s).name for s in document["skipped"]] == ["pipe.toml"]
    assert "not a regular file" in runner.invoke(app, ["check", str(tmp_path)]).stdout  # in-process: it no longer waits


def test_an_unreadable_file_is_an_invalid_scene(runner, tmp_path, monkeypatch):
    locked = tmp_path / "locked.toml"
    locked.write_bytes(FRAME_SAW.read_bytes())
    locked.chmod(0)
    if os.geteuid() == 0:  # root reads anything: refuse it as the kernel refuses any other user
        import builtins

        real_open, real_access = builtins.open, os.access

        def deny(path, *args, **kwargs):
            if os.fspath(path) == str(locked):
                raise PermissionError(13, "Permission denied", str(locked))
            return real_open(path, *args, **kwargs)

        monkeypatch.setattr(builtins, "open", deny)
        monkeypatch.setattr(os, "access", lambda path, mode, **k: os.fspath(path) != str(locked) and real_access(path, mode, **k))
    for command in ("resonance", "amplitudes", "soil", "runup", "report", "sweep", "platform"):
        options = ["--speed", "100:300:3"] if command == "sweep" else []
        result = runner.invoke(app, [command, str(locked), *options])
        assert result.exit_code == 3, (command, result.output)
        assert "cannot be read: Permission denied" in result.stderr
    assert runner.invoke(app, ["check", str(locked)]).exit_code == 3


@pytest.mark.parametrize(
    ("text", "tables"),
    [
        (FRAME_SAW.read_text().replace('kind = "crank_foundation"', ""), "[foundation]"),
        ((CONFIGS / "platform_paper_example.toml").read_text().replace('kind = "platform"', ""), "[platform]"),
        ("[block]\nlength = 4.0\n\n[[machines]]\nmass = 1e3\n", "[block]"),
    ],
    ids=["crank", "platform", "block"],
)
def test_a_scene_that_lost_its_kind_line_is_invalid_even_in_a_folder(runner, tmp_path, text, tables):
    assert "kind" not in text
    (tmp_path / "lost.toml").write_text(text)
    (tmp_path / "pyproject.toml").write_text('[project]\nname = "x"\n')
    for strict in ([], ["--strict"]):
        result = runner.invoke(app, ["check", str(tmp_path), *strict])
        assert result.exit_code == 3, result.output
        assert "kind" in result.stderr and tables in result.stderr and '"crank_foundation"' in result.stderr
    document = json.loads(runner.invoke(app, ["check", str(tmp_path), "--json"]).stdout)
    assert [Path(s).name for s in document["skipped"]] == ["pyproject.toml"]


def test_the_scene_tables_are_every_table_of_every_kind():
    from foundation_calc.scenes.kinds import KINDS, SCENE_TABLES, model_for_kind

    for kind in KINDS:  # [project] and [require] are also what an office file (fcalc.toml) holds: no scene
        assert set(model_for_kind(kind).model_fields) - {"kind", "schema_version", "name", "project", "require"} <= SCENE_TABLES


def test_an_empty_file_says_it_is_empty(runner, tmp_path):
    (tmp_path / "empty.toml").write_text("\n# nothing yet\n")
    result = runner.invoke(app, ["resonance", str(tmp_path / "empty.toml")])
    assert result.exit_code == 3 and "is empty" in result.stderr and "missing" not in result.stderr


INVALID = 'kind = "crank_foundation"\nname = "x"\n[foundation]\nmass = -1.0\n'


@pytest.mark.parametrize("command", ["resonance", "amplitudes", "soil", "runup", "sweep", "platform"])
def test_with_json_an_invalid_scene_is_one_json_document_of_its_error(runner, tmp_path, command):
    text = INVALID if command != "platform" else INVALID.replace("crank_foundation", "platform").replace("[foundation]", "[platform]")
    (tmp_path / "bad.toml").write_text(text)
    options = ["--speed", "100:300:3"] if command == "sweep" else []
    result = runner.invoke(app, [command, str(tmp_path / "bad.toml"), *options, "--json"])
    assert result.exit_code == 3, result.output
    document = json.loads(result.stdout)
    assert document["command"] == command and document["verdict"] == "invalid" and document["exit_code"] == 3
    field = "foundation.mass" if command != "platform" else "platform.mass"
    assert any(p["field"] == field for p in document["problems"]), document
    assert "error" in result.stderr  # the message is on stderr as without --json
