"""Which scene keys a sizing search may vary, and a candidate design put into a scene document.

The varied keys are the block's dimensions, per kind (:data:`VARIABLES`): a
``block_foundation``'s ``block.length``, ``block.width``, ``block.height`` (a block given by
height and density), a ``crank_foundation``'s ``foundation.block.length``, ``width``, ``height``
(``block.length`` … is accepted as their shorthand); and the sizes of its own that the scene's
support lets a design vary (:func:`~foundation_calc.solvers.supports.design_variables`, e.g. a
pile group's ``piles.length`` and ``piles.diameter``: :attr:`~foundation_calc.solvers.supports.base.Sizing.sizes`).
Each has bounds: the plausible range of :data:`~foundation_calc.scenes.plausibility.RANGES` (what
real blocks measure), so that a search never proposes a 5 km block, or the support's own.

What changes with the block besides its dimensions (:func:`moved`, one rule for every position
the scene gives):

- the machines stand on the block: every position at or above the block's top (machines'
  centres of mass, load, unbalance and exciter points, checked points, a crank's axis) rises or sinks
  with the top, by H_new - H; positions below the top keep their height;
- a position on or beyond an end face (|x| >= L/2, or |y| >= B/2) keeps its distance from that
  face (a point on the block's corner stays on the corner); one inside keeps its coordinates;
- a position a machine carries rigidly (a crank's centre: the model gives the mechanism at the
  machine's centre of mass) moves with that machine's centre of mass (:func:`moved_positions`:
  a block scene's positions are the scene's one list,
  :meth:`~foundation_calc.scenes.block.BlockScene.positions`);
- what the support places under the base moves with the plan as the support says
  (:meth:`~foundation_calc.solvers.supports.base.Sizing.plan_changes`: a pile group's heads keep
  their place in the plan, x scaled with L and y with B);
- a crank foundation's mass, moment of inertia, centre-of-mass height, base area, second moment
  and base length and width, when the scene gives them beside ``[foundation.block]``, are left out
  of the candidate's document and computed from the block (:data:`CRANK_DERIVED`: given, they
  would disagree with the new block, which validation rejects); its positions given from the
  centre of mass C (``mechanism.crank_axis_to_cog``, ``loads[].at.height``, ``points[].height``)
  are moved by the rule above in base coordinates and measured again from the new C.

A vectorised evaluator applies the same rule on arrays with :func:`moved` and
:func:`moved_positions` (and, for a crank scene, :func:`moved_machine_height` and :func:`moved_from_c`), so that its verdicts and those of
:func:`apply` followed by ``fcalc check``'s path are the same.
"""

from __future__ import annotations

import copy
import dataclasses
import difflib
from collections.abc import Mapping
from typing import Any

import numpy as np

from foundation_calc.errors import ExitCode, FcalcError
from foundation_calc.solvers.supports.base import Variable


class VaryError(FcalcError, ValueError):
    """A key that cannot vary, or a value outside its bounds: a command-line usage error."""

    exit_code = ExitCode.USAGE


def _bounded(found: Variable) -> Variable:
    """``found`` with its bounds and unit: its own, else the plausible range of its key."""
    if found.low is not None:
        return found
    from foundation_calc.scenes.plausibility import KEYS, RANGES

    plausible = RANGES[KEYS[found.key]]
    return dataclasses.replace(found, unit=plausible.unit, low=plausible.low, high=plausible.high)


def _variables(prefix: str) -> dict[str, Variable]:
    where = "a scene with [foundation.block]" if prefix.startswith("foundation.") else "a block scene"
    return {key: _bounded(Variable(key, text, where)) for key, text in (
        (f"{prefix}length", "block length along x"), (f"{prefix}width", "block width along y"),
        (f"{prefix}height", "block height"))}


#: scene kind -> {varied key: Variable} of the block's dimensions (the supports' own sizes:
#: :func:`variables`).
VARIABLES: dict[str, dict[str, Variable]] = {
    "block_foundation": _variables("block."),
    "crank_foundation": _variables("foundation.block."),
}


