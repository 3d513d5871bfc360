"""Every command reads well in an 80-column terminal: a sweep's row takes one or two lines (its
status compact, a legend under the table), a soil's prose wraps at words under its own start, and
no line is wider than the terminal. In a file or a pipe the output is as it was: each row one
line with its status in full (scripts grep them). Run in-process on fcalc's own console class,
made as on an 80-column terminal (small sweeps: a few seconds in all)."""

from __future__ import annotations

import json

import pytest
from rich.cells import cell_len

from tests.conftest import CONFIGS

WIDTH = 80


def _run(runner, *args: str) -> str:
    """stdout of ``fcalc args`` in a file or a pipe (CliRunner's stdout: unlimited width)."""
    from foundation_calc.cli.app import app

    result = runner.invoke(app, [str(CONFIGS / a) if a.endswith(".toml") else a for a in args])
    assert result.exit_code in (0, 1), result.output
    return result.stdout


@pytest.fixture
def on_terminal(runner, monkeypatch):
    """The lines of ``fcalc args`` as fcalc's own stdout console shows them on an 80-column
    terminal (fitted tables, words kept whole): every output module, in subpackages too, prints to
    it (each imported first, so that none keeps the test's console after it)."""
    import importlib
    import pkgutil

    from foundation_calc import output
    from foundation_calc.output import console

    modules = [importlib.import_module(m.name) for m in pkgutil.walk_packages(output.__path__, f"{output.__name__}.")]
    printing = [m for m in modules if getattr(m, "stdout", None) is console.stdout]

    def run(*args: str) -> list[str]:
        term = console._console_class()(False, force_terminal=True, width=WIDTH, record=True, color_system=None,
                                        emoji=False)
        with monkeypatch.context() as patched:
            for module in printing:
                patched.setattr(module, "stdout", lambda: term)
            _run(runner, *args)
        return term.export_text().splitlines()

    return run


def _rows(lines: list[str]) -> list[list[str]]:
    """The body rows of the tables in ``lines``, each the terminal lines it takes: a row starts
    where its first cell is not blank, its other lines leave that cell blank."""
    rows: list[list[str]] = []
    inside = False
    for line in lines:
        if "│" not in line:
            inside = False
            continue
        cells = line.split("│")
        first = (cells[1] if line.startswith("│") else cells[0]).strip()  # a table with or without its edge
        if first or not inside:
            rows.append([line])
        else:
            rows[-1].append(line)
        inside = True
    return rows


SWEEPS = [
    ("sweep", "frame_saw.toml", "--speed", "100:600:11"),
    ("sweep", "frame_saw.toml", "--soil", "0.5:1.5:5"),
    ("sweep", "compressor_damped_near_resonance.toml", "--speed", "100:600:6"),
    ("sweep", "vertical_compressor.toml", "--speed", "100:600:6"),
    ("sweep", "block_two_machines.toml", "--machine", "compressor", "--speed", "100:3000:5"),
    ("sweep", "block_opposed_compressor.toml", "--speed", "100:3000:8"),  # two limits exceeded and a resonance
    ("sweep", "block_two_machines.toml", "--soil", "0.5:2:5"),  # a block's soil sweep: the same status table
]


@pytest.mark.parametrize("args", SWEEPS, ids=" ".join)
def test_a_sweep_row_takes_at_most_two_lines_at_80_columns(runner, on_terminal, args):
    """Before, the status column ("pass: resonances clear, governing 3ω = p1 at 72.4% (needs
    20%)") wrapped each row to 4 lines (frame_saw.toml) at 80 columns; now a compact status, the
    full wording in a pipe (the same run's stdout here, unlimited width), as the legend says."""
    lines = on_terminal(*args)
    piped = _run(runner, *args)
    assert all(cell_len(line) <= WIDTH for line in lines), [line for line in lines if cell_len(line) > WIDTH]
    rows = _rows(lines)
    assert len(rows) >= 5
    assert all(len(row) <= 2 for row in rows), [row for row in rows if len(row) > 2]
    legend = " ".join(lines[lines.index(next(line for line in lines if line.startswith("status: verdict"))):])
    assert "Full words: --json, --csv or a " in " ".join(legend.split())
    assert "resonances clear, governing" in piped or "inside" in piped  # the full wording stays in a pipe
    assert "Full words:" not in piped


