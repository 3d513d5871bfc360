"""Platform design (Bolotnik et al. 1986, section 3): the corrected example and feasibility."""

from __future__ import annotations

import math

import numpy as np
import pytest
from hypothesis import event, given, reject, settings
from hypothesis import strategies as st

from foundation_calc.errors import PhysicsError
from foundation_calc.solvers.platform.design import (
    design_from_position,
    design_from_vertical,
    position_from_vertical,
)

M, m, l, u, K, g = 2.0e4, 25.0, 0.2, 1.0e-3, 1.0e8, 9.81
HALF = (0.5, 0.5, 0.5, 0.5)


def example(omega, **kw):
    args = dict(M=M, m=m, l=l, u=u, omega=omega, xi=1.5, eta=1.0, zeta=0.65, A=3.0, B=2.0, sigma=-1.0, g=g,
                a=0.0, b=0.0, K=K, split=HALF)
    args.update(kw)
    return design_from_position(**args)


def quantities(d):
    s = d.stiffness
    return {
        "(c33+c23)/c3": (s[2, 2] + s[1, 2]) / d.c3,
        "c0": d.c0,
        "c22+c32": d.horizontal_sums["c22+c32"],
        "c31+c41": d.horizontal_sums["c31+c41"],
        "c11+c21": d.horizontal_sums["c11+c21"],
        "c12+c42": d.horizontal_sums["c12+c42"],
        "c11": s[0, 0], "c21": s[1, 0], "c12": s[0, 1], "c42": s[3, 1],
        "c22": s[1, 1], "c32": s[2, 1], "c31": s[2, 0], "c41": s[3, 0],
        "c13": s[0, 2], "c23": s[1, 2], "c33": s[2, 2], "c43": s[3, 2],
        "c3": d.c3,
        "z": d.static_deflection,
        "c": d.c,
    }


# The note's table (platform.md, "Worked example, corrected"), as printed: value and the unit of
# its last printed digit; the tolerance is half that unit.
NOTE_50PI = [
    ("(c33+c23)/c3", 0.49938, 1e-5), ("c0", 3.7073e8, 1e4), ("c22+c32", 2.4674e8, 1e4),
    ("c31+c41", 2.4674e8, 1e4), ("c11+c21", 1.2399e8, 1e4), ("c12+c42", 1.2399e8, 1e4),
    ("c11", 0.6199e8, 1e4), ("c42", 0.6199e8, 1e4), ("c22", 1.2337e8, 1e4), ("c41", 1.2337e8, 1e4),
    ("c13", 1.005e8, 1e5), ("c23", 1.0e8, 1e5), ("c3", 4.005e8, 1e5), ("z", -4.905e-4, 1e-7),
    ("c", 2.6127, 1e-4),
]
NOTE_50 = [
    ("(c33+c23)/c3", 0.49938, 1e-5), ("c0", 3.75625e7, 1e2), ("c22+c32", 2.5000e7, 1e3),
    ("c11+c21", 1.25625e7, 1e2), ("c11", 0.6281e7, 1e3), ("c22", 1.25e7, 1e5),
    ("c13", 1.005e8, 1e5), ("c3", 4.005e8, 1e5), ("z", -4.905e-4, 1e-7), ("c", 2.6091, 1e-4),
]
# The paper's own figures (printed with ω "= 50", reproduced only with 50π), 3 significant digits.
PRINTED = [("c22+c32", 2.467e8, 1e5), ("c11+c21", 1.240e8, 1e5), ("c11", 0.620e8, 1e6),
           ("c22", 1.234e8, 1e5)]


@pytest.mark.parametrize("name,value,unit", NOTE_50PI, ids=[f"note-50pi-{r[0]}" for r in NOTE_50PI])
def test_note_table_at_50pi(name, value, unit):
    assert quantities(example(50 * math.pi))[name] == pytest.approx(value, abs=unit / 2 * 1.0000001)


@pytest.mark.parametrize("name,value,unit", NOTE_50, ids=[f"note-50-{r[0]}" for r in NOTE_50])
def test_note_table_at_50(name, value, unit):
    assert quantities(example(50.0))[name] == pytest.approx(value, abs=unit / 2 * 1.0000001)


@pytest.mark.parametrize("name,value,unit", PRINTED, ids=[f"paper-3.19-3.21-{r[0]}" for r in PRINTED])
def test_paper_figures_need_omega_50pi(name, value, unit):
    assert quantities(example(50 * math.pi))[name] == pytest.approx(value, abs=unit / 2)
    assert quantities(example(50.0))[name] != pytest.approx(value, abs=unit / 2)


@pytest.mark.parametrize("omega", [50 * math.pi, 50.0])
def test_example_against_the_simplified_formulas(omega):
    """(3.19)-(3.21) and (3.15), typed by hand from the note, against the general code path
    ((3.6)-(3.7), (3.11), the K-rule): independent algebra, agreement to round-off (1e-12)."""
    q = quantities(example(omega))
    w2, Ms = omega**2, M + m
    hand = {
        "c22+c32": M * w2 / 2, "c31+c41": M * w2 / 2,
        "c11+c21": w2 * ((M + 2 * m) / 2 - m * l / u), "c12+c42": w2 * ((M + 2 * m) / 2 - m * l / u),
        "c0": Ms * w2 - m * l * w2 / u,
        "c13": (M + 4 * m) * K / M, "c23": K, "c33": K, "c43": K, "c3": 4 * K * Ms / M,
        "z": -Ms * g / (4 * K * Ms / M),
        "c": (m * g * l - M * u * 0.65 * w2) / (m * w2 * (u - l)),
        "(c33+c23)/c3": M / (2 * Ms),
    }
    for name, value in hand.items():
        assert q[name] == pytest.approx(value, rel=1e-12), name


