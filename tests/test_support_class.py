"""The support class of ISO 10816-3 (3.4) classified from the foundation's own modes
(checks/support.py): rigid in a measuring direction when the lowest natural frequency in that
direction is at least 1.25 × the main excitation frequency.

The boundary is found independently: the lowest natural frequency by scipy.linalg.eigh of the
plane model's M, K assembled here from the scene's numbers (crank), or of the block's matrices
(block); the speed is then put a relative 1e-6 either side of p/1.25, far beyond round-off (1e-12)
and far inside any physical change. Each direction's values are read in its own class's table, the
worse zone deciding: checked here against zones computed from the printed tables.
"""

from __future__ import annotations

import json

import numpy as np
import pytest

from foundation_calc.checks.codes import TABLES, ZONES, zone, displacement_zone
from foundation_calc.cli.app import app
from foundation_calc.scenes import load_scene
from tests.conftest import CONFIGS

linalg = pytest.importorskip("scipy.linalg")

#: A block given by its mass properties on Barkan's coefficients, its machine by one horizontal load
#: at C: horizontal modes p1, p2 low, the vertical k0 high (c_z ≫ c_x).
CRANK = """\
kind = "crank_foundation"
name = "support class at the boundary"

[foundation]
mass = 100.0e3
moment_of_inertia = 3.0e5
cog_height = 1.2
base_area = 20.0
base_second_moment = 60.0

[soil]
c_z = 2.0e8
c_x = 1.0e7
c_phi = 2.0e8
damping = [0.1, 0.1, 0.05]

[operation]
omega = {omega!r}

[[loads]]
order = 1
horizontal = 5.0e3

[limits]
code = "ISO 10816-3"
machine_group = 2
machine_power = 100e3
{extra}
"""

#: A block on given springs, soft along x: its lowest mode slides along x (with rocking about y).
BLOCK = """\
kind = "block_foundation"

[block]
length = 6.0
width = 4.0
height = 1.5
density = 2400.0

[[machines]]
name = "fan"
mass = 5.0e3
cog = [0.0, 0.0, 2.0]
inertia = [1.0e3, 1.0e3, 1.0e3]
omega = {omega!r}

[[machines.loads]]
order = 1
force = [3.0e3, 0.0, 0.0]
at = [0.0, 0.0, 2.0]

[soil]
method = "springs"
stiffness = [1.0e8, 9.0e8, 3.0e9, 3.0e10, 2.0e10, 2.0e10]
dashpot = [1.0e6, 1.0e6, 1.0e6, 1.0e6, 1.0e6, 1.0e6]

[limits]
code = "ISO 10816-3"
machine_group = 2
machine_power = 100e3
"""

NUDGE = 1e-6


def _crank_p1() -> float:
    """The lowest sliding-rocking mode of :data:`CRANK` [rad/s], by an eigen-solve of the plane model."""
    M, I_c, h, S, I1, g = 100.0e3, 3.0e5, 1.2, 20.0, 60.0, 9.81
    K_x, K_phi = 1.0e7 * S, 2.0e8 * I1
    K = np.array([[K_x, -h * K_x], [-h * K_x, K_phi + h * h * K_x - M * g * h]])
    return float(np.sqrt(linalg.eigvalsh(K, np.diag([M, I_c]))[0]))


def _amplitudes(runner, path) -> dict:
    result = runner.invoke(app, ["amplitudes", str(path), "--json"])
    assert result.exit_code in (0, 1), result.output
    return json.loads(result.stdout)


def _support(point: dict) -> dict:
    return {c["direction"]: c for c in point["support"]}


@pytest.mark.parametrize("side, expected", [(-1, "rigid"), (+1, "flexible")])
def test_the_crank_support_flips_at_a_quarter_above_the_speed(runner, tmp_path, side, expected):
    p1 = _crank_p1()
    omega = p1 / 1.25 * (1.0 + side * NUDGE)
    path = tmp_path / "crank.toml"
    path.write_text(CRANK.format(omega=omega, extra=""))
    code = _amplitudes(runner, path)["code"]
    c = _support(code["points"][0])  # C
    assert c["horizontal"]["support"] == expected and not c["horizontal"]["given"]
    assert c["horizontal"]["mode"] == "p1" and c["horizontal"]["frequency"] == pytest.approx(p1, rel=1e-9)
    assert c["horizontal"]["excitation"] == pytest.approx(omega, rel=1e-12)
    assert c["vertical"]["support"] == "rigid" and c["vertical"]["mode"] == "k0"  # k0 far above 1.25 ω
    assert code["support_rule"] == {"clause": "ISO 10816-3:2009, 3.4", "ratio": 1.25, "direction_share": 0.01,
                                    "given_in_scene": False}


def test_each_direction_is_read_in_its_own_classs_table(runner, tmp_path):
    """Horizontal flexible, vertical rigid at C: the zone is the worse of the horizontal values in
    the flexible table and the vertical ones in the rigid table (printed boundaries)."""
    omega = _crank_p1() / 1.25 * (1.0 + NUDGE)
    path = tmp_path / "crank.toml"
    path.write_text(CRANK.format(omega=omega, extra=""))
    doc = _amplitudes(runner, path)
    point = doc["code"]["points"][0]
    flexible, rigid = TABLES["ISO 10816-3", 2, "flexible"], TABLES["ISO 10816-3", 2, "rigid"]
    v, d = point["velocity_rms"], point["displacement_rms"]
    horizontal = max(ZONES.index(zone(v["horizontal"], flexible)), ZONES.index(displacement_zone(d["horizontal"], flexible)))
    vertical = max(ZONES.index(zone(v["vertical"], rigid)), ZONES.index(displacement_zone(d["vertical"], rigid)))
    assert point["zone"] == ZONES[max(horizontal, vertical)]
    assert set(doc["code"]["tables"]) >= {point["foundation"]}


