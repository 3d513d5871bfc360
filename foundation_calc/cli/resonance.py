"""``fcalc resonance SCENE``: natural frequencies and resonance margins (:func:`foundation_calc.api.resonance.resonance`)."""

from __future__ import annotations

from pathlib import Path
from typing import Annotated

import typer

from foundation_calc.cli.guard import reports_errors, warn_implausible
from foundation_calc.cli.kinds import RIGID_BODY_SCENE, scene_argument
from foundation_calc.cli.units import UnitsOpt

SceneArg = Annotated[Path, scene_argument(RIGID_BODY_SCENE)]
JsonOpt = Annotated[bool, typer.Option("--json", help="Print one JSON document (SI units) instead of tables.")]
StrictOpt = Annotated[bool, typer.Option("--strict", help="Treat warnings (extra resonances) as failures.")]


@reports_errors
def resonance(scene: SceneArg, json: JsonOpt = False, strict: StrictOpt = False, units: UnitsOpt = None) -> None:
    """Natural frequencies of the foundation and the margin of every machine's speed from each.

    A block_foundation (or a platform, read as a block on its isolators): the six modes of the
    rigid body on its supports, each named by its dominant motion, and every order n of every
    machine against every mode; a crank_foundation: the paper's k0, p1, p2 and its conditions
    ω = k0, 2ω = k0, ω = p1,p2, 3ω = p1,p2, with the extra ones 4ω = k0, 2ω = p1,p2 and, with
    [[loads]], n ω = k0, p1, p2 for every order n of the loads. One rule judges every kind
    (docs/resonance-rule.md): a condition the source names, or whose order forces its mode with a
    share of at least 1 %, fails inside the [limits] detuning band (default 20 %) of its order.
    """
    from foundation_calc.api.options import display_units
    from foundation_calc.api.resonance import KINDS, resonance
    from foundation_calc.api.scene import scene_of

    shown = display_units(units)
    loaded = scene_of(scene, KINDS, platform_as_block=True)
    warn_implausible(loaded.model)
    result = resonance(loaded, strict=strict)
    if json:
        from foundation_calc.output.console import print_json

        print_json(result.document)
    else:
        from foundation_calc.output.resonance import print_resonance

        print_resonance(result.report, loaded.model, loaded.source, shown, strict)
    raise typer.Exit(result.exit_code)
