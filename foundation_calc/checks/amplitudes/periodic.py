"""The exact periodic solution of a block's machines with periodic inertia and the first
approximation's error.

Every block command judges the first approximation (the averaged operator: the machines' mean mass
and weight, their forcing harmonics; :mod:`foundation_calc.solvers.block.response`), as the crank
scene does. For each machine with a part of angle-dependent inertia (a crank mechanism,
``[[machines.cranks]]``; an exciter's rotor, ``[[machines.exciters]]``) this module adds the exact
T-periodic solution with that inertia (harmonic balance,
:mod:`foundation_calc.solvers.block.periodic_inertia`) and the first
approximation's error against it: the largest relative difference of the peaks of G's and every
point's displacement and of the rotations. Computed once per scene (not over a soil's modulus
range). A rod barely longer than its crank may need more harmonics than the cap: the solution at
the cap is given, with its change from half as many harmonics as its error estimate
(``harmonic_change``).
"""

from __future__ import annotations

import numpy as np


def periodic_errors(scene, model, impedance) -> tuple:
    """:class:`~foundation_calc.solvers.block.periodic_inertia.FirstApproximationError` of every
    machine with periodic inertia, in the scene's order (empty without)."""
    if not any(m.periodic_parts for m in scene.machines):
        return ()
    from foundation_calc.solvers.block.periodic_inertia import exact_response, first_approximation_error
    from foundation_calc.solvers.block.response import complex_amplitudes
    from foundation_calc.solvers.constants import GRAVITY
    from foundation_calc.solvers.rigid_body.kinematics import point_maps
    from foundation_calc.solvers.rigid_body.periodic import HarmonicCapReached

    T = point_maps(np.vstack([np.asarray(model.cog, dtype=float)[None, :]] + [np.array([p.at]) for p in scene.points]))
    found = []
    for machine, exc in zip(scene.machines, scene.excitations()):
        if machine.periodic_parts:
            try:
                exact = exact_response(model, exc, machine.periodic_parts, GRAVITY, impedance)
            except HarmonicCapReached as capped:  # given with its truncation error (harmonic_change)
                exact = capped.solution
            first = complex_amplitudes(model, exc, impedance=impedance)
            found.append(first_approximation_error(machine.name, first, exc, exact, T))
    return tuple(found)


__all__ = ["periodic_errors"]
