"""The crank scene's design always carries its support's coupling; the paper's closed forms step aside
where they do not apply, and say why.

1. ``CrankScene.design`` and ``in_plane`` take no ``coupled`` flag: a pile group's sway-rocking
   K_xφ, C_xφ (configs/crank_on_piles.toml) is in every design, read from the support's 6 × 6 at O
   (its (u_x, θ_y) term, taken here from the support's own matrix); the first approximation, which
   takes three uncoupled springs, refuses such a design by its own ``coupled``, by name, and the
   block under a machine given by its loads refuses the support by name.
2. The first approximation on an uncoupled frequency-dependent footing whose rocking spring at a
   harmonic's soil, K_φ(nω), does not exceed P h (Gazetas, V_s = 3 and 3.5 m/s under the medium-sand
   compressor: K_φ(ω)/(P h) = 0.74 and K_φ(2ω)/(P h) = 0.998, each standing at rest): the amplitudes
   are not refused as "unstable in rocking" (the block stands at rest) but report the averaged
   operator, the first approximation "not applicable" naming the harmonic, K_φ(nω) and P h. The
   averaged operator's harmonics n = 1, 2, 3 are checked against a direct complex solve of
   (K(nω) + i nω C(nω) - n²ω² M) Z = F_n written here: M averaged by sampling the kinematics with
   the slider a separate point mass (tests/crank_reference.py), K from the soil's generalized
   forces and the moving masses' weight tilting about C, C of the base dashpots acting on x - hθ, y and θ, each at the harmonic's soil (tolerance
   1e-9 of the largest harmonic: the sampled mean of a smooth periodic function converges
   spectrally, far below it). The mechanism's forcing F_n is the code's (not what is tested here).
3. When only harmonics the first approximation does not have (n > 3) meet K_φ(nω) <= P h
   (V_s = 3.51 m/s: only 8ω), the first approximation is reported as usual.
4. ``fcalc sweep --speed`` on those scenes runs (exit 0): at each speed where the first
   approximation steps aside (V_s = 3.5: 150 rpm, whose 2ω = 31.4 rad/s lies past the 25.1 rad/s
   where K_φ falls to P h; not 75 rpm, whose 3ω = 23.6 rad/s does not) the row's harmonics are the
   direct solve's of item 2 at that speed (1e-9, as there), and the row at the scene's own speed is
   ``fcalc amplitudes``' averaged operator (peaks and harmonics, 1e-12: the same operator and
   forcing, solved for the sweep's speeds at once); the speed where it applies keeps the first
   approximation, as amplitudes does there (1e-12). The JSON says so as on piles: ``method`` names
   the averaged operator, ``not_applicable`` amplitudes' refusal.
5. ``fcalc soil --sample`` on the V_s = 3.5 scene (stable at rest) is not refused as unstable in
   rocking: a sample without scatter is the scene, its peaks of C those of the direct solve's series
   (harmonics 0 ... 12 of item 2, the rest below 1e-12 of the peak; its peak found on 8192 phases),
   at most 0.5 % low (the sample's 96 phases a revolution); it tips over nowhere and fails the
   amplitudes, as the check does.
"""

from __future__ import annotations

import inspect

import numpy as np
import pytest

import foundation_calc as fc
from foundation_calc.scenes import read_toml
from foundation_calc.scenes.crank import CrankScene
from foundation_calc.scenes.loading import load_scene
from foundation_calc.solvers.constants import GRAVITY
from tests import crank_reference as ref
from tests.conftest import CONFIGS

PILED = CONFIGS / "crank_on_piles.toml"
FOOTING = CONFIGS / "compressor_medium_sand_lysmer.toml"


def _gazetas(tmp_path, velocity: float, speed_rpm: float | None = None):
    """The medium-sand compressor on Gazetas' springs of soil with V_s = ``velocity`` [m/s] (at
    ``speed_rpm``, its own 150 rpm by default), written under ``tmp_path``."""
    import tomli_w

    data = read_toml(FOOTING)
    data["soil"].update(method="gazetas", shear_wave_velocity=velocity)
    if speed_rpm is not None:
        data["mechanism"]["speed_rpm"] = speed_rpm
    path = tmp_path / f"gazetas_{velocity}_{speed_rpm}.toml"
    path.write_text(tomli_w.dumps(data), encoding="utf-8")
    return path


