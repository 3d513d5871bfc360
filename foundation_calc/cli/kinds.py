"""The KIND argument shared by ``fcalc init`` and ``fcalc schema``, the scene-file argument of every
command, and the commands that other scene kinds than the crank foundation bring: a command that
meets a scene of a kind in :data:`KIND_MODULES` hands it to the function of the same name in that
kind's CLI module."""

from __future__ import annotations

from typing import Annotated, Any

import typer

from foundation_calc.scenes.kinds import KINDS

#: scene kind -> the CLI module whose functions ``resonance``, ``amplitudes`` ... take its scenes
#: (``(scene, source, json=, strict=, units=) -> exit code``).
KIND_MODULES: dict[str, str] = {"block_foundation": "foundation_calc.cli.block"}


def run_kind(command: str, loaded, source: str, **options) -> None:
    """Run ``command`` of a scene whose kind is in :data:`KIND_MODULES` and exit with its code."""
    import importlib

    module = importlib.import_module(KIND_MODULES[loaded.kind])
    raise typer.Exit(int(getattr(module, command)(loaded, source, **options)))


def _known_kind(kind: str) -> str:
    if kind not in KINDS:
        raise typer.BadParameter(f"unknown scene kind {kind!r}; choose from {', '.join(KINDS)}")
    return kind


KindArg = Annotated[
    str,
    typer.Argument(
        metavar="KIND", help=f"Scene kind: {', '.join(KINDS)}.", callback=_known_kind, show_default=False
    ),
]


def scene_argument(help: str, metavar: str = "SCENE") -> Any:
    """A typer argument naming scene files. fcalc reads them itself, so an unreadable file is an
    invalid scene (exit 3, with the reason), not a usage error of typer's (exit 2)."""
    return typer.Argument(metavar=metavar, help=help, show_default=False, readable=False)
