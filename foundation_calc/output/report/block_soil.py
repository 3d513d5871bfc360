"""The block's six soil springs and dashpots at O as hand calculations, and those each order used.

The block takes the soil's springs of :func:`~foundation_calc.solvers.supports.footing_springs.six_springs`:
a plane method twice (the plane of x: sliding x, rocking about y, L in the plane; the plane of y:
sliding y, rocking about x, B in the plane) and torsion about z, then each dashpot
C_i = 2 ξ_i √(K_i m_i) (m_i the total mass, or the moment of inertia J_x, J_y, J_z about the axis
through O; :meth:`~foundation_calc.scenes.block.BlockScene.soil_impedance`). The chains print
each formula with its values (Lysmer's analogs with Reissner-Sagoci's torsion, Barkan's
coefficients, SP 26.13330: the formulas of :mod:`~foundation_calc.output.report.soil_methods`
that the crank's plane chains print too; Gazetas' and Pais & Kausel's static springs through the
crank's own chains, once per plane); on a frequency-dependent soil a
table gives the six springs and dashpots each order n of each machine was solved with, K(nω) and
C(nω) of the solver, with the chain at every such frequency. ``tests/test_report_block_soil.py``
recomputes the printed springs from the printed inputs and one order's response from the printed
K(nω), C(nω), M and Q_n.
"""

from __future__ import annotations

from types import SimpleNamespace

import numpy as np

from foundation_calc.output.report.handcalc import SYMBOLS, Chain, Columns
from foundation_calc.output.report.model import Paragraph, Table, table
from foundation_calc.output.report.numbers import column
from foundation_calc.output.report.soil_methods import (DASHPOT, LYSMER_RADII, RHW, SP26_FORMULAS, dashpot, lysmer_ratio,
                                                        lysmer_spring, sp26_givens)

BA = "[KM] (3.2)-(3.4); [Ba]"
SP26 = "[SP26]"
PK = "[PK]; [NIST] Table 2-3a"
#: The six springs' and dashpots' names at O, in the order of q.
SPRINGS = ("K_x", "K_y", "K_z", "K_rx", "K_ry", "K_rz")
DASHPOTS = ("C_x", "C_y", "C_z", "C_rx", "C_ry", "C_rz")
RATIOS = ("xi_x", "xi_y", "xi_z", "xi_rx", "xi_ry", "xi_rz")
UNITS_K = ("N/m", "N/m", "N/m", "N m/rad", "N m/rad", "N m/rad")
UNITS_C = ("N s/m", "N s/m", "N s/m", "N m s/rad", "N m s/rad", "N m s/rad")
MASSES = ("M", "M", "M", "J_x", "J_y", "J_z")
#: At most this many orders side by side (the page's width).
MOST_COLUMNS = 4


def _givens(chain: Chain, footing, model) -> None:
    """The block's base and masses about O (every method's chain starts from them)."""
    L, B = footing.base
    m = np.diagonal(model.M)
    chain.given("L", L, "m", "base length along x")
    chain.given("B", B, "m", "base width along y")
    chain.given("M", m[0], "kg", "total mass of the block and the machines")
    for name, value, axis in zip(("J_x", "J_y", "J_z"), m[3:], "xyz"):
        chain.given(name, value, "kg m²", f"moment of inertia of the block and the machines about the axis {axis} through O (M's diagonal)")


MEANINGS = ("sliding spring along x", "sliding spring along y", "vertical spring", "rocking spring about x",
            "rocking spring about y", "torsional spring about z")


def _springs(chain: Chain, formulas: tuple[str, ...], sources: tuple[str, ...]) -> None:
    """The six springs at O, K_x ... K_rz, by the method's ``formulas``."""
    for K, formula, unit, source, meaning in zip(SPRINGS, formulas, UNITS_K, sources, MEANINGS):
        chain.step(K, formula, unit, source, meaning)


def _dashpots(chain: Chain) -> None:
    """C_i = 2 ξ_i √(K_i m_i) of every motion, as the solver makes them."""
    for C, xi, K, m, unit, motion in zip(DASHPOTS, RATIOS, SPRINGS, MASSES, UNITS_C, MEANINGS):
        dashpot(chain, C, xi, K, m, unit, DASHPOT, f"dashpot at O: {motion.replace(' spring', '')}")


