"""``fcalc soil`` of a block foundation on a frequency-dependent support: the six springs and
dashpots at O at rest, at each machine's speed and at each mode's own frequency.

The support (:meth:`~foundation_calc.scenes.block.BlockScene.support`; e.g. Gazetas' and Pais &
Kausel's impedances, :mod:`foundation_calc.solvers.soil.impedance`) gives K_i(ω) and C_i(ω); the amplitudes take them at each order's n ω, the modes each at its own
frequency p_j = p_j(K(p_j)) (:func:`~foundation_calc.checks.block.scene_modes`, the resonance
check's). These are the frequencies a reader of ``fcalc soil`` needs them at, as the crank
foundation's table gives them at its speed and at k0, p1, p2
(:class:`~foundation_calc.checks.soil_methods.DynamicRow`).
"""

from __future__ import annotations

from dataclasses import dataclass

import numpy as np


@dataclass(frozen=True)
class SoilAt:
    """The six springs [N/m, N m/rad] and dashpots [N s/m, N m s/rad] at O, along x, y, z and
    about x, y, z, at one frequency ``omega`` [rad/s], a0 [-] there (the support's, e.g. ω B'/V_s;
    None when none applies).

    ``at``: ``"static"`` (at rest), ``"speed"`` (a machine's speed, ``name`` the machine), ``"order"``
    (a crank's harmonic n ω, ``name`` ``"2ω"``) or ``"mode"`` (a mode's own frequency; ``mode`` its number from 1,
    ``name`` its dominant motion). ``coupling``: a coupled support's off-diagonal (K, C), (6, 6) each
    (:class:`~foundation_calc.solvers.supports.base.AtO`), None for an uncoupled one.
    """

    at: str
    name: str
    mode: int | str | None
    omega: float
    a0: float | None
    springs: np.ndarray
    dashpots: np.ndarray
    coupling: tuple | None = None

    @property
    def label(self) -> str:
        """``"static"``, ``"ω, compressor"``, ``"2ω"`` (a harmonic) or ``"1 (y)"`` (mode 1, as the
        run-up names it; a crank's ``"k0 (vertical)"``): the column's heading."""
        return {"static": "static", "speed": f"ω, {self.name}", "order": self.name, "mode": f"{self.mode} ({self.name})"}[self.at]


def soil_at_frequencies(scene, model) -> tuple[SoilAt, ...]:
    """Springs and dashpots of a block scene's support at rest, at every machine's speed and at
    every mode's own frequency (module docstring); empty when they do not depend on frequency (the
    same at every frequency). ``model``: the scene's block (:meth:`scene.model`)."""
    support = scene.support()
    if not support.frequency_dependent:
        return ()
    from foundation_calc.checks.block import scene_modes

    modes, _ = scene_modes(scene, model)
    entries = [("static", "", None, 0.0)]
    entries += [("speed", m.name, None, m.omega_rad_s) for m in scene.machines]
    entries += [("mode", d, j + 1, float(p)) for j, (p, d) in enumerate(zip(modes.frequencies, modes.dominant))]
    return support_at(support, entries)


def support_at(support, entries) -> tuple[SoilAt, ...]:
    """A support's springs and dashpots at O (:meth:`~foundation_calc.solvers.supports.base.Support.impedance`,
    the six of the diagonal and a coupled support's off-diagonal K, C) at each of ``entries``, the
    (at, name, mode, ω [rad/s]) of a :class:`SoilAt`, in one call: any scene's support, a block's or
    a crank's."""
    omega = np.array([w for *_, w in entries])
    at = support.impedance(omega)
    a0, _ = support.a0(omega)
    return tuple(
        SoilAt(kind, name, mode, float(w), None if a0 is None else float(a0[i]), at.springs[i], at.dashpots[i],
               None if at.coupling is None else (at.coupling[0][i], at.coupling[1][i]))
        for i, (kind, name, mode, w) in enumerate(entries)
    )


__all__ = ["SoilAt", "soil_at_frequencies", "support_at"]
