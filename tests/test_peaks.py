"""Peaks of trigonometric series (the fast search) against brute-force dense sampling.

The reference is independent of the search: every series is evaluated by an inverse FFT on a
grid of 2^17 phases (no Newton steps, no candidate selection), whose largest |value| brackets the
true peak P from below within Taylor's bound, dense <= P <= dense + Σ n²|c_n| (2π/M)²/8. The
fast peak must lie in that bracket, widened by round-off (1e-14 relative: sums of up to a few
hundred terms of double precision).
"""

from __future__ import annotations

import mpmath
import numpy as np
import pytest
from hypothesis import example, given, settings
from hypothesis import strategies as st

from foundation_calc.solvers.crank.response import PeriodicMotion, point_series, theta_minus_sine
from foundation_calc.solvers.numerics.trig_series import derivative, peak, sample, searched_harmonics

DENSE = 2**17
ROUNDOFF = 1e-14


def dense_bracket(cos, sin):
    """(lower, upper) bounds of the peak of each series from 2^17 samples, without refinement."""
    cos, sin = np.atleast_2d(cos), np.atleast_2d(sin)
    K = cos.shape[-1] - 1
    spectrum = np.zeros(cos.shape[:-1] + (DENSE // 2 + 1,), dtype=complex)
    spectrum[..., : K + 1] = (DENSE / 2.0) * (cos - 1j * sin)
    spectrum[..., 0] = DENSE * cos[..., 0]
    lower = np.abs(np.fft.irfft(spectrum, DENSE, axis=-1)).max(-1)
    curvature = (np.arange(K + 1) ** 2 * np.hypot(cos, sin)).sum(-1)
    return lower, lower + curvature * (2 * np.pi / DENSE) ** 2 / 8


def assert_bracketed(found, cos, sin):
    lower, upper = dense_bracket(cos, sin)
    scale = np.abs(cos).sum(-1) + np.abs(sin).sum(-1)
    found = np.atleast_1d(found)
    assert np.all(found >= lower - ROUNDOFF * scale), (found - lower) / scale
    assert np.all(found <= upper + ROUNDOFF * scale), (found - upper) / scale


@st.composite
def series(draw):
    """A batch of series as solvers make them: a few significant harmonics, decaying at a random
    rate, and optionally a tail of round-off up to harmonic K (it must not mislead the search)."""
    K = draw(st.integers(1, 96))
    batch = draw(st.integers(1, 6))
    seed = draw(st.integers(0, 2**32 - 1))
    decay = draw(st.sampled_from([0.0, 0.1, 0.5, 2.0, 8.0]))
    noise = draw(st.sampled_from([0.0, 1e-17, 1e-13]))
    rng = np.random.default_rng(seed)
    envelope = np.exp(-decay * np.arange(K + 1))
    cos = rng.normal(size=(batch, K + 1)) * envelope + noise * rng.normal(size=(batch, K + 1))
    sin = rng.normal(size=(batch, K + 1)) * envelope + noise * rng.normal(size=(batch, K + 1))
    return cos, sin


@settings(max_examples=60, deadline=None)
@given(series())
def test_peak_lies_within_the_dense_sampling_bracket(case):
    cos, sin = case
    assert_bracketed(peak(cos, sin), cos, sin)


@settings(max_examples=30, deadline=None)
@given(series(), st.integers(1, 2), st.floats(0.5, 300.0))
def test_peaks_of_derivatives_lie_within_the_bracket(case, order, omega):
    """Velocity and acceleration series weight harmonic n by (nω)^k: their tails count more."""
    cos, sin = derivative(*case, omega, order)
    assert_bracketed(peak(cos, sin), cos, sin)


@settings(max_examples=20, deadline=None)
@given(series())
def test_a_series_has_the_same_peak_alone_and_in_a_batch(case):
    """The batch shares one search resolution; each series' peak must not depend on its company."""
    cos, sin = case
    together = peak(cos, sin)
    alone = np.array([peak(c, s) for c, s in zip(cos, sin)])
    np.testing.assert_allclose(together, alone, rtol=ROUNDOFF, atol=0)


@pytest.mark.parametrize(
    ("cos", "sin", "expected"),
    [
        ([3.0], [0.0], 3.0),  # a constant: no local maximum to refine
        ([0.0, 0.0, 0.0], [0.0, 0.0, 0.0], 0.0),
        ([-2.0, 0.0, 0.0], [0.0, 0.0, 0.0], 2.0),
        ([0.0, 0.0, 0.0, 0.0], [0.0, 1.0, 0.0, 1.0 / 3.0], 2.0 * np.sqrt(2.0) / 3.0),
    ],
    ids=["constant", "zero", "negative-constant", "sin-plus-sin3"],
)
def test_peaks_with_a_closed_form(cos, sin, expected):
    """sin φ + sin 3φ/3 peaks at φ = π/4: √2/2 + √2/6 = 2√2/3."""
    assert peak(np.array(cos), np.array(sin)) == pytest.approx(expected, rel=1e-15, abs=0)


def test_an_empty_batch_has_no_peaks():
    assert peak(np.zeros((0, 2, 5)), np.zeros((0, 2, 5))).shape == (0, 2)


def test_equal_peaks_of_both_signs_are_found():
    """An odd series (x and θ of an undamped crank foundation) peaks equally at +q and -q."""
    cos = np.zeros(4)
    sin = np.array([0.0, 4.5e-5, 0.0, 1.1e-7])
    cos2, sin2 = derivative(cos, sin, 26.18, 2)
    for c, s in ((cos, sin), (cos2, sin2)):
        assert_bracketed(peak(c, s), c, s)


def test_round_off_tails_do_not_widen_the_search():
    """A series whose harmonics beyond the 8th are round-off is searched over about 8 harmonics."""
    rng = np.random.default_rng(7)
    cos = np.zeros((5, 97))
    sin = np.zeros((5, 97))
    sin[:, 1:9] = rng.normal(size=(5, 8)) * 0.1 ** np.arange(8)
    sin[:, 9:] = 1e-22 * rng.normal(size=(5, 88))
    assert searched_harmonics(cos, sin) <= 9
    assert_bracketed(peak(cos, sin), cos, sin)
    # ... but a real high harmonic is searched
    sin[0, 60] = 1e-3
    assert searched_harmonics(cos, sin) == 60
    assert_bracketed(peak(cos, sin), cos, sin)


@settings(max_examples=40, deadline=None)
@given(st.floats(-3.0, 3.0, allow_subnormal=False))
@example(1e-300)
@example(1.5175418153438192)
@example(1e-8)
@example(0.5)
@example(-0.5000001)
@example(1.9999999)
@example(2.0000001)
def test_theta_minus_sine_keeps_its_digits(theta):
    """θ - sin θ against multi-precision arithmetic with 40 digits to spare beyond the ~2 |log θ|
    that cancel (written out in double precision it loses every digit below |θ| ~ 1e-8).

    Tolerance 1e-15 relative, about 4 ulp: three roundings in θ t/6 and the 14-step Horner sum of
    the series, which stays in [0.8, 1] and damps each step's rounding by t/ratio ≤ 0.2 (a draw
    at θ = 1.5175 is 2 ulp off)."""
    with mpmath.workdps(40 + 2 * max(0, -int(np.log10(abs(theta) or 1.0)))):
        want = float(mpmath.mpf(theta) - mpmath.sin(mpmath.mpf(theta)))
    assert float(theta_minus_sine(theta)) == pytest.approx(want, rel=1e-15, abs=1e-320)


def test_point_series_is_the_rigid_body_motion_to_round_off():
    """A point's series, sampled, equals X + (R(θ) - I) b evaluated in 50-digit arithmetic."""
    rng = np.random.default_rng(3)
    K = 6
    cos = rng.normal(size=(3, K + 1)) * 1e-5 * 0.3 ** np.arange(K + 1)
    sin = rng.normal(size=(3, K + 1)) * 1e-5 * 0.3 ** np.arange(K + 1)
    motion = PeriodicMotion(30.0, cos, sin)
    u, H = 2.5, -1.3
    pc, ps = point_series(motion, u, H)
    got = sample(pc, ps, 40)
    x, y, th = sample(cos, sin, 40)
    with mpmath.workdps(50):
        want = np.array(
            [
                [float(mpmath.mpf(xi) + (mpmath.cos(t) - 1) * u + mpmath.sin(t) * H) for xi, t in zip(x, th)],
                [float(mpmath.mpf(yi) + mpmath.sin(t) * u - (mpmath.cos(t) - 1) * H) for yi, t in zip(y, th)],
            ]
        )
    # θ³ harmonics beyond 2K are left out: |θ| ~ 1e-5 makes them ~1e-15 θ, far below 1e-19 m
    np.testing.assert_allclose(got, want, rtol=0, atol=1e-19)  # 2e-15 of the peak
    # accelerations: d²/dφ² of x + u (cos θ - 1) + H sin θ, and of the vertical likewise
    got = sample(*derivative(pc, ps, 1.0, 2), 40)
    x2, y2, th2 = sample(*derivative(cos, sin, 1.0, 2), 40)
    _, _, th1 = sample(*derivative(cos, sin, 1.0, 1), 40)
    with mpmath.workdps(50):
        bend = [(-mpmath.sin(t) * b - mpmath.cos(t) * s * s, mpmath.cos(t) * b - mpmath.sin(t) * s * s)
                for t, s, b in zip(th, th1, th2)]  # (cos θ)'' and (sin θ)''
        want = np.array(
            [
                [float(mpmath.mpf(a) + c * u + d * H) for a, (c, d) in zip(x2, bend)],
                [float(mpmath.mpf(a) + d * u - c * H) for a, (c, d) in zip(y2, bend)],
            ]
        )
    np.testing.assert_allclose(got, want, rtol=0, atol=1e-19)
