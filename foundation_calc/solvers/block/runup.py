"""One machine of a block foundation as a linear structure for start-up and run-down.

The block's Eq. (1) of :mod:`.model` (M, C, K about O: the rigid-body core's mass matrix, the
springs with the weight's tilt, the dashpots or the uncoupled damping ratios as dashpots) under
one machine's loads. As for a crank machine given by its vendor's loads, every load of the
machine acts as an unbalance while the speed changes: its amplitude grows as Q_n (Ω/ω)², Q_n the
generalised force of order n at the machine's operating speed ω (an unbalance's exactly, a
vendor's load as the inertia forces it stands for), with its tangential part Q_n Ω'/(n ω²) (the
-i Ω'/r term of :class:`~foundation_calc.solvers.numerics.sweep_response.RotatingLoad`). The
harmonic of order n has speed ratio n. Points: the combined centre of mass G and the scene's
points, each moving by u_P = T_P q (Eq. (1) of :mod:`~foundation_calc.solvers.rigid_body.kinematics`).

The modes are the block's as the resonance check found them (:class:`~foundation_calc.solvers.block.response.BlockModes`,
on a frequency-dependent soil each at its own frequency); on such a soil the structure carries its
springs and dashpots at any frequency, Ω -> K(Ω), C(Ω) of Eq. (1), and each harmonic is integrated
on those at its own frequency (:mod:`~foundation_calc.solvers.numerics.runup`).
"""

from __future__ import annotations

import numpy as np

from foundation_calc.solvers.block.model import BlockModel, Excitation
from foundation_calc.solvers.block.response import BlockModes
from foundation_calc.solvers.numerics.runup import Modes, Structure
from foundation_calc.solvers.numerics.sweep_response import RotatingLoad
from foundation_calc.solvers.rigid_body.kinematics import point_maps


def machine_structure(model: BlockModel, machine: Excitation, points, modes: BlockModes, impedance=None) -> Structure:
    """The block of ``model`` under the loads of ``machine`` alone, measured at G and at
    ``points`` (P, 3) [m] from O, with the block's ``modes``; ``impedance``: a frequency-dependent
    soil, Ω -> (springs, dashpots) at O (module docstring)."""
    at = np.vstack([model.cog[None, :], np.asarray(points, dtype=float).reshape(-1, 3)])
    inertial = np.asarray(machine.Q, dtype=complex) / machine.omega**2
    load = RotatingLoad(machine.orders.astype(float), inertial, np.zeros_like(inertial))

    def at_frequency(omega):
        K, C = model.soil_matrices(*impedance(omega))
        return C, K

    return Structure(mass=model.M, damping=model.C, stiffness=model.K, load=load, points=point_maps(at),
                     modes=Modes(modes.frequencies, modes.shapes, modes.damping, modes.dominant),
                     at_frequency=None if impedance is None else at_frequency)


__all__ = ["machine_structure"]
