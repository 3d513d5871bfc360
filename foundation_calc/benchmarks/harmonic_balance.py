"""Platform harmonic balance in ``fcalc bench``: run time and error against the truncation order K
for rigs of 1, 3 and 17 exciters, and the time of the whole check (6-DOF verification and its
28-variant sensitivity table) of each rig, as a ratio to the one-exciter rig measured in the same run.

The rigs are the paper's platform (the embedded default scene) alone, and with rubber isolators
(loss factor 0.01) and 2 or 16 further exciters: the 2 at speed ratios -1 and 0.673, the 16 at
ratios spread by the golden ratio, so that no two combinations of their speeds coincide and the
harmonic set is the largest it can be for that many rotors.
"""

from __future__ import annotations

import math
from dataclasses import dataclass

import numpy as np

from foundation_calc.benchmarks.measure import measure

#: Truncation orders K = |n|₁ timed besides the converged solve.
ORDERS = (1, 2, 3, 4, 5, 6)

#: Loss factor of the rubber isolators of the rigs with further exciters [-].
RUBBER_LOSS_FACTOR = 0.01

_GOLDEN = (math.sqrt(5.0) - 1.0) / 2.0


def _extras(count: int) -> list[dict]:
    if count == 2:
        ratios = [-1.0, 0.673]
    else:
        ratios = [(0.55 + 0.9 * ((j + 1) * _GOLDEN % 1.0)) * (-1) ** j for j in range(count)]
    return [
        {
            "rotor_mass": 5.0,
            "eccentricity": 0.1,
            "position": [3.0 * ((j * _GOLDEN) % 1.0), 2.0 * ((j * _GOLDEN**2) % 1.0), 0.1 + 0.05 * (j % 5)],
            "speed_ratio": r,
            "phase": 0.7 * j,
        }
        for j, r in enumerate(ratios)
    ]


def rig(extra_count: int):
    """The validated scene of the paper's platform with ``extra_count`` further exciters (0, 2, 16)."""
    from foundation_calc.scenes import parse_scene
    from foundation_calc.scenes.files import read_toml
    from foundation_calc.scenes.platform import DEFAULT_SCENE

    data = read_toml(DEFAULT_SCENE)
    if extra_count:
        data["name"] = f"paper platform, rubber isolators, {extra_count + 1} exciters"
        data["isolators"]["loss_factor"] = RUBBER_LOSS_FACTOR
        data["extra_exciters"] = _extras(extra_count)
    return parse_scene(data, source=f"rig with {extra_count + 1} exciters", expect="platform")


@dataclass(frozen=True)
class TruncationRow:
    """One solve of a rig: order cap K (None: converged, the reference), the order and number of
    harmonics it retained, median time [s], peak memory [bytes], and errors relative to the required
    amplitude u: ``error`` = largest difference of the peaks (x, y, z, rocking, corners) from the
    reference, ``estimate`` = the solver's own truncation estimate."""

    exciters: int
    cap: int | None
    order: int
    harmonics: int
    seconds: float
    peak_bytes: int
    error: float | None
    estimate: float


@dataclass(frozen=True)
class CheckTime:
    """The whole platform check of a rig [s] and its ratio to the one-exciter rig."""

    exciters: int
    seconds: float
    peak_bytes: int
    ratio_to_one_exciter: float


def _peaks(v) -> np.ndarray:
    return np.concatenate([v.amplitudes, [v.rocking], v.corner_peaks])


#: Further exciters of the rigs: 1, 3 and 17 exciters in all.
RIGS = (0, 2, 16)


def benchmark_truncation(
    min_time: float, on_rig=lambda text: None, rigs=RIGS
) -> tuple[list[TruncationRow], list[CheckTime]]:
    """Rows of time and error against K for each rig (``rigs``: numbers of further exciters), and
    each rig's whole-check time."""
    from foundation_calc.checks.platform import check_platform
    from foundation_calc.solvers.platform.harmonic_balance import steady_state
    from foundation_calc.solvers.platform.verification import build, measure as measured, product_corners

    rows, checks = [], []
    for extra in rigs:
        on_rig(f"harmonic balance: {extra + 1} exciter{'s' if extra else ''}")
        scene = rig(extra)
        design, model = scene.design(), scene.model()
        platform, rotors = build(design, model)
        corners = product_corners(design.A, design.B, model.product_height)

        def solved(cap):
            return measured(steady_state(platform, rotors, max_order=cap), platform.r_c, corners, design.u)

        reference = solved(None)
        for cap in (*ORDERS, None):
            if cap is not None and cap > reference.order:
                break
            timing = measure(lambda: solved(cap), min_time=min_time, min_calls=1, warm_up=False)
            v = reference if cap is None else solved(cap)
            error = None if cap is None else float(np.max(np.abs(_peaks(v) - _peaks(reference)))) / design.u
            rows.append(TruncationRow(extra + 1, cap, v.order, v.harmonics, timing.seconds, timing.peak_bytes,
                                      error, v.truncation_error / design.u))
        timing = measure(lambda: check_platform(design, model, scene.limits, True), min_time=min_time, min_calls=1, warm_up=False)
        base = checks[0].seconds if checks else timing.seconds
        checks.append(CheckTime(extra + 1, timing.seconds, timing.peak_bytes, timing.seconds / base))
    return rows, checks
