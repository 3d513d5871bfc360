"""[[machines.cranks]] of a block scene: validation, the loads and mass they give the block, and the
commands on the shipped crank scenes (configs/block_two_throw_compressor.toml,
configs/block_opposed_compressor.toml)."""

from __future__ import annotations

import copy
import json
import math
from pathlib import Path

import numpy as np
import pytest

from foundation_calc.cli.app import app
from foundation_calc.errors import SceneError
from foundation_calc.scenes import parse_scene
from tests.conftest import read_toml

ROOT = Path(__file__).resolve().parents[1]
TWO_THROW = ROOT / "configs" / "block_two_throw_compressor.toml"
OPPOSED = ROOT / "configs" / "block_opposed_compressor.toml"


@pytest.fixture
def two_throw() -> dict:
    return copy.deepcopy(read_toml(TWO_THROW))


@pytest.mark.parametrize(("key", "value", "expected"), [
    ("slider_axis", [0.0, 0.3, 1.0], "must be normal to shaft_axis"),
    ("shaft_axis", [0.0, 0.0, 0.0], "shaft_axis must not be [0, 0, 0]"),
    ("rod_length", 0.1, "rod_length l = 0.1 m must exceed crank_radius r = 0.11 m"),
    ("rod_cog_to_crank_pin", 0.6, "must lie on the rod"),
    ("rotating_radius", 0.0, "give rotating_mass [kg] and rotating_radius [m] together"),
    ("crank_radius", -0.11, "crank_radius: must be > 0 (got -0.11; r [m]"),
    ("stroke", 0.22, "stroke"),
])
def test_an_impossible_throw_is_an_invalid_scene_naming_its_key(two_throw, key, value, expected):
    two_throw["machines"][0]["cranks"][0][key] = value
    with pytest.raises(SceneError) as err:
        parse_scene(two_throw)
    assert expected in str(err.value)
    assert "machines.0.cranks.0" in str(err.value) or "machines[0].cranks[0]" in str(err.value)


def test_a_machine_with_cranks_alone_needs_no_other_load(two_throw):
    assert not two_throw["machines"][0].get("loads") and "unbalance" not in two_throw["machines"][0]
    del two_throw["machines"][0]["cranks"]
    with pytest.raises(SceneError, match=r"\[\[machines.cranks\]\]"):
        parse_scene(two_throw)


def test_a_crank_angle_in_degrees_is_a_plausibility_warning(two_throw):
    two_throw["machines"][0]["cranks"][1]["crank_angle"] = 90.0
    found = parse_scene(two_throw).plausibility_warnings()
    assert any("machines[0].cranks[1].crank_angle" in w for w in found), found


def test_the_cranks_mean_mass_is_in_the_model_and_moves_the_centre_of_mass(two_throw):
    """Total mass: block, machine, and every moving part (2 × (65 + 140) + 40 kg)."""
    scene = parse_scene(two_throw)
    model = scene.model()
    block = 6.0 * 4.0 * 2.0 * 2400.0
    assert model.mass == pytest.approx(block + 14.0e3 + 2 * (65.0 + 140.0) + 40.0, rel=1e-12)
    del two_throw["machines"][0]["cranks"]
    two_throw["machines"][0]["loads"] = [{"order": 1, "force": [1.0, 0.0, 0.0]}]
    assert parse_scene(two_throw).model().cog[2] < model.cog[2]  # the pistons ride above the machine's cog


def test_the_crank_loads_are_the_solver_harmonics_about_O(two_throw):
    """The loads rows at the machine's cog give back the solver's Q_n about O (to round-off)."""
    from foundation_calc.solvers.constants import GRAVITY
    from foundation_calc.solvers.machines.crank_mechanism import forcing_harmonics

    scene = parse_scene(two_throw)
    machine = scene.machines[0]
    exc = scene.excitations()[0]
    fh = forcing_harmonics(machine.crank_throws(), machine.omega_rad_s, GRAVITY)
    Q = fh.inertial + fh.weight
    assert list(exc.orders) == list(fh.orders)
    assert np.abs(exc.Q - Q).max() <= 1e-12 * np.abs(Q).max()
    # at 1.5 × the speed the inertia forces grow 2.25 times, the weight's moment does not
    assert np.abs(exc.loads_at(1.5 * exc.omega) - (2.25 * fh.inertial + fh.weight)).max() <= 1e-12 * np.abs(Q).max()


@pytest.mark.parametrize("config", [TWO_THROW, OPPOSED], ids=lambda p: p.name)
def test_amplitudes_json_gives_the_exact_solution_and_the_first_approximations_error(runner, config):
    result = runner.invoke(app, ["amplitudes", str(config), "--json"])
    assert result.exit_code == 0, result.stdout + result.stderr
    doc = json.loads(result.stdout)
    (crank,) = doc["periodic_inertia"]
    assert 0.0 < crank["first_approximation_error"] < 1e-3
    for name, point in doc["points"].items():
        first = crank["first_approximation"]["displacement_peak"][name]
        assert point["displacement_peak"] == pytest.approx(first, rel=1e-12)  # the limits judge the first approximation
        exact = crank["exact"]["displacement_peak"][name]
        for d in "xyz":
            assert abs(first[d] - exact[d]) <= crank["first_approximation_error"] * exact[d] * (1 + 1e-9) + 1e-9 * max(exact.values())
    assert math.isfinite(crank["harmonics"])