@pytest.fixture(scope="module")
def soft(tmp_path_factory):
    """velocity -> (scene, fc.amplitudes result) of :func:`_gazetas`, each computed once."""
    folder, found = tmp_path_factory.mktemp("soft"), {}

    def of(velocity: float):
        if velocity not in found:
            path = _gazetas(folder, velocity)
            found[velocity] = load_scene(path), fc.amplitudes(path)
        return found[velocity]

    return of


def test_the_coupled_flag_is_gone_from_the_scene():
    """The design and the plane's springs carry the coupling always: no flag to pass or to forget."""
    from foundation_calc.solvers.supports.plane_footing import plane

    for method in (CrankScene.design, CrankScene.in_plane, plane):
        assert "coupled" not in inspect.signature(method).parameters, method.__qualname__


def test_a_piled_design_carries_the_groups_sway_rocking():
    """K_xφ, C_xφ of the design are the (u_x, θ_y) terms of the group's 6 × 6 at O (1e-12), at rest and
    at 2ω, and the design says it is coupled."""
    scene = load_scene(PILED)
    support = scene.support()
    for w in (0.0, 2.0 * scene.speed.omega_rad_s):
        design = scene.design(w)
        at = support.impedance(w)
        K_c, C_c = (np.asarray(part, dtype=float) for part in at.coupling)
        assert design.coupled
        assert design.K_xphi == pytest.approx(K_c[0, 4], rel=1e-12) and design.K_xphi != 0.0
        assert design.C_xphi == pytest.approx(C_c[0, 4], rel=1e-12)


def test_the_piled_designs_closed_forms_step_aside_by_name():
    """The first approximation refuses the coupled design itself (NotApplicable, a PhysicsError: exit
    3 where nothing else applies), in the words fcalc amplitudes prints for it; the rigid block under
    vendor loads refuses the support by its name."""
    from foundation_calc.checks.amplitudes.approximations import FIRST_NOT_APPLICABLE
    from foundation_calc.errors import NotApplicable, PhysicsError
    from foundation_calc.solvers.crank.closed_form import design_first_approximation

    scene = load_scene(PILED)
    with pytest.raises(NotApplicable, match=r"couples sway with rocking \(K_xφ, a pile group\)") as refused:
        design_first_approximation(scene.design())
    assert isinstance(refused.value, PhysicsError)
    assert FIRST_NOT_APPLICABLE == f"not applicable: {refused.value.message}"
    with pytest.raises(PhysicsError, match=r"the support piles .*couples the motions of the plane at O") as block:
        scene.block()
    assert block.value.field == "soil"


def _averaged_by_hand(scene, n: int) -> np.ndarray:
    """Z_n = (x, y, θ) of harmonic n of C by the direct complex solve of the averaged 3 × 3 system on
    the springs and dashpots at n ω (module docstring); the forcing is the code's."""
    from foundation_calc.solvers.crank.averaged import averaged_operator

    f, mech = scene.foundation, scene.mechanism
    w = scene.speed.omega_rad_s
    d = scene.design(n * w)
    h = f.cog_height
    K = ref.stiffness_matrix(M_tot=scene.total_mass, h=h, S=d.S, I1=d.I1, c=d.c, c1=d.c1, c_phi=d.c_phi, g=GRAVITY)
    M = ref.averaged_mass_matrix(M=f.mass, I_c=f.moment_of_inertia, m=mech.rod_mass, l1=mech.rod_cog_to_crank_pin,
                                 rho=mech.rod_radius_of_gyration, m1=mech.slider_mass, a=mech.crank_axis_to_cog,
                                 r=mech.crank_radius, l=mech.rod_length)
    # the moving masses' weight tilts with θ about C: m g ⟨v⟩ of each (v downward from C; the block's
    # own weight is the -P h of the soil's forces), sampled over a revolution as the mass matrix is
    phi = np.linspace(0.0, 2.0 * np.pi, 4096, endpoint=False)
    crank_pin, slider_pin = ref.mechanism_points(phi, a=mech.crank_axis_to_cog, r=mech.crank_radius, l=mech.rod_length)
    l1, l = mech.rod_cog_to_crank_pin, mech.rod_length
    rod_cog = (l - l1) / l * crank_pin + l1 / l * slider_pin
    K[2, 2] += GRAVITY * (mech.rod_mass * rod_cog[1].mean() + mech.slider_mass * slider_pin[1].mean())
    # dashpots: C_x on the base's slide x - hθ, C_z on y, C_φ on θ
    C = np.array([[d.C_x, 0.0, -h * d.C_x], [0.0, d.C_z, 0.0], [-h * d.C_x, 0.0, h * h * d.C_x + d.C_phi]])
    _, _, _, fc_, fs = averaged_operator(d)
    W = n * w
    return np.linalg.solve(K + 1j * W * C - W * W * M, fc_[:, n] - 1j * fs[:, n])


