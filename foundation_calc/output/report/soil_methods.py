"""Hand calculations of the soil springs and damping by Gazetas', Pais & Kausel's formulas and by SP 26.13330.

The same chains as the Lysmer chain of :mod:`~foundation_calc.output.report.methods`, for the
two other elastic-soil methods, each printing the formulas of its solver with their table
numbers: :mod:`foundation_calc.solvers.soil.gazetas` (Gazetas 1991, Tables 1-2; the embedment
factors with the sidewall in contact over the full depth, d = D; the radiation dashpots of
:func:`~foundation_calc.solvers.soil.impedance.footing_impedance` at ω = 0, the springs the
sheet's checks use) and :mod:`foundation_calc.solvers.soil.sp26`. ``tests/test_report_methods.py``
compares every end value with the solvers'.
"""

from __future__ import annotations

from foundation_calc.output.report.handcalc import SYMBOLS, Chain
from foundation_calc.solvers.constants import GRAVITY

RHW = "[RHW] ch. 10; [DR] ch. 5"
#: The source of C = 2 ξ √(K m) of a block's dashpot at O.
DASHPOT = "[RHW] ch. 10, C = 2 ξ √(K m)"
GA = "[Ga] Table 1"
GA2 = "[Ga] Table 2 (d = D)"
SP26 = "[SP26]"
PK = "[PK]; [NIST] Table 2-3a"
PK2 = "[PK]; [NIST] Table 2-2a"
PK2B = "[PK]; [NIST] Table 2-2b (d = D)"


def dashpot(chain: Chain, C: str, xi: str, K: str, m: str, unit: str, source: str, meaning: str) -> float:
    """Add the dashpot ``C`` = 2 ξ √(K m) of one motion to ``chain`` from its damping ratio ``xi``,
    spring ``K`` and mass (or moment of inertia) ``m`` ([RHW] ch. 10), the form every soil method's
    chain and the solvers use (:func:`~foundation_calc.solvers.supports.plane_footing.plane_dashpots`)."""
    return chain.step(C, f"2*{xi}*sqrt({K}*{m})", unit, source, meaning)


#: Lysmer's and Hall's analogs ([RHW] ch. 10, :func:`~foundation_calc.solvers.soil.lysmer.lysmer_springs`)
#: and Reissner-Sagoci's torsion (:func:`~foundation_calc.solvers.soil.torsion.lysmer_torsion`), each
#: motion as (who, spring, mass ratio, damping ratio): ``{r}`` the radius of the circle of the base's
#: area (or of its second moment about the motion's axis), ``{m}`` the mass (or moment of inertia
#: about that axis), ``{B}`` the mass ratio's symbol. The crank takes the plane's three motions once,
#: the block each plane's and the torsion.
LYSMER = {
    "vertical": ("Lysmer", "4*G*{r}/(1 - nu)", "(1 - nu)*{m}/(4*rho*{r}**3)", "0.425/sqrt({B}) + xi_m"),
    "sliding": ("Hall", "32*(1 - nu)*G*{r}/(7 - 8*nu)", "(7 - 8*nu)*{m}/(32*(1 - nu)*rho*{r}**3)", "0.2875/sqrt({B}) + xi_m"),
    "rocking": ("Hall", "8*G*{r}**3/(3*(1 - nu))", "3*(1 - nu)*{m}/(8*rho*{r}**5)", "0.15/((1 + {B})*sqrt({B})) + xi_m"),
    "torsion": ("Reissner-Sagoci", "16*G*{r}**3/3", "{m}/(rho*{r}**5)", "0.5/(1 + 2*{B}) + xi_m"),
}

#: Radii of the circles of the base's area and of its second moments, L along x, B along y ([RHW] ch. 10).
LYSMER_RADII = {
    "area": "sqrt(B*L/pi)",
    "about y": "(B*L**3/(3*pi))**0.25",
    "about x": "(L*B**3/(3*pi))**0.25",
    "polar": "(L*B*(L**2 + B**2)/(6*pi))**0.25",
}


