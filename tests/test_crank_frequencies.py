"""Natural frequencies of the crank foundation against an independent eigen-solve.

Tolerance 1e-9 relative: both sides are exact in double precision (closed form vs LAPACK), the
bound leaves room for the eigen-solver's backward error on matrices with entries spanning 1e5-1e10.
"""

from __future__ import annotations

import math

import numpy as np
import pytest
from hypothesis import example, given, settings
from hypothesis import strategies as st

from foundation_calc.errors import PhysicsError
from foundation_calc.solvers.crank.frequencies import (
    averaged_inertia_frequencies,
    zero_order_frequencies,
)
from foundation_calc.solvers.crank.mechanism import lump_slider
from tests import crank_reference as ref

REL = 1e-9


def _soil(design):
    return {k: design[k] for k in ("M_tot", "h", "S", "I1", "c", "c1")}


def _zero_order(design):
    d = design
    return zero_order_frequencies(d["M_tot"], d["I_c"], d["h"], d["S"], d["I1"], d["c"], d["c1"], d["c"], ref.G)


def _reference_zero_order(design):
    K = ref.stiffness_matrix(**_soil(design))
    Mm = np.diag([design["M_tot"], design["M_tot"], design["I_c"]])
    coupled = ref.frequencies(K[np.ix_([0, 2], [0, 2])], Mm[np.ix_([0, 2], [0, 2])])
    return math.sqrt(K[1, 1] / Mm[1, 1]), coupled, ref.frequencies(K, Mm)


FRAME_SAW = dict(M_tot=1.015e5, I_c=4.5e5, h=1.5, S=30.0, I1=90.0, c=4.0e7, c1=2.8e7)

designs = st.fixed_dictionaries(
    {
        "M_tot": st.floats(1e2, 1e8),
        "I_c_ratio": st.floats(0.05, 20.0),  # I_c / (M_tot h²)
        "h": st.floats(0.05, 20.0),
        "S": st.floats(0.1, 1e3),
        "I1_ratio": st.floats(0.01, 10.0),  # I1 / S²
        "c": st.floats(1e5, 1e10),
        "c1_ratio": st.floats(0.05, 2.0),
    }
)


def _materialise(raw):
    d = dict(raw)
    d["I_c"] = raw["I_c_ratio"] * raw["M_tot"] * raw["h"] ** 2
    d["I1"] = raw["I1_ratio"] * raw["S"] ** 2
    d["c1"] = raw["c1_ratio"] * raw["c"]
    return d


def test_frame_saw_against_eigen_solve():
    got = _zero_order(FRAME_SAW)
    k0, (p1, p2), all_three = _reference_zero_order(FRAME_SAW)
    assert got.k0 == pytest.approx(k0, rel=REL)
    assert got.p1 == pytest.approx(p1, rel=REL)
    assert got.p2 == pytest.approx(p2, rel=REL)
    assert sorted([got.k0, got.p1, got.p2]) == pytest.approx(all_three, rel=REL)


@settings(max_examples=200, deadline=None)
@given(designs)
@example(  # nearly equal p1 and p2: a0 ≈ b1 and weak coupling (short block, tall inertia)
    {"M_tot": 1e5, "I_c_ratio": 20.0, "h": 0.05, "S": 30.0, "I1_ratio": 0.0101, "c": 4e7, "c1_ratio": 0.5}
)
@example(  # 1.3e-5 above the rocking stability limit: stable, and not compared (see below)
    {"M_tot": 30211908.0, "I_c_ratio": 1.0, "h": 13.234375, "S": 1 / 3, "I1_ratio": 6.078125, "c": 5808031548.0,
     "c1_ratio": 1.0}
)
def test_random_designs_against_eigen_solve(raw):
    d = _materialise(raw)
    reserve = d["c"] * d["I1"] / (d["M_tot"] * ref.G * d["h"]) - 1.0
    if reserve <= 0.0:
        with pytest.raises(PhysicsError):
            _zero_order(d)
        return
    if reserve < 1e-3:  # p1 → 0: the reference's small eigenvalue is round-off of the large one
        assert 0.0 < _zero_order(d).p1 < _zero_order(d).p2
        return
    got = _zero_order(d)
    k0, (p1, p2), _ = _reference_zero_order(d)
    assert got.k0 == pytest.approx(k0, rel=REL)
    assert got.p2 == pytest.approx(p2, rel=REL)
    # p1 is computed without cancellation; the reference's small eigenvalue loses digits as p1 -> 0
    assert got.p1 == pytest.approx(p1, rel=max(REL, 1e-13 * (p2 / p1) ** 2))
    assert got.p1 <= got.p2


