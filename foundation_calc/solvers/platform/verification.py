"""Check a platform design on the full 6-DOF model: amplitudes, rocking, tolerance sensitivity.

The design formulas of :mod:`~foundation_calc.solvers.platform.design` make the platform move
purely translationally; this module builds the 6-DOF model of
:mod:`~foundation_calc.solvers.platform.dynamics` for a design and measures what the paper
exists for: how uniformly the corners of the product vibrate.

Rocking = max over the corners p of the product box of the peak of |Φ(t) × (p - r_c)|, i.e. the
motion of a corner relative to the centre of mass, in % of u. Spread = (largest - smallest) peak
dynamic displacement of the corners, in % of u.
"""

from __future__ import annotations

from dataclasses import dataclass, replace

import numpy as np

from foundation_calc.solvers.platform.design import PlatformDesign
from foundation_calc.solvers.platform.dynamics import (
    RigidPlatform,
    Rotor,
    SteadyState,
    inertia_about_corner,
    point_map,
    skew,
    steady_state,
)

#: Tolerances of the sensitivity table: relative for stiffnesses and ζ, absolute [m] for a, b, c.
STIFFNESS_TOLERANCE = 0.01
POSITION_TOLERANCE = 0.01
ZETA_TOLERANCE = 0.01


@dataclass(frozen=True)
class ExtraRotor:
    """A further rotor given relative to the operating speed (scene ``[[extra_exciters]]``)."""

    m: float
    l: float
    rho: tuple
    delta1: float
    delta2: float
    speed_ratio: float
    phi0: float


@dataclass(frozen=True)
class PlatformModel:
    """Everything the 6-DOF model needs besides the design's stiffnesses."""

    J_c: tuple
    eta: float
    product_height: float
    extra: tuple = ()


def build(design: PlatformDesign, model: PlatformModel, stiffness=None, rho=None, zeta=None):
    """The rigid platform and its rotors for ``design`` (optionally with changed values)."""
    d = design
    r_c = (d.xi, d.eta, d.zeta if zeta is None else zeta)
    platform = RigidPlatform(
        M=d.M,
        r_c=r_c,
        J_O1=inertia_about_corner(d.M, r_c, model.J_c),
        A=d.A,
        B=d.B,
        stiffness=d.stiffness if stiffness is None else stiffness,
        eta=model.eta,
        g=d.g,
    )
    main = Rotor(d.m, d.l, (d.a, d.b, d.c) if rho is None else rho, 0.0, 0.0, d.omega, 0.0)
    extra = [Rotor(e.m, e.l, e.rho, e.delta1, e.delta2, e.speed_ratio * d.omega, e.phi0) for e in model.extra]
    return platform, [main, *extra]


def product_corners(A, B, H) -> np.ndarray:
    """The eight corners of the product box [0, A] × [0, B] × [0, H] [m]."""
    return np.array([[x, y, z] for x in (0.0, A) for y in (0.0, B) for z in (0.0, H)])


@dataclass(frozen=True)
class Verification:
    """Steady-state motion of a design on the 6-DOF model (SI units).

    Attributes
    ----------
    amplitudes : peak |x|, |y|, |z| of O1 over time [m]
    rotations : peak |α|, |β|, |γ| over time [rad]
    static : static equilibrium (x, y, z [m], α, β, γ [rad])
    mean : static equilibrium plus the mean offset of the periodic terms
    corner_peaks : peak dynamic displacement of each product corner [m]
    rocking : largest corner motion relative to the centre of mass [m]
    static_offset : largest static displacement of a corner relative to the centre of mass,
        from the static tilt [m]
    u : required amplitude [m]
    orders : Neumann orders used
    """

    amplitudes: tuple
    rotations: tuple
    static: np.ndarray
    mean: np.ndarray
    corners: np.ndarray
    corner_peaks: np.ndarray
    rocking: float
    static_offset: float
    u: float
    orders: int

    @property
    def rocking_percent(self) -> float:
        """Rocking in % of u."""
        return 100.0 * self.rocking / self.u

    @property
    def spread_percent(self) -> float:
        """(max - min) peak corner amplitude in % of u."""
        return 100.0 * float(self.corner_peaks.max() - self.corner_peaks.min()) / self.u

    @property
    def static_offset_percent(self) -> float:
        """Static corner offset from the tilt in % of u."""
        return 100.0 * self.static_offset / self.u

    @property
    def static_tilt(self) -> float:
        """|(α, β, γ)| of the static equilibrium [rad]."""
        return float(np.linalg.norm(self.static[3:]))


def _unit_row(i) -> np.ndarray:
    T = np.zeros((1, 6))
    T[0, i] = 1.0
    return T


