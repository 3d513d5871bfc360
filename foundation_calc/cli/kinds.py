"""The KIND argument shared by ``fcalc init`` and ``fcalc schema``, and the scene-file argument of
every command."""

from __future__ import annotations

from typing import Annotated, Any

import typer

from foundation_calc.scenes.kinds import KINDS


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


#: The SCENE help of the commands of the one rigid body (resonance, amplitudes, sweep, soil).
RIGID_BODY_SCENE = ("Scene file (TOML) of kind block_foundation or crank_foundation, or a platform (read as a block on"
                    " its designed isolators).")


def scene_argument(help: str, metavar: str = "SCENE") -> Any:
    """A typer argument naming scene files. fcalc reads them itself, so an unreadable file is an
    invalid scene (exit 3, with the reason), not a usage error of typer's (exit 2)."""
    return typer.Argument(metavar=metavar, help=help, show_default=False, readable=False)
