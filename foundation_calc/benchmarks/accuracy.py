"""Run time against error of every amplitude method of the crank foundation, scene by scene.

Each method maps a :class:`CrankDesign` to the periodic motion x(t), y(t), θ(t). Its error is the
largest relative error of the peaks of x, y and θ over one revolution against the converged
harmonic balance of the exact equations (:func:`exact_periodic_solution`, truncation below 1e-10
relative); its time is the median of repeated calls (:func:`measure`), peak memory from
tracemalloc. Solvers are imported inside the methods, so each pays its own imports once, in the
warm-up call.
"""

from __future__ import annotations

from collections.abc import Callable, Iterable
from dataclasses import dataclass

import numpy as np

from foundation_calc.benchmarks.measure import measure
from foundation_calc.errors import FcalcError
from foundation_calc.solvers.crank.mechanism import CrankDesign
from foundation_calc.solvers.crank.response import DOFS, PeriodicMotion, motion_peaks, relative_error

#: Numbers of harmonics at which the harmonic balance is shown truncated.
HARMONICS = (1, 2, 4, 8, 16)


def _first_approximation(design: CrankDesign) -> PeriodicMotion:
    from foundation_calc.solvers.crank.closed_form import first_approximation_motion

    return first_approximation_motion(design)[0]


def _averaged(design: CrankDesign) -> PeriodicMotion:
    from foundation_calc.solvers.crank.averaged import averaged_response

    return averaged_response(design).motion


def _harmonic_balance(K: int) -> Callable[[CrankDesign], PeriodicMotion]:
    def solve(design: CrankDesign) -> PeriodicMotion:
        from foundation_calc.solvers.crank.exact import fixed_harmonics_solution

        return fixed_harmonics_solution(design, K)

    return solve


def _shooting(design: CrankDesign) -> PeriodicMotion:
    from foundation_calc.solvers.crank.shooting import shooting_solution

    return shooting_solution(design).motion


def _converged(design: CrankDesign) -> PeriodicMotion:
    from foundation_calc.solvers.crank.exact import exact_periodic_solution

    return exact_periodic_solution(design).motion


@dataclass(frozen=True)
class Method:
    """One way of computing the steady state: a key for JSON, a label for people."""

    key: str
    label: str
    solve: Callable[[CrankDesign], PeriodicMotion]


REFERENCE = Method("harmonic_balance_converged", "harmonic balance, converged (reference)", _converged)

METHODS: tuple[Method, ...] = (
    Method("first_approximation", "first approximation (paper, corrected)", _first_approximation),
    Method("averaged_operator", "averaged operator (improved closed form)", _averaged),
    *(Method(f"harmonic_balance_K{K}", f"harmonic balance, K = {K}", _harmonic_balance(K)) for K in HARMONICS),
    Method("shooting_solve_ivp", "time integration: shooting, solve_ivp DOP853", _shooting),
    REFERENCE,
)


@dataclass(frozen=True)
class MethodResult:
    """Time, memory and error of one method on one scene.

    ``error`` is the largest of ``errors`` (x, y, θ peaks, relative) [-]; both None for the
    reference itself or when the method failed (``failure`` says why).
    """

    method: Method
    seconds: float | None
    peak_bytes: int | None
    calls: int
    error: float | None
    errors: dict[str, float] | None
    failure: str | None = None


@dataclass(frozen=True)
class SceneBenchmark:
    """Every method on one scene, and the reference peaks [m, m, rad] (None if it failed)."""

    scene: str
    name: str
    reference_peaks: dict[str, float] | None
    results: tuple[MethodResult, ...]
    reference_failure: str | None = None


def peak_errors(motion: PeriodicMotion, reference: np.ndarray) -> dict[str, float]:
    """Relative error of the x, y, θ peaks of ``motion`` against ``reference`` peaks."""
    errors = relative_error(motion_peaks(motion).displacement, reference)
    return dict(zip(DOFS, map(float, errors)))


def benchmark_scene(
    scene: str,
    name: str,
    design: CrankDesign,
    *,
    methods: Iterable[Method] = METHODS,
    min_time: float = 0.2,
    on_method: Callable[[str], None] = lambda label: None,
) -> SceneBenchmark:
    """Time every method on ``design`` and compare its peaks with the converged reference.

    ``on_method(label)`` is called before each method (for a progress display).
    """
    try:
        reference = motion_peaks(REFERENCE.solve(design)).displacement
        reference_failure = None
    except FcalcError as exc:
        reference, reference_failure = None, str(exc)
    results = []
    for method in methods:
        on_method(method.label)
        solved: list[PeriodicMotion] = []
        try:  # measure's warm-up call is the one whose answer is checked
            timing = measure(lambda: solved.append(method.solve(design)), min_time=min_time)
            motion = solved[0]
        except FcalcError as exc:
            results.append(MethodResult(method, None, None, 0, None, None, failure=str(exc)))
            continue
        errors = None if reference is None or method is REFERENCE else peak_errors(motion, reference)
        results.append(
            MethodResult(
                method,
                timing.seconds,
                timing.peak_bytes,
                timing.calls,
                None if errors is None else max(errors.values()),
                errors,
            )
        )
    return SceneBenchmark(
        scene=scene,
        name=name,
        reference_peaks=None if reference is None else dict(zip(DOFS, map(float, reference))),
        results=tuple(results),
        reference_failure=reference_failure,
    )


__all__ = ["HARMONICS", "METHODS", "REFERENCE", "Method", "MethodResult", "SceneBenchmark", "benchmark_scene", "peak_errors"]
