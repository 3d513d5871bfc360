"""``fcalc schema KIND``: the JSON Schema of a scene kind, for editors that validate TOML."""

from __future__ import annotations

from foundation_calc.cli.guard import reports_errors
from foundation_calc.cli.kinds import KindArg


@reports_errors
def schema(kind: KindArg) -> None:
    """Print the JSON Schema (draft 2020-12) of scene files of KIND on stdout.

    Save it next to your scenes and point the editor at it, e.g. with a first line
    `#:schema ./block_foundation.schema.json` (taplo / Even Better TOML); see docs/commands.md.
    """
    from foundation_calc.output.console import print_json
    from foundation_calc.scenes.schema import scene_schema

    print_json(scene_schema(kind))