def variables(kind: str) -> dict[str, Variable]:
    """Every key a search may vary in a scene of ``kind``: the block's dimensions and every size a
    support may let a design vary (the scene's support decides whether it does: :func:`applied_document`)."""
    from foundation_calc.solvers.supports import design_variables

    return VARIABLES[kind] | {key: _bounded(found) for key, found in design_variables().items()}


#: scene kind -> {shorthand: varied key}.
ALIASES: dict[str, dict[str, str]] = {
    "crank_foundation": {f"block.{side}": f"foundation.block.{side}" for side in ("length", "width", "height")},
}

#: Keys of a crank scene's ``[foundation]`` computed from ``[foundation.block]``: left out of a
#: candidate's document (module docstring).
CRANK_DERIVED = ("mass", "moment_of_inertia", "cog_height", "base_area", "base_second_moment", "base_length", "base_width")

#: Tolerance of "on the face" and "at the top" [m]: coordinates typed to the millimetre.
ON_FACE = 1e-3


def variable(kind: str, key: str, given: Mapping[str, float] | None = None) -> Variable:
    """The :class:`Variable` of ``key`` (or its shorthand) in a scene of ``kind``; with ``given``
    (the scene's values, :func:`given_dimensions`), one of the keys that scene has.

    Raises
    ------
    VaryError
        naming the keys that can vary (in the scene, with ``given``), and the nearest one to a
        misspelt key; or, with ``given``, a support's size the scene's support does not have.
    """
    if kind not in VARIABLES:
        kinds = ", ".join(f'"{k}"' for k in VARIABLES)
        raise VaryError(f'a "{kind}" scene has no dimensions fcalc design can vary (it sizes {kinds} scenes)')
    every = variables(kind)
    key = ALIASES.get(kind, {}).get(key, key)
    if given is not None and key in every and key not in given:
        raise VaryError(f"{key} varies only in {every[key].where}")
    known = every if given is None else {k: v for k, v in every.items() if k in given}
    if key in known:
        return known[key]
    names = list(known) + list(ALIASES.get(kind, {}))
    close = difflib.get_close_matches(key, names, n=1, cutoff=0.6)
    hint = f"; did you mean {close[0]}?" if close else ""
    raise VaryError(f"{key} cannot vary in a {kind} scene{hint} (the keys that can: {', '.join(known)})")


def _block_table(document: Mapping[str, Any]) -> dict[str, Any] | None:
    """The document's table of the block's dimensions, or None."""
    if document.get("kind") == "crank_foundation":
        foundation = document.get("foundation")
        block = foundation.get("block") if isinstance(foundation, dict) else None
    else:
        block = document.get("block")
    return block if isinstance(block, dict) else None


def sizing_of(scene):
    """The sizing hooks (:func:`~foundation_calc.solvers.supports.base.sizing`) of the support of
    ``scene`` (a block's or a crank's), or the defaults for a scene that gives no support."""
    from foundation_calc.solvers.supports.base import Sizing, sizing

    support = getattr(scene, "support", None)
    return Sizing() if support is None else sizing(support())


def _given(document: Mapping[str, Any], sizing) -> dict[str, float]:
    """:func:`given_dimensions` of ``document``, whose support's sizing hooks are ``sizing``."""
    kind = document.get("kind")
    known = VARIABLES.get(kind)
    if known is None:
        variable(str(kind), "")
    block = _block_table(document)
    table = "[foundation.block]" if kind == "crank_foundation" else "[block]"
    needed = [key for key in known if not isinstance((block or {}).get(key.rsplit(".", 1)[1]), (int, float))]
    if needed:
        raise VaryError(f"the block's dimensions can vary only when the scene gives {table} length, width, height"
                        f" and density (missing: {', '.join(needed)})")
    return {key: float(block[key.rsplit(".", 1)[1]]) for key in known} | sizing.sizes


def volumes(scene, given: Mapping[str, float]):
    """batch -> (n,) the concrete volume [m³] of candidates of ``scene`` (varied key -> (n,); the
    ``given`` values, :func:`given_dimensions`, where not varied): the block's L B H and what its
    support adds at the candidates' sizes (:meth:`~foundation_calc.solvers.supports.base.Sizing.concrete`),
    as the evaluators count it."""
    sizing = sizing_of(scene)

    def volume(batch) -> np.ndarray:
        n = len(next(iter(batch.values())))
        values = {key: np.broadcast_to(np.asarray(batch.get(key, value), dtype=float), (n,)) for key, value in given.items()}
        L, B, H = (values[key] for key in VARIABLES[scene.kind])
        return L * B * H + sizing.concrete({key: values[key] for key in sizing.sizes})

    return volume


