"""The block foundation (6-DOF) against the crank foundation (3-DOF), against itself turned a
quarter turn, and against an independent time integration of its equations of motion.

Tolerances: 1e-10 relative where two linear solves of the same physics meet (round-off of
6×6 solves and of the parallel-axis sums, about 1e-13, with margin); 1e-6 for the time
integration (DOP853 at rtol 1e-11 over a period: its error is about 1e-9 of the motion).
"""

from __future__ import annotations

import copy
import math

import numpy as np
import pytest
from scipy.integrate import solve_ivp

from foundation_calc.scenes import load_scene, parse_scene
from foundation_calc.solvers.block.response import block_modes, complex_amplitudes, point_motion
from foundation_calc.solvers.constants import GRAVITY
from foundation_calc.solvers.crank.loads import loads_response

CONFIGS = "configs"


def _block_like_crank(crank) -> dict:
    """The crank scene's block and loads in the block's axes: x the same, z = -y (up), θ_y = θ."""
    f, soil, h = crank.foundation, crank.soil, crank.foundation.cog_height
    L = (12.0 * f.base_second_moment / f.base_area) ** 0.5
    loads = []
    for ld in crank.loads:
        loads.append({
            "order": ld.order, "force": [ld.horizontal, 0.0, -ld.vertical], "moment": [0.0, ld.moment, 0.0],
            "phase": ld.phase, "at": [ld.at.horizontal, 0.0, h + ld.at.height],
        })
    machine = 1.0e3  # a small machine at G: the block's mass is the rest
    return {
        "kind": "block_foundation",
        "block": {"length": L, "width": f.base_area / L, "mass": f.mass - machine, "cog": [0.0, 0.0, h],
                  "inertia": [2.0e5, f.moment_of_inertia, 3.0e5]},
        "machines": [{"name": "compressor", "mass": machine, "cog": [0.0, 0.0, h], "speed_rpm": crank.speed.speed_rpm,
                      "loads": loads}],
        "soil": {"c_z": soil.c_z, "c_x": soil.c_x, "damping": list(soil.damping)},
    }


def test_a_plane_block_reproduces_the_crank_foundation_loads_scene():
    crank = load_scene(f"{CONFIGS}/compressor_vendor_loads.toml")
    motion = loads_response(crank.block(), crank.speed.omega_rad_s, crank.harmonic_loads()).motion
    crank_Z = motion.cos - 1j * motion.sin  # (3, K + 1): x, y (down), θ
    block = parse_scene(_block_like_crank(crank))
    model, (exc,) = block.model(), block.excitations()
    Z = complex_amplitudes(model, exc)  # about O
    G = point_motion(model, [exc], [], np.zeros((0, 3))).displacement[0][0]  # (3, H) at G
    expected = np.stack([G[0], -G[2], Z[:, 4]])
    got = crank_Z[:, exc.orders]
    scale = np.abs(got).max(axis=1, keepdims=True)
    np.testing.assert_allclose(expected / scale, got / scale, rtol=0, atol=1e-10)
    # and nothing out of the plane
    assert np.abs(G[1]).max() < 1e-12 * np.abs(G).max()


def _turned(data: dict) -> dict:
    """The scene turned 90° about z: (x, y, z) -> (-y, x, z) for positions, forces and moments."""
    t = copy.deepcopy(data)

    def turn(v):
        return [-v[1], v[0], v[2]]

    b = t["block"]
    b["length"], b["width"] = b["width"], b["length"]
    for m in t["machines"]:
        m["cog"] = turn(m["cog"])
        m["inertia"] = [m["inertia"][1], m["inertia"][0], m["inertia"][2]]
        for part in m.get("loads", []) + [m.get("unbalance", {})]:
            for key in ("force", "moment", "at", "axis"):
                if key in part:
                    part[key] = turn(part[key])
    k, c = t["soil"]["stiffness"], t["soil"]["dashpot"]
    t["soil"]["stiffness"] = [k[1], k[0], k[2], k[4], k[3], k[5]]
    t["soil"]["dashpot"] = [c[1], c[0], c[2], c[4], c[3], c[5]]
    t["points"] = [{"name": p["name"], "at": turn(p["at"])} for p in t["points"]]
    return t


