"""The batch evaluator of crank-foundation blocks against the full path of ``fcalc check``.

Independent reference: every candidate is written into the scene document, validated as a scene
and judged by :func:`~foundation_calc.checks.batch.run_checks`, one scene at a time (the scalar
reports: the scene's own design, its averaged-operator solve by LAPACK, the peaks of every point).
The batch shares the equations but not the path: block and mechanism split apart, Cramer's rule
over stacks, harmonics beyond the forcing's round-off left out, the fixed point of a
frequency-dependent soil iterated over the whole batch.

Tolerances: outcomes equal. Utilisations within 1e-9 relative (observed below 1e-13: the
harmonics left out are below 1e-15 of the forcing, the solves differ by round-off times the
systems' condition); on Gazetas' frequency-dependent soil the natural frequencies are fixed points
iterated to a relative change of 1e-10, the scalar path one mode at a time, the batch until every
candidate has converged, so the margins differ by up to ~1e-10 and the resonance utilisation
needed/margin by up to ~1e-10/margin: 1e-7 there.
"""

from __future__ import annotations

import math

import numpy as np
import pytest

from foundation_calc.checks.batch import run_checks
from foundation_calc.checks.design.candidates import EVALUATORS, FAIL, PASS, WARN
from foundation_calc.checks.design.crank import NOT_EVALUATED, evaluate, sample_batch
from foundation_calc.checks.design.modulus_range import OVER_RANGE
from foundation_calc.scenes import parse_scene, read_toml
from foundation_calc.scenes.soil import SOIL_METHODS
from tests.conftest import CONFIGS

CODES = {"pass": 0, "warn": 1, "fail": 2}


def _candidate(doc: dict, L: float, B: float, H: float):
    """The scene of the block L × B × H as fcalc design writes it (checks/design/apply.py: the
    machine, the crank axis and the points move with the block, its derived keys computed)."""
    from foundation_calc.checks.design.apply import apply

    return apply(doc, {"foundation.block.length": L, "foundation.block.width": B, "foundation.block.height": H})


def _utilisation(run) -> float:
    """Demand over capacity of a scalar check's report, as candidates.py defines it."""
    report = run.report
    if run.check == "resonance":
        g = report.governing
        return math.inf if g.margin <= 0.0 else g.needed / g.margin
    if run.check == "amplitudes":
        if report.resonant:
            return math.inf
        return max((row.ratio for row in (*report.limit_rows, *report.zone_rows)), default=math.nan)
    if run.check == "office":
        row = report.office[0]
        return row.value / row.limit
    return math.nan


def _variant(name: str) -> dict:
    if name == "sp26":
        return read_toml(CONFIGS / "compressor_medium_sand_sp26.toml")
    doc = read_toml(CONFIGS / "compressor_medium_sand_lysmer.toml")
    if name in ("coefficients", "gazetas", "pais_kausel"):  # with points, a code, RMS and peak limits and the office's pressure
        doc["points"] = [{"name": "top edge", "horizontal": 3.0, "height": 1.2},
                         {"name": "bearing", "horizontal": 0.4, "height": 2.0}]
        doc["limits"].update(code="ISO 10816-3", machine_group=2, foundation="rigid", acceleration=0.05,
                             velocity_rms=2e-3, bearing_pressure=6e4)
    if name == "coefficients":  # Barkan's coefficients with damping ratios; limits tight enough to fail some
        doc["soil"] = {"c_z": 6.0e7, "c_x": 4.2e7, "c_phi": 1.1e8, "damping": [0.1, 0.06, 0.05]}
        doc["limits"].update(amplitude=4e-6, acceleration=2e-3, velocity_rms=1.2e-4)
    if name in ("gazetas", "pais_kausel"):
        doc["soil"]["method"] = name
        doc["foundation"]["embedment"] = 0.8
    return doc


#: (soil method, candidates, relative tolerance of the resonance utilisation): the
#: frequency-dependent soils' fixed points converge to 1e-10 (module docstring), and their full
#: path costs seconds a candidate: Pais & Kausel's differs from Gazetas' only in its static
#: springs (tests/test_soil_closed_forms.py), so one candidate of it is enough here.
CASES = [("lysmer", 60, 1e-9), ("sp26", 60, 1e-9), ("coefficients", 60, 1e-9), ("gazetas", 2, 1e-7),
         ("pais_kausel", 1, 1e-7)]


def test_every_soil_method_of_a_crank_scene_is_judged_here():
    """A soil method a crank scene accepts and no case below uses would go untested by the batch
    evaluator (Pais & Kausel's block soil crashed fcalc design, exit 4)."""
    assert {name for name, _, _ in CASES} == set(SOIL_METHODS)


