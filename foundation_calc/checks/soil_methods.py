"""``fcalc soil``: the springs, damping and frequencies of every soil method the scene's data allow.

Each method ends in K_z, K_x, K_φ and damping ratios (:mod:`foundation_calc.solvers.soil`); here
they become the equivalent coefficients c_z = K_z/S, c_x = K_x/S, c_φ = K_φ/I1, the base
dashpots, the uncoupled frequencies of the block and the coupled k0, p1, p2 of the paper's
zero-order operator (4.5)-(4.7), and methods that disagree by more than
:data:`DISAGREEMENT_FACTOR` are named.
"""

from __future__ import annotations

import math
from dataclasses import dataclass

from foundation_calc.solvers.constants import GRAVITY
from foundation_calc.solvers.crank.frequencies import rocking_stability_margin, zero_order_frequencies
from foundation_calc.solvers.soil.springs import uncoupled_frequencies

#: Two methods whose springs differ by more than this factor are flagged [-]: the spread of
#: the published methods for one site is about ±30 %, a factor of 2 means a wrong input or a
#: method outside its range.
DISAGREEMENT_FACTOR = 2.0

#: The springs and damping ratios compared between methods, with their names in messages.
SPRINGS = {"K_z": "vertical", "K_x": "horizontal", "K_phi": "rocking"}
RATIOS = {"xi_z": "vertical", "xi_x": "horizontal", "xi_phi": "rocking"}

#: Why a method's damping ratio may stand apart, said beside its disagreement.
RATIO_CAVEATS = {
    ("gazetas", "xi_phi"): "gazetas' rocking keeps the material damping alone (its radiation is left out,"
    " which over-states the rocking response)",
}


@dataclass(frozen=True)
class MethodResult:
    """One soil method applied to the scene (SI units; frequencies in rad/s).

    ``p1``, ``p2``, ``omega_phi`` are nan when the method's rocking spring does not exceed the
    weight's overturning moment (``rocking_stability_margin`` <= 0).
    """

    method: str
    K_z: float
    K_x: float
    K_phi: float
    c_z: float
    c_x: float
    c_phi: float
    xi_z: float
    xi_x: float
    xi_phi: float
    C_z: float
    C_x: float
    C_phi: float
    omega_z: float
    omega_x: float
    omega_phi: float
    k0: float
    p1: float
    p2: float
    rocking_stability_margin: float


@dataclass(frozen=True)
class SoilComparison:
    """Every method the scene's data allow, the one the scene uses, and what to look at."""

    used: str
    results: tuple[MethodResult, ...]
    #: the scene's plausibility warnings (a unit slip, a static modulus for a dynamic one)
    input_warnings: tuple[str, ...]
    #: methods that disagree by more than DISAGREEMENT_FACTOR, methods that tip the block over
    findings: tuple[str, ...]


def _method_result(scene, method: str) -> MethodResult:
    f = scene.foundation
    s = scene.soil_springs(method)
    M_tot, g, h = scene.total_mass, GRAVITY, f.cog_height
    I_0 = f.moment_of_inertia + M_tot * h**2
    K_z, K_x, K_phi = float(s.K_z), float(s.K_x), float(s.K_phi)
    c, c1, c_phi = K_z / f.base_area, K_x / f.base_area, K_phi / f.base_second_moment
    d = scene.base_dashpots(s, M_tot)  # no numpy import for an undamped scene
    u = uncoupled_frequencies(K_z, K_x, K_phi, M_tot, I_0, h, g)
    margin = rocking_stability_margin(c_phi, f.base_second_moment, M_tot * g, h)
    omega_phi = p1 = p2 = math.nan
    if margin > 0.0:
        coupled = zero_order_frequencies(M_tot, f.moment_of_inertia, h, f.base_area, f.base_second_moment,
                                         c, c1, c_phi, g)
        p1, p2, omega_phi = float(coupled.p1), float(coupled.p2), float(u.omega_phi)
    return MethodResult(
        method=method, K_z=K_z, K_x=K_x, K_phi=K_phi, c_z=c, c_x=c1, c_phi=c_phi,
        xi_z=float(s.xi_z), xi_x=float(s.xi_x), xi_phi=float(s.xi_phi),
        C_z=d["C_z"], C_x=d["C_x"], C_phi=d["C_phi"],
        omega_z=float(u.omega_z), omega_x=float(u.omega_x), omega_phi=omega_phi,
        k0=math.sqrt(K_z / M_tot), p1=p1, p2=p2, rocking_stability_margin=float(margin),
    )


def _disagreements(results: tuple[MethodResult, ...]) -> list[str]:
    found = []
    for i, a in enumerate(results):
        for b in results[i + 1:]:
            for key, name in (*((k, f"{n} springs") for k, n in SPRINGS.items()),
                              *((k, f"{n} damping ratios") for k, n in RATIOS.items())):
                low, high = sorted((getattr(a, key), getattr(b, key)))
                if high > DISAGREEMENT_FACTOR * low:
                    caveats = [RATIO_CAVEATS[m, key] for m in (a.method, b.method) if (m, key) in RATIO_CAVEATS]
                    apart = f"a factor of {high / low:.3g}" if low > 0.0 else f"{high:.3g} against 0"
                    found.append(
                        f"the {name} {key} of {a.method!r} and {b.method!r} differ by {apart}"
                        f" (more than a factor of {DISAGREEMENT_FACTOR:g}): "
                        + (f"{caveats[0]}" if caveats else "check the soil data and each method's range before choosing")
                    )
    return found


#: Dimensionless frequency a0 = ω B'/V_s up to which the half-space methods' frequency-independent
#: damping holds: Gazetas' dashpot coefficients stay within about 10 % of their low-frequency
#: limit below it, and Richart, Hall & Woods fit the analogs' damping over a0 < 1.5 [-].
A0_RANGE = 1.0


def _frequency_range(scene) -> list[str]:
    """The operating speed's a0 when it is beyond :data:`A0_RANGE` (half-space methods only)."""
    if scene.soil.method_used not in ("lysmer", "gazetas"):
        return []
    half_width = min(scene.foundation.dimensions) / 2.0
    a0 = scene.speed.omega_rad_s * half_width / scene.soil.V_s
    if a0 <= A0_RANGE:
        return []
    return [
        f"a0 = ω B'/V_s = {a0:.3g} at the operating speed is beyond {A0_RANGE:g}: the frequency-independent"
        " damping of the half-space methods over-states the radiation there; check with frequency-dependent"
        " impedances"
    ]


def compare_soil_methods(scene) -> SoilComparison:
    """Apply every method the scene's ``[soil]`` data allow (:meth:`Soil.methods_allowed`)."""
    results = tuple(_method_result(scene, m) for m in scene.soil.methods_allowed())
    findings = _disagreements(results)
    findings += _frequency_range(scene)
    if scene.foundation.embedment and scene.soil.method_used != "gazetas":
        findings.append(
            f"foundation.embedment = {scene.foundation.embedment:g} m is used by method 'gazetas' only;"
            f" method {scene.soil.method_used!r} takes the base as a surface footing"
        )
    findings += [
        f"method {r.method!r}: the rocking spring K_phi = {r.K_phi:.4g} N m/rad does not exceed the weight's"
        f" overturning moment M_tot g h (margin {r.rocking_stability_margin:.3g}): the block tips over"
        for r in results
        if r.rocking_stability_margin <= 0.0
    ]
    return SoilComparison(
        used=scene.soil.method_used,
        results=results,
        input_warnings=tuple(scene.plausibility_warnings()),
        findings=tuple(findings),
    )
