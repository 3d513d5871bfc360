"""Machines on a rigid body: each module gives one machine's mean mass properties, its periodic
inertia (if any) and its forcing harmonics, about the body's reference point O, in the axes and
coordinates of :mod:`foundation_calc.solvers.rigid_body`.
"""
