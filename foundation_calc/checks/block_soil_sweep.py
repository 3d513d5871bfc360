"""``fcalc sweep --soil`` of a block scene: one row per factor on the soil's stiffness data, every
machine at its own speed, each row ``fcalc amplitudes`` and ``fcalc resonance`` of the scene on
that soil.

ACI 351.3R-18 §4.4 asks that a foundation's dynamic analysis bound the soil's stiffness (commonly
0.5-2 × the best estimate); the sweep shows how the block's amplitudes and resonance margins move
over such a range. At each factor f the scene's soil is replaced by its stiffness data × f
(:meth:`~foundation_calc.scenes.soil.OnSoil.with_modulus_factor`, the same factored soil ``fcalc
check`` judges over ``[soil] modulus_range``: G or V_s², E, Barkan's c_z, c_x, c_phi, c_psi, or
given springs × f with their dashpots × sqrt(f)), and every spring and dashpot is recomputed from
it; the row is :func:`~foundation_calc.checks.block.check_block_as_given` of that scene:

- on a frequency-dependent soil (Gazetas, Pais & Kausel, a stratum, a pile group) each mode at its
  own frequency and each order n of each machine on the springs and dashpots at n ω;
- a pile group (:attr:`~foundation_calc.solvers.supports.base.Support.unscaled`: its springs do
  not scale with one factor) is recomputed from the factored soil around the piles, as the crank
  foundation's soil sweep recomputes its group;
- the resonance rule over every order of every machine against every mode with the forcing shares
  of the modes at that factor (:func:`~foundation_calc.checks.resonance.modes_resonances`), so the
  row's governing condition and verdict are ``fcalc resonance``'s of the factored scene (what the
  check over ``modulus_range`` judges at that factor); the mode numbers and dominant motions in the
  labels are those at the row's factor;
- the limits ``fcalc check`` judges for a block, of the largest peak and RMS values over G and the
  points (:data:`~foundation_calc.checks.block.LIMITED_VALUES`); a row whose order meets an
  undamped mode has no steady state (status ``resonant``, its values NaN).

Isolators are no soil: a block on ``[[isolators]]`` has no soil to factor
(:func:`refusal`). One check per factor: 41 factors of ``configs/block_two_machines.toml`` take
0.3 s of CPU, of ``configs/block_on_piles.toml`` (the group's impedance) 3.3 s.
"""

from __future__ import annotations

from dataclasses import dataclass

import numpy as np

from foundation_calc.checks.sweep_status import RowVerdicts, over_limits, row_verdicts


@dataclass(frozen=True)
class BlockSoilSweep:
    """A block's sweep of a factor on its soil's stiffness data.

    Attributes
    ----------
    factor : (N,) the factors on the soil's stiffness data [-]
    speeds : machine name -> its speed in the scene [rad/s] (every machine runs at its own)
    peak, velocity_peak, displacement_rms, velocity_rms, acceleration_peak, acceleration_rms : (N, 3)
        the largest over G and the points along x, y, z [m, m/s, m/s²]; NaN where ``resonant``
    resonant : (N,) an order meets an undamped mode: no steady state at that factor
    row_conditions : per row, the conditions judged there (every order of every machine against
        every mode, labelled with the modes at that factor), in the order of ``rows.governing``
    rows : the rows' verdicts (:class:`~foundation_calc.checks.sweep_status.RowVerdicts`)
    limits : limited quantity -> limit (SI) judged along the sweep
    detuning : the scene's band(s)
    """

    factor: np.ndarray
    speeds: dict
    peak: np.ndarray
    velocity_peak: np.ndarray
    displacement_rms: np.ndarray
    velocity_rms: np.ndarray
    acceleration_peak: np.ndarray
    acceleration_rms: np.ndarray
    resonant: np.ndarray
    row_conditions: tuple
    rows: RowVerdicts
    limits: dict
    detuning: object


def refusal(scene) -> str | None:
    """Why a ``block_foundation`` scene has no soil sweep (None: it has one): a block on
    ``[[isolators]]`` stands on catalogue springs, not on a soil whose modulus a factor scales
    (:attr:`~foundation_calc.solvers.supports.base.Support.unscaled` says why)."""
    if scene.soil is not None:
        return None
    return f"{scene.support().unscaled}: a block on them has no soil to factor; sweep a machine's speed (--speed)"


def sweep_block_soil(scene, factors) -> BlockSoilSweep:
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
    from foundation_calc.checks.block import LIMITED_VALUES
    from foundation_calc.checks.limits import limited_quantities
    from foundation_calc.checks.resonance_rule import judge

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
    verdict = judge(margins, orders, shares, required, np.zeros(orders.shape, dtype=bool))
    resonant = np.array([r.resonant for r in reports], dtype=bool)
    largest = {key: np.array([np.full(3, np.nan) if r.motion is None else getattr(r.motion, key).max(axis=0)
                              for r in reports]).reshape(len(factors), 3) for key in LIMITED_VALUES.values()}
    limits = limited_quantities(scene.limits)
    over = over_limits({q: largest[LIMITED_VALUES[q]] for q in limits}, limits)
    return BlockSoilSweep(
        factor=factors, speeds={m.name: m.omega_rad_s for m in scene.machines}, **largest, resonant=resonant,
        row_conditions=tuple(conditions), rows=row_verdicts(margins, verdict, over, resonant), limits=limits,
        detuning=scene.limits.detuning,
    )


def _at_factor(scene, factor: float):
    """:func:`~foundation_calc.checks.block.check_block_as_given` of ``scene`` on its soil × ``factor``;
    a block that tips over there says at which factor."""
    from foundation_calc.checks.block import check_block_as_given
    from foundation_calc.errors import PhysicsError

    try:
        return check_block_as_given(scene.with_modulus_factor(factor))
    except PhysicsError as exc:
        raise PhysicsError(f"at soil factor {factor:g}: {exc.message}", field=exc.field, hint=exc.hint) from None


__all__ = ["BlockSoilSweep", "refusal", "sweep_block_soil"]