def _half_space(chain: Chain, footing) -> None:
    s = footing.soil
    chain.given("rho", s.density, "kg/m³", "mass density of the soil")
    if s.shear_modulus is None:
        chain.given("V_s", s.shear_wave_velocity, "m/s", "shear wave velocity of the soil")
        chain.step("G", "rho*V_s**2", "Pa", "[RHW] ch. 2", "shear modulus of the soil")
    else:
        chain.given("G", s.G, "Pa", "shear modulus of the soil")
    chain.given("nu", s.poisson, "-", "Poisson's ratio of the soil")
    chain.given("xi_m", s.material_damping or 0.0, "-", "material damping ratio of the soil")


def lysmer_chain(footing, model) -> Chain:
    """Lysmer's and Hall's analogs in both vertical planes and Reissner-Sagoci's torsion
    (:func:`~foundation_calc.solvers.soil.lysmer.lysmer_springs`, :func:`~foundation_calc.solvers.soil.torsion.lysmer_torsion`)."""
    chain = Chain("Block soil springs and dashpots at O: Lysmer's, Hall's and Reissner-Sagoci's analogs (soil.method = \"lysmer\")")
    _givens(chain, footing, model)
    _half_space(chain, footing)
    for r, radius, about in (("r0", "area", "area"), ("r0y", "about y", "second moment about y"),
                             ("r0x", "about x", "second moment about x"), ("r0t", "polar", "polar second moment")):
        chain.step(r, LYSMER_RADII[radius], "m", RHW, f"radius of the circle of the base's {about}")
    lysmer_spring(chain, "sliding", "K_x", "r0", MEANINGS[0])
    chain.step("K_y", "K_x", "N/m", f"{RHW} (Hall)", MEANINGS[1])
    for motion, K, r, meaning in zip(("vertical", "rocking", "rocking", "torsion"), SPRINGS[2:], ("r0", "r0x", "r0y", "r0t"),
                                     MEANINGS[2:]):
        lysmer_spring(chain, motion, K, r, meaning)
    lysmer_ratio(chain, "sliding", "B_x", "xi_x", "r0", "M", ("sliding mass ratio", "sliding damping ratio along x (radiation + material)"))
    chain.step("xi_y", "xi_x", "-", RHW, "sliding damping ratio along y")
    lysmer_ratio(chain, "vertical", "B_z", "xi_z", "r0", "M", ("vertical mass ratio", "vertical damping ratio (radiation + material)"))
    for axis in "xy":
        lysmer_ratio(chain, "rocking", f"B_r{axis}", f"xi_r{axis}", f"r0{axis}", f"J_{axis}",
                     (f"rocking inertia ratio about {axis}", f"rocking damping ratio about {axis}"))
    lysmer_ratio(chain, "torsion", "B_t", "xi_rz", "r0t", "J_z", ("torsional inertia ratio", "torsional damping ratio (radiation + material)"))
    _dashpots(chain)
    return chain


def _base(chain: Chain, source: str) -> None:
    """The base's area A and second moments I_x, I_y."""
    chain.step("A", "L*B", "m²", source, "area of the base")
    chain.step("I_x", "L*B**3/12", "m⁴", source, "second moment of the base about x")
    chain.step("I_y", "B*L**3/12", "m⁴", source, "second moment of the base about y")


