"""A block on piles on the sheet: the single pile's static head springs as a hand calculation
(EN 1998-5 Table C.1, Randolph & Wroth, Randolph's torsion), then the group under the cap as the
solver assembles it (the interaction needs a linear solve, so the sheet gives its method and the
resulting springs and dashpots at O rather than a chain), and the coupling terms.

``tests/test_piles_cli.py`` compares the chain's printed springs with the solver's.
"""

from __future__ import annotations

import numpy as np

from foundation_calc.output.report.handcalc import Chain
from foundation_calc.output.report.model import Paragraph, table
from foundation_calc.output.report.numbers import column

#: Randolph & Wroth's r_m by the tip: (formula, ξ).
R_M = {"end_bearing": ("0.25*L_p", "ξ = 0"), "floating": ("(0.25 + (2.5*rho_G*(1 - nu) - 0.25))*L_p", "ξ = 1")}

#: Randolph & Wroth's head stiffness by the tip: (formula, note on the source, meaning).
K_V = {"end_bearing": ("G_L*r0/t", ", ξ → 0", "vertical spring, tip on rock"),
       "floating": ("G_L*r0*(b_t + 2*pi*rho_G/zeta*tanh(muL)/muL*L_p/r0)/(1 + b_t*t)", "", "vertical spring, floating tip")}

#: f(z/d) of the profile as an expression of ``t`` = z/d (EN 1998-5 Table C.1's three soil models).
PROFILE = {"uniform": "1", "linear": "{t}", "parabolic": "sqrt({t})"}


def single_pile_chain(scene) -> Chain:
    """The single pile's static head springs (:func:`~foundation_calc.solvers.piles.single.single_pile` at ω = 0)."""
    from foundation_calc.solvers.piles.single import ACTIVE_LENGTH_EXPONENT, PILE_POISSON, TABLE_C1

    soil, p = scene.soil, scene.piles
    chain = Chain(f"One pile's static head springs ({p.head} head, {p.tip.replace('_', '-')}, soil {p.soil_profile})")
    chain.given("d", p.diameter, "m", "pile diameter")
    chain.given("L_p", p.length, "m", "pile length")
    chain.given("E_p", p.modulus, "Pa", "Young's modulus of the pile")
    chain.given("G", soil.G, "Pa", "shear modulus of the soil at depth d")
    chain.given("nu", soil.poisson, "-", "Poisson's ratio of the soil")
    chain.step("E_s", "3*G", "Pa", "[EC8] Annex C", "Young's modulus of the table's soil model at depth d (3 G)")
    (a, m), (b, n), (c, q) = TABLE_C1[p.soil_profile]
    chain.step("K_HH", f"d*E_s*{a:g}*(E_p/E_s)**{m:g}", "N/m", "[EC8] Table C.1", "sway spring of a fixed head")
    chain.step("K_MM", f"d**3*E_s*{b:g}*(E_p/E_s)**{n:g}", "N m/rad", "[EC8] Table C.1", "rocking spring of a fixed head")
    chain.step("K_HM", f"d**2*E_s*({c:g})*(E_p/E_s)**{q:g}", "N/rad", "[EC8] Table C.1", "sway-rocking coupling of a fixed head")
    if p.head == "pinned":
        chain.step("K_HHp", "K_HH - K_HM**2/K_MM", "N/m", "[EC8] Table C.1, M = 0", "sway spring of a pinned head")
    chain.step("l_a", f"2*d*(E_p/E_s)**{ACTIVE_LENGTH_EXPONENT[p.soil_profile]:g}", "m", "[Fa] ch. 15", "active length")
    f = PROFILE[p.soil_profile]
    chain.step("G_L", "G*" + f.format(t="max(L_p, d)/d"), "Pa", "[EC8] Table C.1", "shear modulus of the soil at the tip")
    chain.step("rho_G", "(" + f.format(t="max(L_p/2, d)/d") + ")/(" + f.format(t="max(L_p, d)/d") + ")", "-", "[RW]",
               "mid-depth modulus over the tip's")
    chain.step("r0", "d/2", "m", "[RW]", "pile radius")
    chain.step("lam", "E_p/G_L", "-", "[RW]", "pile-soil stiffness ratio")
    r_m, shown = R_M[p.tip]
    chain.step("r_m", r_m, "m", f"[RW] {shown}", "radius of the soil's influence")
    chain.step("zeta", "log(r_m/r0)", "-", "[RW]", "shaft's load-transfer factor")
    chain.step("muL", "sqrt(2/(zeta*lam))*L_p/r0", "-", "[RW]", "pile compressibility μL")
    chain.step("t", "tanh(muL)/muL*L_p/r0/(pi*lam)", "-", "[RW]", "compressibility term")
    if p.tip == "floating":
        chain.step("b_t", "4/(1 - nu)", "-", "[RW]", "base term 4η/((1 − ν) ξ), η = ξ = 1")
    K_v, shown, meaning = K_V[p.tip]
    chain.step("K_v", K_v, "N/m", f"[RW] (17){shown}", meaning)
    chain.step("G_m", "G*" + f.format(t="max(L_p/2, d)/d"), "Pa", "[RW] 1981", "shear modulus of the soil at mid-depth")
    chain.step("k_t", "4*pi*G_m*r0**2", "N m/rad/m", "[RW] 1981", "torsional reaction of the shaft per unit length")
    chain.step("GJ", f"E_p/(2*(1 + {PILE_POISSON:g}))*pi*d**4/32", "N m²", "[RW] 1981", "torsional rigidity of the pile")
    chain.step("K_T", "sqrt(k_t*GJ)*tanh(sqrt(k_t/GJ)*L_p)", "N m/rad", "[RW] 1981", "torsional spring of the head")
    return chain


