"""Start-up and run-down of either scene kind against ``[limits] transient_amplitude``.

Builds the scene's linear structure (platform: :mod:`~foundation_calc.solvers.platform.runup`;
crank foundation: :mod:`~foundation_calc.solvers.crank.runup`; block foundation: one per machine,
:mod:`~foundation_calc.solvers.block.runup`), runs it up and, when asked, down
(:func:`~foundation_calc.solvers.numerics.runup.runup`), and compares the largest displacement of
every point during each run with the limit. A block's machine is run with its own loads; the
other machines' steady peaks are added to every point's transient peak, as the block's steady
peaks of several machines add (:mod:`~foundation_calc.solvers.block.response`). Several machines
are also run together, each from rest to its own speed in the same time
(:func:`~foundation_calc.solvers.block.runup.machines_structure`): passages of several machines
may then coincide; that run's peak is at least the machines' steady peaks added (its hold at the
final speeds samples their sum, which reaches that bound only over a long time). A scene's
``[drive]``, or a block machine's ``[machines.drive]``, starts that structure by its motor
(:func:`~foundation_calc.solvers.numerics.sommerfeld.motor_runup`): a block machine's motor
turns the machine's own structure, its peaks with the other machines' steady peaks added as the
ramp's. An undamped structure gets a warning: its passage peaks are Lewis' asymptote and the time
integration's ringing never decays.
"""

from __future__ import annotations

from dataclasses import dataclass, replace

from foundation_calc.checks.outcomes import Outcome, worst
from foundation_calc.errors import PhysicsError


@dataclass(frozen=True)
class LimitRow:
    """One point in one run against the transient limit [m]: the peak magnitude |u| of the
    point's displacement vector; ``outcome`` None (not judged) without a limit."""

    point: str
    run: str
    value: float
    limit: float | None
    ratio: float | None
    outcome: Outcome | None


@dataclass(frozen=True)
class RunupReport:
    """Every run of a scene, the points, the limit rows and the verdict.

    Attributes
    ----------
    runs : {"run_up" | "run_down": RunupResult}; a block's ``"run_up:MACHINE"`` ... per machine,
        whose ``transient_points`` and ``transient_directions`` include the other machines'
        steady peaks (``steady_points`` the machine's own)
    motors : the start-ups by motor (MotorRun) by machine: "" the scene's [drive], a block
        machine's name its [machines.drive] (its ``transient_points`` with the other machines'
        steady peaks added); empty without a drive
    torques : Sommerfeld rows, one per resonance each motor passes
    points : names of the measured points, in the order of the results' arrays
    directions : names of the directions of a point's displacement vector (the rows of its map)
    steady_points : peak displacement magnitude |u| of each point in the steady state at
        ``omega`` [m]
    steady_directions : the same along each direction, shape (P, d) [m]
    omega : operating speed [rad/s]
    rows : one per point and run
    warnings : findings that do not change the verdict (undamped)
    outcome : worst judged row or motor torque (PASS when nothing is judged: see ``judged``)
    speeds : a block's machines as (name, speed [rad/s]); empty for one machine
    names : what the resonance check calls each mode, ascending frequency (a block's dominant
        motion, a crank foundation's k0, p1, p2; empty for a platform)
    frequency_dependent : True when the runs were integrated on springs and dashpots that depend
        on frequency (a structure's ``at_frequency``: the support's, or the crank foundation's soil)
    """

    runs: dict
    motors: dict
    torques: tuple
    points: tuple
    directions: tuple
    steady_points: object
    steady_directions: object
    omega: float
    rows: tuple
    warnings: tuple
    outcome: Outcome
    speeds: tuple = ()
    names: tuple = ()
    frequency_dependent: bool = False

    @property
    def judged(self) -> bool:
        """True when a limit or a motor's torque judged something, or a motor that passes no
        resonance reached its speed."""
        reached = any(m.reached for m in self.motors.values())
        return bool(self.torques) or reached or any(row.outcome is not None for row in self.rows)


RUN_TITLES = {"run_up": "start-up", "run_down": "run-down", "motor": "motor start-up"}


#: The machine part of the run key of a block's machines started or stopped together ("run_up:*").
TOGETHER = "*"


