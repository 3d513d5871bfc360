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
