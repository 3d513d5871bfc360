"""A crank foundation on a support that gives no soil method's chain in the plane (a pile group):
the sheet's springs, dashpots and natural frequencies from the plane's one model.

The paper's chain (the soil method's K_z, K_x, K_φ and damping ratios, then [KM] (4.5)-(4.7)) takes
three uncoupled springs; a pile group couples sway with rocking (K_xφ, C_xφ), so its sheet states
instead, each reproducible by hand from what the sheet prints:

- where the springs come from: the support's own sheet items (:meth:`~foundation_calc.solvers.supports.base.Support.sheet`,
  rendered as the block's sheet renders them, :func:`~foundation_calc.output.report.block_soil.rendered`),
  then the plane's K_x, K_z, K_φ, K_xφ and C_x, C_z, C_φ, C_xφ at O at every frequency the checks
  took them (rest, each harmonic n ω the damped solve lists, each mode's own ω*);
- the natural frequencies about C (the centre of mass of block and machine, the paper's x, y, θ):
  the mechanism's averaged inertia M̄ (:func:`~foundation_calc.solvers.crank.averaged.averaged_operator`)
  and the springs moved from O to C (u_x = x − h θ at O), K̄_xθ = K_xφ − h K_x,
  K̄_θθ = K_φ − 2 h K_xφ + h² K_x − P h − g M̄_xθ (the weight's tilt of block and machine at C, and
  of the moving masses at their mean height above C). y decouples: k0 = √(K_z/M_tot). Sway and
  rocking: det(K̄ − p² M̄) = 0 in the plane (x, θ) is A2 p⁴ − A1 p² + A0 = 0 with
  A2 = M_tot M̄_θθ − M̄_xθ², A1 = K_x M̄_θθ + K̄_θθ M_tot − 2 K̄_xθ M̄_xθ, A0 = K_x K̄_θθ − K̄_xθ²,
  p1,2² = (A1 ∓ √(A1² − 4 A2 A0))/(2 A2). These are the frequencies ``fcalc resonance`` reports
  (its zero-order and averaged-inertia values are one on a coupled support), each mode at its own
  frequency ω* = p(K(ω*)) on a frequency-dependent support.

``tests/test_crank_piles_report.py`` re-solves the printed numbers by a brute-force eigen-solve.
"""

from __future__ import annotations

from foundation_calc.output.report.handcalc import Chain, Columns
from foundation_calc.output.report.model import Paragraph, table
from foundation_calc.output.report.numbers import column
from foundation_calc.solvers.constants import GRAVITY

#: The plane's springs and dashpots at O: (symbol, unit, meaning), K then C.
SPRINGS = (("K_x", "N/m", "sliding spring at O"), ("K_z", "N/m", "vertical spring at O"),
           ("K_φ", "N m/rad", "rocking spring at O about the base axis"), ("K_xφ", "N/rad", "sway-rocking coupling at O"))
DASHPOTS = (("C_x", "N s/m", "sliding dashpot at O"), ("C_z", "N s/m", "vertical dashpot at O"),
            ("C_φ", "N m s/rad", "rocking dashpot at O"), ("C_xφ", "N s/rad", "sway-rocking dashpot coupling at O"))
#: Significant figures of the plane's springs and dashpots (the frequency chain's inputs).
DIGITS = 6
#: Where the sway-rocking steps come from.
PLANE_MODEL = "plane model (averaged operator about C)"


def by_soil_method(scene) -> bool:
    """True when the scene's support gives a soil method's springs and damping ratios in the plane
    (the paper's chain); False for a pile group or another support stated by its own sheet."""
    return hasattr(scene.support(), "plane_springs")


def in_plane(scene, omega: float) -> tuple[list[float], list[float]]:
    """([K_x, K_z, K_φ, K_xφ], [C_x, C_z, C_φ, C_xφ]) at O at ``omega`` [rad/s], as the checks take them."""
    (K_x, K_z, K_phi), (C_x, C_z, C_phi), (K_xphi, C_xphi), _ = scene.in_plane(omega)
    return [K_x, K_z, K_phi, K_xphi], [C_x, C_z, C_phi, C_xphi]