def run_title(key: str) -> str:
    """The title of run ``key``: "start-up", for a block's machine "start-up of compressor", for
    its machines together "start-up of every machine together"."""
    run, _, machine = key.partition(":")
    return RUN_TITLES[run] + (" of every machine together" if machine == TOGETHER else f" of {machine}" if machine else "")


@dataclass(frozen=True)
class TorqueRow:
    """Sommerfeld check of one resonance: steady torque needed there against the motor's [N m];
    ``machine`` the block's machine the motor starts ("" the scene's [drive])."""

    mode: int
    ratio: float
    speed: float
    needed: float
    available: float
    outcome: Outcome
    machine: str = ""


#: Directions of a point's displacement vector per scene kind (the rows of the point maps of
#: :mod:`~foundation_calc.solvers.platform.runup` and :mod:`~foundation_calc.solvers.crank.runup`).
DIRECTIONS = {"platform": ("x", "y", "z"), "crank_foundation": ("horizontal", "vertical"), "block_foundation": ("x", "y", "z")}


def _block_structures(scene):
    """One structure per machine of a block scene as (name, structure, speed [rad/s]), and with
    several machines one of them all started together (name :data:`TOGETHER`, the fastest
    machine's speed); the names of the points (G first). Each is the block with the scene's modes,
    the resonance check's (:func:`~foundation_calc.checks.amplitudes.machines.scene_modes`; a PhysicsError
    naming the soil when the block is unstable)."""
    from foundation_calc.checks.amplitudes.machines import scene_modes
    from foundation_calc.solvers.block.runup import machine_structure, machines_structure

    model = scene.stable_model()  # a PhysicsError naming the likely culprit when the block tips over
    modes, impedance = scene_modes(scene, model)
    at = [p.at for p in scene.points]
    excitations = scene.excitations()
    built = [(e.name, machine_structure(model, e, at, modes, impedance), e.omega) for e in excitations]
    if len(excitations) > 1:
        built.append((TOGETHER, *machines_structure(model, excitations, at, modes, impedance)))
    return built, ("G", *(p.name for p in scene.points))


def _structure(scene):
    """The scene's linear structure, the names of its points, the operating speed and the
    inertia the shaft carries besides the drive's own [kg m²]."""
    if scene.kind == "platform":
        from foundation_calc.solvers.platform.runup import structure, unbalance_inertia

        design, model = scene.design(), scene.model()
        built, names = structure(design, model)
        return built, names, design.omega, unbalance_inertia(design, model)
    from foundation_calc.solvers.crank.averaged import block_matrices
    from foundation_calc.solvers.crank.runup import block_structure, mechanism_inertia, structure, with_vendor_loads

    names = ("C", *(p.name for p in scene.points))
    horizontal, height = [p.horizontal for p in scene.points], [p.height for p in scene.points]
    loads = scene.harmonic_loads()
    if scene.mechanism is None:  # a machine given by its vendor's loads alone
        from foundation_calc.solvers.crank.loads import matrices

        omega = scene.speed.omega_rad_s
        built = block_structure(scene.block(), loads, omega, horizontal, height)
        return _on_soil(scene, built, lambda w: matrices(scene.block(w))[:0:-1]), names, omega, 0.0  # (C, K)
    design = scene.design()
    built = structure(design, horizontal, height)
    if loads is not None:
        built = with_vendor_loads(built, loads, design.omega)
    built = _on_soil(scene, built, lambda w: block_matrices(scene.design(w))[1:])
    return built, names, design.omega, mechanism_inertia(design)


def _on_soil(scene, built, support_at):
    """A crank foundation's structure ``built`` with its scene's modes, the resonance check's
    averaged-inertia k0, p1, p2 (:func:`~foundation_calc.checks.resonance.frequencies.scene_frequencies`,
    :func:`~foundation_calc.solvers.crank.runup.crank_modes`), and on a frequency-dependent support
    its damping and stiffness at any frequency: ``support_at(ω)``, the support's (C, K) there in the
    crank's x, y, θ (a pile group's sway-rocking K_xφ, C_xφ with the rest, as the block's run-up
    takes its support's whole 6 × 6 at the harmonic's frequency), in place of the static ones."""
    from foundation_calc.checks.resonance.frequencies import scene_frequencies
    from foundation_calc.solvers.crank.runup import crank_modes

    if scene.support().frequency_dependent:
        static = support_at(0.0)[0]

        def at_frequency(omega):
            C, K = support_at(omega)
            return built.damping + (C - static), K

        built = replace(built, at_frequency=at_frequency)
    return replace(built, modes=crank_modes(built, scene_frequencies(scene)))


