"""Cases against independent methods: each closed form against a solution it shares no formula with.

- natural frequencies of the crank foundation, Eq. (4.7), against ``scipy.linalg.eigh`` of the
  block's mass and stiffness matrices;
- the corrected first approximation, Eqs. (4.11)-(4.14), against the exact T-periodic solution
  of the full nonlinear equations (harmonic balance converged below 1e-10), with the accuracy
  the manual states for it as the tolerance;
- the platform design, Eqs. (3.8)-(3.21), against the 6-DOF linear model solved by harmonic
  balance: the design promises a pure translation on a circle of radius u.

The crank foundation is the frame saw of configs/frame_saw.toml (block 100 t on c_z = 7e7 N/m³, 250 rpm,
μ = 0.0148), given here in full so that the record does not move with the shipped examples.
"""

from __future__ import annotations

import math
from functools import cache

from foundation_calc.validation.published import PLATFORM_SCENE
from foundation_calc.validation.record import Case

FRAME_SAW_SCENE = {
    "kind": "crank_foundation",
    "foundation": {"mass": 100.0e3, "moment_of_inertia": 4.5e5, "cog_height": 1.5, "base_area": 40.0,
                   "base_second_moment": 213.3},
    "soil": {"c_z": 7.0e7, "c_x": 4.9e7},
    "mechanism": {"speed_rpm": 250.0, "crank_radius": 0.3, "rod_length": 1.2, "rod_mass": 1.5e3,
                  "rod_cog_to_crank_pin": 1.0, "rod_radius_of_gyration": 0.35, "crank_axis_to_cog": 2.0},
}

#: Relative bound of the solvers' round-off on these well-conditioned problems [-].
ROUNDOFF_BOUND = 1e-9


@cache
def _frame_saw():
    from foundation_calc.scenes import parse_scene

    return parse_scene(FRAME_SAW_SCENE, source="validation record")


def _closed_form_frequencies() -> tuple[float, ...]:
    from foundation_calc.solvers.crank.frequencies import zero_order_frequencies

    d = _frame_saw().design()
    f = zero_order_frequencies(d.M + d.rod.m, d.I_c, d.h, d.S, d.I1, d.c, d.c1, d.c_phi, d.g)
    return tuple(sorted(float(w) / (2.0 * math.pi) for w in (f.k0, f.p1, f.p2)))


def _eigen_frequencies() -> tuple[float, ...]:
    import numpy as np
    from scipy.linalg import eigh

    from foundation_calc.solvers.crank.loads import matrices

    M, K, _ = matrices(_frame_saw().block())
    return tuple(float(w) / (2.0 * math.pi) for w in np.sqrt(eigh(K, M, eigvals_only=True)))


@cache
def _exact():
    from foundation_calc.solvers.crank.exact import exact_periodic_solution

    return exact_periodic_solution(_frame_saw().design()).motion


@cache
def _first_approximation():
    from foundation_calc.solvers.crank.closed_form import first_approximation_motion

    return first_approximation_motion(_frame_saw().design())[0]


def _amplitude(motion, dof: str, n: int, unit: float) -> float:
    cos, sin = motion.coefficient(dof, n)
    return math.hypot(float(cos), float(sin)) / unit


@cache
def _platform_verification():
    from foundation_calc.scenes import parse_scene
    from foundation_calc.solvers.platform.verification import verify

    scene = parse_scene(PLATFORM_SCENE, source="validation record")
    return verify(scene.design(), scene.model())


def _harmonic(dof: str, n: int, symbol: str, claim: str, tolerance: float) -> Case:
    unit, label = (1e-6, "µm") if dof in "xy" else (1e-6, "µrad")
    frequency = "ω" if n == 1 else f"{n}ω"
    return Case(
        key=f"first-approximation-{dof}{n}",
        quantity=f"{symbol} = amplitude of {'θ' if dof == 'theta' else dof} at {frequency} [{label}]",
        example="Frame saw (μ = 0.0148): first approximation against the exact periodic solution",
        source="FC",
        where="(4.14)",
        reference=lambda: _amplitude(_exact(), dof, n, unit),
        printed=None,
        fcalc=lambda: _amplitude(_first_approximation(), dof, n, unit),
        method=f"solvers.crank.first_approximation ({symbol}, corrected (4.14))",
        tolerance=tolerance,
        relative=True,
        basis=f"the stated accuracy of the first approximation: {claim}",
    )


CASES: tuple[Case, ...] = (
    Case(
        key="crank-natural-frequencies",
        quantity="p1, k0, p2 [Hz]",
        example="Frame saw block: natural frequencies against an eigen-solve of K, M",
        source="FC",
        where="(4.7)",
        reference=_eigen_frequencies,
        printed=None,
        fcalc=_closed_form_frequencies,
        method="solvers.crank.frequencies.zero_order_frequencies (KM (4.5)-(4.7))",
        tolerance=ROUNDOFF_BOUND,
        relative=True,
        basis="round-off: both are exact in double precision",
    ),
    _harmonic("y", 1, "y1", "1e-6 (rocking coupling only)", 1e-6),
    _harmonic("y", 2, "y2", "about 1.5 % (λ² truncation); 2 % allowed", 0.02),
    _harmonic("x", 1, "x1", "O(μ), about 0.2 % at μ = 0.015", 2e-3),
    _harmonic("theta", 1, "θ1", "O(μ), about 0.2 % at μ = 0.015", 2e-3),
    Case(
        key="platform-6dof-circle",
        quantity="amplitude of O1 along x, y [mm]",
        example="Vibrating platform example on the 6-DOF model (harmonic balance)",
        source="BC",
        where="circle of radius u",
        reference=(1.0, 1.0),
        printed="1 / 1",
        fcalc=lambda: tuple(a * 1e3 for a in _platform_verification().amplitudes[:2]),
        method="solvers.platform.verification.verify (6-DOF harmonic balance)",
        tolerance=ROUNDOFF_BOUND,
        relative=True,
        basis="round-off: the design is exact for the linear model",
    ),
    Case(
        key="platform-6dof-rocking",
        quantity="rocking of the product's corners [% of u]",
        example="Vibrating platform example on the 6-DOF model (harmonic balance)",
        source="BC",
        where="pure translation",
        reference=0.0,
        printed="0",
        fcalc=lambda: _platform_verification().rocking_percent,
        method="solvers.platform.verification.verify (6-DOF harmonic balance)",
        tolerance=100.0 * ROUNDOFF_BOUND,
        basis="round-off: 1e-9 of u",
        scale=100.0,
    ),
)

__all__ = ["CASES", "FRAME_SAW_SCENE"]
