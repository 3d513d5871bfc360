"""The validation record of fcalc: published worked examples and independent solutions.

Each case compares one number fcalc computes with a value it did not produce itself: a value
printed in a publication (a worked example, a code's table, an exact solution), or the result of
an independent method (an eigen-solve, the exact periodic solution by harmonic balance, the
6-DOF model). The cases are data with their sources (:mod:`.published`, :mod:`.independent`,
references in :mod:`.references`); :func:`~.cases.run_record` evaluates them for ``fcalc
validate`` and the calculation sheet alike.
"""
