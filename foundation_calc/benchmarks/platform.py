"""Platform scenes in ``fcalc bench``: time of the design formulas and of the 6-DOF verification,
and what the verification says of the design's purpose (pure translation): the rotation residual."""

from __future__ import annotations

from dataclasses import dataclass

from foundation_calc.benchmarks.measure import measure
from foundation_calc.errors import FcalcError


@dataclass(frozen=True)
class PlatformBenchmark:
    """One platform scene: median times [s], peak rotation of the platform [rad], rocking [% of u].

    The numbers are None when the design or its verification failed (``failure`` says why).
    """

    scene: str
    name: str
    design_seconds: float | None
    verification_seconds: float | None
    rotation_residual: float | None
    rocking_percent: float | None
    failure: str | None = None


def benchmark_platform(scene: str, loaded, *, min_time: float = 0.2) -> PlatformBenchmark:
    """Time ``loaded.design()`` and the 6-DOF verification of a validated platform scene."""
    from foundation_calc.solvers.platform.verification import verify

    name = getattr(loaded, "name", "")
    try:
        design, model = loaded.design(), loaded.model()
        check = verify(design, model)
        design_time = measure(loaded.design, min_time=min_time)
        verify_time = measure(lambda: verify(design, model), min_time=min_time)
    except FcalcError as exc:
        return PlatformBenchmark(scene, name, None, None, None, None, failure=str(exc))
    return PlatformBenchmark(
        scene,
        name,
        design_time.seconds,
        verify_time.seconds,
        float(max(check.rotations)),
        float(check.rocking_percent),
    )