def test_below_resonance_height_is_the_notes_formula():
    d = example(50 * math.pi, sigma=1.0)
    w2 = (50 * math.pi) ** 2
    assert d.c == pytest.approx(-(M * u * 0.65 * w2 + g * m * l) / (m * w2 * (u + l)), rel=1e-12)
    assert d.c < 0 and d.c0 > (M + m) * w2


designs = st.fixed_dictionaries(
    {
        "M": st.floats(2e3, 5e4), "m": st.floats(2.0, 80.0), "l": st.floats(0.05, 0.3),
        "u": st.floats(3e-4, 3e-3), "omega": st.floats(60.0, 320.0),
        "fx": st.floats(0.35, 0.65), "fy": st.floats(0.35, 0.65), "zeta": st.floats(0.1, 1.2),
        "A": st.floats(1.0, 5.0), "B": st.floats(0.8, 4.0), "a": st.floats(-0.5, 0.5), "b": st.floats(-0.5, 0.5),
        "K": st.floats(1e7, 3e8), "sigma": st.sampled_from([-1.0, 1.0]),
    }
)


def build(p, split=HALF):
    return design_from_position(p["M"], p["m"], p["l"], p["u"], p["omega"], p["fx"] * p["A"], p["fy"] * p["B"],
                                p["zeta"], p["A"], p["B"], p["sigma"], g, p["a"], p["b"], p["K"], split)


def feasible(p):
    """The design of ``p``; an example for which the paper's conditions have no design (a
    PhysicsError naming the condition) is rejected and drawn again, so that every one of the
    examples hypothesis counts reaches the assertions (the refusals are tested by name below)."""
    try:
        return build(p)
    except PhysicsError as exc:
        event(f"no design: {exc.field}")
        reject()


@settings(max_examples=60, deadline=None)
@given(designs)
def test_design_satisfies_the_papers_conditions(p):
    """Every returned design satisfies (3.3)-(3.8) as printed (with ζ), or it raised."""
    d = feasible(p)
    s, Ms, w2 = d.stiffness, d.M_sigma, d.omega**2
    c1, c2, c3 = s[:, 0].sum(), s[:, 1].sum(), s[:, 2].sum()
    assert np.all(s > 0)
    assert c1 == pytest.approx(d.c0, rel=1e-12) and c2 == pytest.approx(d.c0, rel=1e-12)
    scale = c3 * M * max(p["A"], p["B"])
    assert abs(c3 * (d.M * d.eta + d.m * d.b) - (s[2, 2] + s[3, 2]) * d.B * Ms) < 1e-12 * scale  # (3.3)
    assert abs(c3 * (d.M * d.xi + d.m * d.a) - (s[1, 2] + s[2, 2]) * d.A * Ms) < 1e-12 * scale  # (3.4)
    big = w2 * w2 * (d.M * abs(d.zeta) + d.m * abs(d.c)) + abs(w2 * d.c + g) * d.c0
    assert abs(w2 * w2 * (d.M * d.zeta + d.m * d.c) + (w2 * d.c + g) * (d.c0 - Ms * w2)) < 1e-11 * big  # (3.5)
    mom = w2 * d.M * d.B + abs(d.b) * d.c0 + (s[2, 0] + s[3, 0]) * d.B
    assert abs(w2 * (d.M * d.eta + d.m * d.b) + d.b * (d.c0 - Ms * w2) - (s[2, 0] + s[3, 0]) * d.B) < 1e-12 * mom
    # (3.14): the translational amplitude of (3.1) is u
    assert abs(d.m * d.l * w2 / (d.c0 - Ms * w2)) == pytest.approx(d.u, rel=1e-10)


@settings(max_examples=40, deadline=None)
@given(designs)
def test_vertical_round_trip(p):
    """Vertical stiffnesses from (a, b, K), then (3.9)-(3.10) give back a and b."""
    d = feasible(p)
    a, b = position_from_vertical(d.M, d.m, d.xi, d.eta, d.A, d.B, *d.stiffness[:, 2])
    assert a == pytest.approx(p["a"], abs=1e-7 * d.M / d.m * d.A)
    assert b == pytest.approx(p["b"], abs=1e-7 * d.M / d.m * d.B)
    again = design_from_vertical(d.M, d.m, d.l, d.u, d.omega, d.xi, d.eta, d.zeta, d.A, d.B, d.sigma, g,
                                 tuple(d.stiffness[:, 2]), HALF)
    np.testing.assert_allclose(again.stiffness, d.stiffness, rtol=1e-6)


def test_amplitude_too_small_names_the_pair_sum_and_the_bound():
    with pytest.raises(PhysicsError) as err:
        example(50 * math.pi, u=4.5e-4)
    bound = m * l / (M + m - M / 2)  # = 2ml/(M+2m), the note's bound
    assert err.value.field == "isolators.c11+c21"
    assert f"u > {bound:.6g} m" in str(err.value)
    example(50 * math.pi, u=bound * 1.001)  # just above: feasible


def test_c0_not_positive():
    with pytest.raises(PhysicsError, match="c0 = c1 = c2") as err:
        example(50 * math.pi, u=2e-4)
    assert err.value.field == "operation.amplitude"


def test_singular_when_u_equals_l():
    with pytest.raises(PhysicsError, match="c0 = M ω²"):
        example(50 * math.pi, u=0.2)


def test_exciter_far_off_centre_names_the_vertical_spring():
    with pytest.raises(PhysicsError) as err:
        example(50 * math.pi, a=-1000.0)
    assert err.value.field.startswith("isolators.c") and "a >" in str(err.value)
