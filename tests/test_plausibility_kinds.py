"""One plausibility table for every scene kind: the same unit slip warns in a crank foundation,
a block foundation and a platform wherever the kind has the key, naming the key as the user
wrote it (``machines[0].loads[1].phase``), and ``--strict`` fails it; a block foundation also
warns about a position off the block, and a block that tips over names the slip behind it.

Each case takes a shipped scene that is plausible and changes one value as a user would mistype
it (``tests/test_plausibility.py`` holds the crank's own slips and the wording of the warnings).
"""

from __future__ import annotations

import json
import typing

import pytest
import tomli_w
from pydantic import BaseModel

from foundation_calc.cli.app import app
from foundation_calc.scenes import read_toml
from foundation_calc.scenes.kinds import KINDS, model_for_kind
from foundation_calc.scenes.plausibility import INERTIA_KEYS, KEYS, Plausible
from tests.conftest import CONFIGS

LYSMER = "compressor_medium_sand_lysmer.toml"
LOADS = "compressor_vendor_loads.toml"
TWO = "block_two_machines.toml"
FAN = "block_fan_torsion_near_speed.toml"
DAMPED = "platform_damped.toml"


def _write(tmp_path, config: str, change) -> str:
    """``config`` after ``change(document)`` (a function that edits the TOML document in place)."""
    document = read_toml(CONFIGS / config)
    change(document)
    file = tmp_path / "slip.toml"
    file.write_text(tomli_w.dumps(document), encoding="utf-8")
    return str(file)


def _set(*path_and_value):
    """A change that sets the key at ``path`` (names and list indices) to ``value``."""
    *path, value = path_and_value

    def change(document):
        table = document
        for key in path[:-1]:
            table = table[key]
        table[path[-1]] = value

    return change


def _speed_rpm(table_path, value):
    """A change that gives the speed of the table at ``table_path`` as ``speed_rpm = value`` only."""

    def change(document):
        table = document
        for key in table_path:
            table = table[key]
        for key in ("omega", "frequency_hz", "speed_rpm"):
            table.pop(key, None)
        table["speed_rpm"] = value

    return change


def _scaled(path, factor):
    """A change that multiplies the number (or every number of the list) at ``path`` by ``factor``."""

    def change(document):
        table = document
        for key in path[:-1]:
            table = table[key]
        value = table[path[-1]]
        table[path[-1]] = [v * factor for v in value] if isinstance(value, list) else value * factor

    return change


def _each(*changes):
    def change(document):
        for one in changes:
            one(document)

    return change


def _extra_exciter(document):
    document["extra_exciters"] = [{"rotor_mass": 6.0, "eccentricity": 0.1, "position": [2.0, 0.5, 0.3], "phase": 90.0}]


def _modulus_in_mpa(document):
    document["soil"] = {"method": "lysmer", "shear_modulus": 72.0, "density": 1850.0, "poisson": 0.33}


def _sp26_in_mpa(document):
    document["soil"] = {"method": "sp26", "deformation_modulus": 35.0, "soil_class": "sand"}


def _steady(change):
    """``change`` on a platform scene without run-up and run-down times (its time integration is
    judged elsewhere; a slip may make it stiff and slow)."""

    def steady(document):
        for key in ("run_up_time", "run_down_time"):
            document["operation"].pop(key, None)
        change(document)

    return steady


_BLOCK_IN_MM = _each(*(_scaled(("block", side), 1e3) for side in ("length", "width", "height")))
_CRANK_IN_MM = _each(*(_scaled(("foundation", "block", side), 1e3) for side in ("length", "width", "height")),
                     *(_scaled(("foundation", side), 1e3) for side in ("base_length", "base_width")))

