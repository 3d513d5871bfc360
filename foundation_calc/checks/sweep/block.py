"""``fcalc sweep`` of a block scene, row by row as ``fcalc check`` judges the scene: a sweep of one
machine's speed (:func:`sweep_block`) or of a factor on the soil's stiffness data, every machine at
its own speed (:func:`sweep_block_soil`); both give the one report of every kind's sweep
(:class:`~foundation_calc.checks.sweep.report.SweepReport`), their columns the largest peak and
RMS values over G and the points along x, y, z (:data:`~foundation_calc.checks.amplitudes.machines.LIMITED_VALUES`).

**A machine's speed.** One machine's speed is swept (:func:`~foundation_calc.solvers.block.sweep.speed_sweep`); the
others run at their own speeds, or are left out (``alone``: they stand still, their mass stays
on the block). At every speed:

- the resonance rule (:func:`~foundation_calc.checks.resonance.rule.judge`) over every order of
  every running machine against every mode, as :func:`~foundation_calc.checks.resonance.report.modes_resonances`
  judges them: the swept machine's margins move with the speed, the others' stay; each
  condition's forcing share is the scene's (at its own speeds), so which conditions are judged
  does not change along the sweep, and the row at the scene's speed is ``fcalc check``'s;
- the limits ``fcalc check`` judges for a block (peak and RMS displacement and velocity of G and
  every point, each direction; :data:`~foundation_calc.checks.amplitudes.machines.LIMITED_VALUES`);
- the row's governing condition, status and the words for it by
  :mod:`~foundation_calc.checks.sweep.status`, which the crank foundation's sweep uses too.

The vibration code's zones are not judged along a sweep (nor for a crank scene's).

**A factor on the soil.** One row per factor, every machine at its own speed, each row ``fcalc
amplitudes`` and ``fcalc resonance`` of the scene on that soil.

ACI 351.3R-18 §4.4 asks that a foundation's dynamic analysis bound the soil's stiffness (commonly
0.5-2 × the best estimate); the sweep shows how the block's amplitudes and resonance margins move
over such a range. At each factor f the scene's soil is replaced by its stiffness data × f
(:meth:`~foundation_calc.scenes.soil.OnSoil.with_modulus_factor`, the same factored soil ``fcalc
check`` judges over ``[soil] modulus_range``: G or V_s², E, Barkan's c_z, c_x, c_phi, c_psi, or
given springs × f with their dashpots × sqrt(f)), and every spring and dashpot is recomputed from
it; the row is :func:`~foundation_calc.checks.amplitudes.machines.check_block_as_given` of that scene:

- on a frequency-dependent soil (Gazetas, Pais & Kausel, a stratum, a pile group) each mode at its
  own frequency and each order n of each machine on the springs and dashpots at n ω;
- a pile group (:attr:`~foundation_calc.solvers.supports.base.Support.unscaled`: its springs do
  not scale with one factor) is recomputed from the factored soil around the piles, as the crank
  foundation's soil sweep recomputes its group;
- the resonance rule over every order of every machine against every mode with the forcing shares
  of the modes at that factor (:func:`~foundation_calc.checks.resonance.report.modes_resonances`), so the
  row's governing condition and verdict are ``fcalc resonance``'s of the factored scene (what the
  check over ``modulus_range`` judges at that factor); the mode numbers and dominant motions in the
  labels are those at the row's factor;
- the limits ``fcalc check`` judges for a block, of the largest peak and RMS values over G and the
  points (:data:`~foundation_calc.checks.amplitudes.machines.LIMITED_VALUES`); a row whose order meets an
  undamped mode has no steady state (status ``resonant``, its values NaN).

Isolators are no soil: a block on ``[[isolators]]`` has no soil to factor
(:func:`refusal`). One check per factor: 41 factors of ``configs/block_two_machines.toml`` take
0.3 s of CPU, of ``configs/block_on_piles.toml`` (the group's impedance) 3.3 s.
"""

from __future__ import annotations

from dataclasses import dataclass

import numpy as np

from foundation_calc.checks.sweep.report import SweepReport
from foundation_calc.checks.sweep.status import over_limits, row_verdicts


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


def _conditions(modes, excitations):
    """Every order of every machine against every mode: (margins at the machines' own speeds
    (C,), orders (C,), shares (C,), labels), machine by machine as ``excitations`` lists them."""
    from foundation_calc.checks.amplitudes.machines import condition_label
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
    """What :func:`~foundation_calc.checks.amplitudes.machines.condition_label` reads of a condition."""

    machine: str
    order: int
    mode: int
    motion: str


def _report(scene, variable: str, values, resonant, largest: dict, margins, verdict, conditions: tuple, **kind) -> SweepReport:
    """The report of a block's sweep over ``values`` of ``variable``: ``largest``: the largest peak
    and RMS values over G and the points, key of :data:`~foundation_calc.checks.amplitudes.machines.LIMITED_VALUES`
    -> (N, 3) [SI]; the ``margins`` (N, C) [-] of the ``conditions`` and the rule's ``verdict`` of
    them; the limits ``fcalc check`` judges for a block; ``kind``: the other fields of
    :class:`~foundation_calc.checks.sweep.report.SweepReport` (``setup``, ``critical``, ``per_row``)."""
    from foundation_calc.checks.amplitudes.machines import LIMITED_VALUES
    from foundation_calc.checks.limits import limited_quantities

    limits = limited_quantities(scene.limits)
    over = over_limits({q: largest[LIMITED_VALUES[q]] for q in limits}, limits)
    return SweepReport(variable=variable, values=values, resonant=resonant,
                       rows=row_verdicts(margins, verdict, over, resonant), conditions=conditions, limits=limits,
                       detuning=scene.limits.detuning, columns=largest, **kind)


