"""Shooting with solve_ivp against the harmonic-balance steady state: two independent methods.

The shooting solver integrates the equations in time (DOP853, rtol 1e-10) and finds the periodic
orbit by Newton's method on the initial state; harmonic balance solves for Fourier coefficients
in the frequency domain. They share only the equations of motion (which test_crank_exact checks
against a sympy derivation). Agreement to 1e-7 relative of each coordinate's largest harmonic is
what an rtol of 1e-10 over one period allows, with margin.
"""

from __future__ import annotations

from dataclasses import replace

import numpy as np
import pytest

from foundation_calc.errors import PhysicsError
from foundation_calc.scenes import parse_scene
from foundation_calc.solvers.crank.exact import exact_periodic_solution
from foundation_calc.solvers.crank.shooting import shooting_solution


@pytest.mark.parametrize("drive_on", [True, False])
def test_shooting_matches_harmonic_balance(frame_saw, drive_on):
    design = replace(parse_scene(frame_saw).design(), drive_on_foundation=drive_on)
    shot = shooting_solution(design).motion
    exact = exact_periodic_solution(design).motion
    K = exact.cos.shape[-1]
    for got, want in ((shot.cos[:, :K], exact.cos), (shot.sin[:, :K], exact.sin)):
        size = np.maximum(np.abs(exact.cos).max(axis=1), np.abs(exact.sin).max(axis=1))[:, None]
        assert np.abs(got - want).max() <= 1e-7 * size.max()
        assert np.all(np.abs(got - want) <= 1e-7 * size)
    assert np.abs(shot.cos[:, K:]).max() <= 1e-9 * np.abs(exact.cos).max()  # nothing beyond K


def test_unstable_rocking_is_a_physics_error(frame_saw):
    design = replace(parse_scene(frame_saw).design(), c_phi=1e3)
    with pytest.raises(PhysicsError):
        shooting_solution(design)
