"""The vibrating platform's design as a hand calculation: Bolotnik et al. (3.8)-(3.21), corrected.

From the ``design`` document of ``fcalc check`` (the inputs and the four vertical stiffnesses the
design chose or was given), the chain works the paper's section 3 in its order: M_Σ, c0 of
(3.14), c3, the exciter's axis point a, b of (3.9)-(3.10) and height c of (3.11), the four
horizontal pair sums of (3.6)-(3.8) (the paper's (3.16)-(3.20) once (3.9)-(3.11) hold), the
static deflection and the translational frequency. The corrections are those of the platform
note: ζ (not ξ) in (3.11); the deflection is downward. With the position given, (3.9)-(3.10)
return it from the verticals it produced, so the chain is the same for both ways of designing.
``tests/test_report_methods.py`` compares every end value with the design's.
"""

from __future__ import annotations

from foundation_calc.output.report.handcalc import Chain

BC = "[BC]"


def platform_chain(doc: dict) -> Chain:
    """The platform's design (3.8)-(3.21), static deflection and translational frequency."""
    i, d = doc["inputs"], doc["design"]
    chain = Chain("Platform design: Bolotnik et al. (3.8)-(3.21), corrected")
    chain.given("M", i["M"], "kg", "platform mass with mould and product, without the rotor")
    chain.given("m", i["m"], "kg", "unbalanced (rotor) mass of the exciter")
    chain.given("l", i["l"], "m", "eccentricity of the unbalance")
    chain.given("u", i["u"], "m", "required circular amplitude")
    chain.given("omega", doc["speed"]["omega"], "rad/s", "exciter speed")
    chain.given("g", i["g"], "m/s²", "acceleration of gravity")
    chain.given("xi", i["xi"], "m", "centre of mass from corner O1 along x'")
    chain.given("eta", i["eta"], "m", "centre of mass from corner O1 along y'")
    chain.given("zeta", i["zeta"], "m", "height of the centre of mass above the support plane")
    chain.given("A", i["A"], "m", "isolator spacing O1O2 along x'")
    chain.given("B", i["B"], "m", "isolator spacing O1O4 along y'")
    for n in range(1, 5):
        chain.given(f"c{n}3", d[f"c{n}3"], "N/m", f"vertical stiffness of isolator O{n}")
    chain.step("M_sigma", "M + m", "kg", BC, "moving mass M + m (platform, product and rotor)")
    sign = "+" if i["regime"] == "below" else "-"
    chain.step("c0", f"M_sigma*omega**2 {sign} m*l*omega**2/u", "N/m", f"{BC} (3.8), (3.14), {i['regime']} resonance",
               "summed horizontal stiffness c0 = c1 = c2")
    chain.step("c3", "c13 + c23 + c33 + c43", "N/m", BC, "summed vertical stiffness")
    chain.step("a", "(c23 + c33)*A*M_sigma/(c3*m) - M*xi/m", "m", f"{BC} (3.9)", "exciter axis point along x'")
    chain.step("b", "(c33 + c43)*B*M_sigma/(c3*m) - M*eta/m", "m", f"{BC} (3.10)", "exciter axis point along y'")
    chain.step("c", "(omega**2*g*M_sigma - g*c0 - M*omega**4*zeta)/(omega**2*(c0 - M*omega**2))", "m",
               f"{BC} (3.11), ξ read as ζ", "exciter height above the support plane")
    chain.step("c31_41", "(omega**2*(M*eta + m*b) + b*(c0 - M_sigma*omega**2))/B", "N/m", f"{BC} (3.6)",
               "x-stiffness of the isolators at y' = B")
    chain.step("c11_21", "c0 - c31_41", "N/m", f"{BC} (3.8)", "x-stiffness of the isolators at y' = 0")
    chain.step("c22_32", "(omega**2*(M*xi + m*a) + a*(c0 - M_sigma*omega**2))/A", "N/m", f"{BC} (3.7)",
               "y-stiffness of the isolators at x' = A")
    chain.step("c12_42", "c0 - c22_32", "N/m", f"{BC} (3.8)", "y-stiffness of the isolators at x' = 0")
    chain.step("z", "-M_sigma*g/c3", "m", f"{BC} (3.1), static deflection (sign corrected)", "static deflection")
    chain.step("omega_t", "sqrt(c0/M_sigma)", "rad/s", f"{BC} (3.1)", "translational natural frequency")
    return chain


