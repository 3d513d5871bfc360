"""``fcalc bench``: its errors against an independent reference, its JSON, its optional plot.

The bench's reference is the converged harmonic balance; here each reported error is recomputed
against the shooting solution (time integration, an independent method) from the peaks of each
method's own output. The two references agree to ~1e-10, so a reported error above 1e-6 must be
reproduced to 1e-4 relative (of itself). No test looks at the measured times.
"""

from __future__ import annotations

import json
from functools import cache

import numpy as np
import pytest

from foundation_calc.benchmarks.accuracy import METHODS, REFERENCE
from foundation_calc.benchmarks.startup import startup_times
from foundation_calc.cli.app import app
from foundation_calc.scenes import load_scene
from foundation_calc.solvers.crank.response import motion_peaks
from foundation_calc.solvers.crank.shooting import shooting_solution
from tests.conftest import CONFIGS

SCENE = CONFIGS / "frame_saw_extra_resonance.toml"


@cache
def bench_json(tmp: str) -> tuple[dict, str]:
    from typer.testing import CliRunner

    args = ["bench", str(SCENE), "--quick", "--json", "--skip", "throughput", "--skip", "startup", "--skip", "batch", "--skip", "points"]
    args += ["--skip", "runup", "--skip", "harmonic_balance"]
    args += [arg for m in METHODS if m.key != "shooting_solve_ivp" for arg in ("--method", m.key)]
    plot = f"{tmp}/bench.png"
    try:
        import matplotlib  # noqa: F401

        args += ["--plot", plot]
    except ModuleNotFoundError:
        plot = ""
    result = CliRunner().invoke(app, args)
    assert result.exit_code == 0, result.output
    return json.loads(result.stdout), plot


@pytest.fixture(scope="module")
def document(tmp_path_factory):
    return bench_json(str(tmp_path_factory.mktemp("bench")))


def test_every_method_is_reported_with_time_memory_and_error(document):
    doc, _ = document
    (scene,) = doc["scenes"]
    assert [m["key"] for m in scene["methods"]] == [m.key for m in METHODS if m.key != "shooting_solve_ivp"]
    for m in scene["methods"]:
        assert m["failure"] is None
        assert m["seconds"] > 0 and m["peak_bytes"] > 0 and m["calls"] >= 3
        if m["key"] == REFERENCE.key:
            assert m["error"] is None
        else:
            assert m["error"] == max(m["errors"].values())


def test_errors_agree_with_shooting(document):
    doc, _ = document
    (scene,) = doc["scenes"]
    design = load_scene(SCENE).design()
    independent = motion_peaks(shooting_solution(design).motion).displacement
    reference = np.array([scene["reference_peaks"][k] for k in ("x", "y", "theta")])
    assert np.allclose(reference, independent, rtol=1e-8, atol=0)
    by_key = {m.key: m for m in METHODS}
    for m in scene["methods"]:
        if m["error"] is None:
            continue
        peaks = motion_peaks(by_key[m["key"]].solve(design)).displacement
        error = np.max(np.abs(peaks - independent) / independent)
        assert m["error"] == pytest.approx(error, rel=1e-4, abs=1e-8), m["key"]


def test_method_errors_are_ordered_as_the_theory_says(document):
    doc, _ = document
    err = {m["key"]: m["error"] for m in doc["scenes"][0]["methods"]}
    assert 1e-3 < err["first_approximation"] < 0.05  # O(μ) plus the missed 2ω ≈ p1 harmonic
    assert err["harmonic_balance_K1"] > err["harmonic_balance_K2"] > err["harmonic_balance_K4"] > err["harmonic_balance_K8"]
    assert err["harmonic_balance_K16"] < 1e-12


def test_plot_is_written_when_matplotlib_is_installed(document):
    _, plot = document
    if not plot:
        pytest.skip("matplotlib (the plot extra) is not installed")
    with open(plot, "rb") as handle:
        assert handle.read(8) == b"\x89PNG\r\n\x1a\n"


def test_unknown_method_is_a_usage_error(runner):
    result = runner.invoke(app, ["bench", str(SCENE), "--method", "euler"])
    assert result.exit_code == 2
    assert "first_approximation" in result.output


def test_plot_without_matplotlib_is_a_usage_error(runner, monkeypatch, tmp_path):
    monkeypatch.setattr("foundation_calc.output.plots.plotting_available", lambda: False)
    result = runner.invoke(app, ["bench", str(SCENE), "--plot", str(tmp_path / "b.png")])
    assert result.exit_code == 2
    assert "foundation_calc[plot]" in result.output
    assert not (tmp_path / "b.png").exists()


def test_throughput_section(runner, monkeypatch):
    """The section's document: each path's design count and the speed-up as the ratio of the two
    rates. No figure here depends on how often a path is timed, so each is timed once (no warm-up
    call, no minimum of calls or seconds; the call that traces memory is kept): the scalar loops
    of 100 designs, five calls each by default, were most of the test's cost."""
    from foundation_calc.benchmarks import measure, throughput

    def timed_once(fn, **options):
        return measure.measure(fn, **(options | {"min_time": 0.0, "min_calls": 1, "warm_up": False}))

    monkeypatch.setattr(throughput, "measure", timed_once)
    args = ["bench", str(SCENE), "--json", "--designs", "2000", "--skip", "accuracy", "--skip", "startup"]
    result = runner.invoke(app, [*args, "--skip", "harmonic_balance", "--skip", "batch", "--skip", "points", "--skip", "runup"])
    assert result.exit_code == 0, result.output
    doc = json.loads(result.stdout)
    assert doc["scenes"] == [] and doc["startup"] is None
    designs = {"resonance_check": 2000, "closed_form_amplitudes": 2000, "closed_form_amplitudes_damped": 2000, "sweep_damped": 200}
    for key, count in designs.items():
        t = doc["throughput"][key]
        assert t["designs"] == count
        assert t["speedup"] == pytest.approx(t["vectorised_designs_per_second"] / t["scalar_designs_per_second"])


