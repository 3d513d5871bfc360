"""``fcalc soil`` of a scene whose support is given as springs and dashpots at O rather than by the
footing's soil methods compared (every block scene; a crank scene on a pile group): the support's
springs and dashpots at the frequencies a reader needs them at — at rest, at each machine's speed or
harmonic n ω, and at each mode's own frequency p_j = p_j(K(p_j)) — as the commands take them.

The support (:meth:`~foundation_calc.solvers.supports.base.Support.impedance`; e.g. Gazetas' and Pais
& Kausel's impedances, :mod:`foundation_calc.solvers.soil.impedance`, or a pile group) gives the
six springs and dashpots at O at any frequency; a scene kind reads them as its model does and names
the frequencies its commands take (:data:`KINDS`):

- a block: the six by motion, at every machine's speed and at each of its six modes
  (:func:`~foundation_calc.checks.amplitudes.machines.scene_modes`, the resonance check's), only when the
  support's springs depend on frequency (otherwise they are the same at every frequency);
- a crank: their projection on the plane u_x, u_z, θ_y with the sway-rocking coupling
  (:func:`~foundation_calc.solvers.supports.plane_footing.plane`), at the speed's harmonics of
  :data:`ORDERS` and at k0, p1, p2 of the plane's one model as ``fcalc resonance`` solves them
  (:func:`~foundation_calc.checks.resonance.scene_resonances_as_given`), with those
  frequencies on the springs at rest and the support's validity there.
"""

from __future__ import annotations

from dataclasses import dataclass

#: The harmonics n of a crank's speed tabled: the mechanism's forcing of the first approximation,
#: whose vertical motion runs to 4 ω (:data:`~foundation_calc.checks.amplitudes.approximations.HARMONICS`);
#: the amplitudes take harmonic n on the springs at n ω.
ORDERS = (1, 2, 3, 4)

#: The crank's plane springs and dashpots, in the order of :func:`~foundation_calc.solvers.supports.plane_footing.plane`.
PLANE_SPRINGS = ("K_x", "K_z", "K_phi", "K_xphi")
PLANE_DASHPOTS = ("C_x", "C_z", "C_phi", "C_xphi")


@dataclass(frozen=True)
class SoilAt:
    """The support's springs [N/m, N m/rad, N/rad] and dashpots [N s/m, N m s/rad, N s/rad] at O at
    one frequency ``omega`` [rad/s], as the scene's kind reads them (``values`` by name: a block's
    ``K_x`` … ``C_rz`` by motion, a crank's ``K_x``, ``K_z``, ``K_phi``, ``K_xphi``, ``C_x`` …), a0 [-]
    there (the support's, e.g. ω B'/V_s; None when none applies).

    ``at``: ``"static"`` (at rest), ``"speed"`` (a machine's speed, ``name`` the machine), ``"order"``
    (a crank's harmonic n ω, ``name`` ``"2ω"``) or ``"mode"`` (a mode's own frequency; ``mode`` its
    number from 1 or its name k0, p1, p2, ``name`` its dominant motion).
    """

    at: str
    name: str
    mode: int | str | None
    omega: float
    a0: float | None
    values: dict[str, float]

    @property
    def label(self) -> str:
        """``"static"``, ``"ω, compressor"``, ``"2ω"`` (a harmonic) or ``"1 (y)"`` (mode 1, as the
        run-up names it; a crank's ``"k0 (vertical)"``): the column's heading."""
        return {"static": "static", "speed": f"ω, {self.name}", "order": self.name, "mode": f"{self.mode} ({self.name})"}[self.at]


@dataclass(frozen=True)
class SupportSoil:
    """``fcalc soil`` of a scene on a support (module docstring): ``method`` the support's label;
    ``speeds`` every machine's speed [rad/s] by its name (the support's own part is taken there);
    ``columns`` at rest and at the machines' speeds or harmonics; ``modes`` at each mode's own
    frequency (both empty for a block on a support whose springs do not depend on frequency);
    ``body`` a block's rigid-body model (its springs and dashpots at rest by motion), None for a
    crank; ``static_frequencies`` a crank's k0, p1, p2 [rad/s] on the springs at rest and
    ``validity`` its support's a0 at the modes and judged orders against the fitted range
    (:class:`~foundation_calc.checks.soil_validity.SoilValidity`), None for a block."""

    method: str
    speeds: dict[str, float]
    columns: tuple[SoilAt, ...]
    modes: tuple[SoilAt, ...]
    body: object = None
    static_frequencies: dict[str, float] | None = None
    validity: object = None

    @property
    def frequencies(self) -> dict:
        """The modes' own frequencies [rad/s] by mode (a crank's k0, p1, p2; a block's 1 … 6)."""
        return {c.mode: c.omega for c in self.modes}


