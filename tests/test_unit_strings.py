"""Numbers written with their unit in a scene (``length = "6000 mm"``, ``speed = "600 rpm"``): the
twin of every shipped scene with its numbers rewritten in other units gives the same scene, and
the same ``check --json`` / ``resonance --json`` / ``platform --json`` documents; a value of the
wrong dimension or no quantity at all is exit 3 naming the key and both dimensions.

The factors of :data:`OTHER_UNITS` are transcribed here from the SI definitions (1 t = 1000 kg,
1 rpm = 2π/60 rad/s, 1 Hz of a shaft = 2π rad/s, 1° = π/180 rad), not taken from the loader.
Tolerance 1e-12 relative: a decimal factor converts back exactly, an angle or a speed to within
a few ulps (1e-16), and the results are smooth in the inputs.
"""

from __future__ import annotations

import json
import math
from decimal import Decimal
import re
import subprocess
import sys

import pytest

from foundation_calc.cli.app import app
from foundation_calc.scenes import KINDS, parse_scene, read_toml
from foundation_calc.scenes.kinds import model_for_kind
from tests.conftest import CONFIGS

#: A key's declared unit -> (another unit, how many of it make one of the key's unit: exact
#: decimals as text, "1e3"; the angle and speed factors as floats).
OTHER_UNITS = {
    "m": ("mm", "1e3"), "m²": ("cm^2", "1e4"), "m⁴": ("cm^4", "1e8"), "kg": ("t", "1e-3"), "kg m²": ("t*m^2", "1e-3"),
    "kg/m³": ("t/m^3", "1e-3"), "N": ("kN", "1e-3"), "N m": ("kN m", "1e-3"), "N/m": ("kN/mm", "1e-6"),
    "N/m³": ("MN/m^3", "1e-6"), "N m/rad": ("MN*m/rad", "1e-6"), "N s/m": ("kN*s/m", "1e-3"),
    "N m s/rad": ("kN*m*s/rad", "1e-3"), "Pa": ("MPa", "1e-6"), "W": ("kW", "1e-3"), "s": ("ms", "1e3"),
    "m/s": ("mm/s", "1e3"), "m/s²": ("mm/s^2", "1e3"), "mm/s": ("m/s", "1e-3"), "rad": ("deg", 180 / math.pi),
    "rad/s": ("rpm", 60 / (2 * math.pi)), "Hz": ("rpm", "60"), "rpm": ("Hz", 1 / 60),
}

CONFIG_FILES = sorted(CONFIGS.glob("*.toml"))


def _units(field) -> list[str]:
    found = re.match(r"^[^\[]*\[([^\]]*)\]:", field.description or "")
    units = [u.strip() for u in found.group(1).split(",")] if found else []
    return units if units and all(u in OTHER_UNITS for u in units) else []


def _written(value, unit: str):
    if isinstance(value, bool) or not isinstance(value, (int, float)):
        return value
    other, factor = OTHER_UNITS[unit]
    if isinstance(factor, str):  # the decimal the user would type: 0.11 m is "110.00 mm", not 110.00000000000001
        return f"{Decimal(repr(float(value))) * Decimal(factor)} {other}"
    return f"{value * factor!r} {other}"


