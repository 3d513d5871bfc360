"""The calculation sheet and ``fcalc check`` give one verdict: the same checks, rows, values, exit code.

Every shipped config and a generated set of scenes (a failing run-up limit, points with velocity
and acceleration limits, vendor loads with ISO zones, a length typed in mm, a platform run up)
are checked with ``fcalc check --json`` and written as a Markdown sheet (no typst needed); the
sheet's verdict table must list check's checks with check's verdicts, its checks table as many
rows per check as check's result documents hold, with the same verdicts, and its exit code must be
check's. Values are compared at the precision the sheet prints them (see ``VALUE_TOLERANCE``).
"""

from __future__ import annotations

import json
import tomllib

import pytest
import tomli_w

from foundation_calc.cli.app import app
from tests.conftest import CONFIGS, sheet_configs
from tests.sheet_numbers import NUMBER, numbers

pytest.importorskip("matplotlib")

#: The sheet prints speeds with 4 significant figures (its reasons with 5): within 5e-4 relative.
VALUE_TOLERANCE = 5e-4

#: The sheet's default display units (report: mm, mm/s), as factors on the SI values of check.
SHEET_FACTOR = {"amplitude": 1e3, "velocity": 1e3, "acceleration": 1.0, "speed": 1.0}


def _variant(tmp_path, config: str, name: str, change) -> object:
    scene = tomllib.loads((CONFIGS / config).read_text(encoding="utf-8"))
    change(scene)
    path = tmp_path / f"{name}.toml"
    path.write_text(tomli_w.dumps(scene), encoding="utf-8")
    return path


def _points(scene):
    scene["points"] = [
        {"name": "saw guide", "horizontal": 1.5, "height": 2.5},
        {"name": "motor foot", "horizontal": -2.0, "height": 0.2},
    ]
    scene["limits"] |= {"velocity": 0.02, "acceleration": 0.3}


def _iso(scene):
    scene["limits"] |= {"machine_group": 1, "foundation": "flexible"}


GENERATED = {
    "runup_fails": ("frame_saw_soft_soil_runup.toml", lambda s: s["limits"].update(transient_amplitude=0.012)),
    "points_limits": ("frame_saw.toml", _points),
    "loads_iso_zones": ("compressor_vendor_loads.toml", _iso),
    "length_in_mm": ("frame_saw.toml", lambda s: s["foundation"].update(cog_height=1500.0)),
    "platform_runup_fails": ("platform_damped.toml", lambda s: s["limits"].update(transient_amplitude=1e-4)),
}


def _sheet_tables(text: str) -> dict[str, list[list[str]]]:
    """The rows of the sheet's verdict table and of its checks table (cells unescaped)."""
    def rows(after: str) -> list[list[str]]:
        following = text.split(after, 1)[1].splitlines()
        start = next(i for i, line in enumerate(following) if line.startswith("|"))
        end = next((i for i in range(start, len(following)) if not following[i].startswith("|")), len(following))
        return [[c.strip().replace("\\", "") for c in line.strip("|").split(" | ")] for line in following[start + 2:end]]

    return {"verdict": rows("## 2. Verdict"), "checks": rows("**Every check")}


def _result_rows(check: dict) -> list[str]:
    """The verdicts of the rows of one check's result document, in the sheet's order."""
    result = check["result"]
    name = check["check"]
    if name == "resonance":  # a condition that is not judged, is not the speed itself (order 1, always judged)
        # and sets no warning shows why instead of PASS
        return [r["verdict"] if r["judged"] or r.get("order", r.get("harmonic")) == 1 or r["status"] in ("warn", "fail") else
                "information" if r["status"] == "information" else "not judged" for r in result["resonances"]]
    if name == "amplitudes":
        code = result.get("code") or {}
        return [r["verdict"] for r in result["limits"]] + [r["verdict"] for r in code.get("points", ())] + [
            "warn" for _ in code.get("warnings", ())
        ]
    if name == "runup":
        return [r["verdict"] for r in result["limits"]] + [t["verdict"] for t in (result.get("motor") or {}).get("sommerfeld", ())]
    if name == "office":
        return [r["verdict"] for r in result["office"]]
    if name == "inputs":  # the plausibility warnings: one row, no result document
        return [check["verdict"]]
    return [c["verdict"] for c in result["checks"]]


def _mixed_notation(column: list[str]) -> list[str]:
    """The cells of ``column`` that show one quantity (same text around the number) in both plain
    and ``a.bc·10ⁿ`` notation, as "0.00135 mm" above "6.70·10⁻⁴ mm"; an exact 0 fits either."""
    notations: dict[str, dict[bool, str]] = {}
    for cell in column:
        found = NUMBER.findall(cell)
        if len(found) != 1 or found[0] in ("0", "-0"):
            continue
        notations.setdefault(NUMBER.sub("#", cell), {})["·10" in found[0]] = cell
    return [cell for seen in notations.values() if len(seen) > 1 for cell in seen.values()]


def _numbers(text: str) -> list[float]:
    return numbers(text)


def _scenes(tmp_path_factory):
    folder = tmp_path_factory.mktemp("generated")
    generated = [_variant(folder, config, name, change) for name, (config, change) in GENERATED.items()]
    return sheet_configs() + generated


