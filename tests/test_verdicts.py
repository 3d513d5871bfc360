"""The verdict rule shared by both scene kinds (docs/checks.md, "Verdicts") and advice that points the
right way: each piece of advice is followed in a test and the margin it names must grow."""

from __future__ import annotations

import copy

import pytest

from foundation_calc.checks.outcomes import Outcome
from foundation_calc.checks.platform import check_platform
from foundation_calc.cli.app import app
from foundation_calc.errors import PhysicsError
from foundation_calc.scenes import parse_scene, read_toml
from foundation_calc.solvers.platform.design import amplitude_for_margin
from tests.conftest import CONFIGS

PAPER = read_toml(CONFIGS / "platform_paper_example.toml")


def _platform(**changes) -> dict:
    scene = copy.deepcopy(PAPER)
    for dotted, value in changes.items():
        table, key = dotted.split("__")
        scene[table][key] = value
    return scene


def _check(scene: dict):
    loaded = parse_scene(scene)
    return check_platform(loaded.design(), loaded.model(), loaded.limits, loaded.inertia_given)


def _finding(report, name):
    return next(f for f in report.findings if f.name == name)


def test_platform_with_mm_typed_as_m_is_not_buildable(runner):
    """u = 0.5 m puts the exciter 867 m below the platform: exit 3 naming the option and the range."""
    result = runner.invoke(app, ["platform", "--amp", "0.5"])
    assert result.exit_code == 3
    assert "error: --amp 0.5: " in result.stderr and "u < 0.0109" in result.stderr.replace("\n", "")


@pytest.mark.parametrize("regime", ["above", "below"])
def test_a_driven_translation_inside_the_band_fails(regime):
    scene = _platform(operation__amplitude=2e-3, operation__regime=regime, limits__detuning=0.2)
    report = _check(scene)
    regime_row = _finding(report, "regime margin")
    assert report.design.regime_margin < 0.2 and regime_row.outcome is Outcome.FAIL
    assert report.outcome is Outcome.FAIL


@pytest.mark.parametrize("regime", ["above", "below"])
@pytest.mark.parametrize("u", [1e-3, 2e-3])
def test_following_the_regime_advice_opens_the_margin(regime, u):
    """The advice names u <= u_max (Eq. (3.14)): a smaller u and a larger rotor mass both widen
    the margin, and u = u_max gives exactly the required detuning."""
    scene = _platform(operation__amplitude=u, operation__regime=regime, limits__detuning=0.3)
    report = _check(scene)
    text = _finding(report, "regime margin").message
    assert "u <=" in text and "larger unbalance" in text
    margin = report.design.regime_margin
    smaller_u = _check(_platform(operation__amplitude=0.9 * u, operation__regime=regime, limits__detuning=0.3))
    assert smaller_u.design.regime_margin > margin
    heavier = _platform(operation__amplitude=u, operation__regime=regime, limits__detuning=0.3)
    heavier["exciter"]["rotor_mass"] *= 1.1
    assert _check(heavier).design.regime_margin > margin
    d = report.design
    u_max = amplitude_for_margin(d.M, d.m, d.l, d.sigma, 0.3)
    assert f"{u_max:.4g}" in text
    at_limit = _check(_platform(operation__amplitude=u_max, operation__regime=regime, limits__detuning=0.3))
    assert at_limit.design.regime_margin == pytest.approx(0.3, rel=1e-12)


def test_following_the_exciter_height_advice_lowers_c():
    """"lowering ζ lowers c (Eq. (3.15))": the exciter of the paper's example sits 4 ζ high."""
    report = _check(_platform())
    assert "lowering ζ lowers c" in _finding(report, "exciter height").message
    lower = _platform()
    lower["platform"]["cog"] = [1.5, 1.0, 0.6]
    assert _check(lower).design.c < report.design.c


def test_the_c0_error_says_what_it_requires():
    """Above resonance c0 > 0 needs u > m l/M_Σ: message and hint must say the same thing."""
    scene = _platform(operation__amplitude=1e-4)
    with pytest.raises(PhysicsError) as info:
        parse_scene(scene).design()
    text = str(info.value)
    assert "must exceed m l / M_Σ = 0.000249688 m" in text and "require u > 0.000249688 m" in text
    assert "cannot exceed" not in text


def test_any_mode_within_five_percent_fails_and_others_in_the_band_warn():
    near = read_toml(CONFIGS / "platform_translation_mode_near_speed.toml")
    row = _finding(_check(near), "natural frequencies")
    assert row.outcome is Outcome.FAIL and "margin 2.3%" in row.message
    paper = _finding(_check(_platform(limits__detuning=0.2)), "natural frequencies")
    assert paper.outcome is Outcome.WARN and "vertical" in paper.message  # 11.1 %, not driven


def test_platform_and_crank_share_the_rule(runner, tmp_path):
    """The same margin gives the same verdict in both kinds: a driven mode inside the band fails."""
    platform = runner.invoke(app, ["platform", str(CONFIGS / "platform_thin_regime_margin.toml")])
    crank = runner.invoke(app, ["resonance", str(CONFIGS / "compressor_near_resonance.toml")])
    assert platform.exit_code == crank.exit_code == 1
