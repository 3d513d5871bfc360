"""The resonance conditions of a crank machine's whole forcing and the paper's margin.

Beyond the paper's six conditions (:data:`~foundation_calc.solvers.crank.resonance.CONDITIONS`),
every harmonic n ω of a machine's forcing (its mechanism's and its loads') meets k0, p1, p2
(:func:`machine_conditions`), each with its forcing share on the mode (:func:`forcing_shares`),
which the resonance rule (docs/resonance-rule.md) reads to judge it. Kept apart from
:mod:`~foundation_calc.solvers.crank.resonance`, which the closed forms import: these need the
natural frequencies and the averaged operator.
"""

from __future__ import annotations

import numpy as np

from foundation_calc.solvers.crank.mechanism import CrankDesign
from foundation_calc.solvers.crank.natural import MODES, design_frequencies
from foundation_calc.solvers.crank.resonance import CONDITIONS, ResonanceCondition, condition_margin


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


__all__ = ["forcing_shares", "harmonic_conditions", "machine_conditions", "paper_margin"]
