"""The governing passage of each run by hand: Lewis' peak, the steady resonance peak and the
integration they check.

A run's judged peak comes from a time integration of the whole linear model
(:mod:`foundation_calc.solvers.numerics.runup`); a checker cannot repeat it. Beside it the sheet
works the passage that governs the run (the passage whose mode the integration moves most at its
point) as a single mode swept linearly through its resonance, every step with its values:

    Ω̇ = ω/T,  Ω̇_r = r Ω̇,  η = Ω̇_r/ω_i²,  x_st = F_m ρ_P/ω_i²       (the ramp; the sweep rate)
    A_L = 1.467/√η                                                   (Lewis [Le], undamped)
    A_ss = 1/(2ζ √(1 − ζ²))                                          (the steady resonance peak)
    x_p = min(A_L, A_ss) x_st,  Δ = x_p/x_int − 1

A passage can reach neither bound: Lewis' is the undamped peak of a fast sweep, the steady
resonance peak (the maximum of 1/√((1 − ν²)² + (2ζν)²), for a constant force and for an
unbalance whose force grows as ν² alike) the limit of a slow one. The smaller is therefore the
closed form of a passage at either end: for ζ/√η ≥ 3 (a slow sweep) within 5 % of the damped
passage (the Faddeeva envelope of :mod:`~foundation_calc.solvers.numerics.passage`: ≤ 1 % for a
constant force, ≤ 4 % for an unbalance at ζ = 0.15), and high, on the safe side, by up to 60 % for
0.3 ≤ ζ/√η ≤ 1 where neither bound is reached. ``tests/test_report_runup_governing.py``
reproduces every step from the printed values and compares x_p with the integration.

The modal inputs ω_i, ζ = φᵀCφ/(2ω_i), F_m = |φᵀ(A Ω_r² + B)| and ρ_P = |T_P φ| are those of the
sheet's passage table (:mod:`~foundation_calc.output.report.runup_methods`); the mode shape φ
(mass-normalised) is printed under the calculation so that they follow from the printed matrices.
"""

from __future__ import annotations

import numpy as np

from foundation_calc.output.report.handcalc import Chain
from foundation_calc.output.report.model import Paragraph
from foundation_calc.output.report.numbers import figure

#: What the closed form is worth against a damped passage (module docstring), printed under it.
VALIDITY = (
    "A passage reaches neither bound: A_L is the undamped peak of a fast sweep, A_ss the limit of a slow one;"
    " for β = ζ/√η ≥ 3 (a slow sweep) x_p is within 5 % of the damped passage, for 0.3 ≤ β ≤ 1 it is high,"
    " on the safe side, by up to 60 %."
)

#: Source of the steady resonance peak, as the chain's source column prints it.
STEADY = "max of 1/√((1 − ν²)² + (2ζν)²)"


def governing(run: dict) -> int | None:
    """Index of the passage of ``run`` (a ``runup`` document's run) whose mode the integration moves
    most (its ``integrated_peak``), the first of equals; None without passages."""
    peaks = [p["integrated_peak"] for p in run["passages"]]
    return int(np.argmax(peaks)) if peaks else None


def governing_chain(title: str, omega: float, duration: float, passage: dict, modal: dict) -> Chain:
    """The hand calculation of one passage (module docstring); ``modal``: the passage table's
    chain values (``omega_i``, ``zeta``, ``F_m``, ``rho_P``, ``C_L``) of that passage."""
    chain = Chain(title)
    chain.given("omega", omega, "rad/s", "operating speed")
    chain.given("T", duration, "s", "duration of the linear ramp")
    chain.given("r", passage["harmonic"], "-", "order of the harmonic that passes it (speed ratio)")
    chain.given("omega_i", modal["omega_i"], "rad/s", "natural frequency of the mode passed")
    chain.given("zeta", modal["zeta"], "-", "modal damping ratio φᵀCφ/(2ω_i)")
    chain.given("F_m", modal["F_m"], "N (modal)", "modal force of the harmonic at the passage, |φᵀ(A Ω_r² + B)|")
    chain.given("rho_P", modal["rho_P"], "m (modal)", "motion of the point per unit of the mode, |T_P φ|")
    chain.given("C_L", modal["C_L"], "-", "Lewis' coefficient (1.467 in print)")
    chain.given("x_int", passage["integrated_peak"], "m", "peak of the mode's motion at the point in the time integration")
    chain.step("Omega_dot", "omega/T", "rad/s²", "[FC] linear ramp", "angular acceleration of the shaft on the ramp")
    chain.step("Omega_dot_r", "r*Omega_dot", "rad/s²", "[FC] linear ramp", "sweep rate of the harmonic's frequency, r Ω̇")
    chain.step("eta_s", "Omega_dot_r/omega_i**2", "-", "[Le]", "sweep rate Ω̇ r / ω_i²")
    chain.step("x_st", "F_m/omega_i**2*rho_P", "m", "[Le]", "static deflection of the mode's force at the point")
    chain.step("A_L", "C_L/sqrt(eta_s)", "-", "[Le] (undamped)", "Lewis' peak amplification, fast sweep")
    chain.step("beta", "zeta/sqrt(eta_s)", "-", "[Le]", "damping against sweep rate, ζ/√η: ≥ 3 a slow sweep")
    if modal["zeta"] > 0.0:
        chain.step("A_ss", "1/(2*zeta*sqrt(1 - zeta**2))", "-", STEADY, "steady resonance amplification, slow sweep")
        chain.step("A_p", "min(A_L, A_ss)", "-", "the smaller bound", "peak amplification of the passage")
    else:
        chain.step("A_p", "A_L", "-", "[Le] (undamped)", "peak amplification of the passage")
    chain.step("x_p", "A_p*x_st", "m", "[Le]", "closed-form peak of the governing passage")
    chain.step("Delta", "100*(x_p/x_int - 1)", "%", "closed form against integration", "difference of the closed form from the integration")
    return chain


