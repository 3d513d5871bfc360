"""``fcalc soil`` of a block foundation on a frequency-dependent soil: the six springs and
dashpots at O at rest, at each machine's speed and at each mode's own frequency.

Gazetas' and Pais & Kausel's impedances (:mod:`foundation_calc.solvers.soil.impedance`) give
K_i(ω) and C_i(ω); the amplitudes take them at each order's n ω, the modes each at its own
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
    about x, y, z, at one frequency ``omega`` [rad/s], a0 = ω B'/V_s [-] there.

    ``at``: ``"static"`` (at rest), ``"speed"`` (a machine's speed, ``name`` the machine) or
    ``"mode"`` (a mode's own frequency; ``mode`` its number from 1, ``name`` its dominant motion).
    """

    at: str
    name: str
    mode: int | None
    omega: float
    a0: float
    springs: np.ndarray
    dashpots: np.ndarray

    @property
    def label(self) -> str:
        """``"static"``, ``"ω, compressor"`` or ``"1 (y)"`` (mode 1, as the run-up names it): the
        column's heading."""
        return {"static": "static", "speed": f"ω, {self.name}", "mode": f"{self.mode} ({self.name})"}[self.at]


def soil_at_frequencies(scene, model) -> tuple[SoilAt, ...]:
    """Springs and dashpots of a block scene's soil at rest, at every machine's speed and at every
    mode's own frequency (module docstring); empty on a frequency-independent soil, whose springs
    are the same at every frequency. ``model``: the scene's block (:meth:`scene.model`)."""
    if not scene.soil.frequency_dependent:
        return ()
    from foundation_calc.checks.block import scene_modes

    modes, impedance = scene_modes(scene, model)
    entries = [("static", "", None, 0.0)]
    entries += [("speed", m.name, None, m.omega_rad_s) for m in scene.machines]
    entries += [("mode", d, j + 1, float(p)) for j, (p, d) in enumerate(zip(modes.frequencies, modes.dominant))]
    omega = np.array([w for *_, w in entries])
    springs, dashpots, *_ = impedance(omega)  # a coupled support adds its off-diagonal K, C
    half = min(scene.base) / 2.0 if scene.piles is None else scene.piles.diameter  # a0 = ω d/V_s of piles
    return tuple(
        SoilAt(at, name, mode, float(w), float(w * half / scene.soil.V_s), springs[i], dashpots[i])
        for i, (at, name, mode, w) in enumerate(entries)
    )


__all__ = ["SoilAt", "soil_at_frequencies"]
