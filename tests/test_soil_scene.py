"""Scene keys of issue 11: the base from its length and width, mass properties from the block and
the machine, the [soil] method and its keys; and the CLI command ``fcalc soil``."""

from __future__ import annotations

import copy
import json
import math

import pytest
import tomli_w

from foundation_calc.cli.app import app
from foundation_calc.errors import SceneError
from foundation_calc.scenes import parse_scene, read_toml
from tests.conftest import CONFIGS
from tests.test_soil_methods import DAS_SCENE

LYSMER = CONFIGS / "compressor_medium_sand_lysmer.toml"
SP26 = CONFIGS / "compressor_medium_sand_sp26.toml"


def _scene(**changes) -> dict:
    """DAS_SCENE with tables replaced or (value None) removed."""
    scene = copy.deepcopy(DAS_SCENE)
    for table, value in changes.items():
        if value is None:
            scene.pop(table, None)
        else:
            scene[table] = value
    return scene


def _problems(document: dict) -> str:
    with pytest.raises(SceneError) as info:
        parse_scene(document)
    return str(info.value)


def _foundation(**keys) -> dict:
    base = {"mass": 3.48e4, "moment_of_inertia": 5.0e4, "cog_height": 1.0}
    return {**base, **keys}


def test_base_area_and_second_moment_from_length_and_width():
    f = parse_scene(_scene(foundation=_foundation(base_length=4.0, base_width=2.0))).foundation
    assert (f.base_area, f.base_second_moment) == (8.0, 2.0 * 4.0**3 / 12.0)
    again = parse_scene(_scene(foundation=_foundation(base_length=4.0, base_width=2.0, base_area=8.0,
                                                     base_second_moment=10.67))).foundation
    assert again.base_second_moment == 10.67  # within 0.5 %: the given value stands


def test_base_from_area_and_second_moment_gives_its_rectangle():
    f = parse_scene(_scene(foundation=_foundation(base_area=8.0, base_second_moment=2.0 * 4.0**3 / 12.0))).foundation
    assert f.dimensions == pytest.approx((4.0, 2.0), rel=1e-14)


@pytest.mark.parametrize(
    ("keys", "fragments"),
    [
        ({"base_length": 4.0, "base_width": 2.0, "base_area": 9.0}, ["foundation.base_area = 9 m²", "8 m²", "12.50%", "0.5%"]),
        ({"base_length": 4.0, "base_width": 2.0, "base_second_moment": 2.667},
         ["foundation.base_second_moment", "10.6667 m⁴", "0.5%"]),
        ({"base_length": 4.0}, ["give both foundation.base_length and foundation.base_width"]),
        ({"base_area": 8.0}, ["foundation.base_second_moment is missing", "[m⁴]", "base_length"]),
    ],
)
def test_base_disagreements_and_gaps_name_the_field(keys, fragments):
    message = _problems(_scene(foundation=_foundation(**keys)))
    for fragment in fragments:
        assert fragment in message, message


def test_mass_properties_from_block_and_machine():
    f = parse_scene(DAS_SCENE).foundation
    assert (f.mass, f.base_area) == (34800.0, 8.0)
    assert f.cog_height == pytest.approx((28800.0 * 0.75 + 6000.0 * 2.0) / 34800.0, rel=1e-14)


@pytest.mark.parametrize(
    ("foundation", "fragments"),
    [
        ({**DAS_SCENE["foundation"], "mass": 30000.0}, ["foundation.mass = 30000 kg", "34800 kg", "0.5%"]),
        ({**DAS_SCENE["foundation"], "base_length": 5.0, "base_width": 2.0}, ["foundation.base_length", "footprint"]),
        ({"machine": DAS_SCENE["foundation"]["machine"], "base_length": 4.0, "base_width": 2.0},
         ["foundation.machine needs [foundation.block]"]),
        ({"base_length": 4.0, "base_width": 2.0}, ["foundation.mass is missing", "[kg]", "[foundation.block]"]),
    ],
)
def test_mass_property_errors(foundation, fragments):
    message = _problems(_scene(foundation=foundation))
    for fragment in fragments:
        assert fragment in message, message


