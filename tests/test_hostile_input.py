"""Hostile input: whatever is in a scene file, fcalc ends with a clear message and exit 3.

Property tests throw random TOML documents, random values at every key of the shipped scenes,
random bytes, deep nesting and odd files at the loader (``load_scene``) and at the command line
(``fcalc check`` / ``fcalc resonance`` through CliRunner). The only acceptable endings are a
valid scene, a :class:`SceneError` / :class:`PhysicsError` (exit 3) whose problems name a
field, or a check verdict; never another exception, never a traceback, never NaN in JSON.
"""

from __future__ import annotations

import copy
import json
import math

import pytest
import tomli_w
from hypothesis import HealthCheck, example, given, settings
from hypothesis import strategies as st

from foundation_calc.checks.registry import CHECKS
from foundation_calc.cli.app import app
from foundation_calc.errors import FcalcError, SceneError
from foundation_calc.output.check_report import result_document
from foundation_calc.scenes import load_scene, parse_scene, read_toml
from foundation_calc.scenes.files import MAX_SCENE_BYTES
from tests.conftest import CONFIGS

SEEDS = {path.name: read_toml(path) for path in sorted(CONFIGS.glob("*.toml"))}
FAST = settings(max_examples=60, deadline=None, suppress_health_check=[HealthCheck.function_scoped_fixture])

# --- strategies --------------------------------------------------------------------------------

numbers = st.one_of(
    st.floats(allow_nan=True, allow_infinity=True),
    st.floats(min_value=-1e-300, max_value=1e-300),
    st.sampled_from([0.0, -0.0, 1e308, -1e308, 5e-324, 1e15, 1.0000001e15, 1e-15, 9.9e-16]),
    st.integers(min_value=-(2**63), max_value=2**63 - 1),
)
scalars = st.one_of(numbers, st.booleans(), st.text(max_size=30), st.datetimes(), st.dates())
toml_values = st.recursive(
    scalars,
    lambda inner: st.one_of(st.lists(inner, max_size=4), st.dictionaries(st.text(max_size=12), inner, max_size=4)),
    max_leaves=12,
)
documents = st.dictionaries(st.text(max_size=12), toml_values, max_size=6)


def _leaf_paths(document: dict, prefix: tuple = ()) -> list[tuple]:
    """Every key path of a scene document, tables included."""
    paths = []
    for key, value in document.items():
        paths.append(prefix + (key,))
        if isinstance(value, dict):
            paths.extend(_leaf_paths(value, prefix + (key,)))
    return paths


def _mutate(document: dict, path: tuple, value) -> dict:
    """A copy of ``document`` with the key at ``path`` set to ``value`` (deleted for None)."""
    mutated = copy.deepcopy(document)
    node = mutated
    for key in path[:-1]:
        node = node[key]
    if value is None:
        del node[path[-1]]
    else:
        node[path[-1]] = value
    return mutated


@st.composite
def mutated_scenes(draw):
    """A shipped scene with one key replaced by a hostile value or removed, and that key's path."""
    seed = SEEDS[draw(st.sampled_from(sorted(SEEDS)))]
    path = draw(st.sampled_from(_leaf_paths(seed)))
    value = draw(st.one_of(st.none(), toml_values))
    return _mutate(seed, path, value), path


def _finite(node) -> bool:
    if isinstance(node, dict):
        return all(_finite(v) for v in node.values())
    if isinstance(node, (list, tuple)):
        return all(_finite(v) for v in node)
    return not isinstance(node, float) or math.isfinite(node)


def _assert_clean_exit3(result) -> None:
    assert result.exit_code == 3, (result.exit_code, result.output)
    assert "Traceback" not in result.output and "internal error" not in result.output


# --- the loader ----------------------------------------------------------------------------------


@FAST
@given(documents)
@example({"kind": "crank_foundation", "foundation": {"mass": float("nan")}})
@example({"kind": ["crank_foundation"]})
@example({"kind": {"a": 1}})
def test_random_documents_end_in_a_scene_error(document):
    with pytest.raises(SceneError) as info:
        parse_scene(document, "random.toml")
    assert info.value.problems and all(isinstance(msg, str) and msg for _, msg in info.value.problems)


