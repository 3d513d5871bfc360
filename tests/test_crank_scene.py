"""Every validation rule of a crank_foundation scene: exit 3 and a message naming the field."""

from __future__ import annotations

import json

import tomli_w
import pytest

from foundation_calc.cli.app import app


def _write(tmp_path, doc, name="scene.toml"):
    path = tmp_path / name
    path.write_text(tomli_w.dumps(doc), encoding="utf-8")
    return path


def _set(doc, dotted, value):
    *parents, key = dotted.split(".")
    node = doc
    for p in parents:
        node = node[p]
    if value is _DELETE:
        del node[key]
    else:
        node[key] = value
    return doc


class _Deleted:
    """A value that removes its key. Its repr is the test id's, the same in every process (pytest-xdist
    requires each worker to collect the same ids; an object()'s repr holds its address)."""

    def __repr__(self) -> str:
        return "<deleted>"


_DELETE = _Deleted()

BROKEN = [
    # (dotted key, value, fragments the message must contain)
    ("foundation.mass", -1.0, ["foundation.mass", "must be > 0", "[kg]"]),
    ("foundation.moment_of_inertia", 0.0, ["foundation.moment_of_inertia", "[kg m²]"]),
    ("foundation.cog_height", 0.0, ["foundation.cog_height", "[m]"]),
    ("foundation.base_area", -30.0, ["foundation.base_area", "[m²]"]),
    ("foundation.base_second_moment", 0.0, ["foundation.base_second_moment", "[m⁴]"]),
    ("soil.c_z", 0.0, ["soil.c_z", "[N/m³]"]),
    ("soil.c_x", -2.8e7, ["soil.c_x", "[N/m³]"]),
    ("mechanism.crank_radius", 0.0, ["mechanism.crank_radius", "[m]"]),
    ("mechanism.rod_length", 0.3, ["mechanism.rod_length", "λ = r/l", "< 1"]),
    ("mechanism.rod_mass", 0.0, ["mechanism.rod_mass", "[kg]"]),
    ("mechanism.rod_cog_to_crank_pin", 1.2, ["mechanism.rod_cog_to_crank_pin", "0 < l' < l"]),
    ("mechanism.rod_cog_to_crank_pin", 0.0, ["mechanism.rod_cog_to_crank_pin", "must be > 0"]),
    ("mechanism.rod_radius_of_gyration", 0.0, ["mechanism.rod_radius_of_gyration", "[m]"]),
    ("mechanism.slider_mass", -1.0, ["mechanism.slider_mass", "[kg]"]),
    ("mechanism.rod_mass", 2.0e5, ["μ", "<= 0.5", "rod_mass"]),
    ("mechanism.speed_rpm", -300.0, ["mechanism.speed_rpm", "[rpm]"]),
    ("mechanism.speed_rpm", _DELETE, ["mechanism", "exactly one of omega"]),
    ("mechanism.omega", 31.4, ["mechanism", "omega and speed_rpm"]),
    ("mechanism.crank_radius", "0.3", ["mechanism.crank_radius", "must be a number"]),
    ("mechanism.crank_radius", float("nan"), ["mechanism.crank_radius", "finite"]),
    ("mechanism.drive_on_foundation", "yes", ["mechanism.drive_on_foundation", "must be true or false"]),
    ("mechanism.rod_lenght", 1.2, ["mechanism.rod_lenght", "unknown key"]),
    ("limits.detuning", 1.5, ["limits.detuning", "less than 1"]),
    ("limits.amplitude", 0.0, ["limits.amplitude", "[m]"]),
    ("kind", "crank", ["kind", "crank_foundation"]),
    ("schema_version", 7, ["schema_version"]),
    ("soil", _DELETE, ["soil", "missing", "c_z, c_x"]),
]


@pytest.mark.parametrize(
    ("key", "value", "fragments"), BROKEN, ids=[f"{k}={v!r}"[:40] for k, v, _ in BROKEN]
)
def test_broken_scene_exits_3_naming_the_field(tmp_path, runner, frame_saw, key, value, fragments):
    path = _write(tmp_path, _set(frame_saw, key, value))
    result = runner.invoke(app, ["resonance", str(path)])
    assert result.exit_code == 3, result.output
    assert result.stdout == ""
    for fragment in fragments:
        assert fragment in result.stderr, result.stderr
    assert "Traceback" not in result.stderr


def test_unstable_foundation_exits_3_with_a_remedy(tmp_path, runner, frame_saw):
    frame_saw["foundation"]["base_second_moment"] = 0.03
    result = runner.invoke(app, ["resonance", str(_write(tmp_path, frame_saw)), "--json"])
    assert result.exit_code == 3
    assert "unstable in rocking" in result.stderr
    assert "foundation.base_second_moment" in result.stderr
    assert json.loads(result.stdout)["problems"][0]["field"] == "foundation.base_second_moment"  # the error's document


def test_not_toml_and_missing_file_exit_3(tmp_path, runner):
    bad = tmp_path / "bad.toml"
    bad.write_text("kind = crank_foundation\n", encoding="utf-8")
    for path, fragment in ((bad, "not valid TOML"), (tmp_path / "none.toml", "cannot be read")):
        result = runner.invoke(app, ["resonance", str(path)])
        assert result.exit_code == 3
        assert fragment in result.stderr


def test_slider_mass_is_lumped_into_the_rod(frame_saw):
    from foundation_calc.scenes import parse_scene

    frame_saw["mechanism"]["slider_mass"] = 500.0
    rod = parse_scene(frame_saw).design().rod
    # combined centre of mass: (1500·1.0 + 500·1.2)/2000 from the crank pin
    assert rod.m == 2000.0
    assert rod.l1 == pytest.approx(1.05, rel=1e-15)
    # parallel-axis theorem: 1500 (0.35² + 0.05²) + 500·0.15², over 2000
    assert rod.rho**2 == pytest.approx((1500 * (0.35**2 + 0.05**2) + 500 * 0.15**2) / 2000, rel=1e-14)