#: slip -> kind -> (config, change, what one warning must say: the user's key, the value, the slip).
SLIPS = {
    "soil density in t/m³": {
        "crank_foundation": (LYSMER, _set("soil", "density", 1.8), ("soil.density = 1.8 kg/m³", "t/m³", "1800 kg/m³")),
        "block_foundation": (FAN, _set("soil", "density", 1.8), ("soil.density = 1.8 kg/m³", "t/m³", "1800 kg/m³")),
    },
    "block in mm": {
        "crank_foundation": (LYSMER, _CRANK_IN_MM, ("foundation.block.height = 1600 m", "mm", "1.6 m")),
        "block_foundation": (FAN, _BLOCK_IN_MM, ("block.length = 5000 m", "mm", "5 m")),
    },
    "amplitude limit in mm": {
        "crank_foundation": (LYSMER, _set("limits", "amplitude", 0.05), ("limits.amplitude = 0.05 m", "mm", "5e-05 m")),
        "block_foundation": (TWO, _set("limits", "amplitude", 0.05), ("limits.amplitude = 0.05 m", "mm", "5e-05 m")),
    },
    "RMS velocity limit in mm/s": {
        "crank_foundation": (LYSMER, _set("limits", "velocity_rms", 2.8),
                             ("limits.velocity_rms = 2.8 m/s", "mm/s", "0.0028 m/s")),
        "block_foundation": (TWO, _set("limits", "velocity_rms", 2.8), ("limits.velocity_rms = 2.8 m/s", "mm/s", "0.0028 m/s")),
    },
    "transient limit in mm": {
        "crank_foundation": (LYSMER, _set("limits", "transient_amplitude", 0.2),
                             ("limits.transient_amplitude = 0.2 m", "mm", "0.0002 m")),
        "block_foundation": (TWO, _set("limits", "transient_amplitude", 0.2),
                             ("limits.transient_amplitude = 0.2 m", "mm", "0.0002 m")),
        "platform": (DAMPED, _steady(_set("limits", "transient_amplitude", 0.2)),
                     ("limits.transient_amplitude = 0.2 m", "mm", "0.0002 m")),
    },
    "phase in degrees": {
        "crank_foundation": (LOADS, _set("loads", 1, "phase", 90.0), ("loads[1].phase = 90 rad", "degrees", "1.5708 rad")),
        "block_foundation": (TWO, _set("machines", 0, "loads", 1, "phase", 90.0),
                             ("machines[0].loads[1].phase = 90 rad", "degrees", "1.5708 rad")),
        "platform": (DAMPED, _steady(_extra_exciter), ("extra_exciters[0].phase = 90 rad", "degrees", "1.5708 rad")),
    },
    "speed in Hz as rpm": {
        "crank_foundation": (LYSMER, _speed_rpm(("mechanism",), 10.0),
                             ("mechanism.speed_rpm = 10 rpm", "Hz", "600 rpm", "write frequency_hz = 10")),
        "block_foundation": (TWO, _speed_rpm(("machines", 0), 10.0),
                             ("machines[0].speed_rpm = 10 rpm", "Hz", "600 rpm", "write frequency_hz = 10")),
        "platform": (DAMPED, _steady(_speed_rpm(("operation",), 10.0)),
                     ("operation.speed_rpm = 10 rpm", "Hz", "600 rpm", "write frequency_hz = 10")),
    },
    "machine mass in t": {
        "crank_foundation": (LYSMER, _set("foundation", "machine", "mass", 14.0),
                             ("block-to-machine mass ratio", "foundation.machine.mass")),
        "block_foundation": (TWO, _set("machines", 1, "mass", 6.0), ("machines[1].mass = 6 kg", " t: ", "6000 kg")),
    },
    "moment of inertia in t·m²": {
        "crank_foundation": (LYSMER, _set("foundation", "machine", "moment_of_inertia", 9.0),
                             ("foundation.machine.moment_of_inertia = 9 kg m²", "t·m²", "9000 kg m²")),
        "block_foundation": (TWO, _scaled(("machines", 0, "inertia"), 1e-3),
                             ("machines[0].inertia[0] = 10 kg m²", "t·m²", "10000 kg m²")),
        "platform": (DAMPED, _steady(_scaled(("platform", "inertia"), 1e-3)),
                     ("platform.inertia[0] = 9 kg m²", "t·m²", "9000 kg m²")),
    },
    "balance grade in m/s": {
        "block_foundation": (TWO, _set("machines", 1, "unbalance", "balance_grade_mm_s", 0.0025),
                             ("machines[1].unbalance.balance_grade_mm_s = 0.0025 mm/s", "m/s", "2.5 mm/s")),
    },
    "shear modulus in MPa": {
        "crank_foundation": (LYSMER, _each(lambda d: d["soil"].pop("shear_wave_velocity"), _set("soil", "shear_modulus", 52.0)),
                             ("soil.shear_modulus = 52 Pa", "MPa", "5.2e+07 Pa")),
        "block_foundation": (FAN, _modulus_in_mpa, ("soil.shear_modulus = 72 Pa", "MPa", "7.2e+07 Pa")),
    },
    "deformation modulus in MPa": {
        "crank_foundation": ("compressor_medium_sand_sp26.toml", _set("soil", "deformation_modulus", 35.0),
                             ("soil.deformation_modulus = 35 Pa", "MPa", "3.5e+07 Pa")),
        "block_foundation": (FAN, _sp26_in_mpa, ("soil.deformation_modulus = 35 Pa", "MPa", "3.5e+07 Pa")),
    },
    # a per-kind rule of the block: positions off the block, through the same channel
    "load point beyond the footprint": {
        "block_foundation": (TWO, _set("machines", 0, "loads", 0, "at", [15.0, 0.3, 3.0]),
                             ("machines[0].loads[0].at = [15.0, 0.3, 3.0] m", "outside the block's footprint", "corner")),
    },
    "point below the base": {
        "block_foundation": (TWO, _set("points", 0, "at", [1.5, 0.3, -3.0]),
                             ("points[0].at = [1.5, 0.3, -3.0] m", "below the block's base")),
    },
    "machine's centre of mass below the base": {
        "block_foundation": (TWO, _set("machines", 1, "cog", [-2.0, -0.4, -2.7]),
                             ("machines[1].cog = [-2.0, -0.4, -2.7] m", "below the block's base")),
    },
    "unbalance beyond the footprint": {
        "block_foundation": (FAN, _set("machines", 0, "unbalance", "at", [4.3, 0.0, 2.7]),
                             ("machines[0].unbalance.at = [4.3, 0.0, 2.7] m", "outside the block's footprint")),
    },
}