def lysmer_spring(chain: Chain, motion: str, K: str, r: str, meaning: str) -> float:
    """Add the spring ``K`` of ``motion`` (:data:`LYSMER`) on the radius ``r``."""
    who, spring, *_ = LYSMER[motion]
    return chain.step(K, spring.format(r=r), "N m/rad" if motion in ("rocking", "torsion") else "N/m", f"{RHW} ({who})",
                      meaning)


def lysmer_ratio(chain: Chain, motion: str, B: str, xi: str, r: str, m: str, meanings: tuple[str, str]) -> float:
    """Add the mass (or inertia) ratio ``B`` and the damping ratio ``xi`` (radiation + material ξ_m) of
    ``motion`` (:data:`LYSMER`) on the radius ``r`` and the mass or moment of inertia ``m``."""
    *_, ratio, damping = LYSMER[motion]
    chain.step(B, ratio.format(r=r, m=m), "-", RHW, meanings[0])
    return chain.step(xi, damping.format(B=B), "-", RHW, meanings[1])


#: SP 26.13330's coefficient of elastic uniform compression from the deformation modulus, the
#: springs as its multiples (C_x = 0.7 C_z, C_φ = 2 C_z) and the damping ratios from the mean
#: static pressure p_m [kPa] ([SP26]; :mod:`foundation_calc.solvers.soil.sp26`); ``{c}`` the
#: coefficient's symbol, ``{m}`` the total mass's.
SP26_FORMULAS = {
    "c_z": "b_sp*E*(1 + sqrt(A10/A))",
    "sliding": "0.7*{c}*A",
    "vertical": "{c}*A",
    "rocking": "2*{c}*{I}",
    "p_m": "{m}*g/A/1000",
    "xi_z": "2/sqrt(p_m)",
    "xi_sliding": "0.6*xi_z",
    "xi_rocking": "0.5*xi_z",
}


def soil_givens(chain: Chain, scene) -> None:
    """The half-space soil's and the block's inputs of a springs chain (Lysmer, Gazetas)."""
    f, s = scene.foundation, scene.soil
    L, B = f.dimensions
    M_tot = scene.total_mass
    chain.given("G", s.G, "Pa", "shear modulus of the soil")
    chain.given("rho", s.density, "kg/m³", "mass density of the soil")
    chain.given("nu", s.poisson, "-", "Poisson's ratio of the soil")
    chain.given("L", L, "m", "base length in the plane of motion")
    chain.given("B", B, "m", "base width")
    chain.given("M_tot", M_tot, "kg", "total vibrating mass")
    chain.given("I_0", f.moment_of_inertia + M_tot * f.cog_height**2, "kg m²", "moment of inertia about the base axis, I_c + M_tot h²")
    chain.given("xi_m", s.material_damping or 0.0, "-", "material damping ratio of the soil")


