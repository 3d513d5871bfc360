"""Natural frequencies and resonance margins of every foundation: the rows, the report, its verdict
and its words, one copy for every scene kind.

Every order n of every machine against every mode, margin |n ω - p_j| / p_j, is judged by the
resonance rule (:func:`~foundation_calc.checks.resonance.rule.judge`, docs/resonance-rule.md)
in one call over every condition of the scene, whose governing index names the governing row.
The scene kinds differ only in which sections of :class:`ResonanceReport` have content:

- a crank-mechanism foundation (:func:`check_resonances`, :func:`check_block_resonances`): the
  paper's plane model (``design``, its zero-order and averaged-inertia frequencies k0, p1, p2, the rocking
  stability margin); each row has both estimates of its critical speed and its margin is to the
  nearer one; the paper's conditions are judged whatever their forcing share;
- a block foundation (:mod:`~foundation_calc.checks.amplitudes.machines`, :func:`modes_resonances`): the six
  modes (``modes``), the block's mass and centre of mass; the rows name their machine and the
  mode's dominant motion.

The plane model's frequencies, conditions and forcing shares are computed in
:mod:`~foundation_calc.solvers.crank.natural` and :mod:`~foundation_calc.solvers.crank.resonance`;
a scene is read in :mod:`~foundation_calc.checks.resonance`.
"""

from __future__ import annotations

from collections.abc import Mapping
from dataclasses import dataclass, replace
from types import SimpleNamespace
from typing import TYPE_CHECKING

import numpy as np

from foundation_calc.checks.outcomes import RESONANCE_FAIL_MARGIN, Outcome, worst
from foundation_calc.checks.resonance.rule import (
    FORCING_SHARE,
    INFORMATION,
    STATUS_NAMES,
    WARN,
    condition_phrase,
    judge,
    required_detuning,
)
from foundation_calc.checks.resonance.rule import outcome as rule_outcome

if TYPE_CHECKING:
    from foundation_calc.solvers.crank.mechanism import CrankDesign


@dataclass(frozen=True)
class ResonanceRow:
    """One condition n ω = p of one machine's order n on one mode, at the operating speed.

    ``condition``: its label as every command names it, order n (``harmonic``), mode (``"k0"``,
    ``"p1"``, ``"p2"`` of the plane model, or 1 ... 6 of the block), source and excitation
    (:class:`~foundation_calc.solvers.crank.resonance.ResonanceCondition`); ``critical`` the
    critical speed p/n [rad/s] (the plane model: of its zero-order frequencies) and
    ``critical_averaged`` with the mechanism's averaged inertia (the block: the same);
    ``margin`` [-]; ``required``: the band of its order [-] (0: none); ``share``: the forcing share
    [-]; ``judged``: it can fail the design; ``status``: code of
    :mod:`~foundation_calc.checks.resonance.rule`; ``machine`` and ``motion``: the block's machine
    and the mode's dominant motion (empty on the plane model).
    """

    condition: object
    critical: float
    critical_averaged: float
    margin: float
    required: float
    share: float
    judged: bool
    status: int
    machine: str = ""
    motion: str = ""

    @property
    def label(self) -> str:
        return self.condition.label

    @property
    def order(self) -> int:
        return self.condition.harmonic

    @property
    def mode(self):
        return self.condition.mode

    @property
    def outcome(self) -> Outcome:
        return rule_outcome(self.status)

    @property
    def status_name(self) -> str:
        return STATUS_NAMES[self.status]

    @property
    def information(self) -> bool:
        """Not judged, inside its band: listed, never the verdict."""
        return self.status == INFORMATION

    @property
    def needed(self) -> float:
        """The margin this condition needs [-]: its band, at least the 5 % every judged one needs."""
        return max(self.required, RESONANCE_FAIL_MARGIN)

    @property
    def phrase(self) -> str:
        """``"3ω = p1 at 30.9% (needs 20%)"``; information rows add their forcing share."""
        if self.information:
            return f"{self.label} at {self.margin:.1%} (forcing share {self.share:.2g} < {FORCING_SHARE:.0%}: not judged)"
        return condition_phrase(self.label, self.margin, self.needed)


