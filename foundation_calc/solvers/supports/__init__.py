"""Supports of a rigid body: what carries it, each giving its own springs and dashpots at O.

One interface (:class:`~.base.Support`), one module per support kind (:mod:`.footing`: a footing
on a soil method, surface or embedded, on a half-space or a stratum; :mod:`.piles`: a pile group
under a rigid cap; :mod:`.isolators`: spring isolators at points of the body, the platform's and
a block's on ``[[isolators]]``; :mod:`.plane_footing`: the crank foundation's footing in the
paper's symbols),
in the spirit of ROSS's bearing elements: the body assembles whatever its support gives, and the
checks and the documents read the support only through the interface.

A new support is one module that defines a :class:`~.base.Support` and a builder
``build(scene, L, B, masses) -> Support | None``: a shipped one names its module in
:data:`SHIPPED`, any other (a test's, a plug-in's) hands its builder to :func:`register`.
:func:`support_of` asks the registered builders, newest first, then the shipped ones in order,
and the first that recognises the scene builds its support.

The sizes a support lets a design vary (:class:`~.base.Variable`) are declared with it: a shipped
module's ``VARIABLES``, a registered builder's ``variables``; :func:`design_variables` lists them
all, so that ``fcalc design`` knows a key before it reads a scene.
"""

from __future__ import annotations

#: The shipped supports' modules, asked in this order (the footing takes every scene: last).
SHIPPED = ("isolators", "piles", "plane_footing", "footing")

#: The builders :func:`register` added, newest first.
BUILDERS: list = []

#: builder -> the sizes its supports let a design vary (:func:`register`'s ``variables``).
VARIABLES: dict = {}


def register(builder, variables=()):
    """Register ``builder(scene, L, B, masses) -> Support | None`` (newest first) and the sizes its
    supports let a design vary (:class:`~.base.Variable` each); returns it, so it serves as a
    decorator. ``masses``: the body's diagonal of M about O, (..., 6) [kg, kg m²]."""
    BUILDERS.insert(0, builder)
    VARIABLES[builder] = tuple(variables)
    return builder


def unregister(builder) -> None:
    """Remove a builder :func:`register` added."""
    BUILDERS.remove(builder)
    VARIABLES.pop(builder, None)


def design_variables() -> dict:
    """Key -> :class:`~.base.Variable` of every size a support may let a design vary: the
    registered builders' and the shipped modules' ``VARIABLES``."""
    from importlib import import_module

    shipped = [getattr(import_module(f"{__name__}.{name}"), "VARIABLES", ()) for name in SHIPPED]
    return {v.key: v for group in (*VARIABLES.values(), *shipped) for v in group}


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


__all__ = ["BUILDERS", "SHIPPED", "VARIABLES", "design_variables", "register", "support_of", "unregister"]
