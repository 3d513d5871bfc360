"""No NaN or inf reaches the output: where one is born the scene is refused with a message, and
the JSON writers turn any that slips through into a per-scene error, never a dead batch."""

from __future__ import annotations

import json
import math

import pytest

from foundation_calc.checks.batch import CheckRun, SceneRun
from foundation_calc.cli.app import app
from foundation_calc.errors import ExitCode, FcalcError
from tests.conftest import CONFIGS

#: A crank scene found by fuzzing (shipped start-up scene, lengths and speed scaled): the crank
#: axis 1.4 km above the centre of mass makes the rod's weight overturn the averaged structure,
#: so the start-up's stiffness K̄ has a negative eigenvalue (ω² < 0, NaN from its square root
#: before the fix, then through the passage's Faddeeva function into the JSON writer).
OVERTURNED = """\
kind = "crank_foundation"
name = "frame saw with its crank axis 1.4 km above the centre of mass"

[foundation]
mass = 100e3
moment_of_inertia = 4.5e5
cog_height = 0.15
base_area = 30.0
base_second_moment = 3.2

[soil]
c_z = 1.0e6
c_x = 0.7e6
damping = [0.15, 0.15, 0.1]

[mechanism]
speed_rpm = 5200
crank_radius = 2.5
rod_length = 16.5
rod_mass = 1.5e3
rod_cog_to_crank_pin = 1.0
rod_radius_of_gyration = 0.35
crank_axis_to_cog = 1400.0

[operation]
run_up_time = 10.0

[limits]
amplitude = 0.01
transient_amplitude = 0.02
"""


def test_a_start_up_that_cannot_be_computed_is_one_invalid_scene_and_the_batch_goes_on(runner, tmp_path):
    (tmp_path / "overturned.toml").write_text(OVERTURNED)
    (tmp_path / "plain.toml").write_text((CONFIGS / "frame_saw.toml").read_text())
    result = runner.invoke(app, ["check", str(tmp_path), "--json"])
    document = json.loads(result.stdout)  # one whole document, no NaN in it
    assert result.exit_code == 3, result.output
    scenes = {s["source"].rsplit("/", 1)[-1]: s for s in document["scenes"]}
    runup = {c["check"]: c for c in scenes["overturned.toml"]["checks"]}["runup"]
    assert runup["verdict"] == "invalid"
    problem = runup["problems"][0]
    assert problem["field"] == "mechanism.crank_axis_to_cog" and "unstable" in problem["message"]
    assert scenes["plain.toml"]["exit_code"] == 0


def test_the_start_up_command_names_the_cause(runner, tmp_path):
    (tmp_path / "overturned.toml").write_text(OVERTURNED)
    result = runner.invoke(app, ["runup", str(tmp_path / "overturned.toml")])
    assert result.exit_code == 3, result.output
    assert "mechanism.crank_axis_to_cog" in result.stderr and "nan" not in result.output.lower()


def test_the_json_writer_refuses_a_non_finite_number_naming_where_it_is():
    from foundation_calc.output.console import json_text

    with pytest.raises(FcalcError) as caught:
        json_text({"result": {"passages": [{"eta": 1.0}, {"eta": math.nan}]}})
    assert caught.value.exit_code == ExitCode.INVALID_SCENE
    assert "result.passages[1].eta" in str(caught.value) and "NaN" in str(caught.value)


def test_a_non_finite_value_in_one_check_makes_that_check_invalid_not_the_batch(tmp_path):
    from foundation_calc.output.check_report import json_entry

    runs = (CheckRun("resonance", "pass", ("fine",), {"speed": ("speed", 10.0)}),
            CheckRun("amplitudes", "pass", ("fine",), {"peak": ("amplitude", math.inf)}))
    light, text = json_entry(SceneRun("a.toml", "crank_foundation", "a", runs))
    entry = json.loads(text)
    verdicts = {c["check"]: c["verdict"] for c in entry["checks"]}
    assert verdicts == {"resonance": "pass", "amplitudes": "invalid"} and entry["exit_code"] == 3
    assert "values.peak.value" in entry["checks"][1]["problems"][0]["message"]
    assert light.exit_code(False) == ExitCode.INVALID_SCENE  # the table, JUnit and the exit code agree
