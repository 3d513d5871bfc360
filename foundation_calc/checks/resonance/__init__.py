"""The resonance check of a scene of any kind (``fcalc resonance``): one report,
:class:`~foundation_calc.checks.resonance.report.ResonanceReport`, judged by the one rule, whose
sections the kinds fill differently (:mod:`~foundation_calc.checks.resonance.report`). The one place the
resonance check tells the kinds apart: a block's six modes, or the plane model's scene read into
its design or block (:mod:`~foundation_calc.checks.resonance.frequencies`), with the soil's modulus
range and the soil model's validity.
"""

from __future__ import annotations

import math
from dataclasses import replace

from foundation_calc.checks.resonance.report import ResonanceReport, check_block_resonances, check_resonances


def scene_resonances(scene):
    """The resonance report of a crank or block scene, with its soil's modulus range and soil
    validity: a block's six modes (:func:`~foundation_calc.checks.amplitudes.machines.check_block`), the plane
    model's (:func:`check_scene_resonances`)."""
    if scene.kind == "block_foundation":
        from foundation_calc.checks.amplitudes.machines import check_block

        return check_block(scene).resonance
    return check_scene_resonances(scene)


def check_scene_resonances(scene) -> ResonanceReport:
    """The resonance report of a ``crank_foundation`` scene: its mechanism, its loads or both; with
    ``soil.modulus_range``, also over that range (the verdict is the worse of the two); the soil
    model's validity at its modes and judged orders (:func:`~foundation_calc.checks.soil_validity.crank_validity`)."""
    from foundation_calc.checks.soil_validity import crank_validity

    report = scene_resonances_as_given(scene)
    report = replace(report, soil_validity=crank_validity(scene, report))
    if scene.soil.modulus_range is None:
        return report
    from foundation_calc.checks.soil_range import resonances_over_range

    return replace(report, modulus_range=resonances_over_range(scene, scene_resonances_as_given))


def scene_resonances_as_given(scene) -> ResonanceReport:
    """The resonance report of a scene with its soil data as given (no ``modulus_range``); on a
    frequency-dependent soil every mode at its own frequency."""
    from foundation_calc.checks.resonance.frequencies import scene_block_frequencies, scene_design_frequencies

    loads = scene.harmonic_loads()
    if scene.mechanism is None:
        return check_block_resonances(scene.block(), scene.speed.omega_rad_s, loads, scene.limits.detuning,
                                      scene_block_frequencies(scene))
    several = {}
    report = check_resonances(scene.design(), scene.limits.detuning, loads, scene_design_frequencies(scene, several))
    return replace(report, several_roots=several_roots_warnings(report, several))


def several_roots_warnings(report: ResonanceReport, several: dict) -> tuple[str, ...]:
    """``WARN`` a line per mode of ``several`` (mode -> every root [rad/s] of ω = p(K(ω))): the
    roots in rad/s and Hz and the one the check took; and a line per judged condition n ω on that
    mode that the resonance rule would fail or warn against another root (its margin
    :func:`~foundation_calc.solvers.crank.resonance.condition_margin` with that root for the mode's
    frequency, against the condition's band): a speed near the other root is as resonant. The
    verdict stays the root taken's."""
    from foundation_calc.solvers.crank.resonance import condition_margin

    lines = []
    for mode, roots in several.items():
        taken = float(getattr(report.averaged, mode))
        listed = ", ".join(f"{w:.4g} rad/s ({w / (2.0 * math.pi):.4g} Hz)" for w in roots)
        lines.append(f"WARN mode {mode} has {len(roots)} natural frequencies on the support's springs at frequency"
                     f" (roots of ω = p(K(ω))): {listed}; the check takes {taken:.4g} rad/s, the root its search brackets")
        for row in (r for r in report.rows if r.judged and r.condition.mode == mode and r.required > 0.0):
            for root in (w for w in roots if abs(w - taken) > 1e-9 * taken):
                other = replace(report.averaged, **{mode: root})
                margin = float(condition_margin(report.omega, replace(report.zero_order, **{mode: root}), other, row.condition))
                if margin < row.required:
                    lines.append(f"WARN {row.label} at the other root {root:.4g} rad/s: margin {margin:.1%} (needs"
                                 f" {row.required:.0%}): a speed near it is as resonant")
    return tuple(lines)


__all__ = ["check_scene_resonances", "scene_resonances", "scene_resonances_as_given", "several_roots_warnings"]
