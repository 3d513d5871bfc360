"""A footing on the soil: the block's base on a soil method's springs and dashpots at O, surface or
embedded (``block.embedment``), on a half-space or on a stratum over bedrock (``soil.stratum_depth``).

The six springs and damping ratios are the scene's soil method's
(:func:`~.footing_springs.six_springs`: Barkan's coefficients, SP 26, Lysmer's analogs, Gazetas'
or Pais & Kausel's impedances, each in both vertical planes, and torsion; or the springs and
dashpots given at O). A damping ratio ξ_i becomes the dashpot
C_i = 2 ξ_i √(|K_i| m_i), m_i the total mass (translations) or the moment of inertia about the
axis through O (rotations; ACI 351.3R-18, 4.5; Richart, Hall & Woods 1970, ch. 10).

Range of validity, by method (:func:`footing_range`): a0 = ω r/V_s with the equivalent radius r of
each motion, a0 <= 1.5 (``"lysmer"``, :data:`~foundation_calc.solvers.soil.lysmer.A0_FITTED`);
a0 = ω B'/V_s, B' the shorter half-side, a0 <= 2 (``"gazetas"``, ``"pais_kausel"``,
:data:`~foundation_calc.solvers.soil.impedance.A0_FITTED`); none for frequency-independent
springs (``"coefficients"``, ``"sp26"``, ``"springs"``). On a stratum, the cutoffs V_s/4H and
V_La/4H (:func:`~foundation_calc.solvers.soil.stratum.cutoff_frequencies`).
"""

from __future__ import annotations

import numpy as np

from foundation_calc.solvers.supports.base import MOTIONS, Assumption, AtO, Sizing, SoilSection, Validity
from foundation_calc.solvers.supports.footing_springs import six_springs
from foundation_calc.solvers.supports.sheet import SoilMethod, Text

#: Why a frequency-independent method has no range of a0, by method.
NO_RANGE = {
    "coefficients": "Barkan's coefficients give frequency-independent springs: no range of a0 applies",
    "sp26": "SP 26.13330's springs and damping ratios do not depend on frequency: no range of a0 applies",
    "springs": "the springs and dashpots given at O are taken at every frequency: no range of a0 applies",
}

#: How each half-space method defines a0.
DEFINITIONS = {
    "lysmer": "a0 = ω r/V_s, r the equivalent radius of the motion (r0 = √(BL/π) vertical and sliding,"
              " r0ψ = (BL³/(3π))^¼ rocking, r0θ = (LB(L² + B²)/(6π))^¼ torsion)",
    "gazetas": "a0 = ω B'/V_s, B' the shorter half-side of the base",
    "pais_kausel": "a0 = ω B'/V_s, B' the shorter half-side of the base",
}

#: soil.method -> how the footing's six springs and dashpots at O are found (the sheet's assumptions).
SOIL_MODELS = {
    "springs": "The six springs (and dashpots) at O as the scene gives them; their source is the"
               " scene's. Frequency-independent.",
    "coefficients": "Winkler springs from Barkan's coefficients [Ba]: K_x = K_y = c_x A, K_z = c_z A,"
                    " K_θx = c_φ I_x, K_θy = c_φ I_y, K_θz = c_ψ J_z (c_ψ default 1.5 c_x, as Barkan is usually quoted:"
                    " unverified against his text); dashpots 2 ξ √(K m)"
                    " of each uncoupled motion from the given damping ratios. Frequency-independent.",
    "lysmer": "Uniform elastic half-space under a rigid surface base, Lysmer's and Hall's analogs in"
              " each vertical plane (equivalent radius per motion) and Reissner-Sagoci's in torsion [RHW]:"
              " radiation plus material damping. Frequency-independent, fitted for a0 < 1.5.",
    "gazetas": "Uniform elastic half-space under a rigid surface base, Gazetas' stiffnesses and"
               " radiation dashpots of the rectangle [Ga]. Frequency-dependent: every order n is solved"
               " with K(nω), C(nω) and every mode at its own frequency; torsion with Pais & Kausel's"
               " modifier and radiation dashpot [PK].",
    "pais_kausel": "Uniform elastic half-space under a rigid surface base, Pais & Kausel's"
                   " stiffnesses with their frequency modifiers [PK] and Gazetas' dashpots. Frequency-"
                   "dependent: every order n is solved with K(nω), C(nω) and every mode at its own"
                   " frequency, torsion included.",
    "sp26": "The code's coefficients C_z, C_x, C_φ from the deformation modulus and the soil class,"
            " C_ψ = C_z and ξ_ψ = 0.3 ξ_z (torsion as the code is usually quoted: unverified against its"
            " text), damping ratios of the code [SP26]. Frequency-independent.",
}