def given_dimensions(document: Mapping[str, Any]) -> dict[str, float]:
    """The block's length, width and height the scene gives [m], by varied key, and the sizes of
    its support's own it lets a design vary (:attr:`~foundation_calc.solvers.supports.base.Sizing.sizes`);
    the values a candidate leaves unchanged. A scene without the block's (a block given by its
    mass, a crank scene without ``[foundation.block]``) raises :class:`VaryError` naming what it needs."""
    from foundation_calc.scenes import parse_scene

    return _given(document, sizing_of(parse_scene(document, "<design>")))


def moved(position, old: tuple[float, float, float], new):
    """``position`` (… × 3 array, [x, y, z] from the centre of the base [m]) on a block resized
    from ``old`` (L, B, H) to ``new`` (L, B, H, each a scalar or an array that broadcasts against
    ``position[..., 0]``): positions at or above the top rise with it; positions on or beyond an
    end face keep their distance from the face (module docstring)."""
    position = np.asarray(position, dtype=float)
    out = []
    for axis, (before, after, half) in enumerate(zip(old, new, (0.5, 0.5, 1.0))):
        c = position[..., axis]
        if axis == 2:
            out.append(np.where(c >= before - ON_FACE, c + (after - before), c))
        else:
            out.append(np.where(np.abs(c) >= half * before - ON_FACE, c + np.sign(c) * half * (after - before), c))
    return np.stack(np.broadcast_arrays(*out), axis=-1)


def moved_positions(scene, old: tuple[float, float, float], new) -> dict[str, np.ndarray]:
    """Key -> (…, 3) [m] of every position a ``block_foundation`` scene gives
    (:meth:`~foundation_calc.scenes.block.BlockScene.positions`) on its block resized from ``old``
    to ``new`` (L, B, H; arrays over candidates broadcast, as :func:`moved`): each by :func:`moved`,
    but one a machine carries (:meth:`~foundation_calc.scenes.block.BlockScene.carried_positions`,
    a crank's centre) by its machine's displacement, as the model moves the machine's parts."""
    positions = scene.positions()
    carriers = scene.carried_positions()
    found = {key: moved(p, old, new) for key, p in positions.items() if key not in carriers}
    for key, carrier in carriers.items():
        found[key] = np.asarray(positions[key], dtype=float) + (found[carrier] - np.asarray(positions[carrier], dtype=float))
    return {key: found[key] for key in positions}


def _put(document: dict, key: str, value) -> None:
    """Set ``key`` (as :meth:`~foundation_calc.scenes.block.BlockScene.positions` writes it:
    ``machines[0].cranks[1].crank_centre``) of ``document`` to ``value``."""
    *path, last = [(name, int(index[:-1]) if index else None) for name, _, index in
                   (part.partition("[") for part in key.split("."))]
    table = document
    for name, index in path:
        table = table[name] if index is None else table[name][index]
    table[last[0]] = value


def _block_positions(document: dict, scene, old, new) -> None:
    """Every position of ``scene`` (the document before the candidate's values), moved onto the
    candidate's block in ``document`` (:func:`moved_positions`)."""
    for key, position in moved_positions(scene, old, new).items():
        _put(document, key, [float(v) for v in position])


def _crank_c_height(foundation: dict, dimensions) -> float:
    """Height of C above the base [m] of the block with ``dimensions`` and the scene's machine."""
    from foundation_calc.solvers.crank.block import block_with_machine

    block, machine = foundation["block"], foundation.get("machine") or {}
    L, B, H = dimensions
    return float(block_with_machine(L, B, H, block["density"], machine.get("mass", 0.0), machine.get("cog_height", 0.0),
                                    machine.get("moment_of_inertia", 0.0)).h)