@settings(max_examples=50, deadline=None)
@given(mutated_scenes())
@example((_mutate(SEEDS["frame_saw_extra_resonance.toml"], ("foundation", "moment_of_inertia"), 1e308), ("foundation",)))
@example((_mutate(SEEDS["frame_saw_extra_resonance.toml"], ("soil", "c_x"), 5e-324), ("soil",)))
@example((_mutate(SEEDS["frame_saw_extra_resonance.toml"], ("mechanism", "crank_axis_to_cog"), 1e308), ("mechanism",)))
@example((_mutate(SEEDS["frame_saw_extra_resonance.toml"], ("foundation", "mass"), 10**30), ("foundation",)))
def test_one_hostile_value_is_named_or_checked(case):
    """Any one value replaced: a SceneError naming that key's table, or every check runs cleanly."""
    document, path = case
    try:
        scene = parse_scene(document, "mutated.toml")
    except SceneError as exc:
        named = " ".join(loc for loc, _ in exc.problems)
        assert path[0] in named or "kind" in named or exc.problems[0][0] == "", exc.problems
        return
    for check in CHECKS[scene.kind].values():
        try:
            finding = check(scene)
        except FcalcError as exc:  # an impossible design: exit 3 with a message
            assert str(exc)
            continue
        if finding is None:  # nothing for this check to judge in the scene
            continue
        document = result_document(finding.check, finding.report, scene)
        assert _finite(document) and _finite(dict(finding.values))


def _numeric_paths(document: dict) -> list[tuple]:
    paths = []
    for path in _leaf_paths(document):
        value = document
        for key in path:
            value = value[key]
        if isinstance(value, (int, float)) and not isinstance(value, bool):
            paths.append(path)
    return paths


@st.composite
def rescaled_scenes(draw, kind=None):
    """A shipped scene with several numbers replaced by any magnitude the loader accepts."""
    names = sorted(name for name, seed in SEEDS.items() if kind in (None, seed["kind"]))
    seed = SEEDS[draw(st.sampled_from(names))]
    magnitude = st.one_of(st.floats(-15, 15).map(lambda e: 10.0**e), st.sampled_from([1e-15, 1e15, 1.0]))
    changes = draw(st.lists(st.tuples(st.sampled_from(_numeric_paths(seed)), magnitude), min_size=1, max_size=12))
    document = seed
    for path, value in changes:
        document = _mutate(document, path, value)
    return document


#: A crash found by the property below, kept as a regression case: a platform 1e15 m long with a
#: 0.1 mm eccentricity gave numpy LinAlgError (exit 4) in the 6-DOF natural frequencies (Cholesky
#: of the mass matrix); rotations are now scaled by the platform's size before the eigen-solve.
PLATFORM_HUGE_LENGTH = _mutate(
    _mutate(SEEDS["platform_explicit_vertical.toml"], ("platform", "length"), 1e15), ("exciter", "eccentricity"), 1e-4
)


def test_pinned_platform_crash_with_a_huge_length():
    _numbers_never_crash_a_check(PLATFORM_HUGE_LENGTH)


#: Draws that once ended the start-up check of the run-up scene in NaN/inf: a rod radius of gyration
#: of 1e15 m and a base area of 1e-15 m² leave the averaged operator singular; both must now end in
#: a per-scene exit 3 naming the cause (conditioning / no stable rest position).
RUNUP_SINGULAR = [
    _mutate(SEEDS["frame_saw_soft_soil_runup.toml"], ("mechanism", "rod_radius_of_gyration"), 1e15),
    _mutate(SEEDS["frame_saw_soft_soil_runup.toml"], ("foundation", "base_area"), 1e-15),
]
#: A rotor so light that (3.14) rounds c0 to M ω² exactly: the exciter height (3.11) divides by 0.
PLATFORM_VANISHING_ROTOR = _mutate(_mutate(SEEDS["platform_damped.toml"], ("exciter", "rotor_mass"), 1e-15),
                                   ("operation", "amplitude"), 1e-12)


@pytest.mark.parametrize("document", RUNUP_SINGULAR, ids=["rod_radius_of_gyration", "base_area"])
def test_singular_runup_scene_ends_in_exit_3_without_nan(runner, tmp_path, document):
    scene = tmp_path / "singular.toml"
    scene.write_text(tomli_w.dumps(document), encoding="utf-8")
    result = runner.invoke(app, ["check", str(scene), "--json"])
    assert result.exit_code == 3, result.output
    assert "Traceback" not in result.output
    doc = json.loads(result.stdout)
    assert _finite(doc)
    invalid = [c for s in doc["scenes"] for c in s["checks"] if c["verdict"] == "invalid"]
    assert invalid and all(c["problems"] for c in invalid), invalid


#: A draw that overflowed (RuntimeWarning, an error in the suite) in the series of θ - sin θ,
#: evaluated where its value is not used: a rotation of 1e13 rpm on a block of no inertia.
CRANK_HUGE_ROTATION = _mutate(
    _mutate(SEEDS["vertical_compressor.toml"], ("foundation", "moment_of_inertia"), 1e-15), ("mechanism", "speed_rpm"), 1e13
)


@settings(max_examples=30, deadline=None)
@given(rescaled_scenes())
@example(CRANK_HUGE_ROTATION)
@example(RUNUP_SINGULAR[0])
@example(RUNUP_SINGULAR[1])
@example(PLATFORM_VANISHING_ROTOR)
def test_numbers_the_loader_accepts_never_crash_a_check(document):
    """Within the accepted magnitudes every check ends in a finite verdict or an FcalcError (exit 3)."""
    _numbers_never_crash_a_check(document)


