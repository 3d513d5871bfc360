"""The vectorised block-foundation evaluator of ``fcalc design`` against the scalar path of
``fcalc check`` (``CHECKS["block_foundation"]``, one scene at a time), candidate by candidate.

Both solve the same equations, the batch on stacks of matrices: outcomes must be equal and
utilisations equal to 1e-9 relative (batched and single 6×6 eigen-solves and complex solves
differ by round-off, about 1e-13 relative on these scenes, so 1e-9 leaves margin without hiding
a wrong term, which moves a utilisation by percents). The scalar path's own numbers are checked
against independent solutions elsewhere (test_block_foundation.py, test_peaks.py).
"""

from __future__ import annotations

import copy
import math
import tomllib

import numpy as np
import pytest

from foundation_calc.checks.amplitudes import machines as scalar
from foundation_calc.checks.amplitudes.machines import condition_label

from foundation_calc.checks.design.apply import apply
from foundation_calc.checks.design.block import NOT_EVALUATED, VARIABLE_KEYS, evaluate
from foundation_calc.checks.design.candidates import EVALUATORS
from foundation_calc.checks.outcomes import RESONANCE_FAIL_MARGIN
from foundation_calc.checks.registry import CHECKS
from foundation_calc.errors import PhysicsError
from foundation_calc.scenes import parse_scene
from foundation_calc.scenes.block_soil import BLOCK_METHOD_KEYS

CODES = {"pass": 0, "warn": 1, "fail": 2}

TWO = "configs/block_two_machines.toml"
FAN = "configs/block_fan_torsion_near_speed.toml"


def _document(path, soil=None, **limits):
    with open(path, "rb") as f:
        document = tomllib.load(f)
    if soil is not None:
        document["soil"] = soil
    document["limits"] |= limits
    return document


def _variants():
    gazetas = _document(TWO, {"method": "gazetas", "shear_wave_velocity": 450.0, "density": 1950.0, "poisson": 0.3,
                              "material_damping": 0.04},
                        velocity=4.0e-3, amplitude_rms=3.0e-5, code="ISO 10816-3", machine_group=1, foundation="rigid",
                        acceptable_zone="B", bearing_pressure=5.0e4, settlement=2.5e-4, detuning={"1": 0.2, "2": 0.1})
    pais_kausel = copy.deepcopy(gazetas)  # the same site by Pais & Kausel's springs (torsion: K_t of a rectangle)
    pais_kausel["soil"]["method"] = "pais_kausel"
    return {
        "springs": _document(TWO, acceleration=0.02, acceleration_rms=0.015),  # peak 0.0221, rms 0.0154 m/s²
        "lysmer": _document(FAN),
        "gazetas": gazetas,
        "pais_kausel": pais_kausel,
        "sp26": _document(FAN, {"method": "sp26", "deformation_modulus": 3.0e7, "soil_class": "sand"}),
        "coefficients": _document(TWO, {"method": "coefficients", "c_z": 2.0e8, "c_x": 1.2e8, "damping": [0.1, 0.08, 0.05]}),
    }


DOCUMENTS = _variants()


def test_every_soil_method_of_a_block_is_judged_here():
    """A soil method a block scene accepts and no variant above uses would go untested by the
    batch evaluator (Pais & Kausel's did, and fcalc design crashed on it: exit 4)."""
    assert set(DOCUMENTS) == set(BLOCK_METHOD_KEYS)


def _candidates(scene, count, seed):
    rng = np.random.default_rng(seed)
    b = scene.block
    return {"block.length": b.length * rng.uniform(0.6, 1.6, count), "block.width": b.width * rng.uniform(0.6, 1.6, count),
            "block.height": b.height * rng.uniform(0.4, 1.8, count)}


def _one(source, batch, i):
    """Candidate ``i`` as ``fcalc check`` sees it: the scene document (or a scene's) with the block's
    dimensions put in and the machines, loads and points moved with the block (checks/design/apply.py)."""
    document = source if isinstance(source, dict) else source.model_dump(exclude_unset=True)
    return apply(document, {key: float(values[i]) for key, values in batch.items()})


def _scalar_utilisation(check, report):
    """Utilisation of a check from the scalar report's rows (the module docstring of checks/design/block.py)."""
    if check == "resonance":
        r = report.nearest
        return max(r.required, RESONANCE_FAIL_MARGIN) / r.margin
    if check == "amplitudes":
        if report.resonant:
            return math.inf
        ratios = [row.ratio for row in report.limit_rows] + [row.ratio for row in report.zone_rows]
        return max(ratios) if ratios else math.nan
    return max(row.limit / row.value if row.name == "mass ratio" else row.value / row.limit for row in report.office)