def _run_chains(scene, runup: dict):
    """(key, run, passage, chain) of every run with passages, its governing passage worked."""
    from foundation_calc.checks.runup import run_title
    from foundation_calc.output.report.runup_methods import passage_chain, runup_structures, sheet_modes
    from foundation_calc.output.runup import mode_label

    structures = runup_structures(scene)
    for key, run in runup["runs"].items():
        k = governing(run)
        if k is None:
            continue
        kind, _, machine = key.partition(":")
        structure, names, omega = structures[f":{machine}" if machine else ""]
        passage = run["passages"][k]
        modes = sheet_modes(structure, run["natural_frequencies"])
        modal = passage_chain(structure, list(names), omega, run["duration"], 1 if kind == "run_up" else -1, passage, modes).values
        title = (f"{run_title(key).capitalize()}: governing passage by hand, mode {mode_label(passage['mode'] - 1, run.get('mode_names'))},"
                 f" {passage['harmonic']:g}ω at {passage['point']} (Lewis' and the steady resonance peak)")
        shape = modes[1][:, passage["mode"] - 1]
        yield key, run, passage, governing_chain(title, omega, run["duration"], passage, modal), shape


class GoverningPassage:
    """One run's governing passage: its chain's table and the mode shape it used, for the
    Methods section (``blocks`` and ``nomenclature`` as a :class:`Chain`'s)."""

    def __init__(self, chain: Chain, shape: np.ndarray, mode: str):
        self.chain = chain
        self.nomenclature = chain.nomenclature
        self.values = chain.values
        self.shape = shape
        self.mode = mode

    def blocks(self) -> tuple:
        phi = ", ".join(figure(float(v), 4) for v in self.shape)
        return (self.chain.table(), Paragraph(
            f"Mode {self.mode}, mass-normalised (φᵀMφ = 1; the order of the sheet's M, C, K): φ = ({phi});"
            " ω_i² = φᵀKφ, ζ = φᵀCφ/(2ω_i), F_m = |φᵀ(A Ω_r² + B)| with the harmonic's load at the passage's speed."
            f" {VALIDITY}"))


def governing_blocks(scene, runup: dict) -> list[GoverningPassage]:
    """The governing passage of every run with passages, worked by hand (module docstring)."""
    from foundation_calc.output.runup import mode_label

    return [GoverningPassage(chain, shape, mode_label(p["mode"] - 1, run.get("mode_names")))
            for _, run, p, chain, shape in _run_chains(scene, runup)]


def governing_lines(scene, runup: dict, units) -> dict[str, Paragraph]:
    """Run key -> one line for under its passage table: the governing passage's closed form x_p
    beside the integration and the run's judged peak (``units`` the sheet's display units)."""
    out = {}
    for key, run, p, chain, _ in _run_chains(scene, runup):
        v, a = chain.values, units.label("amplitude")
        amplification = "min(A_L, A_ss)" if "A_ss" in v else "A_L"
        judged = max(run["transient_points"].values())
        out[key] = Paragraph(
            f"Governing passage (worked by hand in the Methods): mode {p['mode']}, {p['harmonic']:g}ω at {p['point']},"
            f" η = {figure(v['eta_s'], 4)}, ζ = {figure(v['zeta'], 4)}: closed form x_p = {amplification} x_st ="
            f" {figure(units.convert('amplitude', v['x_p']), 4)} {a} against {figure(units.convert('amplitude', v['x_int']), 4)} {a}"
            f" integrated (this mode), Δ = {v['Delta']:+.1f} %; the run's judged peak (every mode, at its point)"
            f" {figure(units.convert('amplitude', judged), 4)} {a}."
        )
    return out


__all__ = ["GoverningPassage", "governing", "governing_blocks", "governing_chain", "governing_lines"]
