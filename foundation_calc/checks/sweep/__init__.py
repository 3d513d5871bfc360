"""``fcalc sweep`` of a scene of any kind: its rows and verdicts along a sweep of a speed or of a
factor on the soil, one report for every kind (:class:`~foundation_calc.checks.sweep.report.SweepReport`),
every row judged by one set of rules (:mod:`~foundation_calc.checks.sweep.status`: the governing
resonance condition, the limits exceeded, the status). Each kind supplies its engine and its
columns: a crank scene's speed or soil, in chunks of arrays (:mod:`~foundation_calc.checks.sweep.crank`,
engine :mod:`~foundation_calc.solvers.crank.sweep`); a block's machine speed or soil, every other
machine at its own speed (:mod:`~foundation_calc.checks.sweep.block`, engine
:mod:`~foundation_calc.solvers.block.sweep`)."""

from __future__ import annotations


def scene_sweep(scene, variable: str, values, machine: int | None = None, alone: bool = False):
    """The :class:`~foundation_calc.checks.sweep.report.SweepReport` of ``scene`` over ``values``
    of ``variable`` (``"omega"`` [rad/s] or ``"soil_factor"`` [-]); a block's ``machine`` (index
    into its machines) is swept, ``alone`` leaving the others out (a speed sweep)."""
    if scene.kind == "block_foundation" and variable == "soil_factor":
        from foundation_calc.checks.sweep.block import sweep_block_soil

        return sweep_block_soil(scene, values)
    if scene.kind == "block_foundation":
        from foundation_calc.checks.sweep.block import sweep_block

        return sweep_block(scene, machine, values, alone)
    from foundation_calc.checks.sweep.crank import scene_sweep_chunks
    from foundation_calc.checks.sweep.report import joined

    return joined(list(scene_sweep_chunks(scene, variable, values)))


__all__ = ["scene_sweep"]
