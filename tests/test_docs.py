"""The README's examples do what the README says.

Every fenced ```sh block: each line that starts with ``fcalc`` is run (in a scratch folder that
sees the shipped ``configs/``) and its exit code compared with the documented one: the ``N`` of a
trailing ``echo $?   # N: ...``, else 0. Every fenced ```toml block that is a whole scene (it has a
``kind`` line) is written to a file and checked with ``fcalc check``; the sentence after the block
states its exit code as "`fcalc check` on this block exits N".
"""

from __future__ import annotations

import re
import shlex

import pytest

from tests.conftest import CONFIGS, ROOT

README = (ROOT / "README.md").read_text()
BLOCKS = re.findall(r"^```(\w*)\n(.*?)^```\n(.*?)(?=\n\n|\Z)", README, re.S | re.M)

#: Lines left out, for their cost: the calculation sheets (`fcalc report`, and `fcalc check
#: --report-dir` that typesets one PDF per shipped scene) are typeset by tests/test_report.py.
COSTLY = ("fcalc report", "--report-dir")


def _commands():
    for lang, body, _ in BLOCKS:
        if lang != "sh":
            continue
        for line in body.splitlines():
            if not line.startswith("fcalc ") and line.strip() != "fcalc" and not line.startswith("fcalc\t"):
                continue
            command, _, comment = line.partition("#")
            documented = 0
            if "echo $?" in command:
                command = command.split(";")[0]
                documented = int(re.match(r"\s*(\d+)", comment).group(1))
            if not any(part in command for part in COSTLY):
                yield command.strip(), documented


COMMANDS = list(_commands())
SCENES = [(body, after) for lang, body, after in BLOCKS if lang == "toml" and re.search(r"^kind = ", body, re.M)]


def test_the_readme_has_examples_to_run():
    assert len(COMMANDS) >= 6 and len(SCENES) >= 2


@pytest.mark.parametrize("command, documented", COMMANDS, ids=[c for c, _ in COMMANDS])
def test_shell_example_exits_as_documented(command, documented, runner, tmp_path, monkeypatch):
    from foundation_calc.cli.app import app

    (tmp_path / "configs").symlink_to(CONFIGS)
    monkeypatch.chdir(tmp_path)
    result = runner.invoke(app, shlex.split(command)[1:])
    assert result.exit_code == documented, result.output


@pytest.mark.parametrize("body, after", SCENES, ids=[re.search(r'kind = "(\w+)"', b).group(1) for b, _ in SCENES])
def test_scene_block_checks_as_documented(body, after, runner, tmp_path):
    from foundation_calc.cli.app import app

    stated = re.search(r"`fcalc check` on this block exits (\d)", after)
    assert stated, "the sentence after a scene block states what `fcalc check` does with it"
    scene = tmp_path / "scene.toml"
    scene.write_text(body)
    result = runner.invoke(app, ["check", str(scene)])
    assert result.exit_code == int(stated.group(1)), result.output
