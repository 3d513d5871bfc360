"""Block scenes as a careless user writes them: each mistake gives one message that names the
key, its unit and what is allowed (docs/exit-codes.md), never a repeated or garbled one."""

from __future__ import annotations

import copy
import json

import tomli_w
from hypothesis import HealthCheck, given, settings
from hypothesis import strategies as st

from foundation_calc.cli.app import app
from foundation_calc.scenes import read_toml
from tests.conftest import CONFIGS

TWO_MACHINES = read_toml(CONFIGS / "block_two_machines.toml")


def _scene(tmp_path, document, name="scene.toml"):
    path = tmp_path / name
    path.write_text(tomli_w.dumps(document), encoding="utf-8")
    return path


def test_check_names_a_problem_that_stops_every_check_once(runner, tmp_path):
    """A block that tips over (its rocking springs typed in N m/rad × 1e-7) makes the resonance and
    the amplitudes invalid alike: `fcalc check` prints the problem once, as `fcalc resonance` does,
    and its JSON still gives each check its problems."""
    document = copy.deepcopy(TWO_MACHINES)
    document["soil"]["stiffness"] = [8.4e3, 8.0e3, 1.05e4, 6.6e3, 1.6e3, 9.1e3]
    path = _scene(tmp_path, document)
    result = runner.invoke(app, ["check", str(path)])
    assert result.exit_code == 3, result.output
    assert result.stderr.count("the block tips over about x") == 1, result.stderr
    assert result.stderr.count("error: invalid scene") == 1, result.stderr
    single = runner.invoke(app, ["resonance", str(path)])
    assert single.exit_code == 3 and single.stderr.count("the block tips over about x") == 1


def test_a_block_given_in_part_names_the_missing_key_and_its_unit(runner, tmp_path):
    """A block given by its mass and cog without its inertia (or by its height without a density)
    is refused with the missing key's full name and unit, not "block needs inertia too"."""
    for block, key in (({"mass": 1.48e5, "cog": [0.0, 0.0, 1.1]}, "block.inertia [kg m²]"),
                       ({"height": 2.2}, "block.density [kg/m³]")):
        document = copy.deepcopy(TWO_MACHINES)
        document["block"] = {"length": 7.0, "width": 4.0, **block}
        result = runner.invoke(app, ["resonance", str(_scene(tmp_path, document))])
        assert result.exit_code == 3, result.output
        assert f"{key} missing" in result.stderr, result.stderr


def test_a_rule_over_an_array_of_tables_does_not_repeat_the_tables(runner, tmp_path):
    """Two machines of one name, a machine with nothing that shakes the block, two points of one
    name: the message names the array and the entry at fault, without the tables' text after it
    ("(got [{'name': 'compressor', 'mass': 12000.0, ...")."""
    same = copy.deepcopy(TWO_MACHINES)
    same["machines"][1]["name"] = "compressor"
    idle = copy.deepcopy(TWO_MACHINES)
    del idle["machines"][0]["loads"]
    points = copy.deepcopy(TWO_MACHINES)
    points["points"][1]["name"] = points["points"][0]["name"]
    for document, key, text in ((same, "machines", "distinct: compressor"), (idle, "machines", "'compressor' needs"),
                                (points, "points", "distinct and not 'G'")):
        result = runner.invoke(app, ["resonance", str(_scene(tmp_path, document))])
        assert result.exit_code == 3, result.output
        assert f"  {key}: " in result.stderr and text in result.stderr, result.stderr
        assert "got [{" not in result.stderr, result.stderr


@settings(max_examples=20, deadline=None, suppress_health_check=[HealthCheck.function_scoped_fixture])
@given(direction=st.integers(0, 5), value=st.sampled_from([0.0, -0.0, -1.0, -8.4e9]),
       key=st.sampled_from(["stiffness", "dashpot"]))
def test_a_spring_not_above_zero_is_refused_with_its_units(runner, tmp_path, direction, value, key):
    """A given spring of 0 or below, in any direction, is refused naming soil.stiffness, both its
    units and "> 0" (0 leaves the block unrestrained, so "must be >= 0" was wrong); a dashpot of 0
    is allowed (none), one below 0 is refused naming soil.dashpot and its units."""
    document = copy.deepcopy(TWO_MACHINES)
    document["soil"][key][direction] = value
    result = runner.invoke(app, ["resonance", str(_scene(tmp_path, document)), "--json"])
    if key == "dashpot" and value == 0.0:
        assert result.exit_code in (0, 1), result.output
        return
    assert result.exit_code == 3, result.output
    if key == "stiffness":
        assert "soil.stiffness must be > 0 N/m (along x, y, z) and > 0 N m/rad" in result.stderr, result.stderr
    else:
        assert "soil.dashpot must be >= 0 N s/m (along x, y, z) and >= 0 N m s/rad" in result.stderr, result.stderr


def test_a_soil_method_names_each_missing_key_with_its_unit(runner, tmp_path):
    """Barkan's coefficients without c_x: `soil.c_x [N/m³]`, as every other message names a key."""
    document = copy.deepcopy(TWO_MACHINES)
    document["soil"] = {"method": "coefficients", "c_z": 8.0e7}
    result = runner.invoke(app, ["resonance", str(_scene(tmp_path, document))])
    assert result.exit_code == 3, result.output
    assert "method 'coefficients' needs soil.c_x [N/m³]" in result.stderr, result.stderr


