"""Resonance conditions of the crank-mechanism foundation.

Source: Krichever & Makarov [1]_, section 4: the first approximation resonates when a harmonic of
the crank speed meets a natural frequency: ω = k0, 2ω = k0 (vertical, harmonics of the slider
motion), ω = p1, p2 and 3ω = p1, p2 (sliding-rocking, crank force and rod couple).

The exact equations also resonate at 4ω = k0 (the λ³ part of the slider motion) and, at order
μ², at 2ω = p1, p2; those are listed as ``source="extra"``.

Beyond the paper's list, every harmonic n ω of a machine's forcing (its mechanism's and its
loads') meets k0, p1, p2 (:func:`machine_conditions`), each with its forcing share on the mode
(:func:`forcing_shares`), which the resonance rule (docs/resonance-rule.md) reads to judge it.

References
----------
.. [1] M.F. Krichever, S.M. Makarov, "Application of the small-parameter method to the problem
   of forced vibrations of the foundation of a crank-slider mechanism".
"""

from __future__ import annotations

from dataclasses import dataclass

import numpy as np

from foundation_calc.solvers.crank.mechanism import CrankDesign
from foundation_calc.solvers.crank.natural import MODES, design_frequencies


@dataclass(frozen=True)
class ResonanceCondition:
    """One condition n·ω = natural frequency.

    Attributes
    ----------
    label : as written in the paper, e.g. ``"3ω = p1"``
    harmonic : n, the harmonic of the crank speed that excites the mode
    mode : ``"k0"``, ``"p1"`` or ``"p2"``
    source : ``"paper"`` (the paper's list), ``"extra"`` (resonances of the exact equations) or
        ``"loads"`` (a harmonic of the scene's [[loads]])
    excitation : what drives this harmonic
    driven : whether a load of this harmonic drives the mode (``"loads"`` only; the paper's
        conditions are driven by the mechanism, the extra ones only weakly)
    """

    label: str
    harmonic: int
    mode: str
    source: str
    excitation: str
    driven: bool = False


MODE_NAMES = {
    "k0": "vertical",
    "p1": "rocking, lower",
    "p2": "rocking, upper",
}

CONDITIONS: tuple[ResonanceCondition, ...] = (
    ResonanceCondition("ω = k0", 1, "k0", "paper", "crank-pin inertia force, vertical"),
    ResonanceCondition("2ω = k0", 2, "k0", "paper", "slider inertia, λ term"),
    ResonanceCondition("ω = p1", 1, "p1", "paper", "crank-pin force and rod couple"),
    ResonanceCondition("ω = p2", 1, "p2", "paper", "crank-pin force and rod couple"),
    ResonanceCondition("3ω = p1", 3, "p1", "paper", "rod couple, λ³ term"),
    ResonanceCondition("3ω = p2", 3, "p2", "paper", "rod couple, λ³ term"),
    ResonanceCondition("4ω = k0", 4, "k0", "extra", "slider inertia, λ³ term (exact equations)"),
    ResonanceCondition("2ω = p1", 2, "p1", "extra", "parametric terms, order μ² (exact equations)"),
    ResonanceCondition("2ω = p2", 2, "p2", "extra", "parametric terms, order μ² (exact equations)"),
)


def critical_speed(natural_frequency, harmonic):
    """Crank speed [rad/s] at which harmonic n meets the natural frequency: ω_c = p / n."""
    return natural_frequency / harmonic


def relative_detuning(omega, omega_critical):
    """Relative distance of the operating speed from a critical speed, |ω - ω_c| / ω_c [-].

    >>> relative_detuning(80.0, 100.0)
    0.2
    """
    return abs(omega - omega_critical) / omega_critical


def condition_margin(omega, zero_order, averaged, condition: ResonanceCondition):
    """Margin [-] of ω from one condition, measured to the nearer of its two critical speeds.

    ``zero_order`` and ``averaged`` hold k0, p1, p2 [rad/s] of the paper's operator and of the
    operator with the mechanism's averaged inertia. Arithmetic only: arrays of designs or speeds
    give an array of margins.

    >>> from types import SimpleNamespace as F
    >>> condition_margin(95.0, F(k0=100.0), F(k0=100.0), CONDITIONS[0])
    0.05
    """
    w0 = critical_speed(getattr(zero_order, condition.mode), condition.harmonic)
    w1 = critical_speed(getattr(averaged, condition.mode), condition.harmonic)
    d0, d1 = relative_detuning(omega, w0), relative_detuning(omega, w1)
    return (d0 + d1 - abs(d0 - d1)) / 2.0


