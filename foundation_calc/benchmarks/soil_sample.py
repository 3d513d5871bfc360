"""Seconds to sample the uncertain soil: ``fcalc soil --sample`` of 10⁵ designs by the closed forms."""

from __future__ import annotations

from dataclasses import dataclass

from foundation_calc.benchmarks.measure import measure

#: Samples timed (the figure the soil sampling must reach in under 2 s on 2 cores).
SAMPLES = 100_000


@dataclass(frozen=True)
class SampleTiming:
    """Median wall time of one sample of ``samples`` designs [s] and its peak traced memory [bytes]."""

    samples: int
    seconds: float
    peak_bytes: int

    @property
    def per_second(self) -> float:
        return self.samples / self.seconds


def soil_sample_timing(scene, min_time: float, samples: int = SAMPLES) -> SampleTiming:
    """Time :func:`~foundation_calc.checks.soil_sample.sample_scene` of ``scene`` (COV 0.3)."""
    from foundation_calc.checks.soil_sample import sample_scene

    m = measure(lambda: sample_scene(scene, samples, 0.3), min_time=min_time, min_calls=3)
    return SampleTiming(samples, m.seconds, m.peak_bytes)