@dataclass(frozen=True)
class ResonanceReport:
    """Natural frequencies of a scene and its resonance rows (module docstring).

    ``rows``: the conditions shown; ``governing``: the row that governs the verdict (the rule's);
    ``speeds``: machine -> its speed [rad/s] (the plane model: its one unnamed machine, ``""``);
    ``detuning``: the scene's ``[limits] detuning`` (a band, or a band per order);
    ``modulus_range``: the check over the soil's ``modulus_range``
    (:mod:`~foundation_calc.checks.soil_range`); ``soil_validity``: a0 of the judged modes and
    orders against the soil method's fitted range (:mod:`~foundation_calc.checks.soil_validity`);
    ``several_roots``: ``WARN`` lines of the modes with several roots of ω = p(K(ω)) on a
    frequency-dependent support (:func:`~foundation_calc.checks.resonance.several_roots_warnings`).

    The plane model's section: ``design`` (None for a machine given by its loads only),
    ``zero_order`` and ``averaged`` frequencies (the same without a mechanism), ``static`` (the
    zero-order frequencies on the static springs of a frequency-dependent soil, else None) and
    ``stability_margin``. The block's: ``modes``
    (:class:`~foundation_calc.solvers.block.response.BlockModes`), ``total_mass`` [kg], ``cog`` [m].
    """

    rows: tuple[ResonanceRow, ...]
    governing: ResonanceRow | None
    speeds: Mapping[str, float]
    detuning: float | Mapping[int, float] = 0.2
    conditions_checked: int = 0
    modulus_range: object = None
    soil_validity: object = None
    design: object = None
    zero_order: object = None
    averaged: object = None
    static: object = None
    stability_margin: float | None = None
    modes: object = None
    total_mass: float | None = None
    cog: object = None
    several_roots: tuple[str, ...] = ()

    @property
    def omega(self) -> float:
        """The speed [rad/s] of a scene with one machine (the plane model's crank speed)."""
        (omega,) = self.speeds.values()
        return omega

    @property
    def per_machine(self) -> bool:
        """Whether the rows name their machines (a block: several machines, six modes)."""
        return self.modes is not None

    @property
    def outcome(self) -> Outcome:
        ranged = () if self.modulus_range is None else (self.modulus_range.outcome,)
        return worst((*(row.outcome for row in self.rows), *ranged))

    @property
    def information(self) -> tuple[ResonanceRow, ...]:
        """Near conditions whose forcing does not matter: listed, not the verdict."""
        return tuple(row for row in self.rows if row.information)

    @property
    def statement(self) -> str:
        """The verdict of the rule in words: the governing condition and its margin, then the other
        failing or warning conditions (``"governing resonance 3ω = p1 at 30.9% (needs 20%)"``)."""
        g = self.governing
        if g is None:
            return "no resonance condition to judge"
        if g.status < WARN:
            return f"governing resonance {g.phrase}"
        others = [row.phrase for row in self.rows if row.status == g.status and row is not g]
        word = "inside the band" if g.margin < g.required else "within 5%"
        return f"{word} of {g.phrase}" + (f"; also {', '.join(others)}" if others else "")

    @property
    def text(self) -> str:
        """The verdict's reason as ``fcalc check`` and ``fcalc resonance`` word it (a recorded
        contract): :attr:`statement` on the plane model; on a block every condition of the worst
        outcome when it is not a pass, then the governing one; then the soil's modulus range."""
        if not self.per_machine:
            ranged = "" if self.modulus_range is None else f" with the soil data as given; {self.modulus_range.text}"
            return self.statement + ranged

        def phrase(r):
            return condition_phrase(r.label, r.margin, r.needed)

        governing = phrase(self.governing)
        outcome = worst(r.outcome for r in self.rows)
        ranged = "" if self.modulus_range is None else f" with the soil data as given; {self.modulus_range.text}"
        if outcome is Outcome.PASS:
            return f"no machine's order is inside a resonance band (governing: {governing})" + ranged
        return "; ".join(phrase(r) for r in self.rows if r.outcome is outcome) + f" (governing: {governing})" + ranged

    def offsets(self) -> dict[str, tuple[float, bool]]:
        """Condition -> (critical speed p/n less its machine's speed [rad/s], judged by the rule)."""
        return {r.label: (r.critical - self.speeds[r.machine], r.judged) for r in self.rows}


