"""``fcalc soil SCENE``: springs, damping and frequencies of every soil method the scene allows
(:func:`foundation_calc.api.soil.soil`)."""

from __future__ import annotations

from pathlib import Path
from typing import Annotated

import typer

from foundation_calc.api.soil import RANGES
from foundation_calc.cli.guard import reports_errors, warn_implausible
from foundation_calc.cli.kinds import RIGID_BODY_SCENE, scene_argument

SceneArg = Annotated[Path, scene_argument(RIGID_BODY_SCENE)]
JsonOpt = Annotated[bool, typer.Option("--json", help="Print one JSON document (SI units) instead of tables.")]
SampleOpt = Annotated[int, typer.Option(
    "--sample", min=RANGES["sample"][0], max=RANGES["sample"][1], metavar="N",
    help="Also sample the uncertain soil N times (lognormal stiffness factor, median 1) and report percentiles"
    " and the probability that each check fails (0: no sample).")]
ModulusCovOpt = Annotated[float, typer.Option(
    "--modulus-cov", min=RANGES["modulus_cov"][0], max=RANGES["modulus_cov"][1],
    help="Coefficient of variation of the soil's stiffness in the sample [-].")]
SpeedCovOpt = Annotated[float, typer.Option(
    "--speed-cov", min=RANGES["speed_cov"][0], max=RANGES["speed_cov"][1],
    help="Coefficient of variation of the speed in the sample (normal, mean as given) [-].")]
SeedOpt = Annotated[int, typer.Option("--seed", min=RANGES["seed"][0], help="Seed of the sample's random numbers.")]


@reports_errors
def soil(scene: SceneArg, json: JsonOpt = False, sample: SampleOpt = 0, modulus_cov: ModulusCovOpt = 0.3,
         speed_cov: SpeedCovOpt = 0.0, seed: SeedOpt = 0) -> None:
    """The support's springs and dashpots at O, every soil method the scene's data allow side by side.

    A block_foundation (or a platform, read as a block on its isolators): the six springs and
    dashpots at O (x, y, z, rx, ry, rz) of its support, with damping ratios and uncoupled
    frequencies, at rest and at the machines' orders where the method depends on frequency; on
    [piles], the group's and the piles' own tables. A crank_foundation: K_z, K_x [N/m] and K_φ
    [N m/rad] of every method, the equivalent c_z, c_x, c_phi [N/m³], damping ratios [-] and
    base dashpots, the uncoupled vertical, horizontal and rocking frequencies and the coupled
    k0, p1, p2 (tables in Hz, JSON in rad/s); on [piles], the pile group's springs and dashpots
    in the plane at O (K_x, K_z, K_φ, K_xφ; C_x, C_z, C_φ, C_xφ) at rest, at the speed's harmonics
    and at each mode's own frequency. The scene's method is marked with *. Warns when a modulus
    looks static where a dynamic one is meant (or the reverse) and when methods differ by more
    than a factor of 2. With --sample N, the soil's stiffness is sampled (lognormal, median 1,
    --modulus-cov) and the percentiles of the natural frequencies, of the resonance margin and of
    the peak displacements are reported with the probability that each check fails. It judges
    nothing: exit 0 for any valid scene.
    """
    from foundation_calc.api.resonance import KINDS
    from foundation_calc.api.scene import scene_of
    from foundation_calc.api.soil import soil
    from foundation_calc.output import soil as soil_out

    loaded = scene_of(scene, KINDS, platform_as_block=True)
    warn_implausible(loaded.model)
    result = soil(loaded, sample=sample, modulus_cov=modulus_cov, speed_cov=speed_cov, seed=seed)
    if json:
        from foundation_calc.output.console import print_json

        print_json(result.document)
        raise typer.Exit(result.exit_code)
    report, drawn = result.report
    if isinstance(report, soil_out.SoilComparison):
        soil_out.print_soil_report(report, loaded.model, loaded.source)
    else:  # a block, or a crank on a support that is no footing (a pile group)
        from foundation_calc.output.soil_support import print_support_soil

        print_support_soil(report, loaded.model, loaded.source)
    if drawn is not None:
        soil_out.print_sample(drawn)
    raise typer.Exit(result.exit_code)
