"""``fcalc sweep`` on a frequency-dependent soil: every harmonic n of every speed on the springs
and dashpots at n ω, margins to the frequency-consistent modes, in one batched solve per harmonic."""

from __future__ import annotations

import numpy as np
import pytest

from foundation_calc.checks.amplitudes.approximations import check_scene_amplitudes, scene_vendor_loads
from foundation_calc.checks.resonance import check_scene_resonances
from foundation_calc.checks.sweep.crank import HARMONICS, scene_dynamic_soil, sweep
from foundation_calc.scenes import parse_scene
from tests.conftest import CONFIGS, read_toml

GAZETAS = {"method": "gazetas", "shear_wave_velocity": 150.0, "density": 1800.0, "poisson": 0.33, "material_damping": 0.03}


def _sweep(scene, rpm):
    design = None if scene.mechanism is None else scene.design()
    points = [(p.name, p.horizontal, p.height) for p in scene.points]
    return sweep(design, "omega", np.asarray(rpm) * np.pi / 30.0, scene.limits, scene.limits.detuning, points,
                 scene_vendor_loads(scene), dynamic=scene_dynamic_soil(scene))


@pytest.mark.parametrize(("config", "section"), [("compressor_medium_sand_lysmer.toml", "mechanism"),
                                                  ("compressor_vendor_loads.toml", "operation")])
def test_a_speed_sweep_is_fcalc_amplitudes_and_resonance_at_each_speed(config, section):
    """The sweep at three speeds against ``check_scene_amplitudes`` and ``check_scene_resonances`` of
    the scene run at each of them alone (rel 1e-9: the same algebra, batched): each harmonic of the
    corrected first approximation (the sweep's) or of the loads, the governing margin; against the static springs the
    harmonics move by more than 1 %, so the test sees the frequency dependence."""
    document = read_toml(CONFIGS / config)
    document["soil"] = GAZETAS
    scene = parse_scene(document)
    rpm = [0.7 * document[section]["speed_rpm"], document[section]["speed_rpm"], 1.3 * document[section]["speed_rpm"]]
    found = _sweep(scene, rpm)
    static = sweep(None if scene.mechanism is None else scene.design(), "omega", np.asarray(rpm) * np.pi / 30.0,
                   scene.limits, scene.limits.detuning, [], scene_vendor_loads(scene))
    moved = 0.0
    for i, speed in enumerate(rpm):
        document[section]["speed_rpm"] = speed
        alone = parse_scene(document)
        amplitudes = check_scene_amplitudes(alone)
        motion = amplitudes.approximations.get("first_approximation", amplitudes.approximations[amplitudes.checked]).motion
        for dof, n in HARMONICS:
            cos, sin = motion.coefficient(dof, n)
            expected = complex(cos - 1j * sin)
            assert found.columns["harmonics"][f"{dof}{n}"][i] == pytest.approx(expected, rel=1e-9, abs=1e-12 * abs(motion.cos).max())
            moved = max(moved, abs(static.columns["harmonics"][f"{dof}{n}"][i] - expected) / abs(motion.cos).max())
        resonance = check_scene_resonances(alone)
        assert found.rows.margin[i] == pytest.approx(resonance.governing.margin, rel=1e-9)
    assert moved > 0.01


def test_the_loads_sweep_on_gazetas_soil_against_the_block_foundation():
    """The vendor loads' sweep against an independent implementation: the block foundation's 6-DOF
    model of the same block on the same soil (its own springs in two planes at n ω), harmonic by
    harmonic at three speeds (atol 1e-10 of the largest, as the static plane test)."""
    from foundation_calc.solvers.block.response import point_motion
    from foundation_calc.scenes import load_scene
    from tests.test_block_foundation import _block_like_crank

    crank = load_scene(CONFIGS / "compressor_vendor_loads.toml")
    document = _block_like_crank(crank) | {"soil": GAZETAS}
    crank = crank.model_copy(update={"soil": crank.soil.__class__(**GAZETAS)})
    rpm = np.array([900.0, 1500.0, 2100.0])
    found = _sweep(crank, rpm)
    for i, speed in enumerate(rpm):
        document["machines"][0]["speed_rpm"] = float(speed)
        block = parse_scene(document)
        model, excitations = block.model(), block.excitations()
        G = point_motion(model, excitations, [], np.zeros((0, 3)), impedance=block.soil_impedance)
        U, R = G.displacement[0][0], G.rotation[0]  # (3, H) at G, (3, H) rotations
        orders = list(excitations[0].orders)
        expected = {"x": U[0], "y": -U[2], "theta": R[1]}
        for dof, n in HARMONICS:
            if n in orders:
                scale = np.abs(expected[dof]).max()
                assert abs(found.columns["harmonics"][f"{dof}{n}"][i] - expected[dof][orders.index(n)]) <= 1e-10 * scale
