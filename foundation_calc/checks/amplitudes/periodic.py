"""The exact periodic solution of a block's machines with periodic inertia and the first
approximation's error.

Every block command judges the first approximation (the averaged operator: the machines' mean mass
and weight, their forcing harmonics; :mod:`foundation_calc.solvers.block.response`), but
``fcalc amplitudes --exact``, which judges the exact solution of every machine with periodic inertia
in place of its first approximation (:func:`exact_motion`), as a crank scene's does. For each machine with a part of angle-dependent inertia (a crank mechanism,
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


def periodic_solutions(scene, model, impedance) -> tuple:
    """The exact periodic solution (:class:`~foundation_calc.solvers.rigid_body.periodic.PeriodicSolution`)
    of every machine of ``scene`` with periodic inertia, None for the others, in the scene's order
    (empty without such a machine)."""
    if not any(m.periodic_parts for m in scene.machines):
        return ()
    from foundation_calc.solvers.block.periodic_inertia import exact_response
    from foundation_calc.solvers.constants import GRAVITY
    from foundation_calc.solvers.rigid_body.periodic import HarmonicCapReached

    found = []
    for machine, exc in zip(scene.machines, scene.excitations()):
        exact = None
        if machine.periodic_parts:
            try:
                exact = exact_response(model, exc, machine.periodic_parts, GRAVITY, impedance)
            except HarmonicCapReached as capped:  # given with its truncation error (harmonic_change)
                exact = capped.solution
        found.append(exact)
    return tuple(found)


def periodic_errors(scene, model, impedance, solutions) -> tuple:
    """:class:`~foundation_calc.solvers.block.periodic_inertia.FirstApproximationError` of every
    machine with periodic inertia against its exact ``solutions`` (:func:`periodic_solutions`), in
    the scene's order (empty without)."""
    from foundation_calc.solvers.block.periodic_inertia import first_approximation_error
    from foundation_calc.solvers.block.response import complex_amplitudes
    from foundation_calc.solvers.rigid_body.kinematics import point_maps

    T = point_maps(np.vstack([np.asarray(model.cog, dtype=float)[None, :]] + [np.array([p.at]) for p in scene.points]))
    return tuple(first_approximation_error(machine.name, complex_amplitudes(model, exc, impedance=impedance), exc, exact, T)
                 for machine, exc, exact in zip(scene.machines, scene.excitations(), solutions) if exact is not None)


def exact_motion(scene, model, impedance, solutions):
    """The steady motion of G and the scene's points (:class:`~foundation_calc.solvers.block.response.PointMotion`)
    with every machine with periodic inertia by its exact ``solutions`` (:func:`periodic_solutions`,
    harmonics 1 ... H) and the others by their first approximation, combined as every block's
    motion is (:func:`~foundation_calc.solvers.block.response.point_motion`)."""
    from foundation_calc.solvers.block.response import point_motion

    given = [None if exact is None else (exact.Z, exact.orders) for exact in solutions]
    return point_motion(model, scene.excitations(), [p.name for p in scene.points], [p.at for p in scene.points],
                        impedance=impedance, given=given)


__all__ = ["exact_motion", "periodic_errors", "periodic_solutions"]