def coefficients_chain(footing, model) -> Chain:
    """Barkan's coefficients times the base's area and second moments (``six_springs``)."""
    from foundation_calc.solvers.supports.footing_springs import BARKAN_TORSION_RATIO

    s = footing.soil
    chain = Chain("Block soil springs and dashpots at O from Barkan's coefficients (soil.method = \"coefficients\")")
    _givens(chain, footing, model)
    chain.given("c_z", s.c_z, "N/m³", "coefficient of elastic uniform compression")
    chain.given("c_x", s.c_x, "N/m³", "coefficient of elastic uniform shear")
    chain.given("c_phi", s.c_z if s.c_phi is None else s.c_phi, "N/m³", "coefficient of non-uniform compression (c_z unless soil.c_phi is given)")
    xi = list(s.damping or (0.0, 0.0, 0.0))
    for name, value in zip(("xi_z", "xi_x", "xi_rx"), xi[:3]):
        chain.given(name, value, "-", "damping ratio given (soil.damping)")
    if s.c_psi is None:
        chain.given("k_psi", BARKAN_TORSION_RATIO, "-", "Barkan's ratio c_ψ/c_x")
        chain.step("c_psi", "k_psi*c_x", "N/m³", BA, "coefficient of non-uniform shear (torsion)")
    else:
        chain.given("c_psi", s.c_psi, "N/m³", "coefficient of non-uniform shear (torsion)")
    _base(chain, BA)
    _springs(chain, ("c_x*A", "c_x*A", "c_z*A", "c_phi*I_x", "c_phi*I_y", "c_psi*(I_x + I_y)"), (BA,) * 6)
    chain.step("xi_y", "xi_x", "-", BA, "sliding damping ratio along y")
    chain.step("xi_ry", "xi_rx", "-", BA, "rocking damping ratio about y")
    if len(xi) == 4:
        chain.given("xi_rz", xi[3], "-", "torsional damping ratio given (soil.damping)")
    else:
        chain.step("xi_rz", "xi_rx", "-", BA, "torsional damping ratio (that of rocking)")
    _dashpots(chain)
    return chain


def sp26_chain(footing, model) -> Chain:
    """SP 26.13330's springs and damping in both planes, torsion by SNiP 2.02.05-87 (``planes``)."""
    from foundation_calc.solvers.supports.footing_springs import SP26_TORSION

    chain = Chain("Block soil springs and dashpots at O by SP 26.13330 (soil.method = \"sp26\")")
    _givens(chain, footing, model)
    sp26_givens(chain, footing.soil)
    chain.given("k_psi", SP26_TORSION[0], "-", "ratio C_ψ/C_z (SNiP 2.02.05-87)")
    chain.given("k_xi", SP26_TORSION[1], "-", "ratio ξ_ψ/ξ_z (SNiP 2.02.05-87)")
    _base(chain, SP26)
    chain.step("c_zsp", SP26_FORMULAS["c_z"], "N/m³", SP26, "coefficient of elastic uniform compression")
    sliding, vertical = SP26_FORMULAS["sliding"].format(c="c_zsp"), SP26_FORMULAS["vertical"].format(c="c_zsp")
    _springs(chain, (sliding, sliding, vertical, *(SP26_FORMULAS["rocking"].format(c="c_zsp", I=I) for I in ("I_x", "I_y")),
                     "k_psi*c_zsp*(I_x + I_y)"),
             (f"{SP26}, C_x = 0.7 C_z",) * 2 + (SP26,) + (f"{SP26}, C_φ = 2 C_z",) * 2 + ("SNiP 2.02.05-87, C_ψ = C_z",))
    chain.step("p_m", SP26_FORMULAS["p_m"].format(m="M"), "kPa", SP26, "mean static pressure under the base")
    chain.step("xi_z", SP26_FORMULAS["xi_z"], "-", f"{SP26} (p_m in kPa)", "vertical damping ratio")
    for xi, formula, meaning in (("xi_x", "xi_sliding", "sliding damping ratio along x"), ("xi_y", "xi_sliding", "sliding damping ratio along y"),
                                 ("xi_rx", "xi_rocking", "rocking damping ratio about x"), ("xi_ry", "xi_rocking", "rocking damping ratio about y")):
        chain.step(xi, SP26_FORMULAS[formula], "-", SP26, meaning)
    chain.step("xi_rz", "k_xi*xi_z", "-", "SNiP 2.02.05-87, ξ_ψ = 0.3 ξ_z", "torsional damping ratio")
    _dashpots(chain)
    return chain


def _plane(footing, model, across: bool) -> SimpleNamespace:
    """The block seen as the crank's plane footing (:func:`~.soil_methods.gazetas_springs_chain`
    reads ``foundation``, ``soil``, ``total_mass``): L in the plane of x (rocking about y, J_y) or,
    ``across``, B in the plane of y (rocking about x, J_x); I_0 the moment of inertia about O's axis."""
    L, B = footing.base
    m = np.diagonal(model.M)
    foundation = SimpleNamespace(dimensions=(B, L) if across else (L, B), embedment=footing.embedment,
                                 moment_of_inertia=m[3] if across else m[4], cog_height=0.0)
    return SimpleNamespace(foundation=foundation, soil=footing.soil, total_mass=m[0])


