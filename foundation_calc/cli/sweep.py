"""``fcalc sweep SCENE --speed FROM:TO[:N] | --soil FROM:TO[:N]``: amplitudes along a sweep
(:func:`foundation_calc.api.sweep.sweep`), its CSV and plot files."""

from __future__ import annotations

from pathlib import Path
from typing import Annotated, Optional

import typer

from foundation_calc.cli.guard import reports_errors, warn_implausible
from foundation_calc.cli.kinds import RIGID_BODY_SCENE, scene_argument
from foundation_calc.cli.units import UnitsOpt

SceneArg = Annotated[Path, scene_argument(RIGID_BODY_SCENE)]
SpeedOpt = Annotated[
    Optional[str],
    typer.Option("--speed", metavar="FROM:TO[:N][UNIT]", show_default=False,
                 help="Sweep the speed (a crank scene's crank, a block's --machine): N points (default 101) from FROM"
                 " to TO, in rpm unless a unit follows (rpm, rad/s, hz), e.g. 100:600:251 or 10:60rad/s; one value is"
                 " one point."),
]
SoilOpt = Annotated[
    Optional[str],
    typer.Option("--soil", metavar="FROM:TO[:N]", show_default=False,
                 help="Sweep a factor on the soil's stiffness data, e.g. 0.5:1.5:41 (soil known to ±50 %): Barkan's c_z,"
                 " c_x, c_phi (c_psi); G, or V_s by its square root (lysmer, gazetas, pais_kausel); E (sp26); a block's"
                 " given springs, their dashpots by its square root; a pile group recomputed from its factored soil."
                 " Every machine of a block at its own speed; not for a block on [[isolators]]."),
]
CsvOpt = Annotated[Optional[Path], typer.Option(
    "--csv", metavar="FILE", show_default=False,
    help="Write the points as CSV (SI units), streamed chunk by chunk; a long sweep then prints a summary, not its rows.",
)]
PlotOpt = Annotated[Optional[Path], typer.Option(
    "--plot", metavar="FILE", show_default=False,
    help="Draw the amplitudes, the operating speed and the detuning bands (.png, .svg or .pdf); needs the plot extra.",
)]

#: A sweep written to CSV with more points than this prints a summary instead of its rows.
TABLE_ROWS_WITH_CSV = 1000
JsonOpt = Annotated[bool, typer.Option("--json", help="Print one JSON document (SI units) instead of the table.")]
MachineOpt = Annotated[
    Optional[str],
    typer.Option("--machine", metavar="NAME", help="block_foundation: the machine whose speed is swept (the others keep theirs"
                 " unless --alone).", show_default=False),
]
AloneOpt = Annotated[bool, typer.Option(
    "--alone", help="block_foundation: the swept machine alone; the others stand still (their mass stays on the block,"
    " their loads and resonances are left out).")]


@reports_errors
def sweep(
    scene: SceneArg,
    speed: SpeedOpt = None,
    soil: SoilOpt = None,
    csv: CsvOpt = None,
    plot: PlotOpt = None,
    json: JsonOpt = False,
    units: UnitsOpt = None,
    machine: MachineOpt = None,
    alone: AloneOpt = False,
) -> None:
    """Amplitudes and resonance margins along a sweep of a machine's speed or of the soil's
    stiffness, resonances marked.

    Each row is fcalc amplitudes and resonance at that speed or soil factor, computed in
    vectorised chunks, with the peaks at the centre of mass and the scene's [[points]] and a
    status that says why: the resonance condition that governs there (docs/resonance-rule.md)
    with its margin, and every limit exceeded. Statuses: resonant (no periodic solution), fail (a
    judged condition inside its band, or a peak or RMS limit exceeded), warn, pass. A
    block_foundation (or a platform, read as a block) sweeps one machine's speed (--machine; the
    others at their own, or left out with --alone), or the factor on its soil with every machine
    at its own speed. A crank_foundation sweeps its crank speed by the corrected first
    approximation (on a pile group, which couples sway with rocking, and at the speeds where a
    frequency-dependent soil's rocking spring at a harmonic falls to P h, by the averaged
    operator, the support at each harmonic's frequency, as amplitudes solves it there), the peaks
    of x, y (of C) and θ; its [[loads]] add their linear steady state and their resonance
    conditions. A long sweep written with --csv is streamed and summarised. A sweep is a picture,
    not a check: it exits 0 unless the scene or the options are invalid.
    """
    from foundation_calc.api.options import display_units, plot_path, writable_path, writing
    from foundation_calc.api.sweep import chunks, plan, swept

    if plot is not None:
        plot_path(plot)
    if csv is not None:
        writable_path(csv, "--csv")
    shown = display_units(units)
    planned = plan(scene, speed, soil, machine, alone)
    loaded = planned.scene
    warn_implausible(loaded.model)
    named = {part.strip().lower() for token in units or [] for part in token.split(",")}
    if speed is not None and not named & {"rad/s", "rad_s", "rads", "hz", "rpm"}:
        from dataclasses import replace

        shown = replace(shown, speed=planned.unit)  # the table speaks the unit the sweep was given in
    name = loaded.name or loaded.source
    if loaded.kind != "block_foundation" and csv is not None and not json and len(planned.values) > TABLE_ROWS_WITH_CSV:
        _stream_csv(chunks(planned), csv, plot, loaded.model, shown, name, len(planned.values))
        return
    result = swept(planned)
    from foundation_calc.output import sweep as out

    if csv is not None:
        from foundation_calc.output.files import write_chunks_atomically

        with writing(csv, "--csv"):
            write_chunks_atomically(csv, (out.sweep_csv(result.report),))
    if plot is not None:
        from foundation_calc.output.sweep_plot import plot_sweep

        with writing(plot, "--plot"):
            plot_sweep(result.report, loaded.model, plot, shown, name)
    if json:
        from foundation_calc.output.console import print_json

        print_json(result.document)
    else:
        out.print_sweep(result.report, loaded.model, loaded.source, shown)


def _stream_csv(chunks, csv: Path, plot, scene, shown, name: str, count: int) -> None:
    """Write a long sweep of a crank ``scene`` to ``csv`` chunk by chunk (memory: one chunk, and 3
    numbers a point for ``plot``), then print a summary of its statuses."""
    from collections import Counter
    from dataclasses import replace

    from foundation_calc.api.options import writing
    from foundation_calc.output import sweep as report_out
    from foundation_calc.output.files import write_chunks_atomically
    from foundation_calc.output.sweep_plot import joined_plot, plot_sweep, plotted

    statuses, kept, first = Counter(), [], []

    def texts():
        for part in chunks:
            if not first:
                first.append(part)
                yield report_out.csv_header(part)
            if part.setup["not_applicable"] and not first[0].setup["not_applicable"]:  # a later chunk's speeds step aside
                first[0] = replace(first[0], setup={**first[0].setup, "not_applicable": part.setup["not_applicable"]})
            statuses.update(map(str, part.rows.status))
            if plot is not None:
                kept.append(plotted(part))
            yield report_out.csv_rows(part)

    with writing(csv, "--csv"):
        write_chunks_atomically(csv, texts())
    if plot is not None:
        with writing(plot, "--plot"):
            plot_sweep(joined_plot(first[0], kept), scene, plot, shown, name)
    report_out.print_sweep_summary(count, statuses, first[0], str(csv), shown)