def machine_structures(scene) -> tuple[list, tuple[str, ...], dict[str, float]]:
    """The linear structures a scene of any kind runs up, as ``[(machine, structure, operating speed
    [rad/s])]`` (a crank's or a platform's one machine, named ``""``; a block's one per machine and
    with several machines one of them all, :func:`_block_structures`), the names of its points, and
    machine -> the inertia its shaft carries besides the drive's own [kg m²]. The one place the
    run-up tells the kinds' structures apart."""
    if scene.kind == "block_foundation":
        machines, names = _block_structures(scene)
        return machines, names, {m.name: m.carried_inertia for m in scene.machines}
    built, names, omega, inertia = _structure(scene)
    return [("", built, omega)], names, {"": inertia}


def run_times(scene) -> tuple[float | None, float | None]:
    """The scene's ``[operation] run_up_time`` and ``run_down_time`` [s] (None when not given)."""
    operation = scene.operation  # None in a crank scene without the table
    return getattr(operation, "run_up_time", None), getattr(operation, "run_down_time", None)


def drives(scene) -> dict:
    """The scene's motors by machine: ``{"": [drive]}`` for a crank or platform scene that gives
    one, a block's ``{machine: [machines.drive]}`` for each machine that gives one."""
    if scene.kind == "block_foundation":
        return {m.name: m.drive for m in scene.machines if m.drive is not None}
    drive = getattr(scene, "drive", None)  # None in a scene without the table
    return {} if drive is None else {"": drive}


def judged(scene) -> bool:
    """True when the scene gives something to judge a start-up by: a run time and
    ``[limits] transient_amplitude``, or a drive (which may stick)."""
    up, down = run_times(scene)
    return bool(drives(scene)) or (scene.limits.transient_amplitude is not None and (up, down) != (None, None))


def _motor(scene, machine: str, drive, built, omega, carried: float):
    """The start-up of ``built`` by ``drive`` (:func:`~foundation_calc.solvers.numerics.sommerfeld.motor_runup`)
    and its Sommerfeld rows, one per resonance passed: FAIL where the steady need exceeds the
    torque and the motor sticks, WARN where it exceeds it but the shaft passes on its kinetic
    energy; a motor stuck although no need exceeds its torque fails at the passage nearest the
    speed where it sticks. ``carried``: the inertia the shaft turns besides the drive's [kg m²]."""
    from foundation_calc.solvers.numerics.runup import INSIGNIFICANT
    from foundation_calc.solvers.numerics.sommerfeld import motor_runup

    available = drive.available_torque
    try:
        motor = motor_runup(built, omega, available, drive.inertia + carried)
    except ValueError as exc:
        field = f"machines[{[m.name for m in scene.machines].index(machine)}].drive.inertia" if machine else "drive.inertia"
        raise PhysicsError(str(exc), field=field) from None
    largest = max((need.torque for need in motor.needs), default=0.0)
    torques = []
    for need in (n for n in motor.needs if n.torque >= INSIGNIFICANT * largest):
        short = need.torque > available
        outcome = Outcome.FAIL if short and not motor.reached else Outcome.WARN if short else Outcome.PASS
        torques.append(TorqueRow(need.mode, need.ratio, need.speed, need.torque, available, outcome, machine))
    if not motor.reached and torques and all(t.outcome is not Outcome.FAIL for t in torques):
        # stuck although no steady need exceeds the torque: the passage nearest the stuck speed
        k = min(range(len(torques)), key=lambda i: abs(torques[i].speed - motor.stuck_speed))
        torques[k] = replace(torques[k], outcome=Outcome.FAIL)
    return motor, torques