def _two_machines() -> dict:
    import tomllib

    with open(f"{CONFIGS}/block_two_machines.toml", "rb") as fh:
        return tomllib.load(fh)


def test_a_block_turned_a_quarter_turn_moves_the_same_with_x_and_y_exchanged():
    data = _two_machines()
    one, two = parse_scene(data), parse_scene(_turned(data))
    assert two.block.mass_properties[0] == one.block.mass_properties[0]
    a = point_motion(one.model(), one.excitations(), [p.name for p in one.points], [p.at for p in one.points])
    b = point_motion(two.model(), two.excitations(), [p.name for p in two.points], [p.at for p in two.points])
    np.testing.assert_allclose(block_modes(two.model()).frequencies, block_modes(one.model()).frequencies, rtol=1e-12)
    # the compressor's loads turn with the block; the motor's unbalance has no phase of its own
    # (its reference direction normal to the axis is the solver's choice), so compare magnitudes
    pairs = [(a.displacement[0], b.displacement[0], -1.0)] + [(np.abs(U), np.abs(V), 1.0) for U, V in zip(a.displacement, b.displacement)]
    for U, V, sign in pairs:
        scale = np.abs(U).max()
        np.testing.assert_allclose(V[:, 0] / scale, sign * U[:, 1] / scale, atol=1e-12)  # x' = -y
        np.testing.assert_allclose(V[:, 1] / scale, U[:, 0] / scale, atol=1e-12)  # y' = x
        np.testing.assert_allclose(V[:, 2] / scale, U[:, 2] / scale, atol=1e-12)
    np.testing.assert_allclose(b.peak, a.peak[:, [1, 0, 2]], rtol=1e-10)
    np.testing.assert_allclose(b.velocity_rms, a.velocity_rms[:, [1, 0, 2]], rtol=1e-10)


# ---- an independent model: Newton-Euler at the centre of mass G, written out here ----


def _newton_euler(scene, loaded=True):
    """Right-hand side of the equations of motion about G (not about O as the solver writes them):
    m u_G'' = F, J_G θ'' = moment about G. The springs and dashpots at O act on O's motion
    u_O = u_G + θ × (O - G); the soil's static reaction W acts under G and turns with the block,
    its moment about G after a tilt being W h (θ_x, θ_y, 0) with h the height of G."""
    bodies = [scene.block.mass_properties] + [(m.mass, m.cog, m.inertia) for m in scene.machines]
    m = sum(b[0] for b in bodies)
    G = sum(b[0] * np.asarray(b[1], dtype=float) for b in bodies) / m
    J = np.zeros((3, 3))
    for mb, r, Jb in bodies:
        d = np.asarray(r, dtype=float) - G
        J += np.diag(Jb) + mb * (d @ d * np.eye(3) - np.outer(d, d))
    L, B = scene.base
    J_O = J + m * (G @ G * np.eye(3) - np.outer(G, G))
    from foundation_calc.solvers.supports.footing_springs import six_springs

    k, xi = six_springs(scene.soil, L, B, m, np.diag(J_O))
    k = np.asarray(k)
    if xi is None:
        c = np.asarray(scene.soil.dashpot or [0.0] * 6)
    else:  # 2 ξ sqrt(k m_i), m_i about the axes through O
        c = 2.0 * np.asarray(xi) * np.sqrt(k * np.concatenate([[m] * 3, np.diag(J_O)]))
    arm = -G  # O - G
    loads = [(mach.omega_rad_s, row) for mach in scene.machines for row in mach.load_rows()] if loaded else []
    W = m * GRAVITY
    Jinv = np.linalg.inv(J)

    def rhs(t, s):
        u, th, du, dth = s[:3], s[3:6], s[6:9], s[9:]
        uO, duO = u + np.cross(th, arm), du + np.cross(dth, arm)
        F = -k[:3] * uO - c[:3] * duO
        Mo = np.cross(arm, F) - k[3:] * th - c[3:] * dth + W * G[2] * np.array([th[0], th[1], 0.0])
        for w, (n, f, mom, phase, at, *_) in loads:
            a = math.cos(n * w * t + phase)
            Fl = a * np.asarray(f)
            F = F + Fl
            Mo = Mo + a * np.asarray(mom) + np.cross(np.asarray(at) - G, Fl)
        return np.concatenate([du, dth, F / m, Jinv @ Mo])

    return rhs, G