def test_the_opposed_pair_moves_the_block_by_its_couples_only(runner):
    """Forces cancel: G does not move vertically (to round-off); the couples turn the block about z
    (the first-order x forces 0.5 m apart) and about x (the rods' swing)."""
    doc = json.loads(runner.invoke(app, ["amplitudes", str(OPPOSED), "--json"]).stdout)
    rot = doc["rotation_peak"]
    assert doc["points"]["G"]["displacement_peak"]["z"] <= 1e-12 * max(rot.values())
    assert rot["rz"] > 0.0 and rot["rx"] > 0.0


def test_the_amplitudes_table_shows_the_exact_solution(runner):
    text = runner.invoke(app, ["amplitudes", str(TWO_THROW)], env={"COLUMNS": "80"}).stdout
    assert "exact periodic solution" in text and "first approximation's error" in text


def test_the_steady_state_table_names_its_unit_and_prints_round_off_as_zero(runner):
    """The vertical two-throw machine's odd orders above the first force the plane x-z only (its
    throws' x forces and moments about y): G's y motion at 3ω, what the block's products of inertia
    and the crankshaft's mean gyroscopic coupling (θ_x with θ_z) carry into y, is 2e-18 m beside
    3.5e-5 m at ω, below the table's round-off, and prints 0 without a phase; the title says the
    unit [m] (once read as markup and dropped). The JSON keeps the computed numbers."""
    text = runner.invoke(app, ["amplitudes", str(TWO_THROW)], env={"COLUMNS": "200"}).stdout
    assert "amplitude [m] and phase [°]" in text
    table = text[text.index("amplitude [m] and phase"):]
    table = table[: table.index("└")]
    rows = [[c.strip() for c in line.split("│")[1:-1]] for line in table.splitlines() if line.startswith("│")]
    order_3_at_g = next(r for r in rows if r[:3] == ["compressor", "3", "G"])
    assert order_3_at_g[4] == "0" and "∠" in order_3_at_g[3]
    assert not any("e-2" in cell for row in rows for cell in row), "a value of 1e-20 m is the solver's noise"


def test_a_frequency_dependent_soil_solves_each_harmonic_on_its_own_springs(two_throw, tmp_path):
    """On Gazetas' impedance the exact solution takes K(|n|ω), C(|n|ω) per harmonic: the command
    runs and the first approximation (solved order by order on the same impedance) stays within 1e-3."""
    two_throw["soil"] = {"method": "gazetas", "shear_modulus": 1.2e8, "poisson": 0.3, "density": 2000.0}
    import tomli_w

    path = tmp_path / "gazetas.toml"
    path.write_bytes(tomli_w.dumps(two_throw).encode())
    from typer.testing import CliRunner

    result = CliRunner().invoke(app, ["amplitudes", str(path), "--json"])
    assert result.exit_code in (0, 1), result.stdout + result.stderr
    (crank,) = json.loads(result.stdout)["periodic_inertia"]
    assert 0.0 < crank["first_approximation_error"] < 1e-3


def test_the_mass_ratio_counts_the_cranks_moving_parts(runner):
    """Machine 14 t plus rods, pistons and the crank web's 40 kg: 14.45 t (office and design alike)."""
    doc = json.loads(runner.invoke(app, ["check", str(TWO_THROW), "--json"]).stdout)
    office = next(c for c in doc["scenes"][0]["checks"] if c["check"] == "office")
    reason = office["reason"] if isinstance(office["reason"], str) else " ".join(office["reason"])
    assert "machines 14.45 t" in reason


def test_the_sheet_says_what_the_cranks_add_and_how_far_the_first_approximation_is(runner, tmp_path):
    sheet = tmp_path / "two_throw.md"
    result = runner.invoke(app, ["report", str(TWO_THROW), "-o", str(sheet)])
    assert result.exit_code == 0, result.stdout + result.stderr
    text = sheet.read_text()
    assert "2 crank throws" in text and "moving mass 450.0 kg" in text
    assert "the first approximation judged here differs from it by at most" in text
    # C as solved: the dashpots and the crankshaft's mean gyroscopic coupling, its entries named
    assert "plus the machines' mean gyroscopic coupling D̄ at their speeds" in text
    assert "= -85.27 N m s/rad" in text and "| C, row θ\\_x | 0 | 0 | 0 | 1.600·10⁷ | 0 | -8.527·10¹ |" in text


def test_a_rod_barely_longer_than_its_crank_warns_and_the_exact_solution_states_its_truncation(two_throw, monkeypatch):
    """λ = 0.995 is no real rod (a plausibility warning names the key); with the harmonics' cap the
    exact solution is given at the cap with its own error, and the amplitudes still come."""
    crank = two_throw["machines"][0]["cranks"][0]
    crank["rod_length"], crank["rod_cog_to_crank_pin"] = 0.1105, 0.05
    scene = parse_scene(two_throw)
    assert any("machines[0].cranks[0]: λ = crank_radius/rod_length = 0.995" in w for w in scene.plausibility_warnings())
    from foundation_calc.checks.amplitudes.machines import check_block
    from foundation_calc.solvers.rigid_body import periodic

    monkeypatch.setattr(periodic, "MAX_HARMONICS", 16)  # the cap, reached sooner: the same path, faster
    (found,) = check_block(scene, periodic=True).periodic
    assert found.harmonics == 16 and found.harmonic_change > periodic.HARMONIC_TOLERANCE
    assert 0.0 < found.error < 0.05
