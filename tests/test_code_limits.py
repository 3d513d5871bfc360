"""RMS limits and vibration-code zones of the crank foundation.

Validation: the zone boundaries against ISO 10816-3:2009, Annex A, Tables A.1 and A.2 as printed
(r.m.s. velocity, mm/s, two significant figures); the RMS of a series against numerical
integration of its square over one period (scipy.integrate.quad, independent of Parseval's
identity the code uses).
"""

from __future__ import annotations

import json
import math

import numpy as np
import pytest

from foundation_calc.checks.codes import CODES, TABLES, ZONES, application_warnings, zone
from foundation_calc.checks.crank_amplitudes import zone_outcome
from foundation_calc.cli.app import app
from foundation_calc.scenes.crank import CODE_NAMES
from foundation_calc.solvers.crank.response import rms_values
from tests.conftest import CONFIGS

integrate = pytest.importorskip("scipy.integrate")

#: ISO 10816-3:2009, Annex A: (group, support) -> zone boundaries A/B, B/C, C/D [mm/s r.m.s.].
PRINTED = {
    (1, "rigid"): (2.3, 4.5, 7.1),  # Table A.1
    (1, "flexible"): (3.5, 7.1, 11.0),  # Table A.1
    (2, "rigid"): (1.4, 2.8, 4.5),  # Table A.2
    (2, "flexible"): (2.3, 4.5, 7.1),  # Table A.2
}


def test_the_scene_offers_exactly_the_codes_with_tables():
    assert CODE_NAMES == CODES == ("ISO 10816-3",)


@pytest.mark.parametrize("group, foundation", sorted(PRINTED), ids=lambda v: str(v))
def test_zone_boundaries_are_the_printed_ones(group, foundation):
    table = TABLES["ISO 10816-3", group, foundation]
    assert table.boundaries_mm_s == PRINTED[group, foundation]
    assert table.clause.endswith("Table A.1" if group == 1 else "Table A.2")


@pytest.mark.parametrize("key", sorted(TABLES), ids=lambda k: f"{k[1]}-{k[2]}")
def test_a_boundary_value_is_in_the_lower_zone_and_just_past_it_in_the_next(key):
    table = TABLES[key]
    assert zone(0.0, table) == "A"
    for i, boundary in enumerate(table.boundaries):
        assert zone(boundary, table) == ZONES[i]
        assert zone(boundary * (1 + 1e-12), table) == ZONES[i + 1]
        assert zone(boundary * (1 - 1e-12), table) == ZONES[i]


def test_zone_verdicts():
    assert [zone_outcome(z, None).value for z in ZONES] == ["pass", "warn", "fail", "fail"]
    assert [zone_outcome(z, "A").value for z in ZONES] == ["pass", "fail", "fail", "fail"]
    assert [zone_outcome(z, "B").value for z in ZONES] == ["pass", "pass", "fail", "fail"]


def test_application_range_warnings():
    table = TABLES["ISO 10816-3", 2, "rigid"]
    assert application_warnings(table, 1500.0, 250.0) == []
    below, displacement, unknown = application_warnings(table, 100.0, None)
    assert "120 to 15000 rpm" in below and "100 rpm" in below
    assert "machine_power" in unknown
    assert "below 600 r/min by their r.m.s. displacement" in displacement and "not stored" in displacement


def test_no_displacement_boundary_is_stored_without_its_printed_value():
    """ISO 10816-3 sets displacement boundaries below 600 r/min; none is stored (their printed
    values were not available to check), so every table warns there and none warns at 600 r/min."""
    for table in TABLES.values():
        assert table.displacement_boundaries_um is None
        assert any("not stored" in w for w in application_warnings(table, 599.0, 1.0e3))
        assert not any("not stored" in w for w in application_warnings(table, 600.0, 1.0e3))
    (outside,) = application_warnings(table, 1500.0, 400.0)
    assert "400 kW is outside group 2" in outside