def footing_range(method: str) -> tuple[float | None, str, str]:
    """(a0_max [-] or None, how a0 is formed, source or why no range applies) of a soil ``method``.

    >>> footing_range("gazetas")[0], footing_range("sp26")[0]
    (2.0, None)
    """
    if method == "lysmer":
        from foundation_calc.solvers.soil.lysmer import A0_FITTED, A0_SOURCE
    elif method in ("gazetas", "pais_kausel"):
        from foundation_calc.solvers.soil.impedance import A0_FITTED, A0_SOURCE
    else:
        return None, "", NO_RANGE[method]
    return A0_FITTED, DEFINITIONS[method], A0_SOURCE


def footing_lengths(method: str, L: float, B: float) -> dict[str, float]:
    """The length b [m] of a0 = ω b/V_s of each motion x, y, z, rx, ry, rz by ``method`` on a base
    L (along x) × B [m]: Lysmer's equivalent radii, else B' = min(L, B)/2.

    >>> b = footing_lengths("lysmer", 6.0, 4.0)
    >>> round(b["z"], 4), round(b["ry"], 4), round(footing_lengths("gazetas", 6.0, 4.0)["rz"], 4)
    (2.764, 3.0943, 2.0)
    """
    if method != "lysmer":
        return dict.fromkeys(MOTIONS, float(min(L, B) / 2.0))
    from foundation_calc.solvers.soil.lysmer import equivalent_radii
    from foundation_calc.solvers.soil.torsion import torsion_radius

    r0, r_ry = equivalent_radii(L, B)
    lengths = (r0, r0, r0, equivalent_radii(B, L)[1], r_ry, torsion_radius(L, B))
    return {m: float(v) for m, v in zip(MOTIONS, lengths)}


def six(values, shape) -> np.ndarray:
    """Six values (floats or arrays) stacked on a last axis, broadcast with ``shape`` first."""
    return np.stack(np.broadcast_arrays(*values, np.zeros(shape))[:-1], axis=-1)


