"""``fcalc soil``: the springs, damping and frequencies of every soil method the scene's data allow.

Each method ends in K_z, K_x, K_φ and damping ratios (:mod:`foundation_calc.solvers.soil`); here
they become the equivalent coefficients c_z = K_z/S, c_x = K_x/S, c_φ = K_φ/I1, the base
dashpots, the uncoupled frequencies of the block and the coupled k0, p1, p2 of the paper's
zero-order operator (4.5)-(4.7), and methods that disagree by more than
:data:`DISAGREEMENT_FACTOR` are named.

A frequency-dependent method (``"gazetas"``, ``"pais_kausel"``) gives each mode its springs at its own frequency:
the frequencies solve ω = p(K(ω)) (:func:`~foundation_calc.solvers.soil.impedance.consistent_frequency`)
and are reported beside their static values, each damping ratio is taken at its own mode's
frequency, and :class:`DynamicRow` tables K and C at the operating speed and at each mode.
Barkan's coefficients, Lysmer's analogs and SP 26 are frequency-independent.
"""

from __future__ import annotations

import math
from dataclasses import dataclass, replace

from foundation_calc.scenes.soil import FREQUENCY_DEPENDENT_METHODS, HALF_SPACE_METHODS
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
    ("lysmer", "xi_phi"): "lysmer's rocking damping is one frequency-independent fit (Hall's analog), gazetas'"
    " is taken at the rocking mode's own frequency",
}


@dataclass(frozen=True)
class DynamicRow:
    """Springs and dashpots of a frequency-dependent method at one frequency (SI).

    ``at`` names the frequency: ``"speed"`` (the operating speed) or a mode (``"k0"``, ``"p1"``,
    ``"p2"``); ``C_*`` include the material damping, as dashpots 2 ξ sqrt(K m) at ``omega``.
    """

    at: str
    omega: float
    a0: float
    K_z: float
    K_x: float
    K_phi: float
    C_z: float
    C_x: float
    C_phi: float


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
    #: frequency-dependent methods: frequencies on the static springs (rad/s), K and C tabled
    static_frequencies: dict[str, float] | None = None
    dynamic: tuple[DynamicRow, ...] = ()


@dataclass(frozen=True)
class SoilComparison:
    """Every method the scene's data allow, the one the scene uses, and what to look at."""

    used: str
    results: tuple[MethodResult, ...]
    #: the scene's plausibility warnings (a unit slip, a static modulus for a dynamic one)
    input_warnings: tuple[str, ...]
    #: methods that disagree by more than DISAGREEMENT_FACTOR, methods that tip the block over
    findings: tuple[str, ...]


def _frequencies(scene, springs, M_tot: float, I_0: float):
    """(uncoupled, coupled k0 p1 p2, stability margin) of the block on ``springs``; coupled None
    when it tips over."""
    f, h = scene.foundation, scene.foundation.cog_height
    K_z, K_x, K_phi = float(springs.K_z), float(springs.K_x), float(springs.K_phi)
    u = uncoupled_frequencies(K_z, K_x, K_phi, M_tot, I_0, h, GRAVITY)
    margin = rocking_stability_margin(K_phi / f.base_second_moment, f.base_second_moment, M_tot * GRAVITY, h)
    coupled = None
    if margin > 0.0:
        coupled = zero_order_frequencies(M_tot, f.moment_of_inertia, h, f.base_area, f.base_second_moment,
                                         K_z / f.base_area, K_x / f.base_area, K_phi / f.base_second_moment, GRAVITY)
    return u, coupled, float(margin)


def _mode_frequencies(scene, method: str, M_tot: float, I_0: float) -> dict[str, float]:
    """Every mode's frequency [rad/s] on the springs at that frequency (ω = p(K(ω)); nan when
    the block tips over)."""
    from foundation_calc.solvers.soil.impedance import consistent_frequency

    def at(w, mode):
        u, coupled, _ = _frequencies(scene, scene.soil_springs(method, w), M_tot, I_0)
        if mode in ("k0", "p1", "p2"):
            return math.nan if coupled is None else float(getattr(coupled, mode))
        return float(getattr(u, mode))

    static = _static_frequencies(scene, scene.soil_springs(method), M_tot, I_0)
    return {
        mode: w if math.isnan(w) else float(consistent_frequency(lambda v, mode=mode: at(v, mode), w))
        for mode, w in static.items()
    }


def _static_frequencies(scene, springs, M_tot: float, I_0: float) -> dict[str, float]:
    u, coupled, _ = _frequencies(scene, springs, M_tot, I_0)
    tipped = coupled is None
    return {
        "omega_z": float(u.omega_z), "omega_x": float(u.omega_x),
        "omega_phi": math.nan if tipped else float(u.omega_phi),
        "k0": float(u.omega_z),
        "p1": math.nan if tipped else float(coupled.p1), "p2": math.nan if tipped else float(coupled.p2),
    }


