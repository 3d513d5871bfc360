"""The vertical amplitudes of the first approximation as a hand calculation, as the code evaluates them.

Source: Krichever & Makarov [KM], Eqs. (4.11), (4.14), corrected (μ once), with the slider lumped
into the rod ([KM], last paragraph; :func:`~foundation_calc.solvers.crank.mechanism.lump_slider`)
and the base's vertical dashpot C_z (:mod:`~foundation_calc.solvers.crank.first_approximation`)::

    m = m_rod + m1,   l' = (m_rod l'_rod + m1 l)/m,   μ = m/M_tot,   λ = r/l,   ζ_z = C_z/M_tot
    |y1| = μ r ω² / |k0² − ω² + i ω ζ_z|,   |y2| = μ (l'/l) λ r ω² / |k0² − 4ω² + 2i ω ζ_z|

so the sheet's first-approximation y1, y2 follow from its printed inputs (a frequency-dependent
soil takes K_z and C_z at n ω for harmonic n, as the amplitudes check does).
"""

from __future__ import annotations

from foundation_calc.output.report.handcalc import Chain
from foundation_calc.solvers.constants import GRAVITY

KM = "[KM]"


def first_approximation_chain(scene) -> Chain:
    """The chain m, l', μ, λ → |y1|, |y2| of the scene's mechanism (``scene.mechanism`` not None);
    an undamped design at a resonance of the vertical mode has no y_n (the sheet says resonant), nor
    one at a harmonic's soil where the first approximation does not apply (the chain's title says
    why, :func:`~foundation_calc.solvers.crank.closed_form.require_first_approximation`)."""
    from foundation_calc.errors import NotApplicable
    from foundation_calc.solvers.crank.closed_form import design_first_approximation

    omega = scene.speed.omega_rad_s
    chain = Chain("First approximation: the slider lumped into the rod, the base's dashpot kept; the forcing to"
                  " leading order in λ")
    _mechanism_steps(chain, scene)
    dependent = scene.support().frequency_dependent
    for n, force in ((1, "mu*r*omega**2"), (2, "mu*(l1/l)*lam*r*omega**2")):
        design = scene.design(n * omega if dependent else 0.0)
        at = ("w" if n == 1 else f"{n}w") if dependent else ""  # printed K_z(ω), K_z(2ω), ...
        if n == 1 or dependent:
            where = f" at {n} ω" if dependent else ""
            chain.given(f"K_z{at}", design.c * design.S, "N/m", f"vertical base spring{where}")
            chain.given(f"C_z{at}", design.C_z, "N s/m", f"vertical base dashpot{where}")
            chain.step(f"k0{at}", f"sqrt(K_z{at}/M_tot)", "rad/s", f"{KM} (4.5)", f"vertical natural frequency{where}")
            chain.step(f"zeta_z{at}", f"C_z{at}/M_tot", "1/s", "base dashpot over the total mass", f"vertical damping coefficient{where}")
        try:
            if bool(design_first_approximation(design).resonant):
                break
        except NotApplicable as why:
            chain.title += f"; y{n} not applicable: {why.message}"
            break
        w = "omega" if n == 1 else f"({n}*omega)"
        chain.step(
            f"y{n}", f"{force}/sqrt((k0{at}**2 - {w}**2)**2 + ({w}*zeta_z{at})**2)", "m",
            f"{KM} (4.11), (4.14) corrected, damped", f"amplitude of the vertical harmonic {n} of C (first approximation)",
        )
    _forcing_steps(chain, scene)
    return chain


def forcing_chain(scene) -> Chain:
    """The mechanism's forcing to leading order in λ without the first approximation's amplitudes,
    which do not apply on a support coupling sway with rocking
    (:data:`~foundation_calc.checks.amplitudes.approximations.FIRST_NOT_APPLICABLE`)."""
    from foundation_calc.checks.amplitudes.approximations import FIRST_NOT_APPLICABLE

    chain = Chain(f"The mechanism's forcing to leading order in λ; the first approximation (4.14) is {FIRST_NOT_APPLICABLE}")
    _mechanism_steps(chain, scene)
    _forcing_steps(chain, scene)
    return chain