def _torsion_static(footing, model) -> Chain:
    """Gazetas' or Pais & Kausel's static torsional spring with its embedment factor
    (:mod:`~foundation_calc.solvers.soil.torsion`, :mod:`~foundation_calc.solvers.soil.pais_kausel`,
    :mod:`~foundation_calc.solvers.soil.torsion_embedment`)."""
    pk = footing.soil.method_used == "pais_kausel"
    source = "[PK]; [NIST] Table 2-2a" if pk else "[Ga] Table 1"
    chain = Chain(f"Block torsional spring about z: {'Pais & Kausel' if pk else 'Gazetas'} (soil.method = \"{footing.soil.method_used}\")")
    _givens(chain, footing, model)
    _half_space(chain, footing)
    chain.given("D", footing.embedment, "m", "embedment depth (sidewall in contact over all of it)")
    chain.step("Lh", "max(L, B)/2", "m", source, "longer half-side of the base")
    chain.step("Bh", "min(L, B)/2", "m", source, "shorter half-side of the base")
    chain.step("r", "Lh/Bh", "-", source, "aspect ratio L'/B' of the base")
    chain.step("J_t", "L*B*(L**2 + B**2)/12", "m⁴", source, "polar second moment of the base")
    if pk:
        chain.step("K_t0", "G*Bh**3*(4.25*r**2.45 + 4.06)", "N m/rad", source, "static torsional spring of the surface base")
        chain.step("eta_t", "1 + (1.3 + 1.32/r)*(D/Bh)**0.9", "-", "[PK]; [NIST] Table 2-2b", "embedment factor of the torsional spring")
    else:
        chain.step("K_t0", "G*J_t**0.75*(4 + 11*(1 - 1/r)**10)", "N m/rad", source, "static torsional spring of the surface base")
        chain.step("eta_t", "1 + 1.4*(1 + 1/r)*(D/Bh)**0.9", "-", "[Ga] Table 2", "embedment factor of the torsional spring")
    chain.step("K_rz", "eta_t*K_t0", "N m/rad", source, "static torsional spring about z")
    if "V_s" not in chain.values:
        chain.step("V_s", "sqrt(G/rho)", "m/s", source, "shear wave velocity")
    return chain


def _torsion_at(chain: Chain, static: Chain, omega: float) -> None:
    """Torsion at ``omega``: Pais & Kausel's modifier k_t(a0) and radiation C_t = ρ V_s J_t c̃_t
    (:func:`~foundation_calc.solvers.soil.impedance.footing_torsion`), ξ and the dashpot at O."""
    for name in ("J_z", "rho", "xi_m", "Bh", "r", "J_t", "K_rz", "V_s"):
        meaning, unit = static.nomenclature[SYMBOLS.get(name, name)]
        chain.given(name, static.values[name], unit, meaning)
    chain.given("omega_s", omega, "rad/s", "circular frequency n ω of the order, or a mode's own ω*")
    chain.step("a_d", "omega_s*Bh/V_s", "-", PK, "dimensionless frequency")
    chain.step("k_t", "1 - (0.33 - 0.03*sqrt(r - 1))*a_d**2/(0.8/(1 + 0.33*(r - 1)) + a_d**2)", "-", PK, "dynamic modifier of the torsional spring")
    chain.step("c_t", "a_d**2/(1.4/(1 + 3*(r - 1)**0.7) + a_d**2)", "-", PK, "torsional radiation coefficient")
    chain.step("K_rzw", "k_t*K_rz", "N m/rad", PK, "torsional spring at n ω")
    chain.step("C_t", "rho*V_s*J_t*c_t", "N m s/rad", PK, "torsional radiation dashpot at n ω")
    chain.step("xi_rzw", "C_t/(2*sqrt(K_rzw*J_z)) + xi_m", "-", PK, "torsional damping ratio at n ω (radiation + material)")
    dashpot(chain, "C_rzw", "xi_rzw", "K_rzw", "J_z", "N m s/rad", DASHPOT, "torsional dashpot at O at n ω")