def judged_rows(conditions, critical, critical_averaged, margin, share, required, verdict, machines=None, motions=None):
    """The rows of every condition of a scene and its governing row (None when no condition can
    decide), from the rule's ``verdict`` on them all in one call
    (:func:`~foundation_calc.checks.resonance.rule.judge`).

    ``conditions``: a label, order and mode each (C,); ``critical``, ``critical_averaged`` [rad/s],
    ``margin``, ``share``, ``required`` [-]: (C,); ``machines``, ``motions``: the block's machine
    and dominant motion of each condition.
    """
    machines = [""] * len(conditions) if machines is None else machines
    motions = [""] * len(conditions) if motions is None else motions
    rows = tuple(
        ResonanceRow(c, float(critical[i]), float(critical_averaged[i]), float(margin[i]), float(required[i]),
                     float(share[i]), bool(verdict.judged[i]), int(verdict.status[i]), machines[i], motions[i])
        for i, c in enumerate(conditions)
    )
    g = int(verdict.governing)
    return rows, (rows[g] if g >= 0 else None)


def condition_label(r) -> str:
    """How a block's condition is named, e.g. ``"motor: ω = mode 1 (y)"`` (``r``: a ``machine``,
    an ``order``, a ``mode`` and its ``motion``)."""
    return f"{r.machine}: {r.order if r.order > 1 else ''}ω = mode {r.mode} ({r.motion})"


def modes_resonances(modes, excitations, detuning) -> ResonanceReport:
    """Every order of every machine (``excitations``,
    :class:`~foundation_calc.solvers.block.model.Excitation`) against every mode of ``modes``
    (:class:`~foundation_calc.solvers.block.response.BlockModes`), the forcing share of each order
    on each mode |φ_jᵀ Q_n| / p_j over its largest value for the machine, judged in one call;
    ``detuning``: the scene's band, one value or one per order. No condition is a source's own."""
    from foundation_calc.solvers.block.response import resonances
    from foundation_calc.solvers.crank.resonance import ResonanceCondition

    conditions, machines, motions, critical, margin, share = [], [], [], [], [], []
    for exc in excitations:
        res = resonances(modes, exc)
        for h, j in np.ndindex(res.margin.shape):
            n, motion = int(exc.orders[h]), modes.dominant[j]
            label = condition_label(SimpleNamespace(machine=exc.name, order=n, mode=j + 1, motion=motion))
            conditions.append(ResonanceCondition(label, n, j + 1, "harmonic", f"order {n} of {exc.name}"))
            machines.append(exc.name)
            motions.append(motion)
            critical.append(float(res.critical[h, j]))
            margin.append(float(res.margin[h, j]))
            share.append(float(res.share[h, j]))
    orders = np.array([c.harmonic for c in conditions], dtype=int)
    required = required_detuning(detuning, orders)
    verdict = judge(np.array(margin), orders, np.array(share), required, np.zeros(orders.shape, dtype=bool))
    rows, governing = judged_rows(conditions, critical, critical, margin, share, required, verdict, machines, motions)
    return ResonanceReport(
        rows=rows, governing=governing, speeds={exc.name: exc.omega for exc in excitations}, detuning=detuning,
        conditions_checked=len(rows), modes=modes,
    )


#: Conditions listed as information beside the judged ones (the nearest first).
SHOWN_INFORMATION = 3


def judge_conditions(omega, zero, averaged, conditions, share, detuning):
    """The rule (:func:`~foundation_calc.checks.resonance.rule.judge`) on ``conditions`` at the
    speeds ``omega`` [rad/s] (a scalar or an array (S,)): margins (..., C), judgement, bands."""
    from foundation_calc.solvers.crank.resonance import condition_margin

    margins = np.stack(
        np.broadcast_arrays(*(np.asarray(condition_margin(omega, zero, averaged, c), dtype=float) for c in conditions)),
        axis=-1,
    )
    orders = np.array([c.harmonic for c in conditions])
    required = required_detuning(detuning, orders)
    source = np.array([c.source == "paper" for c in conditions])
    return margins, judge(margins, orders, share, required, source), required