def gazetas_springs_chain(scene) -> Chain:
    """Gazetas' static springs (embedment factors when embedded) and the low-frequency damping."""
    L, B = scene.foundation.dimensions
    D = scene.foundation.embedment or 0.0
    along_long = L >= B
    chain = Chain("Soil springs and radiation damping: Gazetas' formulas (soil.method = \"gazetas\")")
    soil_givens(chain, scene)
    chain.step("Lh", "max(L, B)/2", "m", GA, "longer half-side of the base")
    chain.step("Bh", "min(L, B)/2", "m", GA, "shorter half-side of the base")
    chain.step("chi", "Bh/Lh", "-", GA, "aspect ratio B'/L' of the base")
    chain.step("I_b", "B*L**3/12", "m⁴", GA, "second moment of the base about the rocking axis")
    chain.step("K_zs", "2*G*Lh/(1 - nu)*(0.73 + 1.54*chi**0.75)", "N/m", GA, "static vertical spring of the surface base")
    chain.step("K_y", "2*G*Lh/(2 - nu)*(2 + 2.5*chi**0.85)", "N/m", GA, "static horizontal spring along the short side")
    if along_long:
        chain.step("K_hs", "K_y - 0.2*G*Lh*(1 - chi)/(0.75 - nu)", "N/m", f"{GA} (K_x, L along the long side)",
                   "static horizontal spring in the plane of motion")
        chain.step("K_phis", "3*G/(1 - nu)*I_b**0.75*(Lh/Bh)**0.15", "N m/rad", f"{GA} (K_ry, rocking about the short axis)",
                   "static rocking spring of the surface base")
    else:
        chain.step("K_hs", "K_y", "N/m", f"{GA} (K_y, L along the short side)", "static horizontal spring in the plane of motion")
        chain.step("K_phis", "G/(1 - nu)*I_b**0.75*(Lh/Bh)**0.25*(2.4 + 0.5*chi)", "N m/rad",
                   f"{GA} (K_rx, rocking about the long axis)", "static rocking spring of the surface base")
    if D > 0.0:
        chain.given("D", D, "m", "embedment depth (sidewall in contact over all of it)")
        chain.step("A_w", "2*D*(2*Lh + 2*Bh)", "m²", GA2, "sidewall area in contact")
        chain.step("eta_z", "(1 + D/(21*Bh)*(1 + 1.3*chi))*(1 + 0.2*(A_w/(4*Bh*Lh))**(2/3))", "-", GA2,
                   "embedment factor of the vertical spring")
        if along_long:
            chain.step("eta_h", "(1 + 0.15*sqrt(D/Bh))*(1 + 0.52*(D/2*A_w/(Lh*Bh**2))**0.4)", "-", f"{GA2}, η_x",
                       "embedment factor of the horizontal spring")
            chain.step("eta_phi", "1 + 0.92*(D/Lh)**0.6*(1.5 + (D/Lh)**1.9)", "-", f"{GA2}, η_ry",
                       "embedment factor of the rocking spring")
        else:
            chain.step("eta_h", "(1 + 0.15*sqrt(D/Bh))*(1 + 0.52*(D/2*A_w/(Bh*Lh**2))**0.4)", "-", f"{GA2}, η_y",
                       "embedment factor of the horizontal spring")
            chain.step("eta_phi", "1 + 1.26*(D/Bh)*(1 + (D/Bh)*chi**0.5)", "-", f"{GA2}, η_rx",
                       "embedment factor of the rocking spring")
        chain.step("K_z", "eta_z*K_zs", "N/m", GA2, "vertical base spring")
        chain.step("K_x", "eta_h*K_hs", "N/m", GA2, "horizontal base spring")
        chain.step("K_phi", "eta_phi*K_phis", "N m/rad", GA2, "rocking base spring")
    else:
        chain.given("D", 0.0, "m", "embedment depth (surface base)")
        chain.step("K_z", "K_zs", "N/m", GA, "vertical base spring")
        chain.step("K_x", "K_hs", "N/m", GA, "horizontal base spring")
        chain.step("K_phi", "K_phis", "N m/rad", GA, "rocking base spring")
    return _radiation(chain)


