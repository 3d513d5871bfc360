"""``fcalc soil`` of a crank scene on a support that is no footing (a pile group, ``[piles]``): the
support's springs and dashpots in the plane at O, K_x, K_z, K_φ, K_xφ and C_x, C_z, C_φ, C_xφ
(u_x, u_z, θ_y and the sway-rocking coupling, :func:`~foundation_calc.solvers.supports.plane_footing.plane`),
at rest, at the speed's harmonics n ω and at each mode's own frequency, and the natural
frequencies k0, p1, p2 of the plane's one model on them, as ``fcalc resonance`` reports them
(:func:`~foundation_calc.checks.crank_resonance.scene_design_frequencies`: the eigen-solve of the
averaged operator, each mode at its own frequency ω = p(K(ω))).

The six springs and dashpots are the block's soil path (:func:`~foundation_calc.checks.block_soil.support_at`);
the soil methods' comparison (:mod:`.soil_methods`) is the footing's, which the support replaces.
"""

from __future__ import annotations

from dataclasses import dataclass

from foundation_calc.checks.block_soil import SoilAt, support_at

#: The harmonics n of the speed tabled: the mechanism's forcing of the first approximation, whose
#: vertical motion runs to 4 ω (:data:`~foundation_calc.checks.approximations.HARMONICS`); the
#: amplitudes take harmonic n on the springs at n ω.
ORDERS = (1, 2, 3, 4)

#: The plane's springs and dashpots, in the order of :func:`~foundation_calc.solvers.supports.plane_footing.plane`.
SPRINGS = ("K_x", "K_z", "K_phi", "K_xphi")
DASHPOTS = ("C_x", "C_z", "C_phi", "C_xphi")


@dataclass(frozen=True)
class PlaneAt:
    """The support's springs [N/m, N m/rad, N/rad] and dashpots [N s/m, N m s/rad, N s/rad] in the
    plane at O at one frequency: ``values`` by the names of :data:`SPRINGS` and :data:`DASHPOTS`;
    ``column`` the six at O it is read from."""

    column: SoilAt
    values: dict[str, float]

    @property
    def label(self) -> str:
        """The column's heading (:attr:`SoilAt.label`): ``"static"``, ``"2ω"``, ``"p1 (rocking, lower)"``."""
        return self.column.label


@dataclass(frozen=True)
class PlaneSoil:
    """``fcalc soil`` of a crank scene on a support: ``method`` its label; ``columns`` at rest and at
    each n ω of :data:`ORDERS`; ``modes`` at k0, p1, p2, each at its own frequency; ``frequencies``
    and ``static_frequencies`` k0, p1, p2 [rad/s] on those springs and on the springs at rest;
    ``validity`` the support's a0 at the modes and judged orders against its fitted range
    (:class:`~foundation_calc.checks.soil_validity.SoilValidity`)."""

    method: str
    columns: tuple[PlaneAt, ...]
    modes: tuple[PlaneAt, ...]
    frequencies: dict[str, float]
    static_frequencies: dict[str, float]
    validity: object


def _in_plane(column: SoilAt, name: str) -> PlaneAt:
    """The plane's springs and dashpots of the six at O of ``column`` (a coupling other than u_x with
    θ_y is a PhysicsError naming the support ``name``)."""
    from foundation_calc.solvers.supports.base import AtO
    from foundation_calc.solvers.supports.plane_footing import plane

    springs, dashpots, (K_xphi, C_xphi) = plane(AtO(column.springs, column.dashpots, column.coupling), name)
    values = [*springs, K_xphi, *dashpots, C_xphi]
    return PlaneAt(column, dict(zip(SPRINGS + DASHPOTS, map(float, values), strict=True)))


def plane_soil(scene) -> PlaneSoil:
    """The support's springs and dashpots in the plane and the one model's frequencies (module
    docstring) of a crank scene with a mechanism, and the support's validity at the modes and the
    orders the resonance rule judges, as ``fcalc resonance`` gives it
    (:func:`~foundation_calc.checks.soil_validity.crank_validity`); PhysicsError for a machine given
    by its loads only, whose plane model is the paper's uncoupled block."""
    from foundation_calc.checks.crank_resonance import scene_resonances_as_given
    from foundation_calc.checks.soil_validity import crank_validity
    from foundation_calc.solvers.crank.resonance import MODE_NAMES

    support = scene.support()
    resonance = scene_resonances_as_given(scene)
    averaged, static = resonance.averaged, resonance.static or resonance.averaged  # static: None if not frequency-dependent
    omega = scene.speed.omega_rad_s
    modes = {mode: float(getattr(averaged, mode)) for mode in MODE_NAMES}
    entries = [("static", "", None, 0.0), *(("order", f"{n}ω" if n > 1 else "ω", None, n * omega) for n in ORDERS)]
    entries += [("mode", name, mode, modes[mode]) for mode, name in MODE_NAMES.items()]
    at = [_in_plane(column, support.label) for column in support_at(support, entries)]
    return PlaneSoil(support.label, tuple(at[:1 + len(ORDERS)]), tuple(at[1 + len(ORDERS):]), modes,
                     {mode: float(getattr(static, mode)) for mode in MODE_NAMES}, crank_validity(scene, resonance))


__all__ = ["DASHPOTS", "ORDERS", "SPRINGS", "PlaneAt", "PlaneSoil", "plane_soil"]