def _numbers_never_crash_a_check(document):
    try:
        scene = parse_scene(document, "rescaled.toml")
    except SceneError:
        return
    for check in CHECKS[scene.kind].values():
        try:
            finding = check(scene)
        except FcalcError:
            continue
        if finding is None:
            continue
        document = result_document(finding.check, finding.report, scene)
        assert _finite(document) and _finite(dict(finding.values))


@settings(max_examples=40, deadline=None, suppress_health_check=[HealthCheck.function_scoped_fixture])
@given(mutated_scenes())
def test_hostile_values_through_the_command_line(runner, tmp_path, case):
    document, _ = case
    scene = tmp_path / "hostile.toml"
    scene.write_text(tomli_w.dumps(document), encoding="utf-8")
    result = runner.invoke(app, ["check", str(scene), "--json"])
    assert result.exit_code in (0, 1, 3), result.output
    assert "Traceback" not in result.output
    doc = json.loads(result.stdout)  # one JSON document, even for a broken scene
    assert _finite(doc)


@settings(max_examples=60, deadline=None, suppress_health_check=[HealthCheck.function_scoped_fixture])
@given(st.binary(max_size=200))
@example(b"\xff\xfe\x00k\x00i\x00n\x00d")
@example(b"kind = 'crank_foundation'\n\x00")
def test_random_bytes(tmp_path, raw):
    scene = tmp_path / "bytes.toml"
    scene.write_bytes(raw)
    with pytest.raises(SceneError) as info:
        load_scene(scene)
    assert info.value.problems


# --- odd files -----------------------------------------------------------------------------------

ODD_FILES = {
    "empty": (b"", "is empty"),
    "only_comments": (b"# nothing here\n\n", "is empty"),
    "deep_arrays": (b"kind = " + b"[" * 5000 + b"]" * 5000, "not valid TOML"),
    "deep_inline_tables": (b"kind = " + b"{a = " * 3000 + b"1" + b"}" * 3000, "not valid TOML"),
    "deep_table_headers": (b"[" + b".".join([b"a"] * 3000) + b"]\n", "kind: missing: no kind line; it must be one of"),
    "not_utf8": ("kind = 'crank_foundation' # Säge\n".encode("latin-1"), "not UTF-8"),
    "utf16": ("kind = 'crank_foundation'\n".encode("utf-16"), "not UTF-8"),
    "binary_zeros": (b"\x00" * 64, "not valid TOML"),
    "too_large": (b"# " + b"x" * MAX_SCENE_BYTES + b"\n", "bytes"),
    "duplicate_key": (b"kind = 'crank_foundation'\nkind = 'platform'\n", "not valid TOML"),
    "unicode_kind": ("kind = 'крэнк_фаундейшн ✓'\n".encode(), "kind: must be one of"),
}


@pytest.mark.parametrize("name", sorted(ODD_FILES))
def test_odd_files(runner, tmp_path, name):
    raw, fragment = ODD_FILES[name]
    scene = tmp_path / f"{name}.toml"
    scene.write_bytes(raw)
    with pytest.raises(SceneError) as info:
        load_scene(scene)
    assert fragment in str(info.value)
    for command in (["resonance", str(scene)], ["check", str(scene)]):
        result = runner.invoke(app, command)
        _assert_clean_exit3(result)
        assert fragment.split(":")[0] in result.output.replace("\n", "")


def test_byte_order_mark_is_accepted(tmp_path):
    scene = tmp_path / "bom.toml"
    scene.write_bytes(b"\xef\xbb\xbf" + (CONFIGS / "frame_saw_extra_resonance.toml").read_bytes())
    assert load_scene(scene).kind == "crank_foundation"


@pytest.mark.parametrize("make", ["folder", "missing", "device"])
def test_paths_that_are_not_scene_files(runner, tmp_path, make):
    path = {"folder": tmp_path, "missing": tmp_path / "missing.toml", "device": "/dev/zero"}[make]
    fragment = {"folder": "is a folder", "missing": "cannot be read", "device": "bytes"}[make]
    with pytest.raises(SceneError, match=fragment):
        load_scene(path)
    _assert_clean_exit3(runner.invoke(app, ["resonance", str(path)]))


# --- malformed scenes and their messages ---------------------------------------------------------

