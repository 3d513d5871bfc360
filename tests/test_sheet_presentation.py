"""What a reviewer frowns at on a printed sheet, checked on every shipped scene: raw exponents in
the PDF, one unit and one notation per quantity in the Checks table and the limits, a forcing share
as a plain percentage, tables that do not leave a lone row at a page's foot, a sweep figure that
shows every judged resonance, and a block sheet with a sweep figure and an accuracy statement."""

from __future__ import annotations

import re

import pytest

from tests.conftest import CONFIGS, sheet_configs
from tests.sheet_numbers import NUMBER, numbers
from tests.sheet_reader import read_markdown, read_typst

SCENES = [p.stem for p in sheet_configs()]

#: A typst string literal of the source (text set as text, never as math or markup).
LITERAL = re.compile(r'"((?:[^"\\]|\\.)*)"')


@pytest.mark.parametrize("name", SCENES)
def test_no_raw_exponent_in_the_pdf(shipped_sheets, name):
    """e^{i nωt}, a hand calculation's (E_p/E_s)^0.35 and χ^p are typeset (superscripts), never
    printed as a caret."""
    source = shipped_sheets[name]["typ"]
    text_only = [s for line in source.splitlines() if not line.startswith(("#block(breakable: false)[$", "#metadata("))
                 for s in LITERAL.findall(line)]  # equations are typst math and the chain data; the rest is text
    assert not [s for s in text_only if "^" in s]


def _unit(cell: str) -> str:
    """The unit printed after a cell's number (``1.35 µm`` → ``µm``)."""
    match = NUMBER.search(cell.replace("−", "-"))
    return cell[match.end():].strip()


@pytest.mark.parametrize("name", SCENES)
def test_checks_table_one_unit_and_notation_per_quantity(shipped_sheets, name):
    """Value and limit of each row in one unit, plain decimals (no "1.35·10⁻³ mm ≤ 0.0500 mm"), one
    unit per quantity in the whole table, and the [limits] inputs in that unit."""
    sheet = read_markdown(shipped_sheets[name]["md"])
    checks = next(t for t in sheet.tables() if t.title.startswith("Every check"))
    by_quantity: dict[str, set[str]] = {}
    for row in checks.rows:
        value, limit = row[2], row[3]
        if not NUMBER.search(value) or not limit.startswith(("≤", "≥")):
            continue
        assert "·10" not in value + limit, row
        assert _unit(value) == _unit(limit), row
        if row[0] not in ("amplitudes", "runup") or "torque" in row[1]:
            continue  # office and design rows: one quantity each
        zone = re.search(r"RMS (\w+) \(", row[1])
        quantity = ("peak displacement" if row[0] == "runup" else f"RMS {zone.group(1)}" if zone
                    else row[1].rsplit(": ", 1)[-1])
        by_quantity.setdefault(quantity, set()).add(_unit(value))
    assert all(len(units) == 1 for units in by_quantity.values()), by_quantity
    limits = next((t for t in sheet.tables() if t.title == "[limits]"), None)
    shown = {"peak displacement": ("amplitude", "transient_amplitude"), "RMS velocity": ("velocity_rms",),
             "peak velocity": ("velocity",)}
    for quantity, keys in shown.items():
        for row in (limits.rows if limits and quantity in by_quantity else ()):
            if row[0] in keys:
                assert row[3] in by_quantity[quantity], (row, by_quantity[quantity])


@pytest.mark.parametrize("name", [s for s in SCENES if not s.startswith(("block", "platform"))])
def test_forcing_share_is_a_plain_percentage(shipped_sheets, name):
    """The resonance table's forcing share: "100 %", "0.16 %", "< 0.01 %", never "1.0·10⁰"."""
    sheet = read_markdown(shipped_sheets[name]["md"])
    table = next(t for t in sheet.tables() if t.title.startswith("Resonances: critical speeds"))
    shares = [row[table.header.index("forcing share")] for row in table.rows]
    assert all(re.fullmatch(r"(< )?\d+(\.\d+)? %", s) for s in shares), shares


