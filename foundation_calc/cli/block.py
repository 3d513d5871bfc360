"""``fcalc resonance`` and ``fcalc amplitudes`` of a ``block_foundation`` scene (called through
:func:`foundation_calc.cli.kinds.run_kind`); each returns the exit code."""

from __future__ import annotations

from foundation_calc.checks.outcomes import exit_code, worst
from foundation_calc.output.display_units import DisplayUnits


def resonance(loaded, source: str, json: bool, strict: bool, units: DisplayUnits) -> int:
    """Modes of the block and every machine's orders against them."""
    from foundation_calc.checks.block import check_block
    from foundation_calc.output import block as out

    report = check_block(loaded)
    if json:
        from foundation_calc.output.console import print_json

        print_json(out.resonance_document(report, loaded, source))
    else:
        out.print_resonance(report, loaded, source, units, strict)
    return exit_code(report.resonance_outcome, strict)


def amplitudes(loaded, source: str, json: bool, strict: bool, units: DisplayUnits) -> int:
    """Damped steady state per machine and order, peaks and RMS, limits, code zones, office checks."""
    from foundation_calc.checks.block import check_block
    from foundation_calc.output import block as out

    report = check_block(loaded)
    if json:
        from foundation_calc.output.console import print_json

        print_json(out.amplitudes_document(report, loaded, source))
    else:
        out.print_amplitudes(report, loaded, source, units, strict)
    return exit_code(worst([report.amplitude_outcome, report.office_outcome]), strict)


def sweep(loaded, source: str, json: bool, units: DisplayUnits, omega, machine: str | None, csv=None, plot=None) -> int:
    """The block's peaks and RMS velocities along a sweep of one machine's speed ``omega``
    [rad/s] (the others at their own), and its ``csv`` and ``plot`` files if asked; a picture,
    not a check: exit 0."""
    import typer

    from foundation_calc.checks.block import scene_modes
    from foundation_calc.output import block_sweep as out
    from foundation_calc.solvers.block.sweep import speed_sweep

    names = [m.name for m in loaded.machines]
    if machine is None and len(names) > 1:
        raise typer.BadParameter(f"the scene has {len(names)} machines: name the one to sweep ({', '.join(names)})",
                                 param_hint="'--machine'")
    if machine is not None and machine not in names:
        import difflib

        close = difflib.get_close_matches(machine, names, n=1)
        hint = f" (did you mean {close[0]!r}?)" if close else ""
        raise typer.BadParameter(f"no machine {machine!r}{hint}; the scene's machines: {', '.join(names)}", param_hint="'--machine'")
    swept = names.index(machine) if machine is not None else 0
    model = loaded.model()
    modes, impedance = scene_modes(loaded, model)
    result = speed_sweep(model, modes, loaded.excitations(), swept, omega, [p.at for p in loaded.points], impedance)
    rows = out.sweep_rows(result, modes, loaded, swept)
    if csv is not None:
        from foundation_calc.output.files import write_chunks_atomically

        write_chunks_atomically(csv, (out.sweep_csv(rows),))
    if plot is not None:
        out.plot_sweep(rows, modes, loaded, swept, plot, units, loaded.name or source)
    if json:
        from foundation_calc.output.console import print_json

        print_json(out.sweep_document(rows, loaded, source, names[swept]))
    else:
        out.print_sweep(rows, loaded, source, names[swept], units)
    return 0


def soil(loaded, source: str, json: bool) -> int:
    """The block's six springs, damping ratios and dashpots at O, and the uncoupled frequencies
    sqrt(K_i / m_i); on a frequency-dependent soil (labelled static) and at each machine's speed
    and each mode's own frequency; judges nothing."""
    from foundation_calc.checks.block_soil import soil_at_frequencies
    from foundation_calc.output import block_soil as out

    model = loaded.model()
    columns = soil_at_frequencies(loaded, model)
    if json:
        from foundation_calc.output.console import print_json

        print_json(out.soil_document(model, loaded, source, columns))
    else:
        out.print_soil(model, loaded, source, columns)
    return 0
