"""One check function per check whatever the scene's kind (checks/registry.py).

A check that several kinds run is one function in :data:`CHECKS`; the kinds differ below it
(``scene_resonances``, ``scene_amplitudes``, ``scene_office``) and each finding is worded as its
report says. The office finding states exactly the rows of ``scene_office``; a crank's rows are
checked against W/S and W/K_z computed here from the scene's keys: W = (M + m + m1) g with
g = 9.81 m/s² (the project's constant), S the given base area, K_z = c_z S (the paper's footing on
Barkan's coefficient). Each is a sum, a product and a division, so they agree to round-off
(rel 1e-12). The amplitude finding states the report of ``scene_amplitudes``: its verdict, its
largest value/limit row and, for a crank (whose report says so), its speed.
"""

from __future__ import annotations

import tomllib
from collections import defaultdict

import pytest

from foundation_calc.checks.amplitudes import scene_amplitudes
from foundation_calc.checks.office import scene_office
from foundation_calc.checks.registry import CHECKS
from foundation_calc.scenes import load_scene, parse_scene
from tests.conftest import CONFIGS, configs_of_kind

G_ACC = 9.81

#: Allowables that every shipped crank scene's base passes or fails, so that both rows are made.
OFFICE_LIMITS = {"bearing_pressure": 1.0e5, "settlement": 1.0e-3}


def _document(path) -> dict:
    with open(path, "rb") as fh:
        return tomllib.load(fh)


def test_every_check_that_several_kinds_run_is_one_function():
    functions = defaultdict(set)
    for checks in CHECKS.values():
        for name, function in checks.items():
            functions[name].add(function)
    shared = {name for name in functions if sum(name in checks for checks in CHECKS.values()) > 1}
    assert shared == {"inputs", "resonance", "amplitudes", "runup", "office", "requirements"}
    assert {name: len(functions[name]) for name in shared} == dict.fromkeys(shared, 1)
    assert [name for name in functions if name not in shared] == ["design"]  # the platform's own
    assert CHECKS["crank_foundation"]["office"] is CHECKS["block_foundation"]["office"]
    assert CHECKS["crank_foundation"]["amplitudes"] is CHECKS["block_foundation"]["amplitudes"]


def _barkan(path) -> bool:
    document = _document(path)
    return "c_z" in document.get("soil", {}) and "base_area" in document["foundation"]


@pytest.mark.parametrize("path", [p for p in configs_of_kind("crank_foundation") if _barkan(p)], ids=lambda p: p.stem)
def test_a_cranks_office_finding_is_its_scene_office_rows_by_hand(path):
    document = _document(path)
    assert CHECKS["crank_foundation"]["office"](parse_scene(document, path.name)) is None  # no allowable: not run
    document.setdefault("limits", {}).update(OFFICE_LIMITS)
    scene = parse_scene(document, path.name)
    finding = CHECKS["crank_foundation"]["office"](scene)
    rows = scene_office(scene).office
    assert finding.report.office == rows
    assert [r.name for r in rows] == ["bearing pressure", "settlement"]  # over the centroid: no eccentricity, no mass ratio
    foundation, mechanism = document["foundation"], document.get("mechanism", {})
    W = (foundation["mass"] + mechanism.get("rod_mass", 0.0) + mechanism.get("slider_mass", 0.0)) * G_ACC
    S = foundation["base_area"]
    assert rows[0].value == pytest.approx(W / S, rel=1e-12)
    assert rows[1].value == pytest.approx(W / (document["soil"]["c_z"] * S), rel=1e-12)
    assert finding.outcome is max((r.outcome for r in rows), key=["pass", "warn", "fail"].index)
    assert [d.split(": ", 1)[1] for d in finding.details] == [f"{r.text} ({r.source})" for r in rows]


@pytest.mark.parametrize("path", [p for p in configs_of_kind("crank_foundation") if not _barkan(p)], ids=lambda p: p.stem)
def test_a_crank_given_by_its_block_states_its_scene_office_rows(path):
    document = _document(path)
    document.setdefault("limits", {}).update(OFFICE_LIMITS)
    scene = parse_scene(document, path.name)
    rows = scene_office(scene).office
    assert CHECKS["crank_foundation"]["office"](scene).report.office == rows
    assert [r.name for r in rows] == ["bearing pressure", "settlement"]


@pytest.mark.parametrize("name", ["block_two_machines", "block_on_isolators", "block_on_piles"])
def test_a_blocks_office_finding_is_its_scene_office_rows(name):
    from foundation_calc.checks.amplitudes.machines import check_block

    scene = load_scene(CONFIGS / f"{name}.toml")
    finding = CHECKS["block_foundation"]["office"](scene)
    rows = scene_office(scene).office
    assert finding.report.office == rows == check_block(scene).office  # the rows fcalc amplitudes lists
    names = [r.name for r in rows]
    assert names[:2] == ["eccentricity x", "eccentricity y"] and names[-1] == "mass ratio"


@pytest.mark.parametrize("name", ["compressor_near_resonance", "frame_saw_over_amplitude_limit", "block_two_machines",
                                  "block_on_isolators"])
def test_the_amplitude_finding_states_its_scene_amplitudes_report(name):
    scene = load_scene(CONFIGS / f"{name}.toml")
    finding = CHECKS[scene.kind]["amplitudes"](scene)
    report = scene_amplitudes(scene)
    assert finding.outcome is report.amplitude_outcome
    assert finding.report.limit_rows == report.limit_rows and finding.report.zone_rows == report.zone_rows
    top = max(report.limit_rows, key=lambda row: row.ratio)
    assert finding.values["peak"][1] == top.value and finding.values["limit"][1] == top.limit
    if scene.kind == "crank_foundation":  # the crank's report names its one speed; a block's machines have theirs
        assert finding.values["speed"] == ("speed", scene.speed.omega_rad_s)
    else:
        assert "speed" not in finding.values