def check_runup(scene, up: float | None, down: float | None) -> RunupReport:
    """Run ``scene`` up in ``up`` [s] and down in ``down`` [s] (either may be None, not both).

    Raises
    ------
    PhysicsError
        when neither time is given, or a run is too long for the time integration.
    """
    motors_of = drives(scene)
    if up is None and down is None and not motors_of:
        raise PhysicsError(
            "no run-up or run-down time: give [operation] run_up_time [s] (or run_down_time, or a [drive];"
            " a block's machine [machines.drive]) in the scene, or --time / --down on the command line",
            field="operation.run_up_time",
        )
    machines, names, carried = machine_structures(scene)
    # the time integration (scipy.linalg's Schur form) only for a scene that is run up: fcalc check
    # and the sheet ask judged() of every scene
    import numpy as np

    from foundation_calc.solvers.numerics.runup import runup, steady_peaks

    steadies = [steady_peaks(b, w) for m, b, w in machines if m != TOGETHER]
    steady_points, steady_directions = sum(s[0] for s in steadies), sum(s[1] for s in steadies)
    runs: dict = {}
    for k, (machine, built, omega) in enumerate(machines):
        for key, duration, direction in (("run_up", up, 1), ("run_down", down, -1)):
            if duration is None:
                continue
            try:
                result = runup(built, omega, duration, direction)
            except ValueError as exc:
                field = "operation.run_up_time" if direction > 0 else "operation.run_down_time"
                raise PhysicsError(str(exc), field=field, hint="shorten the ramp") from None
            if machine == TOGETHER:  # never below the machines' steady peaks added (module docstring)
                result = replace(
                    result, transient_points=np.maximum(result.transient_points, steady_points),
                    transient_directions=np.maximum(result.transient_directions, steady_directions),
                )
            elif machine:  # the others at their steady speeds: their peaks add (module docstring)
                result = replace(
                    result, transient_points=result.transient_points + steady_points - steadies[k][0],
                    transient_directions=result.transient_directions + steady_directions - steadies[k][1],
                )
            runs[f"{key}:{machine}" if machine else key] = result
    motors, torques = {}, []
    for k, (machine, built, omega) in enumerate(machines):
        if machine not in motors_of:
            continue
        motor, passed = _motor(scene, machine, motors_of[machine], built, omega, carried[machine])
        if machine:  # a block's machine: the others at their steady speeds add, as in its ramp
            motor = replace(motor, transient_points=motor.transient_points + steady_points - steadies[k][0])
        motors[machine] = motor
        torques += passed
    limit = scene.limits.transient_amplitude
    rows = []
    peaks = [(key, result.transient_points) for key, result in runs.items()]
    peaks += [(f"motor:{machine}" if machine else "motor", motor.transient_points) for machine, motor in motors.items()]
    for key, transient in peaks:
        for name, value in zip(names, transient):
            value = float(value)
            ratio = value / limit if limit is not None else None
            outcome = None if limit is None else Outcome.FAIL if value > limit else Outcome.PASS
            rows.append(LimitRow(name, key, value, limit, ratio, outcome))
    warnings = []
    if not built.damped:
        warnings.append(
            "the structure is undamped: a passage's peak is Lewis' asymptote 1.467/sqrt(η) × the static"
            " deflection, and free vibration started by the ramp never decays; give damping"
            + {"platform": " (isolators.loss_factor or damping_ratio)", "block_foundation": " (soil.dashpot or soil.damping)"}
            .get(scene.kind, " (soil.damping)")
        )
    return RunupReport(
        runs=runs, motors=motors, torques=tuple(torques), points=tuple(names), directions=DIRECTIONS[scene.kind],
        steady_points=steady_points, steady_directions=steady_directions, omega=float(max(w for _, _, w in machines)),
        rows=tuple(rows), warnings=tuple(warnings),
        outcome=worst([*(r.outcome for r in rows if r.outcome is not None), *(t.outcome for t in torques)]),
        speeds=tuple((m, float(w)) for m, _, w in machines if m and m != TOGETHER),
        names=() if machines[0][1].modes is None else machines[0][1].modes.names,
        frequency_dependent=any(b.at_frequency is not None for _, b, _ in machines),
    )


__all__ = ["DIRECTIONS", "RUN_TITLES", "TOGETHER", "LimitRow", "RunupReport", "TorqueRow", "check_runup", "drives", "judged",
           "machine_structures", "run_times", "run_title"]
