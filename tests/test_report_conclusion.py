"""The sheet's conclusion in words: what fails, what to change and which way, the scene's note on its data."""

from __future__ import annotations

import re

import pytest

from foundation_calc.output.display_units import DisplayUnits
from foundation_calc.output.report.conclusion import not_real_note, resonance_change
from tests.conftest import CONFIGS

pytest.importorskip("matplotlib")

UNITS = DisplayUnits()


def _target(text: str) -> float:
    """The critical speed [rad/s] the advice asks for (the last speed it prints)."""
    return float(re.findall(r"([0-9.]+) rad/s", text)[-1])


@pytest.mark.parametrize("critical, below", [(90.0, True), (110.0, False)])
def test_resonance_change_moves_p_away_on_its_own_side_to_the_band(critical, below):
    """ω = 100 rad/s, n = 1, band 20 %: the margin |ω − ω_c|/ω_c (docs/resonance-rule.md) at the
    advised critical speed is the band itself (4 figures printed: tolerance 1e-3), on the mode's side."""
    row = {"condition": "ω = p", "mode_name": "vertical", "critical_speed": {"omega": critical}, "margin": abs(100 - critical) / critical, "required": 0.2}
    text = resonance_change(row, 100.0, UNITS)
    target = _target(text)
    assert ("lower p" in text) is below and ("raise p" in text) is not below
    assert (target < critical) is below
    assert abs(100.0 - target) / target == pytest.approx(0.2, rel=1e-3)


def _sheet(name: str):
    from foundation_calc.output.report.documents import scene_sheet

    sheet, _ = scene_sheet(CONFIGS / name, "fcalc report", UNITS, figures=False)
    return sheet


def _texts(section) -> str:
    return "\n".join(getattr(b, "text", "") for b in section.blocks)


def test_failing_sheet_concludes_with_each_condition_and_its_direction():
    """The compressor near resonance: p1 (critical 52.8 > 52.4 rad/s) must rise, 2ω = k0 (48.8 < 52.4) fall."""
    sheet = _sheet("compressor_near_resonance.toml")
    conclusion = next(s for s in sheet.sections if s.title == "Conclusion")
    text = _texts(conclusion)
    assert "does not satisfy" in text
    assert re.search(r"ω = p1 .*raise p", text) and re.search(r"2ω = k0 .*lower p", text)
    assert "Governing limit: C, horizontal" in text


def test_contrived_scene_says_so_first_and_a_real_one_does_not():
    contrived = _sheet("frame_saw_soft_soil_runup.toml")
    first = contrived.sections[0].blocks[0]  # page 1, above the title block's table
    assert first.title.startswith("NOTE: the data are not real") and "contrived soil" in first.rows[0][0]
    assert all(getattr(b, "title", "") != first.title for b in _sheet("frame_saw.toml").sections[0].blocks)
    assert not_real_note("# a real compressor\nkind = 'x'\n# contrived, later\n") is None
