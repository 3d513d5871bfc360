"""Start-up rows of ``fcalc bench``: closed form against time integration, time and error.

Rigs: the paper's platform (the embedded default scene) with loss factor 0.05, run up in 5 s
and 10 s, and the frame saw of the default crank scene on soft soil (c_z = 1e6, c_x = 7e5 N/m³,
ξ = 0.15, 0.15, 0.1) run up in 10 s. Per rig, measured side by side in one run: the closed form
for every passage (one vectorised call), the exponential integrator of the whole run, and
scipy's DOP853 on the same equations (rtol 1e-9) as an independent integrator; errors are the
relative difference of the largest passage's peak (closed form against the exponential
integrator; a weaker passage's mode also carries the other harmonics' motion, which the closed
form leaves out) and of the largest point displacement (exponential against DOP853).
"""

from __future__ import annotations

from dataclasses import dataclass, replace

import numpy as np

from foundation_calc.benchmarks.measure import measure


@dataclass(frozen=True)
class RunupBenchmark:
    """One rig: median times [s], steps of the exponential integrator, passages, errors [-]."""

    rig: str
    duration: float
    passages: int
    steps: int
    closed_form_seconds: float
    integration_seconds: float
    dop853_seconds: float
    closed_form_error: float
    integrator_difference: float


def _rigs():
    from foundation_calc.scenes import parse_scene, read_toml
    from foundation_calc.scenes.platform import DEFAULT_SCENE
    from foundation_calc.scenes.template import example_path
    from foundation_calc.solvers.crank.runup import structure as crank_structure
    from foundation_calc.solvers.platform.runup import structure as platform_structure

    platform = parse_scene(read_toml(DEFAULT_SCENE), expect="platform")
    design = platform.design()
    built, _ = platform_structure(design, replace(platform.model(), eta=0.05))
    data = read_toml(example_path("crank_foundation"))
    data["soil"].update(c_z=1.0e6, c_x=7.0e5, damping=[0.15, 0.15, 0.1])
    saw = parse_scene(data, expect="crank_foundation").design()
    soft = crank_structure(saw, [], [])
    return [
        ("platform, paper example, η = 0.05, 5 s", built, design.omega, 5.0),
        ("platform, paper example, η = 0.05, 10 s", built, design.omega, 10.0),
        ("frame saw on soft damped soil, 10 s", soft, saw.omega, 10.0),
    ]


def _dop853_peak(structure, omega, duration) -> float:
    """Largest point displacement of the same run-up by scipy's DOP853 (independent integrator)."""
    from scipy.integrate import solve_ivp

    from foundation_calc.solvers.numerics.runup import _moving, modes, run_end
    from foundation_calc.solvers.numerics.sweep_response import Ramp, point_displacements

    load = _moving(structure.load)
    M, C, K = structure.mass, structure.damping, structure.stiffness
    n = M.shape[0]
    Minv = np.linalg.inv(M)
    ramp = Ramp(0.0, omega, duration)

    def rhs(t, y):
        w, dw, phi = ramp.speed(np.array([t]))
        f = load.at(w, dw, phi)[:, 0]
        return np.concatenate([y[n:], Minv @ (f - C @ y[n:] - K @ y[:n])])

    q0 = np.linalg.solve(K, load.at(np.zeros(1), np.zeros(1), np.zeros(1))[:, 0])
    t_end = run_end(duration, modes(structure)[0])
    sol = solve_ivp(rhs, (0.0, t_end), np.concatenate([q0, np.zeros(n)]), method="DOP853", rtol=1e-9,
                    atol=1e-12, dense_output=True)
    t = np.linspace(0.0, t_end, 400_001)
    q = sol.sol(t)[:n]
    return float(point_displacements(structure.points, q).max())


def benchmark_runup(min_time: float, on_rig=lambda text: None) -> list[RunupBenchmark]:
    """Time and error of the closed form and the two integrators on each rig (module docstring)."""
    from foundation_calc.solvers.numerics.runup import closed_form, runup

    rows = []
    for name, structure, omega, duration in _rigs():
        on_rig(f"run-up: {name}")
        result = runup(structure, omega, duration, 1)
        forms = measure(lambda: closed_form(structure, omega, duration, 1), min_time=min_time)
        runs = measure(lambda: runup(structure, omega, duration, 1), min_time=min_time, min_calls=3)
        import time

        start = time.perf_counter()
        reference = _dop853_peak(structure, omega, duration)
        dop_seconds = time.perf_counter() - start
        main = max(result.passages, key=lambda p: p.closed_form)
        rows.append(
            RunupBenchmark(
                rig=name, duration=duration, passages=len(result.passages), steps=result.response.t.size - 1,
                closed_form_seconds=forms.seconds, integration_seconds=runs.seconds, dop853_seconds=dop_seconds,
                closed_form_error=abs(main.closed_form / main.integrated - 1.0),
                integrator_difference=abs(float(result.transient_points.max()) / reference - 1.0),
            )
        )
    return rows


__all__ = ["RunupBenchmark", "benchmark_runup"]
