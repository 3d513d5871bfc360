"""Machines given by their loads: the block's steady state against independent methods.

Reference: the rigid block's equations of motion written here from the forces on it (soil
springs and dashpots at the base, the weight's overturning moment, each load's force at its
point of action and its moment about C from r × F), integrated from rest with scipy's solve_ivp
(DOP853) until the transient has decayed (e^-40), the last period analysed by FFT; natural
frequencies by a brute-force generalized eigen-solve of those equations.
"""

from __future__ import annotations

import json
import math

import numpy as np
import pytest

from foundation_calc.cli.app import app
from foundation_calc.scenes.loading import parse_scene
from foundation_calc.solvers.crank.loads import loads_response
from tests.conftest import CONFIGS

scipy_integrate = pytest.importorskip("scipy.integrate")
scipy_linalg = pytest.importorskip("scipy.linalg")

G = 9.81
BLOCK = {"mass": 1.0e5, "moment_of_inertia": 4.5e5, "cog_height": 1.5, "base_area": 30.0, "base_second_moment": 90.0}
SOIL = {"c_z": 4.0e7, "c_x": 2.8e7, "c_phi": 5.0e7}
LOADS = [
    {"order": 1, "horizontal": 12.0e3, "vertical": 5.0e3, "phase": 0.4, "at": {"horizontal": 0.5, "height": 1.0}},
    {"order": 2, "horizontal": 3.0e3, "moment": 2.0e3, "phase": -1.1, "at": {"horizontal": -0.3, "height": 2.0}},
]


def loads_scene(omega, damping=None, loads=LOADS, mass=BLOCK["mass"]) -> dict:
    soil = dict(SOIL, **({} if damping is None else {"damping": list(damping)}))
    return {
        "kind": "crank_foundation",
        "foundation": dict(BLOCK, mass=mass),
        "soil": soil,
        "operation": {"omega": omega},
        "loads": [dict(ld) for ld in loads],
        "points": [{"name": "top", "horizontal": 2.0, "height": 1.3}],
    }


def reference_forces(scene, q, qd, t, omega):
    """Generalized forces on the block (x, y, θ), y and the base below C positive downward."""
    f, s = scene.foundation, scene.soil
    block = scene.block()  # only for the dashpots' values C = 2 ξ sqrt(K m)
    x, y, th = q
    xd, yd, thd = qd
    M_tot, h = f.mass, f.cog_height
    base_x = -s.c_x * f.base_area * (x - h * th) - block.C_x * (xd - h * thd)  # at the base, r = (0, h)
    base_y = -s.c_z * f.base_area * y - block.C_z * yd
    rocking = -s.c_phi * f.base_second_moment * th - block.C_phi * thd + M_tot * G * h * th
    Fx, Fy, Mt = base_x, base_y, rocking - h * base_x  # r × F = r_x F_y - r_y F_x with r = (0, h)
    for ld in scene.loads:
        w = ld.order * omega * t + ld.phase
        fx, fy, mo = (v * math.cos(w) for v in (ld.horizontal, ld.vertical, ld.moment))
        r = (ld.at.horizontal, -ld.at.height)  # above C is negative y
        Fx, Fy, Mt = Fx + fx, Fy + fy, Mt + mo + r[0] * fy - r[1] * fx
    return np.array([Fx, Fy, Mt])


def integrated_steady_state(scene, omega, top):
    """Cos/sin coefficients (3, top + 1) of the motion after the transient, by time integration."""
    f = scene.foundation
    mass = np.array([f.mass, f.mass, f.moment_of_inertia])

    def rhs(t, z):
        return np.concatenate([z[3:], reference_forces(scene, z[:3], z[3:], t, omega) / mass])

    T = 2 * math.pi / omega
    periods = math.ceil(2.5 / T)  # the slowest mode of the test scenes decays by e^-40 in 2.5 s
    N = 64
    t_last = periods * T + np.arange(N) * T / N
    sol = scipy_integrate.solve_ivp(rhs, (0.0, t_last[-1]), np.zeros(6), method="DOP853", rtol=1e-11, atol=1e-16, t_eval=t_last)
    spectrum = np.fft.rfft(sol.y[:3], axis=-1) * 2 / N
    return spectrum.real[:, : top + 1], -spectrum.imag[:, : top + 1]


def natural_frequencies(scene):
    """sqrt of the eigenvalues of K q = p² M q, K from unit displacements of the reference forces."""
    K = -np.column_stack([reference_forces(scene.model_copy(update={"loads": []}), e, np.zeros(3), 0.0, 1.0) for e in np.eye(3)])
    f = scene.foundation
    return np.sqrt(scipy_linalg.eigh(K, np.diag([f.mass, f.mass, f.moment_of_inertia]), eigvals_only=True))