def _radiation(chain: Chain) -> Chain:
    """Gazetas' radiation dashpots at ω = 0 and the damping ratios, on the springs K_z, K_x, K_φ
    the chain has found (Gazetas' or Pais & Kausel's)."""
    chain.step("V_s", "sqrt(G/rho)", "m/s", GA, "shear wave velocity")
    chain.step("V_La", "3.4*V_s/(pi*(1 - nu))", "m/s", GA, "Lysmer's analog wave velocity")
    chain.step("C_z", "rho*(V_La*B*L + V_s*2*D*(L + B))", "N s/m", f"{GA}, Table 2", "vertical radiation dashpot (base and sidewalls)")
    chain.step("C_x", "rho*(V_s*B*L + V_s*2*L*D + V_La*2*B*D)", "N s/m", f"{GA}, Table 2", "horizontal radiation dashpot (base and sidewalls)")
    chain.step("C_phi", "rho*4/3*D**3*(V_La*B/2 + V_s*L/2)", "N m s/rad", f"{GA}, Table 2 at ω = 0 (the base radiates no rocking at rest)",
               "rocking radiation dashpot at low frequency")
    chain.step("xi_z", "C_z/(2*sqrt(K_z*M_tot)) + xi_m", "-", GA, "vertical damping ratio (radiation + material)")
    chain.step("xi_x", "C_x/(2*sqrt(K_x*M_tot)) + xi_m", "-", GA, "horizontal damping ratio (radiation + material)")
    chain.step("xi_phi", "C_phi/(2*sqrt(K_phi*I_0)) + xi_m", "-", GA, "rocking damping ratio (radiation + material)")
    return chain


def pais_kausel_springs_chain(scene) -> Chain:
    """Pais & Kausel's static springs (embedment factors when embedded) and Gazetas' low-frequency
    damping (:mod:`foundation_calc.solvers.soil.pais_kausel`)."""
    L, B = scene.foundation.dimensions
    D = scene.foundation.embedment or 0.0
    chain = Chain("Soil springs and radiation damping: Pais & Kausel's formulas (soil.method = \"pais_kausel\")")
    soil_givens(chain, scene)
    chain.given("D", D, "m", "embedment depth (sidewall in contact over all of it)" if D > 0.0 else "embedment depth (surface base)")
    chain.step("Lh", "max(L, B)/2", "m", PK2, "longer half-side of the base")
    chain.step("Bh", "min(L, B)/2", "m", PK2, "shorter half-side of the base")
    chain.step("r", "Lh/Bh", "-", PK2, "aspect ratio L'/B' of the base")
    chain.step("I_b", "B*L**3/12", "m⁴", GA, "second moment of the base about the rocking axis")
    chain.step("eta_z", "1 + (0.25 + 0.25/r)*(D/Bh)**0.8", "-", PK2B, "embedment factor of the vertical spring")
    chain.step("eta_h", "1 + (0.33 + 1.34/(1 + r))*(D/Bh)**0.8", "-", PK2B, "embedment factor of the horizontal spring")
    chain.step("K_z", "eta_z*G*Bh/(1 - nu)*(3.1*r**0.75 + 1.6)", "N/m", PK2, "vertical base spring")
    if L >= B:
        chain.step("K_x", "eta_h*G*Bh/(2 - nu)*(6.8*r**0.65 + 2.4)", "N/m", f"{PK2} (K_x, L along the long side)",
                   "horizontal base spring")
        chain.step("eta_phi", "1 + D/Bh + 1.6/(0.35 + r**4)*(D/Bh)**2", "-", f"{PK2B}, η_ry", "embedment factor of the rocking spring")
        chain.step("K_phi", "eta_phi*G*Bh**3/(1 - nu)*(3.73*r**2.4 + 0.27)", "N m/rad",
                   f"{PK2} (K_ry, rocking about the short axis)", "rocking base spring")
    else:
        chain.step("K_x", "eta_h*G*Bh/(2 - nu)*(6.8*r**0.65 + 0.8*r + 1.6)", "N/m", f"{PK2} (K_y, L along the short side)",
                   "horizontal base spring")
        chain.step("eta_phi", "1 + D/Bh + 1.6/(0.35 + r)*(D/Bh)**2", "-", f"{PK2B}, η_rx", "embedment factor of the rocking spring")
        chain.step("K_phi", "eta_phi*G*Bh**3/(1 - nu)*(3.2*r + 0.8)", "N m/rad", f"{PK2} (K_rx, rocking about the long axis)",
                   "rocking base spring")
    return _radiation(chain)


