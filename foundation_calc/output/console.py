"""The two consoles of fcalc: results on stdout, messages (errors, warnings) on stderr."""

from __future__ import annotations

import json
from functools import cache
from typing import TYPE_CHECKING

if TYPE_CHECKING:  # rich.console costs ~10 ms to import: only the table path pays for it
    from rich.console import Console

#: JSON documents written by fcalc carry this version; it changes when a key is renamed or removed.
JSON_SCHEMA_VERSION = 1

OUTCOME_STYLE = {"pass": "bold green", "warn": "bold yellow", "fail": "bold red"}


@cache
def stdout() -> Console:
    """Console for results."""
    from rich.console import Console

    return Console(highlight=False)


@cache
def stderr() -> Console:
    """Console for messages; never mixed into JSON on stdout."""
    from rich.console import Console

    return Console(stderr=True, highlight=False)


def verdict_text(outcome: str) -> str:
    """An outcome as styled console markup, e.g. ``[bold red]FAIL[/]``."""
    return f"[{OUTCOME_STYLE[outcome]}]{outcome.upper()}[/]"


def print_json(document: dict) -> None:
    """Write one JSON document to stdout. NaN or inf in it is a bug, so it raises."""
    print(json.dumps(document, indent=2, ensure_ascii=False, allow_nan=False))


def fmt(value: float, digits: int = 5) -> str:
    """A number with ``digits`` significant figures, for tables."""
    return f"{value:.{digits}g}"