def test_a_long_table_does_not_leave_a_row_at_the_foot_of_a_page(shipped_sheets):
    """A table that may break is preceded by the unbreakable spacer that moves it to the next page
    when its title, header and three rows would not fit; a shorter one does not break at all."""
    from foundation_calc.output.report.pdf import ORPHAN_SPACE

    source = shipped_sheets["platform_paper_example"]["typ"].splitlines()
    for k, line in enumerate(source):
        if line.startswith("#block(breakable: true"):
            assert source[k - 2] == f"#block(breakable: false, height: {ORPHAN_SPACE}, width: 100%)", line[:80]
    tables = {t.title: t for t in read_typst(shipped_sheets["platform_paper_example"]["typ"]).tables()}
    matrices = next(line for line in source if "mean matrices about O1" in line)
    assert matrices.startswith("#block(breakable: false") and len(next(t for n, t in tables.items() if "mean matrices" in n).rows) > 12


@pytest.mark.parametrize("name", [s for s in SCENES if not s.startswith(("block", "platform"))])
def test_sweep_figure_spans_every_judged_resonance(runner, name):
    """The crank sheet's sweep runs past every judged critical speed and its band (the Lysmer
    compressor's ω = p2 at 140.6 rad/s, 9 ω, was off the plot)."""
    import json

    from foundation_calc.cli.app import app
    from foundation_calc.output.report.figures import sweep_factors

    result = runner.invoke(app, ["check", str(CONFIGS / f"{name}.toml"), "--json"])
    doc = next(c["result"] for c in json.loads(result.stdout)["scenes"][0]["checks"] if c["check"] == "resonance")
    omega = doc["speed"]["omega"]
    low, high = sweep_factors(omega, doc["resonances"])
    for r in doc["resonances"]:
        if r["judged"]:
            assert low * omega <= r["critical_speed"]["omega"] * (1 - r["required"])
            assert r["critical_speed"]["omega"] * (1 + r["required"]) <= high * omega


def test_block_sheet_has_a_sweep_per_machine_and_an_accuracy_section(runner, tmp_path):
    """Like a crank sheet: a speed sweep figure (one per machine) and an Accuracy section."""
    from foundation_calc.cli.app import app

    out = tmp_path / "block.md"
    result = runner.invoke(app, ["report", str(CONFIGS / "block_two_machines.toml"), "-o", str(out)])
    assert result.exit_code == 0, result.output
    text = out.read_text(encoding="utf-8")
    assert "## 6. Plots" in text and "## 7. Accuracy" in text
    assert "Sweep of compressor's speed" in text and "Sweep of motor's speed" in text
    assert sorted(p.name for p in tmp_path.glob("*.svg")) == ["block-figure1.svg", "block-figure2.svg"]


def test_block_points_table_takes_the_sheets_fitted_unit(shipped_sheets, tmp_path):
    """The two-machine block limited to 0.2 mm (≥ 0.1 mm) prints its points in mm, as its Checks
    table does; its limit of 50 µm prints µm. The same corner's peak, µm / 1000 = mm (3 figures
    printed: tolerance 0.5 % of each)."""
    import warnings

    from foundation_calc.api.options import display_units
    from foundation_calc.api.report import SHEET_UNITS
    from foundation_calc.output.report import markdown
    from foundation_calc.output.report.documents import scene_sheet

    def points(md: str):
        found = next(t for t in read_markdown(md).tables() if t.title.startswith("Points: u_P"))
        return found.header, {(r[0], r[1]): numbers(r[2])[0] for r in found.rows}

    name = "block_two_machines"
    micro_header, micro = points(shipped_sheets[name]["md"])
    assert micro_header[2] == "peak displacement [µm]"
    text = (CONFIGS / f"{name}.toml").read_text(encoding="utf-8")
    path = tmp_path / f"{name}.toml"
    path.write_text(text.replace("amplitude = 5.0e-5", "amplitude = 2.0e-4"), encoding="utf-8")
    with warnings.catch_warnings():
        warnings.simplefilter("ignore")
        sheet, _ = scene_sheet(path, "fcalc report", display_units(None, SHEET_UNITS), figures=False, fit_units=True)
    md = markdown.render(sheet, [])
    header, milli = points(md)
    assert tuple(header[2:5]) == ("peak displacement [mm]", "peak velocity [mm/s]", "v_rms [mm/s]")
    checks = next(t for t in read_markdown(md).tables() if t.title.startswith("Every check"))
    assert {_unit(r[2]) for r in checks.rows if r[1].endswith("peak displacement")} == {"mm"}
    for key, value in micro.items():
        assert milli[key] == pytest.approx(value / 1e3, rel=5e-3), key


