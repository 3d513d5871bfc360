"""Numerical stress tests of the closed-form amplitudes and of ``fcalc sweep``.

Speeds 1e-12 .. 1e-2 relative from every resonance, μ → 0 and 0.5, λ → 1, p1 ≈ p2, rocking near
instability, random designs over six decades: the answer is a finite amplitude, a resonant
verdict with its margin, or a clear error — never inf, NaN or a traceback. Where the exact
solution exists the closed form's error is bounded by what its truncation predicts.
"""

from __future__ import annotations

import json
from dataclasses import replace

import numpy as np
import pytest
import tomli_w
from hypothesis import example, given, settings
from hypothesis import strategies as st

from foundation_calc.checks.sweep.crank import sweep
from foundation_calc.cli.app import app
from foundation_calc.errors import PhysicsError, SceneError
from foundation_calc.scenes import parse_scene
from foundation_calc.solvers.crank.closed_form import first_approximation_motion
from foundation_calc.solvers.crank.exact import exact_periodic_solution
from foundation_calc.solvers.crank.first_approximation import RESONANT_MARGIN
from foundation_calc.solvers.crank.mechanism import lump_slider
from foundation_calc.solvers.crank.resonance import CONDITIONS
from foundation_calc.solvers.crank.response import motion_peaks
from tests import crank_reference as ref
from tests.test_stress_resonance import _finite

OFFSETS = np.array([0.0, 1e-12, -1e-12, 1e-9, -1e-9, 1e-6, -1e-6, 1e-4, -1e-4, 1e-2, -1e-2])



def _check_sweep(report):
    assert np.all(np.isfinite(report.columns["peaks"])) and np.all(report.columns["peaks"] >= 0)
    assert np.all(np.isfinite(report.rows.margin)) and np.all(report.rows.margin >= 0)
    assert np.all(report.columns["peaks"][report.resonant] == 0)


@pytest.mark.parametrize("critical", ["zero_order", "averaged"])
@pytest.mark.parametrize("condition", CONDITIONS, ids=lambda c: c.label)
def test_speeds_near_every_resonance(frame_saw, condition, critical):
    design = parse_scene(frame_saw).design()
    (crit,) = [c for c in sweep(design, "omega", [1e-3, 1e4], None, 0.2).critical if c.label == condition.label]
    omegas = getattr(crit, critical) * (1.0 + OFFSETS)
    report = sweep(design, "omega", omegas, None, 0.2)
    _check_sweep(report)
    if condition.source == "paper":  # judged: it governs this close (an extra one may be information)
        assert np.all(report.rows.margin <= np.abs(OFFSETS) * (1 + 1e-6) + 1e-15)
    # an extra condition decides only when its forcing share reaches 1 % (docs/resonance-rule.md)
    expected = {"paper": {"fail", "resonant"}, "extra": {"pass", "warn", "fail", "resonant"}}[condition.source]
    assert set(report.rows.status) <= expected
    if condition.source == "paper" and critical == "zero_order":
        # the first approximation's own denominators vanish here: no periodic solution
        clear = np.abs(np.abs(OFFSETS) - RESONANT_MARGIN) > 1e-7  # not at the threshold itself
        assert np.all(report.resonant[clear] == (np.abs(OFFSETS) < RESONANT_MARGIN)[clear])


