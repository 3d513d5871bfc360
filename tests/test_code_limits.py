"""RMS limits and vibration-code zones of the crank foundation.

Validation: the zone boundaries against ISO 10816-3:2009, Annex A, Tables A.1 and A.2 as printed
(r.m.s. velocity, mm/s, two significant figures) and as reproduced (r.m.s. displacement, µm),
the displacement ones also against the velocity boundaries they follow (a sinusoid at 12.5 Hz,
group 1, or 10 Hz, group 2, within the tables' rounding to 1 µm); the RMS of a series against
numerical integration of its square over one period (scipy.integrate.quad, independent of
Parseval's identity the code uses).
"""

from __future__ import annotations

import json
import math

import numpy as np
import pytest

from foundation_calc.checks.codes import CODES, TABLES, ZONES, application_warnings, code_zone, displacement_zone, zone
from foundation_calc.checks.codes import zone_outcome
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


#: ISO 10816-3:2009, Annex A, displacement columns: (group, support) -> A/B, B/C, C/D [µm r.m.s.].
DISPLACEMENT = {
    (1, "rigid"): (29.0, 57.0, 90.0),  # Table A.1
    (1, "flexible"): (45.0, 90.0, 140.0),  # Table A.1
    (2, "rigid"): (22.0, 45.0, 71.0),  # Table A.2
    (2, "flexible"): (37.0, 71.0, 113.0),  # Table A.2
}


@pytest.mark.parametrize("group, foundation", sorted(DISPLACEMENT), ids=lambda v: str(v))
def test_displacement_boundaries_are_the_tables_and_follow_the_velocity_ones(group, foundation):
    """Each displacement boundary is the r.m.s. displacement of a sinusoid with the velocity
    boundary's r.m.s. velocity at 12.5 Hz (group 1) or 10 Hz (group 2), rounded to 1 µm: a
    mistyped digit in either column breaks it (tolerance 1 µm, the tables' last digit)."""
    table = TABLES["ISO 10816-3", group, foundation]
    assert table.displacement_boundaries_um == DISPLACEMENT[group, foundation]
    corner_hz = 12.5 if group == 1 else 10.0
    for v_mm_s, x_um in zip(table.boundaries_mm_s, table.displacement_boundaries_um):
        assert x_um == pytest.approx(v_mm_s * 1e3 / (2 * math.pi * corner_hz), abs=1.0)


@pytest.mark.parametrize("key", sorted(TABLES), ids=lambda k: f"{k[1]}-{k[2]}")
def test_a_displacement_boundary_is_in_the_lower_zone(key):
    table = TABLES[key]
    for i, boundary in enumerate(table.displacement_boundaries):
        assert displacement_zone(boundary, table) == ZONES[i]
        assert displacement_zone(boundary * (1 + 1e-12), table) == ZONES[i + 1]


@pytest.mark.parametrize(
    "velocity, displacement, expected",
    [
        (2.0e-3, 60e-6, ("C", "displacement", "B", "C")),  # the displacement more restrictive
        (3.0e-3, 30e-6, ("C", "velocity", "C", "B")),  # the velocity more restrictive
        (2.0e-3, 40e-6, ("B", "velocity", "B", "B")),  # a tie goes to the velocity
    ],
)
def test_the_more_restrictive_of_velocity_and_displacement_decides(velocity, displacement, expected):
    """ISO 10816-3:2009, 5.2.3."""
    z = code_zone(TABLES["ISO 10816-3", 2, "rigid"], velocity, displacement, None)
    assert (z.zone, z.quantity, z.velocity_zone, z.displacement_zone) == expected
    assert z.limit == (2.8e-3 if z.quantity == "velocity" else 45e-6)  # zone B's upper boundary


@pytest.mark.parametrize("key", sorted(TABLES), ids=lambda k: f"{k[1]}-{k[2]}")
def test_above_750_rpm_a_harmonic_response_is_decided_by_its_velocity(key):
    """A sinusoid at 12.5 Hz (750 r/min) or faster: its displacement zone is never worse than its
    velocity zone, save where the tables' rounding to 1 µm puts the two boundaries apart."""
    table = TABLES[key]
    for f in (12.5, 25.0, 50.0):
        for v in np.linspace(0.1e-3, 15e-3, 300):
            x = v / (2 * math.pi * f)
            near = min(abs(x - b) for b in table.displacement_boundaries)
            if near > 1.0e-6:
                assert code_zone(table, v, x, None).quantity == "velocity", (f, v)