#: Names of the static chain that the chains at a frequency take as given.
STATIC_GIVENS = ("G", "rho", "nu", "L", "B", "D", "M_tot", "I_0", "xi_m", "Lh", "Bh", "I_b", "V_s", "V_La", "K_z", "K_x",
                 "K_phi", "C_z", "C_x")


def gazetas_at(chain: Chain, scene, static: Chain, omega: float, meaning: str, dashpots: bool = True, name: str = "omega") -> Chain:
    """Add to ``chain`` Gazetas' springs (and, with ``dashpots``, the dashpots and damping ratios)
    at the circular frequency ``omega`` [rad/s] (called ``name`` in the formulas): Pais & Kausel's stiffness modifiers and the
    rocking radiation's rise with frequency (``impedance`` module docstring), from the static
    chain's numbers."""
    L, B = scene.foundation.dimensions
    about_short = L >= B
    for given in STATIC_GIVENS:
        meaning_of, unit = static.nomenclature[SYMBOLS.get(given, given)]
        chain.given(given, static.values[given], unit, meaning_of)
    chain.given(name, omega, "rad/s", meaning)
    chain.step("a_d", f"{name}*Bh/V_s", "-", PK, "dimensionless frequency")
    chain.step("r", "Lh/Bh", "-", PK, "aspect ratio L'/B' of the base")
    chain.step("k_z", "1 - (0.4 + 0.2/r)*a_d**2/(10/(1 + 3*(r - 1)) + a_d**2)", "-", PK, "dynamic modifier of the vertical spring")
    if about_short:
        chain.step("k_phi", "1 - 0.55*a_d**2/(0.6 + 1.4/r**3 + a_d**2)", "-", f"{PK}, k_ry",
                   "dynamic modifier of the rocking spring")
    else:
        chain.step("k_phi", "1 - (0.55 + 0.01*sqrt(r - 1))*a_d**2/(2.4 - 0.4/r**3 + a_d**2)", "-", f"{PK}, k_rx",
                   "dynamic modifier of the rocking spring")
    chain.step("K_zw", "k_z*K_z", "N/m", PK, "vertical spring at ω")
    chain.step("K_xw", "K_x", "N/m", f"{PK} (k_x = 1)", "horizontal spring at ω")
    chain.step("K_phiw", "k_phi*K_phi", "N m/rad", PK, "rocking spring at ω")
    if not dashpots:
        return chain
    if about_short:
        chain.step("c_r", "1.8/(1 + 1.75*(r - 1))", "-", f"{PK}, β_yy shape", "frequency constant of the rocking radiation")
    else:
        chain.step("c_r", "2.2 - 0.4/r**3", "-", f"{PK}, β_xx shape", "frequency constant of the rocking radiation")
    chain.step("c_rw", "a_d**2/(c_r + a_d**2)", "-", "[Ga] Table 1 with the frequency shape of [PK]", "rocking radiation coefficient at ω")
    chain.step("C_phiw", "rho*((V_La*I_b + V_s*(2*B*D*L**2/4 + D*L**3/6))*c_rw + 4/3*D**3*(V_La*B/2 + V_s*L/2))", "N m s/rad",
               f"{GA}, Table 2", "rocking radiation dashpot at ω (base and sidewalls)")
    chain.step("xi_zw", "C_z/(2*sqrt(K_zw*M_tot)) + xi_m", "-", GA, "vertical damping ratio at ω")
    chain.step("xi_xw", "C_x/(2*sqrt(K_xw*M_tot)) + xi_m", "-", GA, "horizontal damping ratio at ω")
    chain.step("xi_phiw", "C_phiw/(2*sqrt(K_phiw*I_0)) + xi_m", "-", GA, "rocking damping ratio at ω")
    return chain


