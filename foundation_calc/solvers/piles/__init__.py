"""Piles under a rigid cap: single-pile head impedances (:mod:`.single`), pile-to-pile dynamic
interaction (:mod:`.group`) and the capped group's springs and dashpots at the cap's origin
(:mod:`.cap`)."""