def orders_of(scene, own=None) -> list[tuple[str, str, str, float]]:
    """(machine, n, column head, n ω [rad/s]) of every order of every machine, as the block's
    response solves them, then ("mode j", "ω*", head, ω_j*) of each mode at its own frequency
    (``own`` [rad/s], the resonance check's), as the sheet's modes take them."""
    found = [(e.name, str(int(n)), f"{e.name}, n = {int(n)}", float(n * e.omega)) for e in scene.excitations() for n in e.orders]
    return found + [(f"mode {j + 1}", "ω*", f"mode {j + 1} at ω*", float(w)) for j, w in enumerate(own or ())]


def gazetas_blocks(footing, model, orders) -> list:
    """Static chains of torsion and in both planes, then the springs and dashpots at each order's
    n ω and each mode's ω* (``orders``: :func:`orders_of`; at most :data:`MOST_COLUMNS` side by
    side per table)."""
    from foundation_calc.output.report.soil_methods import gazetas_at, gazetas_springs_chain, pais_kausel_springs_chain

    build = pais_kausel_springs_chain if footing.soil.method_used == "pais_kausel" else gazetas_springs_chain
    torsion = _torsion_static(footing, model)
    out: list = [torsion]
    statics = []
    for across, plane in ((False, "x: sliding x (K_x), vertical (K_z), rocking about y (K_ry); L in the plane, I_0 = J_y"),
                          (True, "y: sliding y (K_y), rocking about x (K_rx); B in the plane, I_0 = J_x")):
        chain = build(_plane(footing, model, across))
        chain.title += f", in the plane of {plane}"
        statics.append(chain)
        out.append(chain)
    out.append(Paragraph("The block's static springs (ω = 0, the matrix K below): K_x, K_z, K_ry the plane of x's K_x, K_z, K_φ;"
                         " K_y, K_rx the plane of y's K_x, K_φ; K_rz the torsion's. At a frequency each order's springs and"
                         " dashpots follow, C_i = 2 ξ_i √(K_i m_i) at O."))
    for start in range(0, len(orders), MOST_COLUMNS):
        shown = orders[start:start + MOST_COLUMNS]
        heads = tuple(head for *_, head, _ in shown)
        for across, static, (C_h, C_r) in zip((False, True), statics, (("C_xw", "C_ryw"), ("C_yw", "C_rxw"))):
            chains = []
            for *_, omega in shown:
                chain = Chain("")
                gazetas_at(chain, _plane(footing, model, across), static, omega, "circular frequency n ω of the order, or a mode's own ω*", name="omega_s")
                if not across:
                    dashpot(chain, "C_zw", "xi_zw", "K_zw", "M_tot", "N s/m", DASHPOT, "vertical dashpot at O at n ω")
                dashpot(chain, C_h, "xi_xw", "K_xw", "M_tot", "N s/m", DASHPOT, "sliding dashpot at O at n ω")
                dashpot(chain, C_r, "xi_phiw", "K_phiw", "I_0", "N m s/rad", DASHPOT, "rocking dashpot at O at n ω")
                chains.append(chain)
            axis = "y" if across else "x"
            out.append(Columns(f"Plane of {axis} at each order's n ω and each mode's ω* (the chain above's springs; [PK] modifiers, [Ga] dashpots)",
                               heads, chains, (("omega_s", "n ω, or ω*", "[PK]"),)))
        chains = []
        for *_, omega in shown:
            chain = Chain("")
            _torsion_at(chain, torsion, omega)
            chains.append(chain)
        out.append(Columns("Torsion at each order's n ω and each mode's ω*", heads, chains, (("omega_s", "n ω, or ω*", "[PK]"),)))
    return out


def order_springs_table(scene, model, orders) -> tuple[Table, Table]:
    """The six springs and dashpots at O that each order's response (and each mode) was solved
    with (the solver's ``soil_impedance`` at n ω or ω*; ``orders``: :func:`orders_of`), under
    those at ω = 0 that K and C above hold."""
    omegas = np.array([0.0] + [w for *_, w in orders])
    springs, dashpots, *_ = scene.soil_impedance(omegas)  # a pile group's coupling: its own table
    labels = [("static", "-", "0")] + [(name, n, None) for name, n, *_ in orders]
    omega_col = column(list(omegas), 4)
    labels = [(a, b, omega_col[k]) for k, (a, b, _) in enumerate(labels)]

    def tab(title, values, names, units):
        cols = [column(list(values[:, j]), 4) for j in range(6)]
        head = ("machine", "n", "Ω = nω [rad/s]", *(f"{s} [{u}]" for s, u in zip(names, units)))
        return table(title, head, [(*label, *(c[k] for c in cols)) for k, label in enumerate(labels)], (False, False, *(True,) * 7))

    return (tab("Springs at O each order (and mode) is solved with, k(nω); K(nω) = K + diag(k(nω) − k(0)) (K above, with −W z_G)",
                springs, SPRINGS, UNITS_K),
            tab("Dashpots at O each order (and mode) is solved with, c(nω); C(nω) = diag(c(nω))", dashpots, DASHPOTS, UNITS_C))