def gazetas_dynamic_chain(scene, static: Chain) -> Chain:
    """Gazetas' springs and dashpots at the operating speed ω (:func:`gazetas_at`); the exact
    harmonic balance and the first harmonic take them at ω, harmonic n at n ω by the same
    formulas (:mod:`~foundation_calc.output.report.gazetas_frequencies`)."""
    springs = "Pais & Kausel's springs and Gazetas'" if scene.soil.method_used == "pais_kausel" else "Gazetas' springs and"
    chain = Chain(f"{springs} dashpots at the operating speed ω (frequency-dependent soil)")
    return gazetas_at(chain, scene, static, scene.speed.omega_rad_s, "operating speed (circular frequency of the first harmonic)")


def sp26_givens(chain: Chain, soil) -> None:
    """SP 26.13330's inputs: the deformation modulus, the soil class's b₀, A₁₀ and g."""
    from foundation_calc.solvers.soil.sp26 import A10, B0_BY_CLASS

    chain.given("E", soil.deformation_modulus, "Pa", "static deformation modulus of the soil")
    chain.given("b_sp", B0_BY_CLASS[soil.soil_class], "1/m", f"coefficient of the soil class ({soil.soil_class})")
    chain.given("A10", A10, "m²", "reference area of the code's formula")
    chain.given("g", GRAVITY, "m/s²", "acceleration of gravity")


def sp26_springs_chain(scene) -> Chain:
    """The springs and damping ratios of SP 26.13330 from the static deformation modulus."""
    f, s = scene.foundation, scene.soil
    chain = Chain("Soil springs and damping by SP 26.13330 (soil.method = \"sp26\")")
    sp26_givens(chain, s)
    chain.given("A", f.base_area, "m²", "area of the base")
    chain.given("I1", f.base_second_moment, "m⁴", "second moment of the base area about its axis normal to the plane")
    chain.given("M_tot", scene.total_mass, "kg", "total vibrating mass")
    chain.step("C_z", SP26_FORMULAS["c_z"], "N/m³", SP26, "coefficient of elastic uniform compression")
    chain.step("K_z", SP26_FORMULAS["vertical"].format(c="C_z"), "N/m", SP26, "vertical base spring")
    chain.step("K_x", SP26_FORMULAS["sliding"].format(c="C_z"), "N/m", f"{SP26}, C_x = 0.7 C_z", "horizontal base spring")
    chain.step("K_phi", SP26_FORMULAS["rocking"].format(c="C_z", I="I1"), "N m/rad", f"{SP26}, C_φ = 2 C_z", "rocking base spring")
    chain.step("p_m", SP26_FORMULAS["p_m"].format(m="M_tot"), "kPa", SP26, "mean static pressure under the base")
    chain.step("xi_z", SP26_FORMULAS["xi_z"], "-", f"{SP26} (p_m in kPa)", "vertical damping ratio")
    chain.step("xi_x", SP26_FORMULAS["xi_sliding"], "-", SP26, "horizontal damping ratio")
    chain.step("xi_phi", SP26_FORMULAS["xi_rocking"], "-", SP26, "rocking damping ratio")
    return chain


def gazetas_chains(scene) -> list[Chain]:
    """Gazetas' (or, for ``soil.method = "pais_kausel"``, Pais & Kausel's) static springs and, the
    soil being frequency-dependent, those at the speed ω."""
    static = (pais_kausel_springs_chain if scene.soil.method_used == "pais_kausel" else gazetas_springs_chain)(scene)
    return [static, gazetas_dynamic_chain(scene, static)]


__all__ = ["DASHPOT", "LYSMER", "LYSMER_RADII", "RHW", "SP26_FORMULAS", "dashpot", "gazetas_at", "gazetas_chains", "gazetas_dynamic_chain", "gazetas_springs_chain", "pais_kausel_springs_chain",
           "lysmer_ratio", "lysmer_spring", "soil_givens", "sp26_givens",
           "sp26_springs_chain"]
