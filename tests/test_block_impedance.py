"""A block foundation on Gazetas' frequency-dependent soil: every mode at its own frequency, every
order at n ω. The yardstick is the crank foundation's plane model on the same soil, an independent
implementation (its own 3-DOF matrices, springs from the crank scene, fixed points of its own):
a block with the crank scene's base, mass and loads in the plane x-z must move as it does."""

from __future__ import annotations

import numpy as np
import pytest

from foundation_calc.checks.amplitudes.machines import check_block
from foundation_calc.checks.resonance.frequencies import scene_block_frequencies
from foundation_calc.scenes import load_scene, parse_scene
from foundation_calc.solvers.block.response import complex_amplitudes, point_motion
from foundation_calc.solvers.crank.loads import loads_response
from tests.test_block_foundation import CONFIGS, _block_like_crank

GAZETAS = {"method": "gazetas", "shear_wave_velocity": 150.0, "density": 1800.0, "poisson": 0.33, "material_damping": 0.03}


def _pair():
    crank = load_scene(f"{CONFIGS}/compressor_vendor_loads.toml")
    document = _block_like_crank(crank) | {"soil": GAZETAS}
    return crank.model_copy(update={"soil": crank.soil.__class__(**GAZETAS)}), parse_scene(document)


def test_the_plane_modes_are_the_crank_foundations_frequency_consistent_ones():
    """Sliding x, vertical and rocking about y of the block against the crank foundation's p1, k0,
    p2 on the same soil (each solving ω = p(K(ω)); rel 1e-8, the fixed points' tolerance 1e-10 with
    margin). The rocking falls well below its static value and its damping is radiation, not only
    the soil's material damping 0.03."""
    crank, block = _pair()
    frequencies, static = scene_block_frequencies(crank)
    modes = check_block(block).modes
    by_motion = dict(zip(modes.dominant, modes.frequencies))
    statics = dict(zip(modes.dominant, modes.static))
    for motion, mode in (("x", "p1"), ("z", "k0"), ("ry", "p2")):
        assert by_motion[motion] == pytest.approx(getattr(frequencies, mode), rel=1e-8)
        assert statics[motion] == pytest.approx(getattr(static, mode), rel=1e-8)
    assert by_motion["ry"] < 0.9 * statics["ry"]
    assert dict(zip(modes.dominant, modes.damping))["ry"] > 0.3


def test_each_order_moves_as_the_crank_foundation_does_with_the_springs_at_its_own_frequency():
    """Order n of the block against the crank foundation's loads solved on its soil taken at n ω
    (atol 1e-10 of the largest amplitude, as the static plane test); against the static springs the
    block's motion differs by more than 5 %, so the test sees the frequency dependence."""
    crank, block = _pair()
    omega = crank.speed.omega_rad_s
    model, (exc,) = block.model(), block.excitations()
    Z = complex_amplitudes(model, exc, impedance=block.soil_impedance)
    G = point_motion(model, [exc], [], np.zeros((0, 3)), impedance=block.soil_impedance).displacement[0][0]
    expected = np.stack([G[0], -G[2], Z[:, 4]])
    got = np.empty_like(expected)
    for h, n in enumerate(exc.orders):
        motion = loads_response(crank.block(n * omega), omega, crank.harmonic_loads()).motion
        got[:, h] = (motion.cos - 1j * motion.sin)[:, n]
    scale = np.abs(got).max(axis=1, keepdims=True)
    np.testing.assert_allclose(expected / scale, got / scale, rtol=0, atol=1e-10)
    static = point_motion(model, [exc], [], np.zeros((0, 3))).displacement[0][0]
    assert np.abs(static - G).max() > 0.05 * np.abs(G).max()


def test_a_sweep_on_gazetas_soil_is_the_single_speed_steady_state_at_each_speed():
    """The block sweep (springs and dashpots at every n ω of every speed, in one batched solve)
    against ``check_block`` of the scene with the compressor (vendor loads, amplitudes fixed) at
    each of the speeds, one at a time (rel 1e-9: the same algebra, batched); and the margins
    against the frequency-consistent modes."""
    from foundation_calc.solvers.block.response import consistent_modes
    from foundation_calc.solvers.block.sweep import speed_sweep
    from tests.conftest import read_toml

    document = read_toml(f"{CONFIGS}/block_two_machines.toml")
    document["soil"] = {"method": "gazetas", "shear_wave_velocity": 250.0, "density": 1900.0, "poisson": 0.3,
                        "material_damping": 0.03}
    scene = parse_scene(document)
    model, excitations = scene.model(), scene.excitations()
    modes = consistent_modes(model, scene.soil_impedance)
    rpm = np.array([300.0, 600.0, 1100.0])
    sweep = speed_sweep(model, modes, excitations, 0, rpm * np.pi / 30.0, [p.at for p in scene.points], scene.soil_impedance)
    for i, speed in enumerate(rpm):
        document["machines"][0]["speed_rpm"] = float(speed)
        single = check_block(parse_scene(document))
        np.testing.assert_allclose(sweep.peak[i], single.motion.peak, rtol=1e-9)
        np.testing.assert_allclose(sweep.velocity_rms[i], single.motion.velocity_rms, rtol=1e-9)
        np.testing.assert_allclose(sweep.margin[i, 0], [r.margin for r in single.resonance.rows if r.machine == "compressor" and r.order == 1],
                                   rtol=1e-9)


