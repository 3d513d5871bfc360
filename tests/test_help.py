"""Help text is read as written: units in square brackets and TOML table names survive, and
flags that take no value do not advertise one."""

from __future__ import annotations

import pytest

from foundation_calc.cli.app import app


@pytest.mark.parametrize(
    ("command", "fragments"),
    [
        (["platform"], ("Required circular amplitude u [m]", "Speed [rad/s]", "Speed [Hz]")),
        (["amplitudes"], ("[[points]]", "[limits]")),
        (["--help"], ("141",)),
    ],
)
def test_brackets_survive_in_help(runner, command, fragments):
    result = runner.invoke(app, [*command, "--help"] if command != ["--help"] else command, env={"COLUMNS": "200"})
    assert result.exit_code == 0
    for fragment in fragments:
        assert fragment in result.output


@pytest.mark.parametrize("command", [[], ["platform"], ["check"], ["resonance"]])
def test_flags_without_values_show_none(runner, command):
    result = runner.invoke(app, [*command, "--help"], env={"COLUMNS": "200"})
    assert "<bool>" not in result.output


def _helps(runner):
    """``fcalc --help`` and every command's ``--help``, at 100 columns."""
    from foundation_calc.cli.app import COMMANDS

    yield "fcalc", runner.invoke(app, ["--help"], env={"COLUMNS": "100"}).output
    for name in COMMANDS:
        yield name, runner.invoke(app, [name, "--help"], env={"COLUMNS": "100"}).output


def test_help_reads_as_written_for_an_engineer(runner):
    """No type names of the library (<list[Path]>, <int range>, <float>), no {braces} around
    required arguments, no x>=1 ranges, and the exit codes once per page."""
    import re

    for name, text in _helps(runner):
        assert text.count("Exit codes:") == 1, name
        assert not re.search(r"<[a-z][^>]*>", text), (name, re.findall(r"<[a-z][^>]*>", text))
        usage = text.splitlines()[0]
        assert "{" not in usage and "}" not in usage, usage
        assert "x>=" not in text and "x<=" not in text, name
    texts = dict(_helps(runner))
    assert texts["resonance"].splitlines()[0] == "Usage: fcalc resonance [OPTIONS] SCENE"
    assert texts["check"].splitlines()[0] == "Usage: fcalc check [OPTIONS] PATH..."
    assert texts["platform"].splitlines()[0] == "Usage: fcalc platform [OPTIONS] [SCENE]"
    assert "--jobs N" in texts["check"] and "at least 1" in texts["check"]