@pytest.mark.parametrize(
    ("soil", "fragments"),
    [
        ({"method": "lysmer", "c_z": 4e7, "density": 1800.0, "poisson": 0.3, "shear_modulus": 7e7},
         ["soil.c_z is a key of method 'coefficients', not of 'lysmer'", "shear_modulus, shear_wave_velocity"]),
        ({"method": "lysmer", "shear_modulos": 7e7, "density": 1800.0, "poisson": 0.3},
         ["soil.shear_modulos is not a key of method 'lysmer'", "did you mean shear_modulus"]),
        ({"method": "gazetas", "density": 1800.0, "poisson": 0.3}, ["exactly one of soil.shear_modulus"]),
        ({"method": "gazetas", "density": 1800.0, "poisson": 0.3, "shear_modulus": 7e7, "shear_wave_velocity": 200.0},
         ["exactly one of soil.shear_modulus"]),
        ({"method": "sp26", "deformation_modulus": 3e7}, ["method 'sp26' needs soil.soil_class"]),
        ({"method": "sp26", "deformation_modulus": 3e7, "soil_class": "peat"}, ["soil.soil_class", "sand"]),
        ({"method": "sp26", "deformation_modulus": 3e7, "soil_class": "sand", "poisson": 0.3},
         ["soil.poisson is a key of methods 'lysmer', 'gazetas' and 'pais_kausel', not of 'sp26'", "deformation_modulus, soil_class"]),
        ({"shear_modulus": 7e7}, ['give soil.method = "lysmer"', "c_z and soil.c_x"]),
        ({"method": "lysmer", "shear_modulus": 7e7, "density": 1800.0, "poisson": 0.6}, ["soil.poisson", "must be <= 0.5"]),
    ],
)
def test_soil_method_keys(soil, fragments):
    message = _problems(_scene(soil=soil))
    for fragment in fragments:
        assert fragment in message, message


def test_coefficients_scenes_keep_their_numbers_exactly():
    """Barkan's coefficients pass into the design unchanged (no c_z S / S round trip), undamped."""
    scene = parse_scene(read_toml(CONFIGS / "frame_saw.toml"))
    d = scene.design()
    assert (d.c, d.c1, d.c_phi, d.C_x, d.C_z, d.C_phi) == (scene.soil.c_z, scene.soil.c_x, scene.soil.c_z, 0.0, 0.0, 0.0)


def test_a_soil_method_maps_into_the_design():
    """c = K_z/S, c1 = K_x/S, c_phi = K_φ/I1 and C = 2 ξ sqrt(K m) of each mode."""
    scene = parse_scene(read_toml(LYSMER))
    d, s, f = scene.design(), scene.soil_springs(), scene.foundation
    assert (d.c * f.base_area, d.c1 * f.base_area, d.c_phi * f.base_second_moment) == pytest.approx(
        (float(s.K_z), float(s.K_x), float(s.K_phi)), rel=1e-14
    )
    I_0 = f.moment_of_inertia + d.M_tot * f.cog_height**2
    assert d.C_z == pytest.approx(2.0 * float(s.xi_z) * (float(s.K_z) * d.M_tot) ** 0.5, rel=1e-14)
    assert d.C_phi == pytest.approx(2.0 * float(s.xi_phi) * (float(s.K_phi) * I_0) ** 0.5, rel=1e-14)
    assert float(s.xi_x) > scene.soil.material_damping > 0.0


def _write(tmp_path, document: dict):
    path = tmp_path / "scene.toml"
    path.write_text(tomli_w.dumps(document), encoding="utf-8")
    return path


@pytest.mark.parametrize("config", [LYSMER, SP26, CONFIGS / "frame_saw.toml"], ids=lambda p: p.name)
def test_fcalc_soil_tables_and_json(runner, config):
    table = runner.invoke(app, ["soil", str(config)])
    assert table.exit_code == 0, table.output
    document = json.loads(runner.invoke(app, ["soil", str(config), "--json"]).stdout)
    used = document["method"]
    assert f"{used} *" in table.stdout
    expected = {"lysmer": ["lysmer", "gazetas", "pais_kausel"], "sp26": ["sp26"], "coefficients": ["coefficients"]}[used]
    assert list(document["methods"]) == expected
    numbers = document["methods"][used]
    assert numbers["K_z"] == pytest.approx(numbers["c_z"] * document["base"]["area"], rel=1e-14)
    assert f"{numbers['K_z'] / 1e6:.5g}" in table.stdout