def test_rms_of_a_two_harmonic_series_against_quadrature():
    omega = 7.3
    cos = np.array([0.4, 2.0e-4, 0.0, 0.5e-4])  # the mean 0.4 is not vibration: left out
    sin = np.array([0.0, -1.0e-4, 0.0, 0.7e-4])
    T = 2 * math.pi / omega

    def q(t, order):
        n = np.arange(4)
        w = n * omega
        # d^k/dt^k of cos(wt) and sin(wt), written out
        c = [np.cos(w * t), -w * np.sin(w * t), -(w**2) * np.cos(w * t)][order]
        s = [np.sin(w * t), w * np.cos(w * t), -(w**2) * np.sin(w * t)][order]
        value = (cos * c + sin * s)[1:].sum()
        return value

    values = rms_values(cos, sin, omega)
    for order, got in enumerate((values.displacement, values.velocity, values.acceleration)):
        mean_square, _ = integrate.quad(lambda t: q(t, order) ** 2, 0.0, T, limit=200, epsabs=0, epsrel=1e-13)
        assert float(got) == pytest.approx(math.sqrt(mean_square / T), rel=1e-10)


def _write(tmp_path, text):
    path = tmp_path / "scene.toml"
    path.write_text(text, encoding="utf-8")
    return path


def _with_limits(lines: str) -> str:
    base = (CONFIGS / "frame_saw.toml").read_text(encoding="utf-8")
    head, _, _ = base.partition("[limits]")
    return head + "[limits]\n" + lines + "\n"


def test_code_verdict_names_its_source_and_zone(runner, tmp_path):
    scene = _write(tmp_path, _with_limits('code = "ISO 10816-3"\nmachine_group = 2\nfoundation = "rigid"\nmachine_power = 90e3'))
    result = runner.invoke(app, ["amplitudes", str(scene), "--json"])
    doc = json.loads(result.stdout)
    code = doc["code"]
    assert code["clause"] == "ISO 10816-3:2009, Annex A, Table A.2"
    (c,) = code["points"]
    v = c["velocity_rms"]
    assert c["value"] == max(v["horizontal"], v["vertical"])
    assert c["governing"] == ("vertical" if v["vertical"] > v["horizontal"] else "horizontal")
    assert c["zone"] == "B" and c["verdict"] == "warn" and result.exit_code == 0
    assert c["reason"].startswith("ISO 10816-3, group 2, rigid: zone B, 2.3 mm/s RMS > 1.4")
    # the same number as the RMS of the checked approximation's harmonics
    assert c["value"] == doc["approximations"]["averaged_operator"]["points_rms"]["C"]["vertical"]["velocity"]


def test_acceptable_zone_a_fails_zone_b_and_check_reports_it(runner, tmp_path):
    scene = _write(
        tmp_path,
        _with_limits('code = "ISO 10816-3"\nmachine_group = 2\nfoundation = "rigid"\nacceptable_zone = "A"\nmachine_power = 90e3'),
    )
    junit = tmp_path / "out.xml"
    result = runner.invoke(app, ["check", str(scene), "--junit", str(junit)])
    assert result.exit_code == 1
    assert "zone B, 2.3 mm/s RMS &gt; 1.4" in junit.read_text(encoding="utf-8")  # XML-escaped


def test_rms_limit_key(runner, tmp_path):
    scene = _write(tmp_path, _with_limits("velocity_rms = 2.0e-3"))
    doc = json.loads(runner.invoke(app, ["amplitudes", str(scene), "--json"]).stdout)
    rows = {(r["point"], r["direction"]): r for r in doc["limits"]}
    assert rows["C", "vertical"]["quantity"] == "velocity_rms"
    assert rows["C", "vertical"]["source"] == "scene [limits] velocity_rms"
    assert rows["C", "vertical"]["verdict"] == "fail" and doc["verdict"] == "fail"


@pytest.mark.parametrize(
    "lines, needle",
    [
        ('code = "ISO 20816-3"\nmachine_group = 2\nfoundation = "rigid"', "ISO 20816-3 is not available"),
        ('code = "ISO 10816-3"\nfoundation = "rigid"', "needs machine_group"),
        ("machine_group = 2", "need code"),
        ('code = "ISO 10816-3"\nmachine_group = 3\nfoundation = "rigid"', "machine_group"),
    ],
)
def test_bad_code_keys_are_invalid_scenes(runner, tmp_path, lines, needle):
    result = runner.invoke(app, ["amplitudes", str(_write(tmp_path, _with_limits(lines)))])
    assert result.exit_code == 3
    assert needle in result.output
