"""Sizing (``fcalc design``): the checks of ``fcalc check`` evaluated over arrays of candidate
designs at once, and the search for the cheapest candidate that passes them.

:mod:`.candidates` holds what every kind's evaluator returns; each kind's evaluator lives in a
module of its own, named in :data:`.candidates.EVALUATORS`.
"""