CASES = [pytest.param(slip, kind, id=f"{slip}-{kind}") for slip, kinds in SLIPS.items() for kind in kinds]


def _flat(text: str) -> str:
    return " ".join(text.split())


def _checked(runner, path, *options):
    result = runner.invoke(app, ["check", path, "--json", "-j", "1", *options])
    return result, json.loads(result.stdout)["scenes"][0]


@pytest.mark.parametrize(("slip", "kind"), CASES)
def test_a_slip_warns_naming_the_users_key_in_every_kind_that_has_it(runner, tmp_path, slip, kind):
    config, change, wanted = SLIPS[slip][kind]
    path = _write(tmp_path, config, change)
    assert read_toml(path)["kind"] == kind
    result, scene = _checked(runner, path)
    assert any(all(text in w for text in wanted) for w in scene["warnings"]), (wanted, scene["warnings"])
    inputs = next(c for c in scene["checks"] if c["check"] == "inputs")
    assert inputs["verdict"] == "warn" and wanted[0] in " ".join(inputs["details"])
    strict, scene = _checked(runner, path, "--strict")  # the same warning fails with --strict
    assert next(c for c in scene["checks"] if c["check"] == "inputs")["verdict"] == "fail"
    assert strict.exit_code in (1, 3) and scene["exit_code"] == strict.exit_code
    command = ["platform"] if kind == "platform" else ["resonance"]
    shown = runner.invoke(app, [*command, path])
    assert wanted[0] in _flat(shown.stderr) and shown.exit_code in (0, 1, 3), shown.output


@pytest.mark.parametrize("change", [_set("limits", "velocity_rms", 2.8), _each()], ids=["a slip", "as shipped"])
def test_strict_fails_a_block_whose_only_finding_is_a_warning(runner, tmp_path, change):
    """The two-machine block passes every check: a warning alone makes --strict exit 1
    (docs/exit-codes.md), in `check` and in `resonance`; the scene as shipped has none and still passes."""
    path = _write(tmp_path, TWO, change)
    warned = bool(_checked(runner, path)[1]["warnings"])
    for command in (["check", "-j", "1"], ["resonance"]):
        assert runner.invoke(app, [*command, path]).exit_code == 0
        assert runner.invoke(app, [*command, path, "--strict"]).exit_code == (1 if warned else 0)
    document = json.loads(runner.invoke(app, ["resonance", path, "--json"]).stdout)
    assert bool(document["warnings"]) is warned