def test_damped_loads_at_exact_resonance_match_time_integration():
    probe = parse_scene(loads_scene(10.0, damping=(0.3, 0.3, 0.3)), "probe")
    p1 = natural_frequencies(probe)[0]  # ω = p1: the 1st-order loads sit on the lower rocking mode
    scene = parse_scene(loads_scene(p1, damping=(0.3, 0.3, 0.3)), "damped")
    response = loads_response(scene.block(), p1, scene.harmonic_loads())
    assert not response.resonant and response.margin < 1e-9
    cos, sin = integrated_steady_state(scene, p1, 2)
    scale = np.abs(cos + 1j * sin).max(axis=1, keepdims=True)
    # tolerance: the ODE's rtol 1e-11 over ~30 periods and the e^-40 remainder of the transient
    np.testing.assert_allclose(response.motion.cos / scale, cos / scale, atol=1e-7)
    np.testing.assert_allclose(response.motion.sin / scale, sin / scale, atol=1e-7)


def test_undamped_loads_at_exact_resonance_are_resonant_not_nan(runner, tmp_path):
    probe = parse_scene(loads_scene(10.0), "probe")
    p1 = float(natural_frequencies(probe)[0])
    omega = p1 / 2  # the 2nd-order loads meet p1
    path = tmp_path / "resonant.toml"
    import tomli_w

    path.write_text(tomli_w.dumps(loads_scene(omega)), encoding="utf-8")
    result = runner.invoke(app, ["amplitudes", str(path), "--json"])
    assert result.exit_code == 1, result.output
    doc = json.loads(result.stdout)  # fcalc writes JSON with allow_nan=False: a NaN would be exit 4
    loads = doc["approximations"]["loads"]
    assert loads["resonant"] is True and loads["resonance_margin"] < 1e-9
    assert loads["nearest_resonance"] == "2ω = p1 (loads)"
    res = json.loads(runner.invoke(app, ["resonance", str(path), "--json"]).stdout)
    row = next(r for r in res["resonances"] if r["condition"] == "2ω = p1")
    assert row["source"] == "loads" and row["margin"] < 1e-9 and row["verdict"] == "fail"
    assert res["natural_frequencies"]["p1"] == pytest.approx(p1, rel=1e-12)
    sweep = json.loads(runner.invoke(app, ["sweep", str(path), "--speed", f"{omega * 0.5}:{omega * 1.5}:3rad/s", "--json"]).stdout)
    middle = sweep["points"][1]
    assert middle["resonant"] is True and middle["x_peak"] is None and middle["status"] == "resonant"


def test_undamped_loads_off_resonance_match_time_integration_of_the_damped_limit():
    """Without damping there is no decaying transient to integrate; a tiny damping (ξ = 1e-9)
    changes the steady state by ~1e-9 relative away from resonances, so the undamped solve must
    agree with the lightly damped one there (and the damped one is checked above)."""
    undamped = parse_scene(loads_scene(20.0), "u")
    light = parse_scene(loads_scene(20.0, damping=(1e-9, 1e-9, 1e-9)), "l")
    a = loads_response(undamped.block(), 20.0, undamped.harmonic_loads()).motion
    b = loads_response(light.block(), 20.0, light.harmonic_loads()).motion
    scale = np.abs(a.cos).max()
    np.testing.assert_allclose(a.cos / scale, b.cos / scale, atol=1e-7)


def test_static_limit_is_the_stiffness_solve():
    """ω → 0: the response to loads of order 1 tends to K⁻¹ F with K from the reference forces."""
    scene = parse_scene(loads_scene(1e-4, loads=[LOADS[0]]), "static")
    K = -np.column_stack([reference_forces(scene.model_copy(update={"loads": []}), e, np.zeros(3), 0.0, 1.0) for e in np.eye(3)])
    ld = LOADS[0]
    F = np.array([ld["horizontal"], ld["vertical"], ld["at"]["height"] * ld["horizontal"] + ld["at"]["horizontal"] * ld["vertical"]])
    static = np.linalg.solve(K, F) * np.exp(1j * ld["phase"])
    got = loads_response(scene.block(), 1e-4, scene.harmonic_loads()).motion
    np.testing.assert_allclose(got.cos[:, 1] - 1j * got.sin[:, 1], static, rtol=1e-6)