def _mechanism_steps(chain: Chain, scene) -> None:
    """M_tot and the mechanism's inputs, then m, l', μ, λ with the slider lumped into the rod."""
    mech = scene.mechanism
    chain.given("M_tot", scene.total_mass, "kg", "total vibrating mass (block, machine, rod and slider)")
    chain.given("m_rod", mech.rod_mass, "kg", "connecting-rod mass (mechanism.rod_mass)")
    chain.given("m1", mech.slider_mass, "kg", "mass carried by the slider (mechanism.slider_mass)")
    chain.given("l", mech.rod_length, "m", "connecting-rod length")
    chain.given("l1_rod", mech.rod_cog_to_crank_pin, "m", "rod's centre of mass to the crank pin (mechanism.rod_cog_to_crank_pin)")
    chain.given("r", mech.crank_radius, "m", "crank radius")
    chain.given("omega", scene.speed.omega_rad_s, "rad/s", "operating speed")
    chain.step("m", "m_rod + m1", "kg", f"{KM}, last paragraph", "moving mass: rod and slider")
    chain.step("l1", "(m_rod*l1_rod + m1*l)/m", "m", f"{KM}, last paragraph (slider at M'')",
               "centre of mass of rod and slider to the crank pin")
    chain.step("mu", "m/M_tot", "-", f"{KM} §1", "moving-mass ratio")
    chain.step("lam", "r/l", "-", f"{KM} §1", "crank-to-rod ratio")


def _forcing_steps(chain: Chain, scene) -> None:
    """The mechanism's forcing at ω and 2ω to leading order in λ: (4.11)'s right sides times
    M_tot μ = m (F_y, F_x) and I_c μ = m ρ1² (M_θ). The sheet's F_n are the exact Fourier
    coefficients; these differ from them by O(λ²) (about 1.5 % at 2ω for λ = 0.25)."""
    mech = scene.mechanism
    chain.given("rho_rod", mech.rod_radius_of_gyration, "m", "rod's radius of gyration about its centre of mass")
    chain.given("a", mech.crank_axis_to_cog, "m", "crank axis A to C along the guide, positive when A is above C")
    chain.given("g_s", GRAVITY if mech.drive_on_foundation else 0.0, "m/s²",
                "g when the drive's reaction acts on the foundation (mechanism.drive_on_foundation), else 0")
    chain.step("l2", "l - l1", "m", f"{KM} §1", "centre of mass of rod and slider to the slider pin")
    chain.step("rho", "sqrt((m_rod*(rho_rod**2 + (l1_rod - l1)**2) + m1*(l - l1)**2)/m)", "m",
               f"{KM}, last paragraph (parallel axes)", "radius of gyration of rod and slider about their centre of mass")
    chain.step("kappa", "l1*l2 - rho**2", "m²", f"{KM} (2.6)", "rod-couple coefficient")
    chain.step("F_y1", "m*r*omega**2", "N", f"{KM} (4.11) × M_tot μ",
               "vertical force at ω, F_y1 cos ωt (y down; phase lag 0°)")
    chain.step("F_y2", "m*(l1/l)*lam*r*omega**2", "N", f"{KM} (4.11) × M_tot μ",
               "vertical force at 2ω, F_y2 cos 2ωt (phase lag 0°)")
    chain.step("F_x1", "-(l2/l)*m*r*omega**2", "N", f"{KM} (4.11) × M_tot μ",
               "horizontal force at ω, F_x1 sin ωt (phase lag 90° when positive, −90° when negative)")
    chain.step("M_th1", "m*(-(l2/l)*r*(a*omega**2 + g_s) + kappa*lam*omega**2*(1 - lam**2)*(1 + 9*lam**2/8))", "N m",
               f"{KM} (4.12) corrected × I_c μ", "moment at ω, M_θ1 sin ωt (phase lag 90° when positive, −90° when negative)")


__all__ = ["first_approximation_chain", "forcing_chain"]