def _harmonic(document: dict, n: int) -> np.ndarray:
    found = document["approximations"]["averaged_operator"]["harmonics"]
    return np.array([found[f"{dof}{n}"]["cos"] - 1j * found[f"{dof}{n}"]["sin"] for dof in ("x", "y", "theta")])


@pytest.mark.parametrize("velocity, n", [(3.0, 1), (3.5, 2)], ids=["V_s=3, harmonic 1", "V_s=3.5, harmonic 2"])
def test_a_harmonics_soft_soil_leaves_the_first_approximation_out_and_says_why(soft, velocity, n):
    """K_φ(nω) <= P h at the first harmonic n that meets it, the block standing at rest: the first
    approximation is not applicable there, in words that name harmonic n, K_φ(nω) and P h and do not
    call the foundation unstable; the averaged operator's harmonics are the direct solve's (1e-9),
    and judge the scene (exit 1: its vertical displacement over the limit; not 3)."""
    scene, result = soft(velocity)
    w, P_h = scene.speed.omega_rad_s, scene.total_mass * GRAVITY * scene.foundation.cog_height
    rocking = [scene.in_plane(k * w)[0][2] for k in range(4)]
    assert rocking[0] > P_h and all(k_phi > P_h for k_phi in rocking[1:n]) and rocking[n] <= P_h
    document = result.to_dict()
    why = document["not_applicable"]["first_approximation"]
    assert f"harmonic {n} " in why and f"{rocking[n]:.4g} N m/rad" in why and f"P·h = {P_h:.4g} N m" in why
    assert "does not apply at this harmonic's soil" in why and "averaged operator and the exact solution" in why
    assert "unstable" not in why
    assert set(document["approximations"]) == {"averaged_operator"} and document["checked_with"] == "averaged_operator"
    assert result.exit_code == 1 and document["verdict"] == "fail"
    for k in (1, 2, 3):
        expected = _averaged_by_hand(scene, k)
        assert _harmonic(document, k) == pytest.approx(expected, rel=1e-9, abs=1e-9 * np.abs(expected).max())


def test_a_soft_spring_past_the_first_approximations_harmonics_leaves_it_applied(soft):
    """V_s = 3.51 m/s: K_φ(nω) > P h for n <= 7, not at 8ω, a harmonic the averaged operator has and
    the first approximation has not: the first approximation is reported, nothing left out."""
    scene, result = soft(3.51)
    w, P_h = scene.speed.omega_rad_s, scene.total_mass * GRAVITY * scene.foundation.cog_height
    assert scene.in_plane(3 * w)[0][2] > P_h >= scene.in_plane(8 * w)[0][2]
    document = result.to_dict()
    assert set(document["approximations"]) == {"first_approximation", "averaged_operator"}
    assert "not_applicable" not in document


def test_the_design_batch_judges_the_soft_soil_as_check_does(soft):
    """The design batch on the V_s = 3 m/s scene gives its own block the amplitudes verdict and
    utilisation of fcalc check's amplitudes (the averaged operator's limit rows, not "tips over"; 1e-9)."""
    from foundation_calc.checks.design.candidates import FAIL
    from foundation_calc.checks.design.crank import evaluate

    scene, result = soft(3.0)
    b = scene.foundation.block
    verdicts = evaluate(scene, {f"foundation.block.{k}": np.array([getattr(b, k)]) for k in ("length", "width", "height")})
    assert result.verdict == "fail" and verdicts.outcome["amplitudes"][0] == FAIL
    assert "tips over" not in verdicts.reasons["amplitudes"][verdicts.governing["amplitudes"][0]]
    utilisation = max(row.ratio for row in (*result.report.limit_rows, *result.report.zone_rows))
    assert verdicts.utilisation["amplitudes"][0] == pytest.approx(utilisation, rel=1e-9)


