"""The KIND argument shared by ``fcalc init`` and ``fcalc schema``."""

from __future__ import annotations

from typing import Annotated

import typer

from foundation_calc.scenes.loading import KINDS


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