def rest_table(scene):
    """The inputs section's table: the plane's springs and dashpots at O at rest."""
    K, C = in_plane(scene, 0.0)
    rows = [(symbol, text, unit, meaning) for (symbol, unit, meaning), text in
            zip(SPRINGS + DASHPOTS, column([*K, *C], DIGITS))]
    return table(f"[{scene.support().label}] springs and dashpots in the plane at O at rest (the methods section derives them)",
                 ("quantity", "value", "unit", "meaning"), rows, (False, True, False, False), literal=(0,))


def _frequency_table(scene, entries: list[tuple[str, float]]) -> list:
    """Two tables, springs and dashpots at O, a row per (label, ω) of ``entries``."""
    found = [in_plane(scene, w) for _, w in entries]
    speeds = column([w for _, w in entries], DIGITS)
    out = []
    for k, (names, what) in enumerate(((SPRINGS, "Springs"), (DASHPOTS, "Dashpots"))):
        cols = [column([f[k][j] for f in found], DIGITS) for j in range(4)]
        rows = [(label, speeds[i], *(c[i] for c in cols)) for i, (label, _) in enumerate(entries)]
        out.append(table(f"{what} in the plane at O at each frequency the checks took them",
                         ("at", "ω [rad/s]", *(f"{s} [{u}]" for s, u, _ in names)), rows, (False, *(True,) * 5)))
    return out


def _closed_form_chain(scene, omega_s: float) -> Chain:
    """k0, p1, p2 of [KM] (4.5)-(4.7) on the support's springs at ``omega_s`` where it leaves sway
    and rocking uncoupled (K_xφ = 0: pinned heads), as the resonance check takes them."""
    from foundation_calc.output.report.crank_frequencies import frequency_givens, frequency_steps

    K, _ = in_plane(scene, omega_s)
    chain = Chain("")
    chain.given("omega_s", omega_s, "rad/s", "circular frequency at which the springs are taken (a mode's own ω*)")
    frequency_givens(chain, scene)
    for name, value, (symbol, unit, meaning) in zip(("K_xw", "K_zw", "K_phiw"), K, SPRINGS):
        chain.given(name, value, unit, f"{meaning.replace(' at O', '')} at O at ω*")
    frequency_steps(chain, "K_zw", "K_xw", "K_phiw")
    return chain


def _mode_chain(scene, omega_s: float) -> Chain:
    """k0, p1, p2 of the plane model on the springs at ``omega_s`` (module docstring)."""
    from foundation_calc.solvers.crank.averaged import averaged_operator

    M = averaged_operator(scene.design(omega_s))[0]
    K, _ = in_plane(scene, omega_s)
    chain = Chain("")
    chain.given("omega_s", omega_s, "rad/s", "circular frequency at which the springs are taken (a mode's own ω*)")
    chain.given("M_tot", scene.total_mass, "kg", "total vibrating mass (block, machine, rod and slider), M̄_xx = M̄_yy")
    chain.given("M_xt", M[0, 2], "kg m", "averaged sway-rocking mass about C, M̄_xθ (the moving masses' mean height above C times m)")
    chain.given("M_tt", M[2, 2], "kg m²", "averaged moment of inertia about C, M̄_θθ (I_c and the mechanism's mean)")
    chain.given("h", scene.foundation.cog_height, "m", "height of C above the base")
    chain.given("g", GRAVITY, "m/s²", "acceleration of gravity")
    for name, value, (symbol, unit, meaning) in zip(("K_xw", "K_zw", "K_phiw", "K_xphiw"), K, SPRINGS):
        chain.given(name, value, unit, f"{meaning.replace(' at O', '')} at O at ω*")
    chain.step("P", "M_tot*g", "N", "[KM] (3.4)", "weight of the vibrating mass")
    chain.step("k0", "sqrt(K_zw/M_tot)", "rad/s", f"{PLANE_MODEL}: y decouples", "vertical natural frequency")
    chain.step("K_xt", "K_xphiw - h*K_xw", "N/rad", f"{PLANE_MODEL}: u_x = x − h θ at O", "sway-rocking entry of K̄ about C")
    chain.step("K_tt", "K_phiw - 2*h*K_xphiw + h**2*K_xw - P*h - g*M_xt", "N m/rad",
               f"{PLANE_MODEL}; [KM] (3.4) −P h", "rocking entry of K̄ about C, less the weights' tilt")
    chain.step("A2", "M_tot*M_tt - M_xt**2", "kg² m²", "det(K̄ − p² M̄) = A2 p⁴ − A1 p² + A0", "coefficient of p⁴")
    chain.step("A1", "K_xw*M_tt + K_tt*M_tot - 2*K_xt*M_xt", "kg N m/rad", "det(K̄ − p² M̄) = A2 p⁴ − A1 p² + A0", "coefficient of −p²")
    chain.step("A0", "K_xw*K_tt - K_xt**2", "N²/rad", "det(K̄ − p² M̄) = A2 p⁴ − A1 p² + A0", "constant term")
    chain.step("p1", "sqrt((A1 - sqrt(A1**2 - 4*A2*A0))/(2*A2))", "rad/s", "root of the quadratic in p²", "lower sway-rocking frequency")
    chain.step("p2", "sqrt((A1 + sqrt(A1**2 - 4*A2*A0))/(2*A2))", "rad/s", "root of the quadratic in p²", "upper sway-rocking frequency")
    return chain