@pytest.mark.parametrize(("name", "count", "resonance_tolerance"), CASES)
def test_batch_agrees_with_the_full_check(name, count, resonance_tolerance):
    doc = _variant(name)
    scene = parse_scene(doc)
    batch = sample_batch(scene, count, seed=7)
    verdicts = evaluate(scene, batch)
    L, B, H = (batch[f"foundation.block.{k}"] for k in ("length", "width", "height"))
    seen = {c: set() for c in verdicts.outcome}
    for i in range(count):
        runs = {run.check: run for run in run_checks(_candidate(doc, L[i], B[i], H[i]))}
        assert set(runs) <= set(verdicts.outcome)
        for check, outcome in verdicts.outcome.items():
            run = runs.get(check)
            expected = CODES[run.verdict] if run is not None else PASS  # left out: nothing to judge
            assert outcome[i] == expected, (i, check, run.reason if run else None)
            seen[check].add(expected)
            if run is None or check == "inputs":
                continue
            tolerance = resonance_tolerance if check == "resonance" else 1e-9
            assert verdicts.utilisation[check][i] == pytest.approx(_utilisation(run), rel=tolerance), (i, check)
    if name not in ("gazetas", "pais_kausel"):  # the sample reaches both sides of the resonance rule
        assert seen["resonance"] == {PASS, FAIL}
    if name == "coefficients":  # and of the amplitude limits (the code warns below 600 rpm: WARN, not PASS)
        assert seen["amplitudes"] == {WARN, FAIL} and seen["office"] == {PASS, FAIL} and seen["inputs"] == {PASS, WARN}


def test_over_the_soils_modulus_range_as_the_full_check():
    """[soil] modulus_range: the full path's verdict is the worst of the soil as given and of every
    factor (grid and crossings); the utilisation is the soil's as given (reference.py's reading)."""
    doc = _variant("coefficients")
    doc["soil"]["modulus_range"] = [0.6, 1.6]
    scene = parse_scene(doc)
    batch = sample_batch(scene, 3, seed=5)
    verdicts = evaluate(scene, batch)
    L, B, H = (batch[f"foundation.block.{k}"] for k in ("length", "width", "height"))
    for i in range(3):
        runs = {run.check: run for run in run_checks(_candidate(doc, L[i], B[i], H[i]))}
        for check in ("resonance", "amplitudes"):
            run = runs[check]
            assert verdicts.outcome[check][i] == CODES[run.verdict], (i, check)
            assert verdicts.utilisation[check][i] == pytest.approx(_utilisation(run), rel=1e-9), (i, check)
            ranged = run.report.modulus_range if check == "resonance" else run.report.amplitude_range
            if ranged.outcome.value == "fail" and _utilisation(run) <= 1.0:
                assert verdicts.reasons[check][verdicts.governing[check][i]].endswith(OVER_RANGE)


def test_a_block_that_tips_over_fails_as_the_full_check_finds_it_invalid():
    doc = _variant("coefficients")
    doc["soil"]["c_phi"] = 2.0e6
    scene = parse_scene(doc)
    L, B, H = np.array([1.0, 8.0]), np.array([4.0, 4.0]), np.array([3.0, 1.0])
    verdicts = evaluate(scene, {"foundation.block.length": L, "block.width": B, "block.height": H})
    tipping = {run.check: run.verdict for run in run_checks(_candidate(doc, 1.0, 4.0, 3.0))}
    assert tipping["resonance"] == tipping["amplitudes"] == "invalid"
    for check in ("resonance", "amplitudes"):
        assert verdicts.outcome[check].tolist()[0] == FAIL and verdicts.utilisation[check][0] == math.inf
        assert "tips over" in verdicts.reasons[check][verdicts.governing[check][0]]
        assert np.isfinite(verdicts.utilisation[check][1])


def test_a_judged_run_up_is_left_to_the_full_path():
    doc = _variant("lysmer")
    doc["limits"]["transient_amplitude"] = 1e-3
    doc["operation"] = {"run_up_time": 5.0}
    scene = parse_scene(doc)
    verdicts = evaluate(scene, sample_batch(scene, 3))
    assert verdicts.outcome["runup"].tolist() == [PASS] * 3 and np.isnan(verdicts.utilisation["runup"]).all()
    assert verdicts.reasons["runup"] == (NOT_EVALUATED,)


def test_keys_that_cannot_vary_are_named():
    scene = parse_scene(_variant("lysmer"))
    with pytest.raises(ValueError, match="foundation.block.density cannot vary"):
        evaluate(scene, {"foundation.block.density": np.array([2400.0])})