def _plane_report(design, zero, averaged, stability, omega, conditions, share, detuning) -> ResonanceReport:
    """The plane model's report: every condition judged (:func:`judge_conditions`), its critical
    speeds of both operators, the harmonics not judged listed up to :data:`SHOWN_INFORMATION`."""
    from foundation_calc.solvers.crank.resonance import critical_speed

    margins, verdict, required = judge_conditions(omega, zero, averaged, conditions, share, detuning)
    critical = [critical_speed(getattr(zero, c.mode), c.harmonic) for c in conditions]
    averaged_critical = [critical_speed(getattr(averaged, c.mode), c.harmonic) for c in conditions]
    rows, governing = judged_rows(conditions, critical, averaged_critical, margins, share, required, verdict)
    information = sorted((row for row in rows if row.information and row.condition.source == "harmonic"), key=lambda r: r.margin)
    listed = {id(row) for row in information[:SHOWN_INFORMATION]}
    shown = tuple(
        row for row in rows
        if row.condition.source != "harmonic" or row.judged or row.status > INFORMATION or id(row) in listed
    )
    return ResonanceReport(
        rows=shown, governing=governing, speeds={"": omega}, detuning=detuning, conditions_checked=len(rows),
        design=design, zero_order=zero, averaged=averaged, stability_margin=stability,
    )


def check_resonances(design: CrankDesign, detuning, loads=None, frequencies=None) -> ResonanceReport:
    """Natural frequencies of ``design`` and every resonance condition of its forcing (and of
    ``loads``, :class:`~foundation_calc.solvers.crank.loads.HarmonicLoads`), judged by the rule
    (:mod:`~foundation_calc.checks.resonance.rule`). ``detuning``: a band [-] or order -> band.
    ``frequencies`` = (zero-order, averaged, static) replaces the design's own (a
    frequency-dependent soil,
    :func:`~foundation_calc.checks.resonance.frequencies.scene_design_frequencies`)."""
    from foundation_calc.solvers.crank.frequencies import rocking_stability_margin, stability_arguments
    from foundation_calc.solvers.crank.natural import design_frequencies
    from foundation_calc.solvers.crank.machine_conditions import machine_conditions

    d = design
    zero, averaged = design_frequencies(design)
    static = None
    if frequencies is not None:
        zero, averaged, static = frequencies
    stability = rocking_stability_margin(*stability_arguments(d))
    conditions, share = machine_conditions(design, loads)
    return replace(_plane_report(design, zero, averaged, stability, d.omega, conditions, share, detuning), static=static)


def check_block_resonances(block, omega: float, loads, detuning, frequencies=None) -> ResonanceReport:
    """Resonances of a machine given by its loads only: n ω of every order n of ``loads`` (and
    ω itself) against the natural frequencies of the block (``RigidBlock``) at ``omega`` [rad/s];
    ``frequencies`` = (frequencies, static) replaces the block's own (a frequency-dependent soil)."""
    from foundation_calc.solvers.crank.frequencies import rocking_stability_margin
    from foundation_calc.solvers.crank.loads import block_frequencies
    from foundation_calc.solvers.crank.machine_conditions import machine_conditions

    freqs, static = block_frequencies(block), None
    if frequencies is not None:
        freqs, static = frequencies
    stability = rocking_stability_margin(block.K_phi, 1.0, block.M_tot * block.g, block.h)
    conditions, share = machine_conditions(None, loads, block)
    return replace(_plane_report(None, freqs, freqs, stability, omega, conditions, share, detuning), static=static)


__all__ = [
    "SHOWN_INFORMATION",
    "ResonanceReport",
    "ResonanceRow",
    "check_block_resonances",
    "check_resonances",
    "condition_label",
    "judge_conditions",
    "judged_rows",
    "modes_resonances",
]