class Footing(Sizing):
    """The base on the soil ``soil`` (a block's ``[soil]``: its keys as attributes, as
    :func:`~.footing_springs.six_springs` reads them, and ``frequency_dependent``), L × B [m],
    embedded D [m], under a body whose diagonal of M about O is ``masses`` (..., 6) [kg, kg m²]
    (L, B and the masses: arrays over a batch of candidate blocks, or floats). A design sizes the
    block, not the footing: :class:`~.base.Sizing`'s defaults."""

    def __init__(self, soil, L, B, masses, D):
        self.soil, self.L, self.B, self.masses, self.D = soil, L, B, np.asarray(masses, dtype=float), D
        self.method = soil.method_used
        self.label = repr(self.method)
        self.unscaled = None  # every method's springs scale with one factor on the soil's stiffness data

    #: the base bears on the soil (:func:`~.base.bears_on_soil`)
    base_bears = True

    @property
    def frequency_dependent(self) -> bool:
        """The soil method's (:attr:`~foundation_calc.scenes.soil.Soil.frequency_dependent`)."""
        return self.soil.frequency_dependent

    def _at(self, omega):
        """(ω, masses, L, B) broadcast for the frequencies ``omega`` [rad/s]: ``omega``'s leading
        axes are the batch's, and the masses, L and B gain its axes past the batch's."""
        omega = np.asarray(omega, dtype=float)
        extra = tuple(range(self.masses.ndim - 1, omega.ndim))  # axes of omega past the batch's
        return omega, *(np.expand_dims(v, extra) for v in (self.masses, self.L, self.B))

    def impedance(self, omega) -> AtO:
        """The six springs and dashpots at O at ``omega`` [rad/s] (module docstring), shape batch +
        omega's axes past the batch's + (6,): ``omega``'s leading axes are the batch's."""
        omega, m, L, B = self._at(omega)
        springs, ratios, coupling = self.springs(L, B, m, omega)
        springs = six(springs, omega.shape)
        if ratios is None:
            return AtO(springs, six(self.soil.dashpot or [0.0] * 6, omega.shape))
        return AtO(springs, 2.0 * six(ratios, omega.shape) * np.sqrt(np.abs(springs) * m), coupling)

    def springs(self, L, B, m, omega) -> tuple:
        """(the six springs, the six damping ratios or None for dashpots given at O, the off-diagonal
        (K, C) or None) at ``omega`` [rad/s] of a base L × B [m] under masses ``m`` (..., 6), all
        broadcast (:meth:`_at`): the soil method's (:func:`~.footing_springs.six_springs`), uncoupled."""
        return *six_springs(self.soil, L, B, m[..., 0], np.moveaxis(m[..., 3:], -1, 0), omega, self.D), None

    def validity(self) -> Validity:
        """The method's range of a0 (:func:`footing_range`), each motion's b, and a stratum's cutoffs."""
        a0_max, definition, source = footing_range(self.method)
        if a0_max is None:
            return Validity(self.method, None, definition, source)
        from foundation_calc.solvers.supports.stratum import stratum_cutoffs

        return Validity(self.method, a0_max, definition, source, float(self.soil.V_s),
                        footing_lengths(self.method, self.L, self.B), stratum_cutoffs(self.soil))

    def a0(self, omega):
        """a0 = ω B'/V_s at ``omega`` [rad/s] (None for a frequency-independent soil) and its meaning."""
        values = None
        if self.frequency_dependent:
            values = np.asarray(omega, dtype=float) * (min(self.L, self.B) / 2.0) / self.soil.V_s
        return values, "a0 = ω B'/V_s (B' the base's shorter half-side)"

    def soil_section(self, speeds) -> SoilSection:
        """The stratum's factors and cutoffs (:mod:`.stratum`), when there is one."""
        from foundation_calc.solvers.supports.stratum import stratum_document, stratum_line

        stratum = stratum_document(self.soil, self.L, self.B)
        return SoilSection({"stratum": stratum}, () if stratum is None else (stratum_line(stratum),))

    def assumptions(self) -> tuple[Assumption, ...]:
        """The soil method's model (:data:`SOIL_MODELS`) and the base's: springs and dashpots at O,
        uncoupled, in full contact, surface or embedded D [m], on a half-space or a layer of
        depth H [m] over rigid rock (:mod:`.stratum`)."""
        H = getattr(self.soil, "stratum_depth", None)
        ground = "layering or coupling" if H is None else "coupling"
        layer = "" if H is None else (
            f" The soil is one uniform layer {H:g} m deep over rigid rock: the half-space's springs times Kausel's"
            " factors on the equivalent radii, no radiation damping below the layer's cutoff frequencies V_s/4H and"
            " V_La/4H (material damping only).")
        return (Assumption("soil", SOIL_MODELS[self.method]),
                Assumption("base", "Linear springs and dashpots at O only, uncoupled (no sliding-rocking cross terms); full"
                                   " contact, no uplift; "
                                   + (f"no embedment, side soil, {ground}" if not self.D else
                                      f"embedded {self.D:g} m, sidewalls in full contact (the method's embedment factors"
                                      f" and sidewall dashpots; no torsional sidewall dashpot); no {ground}")
                                   + " through the soil with neighbouring foundations." + layer))

    def not_checked(self, limits) -> tuple[str, ...]:
        """The office checks on the soil that ``limits`` leave out (:func:`static_missing`) and the
        soil's dynamic pressure and settlement, which no check judges."""
        return (*static_missing(limits), "dynamic soil pressure and settlement")

    def sheet(self, model, orders) -> list:
        """The soil method's hand calculations; the springs given at O need none."""
        if self.method == "springs":
            return [Text("Springs and dashpots at O given (soil.stiffness, soil.dashpot): the diagonals of K (the rocking"
                         " entries less W z_G) and C below.")]
        return [SoilMethod(self.method, self.soil, (self.L, self.B), self.D)]


def static_missing(limits) -> list[str]:
    """The office checks of a base on the soil that ``limits`` (a scene's ``[limits]``) leave out for
    want of their allowables: the static bearing pressure and the settlement W/K_z."""
    return ([] if limits.bearing_pressure is not None else ["static bearing pressure (no [limits] bearing_pressure)"]) + (
        [] if limits.settlement is not None else ["static settlement W/K_z (no [limits] settlement)"])


def build(scene, L, B, masses):
    """Every block scene stands on its ``[soil]`` unless another support takes it."""
    return Footing(scene.soil, L, B, masses, scene.embedment)


__all__ = ["DEFINITIONS", "NO_RANGE", "SOIL_MODELS", "Footing", "build", "footing_lengths", "footing_range", "six",
           "static_missing"]