def _sweep_harmonic(row: dict, key: str) -> complex:
    """The sweep row's harmonic ``key`` as cos - i sin (amplitude e^{-i phase lag})."""
    found = row["harmonics"][key]
    return found["amplitude"] * np.exp(-1j * found["phase"])


@pytest.mark.parametrize("velocity, speeds, aside", [(3.0, "150:300:2", (True, True)), (3.5, "75:150:2", (False, True))],
                         ids=["V_s=3, every speed aside", "V_s=3.5, 150 rpm aside, 75 rpm not"])
def test_the_speed_sweep_goes_on_with_the_averaged_operator_where_the_first_approximation_steps_aside(
        soft, tmp_path, runner, velocity, speeds, aside):
    """Item 4 of the module docstring."""
    import json

    from foundation_calc.cli.app import app

    scene, result = soft(velocity)
    run = runner.invoke(app, ["sweep", str(_gazetas(tmp_path, velocity)), "--speed", speeds, "--json"])
    assert run.exit_code == 0, run.output
    document = json.loads(run.stdout)
    assert "averaged operator" in document["method"]
    assert document["not_applicable"]["first_approximation"].startswith("not applicable: the paper's first approximation")
    rows = {round(row["omega"] * 30.0 / np.pi, 6): row for row in document["points"]}
    for (rpm, row), stepped_aside in zip(rows.items(), aside):
        path = _gazetas(tmp_path, velocity, rpm)
        if not stepped_aside:  # the first approximation, as amplitudes gives it at that speed
            first = fc.amplitudes(path).to_dict()
            assert "not_applicable" not in first
            found = first["approximations"]["first_approximation"]["harmonics"]
            for key in ("y1", "y2", "x1", "theta1"):
                assert _sweep_harmonic(row, key) == pytest.approx(found[key]["cos"] - 1j * found[key]["sin"], rel=1e-12)
            continue
        at = load_scene(path)
        for n in (1, 2, 3):
            expected = _averaged_by_hand(at, n)
            for i, dof in enumerate(("x", "y", "theta")):
                if f"{dof}{n}" in row["harmonics"]:
                    assert _sweep_harmonic(row, f"{dof}{n}") == pytest.approx(expected[i], rel=1e-9,
                                                                              abs=1e-9 * np.abs(expected).max())
    own = rows[150.0]  # the scene's speed: fcalc amplitudes' averaged operator
    averaged = result.to_dict()["approximations"]["averaged_operator"]
    for key, dof in (("x_peak", "x"), ("y_peak", "y"), ("theta_peak", "theta")):
        assert own[key] == pytest.approx(averaged["peaks"][dof]["displacement"], rel=1e-12)
    for key in own["harmonics"]:
        found = averaged["harmonics"][key]
        assert _sweep_harmonic(own, key) == pytest.approx(found["cos"] - 1j * found["sin"], rel=1e-12,
                                                          abs=1e-12 * abs(_sweep_harmonic(own, "y1")))
    assert own["status"] == "fail" and own["over_limits"] == ["displacement"]  # as amplitudes judges it


def test_the_soil_sample_does_not_refuse_a_scene_standing_at_rest(soft):
    """Item 5 of the module docstring."""
    from foundation_calc.checks.soil_sample import sample_scene

    scene, result = soft(3.5)
    drawn = sample_scene(scene, 4, 1e-12)
    Z = np.stack([_averaged_by_hand(scene, n) for n in range(13)], axis=-1)  # (3, 13)
    phase = np.linspace(0.0, 2.0 * np.pi, 8192, endpoint=False)
    series = np.real(Z @ np.exp(1j * np.outer(np.arange(13), phase)))
    for key, i in (("peak_horizontal_C", 0), ("peak_vertical_C", 1)):
        peak = float(np.abs(series[i]).max())
        assert peak * (1 - 0.0049) <= drawn.percentiles[key][1] <= peak * (1 + 1e-9)
    assert drawn.failure_probability["tips_over"] == 0.0
    assert drawn.failure_probability["amplitudes"] == 1.0 and result.verdict == "fail"