def support_at(support, entries, read) -> tuple[SoilAt, ...]:
    """A support's springs and dashpots at O (:meth:`~foundation_calc.solvers.supports.base.Support.impedance`)
    at each of ``entries``, the (at, name, mode, ω [rad/s]) of a :class:`SoilAt`, in one call, each
    read by ``read`` (:class:`~foundation_calc.solvers.supports.base.AtO` -> values by name)."""
    import numpy as np

    from foundation_calc.solvers.supports.base import AtO

    omega = np.array([w for *_, w in entries])
    at = support.impedance(omega)
    a0, _ = support.a0(omega)
    return tuple(
        SoilAt(kind, name, mode, float(w), None if a0 is None else float(a0[i]),
               read(AtO(at.springs[i], at.dashpots[i], None if at.coupling is None else (at.coupling[0][i], at.coupling[1][i]))))
        for i, (kind, name, mode, w) in enumerate(entries)
    )


def by_motion(at) -> dict[str, float]:
    """A block's reading of the six at O ``at``: ``K_x`` … ``K_rz``, ``C_x`` … ``C_rz`` (the motions of
    :data:`~foundation_calc.solvers.rigid_body.modes.MOTIONS`)."""
    from foundation_calc.solvers.rigid_body.modes import MOTIONS

    return {f"{q}_{m}": float(v[i]) for q, v in (("K", at.springs), ("C", at.dashpots)) for i, m in enumerate(MOTIONS)}


def in_plane(name: str):
    """A crank's reading of the six at O: the plane's :data:`PLANE_SPRINGS` and :data:`PLANE_DASHPOTS`
    (:func:`~foundation_calc.solvers.supports.plane_footing.plane`; a coupling other than u_x with θ_y
    is a PhysicsError naming the support ``name``)."""
    from foundation_calc.solvers.supports.plane_footing import plane

    def read(at) -> dict[str, float]:
        springs, dashpots, (K_xphi, C_xphi) = plane(at, name)
        return dict(zip(PLANE_SPRINGS + PLANE_DASHPOTS, map(float, [*springs, K_xphi, *dashpots, C_xphi]), strict=True))

    return read


def _block(scene) -> SupportSoil:
    """A block scene's :class:`SupportSoil`: at rest, at every machine's speed and at every mode's
    own frequency, on a frequency-dependent support only."""
    support, body = scene.support(), scene.model()
    speeds = {m.name: m.omega_rad_s for m in scene.machines}
    columns = ()
    if support.frequency_dependent:
        from foundation_calc.checks.amplitudes.machines import scene_modes

        modes, _ = scene_modes(scene, body)
        entries = [("static", "", None, 0.0), *(("speed", name, None, w) for name, w in speeds.items())]
        entries += [("mode", d, j + 1, float(p)) for j, (p, d) in enumerate(zip(modes.frequencies, modes.dominant))]
        columns = support_at(support, entries, by_motion)
    rest = [c for c in columns if c.at != "mode"]
    return SupportSoil(support.label, speeds, tuple(rest), tuple(columns[len(rest):]), body=body)


def _crank(scene) -> SupportSoil:
    """A crank scene's :class:`SupportSoil` (module docstring); PhysicsError for a machine given by
    its loads only, whose plane model is the paper's uncoupled block."""
    from foundation_calc.checks.resonance import scene_resonances_as_given
    from foundation_calc.checks.soil_validity import crank_validity
    from foundation_calc.solvers.crank.resonance import MODE_NAMES

    support = scene.support()
    resonance = scene_resonances_as_given(scene)
    averaged, static = resonance.averaged, resonance.static or resonance.averaged  # static: None if not frequency-dependent
    omega = scene.speed.omega_rad_s
    entries = [("static", "", None, 0.0), *(("order", f"{n}ω" if n > 1 else "ω", None, n * omega) for n in ORDERS)]
    entries += [("mode", name, mode, float(getattr(averaged, mode))) for mode, name in MODE_NAMES.items()]
    at = support_at(support, entries, in_plane(support.label))
    return SupportSoil(support.label, {"machine": omega}, at[:1 + len(ORDERS)], at[1 + len(ORDERS):],
                       static_frequencies={mode: float(getattr(static, mode)) for mode in MODE_NAMES},
                       validity=crank_validity(scene, resonance))


#: What each scene kind tables of its support (:func:`support_soil`).
KINDS = {"block_foundation": _block, "crank_foundation": _crank}


def support_soil(scene) -> SupportSoil:
    """The support's springs and dashpots at the frequencies ``fcalc soil`` tables for ``scene`` of
    any kind of :data:`KINDS` (module docstring)."""
    return KINDS[scene.kind](scene)


__all__ = ["KINDS", "ORDERS", "PLANE_DASHPOTS", "PLANE_SPRINGS", "SoilAt", "SupportSoil", "by_motion", "in_plane",
           "support_at", "support_soil"]
