"""Output that keeps every number whole, at any width, on a terminal or in a file, and exits
141 when its reader closes the pipe. Run as a user runs fcalc: a real process, a real pipe."""

from __future__ import annotations

import json
import os
import subprocess
import sys

import pytest
from rich.console import Console
from rich.table import Table

from foundation_calc.output.console import keep_words_whole
from tests.conftest import CONFIGS

FCALC = (sys.executable, "-m", "foundation_calc")


def _run(*args: str, columns: int) -> subprocess.CompletedProcess:
    env = {**os.environ, "COLUMNS": str(columns)}
    return subprocess.run((*FCALC, *args), capture_output=True, text=True, env=env, check=False)


@pytest.mark.parametrize("columns", [40, 80, 132])
def test_no_number_is_cut_in_a_file(columns):
    result = _run("amplitudes", str(CONFIGS / "frame_saw.toml"), "--exact", columns=columns)
    assert result.returncode == 0, result.stderr
    assert "…" not in result.stdout
    document = json.loads(_run("amplitudes", str(CONFIGS / "frame_saw.toml"), "--exact", "--json", columns=columns).stdout)
    x1 = document["approximations"]["exact"]["harmonics"]["x1"]["sin"]
    assert f"{x1:.6g}" in result.stdout and "e-05" in f"{x1:.6g}"  # whole, with its exponent


def test_check_of_every_config_cuts_nothing_in_a_file():
    result = _run("check", str(CONFIGS), columns=80)
    assert result.returncode in (0, 1), result.stderr
    assert "…" not in result.stdout


@pytest.mark.parametrize("width", [20, 40, 80])
def test_a_narrow_terminal_wraps_words_and_never_cuts_them(width):
    table = Table("quantity", "value")
    table.add_row("a long description of a derived quantity", "-7.15432e-05")
    table.add_row("another", "123456789.123")
    console = Console(width=width, force_terminal=True, record=True, color_system=None)
    keep_words_whole(table)
    console.print(table, crop=False)  # as stdout() prints: the terminal wraps a long line
    text = console.export_text()
    assert "…" not in text
    assert "-7.15432e-05" in text and "123456789.123" in text and "description" in text


def test_a_table_whose_words_fit_is_levelled_to_the_terminal():
    """Rich narrows the widest columns first and stops at a column's longest word, so this row ran
    to 82 cells at 80 although its words fit: fit_columns levels the columns to what fits."""
    from rich.cells import cell_len

    from foundation_calc.output.console import fit_columns

    table = Table("machine", "order", "mode", "critical, rad/s", "margin", "needs", "forcing share", "status")
    table.add_row("opposed compressor", "1", "3 (z)", "181.99", "71.2%", "20%", "0.000305", "not judged")
    console = Console(width=80, record=True, color_system=None)
    keep_words_whole(table)
    fit_columns(table, 80)
    console.print(table, crop=False)
    text = console.export_text()
    assert max(map(cell_len, text.splitlines())) <= 80
    assert "0.000305" in text and "181.99" in text and "compressor" in text


@pytest.mark.parametrize(
    "args",
    [("check", str(CONFIGS)), ("platform",), ("resonance", str(CONFIGS / "frame_saw.toml")), ("check", str(CONFIGS), "--json")],
    ids=lambda a: " ".join(a[:1] + a[2:]),
)
def test_a_closed_pipe_exits_141(args):
    """`fcalc ... | true` in a real pipe: the reader has left before fcalc writes.

    (A reader that leaves after one line, as `head -1`, races the writer: output that fits in the
    pipe's buffer in one write is delivered whole, and the writer never sees the closed pipe.)
    """
    producer = subprocess.Popen((*FCALC, *args), stdout=subprocess.PIPE, stderr=subprocess.PIPE)
    producer.stdout.close()
    _, err = producer.communicate(timeout=60)
    assert producer.returncode == 141, err.decode()
    assert b"Traceback" not in err


def test_round_off_prints_as_zero(runner):
    """The paper's design rocks by 1e-18 % of u (round-off of the 6-DOF solve): the table says 0,
    the JSON keeps the computed number."""
    from foundation_calc.cli.app import app

    table = runner.invoke(app, ["platform"]).stdout
    rows = {line.split("│")[1].strip(): line.split("│")[2].strip() for line in table.splitlines() if line.count("│") == 4}
    for quantity in ("amplitude of z", "rotation amplitude α", "static corner offset from the tilt",
                     "rocking: corner motion relative to the centre of mass"):
        assert rows[quantity] == "0", (quantity, rows[quantity])
    assert rows["amplitude of x"] == "0.001"
    document = json.loads(runner.invoke(app, ["platform", "--json"]).stdout)
    assert 0 <= document["verification"]["rocking_percent"] < 1e-9