def tilt_chain(model, springs) -> Chain:
    """K's rocking entries: the springs K_rx, K_ry at O less the weight's tilt W z_G ([KM] (3.4)'s
    −P h; :func:`~foundation_calc.solvers.block.model.block_model`), z_G from M's first moment."""
    from foundation_calc.solvers.constants import GRAVITY

    chain = Chain("Rocking entries of K: the springs at O less the weight's tilt W z_G")
    chain.given("M", model.M[0, 0], "kg", "total mass of the block and the machines")
    chain.given("S_y", model.M[0, 4], "kg m", "first moment of the mass about the base, M z_G (M's entry u_x, θ_y)")
    chain.given("g", GRAVITY, "m/s²", "acceleration of gravity")
    chain.given("K_rx", springs[3], "N m/rad", "rocking spring at O about x")
    chain.given("K_ry", springs[4], "N m/rad", "rocking spring at O about y")
    chain.step("z_G", "S_y/M", "m", "[KM] (3.4)", "height of the centre of mass above the base")
    chain.step("W", "M*g", "N", "[KM] (3.4)", "weight of the block and the machines")
    chain.step("K_44", "K_rx - W*z_G", "N m/rad", "[KM] (3.4), −P h", "entry θ_x, θ_x of K")
    chain.step("K_55", "K_ry - W*z_G", "N m/rad", "[KM] (3.4), −P h", "entry θ_y, θ_y of K")
    return chain


def block_soil_blocks(scene, model, own=None) -> list:
    """The support's part of the block's sheet (:meth:`~foundation_calc.solvers.supports.base.Support.sheet`,
    rendered by :func:`rendered`: a soil method's chains at every order's n ω and each mode's own ω*
    (``own`` [rad/s]) as well, on a frequency-dependent soil; :func:`order_springs_table` gives the
    solver's at each), then K's rocking entries."""
    orders = orders_of(scene, own)
    out = [block for item in scene.support().sheet(model, orders) for block in rendered(item, scene, model, orders)]
    return [*out, tilt_chain(model, model.springs)]


def rendered(item, scene, model, orders) -> list:
    """A support's sheet item (:mod:`~foundation_calc.solvers.supports.sheet`) as the sheet's blocks."""
    from foundation_calc.solvers.supports.sheet import Given, Grid, HandCalc, SoilMethod, Text

    if isinstance(item, HandCalc):
        chain = Chain(item.title)
        for row in item.rows:
            if isinstance(row, Given):
                chain.given(row.symbol, row.value, row.unit, row.meaning)
            else:
                chain.step(row.symbol, row.formula, row.unit, row.source, row.meaning)
        return [chain]
    if isinstance(item, Text):
        return [Paragraph(item.text)]
    if isinstance(item, Grid):
        values = np.asarray(item.values, dtype=float)
        cols = [column(list(values[:, j]), item.digits) for j in range(values.shape[1])]
        return [table(item.title, item.head, [(name, *(c[i] for c in cols)) for i, name in enumerate(item.names)],
                      (False, *(True,) * values.shape[1]))]
    if isinstance(item, SoilMethod):  # the footing's soil, base and embedment the item carries
        if item.method in ("gazetas", "pais_kausel"):
            return gazetas_blocks(item, model, orders)
        return [{"lysmer": lysmer_chain, "coefficients": coefficients_chain, "sp26": sp26_chain}[item.method](item, model)]
    raise TypeError(f"not a sheet item: {item!r}")


__all__ = ["block_soil_blocks", "coefficients_chain", "rendered", "tilt_chain", "gazetas_blocks", "lysmer_chain", "order_springs_table", "orders_of", "sp26_chain"]
