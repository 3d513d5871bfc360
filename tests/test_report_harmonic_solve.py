"""The sheet's one steady-state solve and its tables, the same for the crank's 3 and the block's 6 coordinates.

The solve is checked against the closed form of a single degree of freedom, Z = F / (k − w² m + i w c)
(exact to round-off, 1e-14 relative), and against a damped 2-DOF system integrated in time to
its steady state (independent of any linear solve; 1e-6 relative, the integrator's tolerance).
The tables' columns are checked by hand-written expectations of the sheet's number format.
"""

from __future__ import annotations

import numpy as np
import pytest

from foundation_calc.output.report.harmonic_solve import (BODY, PLANE, harmonic_table, matrix_table, point_columns,
                                                          solve_harmonic)


@pytest.mark.parametrize("w", [0.0, 3.0, 10.0, 40.0])
def test_one_degree_of_freedom_is_the_closed_form(w):
    m, c, k, F = 2.0, 0.8, 200.0, 5.0 - 1.0j
    Z = solve_harmonic(np.array([[m]]), np.array([[c]]), np.array([[k]]), np.array([F]), w)
    assert Z[0] == pytest.approx(F / (k - w * w * m + 1j * w * c), rel=1e-14)


def test_two_degrees_of_freedom_reach_the_solved_steady_state():
    """M q'' + C q' + K q = Re(F e^{iwt}) integrated from rest for 30 periods of the forcing
    (the transient then decayed): q(t) is Re(Z e^{iwt}) with the solved Z."""
    from scipy.integrate import solve_ivp

    M = np.diag([1.0, 2.0])
    K = np.array([[300.0, -100.0], [-100.0, 100.0]])
    C = 0.05 * K + 0.4 * M
    F = np.array([1.0, 0.5j])
    w = 9.0
    Z = solve_harmonic(M, C, K, F, w)
    T = 2 * np.pi / w
    t_end = 30 * T  # the slower mode decays as e^{-ζ p t}, ζ p ≈ 0.98 /s: its transient is down to 1e-9

    inverse = np.linalg.inv(M)
    A = np.block([[np.zeros((2, 2)), np.eye(2)], [-inverse @ K, -inverse @ C]])  # s = (q, q')

    def rate(t, s):
        return A @ s + np.concatenate([np.zeros(2), inverse @ (F * np.exp(1j * w * t)).real])

    end = solve_ivp(rate, (0.0, t_end), np.zeros(4), rtol=1e-9, atol=1e-12, method="DOP853").y[:2, -1]
    assert end == pytest.approx((Z * np.exp(1j * w * t_end)).real, rel=1e-6, abs=1e-6 * np.abs(Z).max())


def test_the_coordinates_are_data_of_the_kind():
    """A kind's coordinates name the matrices' rows and columns and carry each row's units."""
    for kind, size in ((PLANE, 3), (BODY, 6)):
        assert len(kind.names) == len(kind.forcing) == len(kind.response) == size
        assert all(len(units) == size for units in kind.row_units.values())
        rows = matrix_table("t", (("M", np.eye(size)),), kind.names, kind.row_units).rows
        assert [row[0] for row in rows] == [f"M, row {name}" for name in kind.names]
        assert [row[-1] for row in rows] == list(kind.row_units["M"])


def test_a_harmonic_row_prints_magnitude_and_phase_lag_per_coordinate():
    """Re(2i e^{iΩt}) = 2 cos(Ωt + 90°): phase lag −90° (−2: −180°); each column in one notation."""
    rows = harmonic_table("t", ("n", "Ω", "a", "b"), [("1",), ("2",)], [10.0, 20.0],
                          [(np.array([[2.0j, 1.0], [-2.0, 2.5e-5]]), 4)]).rows
    assert rows[0] == ("1", "10.00", "2.000 ∠-90.0°", "1.000·10⁰ ∠0.0°")
    assert rows[1] == ("2", "20.00", "2.000 ∠-180.0°", "2.500·10⁻⁵ ∠0.0°")


def test_the_columns_of_one_quantity_share_a_notation():
    """A peak velocity and an r.m.s. velocity print alike; a displacement column on its own."""
    displacement, peak, rms = point_columns([([1.5, 2.0], "amplitude"), ([0.5, 2.0e-5], "velocity"), ([0.2, 0.3], "velocity")])
    assert displacement == ["1.50", "2.00"]
    assert peak == ["5.00·10⁻¹", "2.00·10⁻⁵"]
    assert rms == ["2.00·10⁻¹", "3.00·10⁻¹"]
