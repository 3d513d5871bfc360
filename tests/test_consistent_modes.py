"""The frequency-consistent modes of a block on a frequency-dependent support, evaluated once.

``fcalc check`` of a piled block with ``[soil] modulus_range`` took about 30 s: every check asked
for the scene's report anew, the modulus range's two grids re-solved their shared factors, and
each of the six modes sought its root ω = p(K(ω)) with its own evaluations of the pile group.
These tests pin the sharing (counts, not seconds) and that it changes no number.
"""

from __future__ import annotations

from pathlib import Path

import numpy as np
import pytest

import foundation_calc.checks.amplitudes.machines as block_checks
import foundation_calc.solvers.soil.impedance as impedance_module
from foundation_calc.scenes.loading import load_scene
from foundation_calc.solvers.block.response import consistent_batch

CONFIGS = Path(__file__).resolve().parents[1] / "configs"


@pytest.fixture(scope="module")
def piled():
    return load_scene(CONFIGS / "block_on_piles.toml")


def test_six_modes_share_each_evaluation_of_the_pile_group(piled):
    """One block's six roots are sought together: the old search, mode by mode, evaluated the
    group about 15 times per mode (96 in all on this scene)."""
    calls = []

    def counted(omega):
        calls.append(np.shape(omega))
        return piled.soil_impedance(omega)

    consistent_batch(piled.stable_model(), counted)
    assert len(calls) <= 30, calls


def test_modes_sought_together_equal_modes_sought_one_by_one(piled, monkeypatch):
    """The roots are found element by element: seeking the six together (and scanning the trial
    frequencies in one call) gives the roots of the one-mode-at-a-time search to its round-off
    (rtol 1e-10 of the bracket; 1e-12 observed)."""
    model = piled.stable_model()
    together = consistent_batch(model, piled.soil_impedance)
    monkeypatch.setattr(impedance_module, "AT_ONCE", 1)  # a "large batch": one mode, one trial at a time
    alone = consistent_batch(model, piled.soil_impedance)
    np.testing.assert_allclose(together.frequencies, alone.frequencies, rtol=1e-12)
    np.testing.assert_allclose(together.damping, alone.damping, rtol=1e-10, atol=1e-14)
    mac = np.abs(np.einsum("ij,ik,kj->j", together.shapes, model.M, alone.shapes))  # mass-normalised: |φᵀ M φ'| = 1
    np.testing.assert_allclose(mac, 1.0, rtol=1e-9)


def test_a_scene_asked_again_gets_its_report_again(piled):
    """The resonance, amplitude and office findings of one scene share one evaluation (the
    amplitudes' adds the crank machines' periodic solution to it)."""
    report = block_checks.check_block(piled)
    assert block_checks.check_block(piled) is report
    assert block_checks.check_block(piled, periodic=True).modes is report.modes
    assert block_checks.check_block(piled) is report


def test_a_factor_of_the_modulus_range_is_evaluated_once(monkeypatch):
    """The resonance grid, the amplitude grid and the crossings share their factors (the ends, 1,
    the crossings): no factored soil is evaluated twice."""
    scene = load_scene(CONFIGS / "block_fan_torsion_near_speed.toml")
    scene = scene.model_copy(update={"soil": scene.soil.model_copy(update={"modulus_range": [0.8, 1.25]})})
    seen = []
    evaluate = block_checks.check_block_as_given

    def counted(s):
        seen.append(s.soil.model_dump_json())
        return evaluate(s)

    monkeypatch.setattr(block_checks, "check_block_as_given", counted)
    report = block_checks.check_block(scene)
    assert report.amplitude_range is not None and len(report.resonance.modulus_range.points) > 1
    assert len(seen) == len(set(seen))