def _dynamic_row(scene, method: str, at: str, omega: float, M_tot: float, I_0: float) -> DynamicRow:
    s = scene.soil_springs(method, omega)
    d = scene.base_dashpots(s, M_tot)
    a0 = omega * min(scene.foundation.dimensions) / 2.0 / scene.soil.V_s
    return DynamicRow(at, omega, a0, float(s.K_z), float(s.K_x), float(s.K_phi), d["C_z"], d["C_x"], d["C_phi"])


def _method_result(scene, method: str) -> MethodResult:
    f = scene.foundation
    M_tot, h = scene.total_mass, f.cog_height
    I_0 = f.moment_of_inertia + M_tot * h**2
    s = scene.soil_springs(method)
    dependent = method in FREQUENCY_DEPENDENT_METHODS or scene.soil.stratum_depth is not None  # (Soil.frequency_dependent)
    static = _static_frequencies(scene, s, M_tot, I_0)
    freqs = _mode_frequencies(scene, method, M_tot, I_0) if dependent else static
    ratios = {"xi_z": float(s.xi_z), "xi_x": float(s.xi_x), "xi_phi": float(s.xi_phi)}
    if dependent:  # each mode's damping at its own frequency
        ratios = {
            key: float(getattr(scene.soil_springs(method, 0.0 if math.isnan(freqs[mode]) else freqs[mode]), key))
            for key, mode in (("xi_z", "omega_z"), ("xi_x", "omega_x"), ("xi_phi", "omega_phi"))
        }
    K_z, K_x, K_phi = float(s.K_z), float(s.K_x), float(s.K_phi)
    d = scene.base_dashpots(replace(s, **ratios), M_tot)  # no numpy import for an undamped scene
    _, _, margin = _frequencies(scene, s, M_tot, I_0)
    dynamic = ()
    if dependent:
        dynamic = tuple(
            _dynamic_row(scene, method, at, w, M_tot, I_0)
            for at, w in (("speed", scene.speed.omega_rad_s), *((m, freqs[m]) for m in ("k0", "p1", "p2")))
            if not math.isnan(w)
        )
    return MethodResult(
        method=method, K_z=K_z, K_x=K_x, K_phi=K_phi,
        c_z=K_z / f.base_area, c_x=K_x / f.base_area, c_phi=K_phi / f.base_second_moment,
        **ratios, C_z=d["C_z"], C_x=d["C_x"], C_phi=d["C_phi"],
        omega_z=freqs["omega_z"], omega_x=freqs["omega_x"], omega_phi=freqs["omega_phi"],
        k0=freqs["k0"], p1=freqs["p1"], p2=freqs["p2"], rocking_stability_margin=margin,
        static_frequencies=static if dependent else None, dynamic=dynamic,
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


def _frequency_range(scene, results) -> list[str]:
    """Where a0 leaves the range a half-space method was fitted for, at the operating speed or a
    mode (:func:`~foundation_calc.checks.soil_validity.plane_validity`, each method's a0 and range)."""
    if scene.soil.method_used not in HALF_SPACE_METHODS:
        return []
    from foundation_calc.checks.soil_validity import plane_validity
    from foundation_calc.solvers.crank.loads import RigidBlock

    f = scene.foundation
    M_tot, I_c, h = scene.total_mass, f.moment_of_inertia, f.cog_height

    def block_at(method):
        def at(omega):
            s = scene.soil_springs(method, omega)
            return RigidBlock(M_tot, I_c, h, float(s.K_x), float(s.K_z), float(s.K_phi), 0.0, 0.0, 0.0, GRAVITY)
        return at

    L, B = f.dimensions
    found = []
    for r in results:
        validity = plane_validity(r.method, scene.soil.V_s, L, B, {"k0": r.k0, "p1": r.p1, "p2": r.p2},
                                  block_at(r.method), {"the operating speed": scene.speed.omega_rad_s})
        if validity.beyond:
            found.append(validity.text)
    return found


def compares_methods(scene) -> bool:
    """Whether a crank scene stands on the footing whose soil methods are compared: its support gives
    a soil method's chain in the plane (``plane_springs``); a pile group replaces the footing and
    ``fcalc soil`` shows its own springs (:mod:`foundation_calc.checks.soil_support`)."""
    return hasattr(scene.support(), "plane_springs")


def compare_soil_methods(scene) -> SoilComparison:
    """Apply every method the scene's ``[soil]`` data allow (:meth:`Soil.methods_allowed`) to the
    footing (:func:`compares_methods`; on another support :meth:`soil_springs` is a PhysicsError)."""
    results = tuple(_method_result(scene, m) for m in scene.soil.methods_allowed())
    findings = _disagreements(results)
    findings += _frequency_range(scene, results)
    if scene.foundation.embedment and scene.soil.method_used not in FREQUENCY_DEPENDENT_METHODS:
        findings.append(
            f"foundation.embedment = {scene.foundation.embedment:g} m is used by methods 'gazetas' and"
            " 'pais_kausel' only;"
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
