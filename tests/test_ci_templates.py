"""The pre-commit hook and the CI templates in docs/ci run the commands they say, and those
commands do what the templates rely on: the verdict in the exit code, the JUnit report and the
sheets written where the artifacts are collected."""

from __future__ import annotations

import re
import shlex
import shutil
import xml.etree.ElementTree as ET

import pytest
from typer.testing import CliRunner

from foundation_calc.cli.app import app
from tests.conftest import CONFIGS, ROOT

HOOKS = ROOT / ".pre-commit-hooks.yaml"
TEMPLATES = sorted((ROOT / "docs" / "ci").glob("*.yml"))


def _hook_command() -> list[str]:
    """The hook's ``entry`` and ``args`` as pre-commit runs them (``pass_filenames: false``)."""
    text = HOOKS.read_text(encoding="utf-8")
    entry = re.search(r"^  entry: (.+)$", text, re.M).group(1)
    args = re.search(r"^  args: \[(.*)\]$", text, re.M).group(1)
    assert re.search(r"^  pass_filenames: false$", text, re.M)
    return shlex.split(entry) + [a.strip().strip('"') for a in args.split(",") if a.strip()]


def _run(command: list[str], cwd, monkeypatch):
    assert command[0] == "fcalc"
    monkeypatch.chdir(cwd)
    return CliRunner().invoke(app, command[1:])


def test_the_hook_checks_the_repository_and_passes_over_other_toml(tmp_path, monkeypatch):
    shutil.copy(CONFIGS / "crank_press.toml", tmp_path / "press.toml")
    (tmp_path / "pyproject.toml").write_text("[project]\nname = 'x'\n", encoding="utf-8")
    assert _run(_hook_command(), tmp_path, monkeypatch).exit_code == 0
    shutil.copy(CONFIGS / "frame_saw_over_amplitude_limit.toml", tmp_path / "over.toml")
    assert _run(_hook_command(), tmp_path, monkeypatch).exit_code == 1  # the commit is stopped


@pytest.mark.parametrize("template", TEMPLATES, ids=lambda p: p.name)
def test_a_ci_template_writes_the_report_and_the_sheets_it_keeps(template, tmp_path, monkeypatch):
    text = template.read_text(encoding="utf-8")
    (line,) = re.findall(r"^\s*(?:- run: |- )?(fcalc .+)$", text, re.M)
    command = shlex.split(line)
    (tmp_path / "scenes").mkdir()
    shutil.copy(CONFIGS / "crank_press.toml", tmp_path / "scenes")
    result = _run(command, tmp_path, monkeypatch)
    assert result.exit_code == 0, result.output
    junit = command[command.index("--junit") + 1]
    sheets = command[command.index("--report-dir") + 1]
    assert ET.parse(tmp_path / junit).getroot().get("tests") == "2"
    assert [p.name for p in (tmp_path / sheets).iterdir()] == ["crank_press.pdf"]
    assert junit in text and f"{sheets}/" in text  # collected as artifacts
