"""Numerical stress tests of the natural frequencies and the resonance check.

Inputs span many orders of magnitude and approach every singular or degenerate point: a speed
1e-12 .. 1e-2 relative from each resonance, p1 ≈ p2, μ → 0 and μ → 0.5, λ → 1, rocking near
instability. The tool must answer with finite numbers, a resonance verdict with its margin, or a
clear error — never inf, NaN or a traceback.
"""

from __future__ import annotations

import json
import math

import pytest
import tomli_w
from hypothesis import given, settings
from hypothesis import strategies as st

from foundation_calc.checks.resonance.report import check_resonances
from foundation_calc.cli.app import app
from foundation_calc.errors import PhysicsError, SceneError
from foundation_calc.scenes import parse_scene
from foundation_calc.solvers.crank.resonance import CONDITIONS
from tests import crank_reference as ref


def _finite(node) -> bool:
    if isinstance(node, dict):
        return all(_finite(v) for v in node.values())
    if isinstance(node, list):
        return all(_finite(v) for v in node)
    return not isinstance(node, float) or math.isfinite(node)


@pytest.mark.parametrize("condition", CONDITIONS, ids=lambda c: c.label)
@pytest.mark.parametrize("offset", [0.0, 1e-12, -1e-12, 1e-9, 1e-6, -1e-4, 1e-2])
def test_speed_near_every_resonance(frame_saw, condition, offset):
    design = parse_scene(frame_saw).design()
    report = check_resonances(design, 0.2)
    row = next(r for r in report.rows if r.condition == condition)
    frame_saw["mechanism"].pop("speed_rpm")
    frame_saw["mechanism"]["omega"] = row.critical * (1.0 + offset)
    report = check_resonances(parse_scene(frame_saw).design(), 0.2)
    row = next(r for r in report.rows if r.condition == condition)
    assert math.isfinite(row.margin)
    assert row.margin <= abs(offset) * (1 + 1e-6) + 1e-15
    # within 5 % a judged condition fails (the paper's, or an extra one whose forcing share reaches
    # 1 %); an extra one without forcing is information (docs/resonance-rule.md)
    assert row.outcome.value == ("fail" if row.judged else "pass")
    assert row.judged or (row.condition.source == "extra" and row.information)


magnitudes = st.floats(-3.0, 3.0)  # decades around the frame saw's values


@settings(max_examples=150, deadline=None)
@given(
    mass=magnitudes, inertia=magnitudes, height=st.floats(-2, 1.5), area=magnitudes,
    second=magnitudes, c_z=magnitudes, c_x=st.floats(-2, 1), speed=st.floats(-3, 3),
    mu=st.floats(1e-9, 0.5), lam=st.floats(1e-6, 1 - 1e-9), cog=st.floats(1e-6, 1 - 1e-6),
)
def test_random_scenes_give_finite_answers_or_clear_errors(
    mass, inertia, height, area, second, c_z, c_x, speed, mu, lam, cog
):
    scene = ref.scaled_scene(
        mass=mass, inertia=inertia, height=height, area=area, second=second, c_z=c_z, c_x=c_x,
        mu=mu, lam=lam, cog=cog, omega=31.4 * 10**speed,
    )
    try:
        loaded = parse_scene(scene)
        report = check_resonances(loaded.design(), loaded.limits.detuning)
    except (SceneError, PhysicsError) as exc:
        assert str(exc)
        return
    freqs = [report.zero_order.k0, report.zero_order.p1, report.zero_order.p2,
             report.averaged.p1, report.averaged.p2]
    assert all(math.isfinite(f) and f > 0 for f in freqs)
    assert all(math.isfinite(r.margin) for r in report.rows)
    assert report.zero_order.p1 <= report.zero_order.p2 * (1 + 1e-12)


def test_rocking_near_instability_keeps_its_digits(frame_saw):
    """p1² is proportional to the stability reserve c I1/(P h) − 1 as it goes to zero.

    The naive root (a0+b1)/2 − sqrt(...) would lose all digits at a reserve of 1e-12; the ratio
    p1²/reserve must stay constant (p2 hardly moves) to the rounding of the reserve itself.
    """
    f = frame_saw["foundation"]
    M_tot = f["mass"] + frame_saw["mechanism"]["rod_mass"]
    critical_I1 = M_tot * ref.G * f["cog_height"] / frame_saw["soil"]["c_z"]
    ratios = []
    for reserve in (1e-4, 1e-8, 1e-12):
        f["base_second_moment"] = critical_I1 * (1 + reserve)
        report = check_resonances(parse_scene(frame_saw).design(), 0.2)
        assert report.stability_margin == pytest.approx(reserve, rel=1e-3)
        ratios.append(report.zero_order.p1**2 / report.stability_margin)
    assert ratios[1] == pytest.approx(ratios[0], rel=1e-3)
    assert ratios[2] == pytest.approx(ratios[0], rel=1e-3)


def test_exactly_unstable_is_reported_with_its_field(runner, tmp_path, frame_saw):
    f = frame_saw["foundation"]
    M_tot = f["mass"] + frame_saw["mechanism"]["rod_mass"]
    f["base_second_moment"] = M_tot * ref.G * f["cog_height"] / frame_saw["soil"]["c_z"]
    path = tmp_path / "s.toml"
    path.write_text(tomli_w.dumps(frame_saw), encoding="utf-8")
    result = runner.invoke(app, ["resonance", str(path), "--json"])
    assert result.exit_code == 3
    assert "unstable in rocking" in result.stderr and json.loads(result.stdout)["verdict"] == "invalid"


def test_nearly_equal_p1_p2(frame_saw):
    """a0 = b1 and a vanishing coupling make p1 = p2: the discriminant must not go negative."""
    ref.make_p1_equal_p2(frame_saw)
    report = check_resonances(parse_scene(frame_saw).design(), 0.2)
    assert report.zero_order.p1 == pytest.approx(report.zero_order.p2, rel=1e-4)
    assert math.isfinite(report.averaged.p1) and math.isfinite(report.averaged.p2)


@pytest.mark.parametrize("lam", [0.5, 0.9, 0.999, 1 - 1e-9])
def test_lambda_towards_one(runner, tmp_path, frame_saw, lam):
    frame_saw["mechanism"]["crank_radius"] = frame_saw["mechanism"]["rod_length"] * lam
    path = tmp_path / "s.toml"
    path.write_text(tomli_w.dumps(frame_saw), encoding="utf-8")
    result = runner.invoke(app, ["resonance", str(path), "--json"])
    assert result.exit_code in (0, 1)
    assert _finite(json.loads(result.stdout))


@pytest.mark.parametrize("mu", [1e-12, 1e-6, 0.25, 0.5])
def test_mu_limits(frame_saw, mu):
    M = frame_saw["foundation"]["mass"]
    frame_saw["mechanism"]["rod_mass"] = mu / (1 - mu) * M
    report = check_resonances(parse_scene(frame_saw).design(), 0.2)
    assert report.design.mu == pytest.approx(mu, rel=1e-12)
    shift = abs(report.averaged.p1 / report.zero_order.p1 - 1)
    assert shift < 10 * mu + 1e-15
