"""``fcalc bench [SCENE...]``: run time against error of every method, throughput and start-up."""

from __future__ import annotations

from enum import Enum
from pathlib import Path
from typing import Annotated, Optional

import typer

from foundation_calc.cli.kinds import scene_argument
from foundation_calc.cli.guard import reports_errors


class Section(str, Enum):
    accuracy = "accuracy"
    harmonic_balance = "harmonic_balance"
    runup = "runup"
    throughput = "throughput"
    startup = "startup"
    points = "points"
    batch = "batch"
    block = "block"
    soil_sample = "soil_sample"
    design = "design"


ScenesArg = Annotated[
    Optional[list[Path]],
    scene_argument("Scene files (TOML). Default: every scene file in ./configs."),
]
JsonOpt = Annotated[bool, typer.Option("--json", help="Print one JSON document (seconds, bytes, relative errors).")]
PlotOpt = Annotated[
    Optional[Path],
    typer.Option("--plot", metavar="FILE.png", help="Also draw error against time (log-log); needs the plot extra (matplotlib).", show_default=False),
]
DesignsOpt = Annotated[
    Optional[int],
    typer.Option("--designs", min=1000, help="Designs in the throughput batch. Default: 1e6 (1e5 with --quick).", show_default=False),
]
QuickOpt = Annotated[bool, typer.Option("--quick", help="Shorter timings (fewer repetitions, 1e5 designs, 5 start-up runs).")]
MethodOpt = Annotated[
    Optional[list[str]],
    typer.Option("--method", metavar="KEY", help="Only these methods (repeatable; keys as in --json, e.g."
                 " first_approximation, averaged_operator, harmonic_balance_K4, shooting_solve_ivp)."
                 " The converged reference is always computed.", show_default=False),
]
BatchOpt = Annotated[
    Optional[int],
    typer.Option("--batch-scenes", min=0, help="Scenes in the large fcalc check batch (0: leave it out)."
                 " Default: 10000 (1000 with --quick).", show_default=False),
]
SkipOpt = Annotated[
    Optional[list[Section]], typer.Option("--skip", help="Leave out a section (repeatable).", show_default=False)
]

#: Seconds each method is timed for (at least 3 calls after a warm-up), normal and --quick.
MIN_TIME = {False: 0.2, True: 0.02}
STARTUP_RUNS = {False: 20, True: 5}
POINTS_RUNS = {False: 3, True: 1}
#: fcalc check batch: platform scenes in the small runs, their rounds, scenes in the large batch.
BATCH_MANY, BATCH_ROUNDS, BATCH_LARGE = 100, {False: 5, True: 2}, {False: 10_000, True: 1_000}


def _default_scenes() -> list[Path]:
    folder = Path("configs")
    if not folder.is_dir():
        raise typer.BadParameter("no scene given and no ./configs folder here", param_hint="SCENE")
    return sorted(folder.glob("*.toml"))


def _chosen(methods, keys):
    if not keys:
        return methods
    known = {m.key for m in methods}
    unknown = [k for k in keys if k not in known]
    if unknown:
        raise typer.BadParameter(f"unknown method {unknown[0]!r}; choose from {', '.join(sorted(known))}", param_hint="'--method'")
    return tuple(m for m in methods if m.key in keys)


def _sized_scenes(loaded) -> list:
    """The first block scene and the first crank scene with [foundation.block]: what fcalc design sizes."""
    first = {}
    for path, scene in loaded:
        block = scene.kind == "block_foundation" and scene.block.height is not None
        crank = scene.kind == "crank_foundation" and scene.foundation.block is not None
        if (block or crank) and scene.kind not in first:
            first[scene.kind] = (path, scene)
    return list(first.values())


