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
SampleOpt = Annotated[int, typer.Option(
    "--sample", min=0, max=10_000_000, metavar="N",
    help="Also sample the uncertain soil N times (lognormal stiffness factor, median 1) and report percentiles"
    " and the probability that each check fails (0: no sample).")]
ModulusCovOpt = Annotated[float, typer.Option(
    "--modulus-cov", min=0.0, max=2.0, help="Coefficient of variation of the soil's stiffness in the sample [-].")]
SpeedCovOpt = Annotated[float, typer.Option(
    "--speed-cov", min=0.0, max=0.5, help="Coefficient of variation of the speed in the sample (normal, mean as given) [-].")]
SeedOpt = Annotated[int, typer.Option("--seed", min=0, help="Seed of the sample's random numbers.")]


@reports_errors
def soil(scene: SceneArg, json: JsonOpt = False, sample: SampleOpt = 0, modulus_cov: ModulusCovOpt = 0.3,
         speed_cov: SpeedCovOpt = 0.0, seed: SeedOpt = 0) -> None:
    """Soil springs and damping of every method the scene's [soil] data allow, side by side.

    K_z, K_x [N/m] and K_φ [N m/rad]; the equivalent c_z, c_x, c_phi [N/m³]; damping ratios [-]
    and base dashpots; uncoupled vertical, horizontal and rocking frequencies and the coupled
    k0, p1, p2 (tables in Hz, JSON in rad/s). The scene's method is marked with *. Warns when a
    modulus looks static where a dynamic one is meant (or the reverse) and when methods differ
    by more than a factor of 2. With --sample N, the soil's stiffness is sampled (lognormal, median
    1, --modulus-cov) and the percentiles of k0, p1, p2, of the resonance margin and of the peak
    displacements of C are reported with the probability that each check fails. It judges
    nothing: exit 0 for any valid scene.
    """
    from foundation_calc.checks.soil_methods import compare_soil_methods
    from foundation_calc.output import soil as soil_out
    from foundation_calc.scenes import load_scene

    loaded = load_scene(scene, expect=("crank_foundation", *KIND_MODULES))
    warn_implausible(loaded)
    if loaded.kind in KIND_MODULES:
        run_kind("soil", loaded, str(scene), json=json, sample=sample, modulus_cov=modulus_cov, speed_cov=speed_cov, seed=seed)
    comparison = compare_soil_methods(loaded)
    drawn = None
    if sample and loaded.mechanism is None:
        raise typer.BadParameter(
            "samples the crank mechanism's closed forms; this scene gives the machine by its [[loads]] only",
            param_hint="'--sample'",
        )
    if sample:
        from foundation_calc.checks.soil_sample import sample_scene

        drawn = sample_scene(loaded, sample, modulus_cov, speed_cov, seed)
    if json:
        from foundation_calc.output.console import print_json

        print_json(soil_out.soil_document(comparison, loaded, str(scene)) | {"sample": soil_out.sample_document(drawn)})
    else:
        soil_out.print_soil_report(comparison, loaded, str(scene))
        if drawn is not None:
            soil_out.print_sample(drawn)
