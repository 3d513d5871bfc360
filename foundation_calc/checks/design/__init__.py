"""Sizing (``fcalc design``): the checks of ``fcalc check`` evaluated over arrays of candidate
designs at once, and the search for the cheapest candidate that passes them.

:mod:`.candidates` holds what every kind's evaluator returns; :mod:`.batch` is the one batch
checker and :mod:`.modulus_range` the one checker over the soil's modulus range, each kind handing
in its engine from the module named in :data:`.candidates.EVALUATORS` (:mod:`.block`, :mod:`.crank`).
"""