def moved_from_c(horizontal, height, h_old, h_new, old, new):
    """(horizontal, height) from C [m] of a position given from C (a crank scene's points, loads,
    the crank axis's ``a``) on a block resized from ``old`` to ``new`` (L, B, H), C moving from
    ``h_old`` to ``h_new`` above the base: moved in base coordinates by :func:`moved`, measured
    again from the new C. Arrays broadcast (a batch of candidates), as :func:`moved`."""
    at = np.stack(np.broadcast_arrays(np.asarray(horizontal, dtype=float), 0.0, np.asarray(height, dtype=float) + h_old),
                  axis=-1)
    x, _, z = np.moveaxis(moved(at, old, new), -1, 0)
    return x, z - h_new


def moved_machine_height(cog_height, old, new):
    """A crank machine's ``cog_height`` above the base [m] on a block resized from ``old`` to
    ``new``: it rises with the top when it stands on it (:func:`moved`)."""
    return np.moveaxis(moved(np.stack(np.broadcast_arrays(0.0, 0.0, np.asarray(cog_height, dtype=float)), axis=-1),
                             old, new), -1, 0)[2]


def _crank_positions(document: dict, old, new) -> None:
    """Move the machine, and re-measure from the new C the positions given from C."""
    foundation = document["foundation"]
    h_old = _crank_c_height(foundation, old)
    machine = foundation.get("machine")
    if isinstance(machine, dict) and "cog_height" in machine:
        machine["cog_height"] = float(moved_machine_height(machine["cog_height"], old, new))
    h_new = _crank_c_height(foundation, new)

    def from_c(horizontal: float, height: float) -> tuple[float, float]:
        x, z = moved_from_c(horizontal, height, h_old, h_new, old, new)
        return float(x), float(z)

    mechanism = document.get("mechanism")
    if isinstance(mechanism, dict) and "crank_axis_to_cog" in mechanism:
        mechanism["crank_axis_to_cog"] = from_c(0.0, mechanism["crank_axis_to_cog"])[1]
    located = [load.get("at") for load in document.get("loads", [])] + list(document.get("points", []))
    for at in located:
        if isinstance(at, dict):
            for key, value in zip(("horizontal", "height"), from_c(at.get("horizontal", 0.0), at.get("height", 0.0))):
                if key in at or value != 0.0:  # a key left out (0, at C) stays out while it stays 0
                    at[key] = value
    for key in CRANK_DERIVED:
        foundation.pop(key, None)


def applied_document(document: Mapping[str, Any], candidate: Mapping[str, float]) -> dict[str, Any]:
    """A copy of the scene ``document`` (parsed TOML) with the ``candidate``'s values (varied key
    or shorthand -> value [m]) put in, and what depends on them moved or left out (module
    docstring). Keys the candidate does not name keep the scene's values."""
    from foundation_calc.scenes import parse_scene

    kind = document.get("kind")
    scene = parse_scene(document, "<design>")
    sizing = sizing_of(scene)
    old_values = _given(document, sizing)
    new_values = dict(old_values)
    for key, value in candidate.items():
        new_values[variable(kind, key, old_values).key] = float(value)
    result = copy.deepcopy(dict(document))
    for key, value in new_values.items():
        _put(result, key, value)
    old, new = (tuple(values[key] for key in VARIABLES[kind]) for values in (old_values, new_values))
    if kind == "crank_foundation":
        _crank_positions(result, old, new)
    else:
        _block_positions(result, scene, old, new)
    for key, value in sizing.plan_changes(old[:2], new[:2]).items():
        _put(result, key, value)
    return result


def apply(document: Mapping[str, Any], candidate: Mapping[str, float], source: str = "<design>"):
    """The validated scene model of :func:`applied_document` (raises
    :class:`~foundation_calc.errors.SceneError` when the candidate's scene is invalid)."""
    from foundation_calc.scenes import parse_scene

    return parse_scene(applied_document(document, candidate), source)


__all__ = ["ALIASES", "CRANK_DERIVED", "VARIABLES", "Variable", "VaryError", "applied_document", "apply",
           "given_dimensions", "moved", "moved_from_c", "moved_positions",
           "moved_machine_height", "sizing_of", "variable", "variables", "volumes"]
