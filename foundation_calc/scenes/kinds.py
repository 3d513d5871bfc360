"""The scene kinds: the model of each (imported on first use), the commands that take it, and the
tables that make a TOML document a scene."""

from __future__ import annotations

import importlib
from typing import Any

#: scene kind -> "module:Model"; a module is imported only when a scene of its kind is read.
KINDS: dict[str, str] = {
    "crank_foundation": "foundation_calc.scenes.crank:CrankScene",
    "block_foundation": "foundation_calc.scenes.block:BlockScene",
    "platform": "foundation_calc.scenes.platform:PlatformScene",
}

#: scene kind -> the single-scene commands that take it (for messages that point the way).
KIND_COMMANDS: dict[str, tuple[str, ...]] = {
    "crank_foundation": ("resonance", "amplitudes", "sweep", "soil"),
    "platform": ("platform", "resonance", "amplitudes", "sweep", "soil", "runup", "check", "report"),
    "block_foundation": ("resonance", "amplitudes", "sweep", "runup", "soil", "check", "report"),
}

#: Top-level tables of the scene kinds (of :data:`KINDS`, and ``block``/``machines`` of the block
#: foundation): a TOML file with any of them is a scene, with or without its kind line.
SCENE_TABLES = frozenset({
    "foundation", "soil", "mechanism", "operation", "loads", "limits", "drive", "points",
    "platform", "exciter", "isolators", "isolation", "extra_exciters", "block", "machines", "piles", "report",
})

def model_for_kind(kind: str) -> type:
    """Return the pydantic model class of a scene kind (imported on first use)."""
    module_name, _, class_name = KINDS[kind].partition(":")
    return getattr(importlib.import_module(module_name), class_name)


def is_scene(data: dict[str, Any]) -> bool:
    """True when a TOML document is meant as a scene: it has a ``kind`` or a scene table
    (:data:`SCENE_TABLES`); ``pyproject.toml`` or ``.taplo.toml`` have neither."""
    return "kind" in data or not SCENE_TABLES.isdisjoint(data)
