"""``fc.platform``: isolators and exciter of a vibrating platform, verified in 6 DOF (``fcalc platform``)."""

from __future__ import annotations

import copy

from foundation_calc.api.result import Result, command_result

#: Speed keys of [operation] -> the option that sets each.
SPEED_FLAGS = {"omega": "--omega", "frequency_hz": "--hz", "speed_rpm": "--rpm"}
#: The paper's example, designed when no scene is given.
PAPER_EXAMPLE = "paper example (built in)"


def platform(scene=None, *, omega: float | None = None, hz: float | None = None, rpm: float | None = None,
             amp: float | None = None, strict: bool = False) -> Result:
    """Design a vibrating platform that moves purely translationally and verify it in 6 DOF:
    isolator stiffnesses, exciter position, static deflection (Bolotnik et al., Eqs. (3.8)-(3.21),
    corrected), natural frequencies and the rocking of the product's corners.

    Parameters
    ----------
    scene : Scene, path or mapping, optional
        A ``platform`` scene (:func:`~foundation_calc.api.scene.load`); None: the paper's example.
    omega, hz, rpm : float, optional
        ``--omega`` [rad/s], ``--hz`` [Hz], ``--rpm`` [rpm]: the speed, overriding the scene's
        (at most one of them).
    amp : float, optional
        ``--amp``: the required circular amplitude u [m], overriding the scene's.
    strict : bool
        ``--strict``: a warning fails (exit code 1).

    Returns
    -------
    Result
        ``to_dict()`` is the document of ``fcalc platform --json``.

    Raises
    ------
    SceneError
        An invalid scene, or a scene of another kind.
    PhysicsError
        No such platform exists (a stiffness that must be negative); it names the option when an
        overridden value is the cause.
    UsageError
        More than one speed given.
    """
    return designed(platform_scene(scene, omega=omega, hz=hz, rpm=rpm, amp=amp), strict)


def platform_scene(scene=None, *, omega: float | None = None, hz: float | None = None, rpm: float | None = None,
                   amp: float | None = None):
    """The platform scene of :func:`platform`'s arguments, validated with the options' values in
    place of the scene's; its errors and warnings name the option that gave a value."""
    from foundation_calc.api.scene import Scene, read, scene_of
    from foundation_calc.errors import UsageError
    from foundation_calc.scenes.loading import expect_kind
    from foundation_calc.scenes.platform import DEFAULT_SCENE

    speeds = {key: value for key, value in (("omega", omega), ("frequency_hz", hz), ("speed_rpm", rpm)) if value is not None}
    if len(speeds) > 1:
        raise UsageError("give at most one of --omega, --hz, --rpm", "'--omega' / '--hz' / '--rpm'")
    source = PAPER_EXAMPLE if scene is None else None
    scene = DEFAULT_SCENE if scene is None else scene
    overridden = bool(speeds) or amp is not None
    if overridden:  # the options replace the scene's keys as written; the scene is validated with them
        if isinstance(scene, Scene):
            expect_kind(scene.kind, "platform", scene.source)
        data, source, _ = read(scene, source)
        operation = data.get("operation")
        if isinstance(operation, dict):
            for key in SPEED_FLAGS if speeds else ():
                operation.pop(key, None)
            operation.update(speeds)
            if amp is not None:
                operation["amplitude"] = amp
            source += " (with command-line overrides)"
        scene = scene_of(data, "platform", source)
        typed = {f"operation.{key}": SPEED_FLAGS[key] for key in speeds}
        if amp is not None:
            typed["operation.amplitude"] = "--amp"
        scene.model.given_on_command_line(typed)
        return scene
    return scene_of(scene, "platform", source)


def designed(scene, strict: bool = False) -> Result:
    """:func:`platform` of the scene of :func:`platform_scene`."""
    from operator import attrgetter

    from foundation_calc.checks.outcomes import exit_code
    from foundation_calc.checks.platform import check_platform
    from foundation_calc.errors import PhysicsError
    from foundation_calc.output.platform import platform_document

    loaded = scene.model
    given_as = loaded.operation.speed_given_as
    option = loaded.key_as_given(f"operation.{given_as}")
    if option != f"operation.{given_as}":
        given_as = f"{option} on the command line"
    try:
        design = loaded.design()
    except PhysicsError as exc:  # name the option the user typed, not the scene key it set
        option = loaded.key_as_given(exc.field)
        if option == exc.field:
            raise
        typed = f"{option} {attrgetter(exc.field)(loaded):g}"
        raise PhysicsError(exc.message, field=typed, hint=exc.hint) from None
    report = check_platform(design, loaded.model(), loaded.limits, loaded.inertia_given)
    code = exit_code(report.outcome, strict, bool(loaded.plausibility_warnings()))
    return command_result("platform", platform_document(report, loaded, scene.source, given_as), code, scene,
                          (report, given_as))
