"""The stratum over rigid bedrock on the sheet (``[soil] stratum_depth``): its static factors and
cutoff frequencies as a hand calculation, and which dashpots radiate at every frequency the checks
judged (:mod:`~foundation_calc.solvers.soil.stratum`; the judged frequencies and motions are those
of the soil model's validity, :mod:`~foundation_calc.checks.soil_validity`, as the ``resonance`` and
``amplitudes`` documents hold them)."""

from __future__ import annotations

from foundation_calc.output.report.handcalc import Chain
from foundation_calc.output.report.model import Paragraph, table
from foundation_calc.output.report.numbers import figure

KA = "[Ka]"


class Shown:
    """A paragraph or table among a sheet's chains: it puts itself on the sheet, names no symbol."""

    nomenclature: dict = {}

    def __init__(self, block):
        self.block = block

    def blocks(self) -> tuple:
        return (self.block,)
CUT = "[Ka]; [NIST] 2.2.3"


def stratum_chain(soil, L: float, B: float, block: bool) -> Chain:
    """Kausel's factors on the equivalent radii of the base L (along x, the plane of motion) × B [m]
    and the cutoffs f_s = V_s/4H, f_c = V_La/4H; ``block``: both rocking axes (else about y only)."""
    chain = Chain(f"Stratum over rigid bedrock (soil.stratum_depth = {soil.stratum_depth:g} m): static factors"
                  " on the half-space springs and cutoff frequencies of the radiation")
    chain.given("H_r", soil.stratum_depth, "m", "depth of the soil layer from the surface to rigid bedrock")
    chain.given("L", L, "m", "base length along x (in the plane of motion)")
    chain.given("B", B, "m", "base width along y")
    chain.given("V_s", soil.V_s, "m/s", "shear wave velocity of the soil")
    chain.given("nu", soil.poisson, "-", "Poisson's ratio of the soil")
    chain.step("R_a", "sqrt(B*L/pi)", "m", KA, "radius of the circle of the base's area")
    chain.step("R_ry", "(B*L**3/(3*pi))**0.25", "m", KA, "radius of the circle of the base's second moment about y")
    chain.step("eta_z", "1 + 1.28*R_a/H_r", "-", KA, "stratum factor on the vertical spring")
    chain.step("eta_h", "1 + R_a/(2*H_r)", "-", KA, "stratum factor on the horizontal springs")
    chain.step("eta_ry", "1 + R_ry/(6*H_r)", "-", KA, "stratum factor on the rocking spring about y")
    if block:
        chain.step("R_rx", "(L*B**3/(3*pi))**0.25", "m", KA, "radius of the circle of the base's second moment about x")
        chain.step("eta_rx", "1 + R_rx/(6*H_r)", "-", KA, "stratum factor on the rocking spring about x")
    chain.step("V_La", "3.4*V_s/(pi*(1 - nu))", "m/s", "[Ga] Table 1", "Lysmer's analog wave velocity")
    chain.step("f_s", "V_s/(4*H_r)", "Hz", CUT, "cutoff of the shear motions (sway, torsion)")
    chain.step("f_c", "V_La/(4*H_r)", "Hz", CUT, "cutoff of the compression motions (vertical, rocking)")
    return chain


def radiation_table(validity: dict | None):
    """Per judged frequency and motion: the radiation dashpot kept (at or above the motion's cutoff)
    or material damping only (below), from a document's ``soil_validity`` (None without one)."""
    stratum = (validity or {}).get("stratum")
    if not stratum:
        return None
    shear = ("x", "y", "rz", "horizontal")
    rows: dict[tuple[str, float], dict[str, str]] = {}
    for v in validity["values"]:
        cutoff = stratum["cutoff_shear"] if v["motion"] in shear else stratum["cutoff_compression"]
        rows.setdefault((v["at"], v["omega"]), {})[v["motion"]] = "radiation" if v["omega"] >= cutoff else "material only"
    motions = list(dict.fromkeys(m for cells in rows.values() for m in cells))
    body = [(at, figure(omega / (2 * 3.141592653589793), 4), *(cells.get(m, "-") for m in motions))
            for (at, omega), cells in rows.items()]
    return table("Dashpots at each judged frequency on the stratum: the half-space's radiation dashpot at or above the"
                 " motion's cutoff, material damping only below (motions that hold at least 1 % of a mode's strain energy)",
                 ("at", "f [Hz]", *motions), body, (False, True, *(False,) * len(motions)))


def stratum_blocks(soil, L: float, B: float, block: bool, document: dict | None) -> list:
    """The stratum's chain, how it changes the springs and dashpots, and the radiation table of the
    ``document`` (the ``amplitudes`` or ``resonance`` JSON) of the footing on ``soil`` (its ``[soil]``
    data; None: a support that is no footing); nothing without ``stratum_depth``."""
    if getattr(soil, "stratum_depth", None) is None:
        return []
    out: list = [stratum_chain(soil, L, B, block), Shown(Paragraph(
        "On the stratum every half-space spring above is multiplied by its factor (K_z by η_z, K_x and K_y by η_h,"
        " the rocking springs by η_ry, η_rx; torsion unchanged), and each radiation dashpot is the half-space's at or"
        " above its motion's cutoff (f_s for x, y and torsion; f_c for z and rocking) and zero below, where only the"
        " soil's material damping ξ_m acts: ξ = g ξ_rad/√η + ξ_m, g = 1 at or above the cutoff, 0 below. The"
        " solver's springs and dashpots at each frequency include both."))]
    radiation = radiation_table((document or {}).get("soil_validity"))
    if radiation is not None:
        out.append(Shown(radiation))
    return out


__all__ = ["Shown", "radiation_table", "stratum_blocks", "stratum_chain"]