def test_a_sweep_in_a_pipe_keeps_its_full_status_on_one_line(runner):
    """The same sweep through a pipe (unlimited width): one line a row, the status in its words."""
    piped = _run(runner, "sweep", "frame_saw.toml", "--speed", "100:200:3").splitlines()
    assert any(line.startswith("│         100 │") and "pass: resonances clear, governing 3ω = p1 at 72.4% (needs 20%)" in line
               for line in piped), piped
    assert all(len(row) == 1 for row in _rows(piped))


def test_the_compact_status_keeps_every_cause_in_order():
    """The compact status says what the full one says: the verdict, the limits exceeded (u, v, a
    and their RMS), the governing condition with its margin / the margin it needs."""
    from foundation_calc.checks.sweep.status import status_text

    assert status_text("fail", "motor: ω = mode 1 (y)", 0.309, 0.2, "clear", ["displacement", "velocity_rms"],
                       compact=True) == "fail over u, v_rms; motor: ω=mode 1 (y) 30.9%/20%"
    assert status_text("fail", "3ω = p1", 0.157, 0.2, "fail", ["displacement"], compact=True) == \
        "fail over u; 3ω=p1 15.7%/20%"
    assert status_text("warn", "ω = p1", 0.05, 0.2, "warn", [], compact=True) == "warn ω=p1 5.0%/20%"
    assert status_text("resonant", None, 0.0, 0.0, "clear", [], compact=True) == "resonant"


def _paragraph(lines: list[str], start: str) -> list[str]:
    first = next(i for i, line in enumerate(lines) if line.startswith(start))
    rest = []
    for line in lines[first + 1:]:
        if not line.startswith("  ") or line.startswith("  │"):
            break
        rest.append(line)
    return [lines[first], *rest]


@pytest.mark.parametrize("config", ["compressor_medium_sand_lysmer.toml", "frame_saw.toml"])
def test_fcalc_soil_s_prose_wraps_at_words_at_80_columns(runner, on_terminal, config):
    """``fcalc soil`` of a crank scene on a footing printed its closing paragraph (200 characters)
    and its notes as one line each, which the terminal cut inside words: now they wrap at words,
    under their own text, and every line fits; in a pipe each stays one line."""
    lines = on_terminal("soil", config)
    piped = _run(runner, "soil", config).splitlines()
    assert all(cell_len(line) <= WIDTH for line in lines), [line for line in lines if cell_len(line) > WIDTH]
    for start in ("Frequencies of a frequency-dependent method", "note: "):
        if not any(line.startswith(start) for line in piped):
            continue
        [whole] = [line for line in piped if line.startswith(start)]
        paragraph = _paragraph(lines, start)
        assert len(paragraph) > 1 and cell_len(whole) > WIDTH, paragraph
        assert " ".join(paragraph).split() == whole.split()


def test_a_table_whose_words_are_wider_than_80_columns_drops_its_frame(on_terminal):
    """The limits table of ``fcalc amplitudes`` on compressor_vendor_loads.toml: its longest words
    and numbers with the frame took 83 columns and ran past an 80-column terminal; without its
    outer frame and edge padding it fits, its words whole."""
    lines = on_terminal("amplitudes", "compressor_vendor_loads.toml")
    assert all(cell_len(line) <= WIDTH for line in lines), [line for line in lines if cell_len(line) > WIDTH]
    assert any(line.startswith("crankshaft") and "PASS" in line for line in lines)  # a row of the frameless table


def test_fcalc_validate_gives_each_case_two_or_three_lines_at_80_columns(on_terminal, runner):
    """The validation record's table left its case column 17 cells at 80 columns, so a case took
    up to 7 lines; now each case's words are a line over its numbers, each wrapped at words
    under its start: at most 3 lines a case, none wider than 80. In a pipe it is the table."""
    import re

    lines = on_terminal("validate")
    assert all(cell_len(line) <= WIDTH for line in lines), [line for line in lines if cell_len(line) > WIDTH]
    starts = [i for i, line in enumerate(lines) if re.match(r" {0,2}\d{1,3}  \S", line)]
    cases = len(json.loads(_run(runner, "validate", "--json"))["cases"])
    assert [int(lines[i].split()[0]) for i in starts] == list(range(1, cases + 1))
    ends = [*starts[1:], next(i for i, line in enumerate(lines) if line.endswith(" pass, 0 fail"))]
    taken = [1 + len([line for line in lines[a + 1:b] if line.startswith(" " * 5)]) for a, b in zip(starts, ends)]  # headings apart
    assert max(taken) <= 3, taken
    assert "│" in _run(runner, "validate")  # a file or a pipe keeps the table


