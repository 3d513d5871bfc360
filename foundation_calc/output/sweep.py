"""``fcalc sweep`` of a scene of any kind: its JSON document, table, CSV and plot. Every kind's rows
carry the same verdict cells (:func:`~foundation_calc.output.sweep_report.verdict_cells`, worded
by :func:`~foundation_calc.checks.sweep_status.status_text`); a crank scene's rows add the peaks
of C in x, y, θ, of its points and the harmonics (:mod:`~foundation_calc.output.sweep_report`), a
block's the largest peaks and RMS values over G and its points in x, y, z, along a machine's speed
(:mod:`~foundation_calc.output.block_sweep`) or a factor on its soil
(:mod:`~foundation_calc.output.block_soil_sweep`)."""

from __future__ import annotations


def _block(report):
    """The output module of a block's sweep ``report``, None for a crank scene's."""
    from foundation_calc.checks.block_soil_sweep import BlockSoilSweep
    from foundation_calc.checks.block_sweep import BlockSweep

    if isinstance(report, BlockSweep):
        from foundation_calc.output import block_sweep

        return block_sweep
    if isinstance(report, BlockSoilSweep):
        from foundation_calc.output import block_soil_sweep

        return block_soil_sweep
    return None


def sweep_document(report, scene, source: str) -> dict:
    """The JSON document of ``fcalc sweep`` (SI units), with the scene's plausibility warnings."""
    warnings = scene.plausibility_warnings()
    if (block := _block(report)) is not None:
        return block.sweep_document(report, scene, source, warnings)
    from foundation_calc.output.sweep_report import sweep_document as document

    return document(report, source, scene.name, warnings)


def print_sweep(report, scene, source: str, units) -> None:
    """The sweep's table, speeds and amplitudes in ``units``."""
    if (block := _block(report)) is not None:
        block.print_sweep(report, scene, source, units)
    else:
        from foundation_calc.output.sweep_report import print_sweep as table

        table(report, source, scene.name, units)


def sweep_csv(report) -> str:
    """The sweep as CSV text (SI units, the speed also in Hz and rpm)."""
    if (block := _block(report)) is not None:
        return block.sweep_csv(report)
    from foundation_calc.output.sweep_report import sweep_csv as text

    return text(report)


def plot_sweep(report, scene, path, units, name: str) -> None:
    """The sweep's plot: peaks against the swept variable, the limits, the operating point and the
    critical speeds with their detuning bands."""
    if (block := _block(report)) is not None:
        block.plot_sweep(report, path, units, name)
    else:
        from foundation_calc.output.sweep_report import operating, plot_sweep as plot

        plot(report, path, units, name, operating(scene, report.variable))


__all__ = ["plot_sweep", "print_sweep", "sweep_csv", "sweep_document"]
