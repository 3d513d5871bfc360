"""``fcalc sweep`` of a block scene judged row by row, as ``fcalc check`` judges the scene.

One machine's speed is swept (:func:`~foundation_calc.solvers.block.sweep.speed_sweep`); the
others run at their own speeds, or are left out (``alone``: they stand still, their mass stays
on the block). At every speed:

- the resonance rule (:func:`~foundation_calc.checks.resonance_rule.judge`) over every order of
  every running machine against every mode, as :func:`~foundation_calc.checks.resonance.modes_resonances`
  judges them: the swept machine's margins move with the speed, the others' stay; each
  condition's forcing share is the scene's (at its own speeds), so which conditions are judged
  does not change along the sweep, and the row at the scene's speed is ``fcalc check``'s;
- the limits ``fcalc check`` judges for a block (peak and RMS displacement and velocity of G and
  every point, each direction; :data:`~foundation_calc.checks.block.LIMITED_VALUES`);
- the row's governing condition, status and the words for it by
  :mod:`~foundation_calc.checks.sweep_status`, which the crank foundation's sweep uses too.

The vibration code's zones are not judged along a sweep (nor for a crank scene's).
"""

from __future__ import annotations

from dataclasses import dataclass

import numpy as np

from foundation_calc.checks.sweep_status import RowVerdicts, over_limits, row_verdicts


@dataclass(frozen=True)
class SweepCondition:
    """One order of one running machine against one mode: its label (as ``fcalc check`` names it),
    its critical speed p_j / n [rad/s], whether the rule judges it (or, of order 1, it can warn)
    and the band it needs [-]."""

    label: str
    machine: str
    order: int
    critical: float
    judged: bool
    deciding: bool
    band: float


@dataclass(frozen=True)
class BlockSweep:
    """A block's sweep of one machine's speed.

    Attributes
    ----------
    machine : the swept machine's name
    alone : the other machines are left out
    speed : the swept machine's speed in the scene [rad/s]
    omega : (N,) its speeds [rad/s]
    peak, velocity_peak, displacement_rms, velocity_rms, acceleration_peak, acceleration_rms : (N, 3) the
        largest over G and the points along x, y, z [m, m/s, m/s²]
    conditions : the conditions judged at every row, machine by machine in the scene's order
    rows : the rows' verdicts (:class:`~foundation_calc.checks.sweep_status.RowVerdicts`)
    limits : limited quantity -> limit (SI) judged along the sweep
    detuning : the scene's band(s)
    """

    machine: str
    alone: bool
    speed: float
    omega: np.ndarray
    peak: np.ndarray
    velocity_peak: np.ndarray
    displacement_rms: np.ndarray
    velocity_rms: np.ndarray
    acceleration_peak: np.ndarray
    acceleration_rms: np.ndarray
    conditions: tuple[SweepCondition, ...]
    rows: RowVerdicts
    limits: dict
    detuning: object



def _conditions(modes, excitations):
    """Every order of every machine against every mode: (margins at the machines' own speeds
    (C,), orders (C,), shares (C,), labels), machine by machine as ``excitations`` lists them."""
    from foundation_calc.checks.block import condition_label
    from foundation_calc.solvers.block.response import resonances

    margins, orders, shares, found = [], [], [], []
    for exc in excitations:
        res = resonances(modes, exc)
        margins.append(res.margin.ravel())
        shares.append(res.share.ravel())
        orders.append(np.repeat(exc.orders, len(modes.frequencies)))
        found += [(exc.name, int(n), j, float(res.critical[h, j]))
                  for h, n in enumerate(exc.orders) for j in range(len(modes.frequencies))]
    labels = [condition_label(_Row(name, n, j + 1, modes.dominant[j])) for name, n, j, _ in found]
    return np.concatenate(margins), np.concatenate(orders), np.concatenate(shares), labels, found


@dataclass(frozen=True)
class _Row:
    """What :func:`~foundation_calc.checks.block.condition_label` reads of a condition."""

    machine: str
    order: int
    mode: int
    motion: str


def sweep_block(scene, swept: int, omega, alone: bool = False) -> BlockSweep:
    """Sweep machine ``swept`` (index into ``scene.machines``) of a ``block_foundation`` scene
    over the speeds ``omega`` [rad/s] (module docstring); ``alone``: leave the other machines out."""
    from foundation_calc.checks.block import LIMITED_VALUES, scene_modes
    from foundation_calc.checks.limits import limited_quantities
    from foundation_calc.checks.resonance_rule import judge, required_detuning
    from foundation_calc.solvers.block.sweep import speed_sweep

    omega = np.asarray(omega, dtype=float)
    model = scene.stable_model()
    modes, impedance = scene_modes(scene, model)
    everyone = scene.excitations()
    running = [everyone[swept]] if alone else everyone  # in the scene's order, as fcalc check lists them
    at = 0 if alone else swept
    result = speed_sweep(model, modes, running, at, omega, [p.at for p in scene.points], impedance)
    fixed, orders, share, labels, found = _conditions(modes, running)
    margins = np.broadcast_to(fixed, (len(omega), len(fixed))).copy()
    own = result.margin.shape[1] * result.margin.shape[2]
    first = sum(len(e.orders) for e in running[:at]) * len(modes.frequencies)  # the swept machine's conditions
    margins[:, first : first + own] = result.margin.reshape(len(omega), own)
    required = required_detuning(scene.limits.detuning, orders)
    verdict = judge(margins, orders, share, required, np.zeros(orders.shape, dtype=bool))
    largest = {key: getattr(result, key).max(axis=1) for key in LIMITED_VALUES.values()}
    limits = limited_quantities(scene.limits)
    over = over_limits({q: largest[LIMITED_VALUES[q]] for q in limits}, limits)
    judged = verdict.judged[0]
    conditions = tuple(
        SweepCondition(label, name, n, critical, bool(judged[c]), bool(judged[c] or n == 1), float(required[c]))
        for c, (label, (name, n, _, critical)) in enumerate(zip(labels, found))
    )
    return BlockSweep(
        machine=everyone[swept].name, alone=alone, speed=everyone[swept].omega, omega=omega, **largest,
        conditions=conditions, rows=row_verdicts(margins, verdict, over), limits=limits, detuning=scene.limits.detuning,
    )


__all__ = ["BlockSweep", "SweepCondition", "sweep_block"]
