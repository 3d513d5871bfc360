"""``fc.runup``: start-up and run-down through the resonances (``fcalc runup``)."""

from __future__ import annotations

from foundation_calc.api.result import Result, command_result
from foundation_calc.api.scene import scene_of

#: Shortest run-up or run-down time an option takes [s] (its typer bound on the command line).
SHORTEST_TIME = 1e-6


def runup(scene, *, time: float | None = None, down: float | None = None) -> Result:
    """Peak vibration while the machine starts up (and runs down) through its resonances: a closed
    form and a time integration of the damped linear model per mode passed, and a motor's
    torque against the load when the scene has a [drive].

    Parameters
    ----------
    scene : Scene, path or mapping
        A scene of any kind (:func:`~foundation_calc.api.scene.load`).
    time : float, optional
        ``--time``: run-up time from rest to the operating speed [s]; overrides ``[operation]
        run_up_time``.
    down : float, optional
        ``--down``: run-down time [s]; overrides ``[operation] run_down_time``.

    Returns
    -------
    Result
        ``to_dict()`` is the document of ``fcalc runup --json``; ``report`` the run-up report
        (its ``warnings`` are the integration's own).

    Raises
    ------
    SceneError
        An invalid scene, or one without a run time (given neither here nor in the scene).
    """
    from foundation_calc.api.options import within
    from foundation_calc.checks.outcomes import exit_code
    from foundation_calc.checks.runup import check_runup, run_times
    from foundation_calc.output.runup import runup_document

    for keyword, value in (("time", time), ("down", down)):
        if value is not None:
            within(keyword, value, SHORTEST_TIME)
    loaded = scene_of(scene, ("crank_foundation", "platform", "block_foundation"))
    scene_up, scene_down = run_times(loaded.model)
    up = time if time is not None else scene_up
    report = check_runup(loaded.model, up, down if down is not None else scene_down)
    return command_result("runup", runup_document(report, loaded.model, loaded.source), exit_code(report.outcome), loaded, report)
