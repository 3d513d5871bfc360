"""``fcalc sweep`` of a scene of any kind: its amplitudes and verdicts along the sweep, every row
judged by one set of rules (:mod:`~foundation_calc.checks.sweep_status`: the governing resonance
condition, the limits exceeded, the status). A crank scene sweeps its speed or a factor on its
soil, in chunks of arrays (:mod:`~foundation_calc.checks.crank_sweep`); a block sweeps one
machine's speed (:mod:`~foundation_calc.checks.block_sweep`) or a factor on its soil, every
machine at its own speed (:mod:`~foundation_calc.checks.block_soil_sweep`)."""

from __future__ import annotations


def scene_sweep(scene, variable: str, values, machine: int | None = None, alone: bool = False):
    """The sweep of ``scene`` over ``values`` of ``variable`` (``"omega"`` [rad/s] or
    ``"soil_factor"`` [-]); a block's ``machine`` (index into its machines) is swept, ``alone``
    leaving the others out (a speed sweep)."""
    if scene.kind == "block_foundation" and variable == "soil_factor":
        from foundation_calc.checks.block_soil_sweep import sweep_block_soil

        return sweep_block_soil(scene, values)
    if scene.kind == "block_foundation":
        from foundation_calc.checks.block_sweep import sweep_block

        return sweep_block(scene, machine, values, alone)
    from foundation_calc.checks.crank_sweep import joined, scene_sweep_chunks

    return joined(list(scene_sweep_chunks(scene, variable, values)))


__all__ = ["scene_sweep"]
