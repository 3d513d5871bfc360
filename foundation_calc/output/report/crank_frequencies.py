"""The zero-order natural frequencies of the crank foundation as a hand calculation, [KM] (4.5)-(4.7).

Shared by the sheet's frequency chain on static springs (:mod:`.methods`) and on the springs at
the consistent frequencies (:mod:`.gazetas_frequencies`).
"""

from __future__ import annotations

from foundation_calc.output.report.handcalc import Chain
from foundation_calc.solvers.constants import GRAVITY

KM = "[KM]"


def frequency_steps(chain: Chain, K_z: str = "K_z", K_x: str = "K_x", K_phi: str = "K_phi") -> None:
    """Add to ``chain`` k0, p1, p2 of the zero-order operator [KM] (4.5)-(4.7) on the springs
    named ``K_z``, ``K_x``, ``K_phi`` (M_tot, I_c, h, g given before)."""
    chain.step("P", "M_tot*g", "N", f"{KM} (3.4)", "weight of the vibrating mass")
    chain.step("k0", f"sqrt({K_z}/M_tot)", "rad/s", f"{KM} (4.5)", "vertical natural frequency")
    chain.step("a0", f"{K_x}/M_tot", "1/s²", f"{KM} (4.5)", "sliding coefficient")
    chain.step("b0", f"{K_x}*h/M_tot", "m/s²", f"{KM} (4.5)", "sliding-rocking coupling")
    chain.step("a1", f"{K_x}*h/I_c", "1/(m s²)", f"{KM} (4.5)", "rocking-sliding coupling")
    chain.step("b1", f"({K_x}*h**2 + {K_phi} - P*h)/I_c", "1/s²", f"{KM} (4.5), weight term −P h corrected", "rocking coefficient")
    chain.step("p2", "sqrt((a0 + b1)/2 + sqrt(((a0 - b1)/2)**2 + a1*b0))", "rad/s", f"{KM} (4.7)", "upper sliding-rocking frequency")
    chain.step("p1", "sqrt((a0*b1 - a1*b0)/p2**2)", "rad/s", f"{KM} (4.7)", "lower sliding-rocking frequency")


def frequency_givens(chain: Chain, scene) -> None:
    """The block's mass, inertia and height of C that (4.5)-(4.7) take."""
    f = scene.foundation
    chain.given("M_tot", scene.total_mass, "kg", "total vibrating mass (block, machine, rod and slider)")
    chain.given("I_c", f.moment_of_inertia, "kg m²", "moment of inertia of the block about its centre of mass C")
    chain.given("h", f.cog_height, "m", "height of C above the base")
    chain.given("g", GRAVITY, "m/s²", "acceleration of gravity")
