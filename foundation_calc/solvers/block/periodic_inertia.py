"""A block's machines with periodic inertia (crank mechanisms, exciters): the exact periodic steady state
with their angle-dependent inertia, and the error of the first approximation.

Source: Eq. (1) of :mod:`foundation_calc.solvers.rigid_body.periodic` with the block's matrices
(:mod:`.model`: the parts' mean mass and weight are in M and K already, as bodies, and their mean
gyroscopic coupling D̄ in C) and one machine's periodic terms (the sum over its parts with periodic
inertia of their M(φ), D(φ), S(φ),
:meth:`~foundation_calc.solvers.machines.part.MachinePart.periodic_inertia`, e.g. Eqs. (1)-(3) of
:mod:`foundation_calc.solvers.machines.crank_mechanism`, less the means of M and S and less the D̄ that C holds); its loads Q_n
are the machine's whole excitation (every part's harmonics, all at its speed). Machines at other speeds keep their mean inertia
and mean gyroscopic coupling only (their periodic terms would make the system quasi-periodic), and act on the first
approximation alone.

The first approximation is :func:`~foundation_calc.solvers.block.response.complex_amplitudes`
(the averaged operator). Its error, as the crank scene reports it, is the difference of the peaks
over one revolution of every point's displacement (and the rotations) from the exact solution's,
relative to the exact peak.
"""

from __future__ import annotations

from dataclasses import dataclass

import numpy as np

from foundation_calc.solvers.block.model import BlockModel, Excitation
from foundation_calc.solvers.rigid_body.periodic import PeriodicSolution, periodic_solution


def dense_loads(exc: Excitation) -> np.ndarray:
    """The machine's loads as orders 1 ... max(orders), (H, 6) complex [N, N m] (0 where absent)."""
    Q = np.zeros((int(exc.orders.max()), 6), dtype=complex)
    Q[exc.orders - 1] = exc.Q
    return Q


def exact_response(model: BlockModel, exc: Excitation, parts, g, impedance=None) -> PeriodicSolution:
    """T-periodic steady state of the block under machine ``exc`` whose ``parts`` with periodic
    inertia (:class:`~foundation_calc.solvers.machines.part.MachinePart`, e.g. a
    :class:`~foundation_calc.solvers.machines.crank_mechanism.CrankMechanism`) turn at its speed
    (module docstring); g [m/s²]; on the soil ``impedance`` (Ω -> springs, dashpots at O) if given.
    D(φ) less the machine's mean gyroscopic coupling ``exc.gyroscopic``, which the model's C holds
    (:class:`~foundation_calc.solvers.block.model.Excitation`; D whole when it has none).

    Raises
    ------
    ConvergenceError, HarmonicCapReached
        as :func:`~foundation_calc.solvers.rigid_body.periodic.periodic_solution`.
    """

    def periodic(N):
        M, D, S = (sum(terms) for terms in zip(*(part.periodic_inertia(exc.omega, g, N) for part in parts)))
        return M - M.mean(axis=0), D if exc.gyroscopic is None else D - exc.gyroscopic, S - S.mean(axis=0)

    soil = None if impedance is None else (lambda W: model.soil_matrices(*impedance(W)))
    return periodic_solution(exc.omega, model.M, model.K, model.C, periodic, dense_loads(exc), soil)


@dataclass(frozen=True)
class FirstApproximationError:
    """Peaks of one machine's motion by the exact periodic solution and the first
    approximation's error.

    Attributes
    ----------
    name : the machine
    harmonics : harmonics of the exact solution
    exact_peak : (P, 3) peak displacement of G and the points along x, y, z [m], exact
    first_peak : (P, 3) the same by the first approximation [m]
    rotation_exact, rotation_first : (3,) peak rotations [rad]
    error : largest |first - exact| / exact over the points, directions and rotations [-]
    harmonic_change : the exact solution's change from half its harmonics [-] (its truncation
        error; above :data:`~foundation_calc.solvers.rigid_body.periodic.HARMONIC_TOLERANCE` when
        the harmonics' cap was reached)
    """

    name: str
    harmonics: int
    exact_peak: np.ndarray
    first_peak: np.ndarray
    rotation_exact: np.ndarray
    rotation_first: np.ndarray
    error: float
    harmonic_change: float


def series_peaks(Z: np.ndarray, orders: np.ndarray, T: np.ndarray) -> tuple[np.ndarray, np.ndarray]:
    """Peaks over one period of the displacement of points (maps T (P, 3, 6)) and of the rotations
    for the harmonics Z (H, 6) of orders (H,): ((P, 3) [m], (3,) [rad])."""
    from foundation_calc.solvers.block.response import series_peak

    U = np.einsum("pij,hj->pih", T, Z)
    return series_peak(U, orders), series_peak(Z[:, 3:].T, orders)


def first_approximation_error(name, first: np.ndarray, exc: Excitation, exact: PeriodicSolution,
                              T: np.ndarray) -> FirstApproximationError:
    """Compare the first approximation's amplitudes ``first`` (H, 6) of ``exc``'s orders with
    ``exact`` at the points of maps T (P, 3, 6) (module docstring). A peak that is zero both ways
    (a direction the machine does not move) has no error."""
    fp, fr = series_peaks(first, exc.orders, T)
    ep, er = series_peaks(exact.Z, exact.orders, T)
    a, b = np.concatenate([fp.ravel(), fr]), np.concatenate([ep.ravel(), er])
    scale = max(float(np.abs(b).max()), 1e-300)
    shown = b > 1e-9 * scale  # below this the direction is round-off of the others
    error = float((np.abs(a - b)[shown] / b[shown]).max()) if shown.any() else 0.0
    return FirstApproximationError(str(name), len(exact.orders), ep, fp, er, fr, error, exact.harmonic_change)


__all__ = ["FirstApproximationError", "dense_loads", "exact_response", "first_approximation_error", "series_peaks"]
