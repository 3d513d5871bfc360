"""One machine of a block foundation as a linear structure for start-up and run-down.

The block's Eq. (1) of :mod:`.model` (M, C, K about O: the rigid-body core's mass matrix, the
springs with the weight's tilt, the dashpots or the uncoupled damping ratios as dashpots, and the
machines' mean gyroscopic coupling at their operating speeds, kept there through the ramp: it
grows as the speed, does no work, and at the operating speed the steady state is then
``fcalc amplitudes``') under
one machine's loads. As the crank foundation's start-up does (:mod:`~foundation_calc.solvers.crank.runup`),
the machine's inertia forces grow with the speed and the moving weight's part does not: of the
generalised force Q_n of order n at the machine's operating speed ω, the moving weight's moment
W_n (a crank mechanism's rods and sliders, an exciter's rotor: :attr:`~foundation_calc.solvers.block.model.Excitation.Q_weight`)
stays W_n at every speed Ω, and the rest acts as an unbalance, its amplitude (Q_n - W_n) (Ω/ω)²
(the parts' inertia forces and unbalances exactly, a vendor's load as the inertia forces it
stands for, as the crank foundation's vendor loads), with its tangential part
(Q_n - W_n) Ω'/(n ω²) (the -i Ω'/r term of :class:`~foundation_calc.solvers.numerics.sweep_response.RotatingLoad`)::

    Q_n(Ω, Ω') = (Q_n - W_n) (Ω² - i Ω'/n)/ω² + W_n

The harmonic of order n has speed ratio n. Points: the combined centre of mass G and the scene's
points, each moving by u_P = T_P q (Eq. (1) of :mod:`~foundation_calc.solvers.rigid_body.kinematics`).

The modes are the block's as the resonance check found them (:class:`~foundation_calc.solvers.block.response.BlockModes`,
on a frequency-dependent soil each at its own frequency); on such a soil the structure carries its
springs and dashpots at any frequency, Ω -> K(Ω), C(Ω) of Eq. (1), and each harmonic is integrated
on those at its own frequency (:mod:`~foundation_calc.solvers.numerics.runup`).
Several machines started together are one structure whose harmonics turn at their speeds'
ratios to the fastest machine's (:func:`machines_structure`).
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
    return machines_structure(model, [machine], points, modes, impedance)[0]


def machines_structure(model: BlockModel, machines, points, modes: BlockModes, impedance=None) -> tuple[Structure, float]:
    """The block under every one of ``machines`` at once, started and stopped together: each runs
    from rest to its own speed ω_m in the same time, so its shaft turns at Ω_m = Ω ω_m/ω of one
    reference shaft Ω, ω the fastest machine's speed. Its order n is then a harmonic of speed
    ratio n ω_m/ω whose growing part (Q_n - W_n) (Ω_m/ω_m)² = (Q_n - W_n) (Ω/ω)² (module
    docstring) is an inertial load (Q_n - W_n)/ω² of the reference shaft and whose moving
    weight W_n its constant load; its tangential part follows from the ratio
    (:class:`~foundation_calc.solvers.numerics.sweep_response.RotatingLoad`); each harmonic on the
    soil at its own frequency, ratio × Ω, where the soil depends on frequency (``impedance``).
    Returns the structure and ω [rad/s]; one machine is :func:`machine_structure`."""
    omega = max(m.omega for m in machines)
    at = np.vstack([model.cog[None, :], np.asarray(points, dtype=float).reshape(-1, 3)])
    ratio = np.concatenate([m.orders * (m.omega / omega) for m in machines]).astype(float)
    constant = np.concatenate([np.asarray(m.Q_weight, dtype=complex) for m in machines])
    inertial = (np.concatenate([np.asarray(m.Q, dtype=complex) for m in machines]) - constant) / omega**2
    load = RotatingLoad(ratio, inertial, constant)

    def at_frequency(frequency):
        K, C = model.soil_matrices(*impedance(frequency))
        return C, K

    structure = Structure(mass=model.M, damping=model.C, stiffness=model.K, load=load, points=point_maps(at),
                          modes=Modes(modes.frequencies, modes.shapes, modes.damping, modes.dominant),
                          at_frequency=None if impedance is None else at_frequency)
    return structure, omega


__all__ = ["machine_structure", "machines_structure"]