def test_startup_rows_are_side_by_side():
    rows = startup_times(str(SCENE), runs=1)
    labels = [row.label for row in rows]
    assert "import typer, pydantic, rich" in labels and "fcalc resonance SCENE" in labels
    floor = next(r.seconds for r in rows if r.label == "import typer, pydantic, rich")
    for row in rows:
        assert row.ratio_to_import_floor == pytest.approx(row.seconds / floor)


def test_runup_rows_render_in_json_and_tables():
    from foundation_calc.benchmarks.runup import RunupBenchmark
    from foundation_calc.output.bench_report import _runup_document, _runup_table

    row = RunupBenchmark("rig", 10.0, 2, 160000, 5e-4, 0.4, 6.0, 1.2e-2, 3e-6)
    (doc,) = _runup_document([row])
    assert doc["integration_seconds"] == 0.4 and doc["closed_form_error"] == 1.2e-2
    assert _runup_table([row]).row_count == 1


def test_batch_rows_are_side_by_side_and_write_nothing_into_the_project(tmp_path, monkeypatch):
    from foundation_calc.benchmarks.batch import batch_benchmark
    from foundation_calc.output.bench_report import bench_document

    monkeypatch.chdir(tmp_path)  # scenes go to a temporary folder of their own, not here
    platform = CONFIGS / "platform_paper_example.toml"
    batch = batch_benchmark(platform, [platform, SCENE], many=3, large=4, repeats=1)
    assert list(tmp_path.iterdir()) == []
    assert (batch.one.scenes, batch.many.scenes, batch.many_two_jobs.jobs, batch.large.scenes) == (1, 3, 2, 4)
    assert batch.marginal_seconds == pytest.approx((batch.many.seconds - batch.one.seconds) / 2)
    assert batch.jobs_speedup == pytest.approx(batch.many.seconds / batch.many_two_jobs.seconds)
    for row in (batch.one, batch.many, batch.many_two_jobs, batch.large):
        assert row.seconds > 0 and row.cpu_seconds > 0 and row.peak_bytes_largest_process > 1e6
    document = json.loads(json.dumps(bench_document([], [], None, None, None, batch)))
    assert document["batch"]["large"]["scenes"] == 4
    assert document["batch"]["ratio_many_to_one"] == pytest.approx(batch.many_over_one)


def test_damped_scene_errors_agree_with_shooting():
    """The damped shipped scene (0.9 % from ω = p1): the closed forms' bench errors against the
    damped exact solution are what shooting (time integration) gives, and the averaged operator
    beats the first approximation near the resonance."""
    from foundation_calc.benchmarks.accuracy import benchmark_scene

    scene = CONFIGS / "compressor_damped_near_resonance.toml"
    design = load_scene(scene).design()
    chosen = [m for m in METHODS if m.key in ("first_approximation", "averaged_operator")]
    bench = benchmark_scene(str(scene), "damped", design, methods=chosen, min_time=0.0)
    independent = motion_peaks(shooting_solution(design).motion).displacement
    errors = {}
    for result in bench.results:
        peaks = motion_peaks(result.method.solve(design)).displacement
        errors[result.method.key] = np.max(np.abs(peaks - independent) / independent)
        assert result.error == pytest.approx(errors[result.method.key], rel=1e-4, abs=1e-8)
    assert errors["averaged_operator"] < errors["first_approximation"] / 10


def test_platform_truncation_rows_bound_their_error():
    """The harmonic-balance section on the 1- and 3-exciter rigs: the error against the converged
    solve falls with K and the solver's own estimate is never below it (the 17-exciter rig is
    left to ``fcalc bench``: it costs a minute)."""
    from foundation_calc.benchmarks.harmonic_balance import benchmark_truncation
    from foundation_calc.output.bench_report import bench_document

    rows, checks = benchmark_truncation(0.0, rigs=(0, 2))
    three = [r for r in rows if r.exciters == 3 and r.error is not None]
    assert len(three) >= 4 and [r.exciters for r in checks] == [1, 3]
    errors = [r.error for r in three]
    assert errors == sorted(errors, reverse=True) and errors[0] > 1e-3 and errors[-1] < 1e-10
    for r in three:
        assert r.estimate >= r.error
    doc = bench_document([], [], None, None, (rows, checks))["platform_harmonic_balance"]
    assert [o["exciters"] for o in doc["orders"]] == [r.exciters for r in rows]
    assert doc["whole_check"][0]["ratio_to_one_exciter"] == 1.0


def test_a_scene_a_section_cannot_use_is_skipped_and_named(runner):
    """The shipped loads-only compressor has no mechanism for the amplitude methods: the bench
    leaves it out of those sections, says so, and goes on (it exited 3 on the default scenes)."""
    loads_only = CONFIGS / "compressor_vendor_loads.toml"
    args = ["bench", str(loads_only), "--quick", "--skip", "harmonic_balance", "--skip", "runup", "--skip", "batch"]
    result = runner.invoke(app, [*args, "--json"])
    assert result.exit_code == 0, result.output
    (entry,) = json.loads(result.stdout)["skipped_scenes"]
    assert entry["scene"].endswith("compressor_vendor_loads.toml") and "mechanism" in entry["reason"]
    result = runner.invoke(app, args, env={"COLUMNS": "200"})
    assert result.exit_code == 0 and "skipped" in result.stdout and "compressor_vendor_loads" in result.stdout