#: (id, key path, new value or None to delete, fragments that the message must contain)
MALFORMED = [
    ("negative_mass", ("foundation", "mass"), -1.0, ["foundation.mass", "must be > 0", "[kg]"]),
    ("zero_area", ("foundation", "base_area"), 0.0, ["foundation.base_area", "must be > 0", "[m²]"]),
    ("mass_as_text", ("foundation", "mass"), "heavy", ["foundation.mass", "must be a number", "[kg]"]),
    ("mass_as_pressure", ("foundation", "mass"), "100 MPa", ["foundation.mass", "a pressure", "a mass [kg]"]),
    ("mass_as_bool", ("foundation", "mass"), True, ["foundation.mass", "must be a number"]),
    ("mass_as_list", ("foundation", "mass"), [1.0, 2.0], ["foundation.mass", "must be a number"]),
    ("nan_stiffness", ("soil", "c_z"), float("nan"), ["soil.c_z", "finite", "[N/m³]"]),
    ("inf_stiffness", ("soil", "c_x"), float("inf"), ["soil.c_x", "finite", "[N/m³]"]),
    ("huge_inertia", ("foundation", "moment_of_inertia"), 1e308, ["foundation.moment_of_inertia", "magnitude", "[kg m²]"]),
    ("tiny_shear", ("soil", "c_x"), 5e-324, ["soil.c_x", "magnitude", "1e-15"]),
    ("huge_integer", ("foundation", "mass"), 10**30, ["foundation.mass", "[kg]"]),
    ("missing_mass", ("foundation", "mass"), None, ["foundation.mass", "missing", "allowed > 0", "[kg]"]),
    ("missing_soil", ("soil",), None, ["soil", "missing (a table with c_z, c_x", "method"]),
    ("soil_not_table", ("soil",), 5, ["soil", "must be a table"]),
    ("typo_key", ("foundation", "masse"), 1.0, ["foundation.masse", "unknown key"]),
    ("unknown_table", ("damping",), {"ratio": 0.05}, ["damping", "unknown key"]),
    ("rod_shorter_than_crank", ("mechanism", "rod_length"), 0.2, ["mechanism.rod_length", "crank_radius", "[m]"]),
    ("cog_off_the_rod", ("mechanism", "rod_cog_to_crank_pin"), 1.5, ["mechanism.rod_cog_to_crank_pin", "rod_length"]),
    ("two_speeds", ("mechanism", "omega"), 30.0, ["mechanism", "exactly one of", "[rad/s]", "[rpm]"]),
    ("no_speed", ("mechanism", "speed_rpm"), None, ["mechanism", "exactly one of"]),
    ("speed_negative", ("mechanism", "speed_rpm"), -300, ["mechanism.speed_rpm", "must be > 0", "[rpm]"]),
    ("slider_negative", ("mechanism", "slider_mass"), -1.0, ["mechanism.slider_mass", "must be >= 0"]),
    ("drive_as_text", ("mechanism", "drive_on_foundation"), "yes", ["mechanism.drive_on_foundation", "must be true or false"]),
    ("heavy_rod", ("mechanism", "rod_mass"), 2.0e5, ["mechanism.rod_mass", "μ", "0.5"]),
    ("detuning_too_big", ("limits", "detuning"), 1.5, ["limits.detuning", "less than 1"]),
    ("amplitude_zero", ("limits", "amplitude"), 0.0, ["limits.amplitude", "must be > 0", "[m]"]),
    ("long_name", ("name",), "x" * 500, ["name", "200"]),
    ("unknown_kind", ("kind",), "crank_fundation", ["kind", "must be one of", "crank_foundation"]),
    ("no_kind", ("kind",), None, ["kind", "missing"]),
    ("future_schema", ("schema_version",), 2, ["schema_version", "1"]),
    ("unicode_value", ("foundation", "mass"), "１００", ["foundation.mass", "must be a number"]),
]


@pytest.mark.parametrize("path, value, fragments", [m[1:] for m in MALFORMED], ids=[m[0] for m in MALFORMED])
def test_malformed_scene_messages(runner, tmp_path, frame_saw, path, value, fragments):
    scene = tmp_path / "malformed.toml"
    scene.write_text(tomli_w.dumps(_mutate(frame_saw, path, value)), encoding="utf-8")
    with pytest.raises(SceneError) as info:
        load_scene(scene)
    message = str(info.value)
    for fragment in fragments:
        assert fragment in message, (fragment, message)
    for command in (["resonance", str(scene)], ["check", str(scene)]):
        result = runner.invoke(app, command)
        _assert_clean_exit3(result)
        assert fragments[0] in result.output


def test_impossible_design_is_exit3_with_the_field(runner, tmp_path, frame_saw):
    """Valid numbers, but the block overturns on the soil: a PhysicsError naming the field."""
    frame_saw["foundation"]["base_second_moment"] = 1e-3
    scene = tmp_path / "unstable.toml"
    scene.write_text(tomli_w.dumps(frame_saw), encoding="utf-8")
    for command in (["resonance", str(scene)], ["check", str(scene)]):
        result = runner.invoke(app, command)
        _assert_clean_exit3(result)
        assert "base_second_moment" in result.output.replace("\n", "")
