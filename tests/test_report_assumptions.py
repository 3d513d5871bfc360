"""The block foundation's assumptions and limitations, generated from what its scene uses.

Each row is compared with the scene's own facts, not with the sheet's wording of them: the soil
method's frequency dependence (``soil.frequency_dependent``, which decides whether the response is
solved at K(nω), C(nω)), the bearing-pressure limit the office check needs, the count of machines
(peaks added only when several), and whether the run-up check ran.
"""

from __future__ import annotations

import tomllib
from types import SimpleNamespace

import pytest

from foundation_calc.output.report.assumptions import assumptions_section
from foundation_calc.scenes.loading import parse_scene
from tests.conftest import CONFIGS

HALF_SPACE = {"shear_wave_velocity": 150.0, "density": 1850.0, "poisson": 0.33, "material_damping": 0.03}
SOILS = {
    "springs": None,  # the config's own
    "coefficients": {"c_z": 8.0e7, "c_x": 5.6e7, "damping": [0.1, 0.1, 0.05]},
    "lysmer": HALF_SPACE,
    "gazetas": HALF_SPACE,
    "pais_kausel": HALF_SPACE,
    "sp26": {"deformation_modulus": 3.0e7, "soil_class": "sand"},
}
REFERENCE = {"coefficients": "[Ba]", "lysmer": "[RHW]", "gazetas": "[Ga]", "pais_kausel": "[PK]", "sp26": "[SP26]"}


def _scene(method: str, **limits):
    data = tomllib.loads((CONFIGS / "block_two_machines.toml").read_text(encoding="utf-8"))
    if SOILS[method] is not None:
        data["soil"] = {"method": method, **SOILS[method]}
    data["limits"].update(limits)
    return parse_scene(data)


def _rows(scene, checks=("inputs", "resonance", "amplitudes", "office")) -> dict[str, str]:
    (table,) = assumptions_section(scene, [SimpleNamespace(check=c) for c in checks]).blocks
    return dict(table.rows)


@pytest.mark.parametrize("method", SOILS)
def test_the_soil_row_says_which_method_and_whether_it_depends_on_frequency(method):
    scene = _scene(method)
    soil = _rows(scene)["soil"]
    assert ("Frequency-dependent" in soil) == scene.soil.frequency_dependent, soil
    assert ("Frequency-independent" in soil) != scene.soil.frequency_dependent, soil
    assert REFERENCE.get(method, "as the scene gives them") in soil


def test_what_is_not_checked_follows_the_limits_machines_and_run_up():
    rows = _rows(_scene("springs"))
    assert "static bearing pressure" in rows["not checked"].lower()  # no [limits] bearing_pressure
    assert "peaks of the machines added" in rows["machines"]  # two machines
    assert "Start-up and run-down not checked" in rows["start-up"]
    assert "velocity" in rows["amplitudes"] and "no vibration code zone" in rows["amplitudes"]

    scene = _scene("springs", bearing_pressure=2.0e5)
    scene = scene.model_copy(update={"machines": scene.machines[:1]})
    rows = _rows(scene, ("resonance", "amplitudes", "runup", "office"))
    assert "bearing pressure" not in rows["not checked"]
    assert "machines" not in rows
    assert "not checked" not in rows["start-up"]