def _judged(margins, orders, shares, required):
    """The resonance rule's verdict of a block's conditions (:func:`~foundation_calc.checks.resonance.rule.judge`;
    none is the paper's)."""
    from foundation_calc.checks.resonance.rule import judge

    return judge(margins, orders, shares, required, np.zeros(np.shape(orders), dtype=bool))


def sweep_block(scene, swept: int, omega, alone: bool = False) -> SweepReport:
    """Sweep machine ``swept`` (index into ``scene.machines``) of a ``block_foundation`` scene
    over the speeds ``omega`` [rad/s] (module docstring); ``alone``: leave the other machines out.
    The report's ``critical``: the swept machine's conditions that can decide a row, whose
    critical speed lies inside the range (:class:`SweepCondition`)."""
    from foundation_calc.checks.amplitudes.machines import LIMITED_VALUES, scene_modes
    from foundation_calc.checks.resonance.rule import required_detuning
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
    verdict = _judged(margins, orders, share, required)
    largest = {key: getattr(result, key).max(axis=1) for key in LIMITED_VALUES.values()}
    judged = verdict.judged[0]
    conditions = tuple(
        SweepCondition(label, name, n, critical, bool(judged[c]), bool(judged[c] or n == 1), float(required[c]))
        for c, (label, (name, n, _, critical)) in enumerate(zip(labels, found))
    )
    machine = everyone[swept].name
    lo, hi = (float(omega.min()), float(omega.max())) if omega.size else (np.inf, -np.inf)
    critical = tuple(c for c in conditions if c.machine == machine and c.deciding and lo <= c.critical <= hi)
    return _report(scene, "omega", omega, np.zeros(omega.shape, dtype=bool), largest, margins, verdict, conditions,
                   setup={"machine": machine, "alone": alone, "speed": everyone[swept].omega}, critical=critical)


def refusal(scene) -> str | None:
    """Why a ``block_foundation`` scene has no soil sweep (None: it has one): a block on
    ``[[isolators]]`` stands on catalogue springs, not on a soil whose modulus a factor scales
    (:attr:`~foundation_calc.solvers.supports.base.Support.unscaled` says why)."""
    if scene.soil is not None:
        return None
    return f"{scene.support().unscaled}: a block on them has no soil to factor; sweep a machine's speed (--speed)"


def sweep_block_soil(scene, factors) -> SweepReport:
    """Sweep the factor on the soil's stiffness data of a ``block_foundation`` scene over
    ``factors`` [-] (module docstring).

    Raises
    ------
    ValueError
        the scene stands on ``[[isolators]]`` (:func:`refusal`).
    PhysicsError
        a factor so small that the block tips over (its rocking spring at O no stiffer than the
        weight's overturning moment): the scene's message, naming the factor.
    """
    from foundation_calc.checks.amplitudes.machines import LIMITED_VALUES

    if (why := refusal(scene)) is not None:
        raise ValueError(why)
    factors = np.asarray(factors, dtype=float)
    reports = [_at_factor(scene, float(f)) for f in factors]
    conditions = [r.resonance.rows for r in reports]
    first = conditions[0]
    margins = np.array([[c.margin for c in rows] for rows in conditions]).reshape(len(factors), len(first))
    shares = np.array([[c.share for c in rows] for rows in conditions]).reshape(margins.shape)
    orders = np.array([c.order for c in first], dtype=int)
    required = np.array([c.required for c in first], dtype=float)
    verdict = _judged(margins, orders, shares, required)
    resonant = np.array([r.resonant for r in reports], dtype=bool)
    largest = {key: np.array([np.full(3, np.nan) if r.motion is None else getattr(r.motion, key).max(axis=0)
                              for r in reports]).reshape(len(factors), 3) for key in LIMITED_VALUES.values()}
    return _report(scene, "soil_factor", factors, resonant, largest, margins, verdict, tuple(conditions),
                   setup={"speeds": {m.name: m.omega_rad_s for m in scene.machines}}, per_row=True)


def _at_factor(scene, factor: float):
    """:func:`~foundation_calc.checks.amplitudes.machines.check_block_as_given` of ``scene`` on its soil × ``factor``;
    a block that tips over there says at which factor."""
    from foundation_calc.checks.amplitudes.machines import check_block_as_given
    from foundation_calc.errors import PhysicsError

    try:
        return check_block_as_given(scene.with_modulus_factor(factor))
    except PhysicsError as exc:
        raise PhysicsError(f"at soil factor {factor:g}: {exc.message}", field=exc.field, hint=exc.hint) from None


__all__ = ["SweepCondition", "refusal", "sweep_block", "sweep_block_soil"]