@pytest.mark.parametrize("name", SCENES)
def test_each_column_of_a_matrix_table_is_in_one_notation(shipped_sheets, name):
    """A matrix table (M, K, C stacked) prints each of its columns plain or all a.bc·10ⁿ, not
    165840 above 8.400·10⁹ (zeros aside)."""
    for found in read_markdown(shipped_sheets[name]["md"]).tables():
        if "matrices" not in found.title.lower():
            continue
        for j in range(1, len(found.header)):
            cells = [row[j] for row in found.rows if NUMBER.fullmatch(row[j].replace("−", "-")) and row[j] != "0"]
            assert len({"·10" in c for c in cells}) <= 1, (found.title, found.header[j], cells)


def test_subscripts_are_typeset_in_pdf_and_html_and_plain_in_markdown(shipped_sheets):
    """Z_n, K_z, u_P,n are set as subscripts in the PDF (typst sub) and the HTML (<sub>); the
    Markdown keeps Z_n; a scene key keeps its _ everywhere: c_z in the inputs' key column, speed_rpm."""
    crank = shipped_sheets["compressor_near_resonance"]
    assert 'sub("z")' in crank["typ"] and "K<sub>z</sub>" in crank["html"] and "K\\_z" in crank["md"]
    key_cells = re.findall(r'table\.header\("key".*', crank["typ"])
    assert any('"c_z"' in line for line in key_cells) and '<td>c_z</td>' in crank["html"]
    block = shipped_sheets["block_two_machines"]
    assert 'sub("P,n")' in block["typ"] and "u<sub>P,n</sub>" in block["html"]
    assert '"speed_rpm"' in block["typ"] and "speed_rpm" in block["html"]


@pytest.mark.parametrize("name", [s for s in SCENES if s.startswith("block_")])
def test_block_points_columns_of_one_unit_share_one_notation(shipped_sheets, name):
    """The Points table's peak velocity and v_rms (both mm/s) print in one notation, not 0.00138
    beside 9.72·10⁻⁴."""
    found = next(t for t in read_markdown(shipped_sheets[name]["md"]).tables() if t.title.startswith("Points: u_P"))
    by_unit: dict[str, set[bool]] = {}
    for j, head in enumerate(found.header[2:], 2):
        unit = head.rsplit("[", 1)[-1]
        by_unit.setdefault(unit, set()).update("·10" in row[j] for row in found.rows if row[j] != "0")
    assert all(len(kinds) == 1 for kinds in by_unit.values()), by_unit


def test_crank_harmonics_are_named_as_the_paper_writes_them(shipped_sheets):
    """The amplitude and phase tables name the rotation's harmonics θ1, θ3 (the paper's symbol, as
    the hand calculations write M_θ1), never the JSON key theta1."""
    tables = read_markdown(shipped_sheets["frame_saw_soft_soil_runup"]["md"]).tables()
    rows = [r[0] for t in tables if "per harmonic" in t.title for r in t.rows]
    assert "θ1 [rad]" in rows and "θ1" in rows and not [r for r in rows if "theta" in r]