#: Candidates per soil method: fewer on a frequency-dependent soil, whose scalar path costs about
#: a second a candidate (springs solved at each mode's own frequency).
COUNTS = {"pais_kausel": 12}


@pytest.mark.parametrize("name", sorted(DOCUMENTS))
def test_batch_verdicts_equal_the_scalar_checks(name):
    document = DOCUMENTS[name]
    scene = parse_scene(document, name)
    count = COUNTS.get(name, 60)
    batch = _candidates(scene, count, seed=len(name))
    verdicts = evaluate(scene, batch)
    assert list(verdicts.outcome) == [c for c in CHECKS["block_foundation"] if c in verdicts.outcome]
    seen = set()
    for i in range(count):
        one = _one(document, batch, i)
        report = scalar.check_block(one)
        for check, function in CHECKS["block_foundation"].items():
            finding = function(one)
            if finding is None:
                assert verdicts.outcome.get(check, np.zeros(60))[i] == 0, (check, i)
                continue
            assert verdicts.outcome[check][i] == CODES[finding.outcome.value], (check, i, finding.reason)
            seen.add((check, finding.outcome.value))
            if check in ("resonance", "amplitudes", "office"):
                expected = _scalar_utilisation(check, report)
                np.testing.assert_allclose(verdicts.utilisation[check][i], expected, rtol=1e-9, err_msg=f"{check} {i}")
        governing = verdicts.reasons["resonance"][verdicts.governing["resonance"][i]]
        assert governing == condition_label(report.nearest)
        np.testing.assert_allclose(verdicts.volume[i], one.block.length * one.block.width * one.block.height, rtol=1e-15)
        np.testing.assert_allclose(verdicts.mass[i], one.block.mass_properties[0], rtol=1e-15)
    assert ("resonance", "fail") in seen  # the candidates reach both sides of the checks
    assert ("resonance", "pass") in seen or name in ("lysmer", "sp26")


def test_governing_amplitude_names_the_scalar_paths_largest_row():
    scene = parse_scene(DOCUMENTS["gazetas"], "gazetas")
    batch = _candidates(scene, 40, seed=7)
    verdicts = evaluate(scene, batch)
    for i in range(40):
        report = scalar.check_block(_one(DOCUMENTS["gazetas"], batch, i))
        rows = list(report.limit_rows) + list(report.zone_rows)
        top = max(rows, key=lambda row: row.ratio)
        text = verdicts.reasons["amplitudes"][verdicts.governing["amplitudes"][i]]
        if hasattr(top, "quantity"):
            assert text == f"{top.quantity} at {top.point} ({top.direction})"
        else:
            assert text == f"{top.table.title} zone at {top.point}"


def test_a_block_that_tips_over_fails_where_the_scalar_path_refuses_it():
    """Soft rocking springs: the tall candidates' weight overturns them (fcalc check: a PhysicsError)."""
    document = _document(TWO)
    document["soil"]["stiffness"][3:5] = [4.0e6, 4.0e6]
    scene = parse_scene(document, "soft")
    batch = {"block.height": np.linspace(0.3, 4.0, 12)}
    verdicts = evaluate(scene, batch)
    refused = []
    for i in range(12):
        try:
            scalar.check_block(_one(document, batch, i))
            refused.append(False)
        except PhysicsError:
            refused.append(True)
    assert any(refused) and not all(refused)
    for check in ("resonance", "amplitudes"):
        assert (verdicts.outcome[check][refused] == 2).all()
        assert np.isinf(verdicts.utilisation[check][refused]).all()
        assert verdicts.reasons[check][verdicts.governing[check][refused][0]].startswith("the block tips over")


def test_a_judged_runup_is_reported_as_not_evaluated():
    document = _document(TWO, transient_amplitude=1.0e-3) | {"operation": {"run_up_time": 5.0}}
    verdicts = evaluate(parse_scene(document, "runup"), {"block.length": np.array([6.0, 8.0])})
    assert "runup" in NOT_EVALUATED and (verdicts.outcome["runup"] == 0).all() and np.isnan(verdicts.utilisation["runup"]).all()
    assert "runup" not in evaluate(parse_scene(_document(TWO), "two"), {"block.length": np.array([6.0])}).outcome


def test_a_batch_in_pieces_keeps_its_deferred_checks(monkeypatch):
    """A batch larger than a piece is judged piece by piece on threads and put together again;
    the run-up it leaves to the full path must stay deferred, or the search would take a design
    that fails its run-up for a disagreement."""
    from foundation_calc.checks.design import block

    document = _document(TWO, transient_amplitude=1.0e-3) | {"operation": {"run_up_time": 5.0}}
    scene = parse_scene(document, "runup")
    whole = evaluate(scene, {"block.length": np.linspace(6.0, 8.0, 5)})
    monkeypatch.setattr(block, "PIECE", 2)
    pieces = evaluate(scene, {"block.length": np.linspace(6.0, 8.0, 5)})
    assert whole.deferred == pieces.deferred == ("runup",)
    for check in whole.outcome:
        assert np.array_equal(whole.utilisation[check], pieces.utilisation[check], equal_nan=True)


