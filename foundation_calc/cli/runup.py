"""``fcalc runup SCENE``: start-up and run-down through the resonances, against a transient limit."""

from __future__ import annotations

from pathlib import Path
from typing import Annotated, Optional

import typer

from foundation_calc.cli.guard import reports_errors, warn_implausible

SceneArg = Annotated[Path, typer.Argument(help="Scene file (TOML) of kind crank_foundation or platform.", show_default=False)]
TimeOpt = Annotated[
    Optional[float],
    typer.Option("--time", min=1e-6, help="Run-up time [s] from rest to the operating speed; overrides [operation] run_up_time.", show_default=False),
]
DownOpt = Annotated[
    Optional[float],
    typer.Option("--down", min=1e-6, help="Run-down time [s] from the operating speed to rest; overrides [operation] run_down_time.", show_default=False),
]
JsonOpt = Annotated[bool, typer.Option("--json", help="Print one JSON document (SI units) instead of tables.")]


@reports_errors
def runup(scene: SceneArg, time: TimeOpt = None, down: DownOpt = None, json: JsonOpt = False) -> None:
    """Peak vibration while the machine starts up (and runs down) through its resonances.

    The speed ramps linearly from rest to the operating speed in the run-up time (and back in
    the run-down time). For every mode passed: its frequency, the sweep rate η = Ω'/ω_n², the
    peak by a closed form and by time integration of the damped linear model (6 DOF platform,
    3 DOF crank foundation), the time of the peak and its ratio to the steady amplitude. Fails
    (exit 1) when a point moves more than [limits] transient_amplitude [m].
    """
    from foundation_calc.checks.outcomes import exit_code
    from foundation_calc.checks.runup import check_runup
    from foundation_calc.output import runup as report_out
    from foundation_calc.scenes import load_scene

    loaded = load_scene(scene)
    warn_implausible(loaded)
    operation = loaded.operation
    up = time if time is not None else operation.run_up_time
    down_time = down if down is not None else operation.run_down_time
    report = check_runup(loaded, up, down_time)
    if json:
        from foundation_calc.output.console import print_json

        print_json(report_out.runup_document(report, loaded, str(scene)))
    else:
        report_out.print_runup_report(report, loaded, str(scene))
    raise typer.Exit(int(exit_code(report.outcome)))
