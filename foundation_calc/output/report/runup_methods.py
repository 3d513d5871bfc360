"""The run-up's closed form as a hand calculation, one column per resonance passed.

For each passage of mode i by harmonic r (:mod:`foundation_calc.solvers.numerics.runup`,
:mod:`foundation_calc.solvers.numerics.passage`): the speed and time of the passage on the linear
ramp of duration T to the operating speed ω, the sweep rate η = r ω / (T ω_i²), the static
deflection of the mode's force at the point it moves most, x_st = |φ_iᵀ(A Ω_r² + B)| / ω_i² ·
|T_P φ_i| (φ_i mass-normalised, found on the sheet by an eigen-solve of M⁻¹K of the run-up's
structure: on a frequency-dependent soil with K and C at the mode's own frequency ω_i, the
resonance check's, :func:`sheet_modes`), Lewis' undamped peak 1.467/√η · x_st [Le] and the closed form with damping,
R(ζ, η) · x_st, R the envelope's maximum through the Faddeeva function (passage.py; it is a
table look-up for a hand calculation, printed as a given). ``tests/test_report_runup_methods.py``
compares every value with the ``runup`` check's.
"""

from __future__ import annotations

import numpy as np

from foundation_calc.output.report.block_methods import modes_of
from foundation_calc.output.report.handcalc import Chain, Columns

LE = "[Le]"


def runup_structures(scene) -> dict:
    """Run key prefix ("" or ":MACHINE", as :func:`~foundation_calc.checks.runup.check_runup` keys
    its runs) -> (structure, point names, operating speed)."""
    from foundation_calc.checks.runup import machine_structures

    machines, names, _ = machine_structures(scene)
    return {f":{name}" if name else "": (structure, names, omega) for name, structure, omega in machines}


def passage_chain(structure, names, omega: float, duration: float, direction: int, passage: dict, modes) -> Chain:
    """One passage's chain: givens of the passage, then its speed, time, η, x_st and peaks."""
    from foundation_calc.solvers.numerics.passage import LEWIS_COEFFICIENT, passage_peak

    natural, shapes, zeta = modes
    i, r = passage["mode"] - 1, passage["harmonic"]
    load = structure.load
    h = int(np.argmin(np.abs(load.ratio - r)))
    w = natural[i]
    speed = w / r
    a = shapes[:, i] @ load.inertial[h] * speed * speed
    b = shapes[:, i] @ load.constant[h] if load.ratio[h] > 0.0 else 0.0
    p = names.index(passage["point"])
    reach = float(np.linalg.norm(structure.points[p] @ shapes[:, i]))
    eta = r * omega / (duration * w * w)
    chain = Chain("")
    chain.given("omega", omega, "rad/s", "operating speed")
    chain.given("T", duration, "s", "duration of the linear ramp")
    chain.given("omega_i", w, "rad/s", "natural frequency of the mode passed")
    chain.given("r", r, "-", "order of the harmonic that passes it (speed ratio)")
    chain.given("zeta", float(zeta[i]), "-", "modal damping ratio φᵀCφ/(2ω_i)")
    chain.given("F_m", float(abs(a + b)), "N (modal)", "modal force of the harmonic at the passage, |φᵀ(A Ω_r² + B)|")
    chain.given("rho_P", reach, "m (modal)", "motion of the point per unit of the mode, |T_P φ|")
    chain.given("C_L", LEWIS_COEFFICIENT, "-", "Lewis' coefficient (1.467 in print)")
    chain.given("R", float(passage_peak(zeta[i], eta, a, b, direction).ratio), "-",
                "closed-form peak over static deflection, Faddeeva envelope with damping")
    chain.step("Omega_r", "omega_i/r", "rad/s", "[FC] runup", "shaft speed at the passage")
    chain.step("t_r", "T*Omega_r/omega" if direction > 0 else "T*(1 - Omega_r/omega)", "s", "[FC] linear ramp", "time of the passage")
    chain.step("eta_s", "r*omega/(T*omega_i**2)", "-", LE, "sweep rate Ω̇ r / ω_i²")
    chain.step("x_st", "F_m/omega_i**2*rho_P", "m", LE, "static deflection of the mode's force at the point")
    chain.step("x_L", "C_L/sqrt(eta_s)*x_st", "m", f"{LE} (undamped)", "Lewis' peak")
    chain.step("x_cf", "R*x_st", "m", f"{LE}, damping kept", "closed-form peak of the passage")
    return chain


def sheet_modes(structure, natural) -> tuple[np.ndarray, np.ndarray, np.ndarray]:
    """The sheet's own modes of the run-up's ``structure``: p [rad/s] ascending, shapes
    mass-normalised (columns) and ζ = φᵀ C φ / (2 p), of M⁻¹K; on a frequency-dependent soil mode i
    is the eigenpair nearest the run's ω_i of ``natural`` [rad/s] (the resonance check's) with K
    and C taken at ω_i."""
    if structure.at_frequency is None:
        return modes_of(structure.mass, structure.stiffness, structure.damping)
    from foundation_calc.solvers.numerics.runup import matrices_at

    natural = np.asarray(natural, dtype=float)
    C, K = matrices_at(structure, natural)
    found = [modes_of(structure.mass, K[i], C[i]) for i in range(natural.size)]
    nearest = [int(np.argmin(np.abs(p - w))) for (p, _, _), w in zip(found, natural)]
    return (np.array([p[k] for (p, _, _), k in zip(found, nearest)]),
            np.column_stack([v[:, k] for (_, v, _), k in zip(found, nearest)]),
            np.array([z[k] for (_, _, z), k in zip(found, nearest)]))


def runup_columns(scene, runup: dict) -> list[Columns]:
    """A table of passage columns for every run of the ``runup`` document with passages."""
    from foundation_calc.checks.runup import run_title
    from foundation_calc.output.runup import mode_label

    structures = runup_structures(scene)
    out = []
    for key, run in runup["runs"].items():
        if not run["passages"]:
            continue
        kind, _, machine = key.partition(":")
        structure, names, omega = structures[f":{machine}" if machine else ""]
        direction = 1 if kind == "run_up" else -1
        modes = sheet_modes(structure, run["natural_frequencies"])
        chains = [passage_chain(structure, list(names), omega, run["duration"], direction, p, modes) for p in run["passages"]]
        heads = tuple(f"mode {mode_label(p['mode'] - 1, run.get('mode_names'))}, {p['harmonic']:g}ω" for p in run["passages"])
        lead = tuple((name, "given", source) for name, source in
                     (("omega_i", "modes of M⁻¹K(ω_i)" if structure.at_frequency is not None else "modes of M⁻¹K"),
                      ("r", "harmonic"), ("zeta", "φᵀCφ/(2ω_i)"), ("F_m", "φᵀ(A Ω_r² + B)"),
                      ("rho_P", "|T_P φ|"), ("R", "Faddeeva envelope, passage.py")))
        out.append(Columns(f"{run_title(key).capitalize()}: each resonance passed (closed form; T = {run['duration']:g} s,"
                           f" ω = {omega:.4g} rad/s, C_L = 1.467)", heads, chains, lead))
    return out


__all__ = ["passage_chain", "runup_columns", "runup_structures", "sheet_modes"]