__all__ = ["platform_chain"]


#: The platform's coordinates: corner O1's displacement and the Krylov angles.
COORDINATES = ("x", "y", "z", "α", "β", "γ")
ROW_UNITS = {
    "M₀": ("kg, kg m", "kg, kg m", "kg, kg m", "kg m, kg m²", "kg m, kg m²", "kg m, kg m²"),
    "K_springs": ("N/m, N", "N/m, N", "N/m, N", "N, N m/rad", "N, N m/rad", "N, N m/rad"),
    "K₀": ("N/m, N", "N/m, N", "N/m, N", "N, N m/rad", "N, N m/rad", "N, N m/rad"),
}


def verification_system(scene):
    """The 6-DOF equations the verification solves for the scene's design (PeriodicSystem)."""
    from foundation_calc.solvers.platform.dynamics import periodic_system
    from foundation_calc.solvers.platform.verification import build

    return periodic_system(*build(scene.design(), scene.model()))


def verification_blocks(scene, doc: dict) -> tuple:
    """The mean matrices of the 6-DOF verification with their numbers, its modes solved on the
    sheet (K₀ v = p² M₀ v) and the forcing's harmonics: what the harmonic balance starts from."""
    import numpy as np

    from foundation_calc.output.report.block_methods import modes_of
    from foundation_calc.output.report.handcalc import Definitions
    from foundation_calc.output.report.harmonic_solve import matrix_table
    from foundation_calc.output.report.model import Paragraph, table
    from foundation_calc.output.report.numbers import column, figure

    system = verification_system(scene)
    M0, K0, Ks = system.mass[0].real, system.stiff[0].real, np.asarray(system.springs).real
    matrices = matrix_table("6-DOF verification: mean matrices about O1 (order x, y, z, α, β, γ)",
                            (("M₀", M0), ("K_springs", Ks), ("K₀", K0)), COORDINATES, ROW_UNITS)
    p, _, _ = modes_of(M0, K0, np.zeros_like(K0))
    names = [f["mode"] for f in doc["natural_frequencies"]]
    modes = table("Modes of the mean system: K₀ v = p² M₀ v (eigen-solve of M₀⁻¹K₀, gyroscopic terms left out)",
                  ("mode", "dominant motion", "p [rad/s]", "f [Hz]", "ω/p"),
                  [(str(j + 1), names[j], figure(w, 4), figure(w / (2 * np.pi), 4), figure(doc["speed"]["omega"] / w, 4))
                   for j, w in enumerate(p)], (False, False, True, True, True))
    live = [k for k in range(len(system.force)) if np.abs(system.force[k]).max() > 0.0]
    cols = [column([abs(system.force[k][j]) for k in live], 4) for j in range(6)]
    forcing = table("Forcing harmonics F_n (|F|: forces [N] along x, y, z, moments [N m] about O1), Ω = n·ω",
                    ("n", "Ω [rad/s]", "F_x", "F_y", "F_z", "M_α", "M_β", "M_γ"),
                    [(", ".join(str(int(v)) for v in system.force_keys[k]), figure(abs(float(system.frequencies(system.force_keys[k]))), 4),
                      *(c[i] for c in cols)) for i, k in enumerate(live)], (False, *(True,) * 7))
    note = Paragraph(
        "K₀ = K_springs + the weight's tilt and the rotors' mean terms; K_springs = Σ T_iᵀ diag(c_i1, c_i2, c_i3) T_i,"
        " T_i = [I, −[r_i]×], from the isolator table above. The harmonic balance (Equations used) couples these"
        " harmonics through the rotors' periodic terms; its steady state gives the verification's amplitudes.")
    terms = Definitions({
        "M₀, K₀": ("mean mass and stiffness matrices of the 6-DOF equations about O1", "SI"),
        "K_springs": ("stiffness matrix of the twelve isolator springs about O1", "N/m, N, N m/rad"),
        "F_n": ("complex amplitude of the forcing at harmonic vector n", "N, N m"),
        "p": ("natural frequency of the mean system", "rad/s"),
    })
    return (note, matrices, modes, forcing, terms)


__all__ += ["verification_blocks", "verification_system"]
