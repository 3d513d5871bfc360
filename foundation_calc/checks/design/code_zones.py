"""A vibration code's zones (``[limits] code``) on a batch of candidates, for every kind's engine:
each point's zone by the larger of its RMS velocity and RMS displacement
(:func:`~foundation_calc.checks.codes.code_zone_index`, the more restrictive decides), the zone's
outcome (:func:`~foundation_calc.checks.codes.zone_verdicts`: beyond the acceptable zone fails; with
none given, zone C warns and D fails) and the utilisation: the value over the boundary of the
highest acceptable zone (B by default) of the quantity that decides."""

from __future__ import annotations

import numpy as np


def code_zones(limits, velocity, displacement):
    """(the code's table, outcome (shape) int8 of :data:`~.candidates.PASS` ... :data:`~.candidates.FAIL`,
    utilisation (shape)) of the points' largest RMS ``velocity`` [m/s] and ``displacement`` [m]
    (arrays of one shape, e.g. (N, points)) under ``limits`` (module docstring)."""
    from foundation_calc.checks.codes import TABLES, ZONES, code_zone_index, zone_verdicts
    from foundation_calc.checks.design.candidates import FAIL, PASS, WARN

    table = TABLES[limits.code, limits.machine_group, limits.foundation]
    highest = ZONES.index(limits.acceptable_zone or "B")
    index, by_displacement = code_zone_index(velocity, displacement, table)
    codes = {"pass": PASS, "warn": WARN, "fail": FAIL}
    verdicts = np.array([codes[v.value] for v in zone_verdicts(limits.acceptable_zone)], dtype=np.int8)
    ratio = np.where(by_displacement, displacement / table.displacement_boundaries[highest],
                     velocity / table.boundaries[highest])
    return table, verdicts[index], ratio


__all__ = ["code_zones"]