def test_registered_for_the_kind():
    assert EVALUATORS["crank_foundation"] == "foundation_calc.checks.design.crank"


def test_the_decoupled_solve_is_the_full_one_without_round_off_couplings():
    """Every shipped mechanism's averaged operator leaves y apart from x and θ to round-off; the
    2 × 2 + 1 solves then equal the 3 × 3 ones (Cramer's rule, against numpy's LAPACK solve too)."""
    from foundation_calc.checks.design.crank_physics import candidate_designs
    from foundation_calc.solvers.crank.averaged import block_matrices
    from foundation_calc.solvers.crank.batch import MechanismOperator, harmonic_response

    scene = parse_scene(_variant("coefficients"))
    batch = sample_batch(scene, 50, seed=2)
    designs = candidate_designs(scene, *(batch[f"foundation.block.{k}"] for k in ("length", "width", "height")))
    operator = MechanismOperator.of(scene.design())
    assert operator.decoupled
    M_m, C_m, K_m, fc, fs = operator.at(designs.a)
    M, C, K = (a + b for a, b in zip((M_m, C_m, K_m), block_matrices(designs.at(0.0))))
    split = harmonic_response(M, C, K, scene.mechanism.omega_rad_s, fc, fs, 8, decoupled=True)
    full = harmonic_response(M, C, K, scene.mechanism.omega_rad_s, fc, fs, 8)
    w = np.arange(9) * scene.mechanism.omega_rad_s
    ops = K[:, None] + 1j * w[:, None, None] * C[:, None] - (w * w)[:, None, None] * M[:, None]
    lapack = np.swapaxes(np.linalg.solve(ops, np.swapaxes(fc - 1j * fs, -1, -2)[:, :9, :, None])[..., 0], -1, -2)
    scale = np.abs(lapack).max(axis=-1, keepdims=True)
    assert np.abs(split - full).max() <= 1e-12 * scale.max() and np.all(np.abs(full - lapack) <= 1e-12 * scale)


def test_the_code_zone_by_the_more_restrictive_of_velocity_and_displacement():
    """ISO 10816-3 (5.2.3) judges a point by the worse of its r.m.s. velocity and r.m.s.
    displacement zones. At the compressor's 150 rpm the displacement decides (its boundaries
    correspond to the velocity's at 10 Hz), so a batch that judged the velocity alone would
    give other utilisations and zones than the full path; with only the code limiting, the
    code zone row is the amplitude check's utilisation."""
    doc = read_toml(CONFIGS / "compressor_medium_sand_lysmer.toml")
    doc["points"] = [{"name": "top edge", "horizontal": 3.0, "height": 1.2}]
    doc["mechanism"].update(slider_mass=2500.0, crank_radius=0.3)  # forces that reach zones B-D
    doc["limits"] = {"code": "ISO 10816-3", "machine_group": 2, "foundation": "rigid", "detuning": 0.2}
    scene = parse_scene(doc)
    batch = sample_batch(scene, 20, seed=3)
    verdicts = evaluate(scene, batch)
    L, B, H = (batch[f"foundation.block.{k}"] for k in ("length", "width", "height"))
    by_displacement = 0
    for i in range(20):
        run = next(r for r in run_checks(_candidate(doc, L[i], B[i], H[i])) if r.check == "amplitudes")
        assert verdicts.outcome["amplitudes"][i] == CODES[run.verdict], i
        if run.report.resonant:
            continue
        assert verdicts.utilisation["amplitudes"][i] == pytest.approx(_utilisation(run), rel=1e-9), i
        by_displacement += any(row.judged.quantity == "displacement" for row in run.report.zone_rows)
    assert by_displacement > 0  # the sample reaches the displacement's zones


def test_chunks_on_threads_give_the_verdicts_of_one_chunk(monkeypatch):
    """A batch of several chunks is judged on threads: the verdicts equal those of one chunk
    (utilisations to 1e-12: arrays of other lengths may round differently in their products)."""
    from foundation_calc.checks.design import crank

    scene = parse_scene(_variant("coefficients"))
    batch = sample_batch(scene, 40, seed=5)
    whole = evaluate(scene, batch)
    monkeypatch.setattr(crank, "CHUNK", 7)
    chunked = evaluate(scene, batch)
    for check in whole.outcome:
        assert np.array_equal(whole.outcome[check], chunked.outcome[check])
        np.testing.assert_allclose(chunked.utilisation[check], whole.utilisation[check], rtol=1e-12)
        assert np.array_equal(whole.governing[check], chunked.governing[check])
