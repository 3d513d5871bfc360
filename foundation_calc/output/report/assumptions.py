"""Assumptions and limitations of a sheet, generated from what the scene uses and what it checks."""

from __future__ import annotations

from foundation_calc.output.report.model import Section, table

#: soil.method -> how its springs and damping are modelled.
SOIL_MODELS = {
    "coefficients": "Soil: linear springs at the base from Barkan's coefficients c_z, c_x, c_φ (Winkler"
                    " model) [Ba]; damping only as the ratios given in soil.damping.",
    "lysmer": "Soil: uniform elastic half-space under a rigid surface base, Lysmer's and Hall's analogs"
              " [RHW]: frequency-independent springs and radiation damping fitted for a0 < 1.5.",
    "gazetas": "Soil: uniform elastic half-space, Gazetas' static stiffnesses with embedment factors [Ga]"
               " and frequency-independent damping ratios.",
    "pais_kausel": "Soil: uniform elastic half-space, Pais & Kausel's static stiffnesses with embedment"
                   " factors [PK], Gazetas' dashpots and Pais & Kausel's frequency modifiers.",
    "sp26": "Soil: the code's coefficients from the static deformation modulus [SP26]; damping ratios of"
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
    rows.append(("not checked", "Bearing pressure and settlement of the soil, strength of the block, anchors"
                                " and machine, fatigue, out-of-plane vibration, transmission to neighbouring"
                                " structures."))
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


def assumptions_section(scene, runs) -> Section:
    """The scene's assumptions and what the sheet does not check."""
    checks = {run.check for run in runs}
    maker = {"crank_foundation": _crank, "platform": _platform}.get(scene.kind)
    rows = maker(scene, checks) if maker else [
        ("model", f"Scene kind {scene.kind!r}: the checks {', '.join(sorted(checks))} as fcalc check runs them.")
    ]
    if "runup" in checks:
        rows.append(("start-up", "Linear speed ramp (or the motor's torque against the load, Sommerfeld"
                                 " effect); passages of resonances by the closed form and a time integration"
                                 " of the linear model [Le]."))
    return Section("Assumptions and limitations", (table("", ("topic", "assumption or limitation"), rows, (False, False)),))
