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
