"""The sensitivity table's 28 tolerance variants solved together (one stacked harmonic balance and
one stacked eigenproblem) against the same variants solved one at a time, and against each
variant's own full harmonic balance (its own harmonics grown from the forcing, dense LU)."""

from __future__ import annotations

import math
from pathlib import Path

import numpy as np
import pytest

from foundation_calc.errors import PhysicsError
from foundation_calc.scenes import parse_scene, read_toml
from foundation_calc.solvers.platform import verification
from foundation_calc.solvers.platform.dynamics import natural_frequencies
from foundation_calc.solvers.platform.harmonic_balance import VARIANT_TOL, VariantBasis
from foundation_calc.solvers.platform.verification import build, sensitivity, verify

CONFIGS = sorted((Path(__file__).parent.parent / "configs").glob("platform*.toml"))
W = 50 * math.pi
THREE = (
    {"rotor_mass": 40.0, "eccentricity": 0.2, "position": [2.5, 0.4, 0.3], "speed_ratio": -1.0, "phase": 0.4},
    {"rotor_mass": 30.0, "eccentricity": 0.15, "position": [0.5, 1.6, 0.2], "axis": [0.3, 1.2], "speed_ratio": 1.5,
     "phase": 1.1},
)


def _rig(damping_ratio):
    """A platform with three exciters (ω, -ω, 1.5 ω): 31 combination frequencies."""
    return {
        "kind": "platform",
        "platform": {"mass": 2e4, "length": 3.0, "width": 2.0, "cog": [1.5, 1.0, 0.65], "inertia": [9e3, 1.7e4, 2.2e4]},
        "exciter": {"rotor_mass": 100.0, "eccentricity": 0.2, "position": [0.0, 0.0]},
        "operation": {"omega": W, "amplitude": 1e-3, "regime": "below"},
        "isolators": {"vertical_reference": 1.6e8, "damping_ratio": damping_ratio},
        "extra_exciters": list(THREE),
    }


SCENES = {path.stem: (lambda p=path: parse_scene(read_toml(p), str(p))) for path in CONFIGS}
SCENES["three_rotors_damped"] = lambda: parse_scene(_rig(0.02), "rig")
SCENES["three_rotors_undamped"] = lambda: parse_scene(_rig(0.0), "rig")


def _variants(name):
    scene = SCENES[name]()
    design, model = scene.design(), scene.model()
    nominal = verify(design, model)
    basis = VariantBasis(nominal.state, float(np.hypot(design.A, design.B)))
    changes = [c for _, _, *pair in verification._tolerance_variants(design) for c in pair]
    return design, model, nominal, basis, changes


@pytest.mark.parametrize("name", sorted(SCENES))
def test_variants_solved_together_match_one_at_a_time(name):
    design, model, _, basis, changes = _variants(name)
    numbers, frequencies = verification._variants_together(design, model, basis, changes)
    assert numbers.shape == (28, 2) and frequencies.shape == (28, 6)
    for change, got, modes in zip(changes, numbers, frequencies):
        want, want_modes = verification._variant(design, model, basis, change)
        # both refine to the same residual from the same start; they differ by round-off only
        np.testing.assert_allclose(got, want, rtol=1e-9, atol=1e-12)
        np.testing.assert_allclose(modes, want_modes, rtol=1e-12)


@pytest.mark.parametrize(
    "name", ["platform_damped", "three_rotors_damped", "platform_paper_example", "platform_explicit_vertical"]
)
def test_variants_solved_together_match_their_own_full_solve(name):
    """Also for purely translating designs, whose nominal needs ω alone but whose variants rock."""
    design, model, nominal, basis, changes = _variants(name)
    numbers, frequencies = verification._variants_together(design, model, basis, changes)
    largest = max(nominal.amplitudes)  # [m]
    for change, got, modes in zip(changes, numbers, frequencies):
        full = verify(design, model, **change)
        # the basis drops harmonics worth VARIANT_TOL of the largest peak; corners sit within 3.6 m of
        # the centre of mass (rotations times the diagonal): 2 × that, in % of u
        atol = 100.0 * 2 * VARIANT_TOL * largest * 3.6 / design.u
        np.testing.assert_allclose(got, [full.rocking_percent, full.static_offset_percent], rtol=0, atol=atol)
        platform, rotors = build(design, model, **change)
        np.testing.assert_allclose(modes, natural_frequencies(platform, rotors).frequencies, rtol=1e-12)


def test_a_variant_without_a_steady_state_is_told_per_row(monkeypatch):
    """When the stacked solve meets a variant it cannot answer, every variant is solved on its own
    and only that variant's row carries the message."""
    design, model, nominal, _, _ = _variants("platform_paper_example")
    modes = natural_frequencies(*build(design, model)).frequencies
    want = sensitivity(design, model, nominal, modes)
    one_at_a_time = verification._variant

    def refuse_c13_plus(d, m, basis, change):
        stiffness = change.get("stiffness")
        if stiffness is not None and stiffness[0, 2] > design.stiffness[0, 2]:
            raise PhysicsError("no steady state", field="isolators")
        return one_at_a_time(d, m, basis, change)

    def stacked_refuses(*args):
        raise PhysicsError("a variant has no steady state", field="isolators")

    monkeypatch.setattr(verification, "_variant", refuse_c13_plus)
    monkeypatch.setattr(verification, "_variants_together", stacked_refuses)
    rows = {r.parameter: r for r in sensitivity(design, model, nominal, modes)}
    assert rows["c13"].rocking_plus is None and rows["c13"].resonance.endswith("no steady state")
    assert rows["c13"].rocking_minus is not None
    for row in want:
        if row.parameter != "c13":
            got = rows[row.parameter]
            assert (got.resonance, got.tolerance) == (row.resonance, row.tolerance)
            numbers = [got.rocking_plus, got.rocking_minus, got.static_plus, got.static_minus]
            assert numbers == pytest.approx([row.rocking_plus, row.rocking_minus, row.static_plus, row.static_minus], rel=1e-9)
