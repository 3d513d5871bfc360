"""The engine of a ``crank_foundation`` scene's sample (:mod:`~foundation_calc.checks.soil_sample`):
the scene's mechanism on its soil × F at speed × the speed factor
(:func:`~foundation_calc.solvers.crank.closed_form.varied`; a frequency-dependent soil by the
scene's own method on G × F, so V_s by sqrt F and every a0 with it), computed by
:func:`~foundation_calc.solvers.crank.sample.sample_mechanism` and judged as the checks judge it.
The sample is of the crank mechanism's response; a scene's ``[[loads]]`` are not part of it.

The resonance check fails where the margin from the nearest paper condition is below the scene's
detuning (the paper's conditions fail inside the band), the amplitude check where a peak of C
exceeds ``[limits] amplitude`` or the sample is resonant; a sample whose rocking spring does not
exceed the weight's overturning moment tips over and fails both.
"""

from __future__ import annotations

from dataclasses import replace

import numpy as np

from foundation_calc.solvers.crank.closed_form import varied
from foundation_calc.solvers.crank.sample import sample_mechanism


def _designs_at(scene, base):
    """``at(soil_frequency, factor, speed)``: the scene's design ``base`` as arrays, speed ω ×
    ``speed``, soil stiffness × ``factor``, a frequency-dependent soil's springs and dashpots taken
    at ``soil_frequency`` [rad/s] (arrays alike), which the design carries (its ``soil_frequency``)."""
    if not scene.support().frequency_dependent:
        return lambda soil_frequency, factor, speed: varied(base, omega=base.omega * speed, soil_factor=factor)
    from foundation_calc.solvers.soil.dashpots import dashpots_from_ratios

    f = scene.foundation
    h, I_c, M_rod = f.cog_height, f.moment_of_inertia, base.M_tot  # the dashpots' body as scene.design takes it

    def at(soil_frequency, factor, speed):  # the scene's own method (and stratum) on the soil × factor
        k = scene.with_modulus_factor(factor).soil_springs(omega=soil_frequency)
        c = dashpots_from_ratios(k.xi_z, k.xi_x, k.xi_phi, k.K_z, k.K_x, k.K_phi, M_rod, I_c + M_rod * h * h)
        return replace(base, omega=base.omega * speed, c=k.K_z / f.base_area, c1=k.K_x / f.base_area,
                       c_phi=k.K_phi / f.base_second_moment, C_x=c.C_x, C_z=c.C_z, C_phi=c.C_phi,
                       soil_frequency=np.asarray(soil_frequency, dtype=float))

    return at


def engine(scene, factor, speed):
    """The sampled k0, p1, p2, margin and peaks of C and the outcomes of the samples ``factor``,
    ``speed`` (n,) (:data:`~foundation_calc.checks.soil_sample.ENGINES`)."""
    base = scene.design()
    s = sample_mechanism(base, _designs_at(scene, base), factor, speed, scene.support().frequency_dependent)
    fails_resonance = ~s.stable | (s.margin < scene.limits.detuning)
    fails_amplitude = ~s.stable | s.resonant
    if scene.limits.amplitude is not None:
        fails_amplitude |= (s.horizontal > scene.limits.amplitude) | (s.vertical > scene.limits.amplitude)
    values = {"k0": s.frequencies.k0, "p1": s.frequencies.p1, "p2": s.frequencies.p2, "resonance_margin": s.margin,
              "peak_horizontal_C": s.horizontal, "peak_vertical_C": s.vertical}
    return values, s.stable & ~s.resonant, ~s.stable, fails_resonance, fails_amplitude
