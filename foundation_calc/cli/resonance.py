"""``fcalc resonance SCENE``: natural frequencies and resonance margins of a crank foundation."""

from __future__ import annotations

from pathlib import Path
from typing import Annotated

import typer

from foundation_calc.cli.kinds import scene_argument
from foundation_calc.cli.guard import reports_errors, warn_implausible
from foundation_calc.cli.kinds import KIND_MODULES, run_kind
from foundation_calc.cli.units import UnitsOpt, display_units

SceneArg = Annotated[Path, scene_argument("Scene file (TOML) of kind crank_foundation or block_foundation.")]
JsonOpt = Annotated[bool, typer.Option("--json", help="Print one JSON document (SI units) instead of tables.")]
StrictOpt = Annotated[bool, typer.Option("--strict", help="Treat warnings (extra resonances) as failures.")]


@reports_errors
def resonance(scene: SceneArg, json: JsonOpt = False, strict: StrictOpt = False, units: UnitsOpt = None) -> None:
    """Natural frequencies k0, p1, p2 and the margin of the crank speed from every resonance.

    Checks the paper's conditions ω = k0, 2ω = k0, ω = p1,p2, 3ω = p1,p2 (fail inside the
    [limits] detuning band, default 20 %) and the extra ones 4ω = k0, 2ω = p1,p2 (warn); with
    [[loads]], n ω = k0, p1, p2 for every order n of the loads.
    """
    from foundation_calc.checks.crank_resonance import check_scene_resonances
    from foundation_calc.checks.outcomes import exit_code
    from foundation_calc.output import crank_resonance as report_out
    from foundation_calc.scenes import load_scene

    shown = display_units(units)
    loaded = load_scene(scene, expect=("crank_foundation", *KIND_MODULES))
    warn_implausible(loaded)
    if loaded.kind in KIND_MODULES:
        run_kind("resonance", loaded, str(scene), json=json, strict=strict, units=shown)
    report = check_scene_resonances(loaded)
    if json:
        from foundation_calc.output.console import print_json

        print_json(report_out.resonance_document(report, loaded, str(scene)))
    else:
        report_out.print_resonance_report(report, loaded, str(scene), shown, strict)
    raise typer.Exit(int(exit_code(report.outcome, strict, bool(loaded.plausibility_warnings()))))