def test_mechanism_and_loads_add_linearly(runner, tmp_path):
    import tomli_w

    from foundation_calc.scenes import read_toml

    saw = read_toml(CONFIGS / "frame_saw.toml")
    both = dict(saw, loads=LOADS)
    mech = saw["mechanism"]
    alone = loads_scene(None, loads=LOADS, mass=saw["foundation"]["mass"] + mech["rod_mass"] + mech.get("slider_mass", 0.0))
    alone["foundation"] = dict(saw["foundation"], mass=alone["foundation"]["mass"])
    alone["soil"] = saw["soil"]
    alone["operation"] = {"speed_rpm": mech["speed_rpm"]}
    alone["points"] = saw.get("points", [])
    docs = {}
    for key, data in (("both", both), ("saw", saw), ("alone", alone)):
        path = tmp_path / f"{key}.toml"
        path.write_text(tomli_w.dumps(data), encoding="utf-8")
        result = runner.invoke(app, ["amplitudes", str(path), "--json"])
        docs[key] = json.loads(result.stdout)
    for method in ("first_approximation", "averaged_operator"):
        combined = docs["both"]["approximations"][method]["harmonics"]
        assert docs["both"]["approximations"][method]["title"].endswith("+ vendor loads (linear)")
        for name, h in combined.items():
            mechanism = docs["saw"]["approximations"][method]["harmonics"].get(name, {"cos": 0.0, "sin": 0.0})
            loads = docs["alone"]["approximations"]["loads"]["harmonics"].get(name, {"cos": 0.0, "sin": 0.0})
            for part in ("cos", "sin"):
                assert h[part] == pytest.approx(mechanism[part] + loads[part], rel=1e-12, abs=1e-18), (method, name, part)


def test_loads_rows_join_the_resonance_check_with_the_verdict_rule():
    probe = parse_scene(loads_scene(10.0), "probe")
    k0 = float(np.sqrt(SOIL["c_z"] * BLOCK["base_area"] / BLOCK["mass"]))
    vertical_only = [{"order": 1, "vertical": 1.0e3}]
    scene = parse_scene(loads_scene(k0 * 1.1, loads=[{"order": 1, "horizontal": 1.0e3}]), "h")
    from foundation_calc.checks.resonance import check_scene_resonances

    rows = {r.condition.label: r for r in check_scene_resonances(scene).rows}
    assert rows["ω = k0"].outcome.value == "warn"  # a horizontal load does not drive k0: warns in the band
    scene = parse_scene(loads_scene(k0 * 1.1, loads=vertical_only), "v")
    rows = {r.condition.label: r for r in check_scene_resonances(scene).rows}
    assert rows["ω = k0"].outcome.value == "fail" and rows["ω = k0"].margin == pytest.approx(0.1, rel=1e-9)
    assert probe.mechanism is None


@pytest.mark.parametrize(
    "change, needle",
    [
        ({"operation": None}, "needs its speed"),
        ({"loads": []}, "give the machine as [mechanism] or by its [[loads]]"),
        ({"loads": [{"order": 1}]}, "give at least one of horizontal"),
        ({"loads": [{"order": 0, "horizontal": 1.0}]}, "loads.0.order"),
    ],
)
def test_bad_loads_scenes_are_invalid(change, needle):
    from foundation_calc.errors import SceneError

    data = loads_scene(30.0)
    for key, value in change.items():
        if value is None:
            data.pop(key)
        else:
            data[key] = value
    with pytest.raises(SceneError) as err:
        parse_scene(data, "bad")
    assert needle in str(err.value)


def test_shipped_vendor_loads_config_passes_every_command(runner):
    path = str(CONFIGS / "compressor_vendor_loads.toml")
    for command in (["resonance"], ["amplitudes"], ["sweep", "--speed", "1000:2000:11"], ["check"]):
        result = runner.invoke(app, [*command, path])
        assert result.exit_code == 0, (command, result.output)
    doc = json.loads(runner.invoke(app, ["amplitudes", path, "--json"]).stdout)
    assert {p["zone"] for p in doc["code"]["points"]} == {"A"} and doc["code"]["warnings"] == []


def test_sweep_points_equal_the_single_speed_answer(runner):
    """A speed sweep and a soil sweep through the scene's own speed and soil give the peaks of
    ``fcalc amplitudes`` there (the sweep's vectorised path against the single solve)."""
    path = str(CONFIGS / "compressor_vendor_loads.toml")
    single = json.loads(runner.invoke(app, ["amplitudes", path, "--json"]).stdout)["approximations"]["loads"]
    speed = json.loads(runner.invoke(app, ["sweep", path, "--speed", "1400:1500:3", "--json"]).stdout)["points"][-1]
    soil = json.loads(runner.invoke(app, ["sweep", path, "--soil", "0.5:1:3", "--json"]).stdout)["points"][-1]
    for point in (speed, soil):
        assert point["x_peak"] == pytest.approx(single["peaks"]["x"]["displacement"], rel=1e-12)
        assert point["theta_peak"] == pytest.approx(single["peaks"]["theta"]["displacement"], rel=1e-12)
        bearing = point["points"]["crankshaft bearing"]
        assert bearing["horizontal"] == pytest.approx(single["points"]["crankshaft bearing"]["horizontal"]["displacement"], rel=1e-12)