def measure(state: SteadyState, r_c, corners, u) -> Verification:
    """Amplitudes, rotations, rocking and corner peaks of a steady state."""
    rc = np.asarray(r_c, dtype=float)
    relative = [np.hstack([np.zeros((3, 3)), -skew(p - rc)]) for p in corners]
    return Verification(
        amplitudes=tuple(state.peak(_unit_row(i)) for i in range(3)),
        rotations=tuple(state.peak(_unit_row(i)) for i in range(3, 6)),
        static=state.static,
        mean=state.mean,
        corners=corners,
        corner_peaks=np.array([state.peak(point_map(p)) for p in corners]),
        rocking=max(state.peak(T) for T in relative),
        static_offset=max(float(np.linalg.norm(T @ state.static)) for T in relative),
        u=float(u),
        orders=state.orders,
    )


def verify(design: PlatformDesign, model: PlatformModel, **changes) -> Verification:
    """Solve the 6-DOF model of ``design`` (``changes`` as for :func:`build`) and measure it.

    >>> import math
    >>> from foundation_calc.solvers.platform.design import design_from_position
    >>> d = design_from_position(2e4, 25.0, 0.2, 1e-3, 50 * math.pi, 1.5, 1.0, 0.65, 3.0, 2.0,
    ...                          -1.0, 9.81, 0.0, 0.0, 1e8, (0.5,) * 4)
    >>> v = verify(d, PlatformModel((9.5e3, 1.8e4, 2.2e4), 0.0, 1.3))
    >>> round(v.amplitudes[0] / 1e-3, 9), v.rocking_percent < 1e-10
    (1.0, True)
    """
    platform, rotors = build(design, model, **changes)
    corners = product_corners(design.A, design.B, model.product_height)
    return measure(steady_state(platform, rotors), platform.r_c, corners, design.u)


@dataclass(frozen=True)
class SensitivityRow:
    """Rocking and static corner offset caused by one tolerance, both signs (in % of u)."""

    parameter: str
    tolerance: str
    rocking_plus: float
    rocking_minus: float
    static_plus: float
    static_minus: float

    @property
    def worst(self) -> float:
        """The largest of the four numbers [% of u]."""
        return max(self.rocking_plus, self.rocking_minus, self.static_plus, self.static_minus)


def _row(parameter: str, tolerance: str, plus: Verification, minus: Verification) -> SensitivityRow:
    return SensitivityRow(
        parameter,
        tolerance,
        plus.rocking_percent,
        minus.rocking_percent,
        plus.static_offset_percent,
        minus.static_offset_percent,
    )


def _scaled(stiffness, cells, factor):
    s = np.array(stiffness, dtype=float)
    for i, j in cells:
        s[i, j] *= factor
    return s


#: (name, cells of the stiffness table scaled together) for the stiffness tolerances.
STIFFNESS_GROUPS = (
    ("c1 (all c_i1)", [(0, 0), (1, 0), (2, 0), (3, 0)]),
    ("c2 (all c_i2)", [(0, 1), (1, 1), (2, 1), (3, 1)]),
    ("c11+c21", [(0, 0), (1, 0)]),
    ("c31+c41", [(2, 0), (3, 0)]),
    ("c12+c42", [(0, 1), (3, 1)]),
    ("c22+c32", [(1, 1), (2, 1)]),
    ("c13", [(0, 2)]),
    ("c23", [(1, 2)]),
    ("c33", [(2, 2)]),
    ("c43", [(3, 2)]),
)


def sensitivity(design: PlatformDesign, model: PlatformModel) -> list[SensitivityRow]:
    """Rocking and static tilt from ±1 % on each stiffness group, ±1 cm on a, b, c, ±1 % on ζ.

    Rows are sorted by their largest number, largest first.

    Computed without isolator damping, so each row shows what the tolerance alone does.
    """
    d, model = design, replace(model, eta=0.0)
    rows = []
    for name, cells in STIFFNESS_GROUPS:
        plus, minus = (
            verify(d, model, stiffness=_scaled(d.stiffness, cells, 1.0 + s * STIFFNESS_TOLERANCE)) for s in (1.0, -1.0)
        )
        rows.append(_row(name, f"±{STIFFNESS_TOLERANCE:.0%}", plus, minus))
    rho = np.array([d.a, d.b, d.c], dtype=float)
    for i, name in enumerate(("a", "b", "c")):
        shifted = [rho + s * POSITION_TOLERANCE * np.eye(3)[i] for s in (1.0, -1.0)]
        plus, minus = (verify(d, model, rho=tuple(r)) for r in shifted)
        rows.append(_row(name, f"±{POSITION_TOLERANCE * 100:.0f} cm", plus, minus))
    plus, minus = (verify(d, model, zeta=d.zeta * (1.0 + s * ZETA_TOLERANCE)) for s in (1.0, -1.0))
    rows.append(_row("ζ", f"±{ZETA_TOLERANCE:.0%}", plus, minus))
    return sorted(rows, key=lambda r: -r.worst)
