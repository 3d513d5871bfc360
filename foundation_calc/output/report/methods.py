"""The methods section of a sheet as hand calculations, only for what the scene used.

Each chain starts from the scene's numbers and ends in a number a check judged (or that feeds
one): the soil's springs and damping by the scene's method, the natural frequencies, the base
dashpots of a damped scene, the platform's design. The chains evaluate their own printed
formulas (:mod:`~foundation_calc.output.report.handcalc`); ``tests/test_report_methods.py``
compares every end value with the solvers'.
"""

from __future__ import annotations

from foundation_calc.output.report.crank_frequencies import KM, frequency_givens, frequency_steps
from foundation_calc.output.report.handcalc import Chain
from foundation_calc.output.report.platform_methods import platform_chain
from foundation_calc.output.report.soil_methods import (LYSMER_RADII, RHW, dashpot, gazetas_chains, lysmer_ratio, lysmer_spring,
                                                        soil_givens, sp26_springs_chain)
from foundation_calc.output.report.stratum import stratum_blocks
from foundation_calc.scenes.soil import FREQUENCY_DEPENDENT_METHODS


def _coefficient_springs(scene) -> Chain:
    f, s = scene.foundation, scene.soil
    chain = Chain("Soil springs from Barkan's coefficients (soil.method = \"coefficients\")")
    chain.given("S", f.base_area, "m²", "area of the base")
    chain.given("I1", f.base_second_moment, "m⁴", "second moment of the base area about its axis normal to the plane")
    chain.given("c_z", s.c_z, "N/m³", "coefficient of elastic uniform compression")
    chain.given("c_x", s.c_x, "N/m³", "coefficient of elastic uniform shear")
    chain.given("c_phi", s.c_z if s.c_phi is None else s.c_phi, "N/m³",
                "coefficient of elastic non-uniform compression (rocking; c_z unless soil.c_phi is given)")
    chain.step("K_z", "c_z*S", "N/m", f"{KM} (3.2); [Ba]", "vertical base spring")
    chain.step("K_x", "c_x*S", "N/m", f"{KM} (3.3); [Ba]", "horizontal base spring")
    chain.step("K_phi", "c_phi*I1", "N m/rad", f"{KM} (3.4); [Ba]", "rocking base spring")
    return chain


def _lysmer_springs(scene) -> Chain:
    chain = Chain("Soil springs and radiation damping: Lysmer's and Hall's analogs (soil.method = \"lysmer\")")
    soil_givens(chain, scene)
    chain.step("r0", LYSMER_RADII["area"], "m", RHW, "radius of the circle of the base's area")
    chain.step("r0psi", LYSMER_RADII["about y"], "m", RHW, "radius of the circle of the base's second moment")
    for motion, K, B, xi, r, m, meanings in (
        ("vertical", "K_z", "B_z", "xi_z", "r0", "M_tot", ("vertical base spring", "vertical mass ratio", "vertical damping ratio")),
        ("sliding", "K_x", "B_x", "xi_x", "r0", "M_tot", ("horizontal base spring", "horizontal mass ratio", "horizontal damping ratio")),
        ("rocking", "K_phi", "B_phi", "xi_phi", "r0psi", "I_0", ("rocking base spring", "rocking inertia ratio", "rocking damping ratio")),
    ):
        lysmer_spring(chain, motion, K, r, meanings[0])
        lysmer_ratio(chain, motion, B, xi, r, m, (meanings[1], f"{meanings[2]} (radiation + material)"))
    return chain


def _frequencies(scene, springs) -> Chain:
    chain = Chain("Natural frequencies of the block on its springs (zero-order operator)")
    frequency_givens(chain, scene)
    for name, meaning, unit in (("K_z", "vertical base spring", "N/m"), ("K_x", "horizontal base spring", "N/m"),
                                ("K_phi", "rocking base spring", "N m/rad")):
        chain.given(name, float(getattr(springs, name)), unit, meaning)
    frequency_steps(chain)
    return chain


def _dashpots(scene, springs) -> Chain:
    f = scene.foundation
    M_tot = scene.total_mass
    chain = Chain("Base dashpots of the damped soil (C = 2 ξ sqrt(K m) per uncoupled mode)")
    chain.given("M_tot", M_tot, "kg", "total vibrating mass")
    chain.given("I_0", f.moment_of_inertia + M_tot * f.cog_height**2, "kg m²", "moment of inertia about the base axis, I_c + M_tot h²")
    for name, meaning, unit in (
        ("K_z", "vertical base spring", "N/m"), ("K_x", "horizontal base spring", "N/m"), ("K_phi", "rocking base spring", "N m/rad"),
        ("xi_z", "vertical damping ratio", "-"), ("xi_x", "horizontal damping ratio", "-"), ("xi_phi", "rocking damping ratio", "-"),
    ):
        chain.given(name, float(getattr(springs, name)), unit, meaning)
    dashpot(chain, "C_z", "xi_z", "K_z", "M_tot", "N s/m", RHW, "vertical dashpot")
    dashpot(chain, "C_x", "xi_x", "K_x", "M_tot", "N s/m", RHW, "horizontal dashpot at the base")
    dashpot(chain, "C_phi", "xi_phi", "K_phi", "I_0", "N m s/rad", RHW, "rocking dashpot")
    return chain


