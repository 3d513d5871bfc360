"""A pile group under the block, its base the rigid cap (``[piles]``): the group's springs and
dashpots at O, frequency-dependent and coupled (sway-rocking), with the cap's own footing in
parallel where it bears on the soil or is embedded (:meth:`Piles.matrices`:
:func:`~foundation_calc.solvers.piles.cap.pile_group` of the single piles of
:func:`~foundation_calc.solvers.piles.single.single_pile`, and the footing's
:func:`~.footing_springs.six_springs`). The material damping ξ_m of the soil adds 2 ξ_m √(|K_ii| m_i)
to each dashpot of the diagonal, m_i the mass (translations) or the moment of inertia about the
axis through O (rotations): the dashpots of the diagonal are found from the damping ratios
ξ_i = C_ii/(2 √(|K_ii| m_i)) + ξ_m as the footing's are.

Range of validity: a0 = ω d/V_s, d the pile diameter, a0 <= 1
(:data:`~foundation_calc.solvers.piles.single.A0_FITTED`). In ``fcalc soil`` the single pile's head
springs and dashpots and the group's efficiency (its spring over n single piles') at rest and at
each machine's speed; on the sheet the single pile's static springs as a hand calculation and the
group's at rest (its interaction needs a linear solve: the method and the result, not a chain).
``tests/test_piles_cli.py`` compares the chain's printed springs with the solver's.

Sizing (:class:`~.base.Sizing`): a design may vary the piles' length and diameter
(:data:`~.pile_sizes.VARIABLES`); the heads keep their place in a resized plan; the piles add
n π d²/4 L of concrete; each candidate's piles are judged against the ranges of the closed forms
as ``fcalc check`` judges a scene's (:mod:`.pile_sizes`).
"""

from __future__ import annotations

from dataclasses import dataclass

import numpy as np

from foundation_calc.solvers.supports.base import MOTIONS, Assumption, FrequencyTable, SoilSection, Validity
from foundation_calc.solvers.supports.footing import Footing
from foundation_calc.solvers.supports.footing_springs import six_springs
from foundation_calc.solvers.supports.pile_sizes import VARIABLES, concrete, errors, heads, warnings
from foundation_calc.solvers.supports.sheet import Grid, HandCalc, Rows, Text
from foundation_calc.units import hz_from_omega

#: Rows of the single pile's table in ``fcalc soil``: (key, label, unit, scale from SI).
SINGLE_ROWS = (
    ("K_v", "K_v", "MN/m", 1e-6), ("K_HH", "K_HH", "MN/m", 1e-6), ("K_MM", "K_MM", "MN m/rad", 1e-6),
    ("K_HM", "K_HM", "MN/rad", 1e-6), ("K_T", "K_T", "MN m/rad", 1e-6),
)

#: Randolph & Wroth's r_m by the tip: (formula, ξ).
R_M = {"end_bearing": ("0.25*L_p", "ξ = 0"), "floating": ("(0.25 + (2.5*rho_G*(1 - nu) - 0.25))*L_p", "ξ = 1")}

#: Randolph & Wroth's head stiffness by the tip: (formula, note on the source, meaning).
K_V = {"end_bearing": ("G_L*r0/t", ", ξ → 0", "vertical spring, tip on rock"),
       "floating": ("G_L*r0*(b_t + 2*pi*rho_G/zeta*tanh(muL)/muL*L_p/r0)/(1 + b_t*t)", "", "vertical spring, floating tip")}

#: f(z/d) of the profile as an expression of ``t`` = z/d (EN 1998-5 Table C.1's three soil models).
PROFILE = {"uniform": "1", "linear": "{t}", "parabolic": "sqrt({t})"}



@dataclass(frozen=True)
class PilesAt:
    """One pile's and the group's springs and dashpots at one frequency ``omega`` [rad/s].

    Attributes
    ----------
    label : ``"static"`` or ``"ω, <machine>"``
    a0 : ω d/V_s [-] (V_s the soil's at depth d)
    single : name -> (K, C) of one pile: K_v, K_HH, K_MM, K_HM, K_T [N/m, N m/rad, N/rad; N s/m ...]
        (K_MM, K_HM zero for a pinned head, K_HH then the free head's)
    group : the group at O, (K, C) each (6, 6)
    efficiency : motion -> the group's spring over n single piles' (x, y: K_HH; z: K_v) [-]
    """

    label: str
    omega: float
    a0: float
    single: dict
    group: tuple
    efficiency: dict


