"""The sizing a failing scene's sheet prints when its [report] design asks for it (issue 32, item 9)."""

from __future__ import annotations

import math
import re

import pytest

from foundation_calc.errors import SceneError
from foundation_calc.scenes import read_toml
from tests.conftest import CONFIGS

FAN = CONFIGS / "block_fan_torsion_near_speed.toml"


def _conclusion(sheet):
    return next(s for s in sheet.sections if s.title == "Conclusion")


def _text(section) -> str:
    return "\n".join(getattr(b, "text", "") for b in section.blocks)


def _sheet(path):
    from foundation_calc.api.report import sheet_sizing
    from foundation_calc.output.display_units import DisplayUnits
    from foundation_calc.output.report.documents import scene_sheet

    return scene_sheet(path, "fcalc report", DisplayUnits(), figures=False, size=sheet_sizing)[0]


def _scene(tmp_path, name: str, report: str):
    text = FAN.read_text(encoding="utf-8").split("[report]")[0] + report
    path = tmp_path / name
    path.write_text(text, encoding="utf-8")
    return path


def test_the_sheet_of_the_failing_fan_block_carries_a_design_that_passes(shipped_sheets):
    """The shipped fan block fails resonance; its [report] design asks for a sizing. The design the
    sheet prints, put into the scene by fcalc design's own rule and judged by fcalc check's path,
    passes every check; and its worst margin is 1 − that path's largest utilisation (3 figures printed)."""
    from foundation_calc.checks.batch import run_checks
    from foundation_calc.checks.design.apply import applied_document
    from foundation_calc.checks.design.reference import judged
    from foundation_calc.scenes.loading import parse_scene

    text = _text(_conclusion(shipped_sheets[FAN.stem]["sheet"]))
    found = re.search(r"The cheapest design that passes every check is (.*?): volume .*? worst margin ([0-9.e-]+)", text)
    assert found, text
    values = {k: float(v) for k, v in re.findall(r"(block\.\w+) = ([0-9.]+) m", found.group(1))}
    assert set(values) == {"block.length", "block.width", "block.height"}
    document = applied_document(read_toml(FAN), values)
    runs = run_checks(parse_scene(document, "sized"))
    assert all(run.verdict in ("pass", "warn") for run in runs), [(r.check, r.verdict) for r in runs]
    worst = max(u for u in (judged(run)[1] for run in runs) if not math.isnan(u))
    assert float(found.group(2)) == pytest.approx(1.0 - worst, rel=5e-3)
    table = next(b for b in _conclusion(shipped_sheets[FAN.stem]["sheet"]).blocks if getattr(b, "title", "").startswith("Cheapest"))
    assert {row[0] for row in table.rows} >= {"resonance", "amplitudes"}


def test_a_sizing_where_nothing_passes_says_so_with_the_closest(tmp_path):
    """Square plans 4-8 m at the given height: every candidate fails resonance (fcalc design says so)."""
    path = _scene(tmp_path, "fan.toml", '[report]\ndesign = ["block.length=4:8", "block.width=4:8"]\ndesign_step = 1.0\n')
    text = _text(_conclusion(_sheet(path)))
    assert "No design in these ranges passes" in text and "fail on every candidate: resonance" in text
    assert re.search(r"closest to passing is block\.length = 4 m, block\.width = 4 m", text)


def test_a_misspelt_range_is_an_invalid_scene_even_when_the_scene_passes(tmp_path):
    """The ranges are read on every sheet: a passing scene's typo is exit 3 naming report.design."""
    passing = CONFIGS / "block_two_machines.toml"
    path = tmp_path / "two.toml"
    path.write_text(passing.read_text(encoding="utf-8") + '\n[report]\ndesign = ["block.lenght=4:8"]\n', encoding="utf-8")
    with pytest.raises(SceneError) as raised:
        _sheet(path)
    assert raised.value.problems[0].field == "report.design" and "block.lenght" in str(raised.value)
    path.write_text(passing.read_text(encoding="utf-8") + '\n[report]\ndesign = ["block.length=4:8"]\n', encoding="utf-8")
    assert "Sizing" not in _text(_conclusion(_sheet(path)))  # a passing scene is not sized


@pytest.mark.parametrize("name, ranges, says", [
    ("frame_saw", '["block.length=3:8"]', "[foundation.block]"),
    ("block_two_machines", '["piles.length=10:20"]', "[piles]"),
])
def test_a_range_the_scene_cannot_take_is_an_invalid_scene_even_when_it_passes(tmp_path, name, ranges, says):
    """A passing crank scene without [foundation.block], a block without [piles]: fcalc design's own message."""
    path = tmp_path / f"{name}.toml"
    path.write_text((CONFIGS / f"{name}.toml").read_text(encoding="utf-8") + f"\n[report]\ndesign = {ranges}\n", encoding="utf-8")
    with pytest.raises(SceneError) as raised:
        _sheet(path)
    assert raised.value.problems[0].field == "report.design" and says in str(raised.value)
