"""Messages and notes at 80 columns: on a terminal (a pseudo-terminal here) a refusal, a warning or
a long note wraps at words with a hanging indent, so that ``error:`` and the field stay on the
left; in a file or a pipe each problem is one line (scripts grep them), and no line of a table's
output ends in a space. Run as a user runs fcalc: a real process, a real terminal or pipe."""

from __future__ import annotations

import os
import subprocess
import sys

import pytest
from rich.cells import cell_len
from rich.console import Console

from foundation_calc.scenes import parse_scene, read_toml
from tests.conftest import CONFIGS, on_terminal

FCALC = (sys.executable, "-m", "foundation_calc")
ENV = {**os.environ, "COLUMNS": "80", "TERM": "dumb", "NO_COLOR": "1"}


def _on_terminal(*args: str) -> tuple[int, list[str]]:
    """Exit code and lines of ``fcalc args`` with stdout and stderr on one 80-column terminal."""
    process, shown = on_terminal((*FCALC, *args), env=ENV)
    return process.returncode, shown.splitlines()


def _recording_terminal(**kwargs) -> Console:
    """A console as fcalc's on an 80-column terminal (before its own classes), recording its text."""
    return Console(force_terminal=True, width=80, record=True, color_system=None, highlight=False, **kwargs)


def _piped(*args: str) -> subprocess.CompletedProcess:
    return subprocess.run((*FCALC, *args), capture_output=True, text=True, env=ENV, check=False)


def _paragraph(lines: list[str], start: str) -> list[str]:
    """The line that starts with ``start`` and the lines after it that are indented deeper than
    it (its continuation on a terminal)."""
    first = next(i for i, line in enumerate(lines) if line.startswith(start))
    lead = len(start) - len(start.lstrip())
    rest = []
    for line in lines[first + 1:]:
        if len(line) - len(line.lstrip()) <= lead:
            break
        rest.append(line)
    return [lines[first], *rest]


def _hangs(lines: list[str], start: str, indent: int, whole: str) -> None:
    """The paragraph at ``start`` fits 80 columns, each line after its first ``indent`` cells in,
    and says ``whole`` (the one line of a pipe) word for word."""
    paragraph = _paragraph(lines, start)
    assert len(paragraph) > 1, paragraph  # long enough to wrap at 80
    assert all(cell_len(line) <= 80 for line in paragraph), paragraph
    assert all(line.startswith(" " * indent) and line[indent] != " " for line in paragraph[1:]), paragraph
    assert " ".join(paragraph).split() == whole.split()


def test_a_refusal_wraps_with_a_hanging_indent_on_a_terminal():
    """``fcalc design`` refuses a block on isolators in a 240-character line: on a terminal it
    wraps under the field (7 cells, after ``error: ``), in a pipe it stays one line."""
    args = ("design", str(CONFIGS / "block_on_isolators.toml"), "--vary", "block.length=2:3")
    piped = _piped(*args)
    assert piped.returncode == 3
    [line] = piped.stderr.splitlines()  # one line per problem, for grep
    assert line.startswith("error: isolators: ") and len(line) > 200
    code, lines = _on_terminal(*args)
    assert code == 3
    _hangs(lines, "error: isolators: ", len("error: "), line)


@pytest.fixture
def terminal(monkeypatch):
    """fcalc's stderr console as on an 80-column terminal, recording what it prints."""
    from foundation_calc.output import console

    term = _recording_terminal(stderr=True)
    monkeypatch.setattr(console, "stderr", lambda: term)
    return term


def test_scene_problems_and_warnings_wrap_under_their_field_on_a_terminal(terminal):
    """A misspelt key (refused) and a block's length typed in mm (a warning), each longer than 80
    columns, as ``fcalc check`` prints them (the same functions as every command)."""
    from foundation_calc.cli.guard import print_warnings, report_error
    from foundation_calc.errors import SceneError

    saw = read_toml(CONFIGS / "frame_saw.toml")
    saw["foundation"]["masss"] = saw["foundation"].pop("mass")
    with pytest.raises(SceneError) as refused:
        parse_scene(saw, source="misspelt.toml")
    block = read_toml(CONFIGS / "block_two_machines.toml")
    block["block"]["length"] = 7000.0  # a 7 m block in mm
    warnings = parse_scene(block, source="in_mm.toml").plausibility_warnings()
    report_error(refused.value)
    print_warnings(warnings, "in_mm.toml")
    lines = terminal.export_text().splitlines()
    assert lines[0] == "error: invalid scene misspelt.toml"
    [(field, message)] = refused.value.problems
    assert field == "foundation.masss"
    _hangs(lines, "  foundation.masss: ", len("    "), f"  {field}: {message}")
    [warning] = warnings
    assert "block.length = 7000 m" in warning
    _hangs(lines, "warning: in_mm.toml: ", len("warning: "), f"warning: in_mm.toml: {warning}")