def paper_margin(design: CrankDesign):
    """Smallest margin [-] of the speed from the paper's six conditions; arrays of designs welcome.

    This is the batch path: one call for a million designs, numpy arrays in and out.
    """
    zero, averaged = design_frequencies(design)
    margins = [condition_margin(design.omega, zero, averaged, c) for c in CONDITIONS if c.source == "paper"]
    smallest = margins[0]
    for m in margins[1:]:
        smallest = (smallest + m - abs(smallest - m)) / 2.0
    return smallest


def _label(n: int, mode: str) -> str:
    return f"{n if n > 1 else ''}ω = {mode}"


def forcing_shares(M, K, forces) -> np.ndarray:
    """Forcing share [-] of each harmonic on each mode: the modal weights
    (:func:`~foundation_calc.solvers.numerics.modal_forcing.modal_forcing_weights`) of ``forces``
    (H, 3) on (K, M), modes in the order k0, p1, p2, over the largest weight; shape (..., H, 3)
    for stacks (..., 3, 3) of operators."""
    from foundation_calc.solvers.crank.averaged import mode_order
    from foundation_calc.solvers.numerics.modal_forcing import modal_forcing_weights

    _, shapes, weights = modal_forcing_weights(M, K, forces)
    weights = np.take_along_axis(weights, mode_order(M, shapes)[..., None, :], axis=-1)
    largest = weights.max(axis=(-2, -1), keepdims=True)
    return np.where(largest > 0.0, weights / np.where(largest > 0.0, largest, 1.0), 0.0)


def harmonic_conditions(orders, load_orders=(), mechanism: bool = True) -> tuple[ResonanceCondition, ...]:
    """The conditions n ω = k0, p1, p2 of every order n of ``orders``, in that order: the paper's
    own where it names them, else one of the mechanism's harmonics, of the loads' orders or of the
    speed itself (a machine given by its loads)."""
    known = {(c.harmonic, c.mode): c for c in CONDITIONS} if mechanism else {}
    conditions = []
    for n in orders:
        for mode in MODES:
            condition = known.get((n, mode))
            if condition is None:
                source = "loads" if n in load_orders else "harmonic" if mechanism else "speed"
                excitation = {
                    "loads": f"loads of order {n}",
                    "harmonic": f"harmonic {n} of the mechanism's forcing",
                    "speed": "the speed itself (no load of order 1)",
                }[source]
                condition = ResonanceCondition(_label(n, mode), n, mode, source, excitation)
            conditions.append(condition)
    return tuple(conditions)


def machine_conditions(design: CrankDesign | None, loads=None, block=None) -> tuple[tuple[ResonanceCondition, ...], np.ndarray]:
    """Every condition n ω = k0, p1, p2 of the machine's forcing and its forcing share [-].

    The mechanism's harmonics 1 ... :data:`~foundation_calc.solvers.crank.averaged.FORCING_HARMONICS`
    come from its exact forcing on the averaged operator; the loads' orders (and order 1, the
    speed itself) from ``loads`` on the averaged operator, or on ``block`` for a machine given by
    its loads only. A harmonic of both adds the two forces (their phases included).
    """
    from foundation_calc.solvers.crank.averaged import averaged_operator
    from foundation_calc.solvers.crank.loads import matrices

    forces: dict[int, np.ndarray] = {1: np.zeros(3, dtype=complex)}
    if design is not None:
        M, _, K, fc, fs = averaged_operator(design)
        for n, force in enumerate((fc - 1j * fs).T[1:], start=1):
            forces[n] = force
    else:
        M, K, _ = matrices(block)
    load_orders = set()
    if loads is not None:
        generalized = loads.generalized()
        for n in sorted({int(k) for k in loads.order}):
            load_orders.add(n)
            forces[n] = forces.get(n, 0.0) + generalized[np.asarray(loads.order) == n].sum(axis=0)
    orders = sorted(forces)
    shares = forcing_shares(M, K, np.array([forces[n] for n in orders]))
    return harmonic_conditions(orders, load_orders, design is not None), shares.ravel()