def test_arrays_of_designs_match_scalar_calls():
    masses = np.array([5e4, 1.015e5, 3e5])
    d = dict(FRAME_SAW, M_tot=masses)
    arr = _zero_order(d)
    for i, mass in enumerate(masses):
        one = _zero_order(dict(FRAME_SAW, M_tot=float(mass)))
        assert arr.p1[i] == pytest.approx(one.p1, rel=1e-15)
        assert arr.p2[i] == pytest.approx(one.p2, rel=1e-15)


def test_unstable_rocking_is_an_error_naming_the_cause():
    d = dict(FRAME_SAW, I1=0.9 * FRAME_SAW["M_tot"] * ref.G * FRAME_SAW["h"] / FRAME_SAW["c"])
    with pytest.raises(PhysicsError, match="unstable in rocking") as info:
        _zero_order(d)
    assert info.value.field == "foundation.base_second_moment"


def test_unstable_design_in_an_array_is_reported():
    d = dict(FRAME_SAW, I1=np.array([90.0, 1e-3]))
    with pytest.raises(PhysicsError):
        _zero_order(d)


def test_vertical_frequency_does_not_depend_on_shear():
    a = _zero_order(FRAME_SAW)
    b = _zero_order(dict(FRAME_SAW, c1=FRAME_SAW["c1"] * 3.7))
    assert a.k0 == b.k0


MECHANISMS = [
    # m, l', ρ, m1, a, r, l
    (1.5e3, 1.0, 0.35, 0.0, 2.0, 0.3, 1.2),
    (65.0, 0.15, 0.17, 140.0, 1.4, 0.11, 0.5),
    (900.0, 0.4, 0.28, 3500.0, -1.8, 0.1, 0.9),
    (2e4, 0.3, 0.2, 1e4, 0.5, 0.45, 0.5),  # λ = 0.9, heavy mechanism (μ ≈ 0.23)
]


@pytest.mark.parametrize("mech", MECHANISMS)
def test_averaged_inertia_against_numerical_time_average(mech):
    """Closed-form averages (elliptic E by AGM, slider lumped) vs sampling one revolution."""
    m, l1, rho, m1, a, r, l = mech
    M = 1.0e5
    base = dict(FRAME_SAW, M_tot=M + m + m1)
    rod = lump_slider(m=m, l=l, l1=l1, rho=rho, m1=m1)
    got = averaged_inertia_frequencies(
        base["M_tot"], base["I_c"], base["h"], base["S"], base["I1"], base["c"], base["c1"], base["c"], ref.G,
        rod.m, a, r, l, rod.l1, rod.rho,
    )
    Mm = ref.averaged_mass_matrix(M=M, I_c=base["I_c"], m=m, l1=l1, rho=rho, m1=m1, a=a, r=r, l=l)
    K = ref.stiffness_matrix(**_soil(base))
    assert Mm[1, 2] == pytest.approx(0.0, abs=1e-9 * Mm[2, 2])  # vertical decoupled on average
    want = ref.frequencies(K, Mm)
    # trapezoidal averaging of a smooth periodic function converges exponentially: 1e-10 is safe
    assert sorted([got.k0, got.p1, got.p2]) == pytest.approx(want, rel=1e-10)


def test_averaged_inertia_moves_rocking_by_order_mu():
    zero = _zero_order(FRAME_SAW)
    rod = lump_slider(m=1.5e3, l=1.2, l1=1.0, rho=0.35, m1=0.0)
    avg = averaged_inertia_frequencies(
        *(FRAME_SAW[k] for k in ("M_tot", "I_c", "h", "S", "I1", "c", "c1", "c")), ref.G,
        rod.m, 2.0, 0.3, 1.2, rod.l1, rod.rho,
    )
    mu = 1.5e3 / FRAME_SAW["M_tot"]
    assert avg.k0 == zero.k0
    for mode in ("p1", "p2"):
        shift = abs(getattr(avg, mode) / getattr(zero, mode) - 1)
        assert 1e-3 * mu < shift < mu