def test_a_refused_option_hangs_under_error_on_a_terminal():
    """``fcalc design --vary`` on a scene without a block: typer's usage error (exit 2) wrote its
    230-character ``Error: ...`` line whole, and the terminal cut it inside words; now it wraps
    under its text on a terminal and stays one line in a pipe (a real process on a pty)."""
    from tests.test_message_width import _hangs, _on_terminal, _piped

    args = ("design", str(CONFIGS / "frame_saw.toml"), "--vary", "block.length=3:8", "--points", "6")
    piped = _piped(*args)
    assert piped.returncode == 2
    [line] = [line for line in piped.stderr.splitlines() if line.startswith("Error: ")]
    assert line.startswith("Error: Invalid value for '--vary': ") and len(line) > 200
    code, lines = _on_terminal(*args)
    assert code == 2
    assert lines[0].startswith("Usage: ") and lines[1].startswith("Try ")
    _hangs(lines, "Error: ", len("Error: "), line)


def _segment(lines: list[str], title: str) -> list[str]:
    """The lines of the table titled ``title`` (its title on one line or more, head and body) among ``lines``."""
    def framed(line: str) -> bool:
        return any(mark in line for mark in "│┃━┏")

    first = next(i for i, line in enumerate(lines) if line.strip().startswith(title))  # a title left or centred
    head = next(i for i in range(first + 1, len(lines)) if framed(lines[i]))
    end = next((i for i in range(head, len(lines)) if not framed(lines[i])), len(lines))
    return lines[first:end]


CHECKED = ("frame_saw.toml", "crank_press.toml", "block_on_piles.toml")  # a fail, an office row of 300 characters