@settings(max_examples=6, deadline=None, suppress_health_check=[HealthCheck.function_scoped_fixture])
@given(axis=st.sampled_from([3, 4]), exponent=st.floats(-9.0, -6.0))
def test_design_judges_a_block_that_tips_over_as_check_does(runner, tmp_path, axis, exponent):
    """A block whose rocking spring about x or y (typed 1e-6 ... 1e-9 of its value) cannot carry
    the weight's overturning moment on any candidate: `fcalc check` refuses the scene, every check
    with it; the design search failed the resonance and amplitudes but passed the office checks,
    so its re-check by check's path reported a DISAGREEMENT, an internal error (exit 4). The
    search now fails the office checks of a block that tips over too: no candidate passes (exit 1)."""
    document = copy.deepcopy(TWO_MACHINES)
    document["soil"]["stiffness"][axis] *= 10.0**exponent
    path = _scene(tmp_path, document)
    assert runner.invoke(app, ["check", str(path)]).exit_code == 3
    result = runner.invoke(app, ["design", str(path), "--vary", "block.length=6:8", "--json"])
    assert result.exit_code == 1, result.output
    assert "DISAGREEMENT" not in result.output


CRANK_LENGTHS = ("crank_radius", "rod_length", "rod_cog_to_crank_pin", "rod_radius_of_gyration", "rotating_radius")


@settings(max_examples=4, deadline=None, suppress_health_check=[HealthCheck.function_scoped_fixture])
@given(throw=st.sampled_from([0, 1]), scale=st.sampled_from([1e3, 1e2]))
def test_a_crank_throw_typed_in_mm_is_warned(runner, tmp_path, throw, scale):
    """A throw of configs/block_two_throw_compressor.toml with its lengths typed in mm (or cm): λ =
    r/l and every position stay plausible, so nothing warned and the amplitudes were judged on a
    110 m crank. Each length (0 is not judged) is now warned, naming its key and the slip to mm."""
    document = read_toml(CONFIGS / "block_two_throw_compressor.toml")
    crank = document["machines"][0]["cranks"][throw]
    for key in CRANK_LENGTHS:
        crank[key] = crank.get(key, 0.0) * scale
    result = runner.invoke(app, ["resonance", str(_scene(tmp_path, document)), "--json"])
    assert result.exit_code in (0, 1), result.output
    warned = " ".join(w if isinstance(w, str) else str(w) for w in json.loads(result.stdout)["warnings"])
    for key in CRANK_LENGTHS:
        if crank[key] > 0:
            found = f"machines[0].cranks[{throw}].{key} = {crank[key]:g} m is above the plausible range"
            assert found in warned, warned
    assert "likely typed in mm" in result.stderr or scale != 1e3


def test_sampling_a_block_on_isolators_does_not_ask_for_a_soil_key(runner):
    """`fcalc soil --sample` refuses a block on [[isolators]] (exit 2); it told the user to give
    soil.modulus_range, a key such a scene cannot have (no [soil]). A piled block keeps the advice."""
    isolated = runner.invoke(app, ["soil", str(CONFIGS / "block_on_isolators.toml"), "--sample", "5"])
    assert isolated.exit_code == 2, isolated.output
    assert "not sampled, a block on [[isolators]]" in isolated.output and "soil.modulus_range" not in isolated.output
    piled = runner.invoke(app, ["soil", str(CONFIGS / "block_on_piles.toml"), "--sample", "5"])
    assert piled.exit_code == 2 and "give soil.modulus_range" in piled.output, piled.output


@settings(max_examples=4, deadline=None, suppress_health_check=[HealthCheck.function_scoped_fixture])
@given(factor=st.sampled_from([1.01, 3.0, 1e3]))
def test_an_unbalanced_rotor_heavier_than_its_machine_is_warned(runner, tmp_path, factor):
    """The motor of configs/block_two_machines.toml (6 t, its rotor 1.8 t) with a rotor heavier than
    the whole machine, which includes it (the rotor in kg, the machine in t, or a typo): judged
    silently before; now a warning names both keys and their unit."""
    document = copy.deepcopy(TWO_MACHINES)
    document["machines"][1]["unbalance"]["rotor_mass"] = document["machines"][1]["mass"] * factor
    result = runner.invoke(app, ["resonance", str(_scene(tmp_path, document))])
    assert result.exit_code in (0, 1), result.output
    assert "machines[1].unbalance.rotor_mass" in result.stderr and "machines[1].mass = 6000 kg" in result.stderr


@settings(max_examples=4, deadline=None, suppress_health_check=[HealthCheck.function_scoped_fixture])
@given(axis=st.sampled_from([3, 4]), exponent=st.floats(-9.0, -6.0))
def test_sampling_a_block_that_tips_over_names_the_culprit(runner, tmp_path, axis, exponent):
    """`fcalc soil --sample` of a block that tips over on its own soil: every sample's percentile
    was NaN, so a numpy RuntimeWarning leaked to stderr and the error named
    `sample.values.resonance_utilisation[0] is NaN`; it is refused as `fcalc check` refuses it,
    naming soil.stiffness and the tipping, exit 3, and its JSON is the error's document."""
    document = copy.deepcopy(TWO_MACHINES)
    document["soil"]["stiffness"][axis] *= 10.0**exponent
    result = runner.invoke(app, ["soil", str(_scene(tmp_path, document)), "--sample", "5", "--json"])
    assert result.exit_code == 3, result.output
    assert "RuntimeWarning" not in result.stderr and "is NaN" not in result.stderr, result.stderr
    assert json.loads(result.stdout)["problems"][0]["field"] == "soil.stiffness"
    assert "the block tips over about" in result.stderr
