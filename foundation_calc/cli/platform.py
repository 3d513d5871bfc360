"""``fcalc platform [SCENE]``: isolator stiffnesses and exciter placement of a vibro-table
(:func:`foundation_calc.api.platform.platform`)."""

from __future__ import annotations

from pathlib import Path
from typing import Annotated, Optional

import typer

from foundation_calc.cli.kinds import scene_argument
from foundation_calc.cli.guard import reports_errors, warn_implausible

SceneArg = Annotated[
    Optional[Path],
    scene_argument("Scene file (TOML) of kind platform; without it, the paper's example."),
]
OmegaOpt = Annotated[Optional[float], typer.Option("--omega", help="Speed [rad/s]; overrides the scene.", show_default=False)]
HzOpt = Annotated[Optional[float], typer.Option("--hz", help="Speed [Hz]; overrides the scene.", show_default=False)]
RpmOpt = Annotated[Optional[float], typer.Option("--rpm", help="Speed [rpm]; overrides the scene.", show_default=False)]
AmpOpt = Annotated[
    Optional[float], typer.Option("--amp", help="Required circular amplitude u [m]; overrides the scene.", show_default=False)
]
JsonOpt = Annotated[bool, typer.Option("--json", help="Print one JSON document (SI units) instead of tables.")]
StrictOpt = Annotated[bool, typer.Option("--strict", help="Treat warnings as failures.")]


@reports_errors
def platform(
    scene: SceneArg = None,
    omega: OmegaOpt = None,
    hz: HzOpt = None,
    rpm: RpmOpt = None,
    amp: AmpOpt = None,
    json: JsonOpt = False,
    strict: StrictOpt = False,
) -> None:
    """Design a vibrating platform that moves purely translationally, and verify it in 6-DOF.

    Computes c0 = c1 = c2, the horizontal pair sums, the 4×3 isolator stiffnesses, the exciter
    position (a, b, c) and the static deflection (Bolotnik et al., Eqs. (3.8)-(3.21), corrected),
    then solves the full 6-DOF equations for the rocking of the product's corners, the natural
    frequencies and the rocking caused by build tolerances. With no scene, designs the paper's
    example (ω = 50π rad/s). An impossible design (a stiffness that must be negative) exits 3.
    """
    from foundation_calc.api.platform import designed, platform_scene

    loaded = platform_scene(scene, omega=omega, hz=hz, rpm=rpm, amp=amp)
    warn_implausible(loaded.model)
    result = designed(loaded, strict)
    if json:
        from foundation_calc.output.console import print_json

        print_json(result.document)
    else:
        from foundation_calc.output.platform import print_platform_report

        report, given_as = result.report
        print_platform_report(report, result.scene.model, result.scene.source, given_as, strict)
    raise typer.Exit(result.exit_code)
