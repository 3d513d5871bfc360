"""``fcalc soil`` of a block on piles: the single pile's head impedances and the capped group's at
rest and at each machine's speed, with the group's efficiency (its spring over n single piles').

The numbers are those the block's support takes (:class:`~foundation_calc.scenes.block_piles.PiledSoil`):
:func:`~foundation_calc.solvers.piles.single.single_pile` and
:func:`~foundation_calc.solvers.piles.cap.pile_group` at the same frequencies.
"""

from __future__ import annotations

from dataclasses import dataclass

import numpy as np


@dataclass(frozen=True)
class PilesAt:
    """One pile's and the group's springs and dashpots at one frequency ``omega`` [rad/s].

    Attributes
    ----------
    label : ``"static"`` or ``"ω, <machine>"``
    a0 : ω d/V_s [-] (V_s the soil's at depth d)
    single : name -> (K, C) of one pile: K_v, K_HH, K_MM, K_HM, K_T [N/m, N m/rad, N/rad; N s/m ...]
        (K_MM, K_HM zero for a pinned head, K_HH then the free head's)
    group : the group at O, (K, C) each (6, 6)
    efficiency : motion -> the group's spring over n single piles' (x, y: K_HH; z: K_v) [-]
    """

    label: str
    omega: float
    a0: float
    single: dict
    group: tuple
    efficiency: dict


def piles_at_frequencies(scene) -> tuple[PilesAt, ...]:
    """The single pile and the group at rest and at every machine's speed (module docstring)."""
    from foundation_calc.solvers.piles.cap import OMEGA_REST, springs_and_dashpots
    from foundation_calc.solvers.piles.single import pinned, single_pile

    soil, p = scene.soil, scene.piles
    L, B = scene.base
    entries = [("static", 0.0)] + [(f"ω, {m.name}", m.omega_rad_s) for m in scene.machines]
    omega = np.array([w for _, w in entries])
    def one(w):
        head = single_pile(p.diameter, p.length, p.modulus, p.density, soil.G, soil.poisson, soil.density,
                           p.soil_profile, p.tip == "end_bearing", w)
        return pinned(head) if p.head == "pinned" else head

    head, damped = one(omega), one(np.maximum(omega, OMEGA_REST))
    K, C = springs_and_dashpots(lambda w: soil.group(L, B, w), omega)
    n = len(p.positions)
    rows = []
    for i, (label, w) in enumerate(entries):
        single = {name: (float(np.real(getattr(head, name)[i])),
                         float(np.imag(getattr(damped, name)[i]) / max(w, OMEGA_REST)))
                  for name in ("K_v", "K_HH", "K_MM", "K_HM", "K_T")}
        efficiency = {"x": K[i, 0, 0] / (n * single["K_HH"][0]), "y": K[i, 1, 1] / (n * single["K_HH"][0]),
                      "z": K[i, 2, 2] / (n * single["K_v"][0])}
        rows.append(PilesAt(label, float(w), float(w * p.diameter / soil.V_s), single, (K[i], C[i]),
                            {k: float(v) for k, v in efficiency.items()}))
    return tuple(rows)


__all__ = ["PilesAt", "piles_at_frequencies"]
