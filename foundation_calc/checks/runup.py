"""Start-up and run-down of either scene kind against ``[limits] transient_amplitude``.

Builds the scene's linear structure (platform: :mod:`~foundation_calc.solvers.platform.runup`;
crank foundation: :mod:`~foundation_calc.solvers.crank.runup`), runs it up and, when asked, down
(:func:`~foundation_calc.solvers.numerics.runup.runup`), and compares the largest displacement of
every point during each run with the limit. An undamped structure gets a warning: its passage
peaks are Lewis' asymptote and the time integration's ringing never decays.
"""

from __future__ import annotations

from dataclasses import dataclass

from foundation_calc.checks.outcomes import Outcome, worst
from foundation_calc.errors import PhysicsError
from foundation_calc.solvers.numerics.runup import RunupResult, runup


@dataclass(frozen=True)
class LimitRow:
    """One point in one run against the transient limit [m]."""

    point: str
    run: str
    value: float
    limit: float | None
    ratio: float | None
    outcome: Outcome


@dataclass(frozen=True)
class RunupReport:
    """Every run of a scene, the points, the limit rows and the verdict.

    Attributes
    ----------
    runs : {"run_up" | "run_down": RunupResult}
    points : names of the measured points, in the order of the results' arrays
    omega : operating speed [rad/s]
    rows : one per point and run
    warnings : findings that do not change the verdict (undamped)
    outcome : worst row (PASS without a limit)
    """

    runs: dict
    points: tuple
    omega: float
    rows: tuple
    warnings: tuple
    outcome: Outcome


RUN_TITLES = {"run_up": "start-up", "run_down": "run-down"}


def _structure(scene):
    """The scene's linear structure, the names of its points and the operating speed."""
    if scene.kind == "platform":
        from foundation_calc.solvers.platform.runup import structure

        design = scene.design()
        built, names = structure(design, scene.model())
        return built, names, design.omega
    from foundation_calc.solvers.crank.runup import structure

    design = scene.design()
    built = structure(design, [p.horizontal for p in scene.points], [p.height for p in scene.points])
    return built, ("C", *(p.name for p in scene.points)), design.omega


def check_runup(scene, up: float | None, down: float | None) -> RunupReport:
    """Run ``scene`` up in ``up`` [s] and down in ``down`` [s] (either may be None, not both).

    Raises
    ------
    PhysicsError
        when neither time is given, or a run is too long for the time integration.
    """
    if up is None and down is None:
        raise PhysicsError(
            "no run-up or run-down time: give [operation] run_up_time [s] (or run_down_time) in the scene,"
            " or --time / --down on the command line",
            field="operation.run_up_time",
        )
    built, names, omega = _structure(scene)
    runs: dict[str, RunupResult] = {}
    for key, duration, direction in (("run_up", up, 1), ("run_down", down, -1)):
        if duration is None:
            continue
        try:
            runs[key] = runup(built, omega, duration, direction)
        except ValueError as exc:
            field = "operation.run_up_time" if direction > 0 else "operation.run_down_time"
            raise PhysicsError(str(exc), field=field, hint="shorten the ramp") from None
    limit = scene.limits.transient_amplitude
    rows = []
    for key, result in runs.items():
        for name, value in zip(names, result.transient_points):
            value = float(value)
            ratio = value / limit if limit is not None else None
            outcome = Outcome.FAIL if limit is not None and value > limit else Outcome.PASS
            rows.append(LimitRow(name, key, value, limit, ratio, outcome))
    warnings = []
    if not built.damped:
        warnings.append(
            "the structure is undamped: a passage's peak is Lewis' asymptote 1.467/sqrt(η) × the static"
            " deflection, and free vibration started by the ramp never decays; give damping"
            + (" (isolators.loss_factor or damping_ratio)" if scene.kind == "platform" else " (soil.damping)")
        )
    return RunupReport(
        runs=runs, points=tuple(names), omega=float(omega), rows=tuple(rows), warnings=tuple(warnings),
        outcome=worst(r.outcome for r in rows),
    )


__all__ = ["RUN_TITLES", "LimitRow", "RunupReport", "check_runup"]