def test_cli_sweep_through_a_resonance_reports_it(runner, tmp_path, frame_saw):
    design = parse_scene(frame_saw).design()
    (crit,) = [c for c in sweep(design, "omega", [1e-3, 1e4], None, 0.2).critical if c.label == "ω = p1"]
    w = crit.zero_order
    path = tmp_path / "s.toml"
    path.write_text(tomli_w.dumps(frame_saw), encoding="utf-8")
    for spec in (f"{w * (1 - 1e-2)!r}:{w * (1 + 1e-2)!r}:3rad/s", f"{w * (1 - 1e-12)!r}:{w * (1 + 1e-12)!r}:5rad/s"):
        result = runner.invoke(app, ["sweep", str(path), "--speed", spec, "--json"])
        assert result.exit_code == 0, result.output
        doc = json.loads(result.stdout)
        assert _finite(doc)
        middle = doc["points"][len(doc["points"]) // 2]
        assert middle["resonant"] and middle["x_peak"] is None and middle["status"] == "resonant"
        assert middle["margin"] < 1e-12 and middle["governing_condition"] == "ω = p1"
        table = runner.invoke(app, ["sweep", str(path), "--speed", spec])
        assert table.exit_code == 0 and "resonant" in table.stdout


@pytest.mark.parametrize("lam, mu", [(0.25, 1e-2), (0.25, 1e-4), (0.1, 1e-3), (0.03, 1e-2), (0.03, 1e-4), (0.25, 0.3), (0.25, 0.5)])
def test_first_approximation_error_is_bounded_by_its_truncation(frame_saw, lam, mu):
    """Away from every resonance (margins ≥ 29 % at ω = 15 rad/s) the peaks' error against the
    exact periodic solution is O(μ) from the zero-order operator and O(λ³) from the truncated
    slider motion (the missing 4ω and λ³ terms). Observed: ≤ 0.04 μ + 0.2 μ² + 0.08 λ³; the
    bound has ~25 % margin, and the error goes to 0 as both go to 0."""
    design = parse_scene(frame_saw).design()
    m = mu / (1 - mu) * design.M
    design = replace(design, omega=15.0, r=lam * design.l, rod=lump_slider(m, design.l, 1.0, 0.35, 0.0))
    exact = motion_peaks(exact_periodic_solution(design).motion).displacement
    closed = motion_peaks(first_approximation_motion(design)[0]).displacement
    error = np.max(np.abs(closed / exact - 1))
    assert error <= 0.05 * mu + 0.25 * mu**2 + 0.1 * lam**3


@pytest.mark.parametrize("mu", [1e-12, 1e-6, 0.25, 0.5])
@pytest.mark.parametrize("lam", [1e-6, 0.5, 0.999, 1 - 1e-9])
def test_mu_and_lambda_limits_give_finite_amplitudes(frame_saw, mu, lam):
    mech = frame_saw["mechanism"]
    mech["rod_mass"] = mu / (1 - mu) * frame_saw["foundation"]["mass"]
    mech["crank_radius"] = mech["rod_length"] * lam
    design = parse_scene(frame_saw).design()
    report = sweep(design, "omega", np.geomspace(1e-3, 1e4, 121), 2e-4, 0.2)
    _check_sweep(report)
    peaks = report.columns["peaks"][~report.resonant]
    # the amplitude is proportional to μ (μ → 0 leaves a motionless foundation, not 0/0)
    assert np.all(peaks <= 1e4 * mu * design.r + 1e-300)


def test_nearly_equal_p1_p2(frame_saw):
    ref.make_p1_equal_p2(frame_saw)
    design = parse_scene(frame_saw).design()
    crit = {c.label: c for c in sweep(design, "omega", [1e-3, 1e4], None, 0.2).critical}
    assert crit["ω = p1"].zero_order == pytest.approx(crit["ω = p2"].zero_order, rel=1e-4)
    report = sweep(design, "omega", crit["ω = p1"].zero_order * (1 + OFFSETS), None, 0.2)
    _check_sweep(report)
    assert report.resonant[0] and set(report.rows.status) <= {"fail", "resonant"}


@pytest.mark.parametrize("reserve", [1e-4, 1e-8, 1e-12])
def test_rocking_near_instability(frame_saw, reserve):
    f = frame_saw["foundation"]
    M_tot = f["mass"] + frame_saw["mechanism"]["rod_mass"]
    f["base_second_moment"] = M_tot * ref.G * f["cog_height"] / frame_saw["soil"]["c_z"] * (1 + reserve)
    report = sweep(parse_scene(frame_saw).design(), "omega", np.geomspace(1e-3, 1e4, 101), None, 0.2)
    _check_sweep(report)


def test_soil_sweep_into_instability_is_a_clear_error(runner, frame_saw, tmp_path):
    f = frame_saw["foundation"]
    M_tot = f["mass"] + frame_saw["mechanism"]["rod_mass"]
    f["base_second_moment"] = M_tot * ref.G * f["cog_height"] / frame_saw["soil"]["c_z"] * 1.5
    path = tmp_path / "s.toml"
    path.write_text(tomli_w.dumps(frame_saw), encoding="utf-8")
    result = runner.invoke(app, ["sweep", str(path), "--soil", "0.5:1.5:11", "--json"])
    assert result.exit_code == 3
    assert "unstable in rocking" in result.stderr and json.loads(result.stdout)["verdict"] == "invalid"


magnitudes = st.floats(-3.0, 3.0)


@settings(max_examples=50, deadline=None)
@given(
    mass=magnitudes, inertia=magnitudes, height=st.floats(-2, 1.5), area=magnitudes,
    second=magnitudes, c_z=magnitudes, c_x=st.floats(-2, 1), mu=st.floats(1e-9, 0.5),
    lam=st.floats(1e-6, 1 - 1e-9), cog=st.floats(1e-6, 1 - 1e-6), drive_on=st.booleans(),
)
@example(mass=0.0, inertia=0.0, height=0.0, area=0.0, second=0.0, c_z=0.0, c_x=0.0, mu=0.5, lam=1 - 1e-9,
         cog=1e-6, drive_on=False)
def test_random_designs_sweep_to_finite_numbers_or_clear_errors(
    mass, inertia, height, area, second, c_z, c_x, mu, lam, cog, drive_on
):
    scene = ref.scaled_scene(
        mass=mass, inertia=inertia, height=height, area=area, second=second, c_z=c_z, c_x=c_x,
        mu=mu, lam=lam, cog=cog, drive_on=drive_on,
    )
    try:
        design = parse_scene(scene).design()
        report = sweep(design, "omega", np.geomspace(1e-4, 1e5, 120), 2e-4, 0.2)
        soil = sweep(design, "soil_factor", np.linspace(0.5, 1.5, 11), 2e-4, 0.2)
    except (SceneError, PhysicsError) as exc:
        assert str(exc)
        return
    _check_sweep(report)
    _check_sweep(soil)
