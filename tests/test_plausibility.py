"""Unit slips: values that validate but lie far outside what real designs use warn on stderr, in
the JSON ``warnings`` and on the calculation sheet, naming the key as the user wrote it, the
value, the plausible range and the likely slip; they never change the exit code unless
``--strict``. A foundation that tips over in rocking names the implausible input behind it.

The ranges are data (``foundation_calc/scenes/plausibility.py``); these tests take each slip
from a shipped scene that is plausible and change one value as a user would mistype it.
"""

from __future__ import annotations

import json

import pytest
import tomli_w

from foundation_calc.cli.app import app
from foundation_calc.scenes import parse_scene, read_toml
from foundation_calc.scenes.plausibility import RANGES
from tests.conftest import CONFIGS

LYSMER = "compressor_medium_sand_lysmer.toml"
SP26 = "compressor_medium_sand_sp26.toml"
LOADS = "compressor_vendor_loads.toml"


def _scene(tmp_path, config: str, *changes) -> str:
    """``config`` with each ``(path, value)`` change applied (path: keys and list indices)."""
    document = read_toml(CONFIGS / config)
    for path, value in changes:
        table = document
        for key in path[:-1]:
            table = table[key]
        if value is None:
            del table[path[-1]]
        else:
            table[path[-1]] = value
    file = tmp_path / "slip.toml"
    file.write_text(tomli_w.dumps(document), encoding="utf-8")
    return str(file)


def _flat(text: str) -> str:
    return " ".join(text.split())


#: (config, changes, what the warning must say: key = value, the range, the slip)
SLIPS = {
    "soil density in t/m³": (
        LYSMER, [(("soil", "density"), 1.8)],
        ("soil.density = 1.8 kg/m³", "1100 to 2500 kg/m³", "t/m³", "1800 kg/m³"),
    ),
    "soil unit weight for density": (
        LYSMER, [(("soil", "density"), 18.0)], ("soil.density = 18 kg/m³", "kN/m³", "1835.5 kg/m³"),
    ),
    "block in mm": (
        LYSMER,
        [(("foundation", "block", "length"), 6000.0), (("foundation", "block", "width"), 4000.0),
         (("foundation", "block", "height"), 1600.0), (("foundation", "base_length"), None),
         (("foundation", "base_width"), None)],
        ("foundation.block.height = 1600 m", "mm", "1.6 m"),
    ),
    "amplitude limit in mm": (
        LYSMER, [(("limits", "amplitude"), 0.15)], ("limits.amplitude = 0.15 m", "mm", "0.00015 m"),
    ),
    "phase in degrees": (
        LOADS, [(("loads", 1, "phase"), -90.0)], ("loads[1].phase = -90 rad", "degrees", "-1.5708 rad"),
    ),
    "shear modulus in MPa": (
        LYSMER, [(("soil", "shear_wave_velocity"), None), (("soil", "shear_modulus"), 52.0)],
        ("soil.shear_modulus = 52 Pa", "MPa", "5.2e+07 Pa"),
    ),
    "shear wave velocity in km/s": (
        LYSMER, [(("soil", "shear_wave_velocity"), 0.17)], ("soil.shear_wave_velocity = 0.17 m/s", "km/s", "170 m/s"),
    ),
    "deformation modulus in MPa": (
        SP26, [(("soil", "deformation_modulus"), 35000.0)],
        ("soil.deformation_modulus = 35000 Pa", "kPa", "3.5e+07 Pa"),
    ),
    "Poisson's ratio of no soil": (
        LYSMER, [(("soil", "poisson"), 0.02)], ("soil.poisson = 0.02", "0.1 to 0.5", "Bowles"),
    ),
    "Barkan's coefficient in MN/m³": (
        "frame_saw.toml", [(("soil", "c_x"), 49.0)], ("soil.c_x = 49 N/m³", "MN/m³", "4.9e+07 N/m³"),
    ),
    "machine mass in t": (
        LYSMER, [(("foundation", "machine", "mass"), 14.0)],
        ("block-to-machine mass ratio", "foundation.machine.mass", "ACI 351.3R"),
    ),
    "a block lighter than its machine": (
        LYSMER, [(("foundation", "machine", "mass"), 60e3)], ("block-to-machine mass ratio", "1.5", "3 to 100", "rule of thumb"),
    ),
}


@pytest.mark.parametrize("slip", SLIPS)
def test_a_unit_slip_warns_everywhere_naming_key_value_range_and_slip(runner, tmp_path, slip):
    config, changes, wanted = SLIPS[slip]
    path = _scene(tmp_path, config, *changes)
    shown = runner.invoke(app, ["resonance", path])
    for text in wanted:
        assert text in _flat(shown.stderr), (text, shown.stderr)
    if shown.exit_code == 3:  # a soil this soft tips the block over: the error names the slip
        assert "likely culprit: " + wanted[0] in _flat(shown.stderr)
    else:
        assert shown.exit_code in (0, 1), shown.output
        document = json.loads(runner.invoke(app, ["resonance", path, "--json"]).stdout)
        assert any(all(text in w for text in wanted) for w in document["warnings"]), document["warnings"]
    batch = json.loads(runner.invoke(app, ["check", path, "--json", "-j", "1"]).stdout)
    assert any(all(text in w for text in wanted) for w in batch["scenes"][0]["warnings"])


