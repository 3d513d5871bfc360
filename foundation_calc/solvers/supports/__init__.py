"""Supports of a rigid body: what carries it, each giving its own springs and dashpots at O.

One interface (:class:`~.base.Support`), one module per support kind (:mod:`.footing`: a footing
on a soil method, surface or embedded, on a half-space or a stratum; :mod:`.piles`: a pile group
under a rigid cap; :mod:`.plane_footing`: the crank foundation's footing in the paper's symbols),
in the spirit of ROSS's bearing elements: the body assembles whatever its support gives, and the
checks and the documents read the support only through the interface.

A new support is one module that defines a :class:`~.base.Support` and a builder
``build(scene, L, B, masses) -> Support | None``: a shipped one names its module in
:data:`SHIPPED`, any other (a test's, a plug-in's) hands its builder to :func:`register`.
:func:`support_of` asks the registered builders, newest first, then the shipped ones in order,
and the first that recognises the scene builds its support.
"""

from __future__ import annotations

#: The shipped supports' modules, asked in this order (the footing takes every scene: last).
SHIPPED = ("piles", "plane_footing", "footing")

#: The builders :func:`register` added, newest first.
BUILDERS: list = []


def register(builder):
    """Register ``builder(scene, L, B, masses) -> Support | None`` (newest first); returns it, so it
    serves as a decorator. ``masses``: the body's diagonal of M about O, (..., 6) [kg, kg m²]."""
    BUILDERS.insert(0, builder)
    return builder


def unregister(builder) -> None:
    """Remove a builder :func:`register` added."""
    BUILDERS.remove(builder)


def support_of(scene, L, B, masses):
    """The support of ``scene`` under a base L × B [m] (floats, or arrays over a batch of candidate
    blocks) carrying a body whose diagonal of M about O is ``masses`` (..., 6): the first
    builder's that recognises the scene (module docstring)."""
    from importlib import import_module

    shipped = [import_module(f"{__name__}.{name}").build for name in SHIPPED]
    for builder in (*BUILDERS, *shipped):
        found = builder(scene, L, B, masses)
        if found is not None:
            return found
    raise LookupError("no support recognises the scene")  # the footing takes every scene: a bug


__all__ = ["BUILDERS", "SHIPPED", "register", "support_of", "unregister"]
