"""``fcalc soil SCENE``: springs, damping and frequencies of every soil method the scene allows."""

from __future__ import annotations

from pathlib import Path
from typing import Annotated

import typer

from foundation_calc.cli.kinds import scene_argument
from foundation_calc.cli.guard import reports_errors, warn_implausible
from foundation_calc.cli.kinds import KIND_MODULES, run_kind

SceneArg = Annotated[Path, scene_argument("Scene file (TOML) of kind crank_foundation or block_foundation.")]
JsonOpt = Annotated[bool, typer.Option("--json", help="Print one JSON document (SI units) instead of tables.")]


@reports_errors
def soil(scene: SceneArg, json: JsonOpt = False) -> None:
    """Soil springs and damping of every method the scene's [soil] data allow, side by side.

    K_z, K_x [N/m] and K_φ [N m/rad]; the equivalent c_z, c_x, c_phi [N/m³]; damping ratios [-]
    and base dashpots; uncoupled vertical, horizontal and rocking frequencies and the coupled
    k0, p1, p2 (tables in Hz, JSON in rad/s). The scene's method is marked with *. Warns when a
    modulus looks static where a dynamic one is meant (or the reverse) and when methods differ
    by more than a factor of 2. It judges nothing: exit 0 for any valid scene.
    """
    from foundation_calc.checks.soil_methods import compare_soil_methods
    from foundation_calc.output import soil as soil_out
    from foundation_calc.scenes import load_scene

    loaded = load_scene(scene, expect=("crank_foundation", *KIND_MODULES))
    warn_implausible(loaded)
    if loaded.kind in KIND_MODULES:
        run_kind("soil", loaded, str(scene), json=json)
    comparison = compare_soil_methods(loaded)
    if json:
        from foundation_calc.output.console import print_json

        print_json(soil_out.soil_document(comparison, loaded, str(scene)))
    else:
        soil_out.print_soil_report(comparison, loaded, str(scene))
