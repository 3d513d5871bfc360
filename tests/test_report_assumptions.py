"""The block foundation's assumptions and limitations, generated from what its scene uses.

Each row is compared with the scene's own facts, not with the sheet's wording of them: the soil
method's frequency dependence (``soil.frequency_dependent``, which decides whether the response is
solved at K(nω), C(nω)), the bearing-pressure limit the office check needs, the count of machines
(peaks added only when several), and whether the run-up check ran.
"""

from __future__ import annotations

import re
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


@pytest.fixture(scope="module")
def piled_sheet(tmp_path_factory) -> str:
    """The markdown sheet of the shipped piled block (its assumptions table is what a checker reads)."""
    import foundation_calc as fc

    out = tmp_path_factory.mktemp("piles") / "piles.md"
    fc.report(CONFIGS / "block_on_piles.toml", output=out)
    return out.read_text(encoding="utf-8")


def _sheet_rows(text: str) -> dict[str, str]:
    """The assumptions table's rows of a markdown sheet, topic -> text (cells split at unescaped pipes)."""
    section = text.split("Assumptions and limitations", 1)[1].split("\n## ", 1)[0]
    return {cells[1].strip(): cells[2].strip() for cells in (re.split(r"(?<!\\)\|", line) for line in section.splitlines())
            if len(cells) == 4 and cells[1].strip() not in ("topic", "---")}


def test_the_piled_blocks_sheet_states_the_groups_coupled_model(piled_sheet):
    """The group couples sway and rocking at O (K and C not diagonal: tests/test_piles_cli.py), its
    springs are the piles' (EN 1998-5 Annex C heads, Dobry & Gazetas' group, Makris & Gazetas'
    frequency shape), and the shipped cap does not bear on the clay (piles.cap_contact = false)."""
    rows = _sheet_rows(piled_sheet)
    assert "uncoupled" not in piled_sheet.lower()
    assert "coupled: sway-rocking" in rows["base"] and "K\\_HM" in rows["base"]
    assert "cap does not bear on the soil" in rows["base"]
    for key in ("\\[EC8\\]", "\\[DG\\]", "\\[MG\\]", "\\[RW\\]", "Frequency-dependent"):
        assert key in rows["soil"], key
    assert "Gazetas' stiffnesses" not in piled_sheet and "half-space under a rigid surface base" not in piled_sheet


@pytest.mark.parametrize(("head", "contact", "embedment", "words"), [
    ("pinned", False, 0.0, ("no sway-rocking terms", "piles alone carry")),
    ("fixed", True, 0.0, ("coupled: sway-rocking", "cap bears on the soil")),
    ("fixed", False, 1.0, ("coupled: sway-rocking", "embedded 1 m")),
])
def test_the_piled_base_row_follows_the_heads_and_the_caps_contact(head, contact, embedment, words):
    data = tomllib.loads((CONFIGS / "block_on_piles.toml").read_text(encoding="utf-8"))
    data["piles"].update(head=head, cap_contact=contact)
    data["block"]["embedment"] = embedment
    base = _rows(parse_scene(data))["base"]
    assert "uncoupled (no sliding-rocking" not in base
    for word in words:
        assert word in base, (word, base)


def test_the_base_row_of_a_footing_on_a_stratum_states_the_layer():
    """A footing on a layer over rock (soil.stratum_depth) is not a half-space: its base row says the
    layer's depth, Kausel's factors and the cutoffs, and no longer "no ... layering"; without the key
    the row is the half-space's."""
    data = tomllib.loads((CONFIGS / "block_fan_torsion_near_speed.toml").read_text(encoding="utf-8"))
    assert "layering" in _rows(parse_scene(data))["base"]
    data["soil"]["stratum_depth"] = 3.0
    base = _rows(parse_scene(data))["base"]
    assert "layering" not in base
    assert "3 m deep over rigid rock" in base and "Kausel" in base and "V_s/4H" in base, base


@pytest.mark.parametrize(("contact", "limits", "named", "absent"), [
    (False, {}, ("static settlement of the pile group w/k_z", "piles' axial and lateral capacity"), ("bearing pressure",)),
    (True, {}, ("static bearing pressure under the cap", "piles' axial and lateral capacity"), ()),
    (False, {"settlement": 0.01}, ("piles' axial and lateral capacity",), ("bearing pressure", "settlement")),
])
def test_a_piled_block_says_what_is_not_checked_of_its_piles(contact, limits, named, absent):
    """The support names its own terms in "not checked": a pile group's capacity, strength and settlement, and a
    bearing pressure only where its cap bears on the soil, not the footing's soil pressure under the base."""
    data = tomllib.loads((CONFIGS / "block_on_piles.toml").read_text(encoding="utf-8"))
    data["piles"]["cap_contact"] = contact
    data["limits"].update(limits)
    text = _rows(parse_scene(data))["not checked"].lower()
    assert "dynamic soil pressure" not in text, text
    for words in named:
        assert words in text, (words, text)
    for words in absent:
        assert words not in text, (words, text)


def test_a_footing_says_what_is_not_checked_of_the_soil():
    text = _rows(_scene("gazetas"))["not checked"]
    assert "static settlement W/K_z (no [limits] settlement)" in text and "dynamic soil pressure and settlement" in text
    assert "pile" not in text


@pytest.mark.parametrize(("config", "named", "absent"), [
    ("block_two_throw_compressor", ("crank mechanisms' inertia forces",), ("unbalance", "vendor's loads")),
    ("block_two_machines", ("vendor's loads as given", "unbalance from its balance grade"), ("crank",)),
    ("block_on_piles", ("unbalance from its balance grade",), ("crank", "vendor's loads")),
])
def test_the_loads_row_names_the_machines_parts(config, named, absent):
    """The loads row says what forces the scene's machines (a crank compressor has no unbalance and
    no vendor's loads), and only a scene with angle-dependent inertia states how the response takes it."""
    rows = _rows(parse_scene(tomllib.loads((CONFIGS / f"{config}.toml").read_text(encoding="utf-8"))))
    for words in named:
        assert words in rows["loads"], (words, rows["loads"])
    for words in absent:
        assert words not in rows["loads"], (words, rows["loads"])
    assert ("response" in rows) == ("crank" in named[0]), rows.get("response")
    if "response" in rows:
        assert "first approximation" in rows["response"] and "exact periodic solution" in rows["response"]


def test_the_accuracy_of_a_block_with_crank_mechanisms_states_the_first_approximations_error():
    """The judged numbers of a scene with angle-dependent inertia are the first approximation's: the
    Accuracy section gives its error against the exact periodic solution (the amplitudes document's),
    and no longer says there is no approximation."""
    from foundation_calc.output.report.block_accuracy import block_accuracy_section

    scene = parse_scene(tomllib.loads((CONFIGS / "block_two_throw_compressor.toml").read_text(encoding="utf-8")))
    periodic = [{"machine": "compressor", "first_approximation_error": 1.44e-4, "harmonics": 16}]
    first = block_accuracy_section(scene, periodic).blocks[0].text
    assert "compressor: at most 0.014 % of a peak (16 harmonics)" in first
    assert "no closed-form approximation" not in first
    assert "no closed-form approximation" in block_accuracy_section(scene).blocks[0].text