@pytest.mark.parametrize(("config", "change", "culprit"), [
    pytest.param(FAN, _modulus_in_mpa, "soil.shear_modulus = 72 Pa", id="shear modulus in MPa"),
    pytest.param(FAN, _sp26_in_mpa, "soil.deformation_modulus = 35 Pa", id="deformation modulus in MPa"),
    pytest.param(TWO, _BLOCK_IN_MM, "block.length = 7000 m", id="block in mm on given springs"),
])
def test_a_block_that_tips_over_from_a_slip_names_it(runner, tmp_path, config, change, culprit):
    path = _write(tmp_path, config, change)
    result = runner.invoke(app, ["resonance", path])
    error = _flat(result.stderr.split("error:", 1)[1])
    assert result.exit_code == 3 and "tips over" in error and f"likely culprit: {culprit}" in error, result.stderr
    assert "stiffen" not in error
    problems = [p for c in _checked(runner, path)[1]["checks"] for p in c.get("problems", [])]
    assert problems and all(p["field"] == culprit.split(" ")[0] for p in problems), problems


def test_a_block_that_tips_over_without_a_slip_names_the_key_of_its_rocking_springs(runner, tmp_path):
    path = _write(tmp_path, TWO, _set("soil", "stiffness", [8.4e9, 8.0e9, 1.05e10, 6.6e4, 1.6e5, 9.1e10]))
    result = runner.invoke(app, ["resonance", path])
    error = _flat(result.stderr)
    assert result.exit_code == 3 and "warning" not in error and "likely culprit" not in error
    assert "error: soil.stiffness: the block tips over about x" in error and "stiffen soil.stiffness" in error


#: The shipped scenes whose [soil] gives a density, of every kind.
WITH_DENSITY = sorted(p.name for p in CONFIGS.glob("*.toml") if "density" in read_toml(p).get("soil", {}))


@pytest.mark.parametrize("config", WITH_DENSITY)
def test_soil_density_in_t_per_m3_is_named_in_every_shipped_scene_that_gives_it(runner, tmp_path, config):
    """Every shipped scene whose [soil] gives a density warns about it typed in t/m³."""
    density = read_toml(CONFIGS / config)["soil"]["density"]
    path = _write(tmp_path, config, _set("soil", "density", round(density / 1000.0, 3)))
    assert "soil.density" in runner.invoke(app, ["check", path, "--json", "-j", "1"]).stdout


def _paths(model: type[BaseModel], prefix: str = "") -> set[str]:
    """Every key a scene of ``model`` can give, ``[]`` for a list index (as :data:`KEYS` writes them)."""
    found = set()
    for name, info in model.model_fields.items():
        key = f"{prefix}{name}"
        found.add(key)
        stack = [info.annotation]
        while stack:
            annotation = stack.pop()
            if isinstance(annotation, type) and issubclass(annotation, BaseModel):
                found |= _paths(annotation, f"{key}.")
            elif typing.get_origin(annotation) is list and typing.get_args(annotation):
                inner = typing.get_args(annotation)[0]
                if isinstance(inner, type) and issubclass(inner, BaseModel):
                    found |= _paths(inner, f"{key}[].")
            else:
                stack += typing.get_args(annotation)
    return found


def test_one_table_serves_every_kind():
    """Every scene kind is judged by the table (it is :class:`Plausible`), and every key of the
    table is a key some kind has (a row for a misspelt key would judge nothing)."""
    keys = set().union(*(_paths(model_for_kind(kind)) for kind in KINDS))
    assert all(issubclass(model_for_kind(kind), Plausible) for kind in KINDS)
    assert sorted(set(KEYS) - keys) == [] and sorted(set(INERTIA_KEYS) - keys) == []
    shared = ("limits.transient_amplitude", "operation.speed_rpm")
    kinds_with = {key: [kind for kind in KINDS if key in _paths(model_for_kind(kind))] for key in shared}
    assert kinds_with == {"limits.transient_amplitude": list(KINDS), "operation.speed_rpm": ["crank_foundation", "platform"]}