@pytest.mark.parametrize(
    "args",
    [
        ("resonance", "frame_saw.toml"),
        ("amplitudes", "compressor_damped_near_resonance.toml"),
        ("amplitudes", "block_two_machines.toml"),
        ("soil", "compressor_medium_sand_lysmer.toml"),
        ("sweep", "frame_saw.toml", "--speed", "150:300:7"),
        ("check", "frame_saw.toml"),
        ("platform",),
    ],
    ids=" ".join,
)
def test_no_line_of_a_file_ends_in_a_space(runner, args):
    """Rich pads a table's title to the table's width; in a file or a pipe fcalc ends every line
    at its last character, with the same text (the JSON is printed apart and is untouched)."""
    from foundation_calc.cli.app import app

    command, *rest = args
    rest = [str(CONFIGS / a) if a.endswith(".toml") else a for a in rest]
    result = runner.invoke(app, [command, *rest])
    assert result.exit_code in (0, 1), result.stderr
    padded = [line for line in result.stdout.splitlines() if line != line.rstrip()]
    assert not padded, padded


@pytest.mark.parametrize("config", ["compressor_damped_near_resonance.toml"])
def test_a_crank_s_damped_amplitudes_note_hangs_at_80_columns(config):
    """The damped crank's note of its base dashpots and damped modes (over 200 characters, one line
    in a file) wraps on an 80-column terminal under its own name, and every line of the output fits."""
    code, lines = _on_terminal("amplitudes", str(CONFIGS / config))
    assert code in (0, 1)  # 1: the compressor is inside its resonance band
    assert all(cell_len(line) <= 80 for line in lines), [line for line in lines if cell_len(line) > 80]
    paragraph = _paragraph(lines, "  damped (base dashpots C_x = ")
    words = " ".join(paragraph).split()
    _hangs(lines, "  damped (base dashpots C_x = ", len("    "), " ".join(words))
    assert "modes of the averaged operator:" in " ".join(words) and words[-3:-1] == ["ζ", "="]


def test_fcalc_check_s_skipped_line_hangs_at_80_columns(runner, tmp_path, monkeypatch):
    """``fcalc check`` of frame_saw.toml beside a TOML file that is not a scene: its skipped line
    (the file's name and why) wraps under its text on a terminal; the summary follows."""
    from foundation_calc.cli.app import app
    from foundation_calc.output import check_report

    (tmp_path / "frame_saw.toml").write_bytes((CONFIGS / "frame_saw.toml").read_bytes())
    name = "a_tool_s_settings_with_a_long_name_beside_the_scenes.toml"
    (tmp_path / name).write_text("[tool]\nline_length = 100\n")
    term = _recording_terminal()
    monkeypatch.setattr(check_report, "stdout", lambda: term)
    monkeypatch.chdir(tmp_path)
    result = runner.invoke(app, ["check", ".", "--strict"])
    assert result.exit_code == 0, result.stderr
    lines = term.export_text().splitlines()
    _hangs(lines, "skipped: ", len("skipped: "), f"skipped: {name} (TOML without a kind or a scene table, not a scene)")
    assert lines[-1] == "1 scene: 1 pass (2 checks: 2 pass); warnings fail (--strict); exit code 0"


def test_fcalc_sweep_s_limits_line_wraps_at_80_columns(runner, monkeypatch):
    """The sweep's closing line of limits and detuning (110 characters for frame_saw.toml) wrapped
    only where the terminal cut it: it wraps at words, under its own text."""
    from foundation_calc.cli.app import app
    from foundation_calc.output import sweep as sweep_report

    term = _recording_terminal()
    monkeypatch.setattr(sweep_report, "stdout", lambda: term)
    result = runner.invoke(app, ["sweep", str(CONFIGS / "frame_saw.toml"), "--speed", "150:300:7"])
    assert result.exit_code == 0, result.stderr
    lines = term.export_text().splitlines()
    whole = "limits (x, y of C and of every point): displacement 0.0002 m; [limits] detuning = 0.2 (docs/resonance-rule.md)"
    _hangs(lines, "limits (x, y of C ", 2, whole)
