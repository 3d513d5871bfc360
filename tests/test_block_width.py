"""Every command on every shipped block scene reads at 80 columns: no line of its tables and text is
wider than a terminal of 80 columns, and no number is cut to fit (the console never cuts a word:
:func:`foundation_calc.output.console.keep_words_whole`; a table that cannot fit runs past the
edge, which this test catches).

In process, as a terminal of 80 columns shows it: the results console (cached) is rebuilt at that
width for the module's tests. The slow commands take their fast paths: a short sweep, a run-up of
1 s each way, a design over 2 × 2 candidates (the tables' shapes do not depend on their lengths).
"""

from __future__ import annotations

import pytest
from rich.cells import cell_len

from foundation_calc.scenes.files import read_toml

from foundation_calc.cli.app import app
from foundation_calc.output import console
from tests.conftest import configs_of_kind

WIDTH = 80
BLOCKS = configs_of_kind("block_foundation")
COMMANDS = {
    "resonance": (),
    "amplitudes": (),
    "check": (),
    "soil": (),
    "sweep": ("--speed", "300:1500:5", "--machine", "{machine}"),
    "runup": ("--time", "1", "--down", "1"),
    "design": ("--vary", "block.length=4:8", "--vary", "block.width=3:6", "--points", "2"),
}


@pytest.fixture(scope="module")
def terminal():
    """The results console at :data:`WIDTH` columns, as on a terminal that wide (the messages'
    console made meanwhile is dropped after, so that a later test's warnings are one line)."""
    with pytest.MonkeyPatch.context() as patch:
        patch.setattr(console, "UNLIMITED_WIDTH", WIDTH)
        console.stdout.cache_clear()
        console.stderr.cache_clear()
        yield
    console.stdout.cache_clear()
    console.stderr.cache_clear()


def test_the_shipped_block_scenes_are_found():
    assert len(BLOCKS) >= 5


@pytest.mark.parametrize("command", COMMANDS)
@pytest.mark.parametrize("config", BLOCKS, ids=lambda p: p.stem)
def test_every_line_fits_80_columns(terminal, runner, command, config):
    scene = read_toml(config)
    machine = scene["machines"][0]["name"]
    result = runner.invoke(app, [command, str(config), *(a.format(machine=machine) for a in COMMANDS[command])])
    refused = command == "design" and "isolators" in scene  # by name, exit 3 (tests/test_block_isolators.py)
    assert result.exit_code in ((3,) if refused else (0, 1)), result.output
    wide = [line for line in result.stdout.splitlines() if cell_len(line) > WIDTH]
    assert not wide, f"{len(wide)} lines wider than {WIDTH}:\n" + "\n".join(wide[:8])
    assert "…" not in result.stdout


def test_check_on_a_narrow_terminal_puts_each_reason_under_its_row(terminal, runner):
    """Beside a scene column as wide as its file's name the reasons had some 17 cells at 80 columns
    (then a table per scene, some 55): each row is now a line, its scene's name first, and its
    reason follows under it, four cells in, across the terminal's width (docs/ci.md)."""
    result = runner.invoke(app, ["check", str(BLOCKS[0]), str(BLOCKS[1])])
    lines = [line.rstrip() for line in result.stdout.splitlines()]
    assert lines[1].split() == ["scene", "check", "verdict"]
    rows = [line for line in lines if line.startswith((BLOCKS[0].name, BLOCKS[1].name))]
    assert {row.split()[0] for row in rows} == {BLOCKS[0].name, BLOCKS[1].name}
    reasons = [line for line in lines if line.startswith("    ") and line[4] != " "]
    assert len(reasons) == len(rows) and max(map(cell_len, reasons)) > 60


#: The crank scenes whose block a design may vary (a [foundation.block]; on piles: tests/test_crank_piles_design.py,
#: over the pile length too).
SIZED_CRANKS = [p for p in configs_of_kind("crank_foundation")
                if "block" in read_toml(p)["foundation"] and "piles" not in read_toml(p)]


def test_a_crank_scene_to_size_is_shipped():
    assert SIZED_CRANKS


@pytest.mark.parametrize("config", SIZED_CRANKS, ids=lambda p: p.stem)
def test_a_crank_design_fits_80_columns(terminal, runner, config):
    """The design of a crank scene over two sizes: its verdict table, its Pareto set (the sizes'
    long keys foundation.block.length, ...) and why cheaper candidates fail, within 80 columns."""
    result = runner.invoke(app, ["design", str(config), "--vary", "block.length=1:8", "--vary", "block.width=1:6",
                                 "--points", "3"])
    assert result.exit_code in (0, 1), result.output
    assert "Pareto set" in result.stdout
    assert "[m³]" in result.stdout and "[t]" in result.stdout  # the headers' units are text, not markup
    wide = [line for line in result.stdout.splitlines() if cell_len(line) > WIDTH]
    assert not wide, f"{len(wide)} lines wider than {WIDTH}:\n" + "\n".join(wide[:8])
    assert "…" not in result.stdout