def test_application_range_warnings():
    table = TABLES["ISO 10816-3", 2, "rigid"]
    assert application_warnings(table, 1500.0, 250.0) == []
    assert application_warnings(table, 300.0, 250.0) == []  # the displacement is judged there, not warned
    below, unknown = application_warnings(table, 100.0, None)
    assert "120 to 15000 rpm" in below and "100 rpm" in below
    assert "machine_power" in unknown
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
    """The frame saw runs at 250 rpm: its velocity is in zone B, its displacement in zone D, which
    decides (5.2.3)."""
    scene = _write(tmp_path, _with_limits('code = "ISO 10816-3"\nmachine_group = 2\nfoundation = "rigid"\nmachine_power = 90e3'))
    result = runner.invoke(app, ["amplitudes", str(scene), "--json"])
    doc = json.loads(result.stdout)
    code = doc["code"]
    assert code["clause"] == "ISO 10816-3:2009, Annex A, Table A.2"
    assert code["displacement_boundaries"] == {"A/B": 22e-6, "B/C": 45e-6, "C/D": 71e-6}
    (c,) = code["points"]
    v, x = c["velocity_rms"], c["displacement_rms"]
    assert (c["velocity_zone"], c["displacement_zone"], c["quantity"]) == ("B", "D", "displacement")
    assert c["value"] == max(x["horizontal"], x["vertical"]) and c["limit"] == 45e-6
    assert c["governing"] == ("vertical" if x["vertical"] > x["horizontal"] else "horizontal")
    assert c["zone"] == "D" and c["verdict"] == "fail" and result.exit_code == 1
    assert c["reason"].startswith("ISO 10816-3, group 2, rigid: zone D, 81.9 µm RMS > 71")
    # the same numbers as the RMS of the checked approximation's harmonics
    rms = doc["approximations"]["averaged_operator"]["points_rms"]["C"]
    assert c["value"] == rms[c["governing"]]["displacement"]
    assert max(v.values()) == pytest.approx(2.3e-3, abs=0.05e-3)  # zone B by velocity alone


def test_at_1500_rpm_the_velocity_decides(runner, tmp_path):
    text = _with_limits('code = "ISO 10816-3"\nmachine_group = 2\nfoundation = "rigid"\nmachine_power = 90e3')
    scene = _write(tmp_path, text.replace("speed_rpm = 250 ", "speed_rpm = 1500 "))
    (c,) = json.loads(runner.invoke(app, ["amplitudes", str(scene), "--json"]).stdout)["code"]["points"]
    assert c["quantity"] == "velocity" and c["value"] == max(c["velocity_rms"].values())
    assert ZONES.index(c["displacement_zone"]) <= ZONES.index(c["velocity_zone"])


def test_acceptable_zone_a_fails_zone_b_and_check_reports_it(runner, tmp_path):
    scene = _write(
        tmp_path,
        _with_limits('code = "ISO 10816-3"\nmachine_group = 2\nfoundation = "rigid"\nacceptable_zone = "A"\nmachine_power = 90e3'),
    )
    junit = tmp_path / "out.xml"
    result = runner.invoke(app, ["check", str(scene), "--junit", str(junit)])
    assert result.exit_code == 1
    assert "zone D, 81.9 µm RMS &gt; 71" in junit.read_text(encoding="utf-8")  # XML-escaped


def _slow_fan(tmp_path):
    """The fan block at 300 rpm with a G 100 fan rotor: RMS velocities in zones A-B, displacements in B-C."""
    text = (CONFIGS / "block_fan_torsion_near_speed.toml").read_text(encoding="utf-8")
    return _write(tmp_path, text.replace("990.0", "300.0").replace("balance_grade_mm_s = 6.3 ", "balance_grade_mm_s = 100.0"))


def test_a_slow_block_is_decided_by_its_displacement(runner, tmp_path):
    doc = json.loads(runner.invoke(app, ["amplitudes", str(_slow_fan(tmp_path)), "--json"]).stdout)
    rows = doc["code"]["points"]
    assert rows and all(r["quantity"] == "displacement" for r in rows)
    for r in rows:
        point = doc["points"][r["point"]]
        quantity = "displacement_rms" if r["quantity"] == "displacement" else "velocity_rms"
        assert r["value"] == max(point[quantity].values())
        assert ZONES.index(r["zone"]) == max(ZONES.index(r["velocity_zone"]), ZONES.index(r["displacement_zone"]))


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


def test_the_design_evaluator_judges_the_displacement_as_check_does(tmp_path):
    """``fcalc design``'s vectorised block evaluator against ``fcalc check``'s path, candidate by
    candidate, on the slow fan block (where the displacement decides): same
    outcome, same utilisation to 1e-9 (round-off of batched against single solves)."""
    from foundation_calc.checks.amplitudes.machines import check_block
    from foundation_calc.checks.design.block import evaluate
    from foundation_calc.checks.registry import CHECKS
    from foundation_calc.scenes import load_scene
    from tests.test_design_block import CODES as OUTCOME_CODES
    from tests.test_design_block import _candidates, _one, _scalar_utilisation

    scene = load_scene(str(_slow_fan(tmp_path)))
    batch = _candidates(scene, 20, seed=7)
    verdicts = evaluate(scene, batch)
    by = set()
    for i in range(20):
        one = _one(scene, batch, i)
        report = check_block(one)
        finding = CHECKS["block_foundation"]["amplitudes"](one)
        assert verdicts.outcome["amplitudes"][i] == OUTCOME_CODES[finding.outcome.value], (i, finding.reason)
        np.testing.assert_allclose(verdicts.utilisation["amplitudes"][i], _scalar_utilisation("amplitudes", report), rtol=1e-9)
        by |= {row.judged.quantity for row in report.zone_rows}
    assert "displacement" in by  # the candidates reach rows the displacement decides
