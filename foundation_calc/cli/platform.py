"""``fcalc platform [SCENE]``: isolator stiffnesses and exciter placement of a vibro-table."""

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

SPEED_FLAGS = {"omega": "--omega", "frequency_hz": "--hz", "speed_rpm": "--rpm"}


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
    speeds = {key: value for key, value in (("omega", omega), ("frequency_hz", hz), ("speed_rpm", rpm)) if value is not None}
    if len(speeds) > 1:
        raise typer.BadParameter("give at most one of --omega, --hz, --rpm", param_hint="'--omega' / '--hz' / '--rpm'")
    _run(scene, speeds, amp, json, strict)


@reports_errors
def _run(scene: Path | None, speeds: dict, amp: float | None, json: bool, strict: bool) -> None:
    from foundation_calc.checks.outcomes import exit_code
    from foundation_calc.checks.platform import check_platform
    from operator import attrgetter

    from foundation_calc.errors import PhysicsError
    from foundation_calc.output import platform as report_out
    from foundation_calc.scenes import parse_scene, read_toml
    from foundation_calc.scenes.platform import DEFAULT_SCENE

    source = str(scene) if scene is not None else "paper example (built in)"
    data = read_toml(scene if scene is not None else DEFAULT_SCENE)
    operation = data.get("operation")
    overridden = bool(speeds) or amp is not None
    if overridden and isinstance(operation, dict):
        if speeds:
            for key in SPEED_FLAGS:
                operation.pop(key, None)
            operation.update(speeds)
        if amp is not None:
            operation["amplitude"] = amp
        source += " (with command-line overrides)"
    loaded = parse_scene(data, source=source, expect="platform")
    if overridden:
        typed = {f"operation.{key}": SPEED_FLAGS[key] for key in speeds}
        if amp is not None:
            typed["operation.amplitude"] = "--amp"
        loaded.given_on_command_line(typed)
    warn_implausible(loaded)
    given_as = loaded.operation.speed_given_as
    if speeds:
        given_as = f"{SPEED_FLAGS[given_as]} on the command line"
    try:
        design = loaded.design()
    except PhysicsError as exc:  # name the option the user typed, not the scene key it set
        option = loaded.key_as_given(exc.field)
        if option == exc.field:
            raise
        typed = f"{option} {attrgetter(exc.field)(loaded):g}"
        raise PhysicsError(exc.message, field=typed, hint=exc.hint) from None
    report = check_platform(design, loaded.model(), loaded.limits, loaded.inertia_given)
    if json:
        from foundation_calc.output.console import print_json

        print_json(report_out.platform_document(report, loaded, source, given_as))
    else:
        report_out.print_platform_report(report, loaded, source, given_as, strict)
    raise typer.Exit(int(exit_code(report.outcome, strict, bool(loaded.plausibility_warnings()))))
