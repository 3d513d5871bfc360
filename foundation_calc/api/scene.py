"""A scene for the Python API: :func:`load` reads a file or takes a mapping and validates it as
the commands do."""

from __future__ import annotations

import copy
import os
from collections.abc import Mapping
from dataclasses import dataclass, field, replace
from pathlib import Path
from typing import Any

#: Source name of a scene given as a mapping (what the documents' ``scene`` then say).
MAPPING_SOURCE = "<scene>"


@dataclass(frozen=True, eq=False)
class Scene:
    """A validated scene.

    Attributes
    ----------
    model : pydantic model
        The scene's model (:mod:`foundation_calc.scenes`), every number in SI units.
    source : str
        The file as the documents name it (``scene``, ``source``), or ``"<scene>"`` for a mapping.
    document : dict
        The scene as read: the file's keys with the office defaults of its ``fcalc.toml``, numbers
        written with a unit (``"6000 mm"``) as written.
    path : pathlib.Path or None
        The scene file; None for a mapping.
    written : dict
        The values written with a unit, by dotted key (``{"block.length": "6000 mm"}``).
    """

    model: Any
    source: str
    document: dict = field(repr=False)
    path: Path | None = None
    written: dict = field(default_factory=dict, repr=False)

    @property
    def kind(self) -> str:
        """``crank_foundation``, ``block_foundation`` or ``platform``."""
        return self.model.kind

    @property
    def name(self) -> str:
        """The scene's ``name`` (``""`` when it gives none)."""
        return self.model.name

    @property
    def warnings(self) -> list[str]:
        """The plausibility warnings (a value that looks like a wrong unit); they never change a
        verdict and the documents carry them."""
        return self.model.plausibility_warnings()


def load(scene: str | os.PathLike | Mapping | Scene, *, source: str | None = None) -> Scene:
    """Read and validate a scene, as every command does with its SCENE argument.

    Parameters
    ----------
    scene : str, os.PathLike, Mapping or Scene
        A scene file (TOML; the office defaults of the nearest ``fcalc.toml`` apply), or a mapping
        with the keys a scene file has (``{"kind": "crank_foundation", "foundation": {...}}``;
        numbers bare SI or strings with their unit, as in a file). A :class:`Scene` is returned
        as it is.
    source : str, optional
        The name the documents give the scene; default: the path as given, ``"<scene>"`` for a
        mapping.

    Returns
    -------
    Scene

    Raises
    ------
    SceneError
        The file cannot be read, is not TOML, or the scene fails validation; its ``problems``
        are the ``problems`` of the JSON documents (``fcalc check --json``) for the scene.
    """
    return scene_of(scene, source=source)


def scene_of(scene, expect: str | tuple[str, ...] | None = None, source: str | None = None,
             platform_as_block: bool = False) -> Scene:
    """:func:`load` for a command that takes the kinds ``expect`` (None: any): a scene of another
    kind is a :class:`~foundation_calc.errors.SceneError` naming the commands that take it; a file
    of another kind is refused before it is validated, as the commands refuse it. With
    ``platform_as_block`` (a command of the one rigid body) a ``platform`` scene is taken too, read
    as its block on its isolators (:meth:`~foundation_calc.scenes.platform.PlatformScene.as_block`)."""
    from foundation_calc.scenes.loading import expect_kind, parse_scene_as_written

    if platform_as_block:
        expect = ((expect,) if isinstance(expect, str) else tuple(expect)) + ("platform",)
    if isinstance(scene, Scene):
        expect_kind(scene.kind, expect, scene.source)
        if platform_as_block and scene.kind == "platform":
            return replace(scene, model=scene.model.as_block(scene.source))
        return scene
    document, source, path = read(scene, source)
    model, written = parse_scene_as_written(document, source, expect)  # it converts into a new document
    if platform_as_block and model.kind == "platform":
        model = model.as_block(source)
    return Scene(model, source, document, path, written)


def read(scene, source: str | None = None) -> tuple[dict, str, Path | None]:
    """The document of a scene file (with its office defaults) or a copy of a mapping's, the
    scene's source name (``source``, else the path, else ``"<scene>"``) and its path (None for a
    mapping), not yet validated."""
    from foundation_calc.scenes.loading import read_scene

    if isinstance(scene, Scene):
        return copy.deepcopy(scene.document), scene.source if source is None else source, scene.path
    if isinstance(scene, Mapping):
        source = MAPPING_SOURCE if source is None else source
        try:  # the caller's mapping stays the caller's
            return copy.deepcopy(dict(scene)), source, None
        except RecursionError:
            from foundation_calc.errors import SceneError

            raise SceneError(source, [("", "is nested too deeply")]) from None
    path = Path(scene)
    return read_scene(path), str(path) if source is None else source, path