def plane_chains(scene, amplitudes: dict | None) -> list:
    """The support's sheet, its springs and dashpots in the plane at every frequency the checks
    took them, and k0, p1, p2 of each mode at its own frequency (module docstring)."""
    from foundation_calc.output.report.block_soil import rendered
    from foundation_calc.output.report.gazetas_frequencies import MODES, consistent_frequencies, frequency_table_rows, shown_harmonics

    support = scene.support()
    out = [block for item in support.sheet(None, []) for block in rendered(item, scene, None, [])]
    omega = scene.speed.omega_rad_s
    static, own = consistent_frequencies(scene) if support.frequency_dependent else ({}, {})
    harmonics = [1, *shown_harmonics(amplitudes)] if support.frequency_dependent else []
    entries = [("rest", 0.0), *((f"n = {n}", n * omega) for n in harmonics), *((f"ω* of {m}", own[m]) for m in own)]
    out.append(Paragraph(
        "The plane of the motion takes the rows and columns u_x, u_z, θ_y of the support's K and C at O: K_x, K_z, K_φ"
        " on the diagonal and the sway-rocking coupling K_xφ, C_xφ."
        + (" The damped solve takes them at each harmonic's n ω, the natural frequencies each mode at its own ω*."
           if support.frequency_dependent else "")))
    out += _frequency_table(scene, entries)
    at = own or {MODES[0]: 0.0}  # a frequency-independent support: one column on the static springs
    coupled = scene.design().coupled
    title = ("Natural frequencies of the plane model about C (the centre of mass, coordinates x, y, θ), the support's"
             " coupling K_xφ included: k0 from K_z, p1 and p2 the roots of det(K̄ − p² M̄) = 0 in (x, θ)" if coupled else
             "Natural frequencies of the zero-order operator on the support's springs, [KM] (4.5)-(4.7) (K_xφ = 0)")
    footer = None
    if own:
        title += "; each mode with the springs at its own ω*, where the mode's own row returns ω* = p(K(ω*))"
        footer = table("Natural frequencies: static springs and each mode at its own frequency (the resonance check's)",
                       ("mode", "static [rad/s]", "at ω* [rad/s]", "change"), frequency_table_rows(static, own))
    chains = [(_mode_chain if coupled else _closed_form_chain)(scene, w) for w in at.values()]
    lead = (("omega_s", "ω* = p(K(ω*))", "the resonance check's root, table below"),) if own else ()
    sources = {"M_tot": "derived quantities", "M_xt": "averaged operator (M̄ under Methods)", "M_tt": "averaged operator (M̄ under Methods)"}
    givens = ("M_tot", "M_xt", "M_tt", "K_xw", "K_zw", "K_phiw", "K_xphiw") if coupled else ("K_xw", "K_zw", "K_phiw")
    lead += tuple((name, "given", sources.get(name, "springs at O, table above")) for name in givens)
    heads = tuple(f"at ω* of {m}" for m in MODES) if own else ("static springs",)
    out.append(Columns(title, heads, chains, lead, footer))
    return out


__all__ = ["by_soil_method", "in_plane", "plane_chains", "rest_table"]