def crank_chains(scene, amplitudes: dict | None = None) -> list:
    """The hand calculations of a crank foundation scene: springs by its soil method, natural
    frequencies, when the soil is damped the dashpots, with a mechanism the first approximation's
    vertical amplitudes; on Gazetas' soil also the springs
    at each harmonic n ω shown in ``amplitudes`` (the ``amplitudes`` document) and each mode at
    its own frequency. A support without a soil method's chain in the plane (a pile group, which
    couples sway with rocking): its own sheet and the plane model's frequencies
    (:func:`~foundation_calc.output.report.plane_support.plane_chains`), then the mechanism's forcing
    (the first approximation does not apply)."""
    from foundation_calc.output.report.plane_support import by_soil_method, plane_chains

    if not by_soil_method(scene):  # a pile group: the support's own sheet and the plane model's frequencies
        from foundation_calc.output.report.first_approximation_methods import forcing_chain

        return [*plane_chains(scene, amplitudes), *([] if scene.mechanism is None else [forcing_chain(scene)])]
    springs = scene.soil_springs()
    method = scene.soil.method_used
    chains = {"coefficients": [_coefficient_springs], "lysmer": [_lysmer_springs], "sp26": [sp26_springs_chain]}.get(method, [])
    dependent = method in FREQUENCY_DEPENDENT_METHODS  # gazetas, pais_kausel: the same dynamic chains
    out = gazetas_chains(scene) if dependent else [make(scene) for make in chains]
    out += stratum_blocks(scene.soil, *scene.foundation.dimensions, False, amplitudes)
    out.append(_frequencies(scene, springs))
    if dependent:
        from foundation_calc.output.report.gazetas_frequencies import gazetas_frequency_columns

        out += gazetas_frequency_columns(scene, out[0], amplitudes)
    if any(float(getattr(springs, k)) > 0 for k in ("xi_z", "xi_x", "xi_phi")):
        out.append(_dashpots(scene, springs))
    if scene.mechanism is not None:
        from foundation_calc.output.report.first_approximation_methods import first_approximation_chain

        out.append(first_approximation_chain(scene))
    return out


def _crank_methods(scene, documents: dict, units) -> tuple[list, tuple]:
    from foundation_calc.output.report.damped_response import damped_response_blocks

    return crank_chains(scene, documents.get("amplitudes")), damped_response_blocks(scene, documents.get("amplitudes"))


def _platform_methods(scene, documents: dict, units) -> tuple[list, tuple]:
    from foundation_calc.output.report.platform_methods import verification_blocks

    return [platform_chain(documents["design"])], verification_blocks(scene, documents["design"])


def _block_methods(scene, documents: dict, units) -> tuple[list, tuple]:
    from foundation_calc.output.report.block_methods import POINT_UNITS, block_sections_blocks

    return [], block_sections_blocks(scene, documents.get("amplitudes"), units or POINT_UNITS)


#: Each scene kind's hand calculations: the check documents it cannot go without, and the maker
#: (scene, documents, units) -> (chains, the kind's own solve as sheet blocks).
KIND_METHODS = {
    "crank_foundation": (set(), _crank_methods),
    "platform": ({"design"}, _platform_methods),
    "block_foundation": (set(), _block_methods),
}


def methods_section(scene, documents: dict, units=None):
    """The hand calculations and nomenclature of the scene (None for a kind without chains here,
    :data:`KIND_METHODS`); ``units``: the sheet's (:class:`~foundation_calc.output.display_units.DisplayUnits`),
    in which a block's points are shown (by default µm and mm/s)."""
    from foundation_calc.output.report.handcalc import nomenclature_table
    from foundation_calc.output.report.model import Section

    needs, parts = KIND_METHODS.get(scene.kind, (None, None))
    if parts is None or not needs <= documents.keys():
        return None
    chains, response = parts(scene, documents, units)
    runup = []
    if "runup" in documents:
        from foundation_calc.output.report.runup_methods import runup_columns

        from foundation_calc.output.report.runup_governing import governing_blocks

        runup = [*runup_columns(scene, documents["runup"]), *governing_blocks(scene, documents["runup"])]
    blocks = [block for chain in chains for block in (chain.blocks() if hasattr(chain, "blocks") else (chain,))]  # a support's text and tables as they are
    chains = [chain for chain in chains if hasattr(chain, "nomenclature")]
    terms = [block for block in response if hasattr(block, "nomenclature")]
    blocks += [block for block in response if not hasattr(block, "nomenclature")]
    blocks += [block for columns in runup for block in columns.blocks()]
    blocks.append(nomenclature_table([*chains, *terms, *runup]))
    return Section("Methods: hand calculation of the judged numbers", tuple(blocks))
