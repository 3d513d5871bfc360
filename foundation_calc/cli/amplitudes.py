"""``fcalc amplitudes SCENE``: forced vibration amplitudes against their limits (:func:`foundation_calc.api.amplitudes.amplitudes`)."""

from __future__ import annotations

from pathlib import Path
from typing import Annotated

import typer

from foundation_calc.cli.guard import reports_errors, warn_implausible
from foundation_calc.cli.kinds import RIGID_BODY_SCENE, scene_argument
from foundation_calc.cli.units import UnitsOpt

SceneArg = Annotated[Path, scene_argument(RIGID_BODY_SCENE)]
JsonOpt = Annotated[bool, typer.Option("--json", help="Print one JSON document (SI units) instead of tables.")]
ExactOpt = Annotated[
    bool,
    typer.Option("--exact", help="Judge the limits with the exact periodic solution (harmonic balance): a block's"
                 " machines with periodic inertia, a crank scene's mechanism (with the closed forms' errors)."),
]
AllPointsOpt = Annotated[
    bool,
    typer.Option("--all-points", help="List every point and limit row; by default a scene with more than 12 points"
                 " shows its governing points and largest value/limit ratios (JSON always lists every point)."),
]


def _exact_note(loaded) -> str | None:
    """Why --exact changes nothing on ``loaded`` (a scene without periodic inertia), None where it applies."""
    if loaded.kind != "block_foundation":
        return None if loaded.model.mechanism is not None else (
            "a [mechanism]; the loads' steady state is already exact for the linear model")
    if any(machine.periodic_parts for machine in loaded.model.machines):
        return None
    return ("a machine's periodic inertia ([[machines.cranks]], [[machines.exciters]]); the machines' steady state"
            " is already exact for the linear model")


@reports_errors
def amplitudes(
    scene: SceneArg, exact: ExactOpt = False, json: JsonOpt = False, units: UnitsOpt = None, all_points: AllPointsOpt = False
) -> None:
    """Steady-state amplitudes per machine and harmonic, peaks and RMS values at the centre of mass
    and the scene's [[points]], against the limits.

    A block_foundation (or a platform, read as a block): the six modes, each machine's orders at
    G and every point, their peaks and RMS values; a machine with angle-dependent inertia (crank
    throws, exciters) adds its exact periodic solution by harmonic balance and the first
    approximation's error against it; --exact judges the limits with that solution. A
    crank_foundation: the paper's corrected first approximation and the closed form with the
    averaged operator, at C and the points; --exact adds the exact periodic solution, checks the
    limits with it and reports the closed forms' relative errors; a machine given by its [[loads]]
    adds (or alone gives) the block's linear steady state. With soil damping every method gives finite amplitudes and phases at and
    through every resonance. Fails (exit 1) when a peak or RMS value exceeds its [limits] key,
    when a point is in zone C or D of [limits] code (ISO 10816-3), or when an undamped scene's
    speed is resonant. It judges the amplitudes alone: a block's office checks (bearing pressure,
    eccentricity, mass ratio) are listed for information, and fcalc check judges them.
    """
    from foundation_calc.api.amplitudes import amplitudes
    from foundation_calc.api.options import display_units
    from foundation_calc.api.resonance import KINDS
    from foundation_calc.api.scene import scene_of

    shown = display_units(units)
    loaded = scene_of(scene, KINDS, platform_as_block=True)
    warn_implausible(loaded.model)
    note = None if not exact else _exact_note(loaded)
    if note is not None:
        from rich.markup import escape

        from foundation_calc.output.console import stderr

        stderr().print(f"note: --exact applies to {escape(note)}")  # its [section] names are no markup
    result = amplitudes(loaded, exact=exact)
    if json:
        from foundation_calc.output.console import print_json

        print_json(result.document)
    else:
        from foundation_calc.output.amplitudes import print_amplitudes

        print_amplitudes(result.report, loaded.model, loaded.source, shown, all_points)
    raise typer.Exit(result.exit_code)
