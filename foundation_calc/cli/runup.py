"""``fcalc runup SCENE``: start-up and run-down through the resonances, against a transient limit
(:func:`foundation_calc.api.runup.runup`)."""

from __future__ import annotations

from pathlib import Path
from typing import Annotated, Optional

import typer

from foundation_calc.api.runup import SHORTEST_TIME
from foundation_calc.cli.guard import reports_errors, warn_implausible
from foundation_calc.cli.kinds import scene_argument

SceneArg = Annotated[Path, scene_argument("Scene file (TOML) of kind block_foundation, crank_foundation or platform.")]
TimeOpt = Annotated[
    Optional[float],
    typer.Option("--time", min=SHORTEST_TIME, help="Run-up time [s] from rest to the operating speed; overrides [operation] run_up_time.", show_default=False),
]
DownOpt = Annotated[
    Optional[float],
    typer.Option("--down", min=SHORTEST_TIME, help="Run-down time [s] from the operating speed to rest; overrides [operation] run_down_time.", show_default=False),
]
JsonOpt = Annotated[bool, typer.Option("--json", help="Print one JSON document (SI units) instead of tables.")]
PlotOpt = Annotated[
    Optional[Path],
    typer.Option("--plot", metavar="FILE.png", help="Draw the displacement against time with the resonances marked; needs the plot extra.", show_default=False),
]


@reports_errors
def runup(scene: SceneArg, time: TimeOpt = None, down: DownOpt = None, json: JsonOpt = False, plot: PlotOpt = None) -> None:
    """Peak vibration while the machine starts up (and runs down) through its resonances.

    The speed ramps linearly from rest to the operating speed in the run-up time (and back in
    the run-down time); with a [drive] the speed follows the motor's torque against the load
    and a motor that would stick at a resonance fails (Sommerfeld). For every mode passed: its frequency, the
    sweep rate η = r Ω'/ω_i² (r the harmonic's speed ratio, Ω' the shaft's acceleration, ω_i the mode's
    natural frequency), the peak by a closed form and by time integration of the damped linear model (6 DOF platform
    and block, 3 DOF crank foundation; a block's machines one at a time, the others' steady peaks added), the time of the peak and its ratio to the steady amplitude. A displacement
    is the magnitude |u| of a point's displacement vector (a table gives it per direction). Fails
    (exit 1) when a point moves more than [limits] transient_amplitude [m], or when the motor sticks;
    without that limit or a [drive] the rows are not judged (exit 0).
    """
    from foundation_calc.api.options import plot_path, writing
    from foundation_calc.api.runup import runup
    from foundation_calc.api.scene import scene_of
    from foundation_calc.output import runup as report_out

    if plot is not None:
        plot_path(plot)
    loaded = scene_of(scene, ("crank_foundation", "platform", "block_foundation"))
    warn_implausible(loaded.model)
    result = runup(loaded, time=time, down=down)
    report = result.report
    if json:
        from foundation_calc.output.console import print_json

        print_json(result.document)
    else:
        report_out.print_runup_report(report, loaded.model, loaded.source)
    report_out.print_warnings(report)
    if plot is not None:
        with writing(plot, "--plot"):
            report_out.plot_runup(report, plot, loaded.name or loaded.source, loaded.model.limits.transient_amplitude)
    raise typer.Exit(result.exit_code)