def test_an_empty_batch_gives_empty_verdicts_of_the_same_checks():
    """A batch of no candidates (a search's empty remainder) is judged as the crank's is: every
    check of a batch of one, with its reasons, and arrays of length 0 (it raised a ValueError
    from a reshape of the empty stacks)."""
    scene = parse_scene(_document(TWO), "two")
    one = evaluate(scene, {key: values[:1] for key, values in _candidates(scene, 1, seed=1).items()})
    empty = evaluate(scene, {key: values[:0] for key, values in _candidates(scene, 1, seed=1).items()})
    assert list(empty.outcome) == list(one.outcome) and empty.reasons == one.reasons and empty.deferred == one.deferred
    assert len(empty.volume) == len(empty.mass) == 0
    assert all(len(a) == 0 and a.dtype == one.outcome[c].dtype for c, a in empty.outcome.items())


def test_inputs_warn_where_a_point_is_far_for_a_small_base():
    document = _document(TWO)
    document["points"][0]["at"] = [1.5, 0.3, 45.0]  # far above the block's top: it rises with the top
    scene = parse_scene(document, "far")
    batch = {"block.length": np.array([2.0, 7.0, 7.0]), "block.width": np.array([1.5, 4.0, 4.0]),
             "block.height": np.array([2.2, 2.2, 50.0])}
    verdicts = evaluate(scene, batch)
    expected = [0 if CHECKS["block_foundation"]["inputs"](_one(document, batch, i)) is None else 1 for i in range(3)]
    assert verdicts.outcome["inputs"].tolist() == expected == [1, 0, 1]


def test_keys_that_cannot_vary_are_refused():
    assert EVALUATORS["block_foundation"] == "foundation_calc.checks.design.block"
    assert "block.height" in VARIABLE_KEYS
    with pytest.raises(ValueError, match="soil.c_z cannot vary"):
        evaluate(parse_scene(_document(TWO), "two"), {"soil.c_z": np.array([1.0e8])})


def test_over_the_soils_modulus_range_the_batch_agrees_with_fcalc_check():
    """The range moves critical speeds through the machines' speeds: the scalar path finds the
    crossings by Brent's method, the batch in closed form; the outcomes must agree, and the
    utilisations (of the data as given) to 1e-9. Some candidates fail their amplitudes only
    at a crossing (the steady state peaks there)."""
    document = DOCUMENTS["coefficients"] | {"soil": DOCUMENTS["coefficients"]["soil"] | {"modulus_range": [0.5, 1.5]}}
    scene = parse_scene(document, "range")  # a block's soil takes a modulus range (docs/soil.md, soil.modulus_range)
    batch = {key: values[:7] for key, values in _candidates(scene, 20, seed=3).items()}
    verdicts = evaluate(scene, batch)
    by_range = []
    for i in range(7):
        one = _one(document, batch, i)
        report = scalar.check_block(one)
        for check in ("resonance", "amplitudes"):
            finding = CHECKS["block_foundation"][check](one)
            assert verdicts.outcome[check][i] == CODES[finding.outcome.value], (check, i, finding.reason)
            np.testing.assert_allclose(verdicts.utilisation[check][i], _scalar_utilisation(check, report), rtol=1e-9)
        if scalar.check_block_as_given(one).amplitude_outcome.value == "pass" and report.amplitude_outcome.value == "fail":
            by_range.append(i)
    assert len(by_range) >= 2  # the range, not the data as given, decides there


def test_a_machine_outside_the_codes_group_warns_the_amplitudes_in_the_batch_as_in_fcalc_check():
    """ISO 10816-3's group 2 is 15 kW < P <= 300 kW: at 500 kW its zones may not apply, and
    the amplitude check warns, for a block as for a crank scene (a block passed, saying only
    "note:"); the batch judges each candidate as fcalc check does."""
    document = _document(FAN, machine_power=500e3)
    scene = parse_scene(document, "fan at 500 kW")
    batch = _candidates(scene, 6, seed=3)
    verdicts = evaluate(scene, batch)
    for i in range(6):
        finding = CHECKS["block_foundation"]["amplitudes"](_one(document, batch, i))
        said = "".join(part for part in finding.reason if isinstance(part, str))
        assert finding.outcome.value == "warn" and "machine_power = 500 kW is outside group 2" in said
        assert verdicts.outcome["amplitudes"][i] == CODES["warn"]