#: The fan block on each frequency-dependent soil, and two blocks (with the fan's machines moved as
#: fcalc design moves them) on which rocking about x passes torsion and rocking about y near its
#: own frequency, where following a mode by its shape made the former solver cycle (exit 4).
CROSSING = {
    "fan, gazetas": (None, "gazetas", 0.33),
    "fan, pais_kausel": (None, "pais_kausel", 0.33),
    "2.0 x 6.8 x 1.2, gazetas, nu 0.25": ((2.0, 6.8, 1.2), "gazetas", 0.25),
    "4.0 x 6.0 x 0.6, gazetas, nu 0.45": ((4.0, 6.0, 0.6), "gazetas", 0.45),
    "2.4 x 6.0 x 0.8, pais_kausel, nu 0.25": ((2.4, 6.0, 0.8), "pais_kausel", 0.25),
}


def _fan_on(dimensions, method, poisson):
    from foundation_calc.checks.design.apply import apply
    from tests.conftest import read_toml

    document = read_toml(f"{CONFIGS}/block_fan_torsion_near_speed.toml")
    document["soil"] = {"method": method, "shear_wave_velocity": 150.0, "density": 1850.0, "poisson": poisson,
                        "material_damping": 0.03}
    if dimensions is None:
        return parse_scene(document)
    return apply(document, dict(zip(("block.length", "block.width", "block.height"), dimensions)))


def _determinant_roots(scene) -> np.ndarray:
    """Every ω with det(K(ω) - ω² M) = 0, found by scanning the determinant's sign on a dense grid
    (step 0.005 rad/s) and refining each change by Brent's method: a solve independent of the
    rank-by-rank root. K(ω): the model's static K with the scene's springs at ω, the torsion spring
    transcribed here from Pais & Kausel (NIST GCR 12-917-21, Table 2-3a): K_t(ω) = K_t (1 -
    (0.33 - 0.03 sqrt(r - 1)) a0²/(0.8/(1 + 0.33 (r - 1)) + a0²)), a0 = ω B'/V_s, r = L'/B'."""
    from scipy.optimize import brentq

    model = scene.model()
    L, B = scene.base
    r, half = max(L, B) / min(L, B), min(L, B) / 2.0
    springs_at_rest = scene.soil_impedance(0.0)[0]

    def determinant(omega):
        omega = np.asarray(omega, dtype=float)
        springs = scene.soil_impedance(omega)[0].copy()
        a2 = (omega * half / scene.soil.V_s) ** 2
        springs[..., 5] = springs_at_rest[5] * (1.0 - (0.33 - 0.03 * np.sqrt(r - 1.0)) * a2 / (0.8 / (1.0 + 0.33 * (r - 1.0)) + a2))
        K = model.K + np.eye(6) * (springs - springs_at_rest)[..., None, :]
        return np.linalg.det((K - omega[..., None, None] ** 2 * model.M) / np.diag(model.K)[:, None])

    grid = np.arange(1.0, 1.2 * np.sqrt(np.max(np.linalg.eigvals(np.linalg.solve(model.M, model.K)).real)), 0.005)
    values = determinant(grid)
    changes = np.flatnonzero(np.sign(values[:-1]) != np.sign(values[1:]))
    return np.array([brentq(lambda w: float(determinant(w)), grid[i], grid[i + 1], xtol=1e-12, rtol=1e-14) for i in changes])


@pytest.mark.parametrize("case", sorted(CROSSING))
def test_the_six_modes_are_the_roots_of_the_determinant_with_the_torsion_modifier(case):
    """Each of the six frequency-consistent modes (the j-th lowest frequency p_j at p_j, by a
    bracketed root) is a root of det(K(ω) - ω² M) = 0, and together they are all six roots, found
    independently by a sign scan (:func:`_determinant_roots`): rel 1e-7 (the bracket's 1e-10, the
    scan's brentq 1e-12). The torsion spring at its own frequency softens the torsional mode by
    about a tenth (the former static spring: by under 1 %)."""
    from foundation_calc.solvers.block.response import consistent_modes

    scene = _fan_on(*CROSSING[case])
    modes = consistent_modes(scene.model(), scene.soil_impedance)
    roots = _determinant_roots(scene)
    assert len(roots) == 6, roots
    np.testing.assert_allclose(modes.frequencies, roots, rtol=1e-7)
    if CROSSING[case][0] is None:
        twist = modes.dominant.index("rz")
        assert modes.frequencies[twist] < 0.92 * modes.static[twist]


def test_a_mode_that_passes_another_keeps_its_static_frequency_beside_it():
    """On a 2.0 × 5.2 × 0.6 m fan block on Gazetas' soil torsion falls from above rocking about y
    (static 169.0 rad/s against 160.4) to below it (152.8 against 155.9): each mode is shown beside
    the static mode of its shape, not of its rank (rel 1e-12: the same eigen-solve)."""
    from foundation_calc.solvers.block.response import block_modes, consistent_modes

    scene = _fan_on((2.0, 5.2, 0.6), "gazetas", 0.33)
    static = block_modes(scene.model())
    modes = consistent_modes(scene.model(), scene.soil_impedance)
    assert static.dominant.index("ry") < static.dominant.index("rz") and modes.dominant.index("ry") > modes.dominant.index("rz")
    assert dict(zip(modes.dominant, modes.static)) == pytest.approx(dict(zip(static.dominant, static.frequencies)), rel=1e-12)