class Piles(Footing):
    """The pile group under the base: the :class:`~.footing.Footing`'s arguments, ``soil`` the
    scene's soil with the piles standing in it (:class:`~foundation_calc.scenes.block_piles.PiledSoil`:
    the soil's keys and ``piles``, the ``[piles]`` table; ``plan``, the base (L, B) [m] the
    positions are given under; ``dimensions``, the piles' (d, L) [m] of a batch of candidates or None)."""

    label = "piles"
    unscaled = ("[piles]: the group's springs do not scale with one factor on the soil's modulus"
                " (EN 1998-5 Table C.1: K ∝ E_s^(1 - n))")

    def __init__(self, soil, L, B, masses, D):
        super().__init__(soil, L, B, masses, D)
        self.piles = soil.piles
        self.label, self.unscaled = Piles.label, Piles.unscaled

    @property
    def base_bears(self) -> bool:
        """Whether the cap bears on the soil (``piles.cap_contact``); else the piles alone carry the
        block (:func:`~.base.bears_on_soil`)."""
        return self.piles.cap_contact

    def springs(self, L, B, m, omega) -> tuple:
        """The diagonal of :meth:`matrices` as springs and damping ratios ξ_i = C_ii/(2 √(|K_ii| m_i))
        plus the soil's material damping (module docstring; a group's dynamic spring can be negative
        at high frequency, where the interaction of its piles makes it so), and its off-diagonal
        terms (the sway-rocking coupling) as :meth:`Footing.springs` gives them."""
        K, C = self.matrices(L, B, m, omega)
        k, c = np.diagonal(K, 0, -2, -1), np.diagonal(C, 0, -2, -1)
        M, J_O = m[..., 0], np.moveaxis(m[..., 3:], -1, 0)
        masses = [M, M, M, *J_O]
        xi_m = self.soil.material_damping or 0.0
        off = 1.0 - np.eye(6)
        return ([k[..., i] for i in range(6)],
                [c[..., i] / (2.0 * np.sqrt(np.abs(k[..., i]) * masses[i])) + xi_m for i in range(6)], (K * off, C * off))

    def group(self, L, B, omega):
        """The group's impedance K + iω C at O, complex omega.shape + (6, 6), the positions scaled
        with the base L × B [m] (arrays over a batch of candidate blocks)."""
        from foundation_calc.solvers.piles.cap import pile_group

        soil, p = self.soil, self.piles
        x, y = heads(p.positions, soil.plan, L, B)
        d, length = (p.diameter, p.length) if soil.dimensions is None else (
            np.reshape(v, np.shape(v) + (1,) * (np.ndim(L) - np.ndim(v))) for v in soil.dimensions)
        return pile_group(x, y, d, length, p.modulus, p.density, soil.G, soil.poisson, soil.density,
                          soil.material_damping or 0.0, p.soil_profile, p.tip == "end_bearing", p.head == "pinned",
                          omega)

    @property
    def sizes(self) -> dict:
        """The piles' length and diameter [m], by scene key (:data:`~.pile_sizes.VARIABLES`)."""
        return {"piles.length": self.piles.length, "piles.diameter": self.piles.diameter}

    def _dimensions(self, values) -> tuple:
        """(d, L) [m] of candidate ``values`` (key -> (N,); the table's where not given)."""
        values = {} if values is None else values
        return tuple(np.asarray(values.get(key, self.sizes[key]), dtype=float) for key in ("piles.diameter", "piles.length"))

    def sized(self, scene, values):
        """``scene`` with every candidate on its own piles (:meth:`~foundation_calc.scenes.block_piles.PiledSoil.with_dimensions`)."""
        return scene.model_copy(update={"soil": self.soil.with_dimensions(*self._dimensions(values))})

    def concrete(self, values=None):
        """n π d²/4 L [m³] of the piles (:func:`~.pile_sizes.concrete`)."""
        return concrete(len(self.piles.positions), *self._dimensions(values))

    def size_warnings(self, values, L, B):
        """L/d, the active length and the spacing of each candidate's piles on its base (:func:`~.pile_sizes.warnings`)."""
        d, length = self._dimensions(values)
        return warnings(self.piles, 3.0 * self.soil.G, self.soil.plan, d, length, L, B)

    def size_errors(self, values, L, B):
        """The candidates whose piles overlap on their base (:func:`~.pile_sizes.errors`)."""
        return errors(self.piles, self.soil.plan, self._dimensions(values)[0], L, B)

    def plan_changes(self, old, new) -> dict:
        """The heads keep their place in the plan: x scaled with L, y with B."""
        return {"piles.positions": [[x * new[0] / old[0], y * new[1] / old[1]] for x, y in self.piles.positions]}

    def cap(self, L, B, m, omega):
        """The cap's own springs and radiation dashpots (diagonal, six each) where it touches the soil:
        the whole footing with ``cap_contact``, else the embedded sidewalls only (embedded less
        surface), else none; ``m`` the body's diagonal of M about O (..., 6) [kg, kg m²]."""
        if not self.piles.cap_contact and not np.any(np.asarray(self.D) > 0):
            return 0.0, 0.0
        xi_m = self.soil.material_damping or 0.0
        M, J_O = m[..., 0], np.moveaxis(m[..., 3:], -1, 0)
        masses = [M, M, M, *J_O]

        def parts(depth):
            springs, ratios = six_springs(self.soil, L, B, M, J_O, omega, depth)
            return np.stack(np.broadcast_arrays(*springs), -1), np.stack(np.broadcast_arrays(
                *[2.0 * (r - xi_m) * np.sqrt(k * mi) for r, k, mi in zip(ratios, springs, masses)]), -1)

        K, C = parts(self.D)
        if self.piles.cap_contact:
            return K, C
        K0, C0 = parts(0.0)
        return K - K0, C - C0

    def matrices(self, L, B, m, omega):
        """(K, C) at O, each omega.shape + (6, 6): the group's (:meth:`group`, its dashpots Im K/ω by
        :func:`~foundation_calc.solvers.piles.cap.springs_and_dashpots`) and the cap's footing
        (:meth:`cap`); arguments as :meth:`cap`."""
        from foundation_calc.solvers.piles.cap import springs_and_dashpots

        K, C = springs_and_dashpots(lambda w: self.group(L, B, w), omega)
        K_f, C_f = self.cap(L, B, m, omega)
        eye = np.eye(6)
        return K + np.asarray(K_f)[..., None] * eye, C + np.asarray(C_f)[..., None] * eye

    def validity(self) -> Validity:
        """a0 = ω d/V_s of every motion against the single pile's fitted range."""
        from foundation_calc.solvers.piles.single import A0_FITTED, A0_SOURCE

        return Validity("piles", A0_FITTED, "a0 = ω d/V_s, d the pile diameter, V_s the soil's at depth d", A0_SOURCE,
                        float(self.soil.V_s), dict.fromkeys(MOTIONS, float(self.piles.diameter)))

    def a0(self, omega):
        """a0 = ω d/V_s at ``omega`` [rad/s] and its meaning."""
        return np.asarray(omega, dtype=float) * self.piles.diameter / self.soil.V_s, "a0 = ω d/V_s (d the piles' diameter)"

    def at_frequencies(self, speeds) -> tuple[PilesAt, ...]:
        """The single pile and the group at rest and at every machine's speed (``speeds``: name -> ω [rad/s])."""
        from foundation_calc.solvers.piles.cap import OMEGA_REST, springs_and_dashpots
        from foundation_calc.solvers.piles.single import pinned, single_pile

        soil, p = self.soil, self.piles
        entries = [("static", 0.0)] + [(f"ω, {name}", w) for name, w in speeds.items()]
        omega = np.array([w for _, w in entries])

        def one(w):
            head = single_pile(p.diameter, p.length, p.modulus, p.density, soil.G, soil.poisson, soil.density,
                               p.soil_profile, p.tip == "end_bearing", w)
            return pinned(head) if p.head == "pinned" else head

        head, damped = one(omega), one(np.maximum(omega, OMEGA_REST))
        K, C = springs_and_dashpots(lambda w: self.group(self.L, self.B, w), omega)
        n = len(p.positions)
        rows = []
        for i, (label, w) in enumerate(entries):
            single = {name: (float(np.real(getattr(head, name)[i])),
                             float(np.imag(getattr(damped, name)[i]) / max(w, OMEGA_REST)))
                      for name in ("K_v", "K_HH", "K_MM", "K_HM", "K_T")}
            efficiency = {"x": K[i, 0, 0] / (n * single["K_HH"][0]), "y": K[i, 1, 1] / (n * single["K_HH"][0]),
                          "z": K[i, 2, 2] / (n * single["K_v"][0])}
            rows.append(PilesAt(label, float(w), float(w * p.diameter / soil.V_s), single, (K[i], C[i]),
                                {k: float(v) for k, v in efficiency.items()}))
        return tuple(rows)

    def soil_section(self, speeds) -> SoilSection:
        """The single pile's springs and dashpots, the group's efficiency and its sway-rocking
        coupling at rest and at each machine's speed (JSON ``piles``; no stratum under piles)."""
        p, rows = self.piles, self.at_frequencies(speeds)
        document = [{
            "at": r.label, "omega": r.omega, "a0": r.a0,
            "single": {k: {"K": K, "C": C} for k, (K, C) in r.single.items()},
            "group": {"K": r.group[0].tolist(), "C": r.group[1].tolist()},
            "efficiency": r.efficiency,
        } for r in rows]
        table = [("f", "Hz", [hz_from_omega(r.omega) for r in rows]), ("a0", "-", [r.a0 for r in rows])]
        table += [(label, unit, [r.single[key][0] * scale for r in rows]) for key, label, unit, scale in SINGLE_ROWS]
        table += [(f"C{label[1:]}", unit.replace("MN", "MN s"), [r.single[key][1] * scale for r in rows])
                  for key, label, unit, scale in SINGLE_ROWS]
        table += [(f"η_{m}", "-", [r.efficiency[m] for r in rows]) for m in ("x", "y", "z")]
        table += [("K_x,ry", "MN/rad", [r.group[0][0, 4] * 1e-6 for r in rows]),
                  ("K_y,rx", "MN/rad", [r.group[0][1, 3] * 1e-6 for r in rows])]
        title = (f"Piles: {len(p.positions)} × d = {p.diameter:g} m, L = {p.length:g} m, {p.head} heads, {p.tip.replace('_', '-')},"
                 f" soil {p.soil_profile}: one pile's head springs and dashpots, the group's efficiency η"
                 " (its spring over n single piles') and coupling at O")
        note = ("Single pile: EN 1998-5 Table C.1 [EC8] (K_HH, K_MM, K_HM), Randolph & Wroth 1978 (K_v), Randolph 1981 (K_T) [RW],"
                " frequency shape of a Winkler pile (Makris & Gazetas 1992 [MG]); group: Dobry & Gazetas 1988 [DG] interaction"
                " factors under a rigid cap. a0 = ω d/V_s.")
        return SoilSection({"stratum": None, "piles": document},
                           (FrequencyTable(title, tuple(r.label for r in rows), tuple(table), 4), note))

    def assumptions(self) -> tuple[Assumption, ...]:
        """What the group models and by which sources (module docstring; :mod:`~foundation_calc.solvers.piles.cap`),
        and how it acts at O: coupled sway-rocking through fixed heads' K_HM, and the cap's contact."""
        from foundation_calc.solvers.piles.single import A0_FITTED

        p, xi_m = self.piles, self.soil.material_damping or 0.0
        heads = ("K_HH, K_MM and K_HM of a fixed head from EN 1998-5 Table C.1 [EC8]" if p.head == "fixed" else
                 "K_HH of a pinned head (K_HH − K_HM²/K_MM, no moment) from EN 1998-5 Table C.1 [EC8]")
        soil = (f"A group of {len(p.positions)} piles (d = {p.diameter:g} m, L = {p.length:g} m, {p.head} heads,"
                f" {p.tip.replace('_', '-')} tips) under the block's base as a rigid cap, in the scene's soil, its"
                f" modulus E_s = 3 G at depth d varying with depth as EN 1998-5 Annex C's {p.soil_profile} profile"
                f" [EC8], not a half-space under the base. One pile's head springs: {heads}, K_v by Randolph & Wroth"
                " 1978 and K_T by Randolph 1981 [RW], each times the Winkler pile's frequency shape (Makris &"
                " Gazetas [MG]); the group by Dobry & Gazetas' interaction factors under a rigid cap [DG]; dashpots"
                f" C = Im K(ω)/ω, with the soil's material damping ξ_m = {xi_m:g} in the interaction factors and"
                " 2 ξ_m √(|K_ii| m_i) added on the diagonal. Frequency-dependent: every order n is solved with"
                f" K(nω), C(nω) and every mode at its own frequency; fitted for a0 = ω d/V_s ≤ {A0_FITTED:g}.")
        coupling = ("coupled: sway-rocking terms K_x,ry and K_y,rx (and C) from the fixed heads' K_HM" if p.head == "fixed"
                    else "pinned heads carry no moment (K_HM = 0): no sway-rocking terms")
        if p.cap_contact:
            cap = (f"the cap bears on the soil: the footing's springs and dashpots of soil.method = {self.method!r}"
                   " (uncoupled) in parallel, full contact, no uplift")
        elif self.D:
            cap = (f"the cap does not bear on the soil; its sidewalls, embedded {self.D:g} m, add the footing's embedded"
                   f" less surface springs and dashpots of soil.method = {self.method!r} (uncoupled) in parallel")
        else:
            cap = "the cap does not bear on the soil (piles.cap_contact = false): the piles alone carry the block"
        base = (f"Linear springs and dashpots at O, {coupling}; where the heads are not symmetric about O, vertical-"
                "rocking and sway-torsion terms through their lever arms (the group's K and C in the soil section"
                f" show every term). Piles elastic and bonded to the soil (no gapping or slip); {cap}; no layering"
                " beyond the modulus profile, no coupling through the soil with neighbouring foundations.")
        return Assumption("soil", soil), Assumption("base", base)

    def not_checked(self, limits) -> tuple[str, ...]:
        """The piles' own terms: their capacity and strength, which no check judges, and the group's
        static settlement W/K_z (K_z the group's) where ``limits`` give no allowable; the cap's
        bearing pressure only where the cap bears on the soil (``piles.cap_contact``)."""
        bearing = ["static bearing pressure under the cap (no [limits] bearing_pressure)"] if (
            self.piles.cap_contact and limits.bearing_pressure is None) else []
        settlement = [] if limits.settlement is not None else [
            "static settlement of the pile group W/K_z (no [limits] settlement)"]
        return (*bearing, *settlement, "the piles' axial and lateral capacity, negative skin friction, their structural"
                " strength (bending, shear, buckling, the heads' connection to the cap) and the dynamic forces in them")

    def sheet(self, model, orders) -> list:
        """The single pile's static springs as a hand calculation, then the group's method and its
        springs and dashpots at O at rest."""
        rest = self.at_frequencies({})[0]
        K, C = (np.where(np.abs(X) > 1e-12 * np.abs(X).max(), X, 0.0) for X in rest.group)  # round-off of the sums
        head = ("", *MOTIONS)
        p = self.piles
        text = (f"{len(p.positions)} piles under the rigid cap (the block's base, O its centre). Under the cap's motion q the"
                " heads move w_i = u_z + y_i θ_x − x_i θ_y, u_x,i = u_x − y_i θ_z, u_y,i = u_y + x_i θ_z. With the"
                " interaction factors of [DG] (α_v = √(r0/S) e^{−(β+i)ωS/V_s}; horizontal α(0°) cos²θ + α(90°) sin²θ,"
                " α(0°) at V_La = 3.4 V_s/(π(1 − ν))), A_ij = α(S_ij), the head forces are P = K_1 A⁻¹ u in each direction"
                " and the cap's springs K = Σ Dᵀ K_1 A⁻¹ D (a linear solve, not a hand calculation), plus each pile's own"
                " K_MM, K_HM and K_T. At frequency ω each single-pile spring is the static one times its Winkler shape χ^{p}"
                " ([MG]); the dashpots C = Im K(ω)/ω, their symmetric part kept positive semi-definite. Efficiency at rest:"
                f" η_x = {rest.efficiency['x']:.3g}, η_z = {rest.efficiency['z']:.3g} (group over n single piles).")
        out = [single_pile_chain(self.soil, p), Text(text),
               Grid("The group's springs at O at rest, K [N/m, N/rad, N m/rad] (the coupling off the diagonal)", head,
                    MOTIONS, K),
               Grid("The group's dashpots at O at rest, C [N s/m, N s/rad, N m s/rad]", head, MOTIONS, C)]
        if p.cap_contact or self.D:
            out.append(Text("The cap's own contact with the soil (piles.cap_contact, or the sidewalls of block.embedment)"
                            " adds the footing's springs and dashpots of soil.method in parallel (not in the tables above)."))
        return out


def single_pile_chain(soil, p) -> HandCalc:
    """The static head springs of one of the piles ``p`` (the ``[piles]`` table) in ``soil`` (:func:`~foundation_calc.solvers.piles.single.single_pile` at ω = 0)."""
    from foundation_calc.solvers.piles.single import ACTIVE_LENGTH_EXPONENT, PILE_POISSON, TABLE_C1

    chain = Rows()
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
    return HandCalc(f"One pile's static head springs ({p.head} head, {p.tip.replace('_', '-')}, soil {p.soil_profile})",
                    tuple(chain))



def build(scene, L, B, masses):
    """A block scene with ``[piles]`` stands on them."""
    if getattr(scene, "piles", None) is None:
        return None
    return Piles(scene.soil, L, B, masses, scene.embedment)


__all__ = ["SINGLE_ROWS", "VARIABLES", "Piles", "PilesAt", "build", "single_pile_chain"]
