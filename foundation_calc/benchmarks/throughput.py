"""Designs per second: the vectorised resonance check against the scalar path, in one run."""

from __future__ import annotations

from dataclasses import dataclass, replace

import numpy as np

from foundation_calc.benchmarks.measure import measure
from foundation_calc.checks.crank_resonance import check_resonances, paper_margin
from foundation_calc.solvers.crank_mechanism import CrankDesign


@dataclass(frozen=True)
class Throughput:
    """Designs per second and peak memory of the scalar and the vectorised paths."""

    designs: int
    scalar_per_second: float
    vectorised_per_second: float
    vectorised_peak_bytes: int

    @property
    def speedup(self) -> float:
        return self.vectorised_per_second / self.scalar_per_second


def perturbed_designs(design: CrankDesign, n: int, seed: int = 0) -> CrankDesign:
    """``n`` variants of a design as one CrankDesign of arrays: soil coefficients ±50 %, speed ±30 %."""
    rng = np.random.default_rng(seed)
    return replace(
        design,
        c=design.c * rng.uniform(0.5, 1.5, n),
        c1=design.c1 * rng.uniform(0.5, 1.5, n),
        omega=design.omega * rng.uniform(0.7, 1.3, n),
    )


def resonance_throughput(design: CrankDesign, designs: int = 1_000_000, scalar_designs: int = 2_000) -> Throughput:
    """Time the vectorised check on ``designs`` designs and the scalar check on a sample of them."""
    batch = perturbed_designs(design, designs)
    sample = [
        replace(design, c=float(batch.c[i]), c1=float(batch.c1[i]), omega=float(batch.omega[i]))
        for i in range(scalar_designs)
    ]

    def scalar_loop() -> None:
        for one in sample:
            check_resonances(one, 0.2)

    scalar = measure(scalar_loop, min_time=0.5, max_calls=5)
    vectorised = measure(lambda: paper_margin(batch), min_time=0.5, max_calls=5)
    return Throughput(
        designs=designs,
        scalar_per_second=scalar_designs / scalar.seconds,
        vectorised_per_second=designs / vectorised.seconds,
        vectorised_peak_bytes=vectorised.peak_bytes,
    )
