"""Hand calculations on a sheet: formula with its source, the values substituted, the result.

A :class:`Chain` is written the way a checking engineer reads a Mathcad sheet: the inputs it uses
(:meth:`Chain.given`), then each step (:meth:`Chain.step`) as ``symbol = formula = values =
result unit`` with the equation's source. A step's formula is a Python expression over the
names given before; the chain evaluates it itself, so the number printed is the one the printed
formula gives with the printed inputs (tests compare it with the solvers' numbers). Every name
used is collected with its meaning and unit for the sheet's nomenclature.

>>> chain = Chain("Soil springs")
>>> chain.given("c_z", 1.0e6, "N/m³", "coefficient of elastic uniform compression")
>>> chain.given("S", 30.0, "m²", "base area")
>>> chain.step("K_z", "c_z*S", "N/m", "[KM] Eq. (3.2)", "vertical base spring")
30000000.0
>>> chain.rows[-1][:4]
('K_z', 'c_z·S', '1.000·10⁶ × 30.00', '3.000·10⁷')
"""

from __future__ import annotations

import math
import re

from foundation_calc.output.report.model import Table, table
from foundation_calc.output.report.numbers import figure

#: Significant figures of every number in a hand calculation.
DIGITS = 4

#: Names of the Python expressions -> the symbols printed.
SYMBOLS = {
    "pi": "π", "nu": "ν", "rho": "ρ", "c_phi": "c_φ", "K_phi": "K_φ", "xi_z": "ξ_z", "xi_x": "ξ_x",
    "xi_phi": "ξ_φ", "C_phi": "C_φ", "r0psi": "r0ψ", "B_phi": "B_φ", "D_phi": "D_φ", "omega": "ω",
    "mu": "μ", "lam": "λ", "zeta": "ζ", "eta": "η", "M_sigma": "M_Σ", "xi_m": "ξ_m", "omega_t": "ω_t",
    "Lh": "L'", "Bh": "B'", "chi": "χ", "eta_z": "η_z", "eta_h": "η_h", "eta_phi": "η_φ", "K_zs": "K_z,s",
    "K_hs": "K_h,s", "K_phis": "K_φ,s", "C_zb": "C_z", "V_La": "V_La", "b_sp": "b₀", "A10": "A₁₀",
    "K_zw": "K_z(ω)", "K_xw": "K_x(ω)", "K_phiw": "K_φ(ω)", "C_phiw": "C_φ(ω)", "xi_zw": "ξ_z(ω)", "xi_xw": "ξ_x(ω)",
    "xi_phiw": "ξ_φ(ω)", "k_phi": "k_φ", "c_rw": "c̃_r", "a_d": "a₀", "omega_s": "ω_s", "xi": "ξ", "c31_41": "(c31+c41)", "c11_21": "(c11+c21)", "c22_32": "(c22+c32)",
    "c12_42": "(c12+c42)", "omega_i": "ω_i", "rho_P": "ρ_P", "Omega_r": "Ω_r", "eta_s": "η_r",
    "l1": "l'", "l1_rod": "l'_rod", "zeta_z": "ζ_z", "zeta_zw": "ζ_z(ω)", "zeta_z2w": "ζ_z(2ω)",
    "l2": "l''", "rho_rod": "ρ_rod", "kappa": "κ", "g_s": "g*", "M_th1": "M_θ1", "k0w": "k0(ω)", "k02w": "k0(2ω)", "C_zw": "C_z(ω)", "K_z2w": "K_z(2ω)", "C_z2w": "C_z(2ω)",
    "xi_y": "ξ_y", "xi_rx": "ξ_rx", "xi_ry": "ξ_ry", "xi_rz": "ξ_rz", "xi_rzw": "ξ_rz(ω)", "K_rzw": "K_rz(ω)", "C_rzw": "C_rz(ω)",
    "C_xw": "C_x(ω)", "C_yw": "C_y(ω)", "C_rxw": "C_rx(ω)", "C_ryw": "C_ry(ω)", "eta_t": "η_t", "K_t0": "K_t,s", "r0t": "r0θ",
    "r0x": "r0ψx", "r0y": "r0ψy", "k_psi": "k_ψ", "c_psi": "c_ψ", "k_xi": "k_ξ", "c_zsp": "c_z,SP",
    "H_r": "H", "R_a": "R", "R_ry": "R_ry", "R_rx": "R_rx", "eta_ry": "η_ry", "eta_rx": "η_rx",
    "M_xt": "M̄_xθ", "M_tt": "M̄_θθ", "K_xt": "K̄_xθ", "K_tt": "K̄_θθ", "K_xphiw": "K_xφ(ω)",
    "Omega_dot": "Ω̇", "Omega_dot_r": "Ω̇_r", "Delta": "Δ", "beta": "β", "rho_G": "ρ_G", "muL": "μL",
}