def test_fcalc_soil_warns_of_the_static_dynamic_trap(runner, tmp_path):
    """E = 2G(1 + ν) = 135 MPa from the site's V_s given as SP 26's static modulus."""
    document = read_toml(SP26)
    document["soil"]["deformation_modulus"] = 135.0e6
    result = runner.invoke(app, ["soil", str(_write(tmp_path, document)), "--json"])
    assert result.exit_code == 0
    assert "dynamic modulus" in result.stderr
    assert any("dynamic modulus" in w for w in json.loads(result.stdout)["warnings"])
    assert "dynamic modulus" in runner.invoke(app, ["resonance", str(_write(tmp_path, document))]).stderr


def test_fcalc_soil_warns_of_a_static_modulus_given_as_shear_modulus(runner, tmp_path):
    document = read_toml(LYSMER)
    del document["soil"]["shear_wave_velocity"]
    document["soil"]["shear_modulus"] = 35.0e6 / (2.0 * 1.3)  # G from the static E = 35 MPa
    result = runner.invoke(app, ["soil", str(_write(tmp_path, document))])
    assert result.exit_code == 0 and "static deformation modulus" in result.stderr


def test_fcalc_soil_names_methods_that_disagree_by_more_than_2(runner, tmp_path):
    """A deep embedment stiffens Gazetas' springs; Lysmer's analogs are for a surface footing."""
    document = read_toml(LYSMER)
    document["foundation"]["embedment"] = 2.0
    result = runner.invoke(app, ["soil", str(_write(tmp_path, document)), "--json"])
    findings = json.loads(result.stdout)["warnings"]
    assert any("'lysmer' and 'gazetas' differ by a factor of" in w for w in findings), findings
    assert any("used by methods 'gazetas' and 'pais_kausel' only" in w for w in findings), findings


def test_gazetas_rocking_damping_at_the_rocking_mode_against_halls_analog(runner):
    """Gazetas' rocking radiation at the rocking mode's own frequency against Hall's analog
    D_φ = 0.15/((1 + B_φ) sqrt(B_φ)) (Richart, Hall & Woods 1970), an independent fit of the
    half-space: within a factor of 2 (the spread of the published methods), not 0.03 (material
    damping alone, the static springs' value). The rocking frequency on the springs at that
    frequency lies below the static one: the rocking spring softens with a0."""
    result = runner.invoke(app, ["soil", str(LYSMER), "--json"])
    methods = json.loads(result.stdout)["methods"]
    lysmer, gazetas = methods["lysmer"], methods["gazetas"]
    assert lysmer["xi_phi"] / 2.0 <= gazetas["xi_phi"] <= 2.0 * lysmer["xi_phi"], (lysmer["xi_phi"], gazetas["xi_phi"])
    assert gazetas["xi_phi"] > 0.15  # radiation, not the material damping 0.03 alone
    assert gazetas["omega_phi"] < gazetas["static_frequencies"]["omega_phi"]
    assert gazetas["p1"] < gazetas["static_frequencies"]["p1"] and gazetas["p2"] < gazetas["static_frequencies"]["p2"]
    assert not any("damping ratios" in w for w in json.loads(result.stdout)["warnings"])


def test_fcalc_soil_names_the_frequencies_beyond_each_methods_range(runner, tmp_path):
    """Each method by its own a0 and range (checks/soil_validity.py), on a 6 m × 4 m base over
    V_s = 170 m/s: Lysmer's a0 = ω r/V_s (r0 = √(BL/π) = 2.76 m, r0ψ = (BL³/(3π))^¼ = 3.09 m)
    against 1.5, Gazetas' a0 = ω B'/V_s (B' = 2 m) against 2. At 150 rpm only Lysmer's p2 lies
    beyond (its a0 by test_soil_validity.py); 1500 rpm puts Lysmer's speed at a0 = 2.55 in sliding
    and 2.86 in rocking, Gazetas' at 1.85 (within 2); 1800 rpm puts Gazetas' at 2.22."""
    r0, r_rock = math.sqrt(24.0 / math.pi), (4.0 * 6.0**3 / (3.0 * math.pi)) ** 0.25
    document = read_toml(LYSMER)
    quiet = json.loads(runner.invoke(app, ["soil", str(_write(tmp_path, document)), "--json"]).stdout)
    lysmer = [w for w in quiet["warnings"] if "soil method 'lysmer'" in w]
    assert len(lysmer) == 1 and "at p2: rocking 2.56, horizontal 2.29" in lysmer[0], quiet["warnings"]
    assert not any("the operating speed" in w or "soil method 'gazetas'" in w for w in quiet["warnings"])
    document["mechanism"]["speed_rpm"] = 1500.0
    omega = 1500.0 * math.pi / 30.0
    loud = json.loads(runner.invoke(app, ["soil", str(_write(tmp_path, document)), "--json"]).stdout)
    speed = f"at the operating speed: rocking {omega * r_rock / 170.0:.3g}, horizontal {omega * r0 / 170.0:.3g}"
    assert any(speed in w for w in loud["warnings"]), loud["warnings"]
    assert not any("soil method 'gazetas'" in w for w in loud["warnings"])  # 157.1 · 2/170 = 1.85 <= 2
    document["mechanism"]["speed_rpm"] = 1800.0
    louder = json.loads(runner.invoke(app, ["soil", str(_write(tmp_path, document)), "--json"]).stdout)
    gazetas = [w for w in louder["warnings"] if "soil method 'gazetas'" in w]
    assert len(gazetas) == 1 and f"at the operating speed: horizontal {1800.0 * math.pi / 30.0 * 2.0 / 170.0:.3g}" in gazetas[0]