@pytest.mark.parametrize("side, expected", [(-1, "rigid"), (+1, "flexible")])
def test_the_block_support_flips_at_a_quarter_above_the_speed(runner, tmp_path, side, expected):
    probe = tmp_path / "probe.toml"
    probe.write_text(BLOCK.format(omega=100.0))
    model = load_scene(probe).model()
    lowest = float(np.sqrt(linalg.eigvalsh(model.K, model.M)[0]))
    omega = lowest / 1.25 * (1.0 + side * NUDGE)
    path = tmp_path / "block.toml"
    path.write_text(BLOCK.format(omega=omega))
    g = _support(_amplitudes(runner, path)["code"]["points"][0])  # G
    assert g["x"]["support"] == expected and g["x"]["frequency"] == pytest.approx(lowest, rel=1e-9)


def test_the_scene_overrides_the_modes_and_says_so(runner, tmp_path):
    omega = _crank_p1() / 1.25 * (1.0 + NUDGE)
    path = tmp_path / "crank.toml"
    path.write_text(CRANK.format(omega=omega, extra='foundation = "rigid"'))
    doc = _amplitudes(runner, path)
    c = _support(doc["code"]["points"][0])["horizontal"]
    assert (c["support"], c["given"], c["by_modes"]) == ("rigid", True, "flexible")
    assert c["text"].startswith("rigid, given in the scene (the modes: flexible, p1 = ")
    assert doc["code"]["points"][0]["foundation"] == "rigid" and doc["code"]["support_rule"]["given_in_scene"]
    text = " ".join(runner.invoke(app, ["amplitudes", str(path)]).stdout.split())
    assert "Support class (ISO 10816-3:2009, 3.4" in text and "given in the scene" in text


def test_the_shipped_vendor_loads_scene_is_flexible_from_its_modes(runner):
    """At 1500 rpm every mode of compressor_vendor_loads.toml lies below the speed: flexible in
    both directions, zone A of the flexible table (its verdict unchanged)."""
    path = CONFIGS / "compressor_vendor_loads.toml"
    doc = _amplitudes(runner, path)
    assert doc["code"]["foundation"] is None and doc["verdict"] == "pass"
    for point in doc["code"]["points"]:
        assert point["foundation"] == "flexible" and point["zone"] == "A"
        assert {c["support"] for c in point["support"]} == {"flexible"}
    check = json.loads(runner.invoke(app, ["check", str(path), "--json"]).stdout)
    amplitudes = next(c for c in check["scenes"][0]["checks"] if c["check"] == "amplitudes")
    assert "support flexible, classified from the modes: p1 = 8.923 Hz < 1.25 × 25 Hz" in amplitudes["reason"]
    assert any(d.startswith("SUPPORT horizontal at every point: flexible") for d in amplitudes["details"])


def test_the_sheet_shows_the_classification():
    from foundation_calc.output.display_units import DisplayUnits
    from foundation_calc.output.report.documents import scene_sheet

    sheet, _ = scene_sheet(CONFIGS / "compressor_vendor_loads.toml", "fcalc report", DisplayUnits(), figures=False)
    tables = [b for s in sheet.sections for b in s.blocks if getattr(b, "title", "").startswith("Support class")]
    assert len(tables) == 1
    assert {row[-1] for row in tables[0].rows} == {"flexible"} and {row[2] for row in tables[0].rows} <= {"k0", "p1"}


def test_fcalc_design_leaves_a_classified_support_to_the_full_path(tmp_path):
    """A candidate block changes the modes and so the class: the vectorised evaluators refuse the
    scene (NotImplementedError) and ``fcalc design`` judges it by ``fcalc check``'s path."""
    from foundation_calc.checks.design.block import evaluate

    path = tmp_path / "block.toml"
    path.write_text(BLOCK.format(omega=100.0))
    with pytest.raises(NotImplementedError, match="support class"):
        evaluate(load_scene(path), {"block.length": np.array([6.0])})


@pytest.mark.parametrize("config, directions", [("compressor_vendor_loads.toml", {"horizontal", "vertical"}),
                                                ("block_fan_torsion_near_speed.toml", {"x", "y", "z"})])
def test_every_kind_on_soil_reports_the_soil_model_and_the_support(runner, config, directions):
    """Conformance: one code path gives a crank and a block foundation their soil model's range of
    validity (resonance and amplitudes) and the code's support class (every point, every measuring
    direction). A platform stands on isolators given as springs and has no vibration code: neither
    applies to it, and its documents carry neither."""
    doc = json.loads(runner.invoke(app, ["check", str(CONFIGS / config), "--json"]).stdout)
    runs = {c["check"]: c["result"] for c in doc["scenes"][0]["checks"]}
    for name in ("resonance", "amplitudes"):
        assert runs[name]["soil_validity"]["method"] == load_scene(CONFIGS / config).soil.method_used
    for point in runs["amplitudes"]["code"]["points"]:
        assert {c["direction"] for c in point["support"]} == directions
    platform = json.loads(runner.invoke(app, ["check", str(CONFIGS / "platform_paper_example.toml"), "--json"]).stdout)
    assert "soil_validity" not in json.dumps(platform) and '"support"' not in json.dumps(platform)