@pytest.fixture(scope="module")
def scenes(tmp_path_factory):
    return _scenes(tmp_path_factory)


def test_sheet_and_check_give_one_verdict(runner, scenes):
    from foundation_calc.api.report import SHEET_UNITS
    from foundation_calc.output.display_units import parse_units
    from foundation_calc.output.report import markdown
    from foundation_calc.output.report.documents import scene_sheet

    checked = json.loads(runner.invoke(app, ["check", *map(str, scenes), "--json", "-j", "1"]).stdout)
    for scene, entry in zip(scenes, checked["scenes"], strict=True):
        checks = entry["checks"]
        sheet, run = scene_sheet(scene, "fcalc report", parse_units([], SHEET_UNITS), figures=False)
        assert int(run.exit_code(strict=False)) == entry["exit_code"], scene.name
        text = markdown.render(sheet, [])
        tables = _sheet_tables(text)
        shown = _numbers(text)
        assert [(r[0], r[1].lower()) for r in tables["verdict"]] == [(c["check"], c["verdict"]) for c in checks], scene.name
        for check in checks:
            for name, value in check["values"].items():
                expected = value["value"] * SHEET_FACTOR[value["quantity"]]
                assert any(abs(x - expected) <= VALUE_TOLERANCE * abs(expected) for x in shown), (scene.name, name)
            sheet_rows = [r[5].lower() for r in tables["checks"] if r[0] == check["check"]]
            assert sheet_rows == _result_rows(check), (scene.name, check["check"])
        for at in (2, 3):  # value and limit columns: one notation per quantity (numbers.py)
            assert not _mixed_notation([r[at] for r in tables["checks"]]), (scene.name, _mixed_notation([r[at] for r in tables["checks"]]))
        # a checking engineer never reads PASS beside a demand above its limit
        assert not [r for r in tables["checks"] if r[5] == "PASS" and r[4] not in ("-", "inf") and float(r[4]) > 1.0], scene.name


def test_failing_start_up_fails_the_sheet(runner, scenes, tmp_path):
    """The start-up over its limit (fcalc check: exit 1, see above): the sheet says FAIL and exits 1."""
    scene = next(s for s in scenes if s.stem == "runup_fails")
    out = tmp_path / "sheet.md"
    assert runner.invoke(app, ["report", str(scene), "-o", str(out)]).exit_code == 1
    text = out.read_text(encoding="utf-8")
    assert "Overall verdict: FAIL (runup)" in text and "Start-up and run-down" in text


def test_a_check_without_a_row_reader_gets_its_reason_as_the_item():
    """A new kind's check (no row reader here) is one row: its reason in the item column (the
    page's free width), no value or limit; a long reason in the value column squeezed the table."""
    from foundation_calc.checks.batch import CheckRun
    from foundation_calc.output.display_units import DisplayUnits
    from foundation_calc.output.report.verdict import checks_section

    run = CheckRun("new check", "warn", ("a reason of some length ", ("amplitude", 1e-3)))
    (table, _) = checks_section([run], {"new check": {}}, None, DisplayUnits(amplitude="mm")).blocks
    assert table.rows == (("new check", "a reason of some length 1 mm", "-", "-", "-", "WARN", "fcalc check"),)


def test_long_tables_may_break_across_pages():
    """A table taller than a page must break (typst lets an unbreakable block run off the page)."""
    from foundation_calc.output.report.model import table
    from foundation_calc.output.report.pdf import _table

    short = table("", ("a", "b"), [("x", "1")] * 3)
    wordy = table("", ("a", "b"), [("word " * 300, "1")] * 8)  # some 200 lines of text: taller than a page
    assert "breakable: false" in _table(short) and "breakable: true" in _table(wordy)


def test_a_sheet_labels_every_resonance_row_as_fcalc_resonance_does(runner, tmp_path):
    """The speed itself (order 1) is always judged by the rule (docs/resonance-rule.md, rule 3),
    whatever its forcing share: the sheet's checks table shows its verdict beside the band it needs,
    as ``fcalc resonance`` shows PASS for it; a higher order under the share stays not judged. The
    opposed compressor's ω = mode 3 (z) has a forcing share of 0 (the throws cancel vertically)."""
    from foundation_calc.output.report.verdict import resonance_verdict

    scene = CONFIGS / "block_opposed_compressor.toml"
    rows = json.loads(runner.invoke(app, ["resonance", str(scene), "--json"]).stdout)["resonances"]
    speed = [r for r in rows if r["order"] == 1 and not r["judged"]]
    higher = [r for r in rows if r["order"] > 1 and not r["judged"] and r["status"] == "clear"]
    assert speed and higher  # the scene still has both kinds of row
    assert [resonance_verdict(r) for r in speed] == [r["verdict"] for r in speed] == ["pass"] * len(speed)
    assert {resonance_verdict(r) for r in higher} == {"not judged"}
    sheet = tmp_path / "sheet.md"
    assert runner.invoke(app, ["report", str(scene), "-o", str(sheet)]).exit_code == 0
    line = next(x for x in sheet.read_text(encoding="utf-8").splitlines() if ": ω = mode 3 (z), critical" in x)
    assert "| PASS |" in line and "≥ 20.0 %" in line, line
