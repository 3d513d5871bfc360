"""``fcalc sweep SCENE --speed FROM:TO[:N] | --soil FROM:TO[:N]``: amplitudes along a sweep."""

from __future__ import annotations

import re
from pathlib import Path
from typing import Annotated, Optional

import typer

from foundation_calc.cli.kinds import scene_argument
from foundation_calc.cli.guard import reports_errors, warn_implausible
from foundation_calc.cli.kinds import KIND_MODULES, run_kind
from foundation_calc.cli.units import UnitsOpt

#: Unit suffixes accepted after a speed range -> display unit label.
SPEED_UNITS = {"rpm": "rpm", "rad/s": "rad/s", "hz": "Hz"}
DEFAULT_POINTS = 101
MAX_POINTS = 100_000

_RANGE = re.compile(r"^\s*([^:\s]+?)\s*(?::\s*([^:\s]+?)\s*(?::\s*(\d+))?)?\s*([a-zA-Z/]*)\s*$")

SceneArg = Annotated[Path, scene_argument("Scene file (TOML) of kind crank_foundation or block_foundation.")]
SpeedOpt = Annotated[
    Optional[str],
    typer.Option("--speed", metavar="FROM:TO[:N][UNIT]", show_default=False,
                 help="Sweep the crank speed: N points (default 101) from FROM to TO, in rpm unless a unit"
                 " follows (rpm, rad/s, hz), e.g. 100:600:251 or 10:60rad/s; one value is one point."),
]
SoilOpt = Annotated[
    Optional[str],
    typer.Option("--soil", metavar="FROM:TO[:N]", show_default=False,
                 help="Sweep a factor on the soil coefficients c_z, c_x and c_phi, e.g. 0.5:1.5:41 (soil known to ±50 %)."),
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


def parse_range(text: str, option: str, units: dict[str, str] | None = None, default_unit: str = "") -> tuple[float, float, int, str]:
    """``FROM:TO[:N][UNIT]`` or ``VALUE[UNIT]`` (one point) -> (from, to, n, unit label); a usage
    error names the option.

    >>> parse_range("250", "--speed", SPEED_UNITS, "rpm"), parse_range("10:60:6rad/s", "--speed", SPEED_UNITS, "rpm")
    ((250.0, 250.0, 1, 'rpm'), (10.0, 60.0, 6, 'rad/s'))
    """
    match = _RANGE.match(text)
    bad = typer.BadParameter
    if not match:
        raise bad(f"{text!r} is not FROM:TO[:N] or one value, e.g. 100:600:251 or 250", param_hint=f"'{option}'")
    lo_text, hi_text, n_text, unit = match.groups()
    hi_text = lo_text if hi_text is None else hi_text  # one value: a single-point sweep
    try:
        lo, hi = float(lo_text), float(hi_text)
    except ValueError:
        raise bad(f"{text!r}: FROM and TO must be numbers", param_hint=f"'{option}'") from None
    if units is None and unit:
        raise bad(f"{text!r}: a factor takes no unit", param_hint=f"'{option}'")
    if units is not None:
        if unit and unit.lower() not in units:
            raise bad(f"unknown unit {unit!r}; use one of {', '.join(units)}", param_hint=f"'{option}'")
        unit = units[unit.lower()] if unit else default_unit
    if lo == hi:
        n = int(n_text) if n_text else 1
        if n != 1:
            raise bad(f"{text!r}: FROM = TO is one point; N must be 1 (or leave it out)", param_hint=f"'{option}'")
    else:
        n = int(n_text) if n_text else DEFAULT_POINTS
    if not (0.0 < lo <= hi < float("inf")):
        raise bad(f"{text!r}: need 0 < FROM <= TO (finite numbers)", param_hint=f"'{option}'")
    if lo < hi and not 2 <= n <= MAX_POINTS:
        raise bad(f"{text!r}: N must be between 2 and {MAX_POINTS}", param_hint=f"'{option}'")
    return lo, hi, n, unit


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
    """Closed-form amplitudes of a crank foundation along a speed or soil sweep, resonances marked.

    Every point is computed in vectorised chunks of the corrected first approximation; each row
    shows the peaks of x, y (of C), θ and of the scene's [[points]] and a status that says why:
    the resonance condition that governs there (docs/resonance-rule.md) with its margin,
    and every limit exceeded. Statuses: resonant (no periodic solution), fail (a judged condition
    inside its band, or a peak or RMS limit exceeded), warn, pass. A scene's [[loads]] add their
    linear steady state and their resonance conditions. A long sweep written with --csv is
    streamed and summarised. A block_foundation scene sweeps one machine's speed (--machine; the
    others at their own, or left out with --alone), its rows judged and worded the same way. A
    sweep is a picture, not a check: it exits 0 unless the scene or the options are invalid.
    """
    if (speed is None) == (soil is None):
        raise typer.BadParameter("give exactly one of --speed and --soil", param_hint="'--speed' / '--soil'")
    import numpy as np

    from foundation_calc.cli.outputs import plot_path, writable_path, writing
    from foundation_calc.cli.units import display_units

    if plot is not None:
        plot_path(plot)
    if csv is not None:
        writable_path(csv, "--csv")
    if speed is not None:
        from foundation_calc.units import omega_from_hz, omega_from_rpm

        lo, hi, n, unit = parse_range(speed, "--speed", SPEED_UNITS, "rpm")
        to_omega = {"rpm": omega_from_rpm, "Hz": omega_from_hz, "rad/s": lambda v: v}[unit]
        variable, values = "omega", to_omega(np.linspace(lo, hi, n))
    else:
        lo, hi, n, unit = parse_range(soil, "--soil")
        variable, values = "soil_factor", np.linspace(lo, hi, n)
    shown = display_units(units)
    named = {part.strip().lower() for token in units or [] for part in token.split(",")}
    if speed is not None and not named & {"rad/s", "rad_s", "rads", "hz", "rpm"}:
        from dataclasses import replace

        shown = replace(shown, speed=unit)  # the table speaks the unit the sweep was given in

    from foundation_calc.checks.crank_sweep import joined
    from foundation_calc.output import sweep_report as report_out
    from foundation_calc.scenes import load_scene

    loaded = load_scene(scene, expect=("crank_foundation", *KIND_MODULES))
    warn_implausible(loaded)
    if loaded.kind in KIND_MODULES:
        if variable != "omega":
            raise typer.BadParameter("a block_foundation scene is swept by --speed", param_hint="'--soil'")
        run_kind("sweep", loaded, str(scene), json=json, units=shown, omega=values, machine=machine, alone=alone, csv=csv,
                 plot=plot)
    if machine is not None or alone:
        raise typer.BadParameter("--machine and --alone choose among the machines of a block_foundation scene",
                                 param_hint="'--machine'" if machine is not None else "'--alone'")
    from foundation_calc.checks.crank_sweep import scene_sweep_chunks

    chunks = scene_sweep_chunks(loaded, variable, values)
    operating = loaded.speed.omega_rad_s if variable == "omega" else 1.0
    if csv is not None and not json and len(values) > TABLE_ROWS_WITH_CSV:
        _stream_csv(chunks, csv, plot, operating, shown, loaded.name or str(scene), len(values))
        return
    report = joined(list(chunks))
    if csv is not None:
        from foundation_calc.output.files import write_chunks_atomically

        with writing(csv, "--csv"):
            write_chunks_atomically(csv, (report_out.csv_header(report), report_out.csv_rows(report)))
    if plot is not None:
        with writing(plot, "--plot"):
            report_out.plot_sweep(report, plot, shown, loaded.name or str(scene), operating)
    if json:
        from foundation_calc.output.console import print_json

        print_json(report_out.sweep_document(report, str(scene), loaded.name, loaded.plausibility_warnings()))
    else:
        report_out.print_sweep(report, str(scene), loaded.name, shown)


def _stream_csv(chunks, csv: Path, plot, operating: float, shown, name: str, count: int) -> None:
    """Write a long sweep to ``csv`` chunk by chunk (memory: one chunk, and 3 numbers a point for
    ``plot``), then print a summary of its statuses."""
    from collections import Counter

    from foundation_calc.cli.outputs import writing
    from foundation_calc.output import sweep_report as report_out
    from foundation_calc.output.files import write_chunks_atomically

    statuses, kept, first = Counter(), [], []

    def texts():
        for part in chunks:
            if not first:
                first.append(part)
                yield report_out.csv_header(part)
            statuses.update(map(str, part.status))
            if plot is not None:
                kept.append(report_out.plotted(part))
            yield report_out.csv_rows(part)

    with writing(csv, "--csv"):
        write_chunks_atomically(csv, texts())
    if plot is not None:
        with writing(plot, "--plot"):
            report_out.plot_sweep(report_out.joined_plot(first[0], kept), plot, shown, name, operating)
    report_out.print_sweep_summary(count, statuses, first[0], str(csv), shown)
