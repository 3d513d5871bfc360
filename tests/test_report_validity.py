"""The sheet evaluates the models' validity: a0 = ω b/V_s of every judged mode and harmonic against
the soil method's fitted range, with the range and its source, and the caveat that a vibration
code's zones (meant for bearing-housing measurements) are applied to predicted motions, also
among ``fcalc check``'s notes.

Each printed a0 is recomputed here from its printed ω, b and the printed V_s (4 figures each:
1 % tolerance, :data:`tests.test_report_reproducible.PRINTED`), and its "within"/"BEYOND" from
the printed range.
"""

from __future__ import annotations

import json

import pytest

from foundation_calc.cli.app import app
from tests.conftest import CONFIGS
from tests.sheet_numbers import numbers
from tests.test_report_reproducible import close, plain, sheet, table_rows


@pytest.mark.parametrize("name", ["compressor_medium_sand_lysmer", "block_fan_torsion_near_speed"])
def test_a0_of_every_judged_mode_and_harmonic_is_printed_and_reproduced(runner, tmp_path, name):
    text = sheet(runner, tmp_path, name)
    title = next(x for x in plain(text).splitlines() if x.startswith("**Soil model 'lysmer': a0 = ω r/V_s"))
    assert "Richart, Hall & Woods (1970)" in title.replace("&amp;", "&")  # the range's source
    V_s = numbers(title.split("V_s = ")[-1])[0]
    top = numbers(title.split("a0 ≤ ")[1])[0]
    assert top == 1.5
    rows = table_rows(text, title.strip("*"))
    assert len(rows) >= 10
    ats = {row[0] for row in rows}
    assert any("ω" in at for at in ats) and len(ats) >= 4  # modes and harmonics
    for at, motion, omega, b, values, a0, verdict in rows:
        (w,), (length,), (printed,) = numbers(omega), numbers(b), numbers(a0)
        assert close(w * length / V_s, printed), (at, motion)
        assert verdict == ("within" if printed <= top else "BEYOND"), (at, motion)


def test_a_method_without_a_range_says_so(runner, tmp_path):
    text = plain(sheet(runner, tmp_path, "frame_saw_soft_soil_runup"))
    assert "Soil model 'coefficients': Barkan's coefficients give frequency-independent springs: no range of a0 applies" in text


def test_the_code_zone_caveat_is_on_the_sheet_and_in_the_checks_notes(runner, tmp_path):
    caveat = "applies them to the predicted motion of the foundation block at the machine's points"
    text = plain(sheet(runner, tmp_path, "compressor_vendor_loads"))
    assert "bearing housings" in text and caveat in text
    result = runner.invoke(app, ["check", str(CONFIGS / "compressor_vendor_loads.toml"), "--json"])
    doc = json.loads(result.output)
    (amplitudes,) = [c for c in doc["scenes"][0]["checks"] if c["check"] == "amplitudes"]
    assert any(line.startswith("NOTE ") and caveat in line for line in amplitudes["details"])
    # a scene without a code has no caveat
    assert caveat not in plain(sheet(runner, tmp_path, "compressor_medium_sand_lysmer"))
