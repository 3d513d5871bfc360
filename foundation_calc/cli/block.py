"""``fcalc resonance`` and ``fcalc amplitudes`` of a ``block_foundation`` scene (called through
:func:`foundation_calc.cli.kinds.run_kind`); each returns the exit code."""

from __future__ import annotations

from foundation_calc.checks.outcomes import exit_code
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
    return exit_code(report.resonance_outcome, strict, bool(loaded.plausibility_warnings()))


def amplitudes(loaded, source: str, json: bool, strict: bool, units: DisplayUnits) -> int:
    """Damped steady state per machine and order, peaks and RMS, limits, code zones; judges the
    amplitudes alone, as for a crank scene (the office checks are listed, ``fcalc check`` judges them)."""
    from foundation_calc.checks.block import check_block
    from foundation_calc.output import block as out

    report = check_block(loaded, periodic=True)
    if json:
        from foundation_calc.output.console import print_json

        print_json(out.amplitudes_document(report, loaded, source))
    else:
        out.print_amplitudes(report, loaded, source, units, strict)
    return exit_code(report.amplitude_outcome, strict)


def sweep(loaded, source: str, json: bool, units: DisplayUnits, omega, machine: str | None, alone: bool = False, csv=None,
          plot=None) -> int:
    """The block's peaks and RMS values along a sweep of one machine's speed ``omega`` [rad/s],
    the others at their own (or left out, ``alone``), each row judged as ``fcalc check`` judges
    the scene (:mod:`~foundation_calc.checks.block_sweep`), and its ``csv`` and ``plot`` files if
    asked; a picture, not a check: exit 0."""
    import typer

    from foundation_calc.checks.block_sweep import sweep_block
    from foundation_calc.output import block_sweep as out

    names = [m.name for m in loaded.machines]
    if machine is None and len(names) > 1:
        raise typer.BadParameter(f"the scene has {len(names)} machines: name the one to sweep ({', '.join(names)})",
                                 param_hint="'--machine'")
    if machine is not None and machine not in names:
        import difflib

        close = difflib.get_close_matches(machine, names, n=1)
        hint = f" (did you mean {close[0]!r}?)" if close else ""
        raise typer.BadParameter(f"no machine {machine!r}{hint}; the scene's machines: {', '.join(names)}", param_hint="'--machine'")
    result = sweep_block(loaded, names.index(machine) if machine is not None else 0, omega, alone)
    from foundation_calc.cli.outputs import writing

    if csv is not None:
        from foundation_calc.output.files import write_chunks_atomically

        with writing(csv, "--csv"):
            write_chunks_atomically(csv, (out.sweep_csv(result),))
    if plot is not None:
        with writing(plot, "--plot"):
            out.plot_sweep(result, plot, units, loaded.name or source)
    if json:
        from foundation_calc.output.console import print_json

        print_json(out.sweep_document(result, loaded, source, loaded.plausibility_warnings()))
    else:
        out.print_sweep(result, loaded, source, units)
    return 0


def soil(loaded, source: str, json: bool, sample: int = 0, modulus_cov: float = 0.3, speed_cov: float = 0.0, seed: int = 0) -> int:
    """The block's six springs, damping ratios and dashpots at O, and the uncoupled frequencies
    sqrt(K_i / m_i); on a frequency-dependent soil (labelled static) and at each machine's speed
    and each mode's own frequency; with ``sample`` > 0 the uncertain soil sampled that many times
    (:func:`~foundation_calc.checks.block_sample.sample_block`); judges nothing."""
    from foundation_calc.checks.block_soil import soil_at_frequencies
    from foundation_calc.output import block_soil as out
    from foundation_calc.output import soil as soil_out

    drawn = None
    if sample:
        import typer

        from foundation_calc.checks.block_sample import sample_block

        if speed_cov:
            raise typer.BadParameter("a block's machines keep their speeds in the sample (a crank scene's speed is sampled)",
                                     param_hint="'--speed-cov'")
        drawn = sample_block(loaded, sample, modulus_cov, seed)
    model = loaded.model()
    columns = soil_at_frequencies(loaded, model)
    if json:
        from foundation_calc.output.console import print_json

        print_json(out.soil_document(model, loaded, source, columns) | {"sample": soil_out.sample_document(drawn)})
    else:
        out.print_soil(model, loaded, source, columns)
        if drawn is not None:
            soil_out.print_sample(drawn)
    return 0
