"""Designs per second: the vectorised resonance check and closed-form amplitudes against the
scalar path, in one run."""

from __future__ import annotations

from collections.abc import Callable
from dataclasses import dataclass, replace
from types import SimpleNamespace

import numpy as np

from foundation_calc.benchmarks.measure import measure
from foundation_calc.checks.resonance.report import check_resonances
from foundation_calc.solvers.crank.machine_conditions import paper_margin
from foundation_calc.solvers.crank.closed_form import design_first_approximation, with_damping
from foundation_calc.solvers.crank.mechanism import CrankDesign


#: Damping ratio [-] of every mode of the damped variant timed when the bench's scene has none.
BENCH_DAMPING = 0.05


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
    """``n`` variants of a design as one CrankDesign of arrays: soil coefficients ±50 % (c_phi
    with c's factor), speed ±30 %."""
    rng = np.random.default_rng(seed)
    factor = rng.uniform(0.5, 1.5, n)
    return replace(
        design,
        c=design.c * factor,
        c_phi=design.c_phi * factor,
        c1=design.c1 * rng.uniform(0.5, 1.5, n),
        omega=design.omega * rng.uniform(0.7, 1.3, n),
    )


def batch_throughput(
    design: CrankDesign,
    vectorised_fn: Callable[[CrankDesign], object],
    scalar_fn: Callable[[CrankDesign], object],
    designs: int = 1_000_000,
    scalar_designs: int = 2_000,
) -> Throughput:
    """Time ``vectorised_fn`` on ``designs`` perturbed designs in one call, ``scalar_fn`` on a
    sample of them one by one, measured in the same run."""
    batch = perturbed_designs(design, designs)
    sample = [
        replace(design, c=float(batch.c[i]), c_phi=float(batch.c_phi[i]), c1=float(batch.c1[i]), omega=float(batch.omega[i]))
        for i in range(scalar_designs)
    ]

    def scalar_loop() -> None:
        for one in sample:
            scalar_fn(one)

    scalar = measure(scalar_loop, min_time=0.5, max_calls=5)
    vectorised = measure(lambda: vectorised_fn(batch), min_time=0.5, max_calls=5)
    return Throughput(
        designs=designs,
        scalar_per_second=scalar_designs / scalar.seconds,
        vectorised_per_second=designs / vectorised.seconds,
        vectorised_peak_bytes=vectorised.peak_bytes,
    )


def resonance_throughput(design: CrankDesign, designs: int = 1_000_000, scalar_designs: int = 2_000) -> Throughput:
    """The resonance check: :func:`paper_margin` on the batch against :func:`check_resonances`."""
    return batch_throughput(design, paper_margin, lambda one: check_resonances(one, 0.2), designs, scalar_designs)


def undamped_variant(design: CrankDesign) -> CrankDesign:
    """``design`` without base dashpots (the paper's model)."""
    return replace(design, C_x=0.0, C_z=0.0, C_phi=0.0)


def damped_variant(design: CrankDesign) -> CrankDesign:
    """``design`` itself when it has base dashpots, else with :data:`BENCH_DAMPING` on every mode."""
    if max(float(np.max(design.C_x)), float(np.max(design.C_z)), float(np.max(design.C_phi))) > 0.0:
        return design
    return with_damping(design, BENCH_DAMPING, BENCH_DAMPING, BENCH_DAMPING)


def sweep_throughput(design: CrankDesign, designs: int = 1_000_000, scalar_designs: int = 2_000) -> Throughput:
    """``fcalc sweep``'s computation (first approximation, peaks, every margin, status, a
    displacement limit) over ``designs`` speeds ±30 % around the design's in one call, against
    one call per speed."""
    from foundation_calc.checks.sweep.crank import sweep

    speeds = perturbed_designs(design, designs).omega
    limits = SimpleNamespace(amplitude=1.0e-4)
    return batch_throughput(
        design,
        lambda batch: sweep(design, "omega", speeds, limits, 0.2),
        lambda one: sweep(design, "omega", np.array([one.omega]), limits, 0.2),
        designs,
        scalar_designs,
    )


def amplitude_throughput(design: CrankDesign, designs: int = 1_000_000, scalar_designs: int = 2_000) -> Throughput:
    """The closed-form amplitudes (six harmonic coefficients and the resonant flag of the corrected
    first approximation), the same function called on the batch and on each design of the sample."""
    return batch_throughput(design, design_first_approximation, design_first_approximation, designs, scalar_designs)
