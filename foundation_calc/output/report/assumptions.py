"""Assumptions and limitations of a sheet, generated from what the scene uses and what it checks."""

from __future__ import annotations

from foundation_calc.output.report.model import Section, table

def _crank(scene, checks: set[str]) -> list[tuple[str, str]]:
    support = scene.support()
    rows = [
        ("model", "Rigid block; plane motion in the plane of symmetry normal to the crank shaft; small"
                  " rotations; the crank's own mass neglected [KM]."),
        *((row.topic, row.text) for row in support.assumptions()),  # the support's own (its soil and base rows)
    ]
    if _undamped(support):
        rows.append(("damping", "Undamped: at a resonance there is no steady state; amplitudes near one are"
                                " upper-bound estimates only."))
    if scene.mechanism is not None:
        rows.append(("response", "Steady state of the small-parameter method: limits judged with the averaged"
                                 " operator and exact forcing; the rod's inertia averaged over a revolution."))
    if scene.loads:
        rows.append(("loads", "The vendor's loads act as given (amplitude, phase, point); no interaction of"
                              " the machine with the block's motion."))
    if "runup" not in checks:
        rows.append(("start-up", "Start-up and run-down not checked (no run time with [limits]"
                                 " transient_amplitude, and no [drive])."))
    from foundation_calc.output.report.plane_support import by_soil_method
    from foundation_calc.solvers.supports.base import not_checked
    from foundation_calc.solvers.supports.footing import static_missing

    missing = static_missing(scene.limits) if by_soil_method(scene) else not_checked(support, scene.limits)  # a pile group's own
    text = "; ".join([*missing, "strength of the block, anchors and machine, fatigue,"
                      " out-of-plane vibration, transmission to neighbouring structures."])
    rows.append(("not checked", text[0].upper() + text[1:]))
    return rows


def _undamped(support) -> bool:
    """True when ``support`` has no dashpot at any frequency."""
    import numpy as np

    return not support.frequency_dependent and not np.any(support.impedance(0.0).dashpots)


def _platform(scene, checks: set[str]) -> list[tuple[str, str]]:
    from foundation_calc.solvers.platform.verification import build

    platform, _ = build(scene.design(), scene.model())
    rows = [
        ("model", "Rigid platform (with mould and product) on linear isolators; exciters at one speed;"
                  " steady state of the linear 6-DOF equations [BC]."),
        *((row.topic, row.text) for row in platform.isolators.assumptions()),  # the support's own
    ]
    if "runup" not in checks:
        rows.append(("start-up", "Start-up and run-down not checked."))
    rows.append(("not checked", "Strength and fatigue of the isolators, exciter bearings, the frame and its"
                                " foundation; noise; compaction of the product."))
    return rows


def _block(scene, checks: set[str]) -> list[tuple[str, str]]:
    support, limits = scene.support(), scene.limits
    rows = [
        ("model", "Rigid block with every machine rigidly attached: six degrees of freedom about O, the"
                  " centre of the base; small rotations; the weight's tilt stiffness −W z_G included."),
        *((row.topic, row.text) for row in support.assumptions()),  # the support's own (its soil and base rows)
    ]
    if _undamped(support):
        rows.append(("damping", "Undamped: amplitudes near a resonance are unbounded; the resonance check"
                                " keeps the speeds away from them."))
    rows.append(("loads", _loads(scene.machines)))
    if any(m.periodic_parts for m in scene.machines):
        rows.append(("response", "Machine parts whose inertia depends on the shaft's angle (see loads): the limits"
                                 " judge the first approximation, their mass averaged over a revolution (the averaged"
                                 " operator); the exact periodic solution with the angle-dependent mass matrix"
                                 " (harmonic balance) gives its error (Accuracy)."))
    if len(scene.machines) > 1:
        rows.append(("machines", "Steady state of each machine solved alone; the peaks of the machines added"
                                 " (an upper bound: their relative phase is not known) and the RMS values"
                                 " combined as the root-sum-square of every harmonic."))
    rows.append(("resonance", "Every order of every machine against each of the six modes (undamped"
                              " frequencies); an order whose forcing share on a mode is under 1 % is not judged."))
    from foundation_calc.checks.limits import limited_quantities
    from foundation_calc.output.report.verdict import quantity_name

    judged = [quantity_name(q) for q in limited_quantities(limits)]
    rows.append(("amplitudes", "Judged at G and the scene's points, along x, y and z: "
                               + (", ".join(judged) if judged else "no limit in [limits]")
                               + (f"; zones of {limits.code} (RMS velocity and displacement)" if getattr(limits, "code", None) else "; no vibration code zone")
                               + "."))
    if "runup" not in checks:
        rows.append(("start-up", "Start-up and run-down not checked (no [operation] run time with [limits]"
                                 " transient_amplitude)."))
    from foundation_calc.solvers.supports.base import not_checked

    text = "; ".join([*not_checked(support, limits), "strength and fatigue of the block, anchors, grout and machines,"
                      " transmission to neighbouring structures and people."])  # the support names its own terms
    rows.append(("not checked", text[0].upper() + text[1:]))
    return rows


def _loads(machines) -> str:
    """The loads row of a block: what forces the scene's machines, each kind of part they have in its
    own words (:meth:`~foundation_calc.solvers.machines.part.MachinePart.assumption`), kind by kind."""
    kinds = list(dict.fromkeys(text for kind in zip(*(m.parts_by_kind for m in machines)) for parts in kind
                               for part in parts if (text := part.assumption()) is not None))
    said = "; ".join(kinds) if kinds else "each machine's parts' loads at their orders n, at nω"
    return f"{said[0].upper()}{said[1:]}; the forces do not depend on the block's motion."


def assumptions_section(scene, runs) -> Section:
    """The scene's assumptions and what the sheet does not check."""
    checks = {run.check for run in runs}
    maker = {"crank_foundation": _crank, "platform": _platform, "block_foundation": _block}.get(scene.kind)
    rows = maker(scene, checks) if maker else [
        ("model", f"Scene kind {scene.kind!r}: the checks {', '.join(sorted(checks))} as fcalc check runs them.")
    ]
    if "runup" in checks:
        rows.append(("start-up", "Linear speed ramp (or the motor's torque against the load, Sommerfeld"
                                 " effect); passages of resonances by the closed form and a time integration"
                                 " of the linear model [Le]."))
    return Section("Assumptions and limitations", (table("", ("topic", "assumption or limitation"), rows, (False, False)),))