def test_fcalc_check_gives_each_reason_the_terminal_s_width(runner, on_terminal):
    """``fcalc check`` at 80 columns put the reasons (150-300 characters) in a 30-cell column, 4-8
    lines a row; now, where a reason would take more than two lines of its column, each row is a
    line (scene, check, verdict) and its reason follows, whole, across the terminal's width: at
    most 1 + ⌈reason / 72⌉ lines a row (72: the 80 cells less the hanging indent of 6 and 2 for
    a line broken at a word), every word of the reason in order. In a pipe: the table."""
    lines = on_terminal("check", "--jobs", "1", *CHECKED)
    assert all(cell_len(line) <= WIDTH for line in lines), [line for line in lines if cell_len(line) > WIDTH]
    document = json.loads(_run(runner, "check", "--jobs", "1", "--json", *CHECKED))
    rows = [(entry["source"].rsplit("/", 1)[-1], c["check"], c["reason"]) for entry in document["scenes"] for c in entry["checks"]]
    bound = [1 + -(-cell_len(reason) // 72) for *_, reason in rows]
    assert len(lines) <= 3 + sum(bound), (len(lines), 3 + sum(bound))  # a title, a head, the rows, the counts
    starts = [next(i for i, line in enumerate(lines) if line.replace("│", " ").split()[:2] == [scene, check])
              for scene, check, _ in rows]
    ends = [*starts[1:], next(i for i, line in enumerate(lines) if " scenes: " in line)]
    for (scene, check, reason), most, a, b in zip(rows, bound, starts, ends):
        assert b - a <= most, (scene, check, lines[a:b])
        assert " ".join(lines[a + 1:b]).split() == reason.split(), (scene, check, lines[a:b])
    piped = _run(runner, "check", "--jobs", "1", *CHECKED)
    assert all(len(row) == 1 for row in _rows(piped.splitlines()))  # a file or a pipe: the table, a line a row


@pytest.mark.parametrize("config", ["block_on_piles.toml", "block_fan_torsion_near_speed.toml"])
def test_fcalc_amplitudes_office_rows_take_at_most_two_lines(runner, on_terminal, config):
    """The office checks' rows (eccentricity, bearing pressure, mass ratio) took 3-4 lines at 80
    columns beside a source column; now the sources are a line under the table, each named once
    with its checks, and a row takes one or two lines. In a pipe: the table with its sources."""
    lines = on_terminal("amplitudes", config)
    assert all(cell_len(line) <= WIDTH for line in lines), [line for line in lines if cell_len(line) > WIDTH]
    office = _rows(_segment(lines, "Office checks"))
    assert len(office) >= 3 and all(len(row) <= 2 for row in office), office
    sources = " ".join(_paragraph(lines, "sources: ")).split()
    assert " ".join(sources).count("ACI 351.3R-18, ch. 3 (rules of thumb)") == 1
    assert "eccentricity x, eccentricity y," in " ".join(sources)
    piped = _run(runner, "amplitudes", config)
    assert "sources: " not in piped and "│ ACI 351.3R-18, ch. 3 (rules of thumb) │" in piped


def test_fcalc_runup_point_column_takes_at_most_three_lines(on_terminal):
    """The "peak of each passage" table's point column wrapped "block top edge, cylinder end" to
    5 lines at 80 columns; now the table drops its frame and the point takes at most 3, the mode
    ("1 (p1)") whole on its line (a 2 s run-up: a second or two)."""
    import re

    lines = on_terminal("runup", "compressor_vendor_loads.toml", "--time", "2")
    assert all(cell_len(line) <= WIDTH for line in lines), [line for line in lines if cell_len(line) > WIDTH]
    peaks = _rows(_segment(lines, "Start-up: peak of each passage"))
    assert peaks and all(len(row) <= 3 for row in peaks), peaks
    points = [" ".join(" ".join(line.split("│")[-1] for line in row).split()) for row in peaks]
    assert set(points) == {"C", "block top edge, cylinder end"}, points  # words whole, in order
    assert all(re.fullmatch(r"\d \([a-z]\d\)", row[0].split("│")[0].strip()) for row in peaks), peaks  # e.g. 1 (p1)


def test_fcalc_design_pareto_rows_take_at_most_three_lines(on_terminal):
    """The Pareto set of a block with three sizes varied left "governed by" 17 cells at 80 columns:
    a row took up to 5 lines; now the numbers' headers wrap and a row takes at most 3."""
    lines = on_terminal("design", "block_two_throw_compressor.toml", "--vary", "block.length=4:8", "--vary",
                        "block.width=3:7", "--vary", "block.height=1:4", "--points", "3")
    assert all(cell_len(line) <= WIDTH for line in lines), [line for line in lines if cell_len(line) > WIDTH]
    pareto = _rows(_segment(lines, "Pareto set"))
    assert len(pareto) >= 3 and all(len(row) <= 3 for row in pareto), pareto


def test_fcalc_amplitudes_limit_rows_keep_their_unit_on_their_line(on_terminal):
    """frame_saw.toml's Limits table was one cell wider than 80 columns, so rich wrapped every
    quantity: "displacement" on a line, "[m]" alone under it (2 rows, 4 lines); now the quantity
    and its unit are one cell that never wraps, the table drops its frame to fit: a row a line."""
    lines = on_terminal("amplitudes", "frame_saw.toml")
    assert all(cell_len(line) <= WIDTH for line in lines), [line for line in lines if cell_len(line) > WIDTH]
    limits = _rows(_segment(lines, "Limits (checked with:"))
    assert len(limits) == 2 and all(len(row) == 1 for row in limits), limits
    assert all("│ displacement [m] │" in row[0] for row in limits), limits


def test_fcalc_amplitudes_limits_put_their_units_in_the_title_where_they_do_not_fit(runner, on_terminal):
    """compressor_vendor_loads.toml's Limits table does not fit 80 columns even without its frame
    with "displacement [m]" whole (its points' longest words take the room): the unit goes into the
    title, once, and no cell holds a unit alone; in a pipe the units stay beside the quantities."""
    lines = on_terminal("amplitudes", "compressor_vendor_loads.toml")
    assert all(cell_len(line) <= WIDTH for line in lines), [line for line in lines if cell_len(line) > WIDTH]
    segment = _segment(lines, "Limits (checked with:")
    assert " ".join(" ".join(segment[:2]).split()).endswith("Z = F) — displacement [m]"), segment[:2]
    body = [line.split("│") for line in segment if "│" in line]  # frameless: point, along, quantity, ...
    starts = [cells for cells in body if cells[1].strip()]  # a row's first line names its direction
    assert len(starts) == 6 and all(cells[2].strip() == "displacement" for cells in starts), segment
    assert all(cells[2].strip() in ("displacement", "") for cells in body), segment  # no unit alone
    piped = _run(runner, "amplitudes", "compressor_vendor_loads.toml")
    assert "│ displacement [m] │" in piped and "— displacement [m]" not in piped


def test_fcalc_amplitudes_rocking_peaks_keep_their_unit_beside_the_number(on_terminal):
    """The rocking row of the peaks table ("0.00017921 rad/s") broke its unit onto a line of its
    own at 80 columns (compressor_vendor_loads.toml): now a number and its unit stay one line."""
    lines = on_terminal("amplitudes", "compressor_vendor_loads.toml")
    peaks = _rows(_segment(lines, "Peaks over one revolution"))
    [rocking] = [row for row in peaks if "rocking θ" in row[0]]
    assert len(rocking) == 1 and "rad/s │" in rocking[0] and rocking[0].rstrip().endswith("rad/s²"), rocking


def test_a_table_title_wraps_at_the_terminal_s_width_not_the_table_s(on_terminal):
    """The crank's harmonics table (58 cells) wrapped its 71-cell title at its own width, two
    lines; now a left-justified title wraps at the terminal's: one line at 80 columns."""
    lines = on_terminal("amplitudes", "frame_saw.toml")
    title = "Harmonics (signed coefficient of cos nωt for y, of sin nωt for x and θ)"
    assert title in [line.rstrip() for line in lines], [line for line in lines if line.startswith("Harmonics")]


def test_a_table_wider_than_80_columns_in_its_words_splits_repeating_its_first_column(runner, on_terminal):
    """``fcalc amplitudes --exact`` on frame_saw.toml: the harmonics table (values and errors of
    three methods) took 88 columns even frameless and ran past the terminal; now it is two tables
    that fit, each with the harmonic column (the values, then the errors: not four columns and
    one), every column once, every row in each. A pipe keeps one."""
    lines = on_terminal("amplitudes", "--exact", "frame_saw.toml")
    assert all(cell_len(line) <= WIDTH for line in lines), [line for line in lines if cell_len(line) > WIDTH]
    heads = [i for i, line in enumerate(lines) if line.replace("┃", " ").split()[:1] == ["harmonic"]]
    assert len(heads) == 2, heads
    head_words = " ".join(" ".join(lines[i - 1:i + 1]) for i in heads).replace("┃", " ").split()
    for name in ("first", "approximation", "averaged", "operator", "exact", "error,"):
        assert name in head_words, (name, head_words)
    errors = [" ".join(lines[i - 1:i + 1]).count("error,") for i in heads]
    assert errors == [0, 2], errors  # as even as fits: the three methods' values, then their two errors
    for i in heads:
        body = [line.replace("│", " ").split()[0] for line in lines[i + 2:i + 12]]
        assert body == ["y1", "y2", "y3", "y4", "x1", "x2", "x3", "theta1", "theta2", "theta3"], lines[i:i + 12]
    piped = _run(runner, "amplitudes", "--exact", "frame_saw.toml")
    assert sum(line.startswith("┃ harmonic ") for line in piped.splitlines()) == 1


def test_a_sweep_of_two_points_and_phases_fits_80_columns_without_a_lone_slash(on_terminal):
    """compressor_vendor_loads.toml's sweep (x, y, θ, two points' h/v pairs, the phase lags, the
    status) took 92 columns and broke each "4.985e-05 / 4.489e-06" into three lines, the slash
    alone on the middle one; now the table splits in two, each with the speed, whose columns
    leave a pair one line, or two with the slash after the first value."""
    lines = on_terminal("sweep", "compressor_vendor_loads.toml", "--speed", "200:900:8")
    assert all(cell_len(line) <= WIDTH for line in lines), [line for line in lines if cell_len(line) > WIDTH]
    cells = [cell.strip() for line in lines if "│" in line for cell in line.split("│")]
    assert "/" not in cells and not any(cell.startswith("/") for cell in cells), [c for c in cells if c.startswith("/")]
    speeds = [line.split("│")[0].strip() for line in lines if "│" in line and line.split("│")[0].strip()]
    assert speeds == [str(s) for s in range(200, 1000, 100)] * 2, speeds


def test_fcalc_amplitudes_support_class_lines_wrap_under_their_own_text(runner, on_terminal):
    """The support class of compressor_vendor_loads.toml's points (3 lines of 78-110 cells) wrapped
    at column 0 on an 80-column terminal, "< 1.25 × 25 Hz = 31.25 Hz" starting a line under an
    indented item; now each line wraps at words under its own text, the same words in order, and
    stays one line in a pipe."""
    lines = on_terminal("amplitudes", "compressor_vendor_loads.toml")
    piped = _run(runner, "amplitudes", "compressor_vendor_loads.toml").splitlines()
    first = next(i for i, line in enumerate(lines) if line.startswith("Support class"))
    end = next(i for i, line in enumerate(lines) if line.startswith("soil model"))
    block = lines[first:end]
    assert all(cell_len(line) <= WIDTH for line in block), block
    assert all(line.startswith("  ") for line in block[1:]), block
    start = next(i for i, line in enumerate(piped) if line.startswith("Support class"))
    whole = piped[start:start + 4]
    assert " ".join(block).split() == " ".join(whole).split(), (block, whole)
    starts = [next(k for k, line in enumerate(block) if line.startswith(item[:30])) for item in whole[1:]]
    for a, b in zip(starts, [*starts[1:], len(block)]):  # each item's own lines: the first, then its wraps under it
        assert len(block[a]) - len(block[a].lstrip()) == 2 and all(line.startswith("    ") for line in block[a + 1:b]), block[a:b]


#: Block scenes at 80 columns, a command each, and the names and short phrases of its tables
#: (machines, points, modes' dominant motions, a status) that broke between their words.
WHOLE_NAMES = [
    (("resonance", "block_opposed_compressor.toml"), ("opposed compressor", "sliding y (with rocking)", "not judged")),
    (("amplitudes", "block_opposed_compressor.toml"), ("opposed compressor", "cylinder head, +x", "block top corner")),
    (("resonance", "block_on_piles.toml"), ("sliding y (with rocking)", "sliding x (with rocking)")),
    (("resonance", "block_two_machines.toml"), ("not judged",)),
]


@pytest.mark.parametrize(("args", "names"), WHOLE_NAMES, ids=[" ".join(args) for args, _ in WHOLE_NAMES])
def test_a_block_table_keeps_its_names_whole_at_80_columns(runner, on_terminal, args, names):
    """A machine ("opposed compressor"), a point ("cylinder head, +x"), a mode's dominant motion
    ("sliding y (with rocking)") or a status ("not judged") broke between its words inside a table
    row at 80 columns, though the table fits otherwise: its frame dropped, its headers wrapped, or
    (a machine too long beside its columns) a table per machine under its name. Now no cell of a
    table line holds only a name's first words ("opposed" over "compressor"), and no line is wider
    than 80; in a pipe the tables are as they were, the machine in its column."""
    lines = on_terminal(*args)
    piped = _run(runner, *args).splitlines()
    assert all(cell_len(line) <= WIDTH for line in lines), [line for line in lines if cell_len(line) > WIDTH]
    for shown in (lines, piped):
        cells = {cell.strip() for line in shown if "│" in line for cell in line.split("│")}
        for name in names:
            words = name.split()
            broken = [" ".join(words[:k]) for k in range(1, len(words)) if " ".join(words[:k]) in cells]
            assert not broken, (name, broken)
            assert any(name in line for line in shown), name
    machines = [line for line in piped if line.startswith("┃ machine ")]
    assert len(machines) == ("Steady state" in "".join(piped)) + ("Resonances:" in "".join(piped)), machines