def test_fcalc_soil_tables_the_frequency_dependent_springs(runner):
    """K and C of the frequency-dependent method at the speed and at k0, p1, p2; none for Lysmer."""
    document = json.loads(runner.invoke(app, ["soil", str(LYSMER), "--json"]).stdout)
    rows = document["methods"]["gazetas"]["at_frequencies"]
    assert [row["at"] for row in rows] == ["speed", "k0", "p1", "p2"]
    assert [row["omega"] for row in rows[1:]] == [document["methods"]["gazetas"][m] for m in ("k0", "p1", "p2")]
    assert document["methods"]["lysmer"]["frequency_dependent"] is False
    table = runner.invoke(app, ["soil", str(LYSMER)], env={"COLUMNS": "80"}).stdout
    assert "K_φ(ω)" in table and "p1, static springs" in table


def test_fcalc_soil_reports_a_block_that_tips_over(runner, tmp_path):
    """A rocking spring below the weight's overturning moment: no p1, p2, f_φ, and a note; not a crash."""
    document = read_toml(CONFIGS / "frame_saw.toml")
    document["soil"]["c_phi"] = 1.0e3  # K_φ = 2.1e5 N m/rad < M_tot g h = 1.5e6 N m
    path = _write(tmp_path, document)
    table = runner.invoke(app, ["soil", str(path)])
    assert table.exit_code == 0 and "tips over" in table.stdout
    numbers = json.loads(runner.invoke(app, ["soil", str(path), "--json"]).stdout)
    assert numbers["methods"]["coefficients"]["p1"] is None and numbers["methods"]["coefficients"]["omega_phi"] is None
    assert any("the block tips over" in w for w in numbers["warnings"])


def test_a_machine_given_by_its_loads_stands_on_the_soil_methods_springs(runner, tmp_path):
    """Vendor loads (no mechanism): the block's springs and dashpots are the soil method's."""
    document = read_toml(CONFIGS / "compressor_vendor_loads.toml")
    document["soil"] = {"method": "lysmer", "shear_wave_velocity": 170.0, "density": 1800.0, "poisson": 0.3,
                        "material_damping": 0.03}
    scene = parse_scene(document)
    block, springs = scene.block(), scene.soil_springs()
    assert (block.K_z, block.K_x, block.K_phi) == (float(springs.K_z), float(springs.K_x), float(springs.K_phi))
    assert block.C_z == pytest.approx(2.0 * float(springs.xi_z) * (float(springs.K_z) * scene.total_mass) ** 0.5)
    path = _write(tmp_path, document)
    assert runner.invoke(app, ["soil", str(path)]).exit_code == 0
    assert runner.invoke(app, ["amplitudes", str(path)]).exit_code in (0, 1)


@pytest.mark.parametrize("method", [[], {}, 3, ["lysmer"]])
def test_a_method_of_the_wrong_type_is_an_invalid_scene(method):
    """Found by the fuzz test: `method = []` reached a set lookup (TypeError, exit 4)."""
    document = read_toml(LYSMER)
    document["soil"]["method"] = method
    with pytest.raises(SceneError, match="soil.method"):
        parse_scene(document)