def _twin(model, table: dict) -> dict:
    """``table`` (of ``model``) with every number at a key with a unit written in another unit."""
    out = {}
    for key, value in table.items():
        field = model.model_fields.get({"speed": "omega"}.get(key, key))
        nested = _model_in(field.annotation) if field is not None else None
        if nested is not None:
            out[key] = [_twin(nested, v) for v in value] if isinstance(value, list) else _twin(nested, value)
            continue
        units = _units(field) if field is not None else []
        if not units:
            out[key] = value
        elif isinstance(value, list):
            per = len(value) // len(units)  # stiffness [N/m, N m/rad]: three forces, three moments
            out[key] = [_written(v, units[i // per]) for i, v in enumerate(value)]
        else:
            out[key] = _written(value, units[0])
    return out


def _model_in(annotation):
    from pydantic import BaseModel

    if isinstance(annotation, type) and issubclass(annotation, BaseModel):
        return annotation
    return next(filter(None, map(_model_in, getattr(annotation, "__args__", ()) or ())), None)


def twin_of(document: dict) -> dict:
    return _twin(model_for_kind(document["kind"]), document)


def _strings(node) -> int:
    if isinstance(node, dict):
        return sum(map(_strings, node.values()))
    if isinstance(node, list):
        return sum(map(_strings, node))
    return int(isinstance(node, str) and bool(re.match(r"^-?[\d.]", node)))


def _largest(node, key: str = "", found: dict | None = None) -> dict:
    """The largest magnitude of each quantity (numbers by their key's name) in a document."""
    found = {} if found is None else found
    if isinstance(node, dict):
        for k, v in node.items():
            _largest(v, k, found)
    elif isinstance(node, list):
        for v in node:
            _largest(v, key, found)
    elif isinstance(node, float):
        found[key] = max(found.get(key, 0.0), abs(node))
    return found


def assert_same(a, b, where: str = "", scale: dict | None = None, key: str = "") -> None:
    """Equal documents: numbers to 1e-12 of the largest value of the same quantity (a share of
    1e-17 beside shares of 0.9 is round-off, as in any two orders of summation; so is the phase of
    a harmonic of round-off magnitude), the rest exactly."""
    scale = _largest(a) if scale is None else scale
    if isinstance(a, dict):
        assert isinstance(b, dict) and a.keys() == b.keys(), where
        noise = "magnitude" in a and abs(a["magnitude"]) <= 1e-12 * scale.get("magnitude", 0.0)
        for k in a:
            path = k in ("source", "scene") and isinstance(a[k], str)  # the file's path
            if not path and not (noise and k == "phase"):
                assert_same(a[k], b[k], f"{where}.{k}", scale, k)
    elif isinstance(a, list):
        assert isinstance(b, list) and len(a) == len(b), where
        for i, (x, y) in enumerate(zip(a, b)):
            assert_same(x, y, f"{where}[{i}]", scale, key)
    elif isinstance(a, float) and isinstance(b, float):
        assert abs(a - b) <= 1e-12 * max(abs(a), abs(b), scale.get(key, 0.0)), (where, a, b)
    else:
        assert a == b, where


@pytest.mark.parametrize("config", CONFIG_FILES, ids=lambda p: p.name)
def test_the_twin_with_units_is_the_same_scene(config):
    """Every number at a key with a unit (tens per scene) rewritten: the validated scenes agree."""
    document = read_toml(config)
    twin = twin_of(document)
    assert _strings(twin) >= 5
    si = parse_scene(document, str(config)).model_dump()
    assert_same(si, parse_scene(twin, "twin").model_dump())


def _write(path, document: dict) -> None:
    import tomli_w

    path.write_text(tomli_w.dumps(document), encoding="utf-8")


#: One shipped scene per kind, run end to end through the commands (each takes a second or two).
END_TO_END = [
    ("compressor_damped_near_resonance.toml", ("check", "resonance")),
    ("block_two_machines.toml", ("check", "resonance")),
    ("platform_damped.toml", ("check", "platform")),
]


@pytest.mark.parametrize(("config", "commands"), END_TO_END, ids=[c for c, _ in END_TO_END])
def test_commands_give_the_same_documents_for_the_twin(runner, tmp_path, config, commands):
    document = read_toml(CONFIGS / config)
    si, twin = tmp_path / "si.toml", tmp_path / "twin.toml"
    _write(si, document)
    _write(twin, twin_of(document))
    for command in commands:
        first = runner.invoke(app, [command, "--json", str(si)])
        second = runner.invoke(app, [command, "--json", str(twin)])
        assert first.exit_code in (0, 1) and second.exit_code == first.exit_code, second.output
        assert_same(json.loads(first.stdout), json.loads(second.stdout), command)
        assert second.stderr == first.stderr.replace(str(si), str(twin))  # the same warnings, if any


@pytest.mark.parametrize(
    ("key", "written", "expected"),
    [
        ("speed_rpm", "10 Hz", 600.0),  # a shaft at 10 revolutions per second
        ("omega", "600 rpm", 20 * math.pi),
        ("frequency_hz", "600 rpm", 10.0),
        ("omega", "10 Hz", 20 * math.pi),
        ("speed_rpm", "62.83185307179586 rad/s", 600.0),
        ("speed_rpm", "600 rev/min", 600.0),
        ("omega", "3600 deg/s", 20 * math.pi),
    ],
)
def test_a_speed_goes_to_the_unit_of_its_key(key, written, expected):
    document = read_toml(CONFIGS / "block_two_machines.toml")
    machine = {k: v for k, v in document["machines"][0].items() if k not in ("omega", "frequency_hz", "speed_rpm")}
    document["machines"][0] = {**machine, key: written}
    scene = parse_scene(document)
    assert math.isclose(getattr(scene.machines[0], key), expected, rel_tol=1e-12)


def test_the_issue_examples(tmp_path):
    """``speed = "600 rpm"``, ``force = ["6 kN", 0, "2 kN"]``, ``density = "1.8 t/m^3"``, µm and um."""
    document = read_toml(CONFIGS / "block_two_machines.toml")
    machine = {k: v for k, v in document["machines"][0].items() if k != "speed_rpm"}
    load = {**machine["loads"][0], "force": ["6 kN", 0, "2 kN"], "phase": "90 deg"}
    document["machines"][0] = {**machine, "speed": "600 rpm", "loads": [load], "cog": ["1200 mm", "300000 µm", "2.9e6 um"]}
    document["block"] = {**document["block"], "density": "1.8 t/m^3", "length": "6000 mm"}
    scene = parse_scene(document)
    machine = scene.machines[0]
    assert math.isclose(machine.omega, 20 * math.pi, rel_tol=1e-12)
    assert list(machine.loads[0].force) == pytest.approx([6000.0, 0.0, 2000.0], rel=1e-12)
    assert machine.loads[0].phase == pytest.approx(math.pi / 2, rel=1e-12)
    assert list(machine.cog) == pytest.approx([1.2, 0.3, 2.9], rel=1e-12)
    assert (scene.block.density, scene.block.length) == pytest.approx((1800.0, 6.0), rel=1e-12)


def test_a_length_written_in_mm_is_not_implausible():
    """The plausibility table judges the converted value: 6000 mm is a 6 m block, no warning."""
    document = read_toml(CONFIGS / "block_two_machines.toml")
    document["block"] = {**document["block"], "length": "7000 mm", "width": "400 cm"}
    assert parse_scene(document).plausibility_warnings() == []


#: kind -> (shipped scene, dotted key, where to write it, the value, words the message must hold).
WRONG = [
    ("compressor_near_resonance.toml", "foundation.mass", ("foundation", "mass"), "72 MPa",
     ("a pressure", "a mass [kg]")),
    ("block_two_machines.toml", "block.length", ("block", "length"), "72 MPa", ("a pressure", "a length [m]")),
    ("block_two_machines.toml", "machines.0.loads.0.force.1", ("machines", 0, "loads", 0, "force", 1), "3 m",
     ("a length", "a force [N]")),
    ("platform_paper_example.toml", "platform.cog.2", ("platform", "cog", 2), "2 kg", ("a mass", "a length [m]")),
    ("platform_paper_example.toml", "operation.omega", ("operation", "omega"), "157 m",
     ("a length", "[rad/s]")),
    # a count per minute without what is counted: revolutions (rpm) and radians are 2π apart
    ("compressor_near_resonance.toml", "mechanism.speed_rpm", ("mechanism", "speed_rpm"), "600 1/min",
     ("does not say what turns", "[rpm]")),
    # speed is another name of omega: named as the field, once
    ("block_two_machines.toml", "machines.1.omega", ("machines", 1, "speed"), "1490 kg",
     ("a mass", "[rad/s]", "(written as speed)")),
]


def _put(document: dict, where: tuple, value) -> None:
    node = document
    for part in where[:-1]:
        node = node[part]
    node[where[-1]] = value


@pytest.mark.parametrize(("config", "key", "where", "value", "words"), WRONG, ids=[w[1] for w in WRONG])
def test_a_value_of_the_wrong_dimension_is_exit_3_naming_the_key(runner, tmp_path, config, key, where, value, words):
    document = read_toml(CONFIGS / config)
    _put(document, where, value)
    path = tmp_path / "wrong.toml"
    _write(path, document)
    result = runner.invoke(app, ["check", str(path)])
    assert result.exit_code == 3
    lines = [line for line in result.stderr.splitlines() if line.strip().startswith(f"{key}:")]
    assert len(lines) == 1 and value in lines[0] and all(word in lines[0] for word in words), result.stderr


@pytest.mark.parametrize("kind_config", ["compressor_near_resonance.toml", "block_two_machines.toml",
                                         "platform_paper_example.toml"])
@pytest.mark.parametrize("value", ["abc", "6000", "12 furlongs per fortnight", "3 m ]]", "1e400 m", "9e999999 km",
                                   "__import__('os') m"])
def test_a_string_that_is_no_quantity_is_exit_3_naming_the_key(runner, tmp_path, kind_config, value):
    document = read_toml(CONFIGS / kind_config)
    table = next(name for name in ("foundation", "block", "platform") if name in document)
    key = next(k for k in ("mass", "length") if isinstance(document[table].get(k), (int, float)))
    document[table][key] = value
    path = tmp_path / "wrong.toml"
    _write(path, document)
    result = runner.invoke(app, ["check", str(path)])
    assert result.exit_code == 3, result.output
    line = next(line for line in result.stderr.splitlines() if line.strip().startswith(f"{table}.{key}:"))
    assert "this key is a" in line and ("[kg]" in line or "[m]" in line), line
    assert "Traceback" not in result.output


def test_units_library_is_loaded_only_for_a_value_with_a_unit(tmp_path):
    """A scene of bare numbers (and names, methods) never imports pint; one unit string does."""
    document = read_toml(CONFIGS / "block_two_machines.toml")
    twin = tmp_path / "twin.toml"
    document["block"]["length"] = "7 m"
    _write(twin, document)
    probe = (
        "import sys; from foundation_calc.scenes import load_scene\n"
        "for path in sys.argv[1:]: load_scene(path); print('pint' in sys.modules)"
    )
    run = subprocess.run([sys.executable, "-c", probe, str(CONFIGS / "block_two_machines.toml"), str(twin)],
                         capture_output=True, text=True, check=True)
    assert run.stdout.split() == ["False", "True"]


@pytest.mark.parametrize("kind", sorted(KINDS))
def test_names_and_methods_are_left_as_text(kind):
    """Keys without a unit (names, methods, codes) are never read as quantities."""
    config = next(p for p in CONFIG_FILES if read_toml(p)["kind"] == kind)
    document = read_toml(config)
    assert parse_scene(twin_of(document)).name == document["name"]


@pytest.mark.parametrize("config", CONFIG_FILES, ids=lambda p: p.name)
def test_the_schema_takes_numbers_with_their_unit(runner, config):
    """``fcalc schema``: the twin validates as the SI scene does; text that is no number with a
    unit, or a unit at a key without one (a name), does not."""
    jsonschema = pytest.importorskip("jsonschema")
    document = read_toml(config)
    result = runner.invoke(app, ["schema", document["kind"]])
    validator = jsonschema.Draft202012Validator(json.loads(result.stdout))
    assert not list(validator.iter_errors(twin_of(document)))
    twin = twin_of(document)
    table, key = next((t, k) for t, v in twin.items() if isinstance(v, dict) for k in v if isinstance(v[k], str)
                      and isinstance(document[t][k], (int, float)))
    for text in ("abc", "6000", "mm 6000"):
        assert list(validator.iter_errors({**document, table: {**document[table], key: text}})), text


@pytest.mark.parametrize("kind", sorted(KINDS))
def test_the_template_shows_the_written_form_and_it_loads(kind):
    """``fcalc init``: the header shows numbers with their unit; its examples load as it says."""
    from foundation_calc.scenes.template import scene_template

    header = [line for line in scene_template(kind).splitlines() if line.startswith("#")][:8]
    shown = " ".join(header)
    assert 'length = "6000 mm"' in shown and 'speed_rpm = "10 Hz"' in shown
    document = read_toml(CONFIGS / "block_two_machines.toml")
    machine = {k: v for k, v in document["machines"][0].items() if k != "speed_rpm"}
    load = {**machine["loads"][0], "force": ["6 kN", 0, "2 kN"], "phase": "90 deg"}
    document["machines"][0] = {**machine, "speed_rpm": "10 Hz", "loads": [load]}
    document["block"] = {**document["block"], "length": "6000 mm", "density": "2.4 t/m^3"}
    scene = parse_scene(document)
    assert (scene.block.length, scene.block.density, scene.machines[0].speed_rpm) == pytest.approx((6.0, 2400.0, 600.0))


def _input_rows(sheet) -> list[tuple[str, ...]]:
    section = next(s for s in sheet.sections if s.title.startswith("Inputs"))
    return [row for block in section.blocks for row in getattr(block, "rows", ())]


def test_the_sheet_shows_each_value_as_written_beside_its_value_in_the_keys_unit(tmp_path):
    """``fcalc report``: ``length = "7000 mm"`` is the row ``length | L | 7 (written 7000 mm) | m``;
    in a list, each element as written (a bare number as the sheet prints it); ``speed = "600 rpm"``
    is the row of omega; a scene of bare numbers shows no "written"."""
    from foundation_calc.output.display_units import DisplayUnits
    from foundation_calc.output.report.documents import scene_sheet

    document = read_toml(CONFIGS / "block_two_machines.toml")
    machine = {k: v for k, v in document["machines"][0].items() if k != "speed_rpm"}
    load = {**machine["loads"][0], "force": ["6 kN", 0.0, "2 kN"]}
    document["machines"][0] = {**machine, "speed": "600 rpm", "mass": "12 t", "loads": [load, *machine["loads"][1:]]}
    document["block"] = {**document["block"], "length": "7000 mm"}
    path = tmp_path / "written.toml"
    _write(path, document)
    rows = _input_rows(scene_sheet(path, "fcalc report", DisplayUnits(), figures=False)[0])
    assert ("length", "L", "7 (written 7000 mm)", "m") in [row[:4] for row in rows]
    assert ("mass", "m_m", "12000 (written 12 t)", "kg") in [row[:4] for row in rows]
    assert ("omega", "ω", "62.8319 (written 600 rpm)", "rad/s") in [row[:4] for row in rows]
    assert any("6000, 0, 2000 (written 6 kN, 0, 2 kN)" in row for row in rows), rows
    _write(path, read_toml(CONFIGS / "block_two_machines.toml"))
    rows = _input_rows(scene_sheet(path, "fcalc report", DisplayUnits(), figures=False)[0])
    assert rows and not any("written" in cell for row in rows for cell in row)


def test_design_varies_and_writes_back_a_scene_written_with_units(runner, tmp_path):
    """``fcalc design --write`` on a block written in mm: the varied length is written as a number
    [m], the keys it leaves alone keep their text ("2.4 t/m^3")."""
    document = read_toml(CONFIGS / "block_two_machines.toml")
    document["block"] = {**document["block"], "length": "7000 mm", "density": "2.4 t/m^3"}
    scene, best = tmp_path / "written.toml", tmp_path / "best.toml"
    _write(scene, document)
    result = runner.invoke(app, ["design", str(scene), "--vary", "block.length=6:7", "--step", "0.5", "--write", str(best)])
    assert result.exit_code == 0, result.output
    written = read_toml(best)["block"]
    assert isinstance(written["length"], float) and written["density"] == "2.4 t/m^3"


def _fuzz_examples() -> int:
    import os

    return int(os.environ.get("FCALC_FUZZ_EXAMPLES", "20"))


def test_any_text_at_a_key_with_a_unit_is_a_value_or_a_scene_error():
    """Text of any shape (a number and unit-like characters, or anything) either converts or is a
    SceneError naming the key; never another exception (pint's parser raises many kinds)."""
    from hypothesis import given, settings
    from hypothesis import strategies as st

    from foundation_calc.errors import SceneError

    document = read_toml(CONFIGS / "block_two_machines.toml")
    unit_like = st.text(alphabet="0123456789.eE+-*/^()_ µ°%²³kmMgGtNPaWsHzrpdeg1", max_size=14)

    @settings(max_examples=_fuzz_examples(), deadline=None, database=None)
    @given(st.one_of(unit_like, st.text(max_size=20), st.tuples(st.floats(allow_nan=False), unit_like).map(lambda pair: f"{pair[0]!r} {pair[1]}")))
    def check(text):
        try:
            parse_scene({**document, "block": {**document["block"], "length": text}})
        except SceneError as exc:
            assert any(where == "block.length" for where, _ in exc.problems), exc.problems

    check()