def group_blocks(scene, model) -> list:
    """The group's method and its springs and dashpots at O at rest."""
    from foundation_calc.checks.block_piles import piles_at_frequencies

    rows = piles_at_frequencies(scene)
    K, C = (np.where(np.abs(X) > 1e-12 * np.abs(X).max(), X, 0.0) for X in rows[0].group)  # round-off of the sums
    head = ("", "x", "y", "z", "rx", "ry", "rz")
    names = ("x", "y", "z", "rx", "ry", "rz")
    cols_K = [column(list(K[:, j]), 4) for j in range(6)]
    cols_C = [column(list(C[:, j]), 4) for j in range(6)]
    p = scene.piles
    text = (f"{len(p.positions)} piles under the rigid cap (the block's base, O its centre). Under the cap's motion q the"
            " heads move w_i = u_z + y_i θ_x − x_i θ_y, u_x,i = u_x − y_i θ_z, u_y,i = u_y + x_i θ_z. With the"
            " interaction factors of [DG] (α_v = √(r0/S) e^{−(β+i)ωS/V_s}; horizontal α(0°) cos²θ + α(90°) sin²θ,"
            " α(0°) at V_La = 3.4 V_s/(π(1 − ν))), A_ij = α(S_ij), the head forces are P = K_1 A⁻¹ u in each direction"
            " and the cap's springs K = Σ Dᵀ K_1 A⁻¹ D (a linear solve, not a hand calculation), plus each pile's own"
            " K_MM, K_HM and K_T. At frequency ω each single-pile spring is the static one times its Winkler shape χ^{p}"
            " ([MG]); the dashpots C = Im K(ω)/ω, their symmetric part kept positive semi-definite. Efficiency at rest:"
            f" η_x = {rows[0].efficiency['x']:.3g}, η_z = {rows[0].efficiency['z']:.3g} (group over n single piles).")
    out = [Paragraph(text),
           table("The group's springs at O at rest, K [N/m, N/rad, N m/rad] (the coupling off the diagonal)", head,
                 [(names[i], *(c[i] for c in cols_K)) for i in range(6)], (False, *(True,) * 6)),
           table("The group's dashpots at O at rest, C [N s/m, N s/rad, N m s/rad]", head,
                 [(names[i], *(c[i] for c in cols_C)) for i in range(6)], (False, *(True,) * 6))]
    if p.cap_contact or scene.embedment:
        out.append(Paragraph("The cap's own contact with the soil (piles.cap_contact, or the sidewalls of block.embedment)"
                             " adds the footing's springs and dashpots of soil.method in parallel (not in the tables above)."))
    return out


def piles_blocks(scene, model) -> list:
    """The piles' part of the block's sheet."""
    return [single_pile_chain(scene), *group_blocks(scene, model)]


__all__ = ["piles_blocks", "single_pile_chain"]
