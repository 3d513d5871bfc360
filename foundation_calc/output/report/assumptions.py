"""Assumptions and limitations of a sheet, generated from what the scene uses and what it checks."""

from __future__ import annotations

from foundation_calc.output.report.model import Section, table

#: soil.method -> how its springs and damping are modelled.
SOIL_MODELS = {
    "coefficients": "Soil: linear springs at the base from Barkan's coefficients c_z, c_x, c_φ (Winkler"
                    " model) [Ba]; damping only as the ratios given in soil.damping.",
    "lysmer": "Uniform elastic half-space under a rigid surface base, Lysmer's and Hall's analogs"
              " [RHW]: frequency-independent springs and radiation damping fitted for a0 < 1.5.",
    "gazetas": "Uniform elastic half-space, Gazetas' static stiffnesses with embedment factors [Ga]"
               " and frequency-independent damping ratios.",
    "pais_kausel": "Uniform elastic half-space, Pais & Kausel's static stiffnesses with embedment"
                   " factors [PK], Gazetas' dashpots and Pais & Kausel's frequency modifiers.",
    "sp26": "The code's coefficients from the static deformation modulus [SP26]; damping ratios of"
            " the code.",
}


def _crank(scene, checks: set[str]) -> list[tuple[str, str]]:
    rows = [
        ("model", "Rigid block; plane motion in the plane of symmetry normal to the crank shaft; small"
                  " rotations; the crank's own mass neglected [KM]."),
        ("soil", SOIL_MODELS.get(scene.soil.method_used, f"Soil method {scene.soil.method_used!r}.")),
    ]
    springs = scene.soil_springs()
    if all(float(getattr(springs, k)) == 0 for k in ("xi_z", "xi_x", "xi_phi")):
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
    from foundation_calc.solvers.supports.footing import static_missing

    text = "; ".join([*static_missing(scene.limits), "strength of the block, anchors and machine, fatigue,"
                      " out-of-plane vibration, transmission to neighbouring structures."])
    rows.append(("not checked", text[0].upper() + text[1:]))
    return rows


def _platform(scene, checks: set[str]) -> list[tuple[str, str]]:
    rows = [
        ("model", "Rigid platform (with mould and product) on linear isolators; exciters at one speed;"
                  " steady state of the linear 6-DOF equations [BC]."),
        ("damping", "Isolator loss factor as given; the soil below the frame is rigid."),
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
    import numpy as np

    if not support.frequency_dependent and not np.any(support.impedance(0.0).dashpots):  # none at any frequency
        rows.append(("damping", "Undamped: amplitudes near a resonance are unbounded; the resonance check"
                                " keeps the speeds away from them."))
    rows.append(("loads", _loads(scene.machines)))
    if any(m.periodic_parts for m in scene.machines):
        rows.append(("response", "Machine parts whose inertia depends on the shaft's angle (a crank mechanism's rods"
                                 " and sliders): the limits judge the first approximation, their mass averaged over a"
                                 " revolution (the averaged operator); the exact periodic solution with the"
                                 " angle-dependent mass matrix (harmonic balance) gives its error (Accuracy)."))
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
    """The loads row of a block: what forces the scene's machines, by the kinds of parts they have."""
    kinds = [text for key, text in (
        ("loads", "the vendor's loads as given, harmonic orders n at nω (amplitude, phase, point)"),
        ("unbalance", "an unbalance from its balance grade, F = m_r G ω rotating normal to its axis"),
        ("cranks", "the crank mechanisms' inertia forces, every order of the sliders' and rods' motion at the"
                   " machine's speed ([KM] for one throw)"),
    ) if any(getattr(m, key) for m in machines)]
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