def test_natural_frequencies_agree_with_free_vibration_of_the_newton_euler_equations():
    data = _two_machines()
    data["soil"].pop("dashpot")
    scene = parse_scene(data)
    rhs, G = _newton_euler(scene, loaded=False)
    modes = block_modes(scene.model())
    for p, v in zip(modes.frequencies, modes.shapes.T):
        u_G = v[:3] + np.cross(v[3:], G)  # the mode's motion of G
        start = np.concatenate([u_G, v[3:], np.zeros(6)])
        T = 2.0 * math.pi / p
        end = solve_ivp(rhs, (0.0, T), start, method="DOP853", rtol=1e-12, atol=1e-14 * np.abs(start).max()).y[:, -1]
        # after one period of the mode the state is back where it started (and not at another p)
        assert np.abs(end - start).max() < 1e-6 * np.abs(start).max(), (p, np.abs(end - start).max())


def test_steady_state_agrees_with_time_integration_of_the_newton_euler_equations():
    scene = load_scene(f"{CONFIGS}/block_two_machines.toml")
    rhs, G = _newton_euler(scene)
    model = scene.model()
    motion = point_motion(model, scene.excitations(), [], np.zeros((0, 3)))
    excs = scene.excitations()

    def state(t):
        u, th = np.zeros(3), np.zeros(3)
        du, dth = np.zeros(3), np.zeros(3)
        for exc, U, R in zip(excs, motion.displacement, motion.rotation):
            e = np.exp(1j * exc.orders * exc.omega * t)
            iw = 1j * exc.orders * exc.omega
            u, th = u + (U[0] @ e).real, th + (R @ e).real
            du, dth = du + (U[0] @ (iw * e)).real, dth + (R @ (iw * e)).real
        return np.concatenate([u, th, du, dth])

    T = 2.0 * math.pi / min(e.omega for e in excs)
    start = state(0.0)
    sol = solve_ivp(rhs, (0.0, T), start, method="DOP853", rtol=1e-11, atol=1e-20, dense_output=True)
    for t in np.linspace(0.0, T, 5)[1:]:
        got, want = sol.sol(t), state(t)
        scale = np.abs(start[:6]).max()
        assert np.abs(got[:3] - want[:3]).max() < 1e-6 * np.abs(start[:3]).max()
        assert np.abs(got[3:6] - want[3:6]).max() < 1e-6 * np.abs(start[3:6]).max(), (t, scale)


def test_a_misspelt_key_names_the_nearest_one():
    data = _two_machines()
    data["machines"][0]["sped_rpm"] = data["machines"][0].pop("speed_rpm")
    with pytest.raises(Exception) as err:
        parse_scene(data)
    assert "speed_rpm" in str(err.value)


def test_a_sweep_at_the_scene_speed_is_the_scene_steady_state():
    """The vectorised sweep of one machine (others fixed) against the per-scene solve: the same
    algebra batched, so to round-off (1e-13)."""
    from foundation_calc.solvers.block.sweep import speed_sweep

    scene = load_scene(f"{CONFIGS}/block_two_machines.toml")
    model, excs = scene.model(), scene.excitations()
    points = [p.at for p in scene.points]
    steady = point_motion(model, excs, [p.name for p in scene.points], points)
    for swept in (0, 1):
        omega = np.array([0.5 * excs[swept].omega, excs[swept].omega])
        sweep = speed_sweep(model, block_modes(model), excs, swept, omega, points)
        np.testing.assert_allclose(sweep.peak[1], steady.peak, rtol=1e-13)
        np.testing.assert_allclose(sweep.velocity_rms[1], steady.velocity_rms, rtol=1e-13)
        assert np.all(sweep.peak[0] != sweep.peak[1])