def test_warnings_change_the_exit_code_only_with_strict(runner, tmp_path):
    path = _scene(tmp_path, LYSMER, (("soil", "density"), 1.8), (("limits", "amplitude"), None),
                  (("limits", "velocity"), None))
    assert runner.invoke(app, ["resonance", path]).exit_code == 0
    assert runner.invoke(app, ["resonance", path, "--strict"]).exit_code == 1
    table = runner.invoke(app, ["check", path, "-j", "1"])
    assert table.exit_code == 0 and "│ inputs │ WARN │ 1 input value outside the plausible ranges: soil.density" in _flat(table.stdout)
    strict = runner.invoke(app, ["check", path, "-j", "1", "--strict"])
    assert strict.exit_code == 1 and "│ inputs │ FAIL │" in _flat(strict.stdout)
    junit = tmp_path / "junit.xml"
    runner.invoke(app, ["check", path, "-j", "1", "--strict", "--junit", str(junit)])
    assert 'name="inputs"' in junit.read_text(encoding="utf-8") and "<failure" in junit.read_text(encoding="utf-8")


def test_the_sheet_lists_the_warnings(runner, tmp_path):
    pytest.importorskip("matplotlib")
    path = _scene(tmp_path, LYSMER, (("soil", "density"), 1.8))
    sheet = tmp_path / "sheet.md"
    result = runner.invoke(app, ["report", path, "-o", str(sheet)])
    assert result.exit_code in (0, 1), result.output
    text = _flat(sheet.read_text(encoding="utf-8"))
    assert "Input warnings" in text and "soil.density = 1.8 kg/m³" in text
    assert "soil.density = 1.8 kg/m³" in _flat(result.stderr)


def test_a_machine_cog_height_in_mm_is_named_as_written(runner, tmp_path):
    path = _scene(tmp_path, LYSMER, (("foundation", "machine", "cog_height"), 2900.0))
    warned = _flat(runner.invoke(app, ["resonance", path]).stderr)
    assert "foundation.machine.cog_height = 2900 m" in warned
    assert "foundation.cog_height" not in warned  # computed, not in the user's file


@pytest.mark.parametrize(
    ("config", "changes", "culprit"),
    [
        (SP26, [(("soil", "deformation_modulus"), 35.0)], "soil.deformation_modulus = 35 Pa"),
        ("frame_saw.toml", [(("soil", "c_z"), 70.0)], "soil.c_z = 70 N/m³"),
        (LYSMER, [(("foundation", "block", "height"), 1600.0)], "foundation.block.height = 1600 m"),
    ],
)
def test_a_rocking_failure_from_a_unit_slip_names_the_culprit(runner, tmp_path, config, changes, culprit):
    path = _scene(tmp_path, config, *changes)
    result = runner.invoke(app, ["resonance", path])
    assert result.exit_code == 3
    error = _flat(result.stderr.split("error:", 1)[1])
    assert "unstable in rocking" in error and f"likely culprit: {culprit}" in error
    assert "foundation.base_second_moment" not in error  # neither given nor the cause


def test_a_rocking_failure_without_a_slip_names_the_keys_of_the_users_file(runner, tmp_path):
    """A 1 m × 1 m × 10 m pier on the softest plausible soil tips over: every value is plausible."""
    block = {"length": 1.0, "width": 1.0, "height": 10.0, "density": 2400.0}
    path = _scene(tmp_path, LYSMER, (("soil",), {"c_z": 4e6, "c_x": 3e6}), (("foundation", "block"), block),
                  (("foundation", "base_length"), 1.0), (("foundation", "base_width"), 1.0),
                  (("foundation", "machine"), {"mass": 2000.0, "cog_height": 9.0}))
    result = runner.invoke(app, ["resonance", path])
    error = _flat(result.stderr)
    assert result.exit_code == 3 and "warning" not in error and "unstable in rocking" in error
    assert "foundation.base_second_moment" not in error and "likely culprit" not in error
    for key in ("soil.c_z", "foundation.base_length", "foundation.block.height", "foundation.machine.cog_height"):
        assert key in error


def test_platform_amp_in_mm_names_the_option(runner):
    result = runner.invoke(app, ["platform", "--amp", "0.5"])
    assert result.exit_code == 3
    text = _flat(result.stderr)
    assert "--amp 0.5" in text and "exciter.height" not in text and "operation.amplitude" not in text
    assert "mm" in text
    fast = _flat(runner.invoke(app, ["platform", "--omega", "3000"]).stderr)
    assert "warning: --omega = 3000 rad/s" in fast and "(use --rpm 3000)" in fast and "speed_rpm" not in fast


def test_shipped_scenes_are_plausible():
    """Every shipped scene but the contrived soft soil of the run-up example has no warning."""
    for config in sorted(CONFIGS.glob("*.toml")):
        warnings = parse_scene(read_toml(config), source=str(config)).plausibility_warnings()
        if config.name == "frame_saw_soft_soil_runup.toml":
            assert [w.split(" ")[0] for w in warnings] == ["soil.c_z", "soil.c_x", "limits.amplitude"], warnings
        else:
            assert warnings == [], (config.name, warnings)


def test_every_range_has_a_source_and_the_manual_table_states_it():
    page = (CONFIGS.parent / "docs" / "plausibility.md").read_text(encoding="utf-8")
    rows = [line for line in page.splitlines() if line.startswith("| ")]
    for name, plausible in RANGES.items():
        assert plausible.source and plausible.basis and plausible.low < plausible.high, name
        assert any(f" | {plausible.span()} | " in row and f"{plausible.source}: {plausible.basis}" in row for row in rows), name