_NAME = re.compile(r"[A-Za-z_][A-Za-z_0-9]*")
_MATH = {"sqrt": math.sqrt, "pi": math.pi, "abs": abs, "max": max, "min": min, "log": math.log, "tanh": math.tanh}
_POWERS = {"**2": "²", "**3": "³", "**4": "⁴", "**5": "⁵", "**0.5": "^½", "**0.25": "^¼"}


def _pretty(expression: str, names, times: str = "·") -> str:
    """The expression as printed: symbols for names, ``times`` for *, superscripts, √."""
    text = expression
    for power, shown in _POWERS.items():  # not **2 of **2.45
        text = re.sub(re.escape(power) + r"(?![0-9.])", shown, text)
    text = re.sub(r"\*\*\(([0-9./]+)\)", r"^{\1}", text)  # an exponent in fcalc's plain form, typeset as one
    text = re.sub(r"\*\*([0-9.]+)", r"^{\1}", text)
    text = text.replace("*", times).replace("/", " / ").replace("sqrt", "√")
    return _NAME.sub(lambda m: names(m.group()), text)


class Chain:
    """One hand calculation: inputs and steps, in order, for one section of the sheet."""

    def __init__(self, title: str):
        self.title = title
        self.values: dict[str, float] = {}
        self.rows: list[tuple[str, str, str, str, str, str]] = []
        self.nomenclature: dict[str, tuple[str, str]] = {}

    def given(self, name: str, value: float, unit: str, meaning: str) -> None:
        """An input of the chain (from the scene or an earlier section)."""
        self.values[name] = float(value)
        self.nomenclature[SYMBOLS.get(name, name)] = (meaning, unit)

    def step(self, name: str, expression: str, unit: str, source: str, meaning: str) -> float:
        """Evaluate ``expression`` over the names given, record the row and return the value."""
        value = float(eval(expression, {"__builtins__": {}}, {**_MATH, **self.values}))  # our own formulas only
        formula = _pretty(expression, lambda n: SYMBOLS.get(n, n))
        substituted = _pretty(expression, lambda n: SYMBOLS.get(n, n) if n in _MATH else figure(self.values[n], DIGITS), " × ")
        symbol = SYMBOLS.get(name, name)
        self.rows.append((symbol, formula, substituted, figure(value, DIGITS), unit, source))
        self.values[name] = value
        self.nomenclature[symbol] = (meaning, unit)
        return value

    def blocks(self) -> tuple[Table, ...]:
        """What the chain puts on the sheet: its table."""
        return (self.table(),)

    def table(self) -> Table:
        """The chain as a table: symbol, formula, values substituted, result, unit, source."""
        return table(
            self.title, ("", "formula", "values", "result", "unit", "source"), self.rows,
            (False, False, False, True, False, False),
        )


class Definitions:
    """Symbols a section uses outside a chain (a solve's matrices, a table's columns), for the
    nomenclature: ``{symbol: (meaning, unit)}``; it puts nothing on the sheet itself."""

    def __init__(self, entries: dict[str, tuple[str, str]]):
        self.nomenclature = dict(entries)

    def blocks(self) -> tuple:
        return ()


def nomenclature_table(chains) -> Table:
    """Every symbol of ``chains`` with its meaning and unit, in order of first use."""
    seen: dict[str, tuple[str, str]] = {}
    for chain in chains:
        for symbol, entry in chain.nomenclature.items():
            seen.setdefault(symbol, entry)
    return table("Nomenclature", ("symbol", "meaning", "unit"), ((s, m, u) for s, (m, u) in seen.items()), (False, False, False))


class Columns:
    """One chain evaluated at several values of its inputs (the harmonics' frequencies, the
    modes' own frequencies): a row per step, a result column per chain, the inputs that differ
    between the columns (``lead``) as the first rows. The chains must take the same steps."""

    def __init__(self, title: str, heads: tuple[str, ...], chains: list[Chain], lead: tuple[tuple[str, str, str], ...] = (),
                 footer: Table | None = None):
        self.title = title
        self.footer = footer
        self.heads = tuple(heads)
        self.chains = list(chains)
        first = self.chains[0]
        self.nomenclature = first.nomenclature
        self.values = [chain.values for chain in self.chains]
        rows = [(SYMBOLS.get(name, name), how, *(figure(c.values[name], DIGITS) for c in self.chains), first.nomenclature[SYMBOLS.get(name, name)][1], source)
                for name, how, source in lead]
        for i, (symbol, formula, _, _, unit, source) in enumerate(first.rows):
            rows.append((symbol, formula, *(chain.rows[i][3] for chain in self.chains), unit, source))
        self.rows = rows

    def blocks(self) -> tuple[Table, ...]:
        """What the columns put on the sheet: their table and the footer table, if any."""
        return (self.table(),) if self.footer is None else (self.table(), self.footer)

    def table(self) -> Table:
        """The columns as a table: symbol, formula, a result per column, unit, source."""
        n = len(self.heads)
        return table(self.title, ("", "formula", *self.heads, "unit", "source"), self.rows,
                     (False, False, *(True,) * n, False, False))