@reports_errors
def bench(
    scenes: ScenesArg = None,
    json: JsonOpt = False,
    plot: PlotOpt = None,
    designs: DesignsOpt = None,
    quick: QuickOpt = False,
    skip: SkipOpt = None,
    method: MethodOpt = None,
    batch_scenes: BatchOpt = None,
) -> None:
    """Time every amplitude method on each crank scene and report its error against the exact solution.

    Methods: the paper's corrected first approximation, the averaged-operator closed form,
    harmonic balance at K = 1, 2, 4, 8, 16 harmonics, shooting with scipy's solve_ivp, and the
    converged harmonic balance that is the reference (error = largest relative error of the x, y,
    θ peaks). Platform scenes: design and 6-DOF verification time, rotation residual. Platform
    harmonic balance on built-in rigs of 1, 3 and 17 exciters: time and error against the
    truncation order K, and the whole check of each rig against one exciter. Start-up: the
    closed form of every resonance passed against the time integration (exponential integrator
    and scipy's DOP853) on a platform and a crank rig. Then the
    designs per second of one vectorised call against a Python loop (closed-form amplitudes
    undamped and damped, and a damped speed sweep of a tenth as many speeds), fcalc's start-up against
    its frameworks', and whole fcalc processes on that scene with 10, 1 000 and 15 000 points
    (time and memory against 10 points) — all measured in this run, on the first crank scene. Last,
    fcalc check on copies of the first platform scene (1 and 100; one job and two: the marginal cost
    of a scene and the scaling with --jobs) and on a large batch of copies of all scenes (peak memory).
    Block scenes: one scene's whole check and a sweep of 10 000 speeds of its first machine.
    Soil sample: seconds of fcalc soil --sample with 10⁵ designs of the first crank scene.
    Design: fcalc design's search over about 10⁵ candidates with the vectorised evaluator against
    a loop over fcalc check's path (200 candidates timed, scaled), on the first block scene and the
    first crank scene with [foundation.block].
    """
    from foundation_calc.api.options import plot_path, writing

    if plot is not None:
        plot_path(plot)
    skipped = set(skip or [])
    paths = list(scenes) if scenes else _default_scenes()

    from foundation_calc.scenes import load_scene

    loaded = [(path, load_scene(path)) for path in paths]
    # the amplitude methods, throughput, start-up and points need a crank mechanism
    cranks = [(p, s) for p, s in loaded if s.kind == "crank_foundation" and s.mechanism is not None]
    left_out = [
        (str(p), "a machine given by its loads, without [mechanism]: not in the accuracy, throughput, start-up"
                 " and points sections")
        for p, s in loaded if s.kind == "crank_foundation" and s.mechanism is None
    ]
    platforms = [(p, s) for p, s in loaded if s.kind == "platform"]
    blocks = [(p, s) for p, s in loaded if s.kind == "block_foundation"]
    if not blocks:
        skipped.add(Section.block)
    if not cranks:  # throughput, start-up, points and the soil sample are measured on the first crank scene
        skipped |= {Section.throughput, Section.startup, Section.points, Section.soil_sample}
    if not platforms:  # the batch's marginal cost is that of a platform scene
        skipped.add(Section.batch)
    sized = _sized_scenes(loaded)
    if not sized:
        skipped.add(Section.design)

    from foundation_calc.benchmarks.accuracy import METHODS, benchmark_scene
    from foundation_calc.output import bench_report as report

    methods = _chosen(METHODS, method)
    steps = len(cranks) * len(methods) if Section.accuracy not in skipped else 0
    steps += len(platforms) if Section.accuracy not in skipped else 0
    steps += 3 * (Section.harmonic_balance not in skipped)
    steps += 3 * (Section.runup not in skipped)
    steps += 4 * (Section.throughput not in skipped) + (Section.startup not in skipped)
    steps += Section.points not in skipped
    steps += Section.soil_sample not in skipped
    large = BATCH_LARGE[quick] if batch_scenes is None else batch_scenes
    steps += (1 + (large > 0)) * (Section.batch not in skipped)
    steps += len(blocks) * (Section.block not in skipped)
    steps += len(sized) * (Section.design not in skipped)
    results, platform_results, throughput, startup, truncation, batch, points = [], [], None, None, None, None, None
    runups, block_timings, sampled, sizing = None, None, None, None
    with report.progress_bar(steps) as step:
        if Section.accuracy not in skipped:
            for path, scene in cranks:
                results.append(
                    benchmark_scene(str(path), scene.name, scene.design(), methods=methods, min_time=MIN_TIME[quick],
                                    on_method=lambda label, p=path: step(f"{p.name}: {label}"))
                )
            if platforms:
                from foundation_calc.benchmarks.platform import benchmark_platform

                for path, scene in platforms:
                    step(f"{path.name}: design + 6-DOF verification")
                    platform_results.append(benchmark_platform(str(path), scene, min_time=MIN_TIME[quick]))
        if Section.harmonic_balance not in skipped:
            from foundation_calc.benchmarks.harmonic_balance import benchmark_truncation

            truncation = benchmark_truncation(MIN_TIME[quick], on_rig=step)
        if Section.runup not in skipped:
            from foundation_calc.benchmarks.runup import benchmark_runup

            runups = benchmark_runup(MIN_TIME[quick], on_rig=step)
        if Section.throughput not in skipped:
            from foundation_calc.benchmarks.throughput import (
                amplitude_throughput,
                damped_variant,
                resonance_throughput,
                sweep_throughput,
                undamped_variant,
            )

            design = cranks[0][1].design()
            n = designs or (100_000 if quick else 1_000_000)
            sample = min(2_000, max(100, n // 50))  # designs timed one by one
            step(f"throughput: resonance check, {n:.3g} designs")
            throughput = {"resonance_check": resonance_throughput(design, n, sample)}
            step(f"throughput: closed-form amplitudes, {n:.3g} designs")
            throughput["closed_form_amplitudes"] = amplitude_throughput(undamped_variant(design), n, sample)
            damped = damped_variant(design)
            step(f"throughput: damped closed-form amplitudes, {n:.3g} designs")
            throughput["closed_form_amplitudes_damped"] = amplitude_throughput(damped, n, sample)
            step(f"throughput: damped speed sweep, {n // 10:.3g} speeds")
            throughput["sweep_damped"] = sweep_throughput(damped, n // 10, min(sample, 200))
        if Section.startup not in skipped:
            from foundation_calc.benchmarks.startup import startup_times

            step("start-up: fcalc resonance against typer, pydantic, rich")
            startup = startup_times(str(cranks[0][0]), runs=STARTUP_RUNS[quick])
        if Section.points not in skipped:
            from foundation_calc.benchmarks.points import POINT_COUNTS, points_scaling

            step(f"points: {', '.join(map(str, POINT_COUNTS))} points, tables, JSON and check")
            points = points_scaling(str(cranks[0][0]), runs=POINTS_RUNS[quick])
        if Section.soil_sample not in skipped:
            from foundation_calc.benchmarks.soil_sample import SAMPLES, soil_sample_timing

            step(f"soil sample: {SAMPLES:.3g} designs of {cranks[0][0].name}")
            sampled = soil_sample_timing(cranks[0][1], MIN_TIME[quick])
        if Section.batch not in skipped:
            from foundation_calc.benchmarks.batch import batch_benchmark

            batch = batch_benchmark(platforms[0][0], paths, BATCH_MANY, large, BATCH_ROUNDS[quick], on_step=step)
        if Section.block not in skipped:
            from foundation_calc.benchmarks.block import benchmark_block

            block_timings = []
            for path, scene in blocks:
                step(f"{path.name}: block check and speed sweep")
                block_timings.append(benchmark_block(str(path), scene, MIN_TIME[quick]))
        if Section.design not in skipped:
            from foundation_calc.benchmarks.design import CANDIDATES, benchmark_design
            from foundation_calc.scenes.loading import read_scene

            sizing = []
            for path, scene in sized:
                step(f"{path.name}: fcalc design, {CANDIDATES:.0e} candidates against a loop over fcalc check")
                sizing.append(benchmark_design(str(path), scene, read_scene(path), MIN_TIME[quick]))
    if plot is not None:
        with writing(plot, "--plot"):
            report.plot_bench(results, plot)
    if json:
        from foundation_calc.output.console import print_json

        document = report.bench_document(results, platform_results, throughput, startup, truncation, batch, runups)
        document["skipped_scenes"] = [{"scene": scene, "reason": reason} for scene, reason in left_out]
        if points is not None:
            from foundation_calc.output.bench_points import points_document

            document["points_scaling"] = points_document(points)
        if block_timings is not None:
            from foundation_calc.output.bench_block import block_document

            document["block"] = block_document(block_timings)
        if sizing is not None:
            from foundation_calc.output.bench_design import design_bench_document

            document["design"] = design_bench_document(sizing)
        if sampled is not None:
            document["soil_sample"] = {"samples": sampled.samples, "seconds": sampled.seconds,
                                       "peak_bytes": sampled.peak_bytes}
        print_json(document)
    else:
        report.print_skipped(left_out)
        report.print_bench(results, platform_results, throughput, startup, truncation, batch, runups)
        if points is not None:
            from foundation_calc.output.bench_points import print_points

            print_points(points)
        if block_timings is not None:
            from foundation_calc.output.bench_block import print_block

            print_block(block_timings)
        if sizing is not None:
            from foundation_calc.output.bench_design import print_design_bench

            print_design_bench(sizing)
        if sampled is not None:
            from foundation_calc.output.console import stdout

            stdout().print(
                f"soil sample (fcalc soil --sample): {sampled.samples} designs in {sampled.seconds:.3g} s"
                f" ({sampled.per_second:.3g} a second), peak memory {sampled.peak_bytes / 2**20:.3g} MiB"
            )
        if plot is not None:
            from foundation_calc.output.console import stderr

            stderr().print(f"plot written to {plot}")
