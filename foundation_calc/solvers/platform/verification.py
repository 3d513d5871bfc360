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

from dataclasses import dataclass, field

import numpy as np

from foundation_calc.solvers.platform.design import PlatformDesign
from foundation_calc.errors import ConvergenceError, PhysicsError
from foundation_calc.solvers.platform.dynamics import (
    RigidPlatform,
    inertia_about_corner,
    natural_frequencies,
    periodic_system,
    rotor,
    spring_stiffness,
    stack,
    stacked_frequencies,
)
from foundation_calc.solvers.rigid_body.inertia import skews
from foundation_calc.solvers.rigid_body.kinematics import point_map
from foundation_calc.solvers.platform.harmonic_balance import (
    SteadyState,
    VariantBasis,
    combination_label,
    orbit_peaks,
    steady_state,
    steady_state_near,
    steady_states_near,
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
    """Everything the 6-DOF model needs besides the design's stiffnesses.

    Attributes
    ----------
    J_c : central principal moments of inertia [kg m²]
    eta : hysteretic loss factor of the isolators [-]
    product_height : height of the product box [m]
    extra : further rotors (:class:`ExtraRotor`)
    damping_ratio : viscous damping ratio D of the isolators at the operating speed: a dashpot
        2 D c_ij / ω in parallel with every spring [-]
    """

    J_c: tuple
    eta: float
    product_height: float
    extra: tuple = ()
    damping_ratio: float = 0.0

    @property
    def damped(self) -> bool:
        return self.eta > 0.0 or self.damping_ratio > 0.0


def build(design: PlatformDesign, model: PlatformModel, stiffness=None, rho=None, zeta=None):
    """The rigid platform on its isolators (:attr:`RigidPlatform.isolators`) and its exciters, each a
    :class:`~foundation_calc.solvers.platform.dynamics.Rotor` (an exciter part at its machine's
    speed: an extra rotor at speed ratio r turns at |r| ω, in the sense of r), for ``design``
    (optionally with changed values)."""
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
        beta=2.0 * model.damping_ratio / abs(d.omega),
    )
    main = rotor(d.m, d.l, (d.a, d.b, d.c) if rho is None else rho, 0.0, 0.0, d.omega, 0.0)
    extra = [rotor(e.m, e.l, e.rho, e.delta1, e.delta2, e.speed_ratio * d.omega, e.phi0) for e in model.extra]
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
    state : the steady state measured
    order : truncation order K of the harmonic balance (largest |n|₁ retained)
    harmonics : number of harmonic vectors retained
    truncation_error : estimated peak motion of the harmonics left out [m]
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
    state: SteadyState = field(repr=False)
    order: int
    harmonics: int
    truncation_error: float

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


def relative_maps(corners, r_c) -> np.ndarray:
    """T with T q = motion of each corner p relative to the centre of mass r_c, [0, -[p - r_c]×];
    ``corners`` (C, 3) [m], ``r_c`` (..., 3) [m]; shape (..., C, 3, 6)."""
    arm = np.asarray(corners, dtype=float) - np.asarray(r_c, dtype=float)[..., None, :]
    return np.concatenate([np.zeros(arm.shape + (3,)), -skews(arm)], axis=-1)


def measure(state: SteadyState, r_c, corners, u) -> Verification:
    """Amplitudes, rotations, rocking and corner peaks of a steady state."""
    relative = relative_maps(corners, r_c)
    absolute = np.array([point_map(p) for p in corners])
    unit = np.eye(6)[:, None, :]
    peaks = state.peaks(np.concatenate([np.pad(unit, ((0, 0), (0, 2), (0, 0))), absolute, relative]))
    n = len(corners)
    return Verification(
        amplitudes=tuple(float(x) for x in peaks[:3]),
        rotations=tuple(float(x) for x in peaks[3:6]),
        static=state.static,
        mean=state.mean,
        corners=corners,
        corner_peaks=peaks[6 : 6 + n],
        rocking=float(np.max(peaks[6 + n :])),
        static_offset=float(np.max(np.linalg.norm(relative @ state.static, axis=1))),
        u=float(u),
        state=state,
        order=state.order,
        harmonics=len(state.vectors),
        truncation_error=state.truncation_error,
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
    return _measured(steady_state(platform, rotors), design, model, platform)


def _measured(state: SteadyState, design: PlatformDesign, model: PlatformModel, platform) -> Verification:
    corners = product_corners(design.A, design.B, model.product_height)
    return measure(state, platform.r_c, corners, design.u)


def _variant_system(basis: VariantBasis, changes: dict, platform, rotors):
    """The equations of a tolerance variant: a change of stiffness alone keeps the rotors' terms."""
    if changes.keys() == {"stiffness"}:
        return basis.system.with_springs(spring_stiffness(platform))
    return periodic_system(platform, rotors)


def _variant(design: PlatformDesign, model: PlatformModel, basis: VariantBasis, changes: dict):
    """(rocking %, static offset %) and the natural frequencies of one tolerance variant, solved on
    the nominal's harmonics (:func:`steady_state_near`)."""
    platform, rotors = build(design, model, **changes)
    state = steady_state_near(basis, platform, rotors, _variant_system(basis, changes, platform, rotors))
    v = _measured(state, design, model, platform)
    return (v.rocking_percent, v.static_offset_percent), natural_frequencies(platform, rotors, state.system).frequencies


def _variants_together(design: PlatformDesign, model: PlatformModel, basis: VariantBasis, changes: list[dict]):
    """(rocking %, static offset %) (shape (V, 2)) and natural frequencies (V, 6) of every tolerance
    variant, as :func:`_variant` gives them one by one, from one stacked solve
    (:func:`steady_states_near`) and stacked eigenproblems.

    Raises
    ------
    PhysicsError, ConvergenceError
        when any variant has no steady state or no six positive natural frequencies.
    """
    built = [build(design, model, **c) for c in changes]
    systems = [_variant_system(basis, c, platform, rotors) for c, (platform, rotors) in zip(changes, built)]
    together = stack(systems)
    static, Q = steady_states_near(basis, together, lambda i: natural_frequencies(*built[i], systems[i]).frequencies)
    frequencies = stacked_frequencies(together, basis.length)
    relative = relative_maps(product_corners(design.A, design.B, model.product_height), [p.r_c for p, _ in built])
    rocking = orbit_peaks(relative, Q[:, basis.positive]).max(axis=1)
    offset = np.linalg.norm(relative @ static[:, None, :, None], axis=(2, 3)).max(axis=1)
    return 100.0 * np.stack([rocking, offset], axis=1) / design.u, frequencies


#: Combinations of the rotor speeds up to this order |n|₁ are watched for resonances under tolerances.
WATCHED_ORDER = 2


@dataclass(frozen=True)
class SensitivityRow:
    """Rocking and static corner offset caused by one tolerance, both signs (in % of u).

    A number is None where that variant has no steady state (an undamped exact resonance);
    ``resonance`` says which combination of the rotor speeds meets which natural frequency inside
    the tolerance range ("2ω meets mode 4 at 113.3 rad/s"), empty when none does.
    """

    parameter: str
    tolerance: str
    rocking_plus: float | None
    rocking_minus: float | None
    static_plus: float | None
    static_minus: float | None
    resonance: str = ""

    @property
    def worst(self) -> float:
        """The largest of the four numbers [% of u] (infinite for a resonant row)."""
        if self.resonance:
            return float("inf")
        return max(x for x in (self.rocking_plus, self.rocking_minus, self.static_plus, self.static_minus) if x is not None)


def _one_variant(design: PlatformDesign, model: PlatformModel, basis: VariantBasis, change: dict):
    """:func:`_variant`, or ((None, None), the message) for a variant without a steady state."""
    try:
        return _variant(design, model, basis, change)
    except (PhysicsError, ConvergenceError) as exc:
        return (None, None), str(exc)


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


def _tolerance_variants(d: PlatformDesign):
    """(name, tolerance text, changes for +, changes for -) of every row of the table."""
    for name, cells in STIFFNESS_GROUPS:
        yield name, f"±{STIFFNESS_TOLERANCE:.0%}", *(
            {"stiffness": _scaled(d.stiffness, cells, 1.0 + s * STIFFNESS_TOLERANCE)} for s in (1.0, -1.0)
        )
    rho = np.array([d.a, d.b, d.c], dtype=float)
    for i, name in enumerate(("a", "b", "c")):
        yield name, f"±{POSITION_TOLERANCE * 100:.0f} cm", *(
            {"rho": tuple(rho + s * POSITION_TOLERANCE * np.eye(3)[i])} for s in (1.0, -1.0)
        )
    yield "ζ", f"±{ZETA_TOLERANCE:.0%}", *({"zeta": d.zeta * (1.0 + s * ZETA_TOLERANCE)} for s in (1.0, -1.0))


def _crossing(watched, nominal: np.ndarray, variants) -> str:
    """The first watched combination (label, Ω) that a natural frequency (by its rank) passes
    between the variants and the nominal design, as text."""
    for label, w in watched:
        for i in range(len(nominal)):
            side = {bool(x[i] > w) for x in (nominal, *variants)}
            if len(side) > 1:
                return f"{label} meets mode {i + 1} at {w:.4g} rad/s"
    return ""


def sensitivity(design: PlatformDesign, model: PlatformModel, nominal: Verification, modes: np.ndarray) -> list[SensitivityRow]:
    """Rocking and static tilt from ±1 % on each stiffness group, ±1 cm on a, b, c, ±1 % on ζ,
    computed with the isolators' damping of ``model`` on the harmonics of ``nominal`` that matter
    (:class:`VariantBasis`);
    ``modes``: the design's natural frequencies [rad/s]. On a small basis (most designs) the 28
    variants are solved together (:func:`_variants_together`); on a large one, or when one of
    them has no steady state, one at a time.

    A row whose range makes a natural frequency (undamped, mean system) cross a combination of
    the rotor speeds of order |n|₁ <= 2 is marked resonant, and so is a row with a variant that
    an undamped platform cannot answer. Rows are sorted resonant first, then by their largest
    number.
    """
    state = nominal.state
    basis = VariantBasis(state, float(np.hypot(design.A, design.B)))
    watched = [
        (combination_label(tuple(int(x) for x in n)), float(w))
        for n, w in zip(state.vectors, state.omega)
        if w > 0 and 0 < np.abs(n).sum() <= WATCHED_ORDER
    ]
    table = list(_tolerance_variants(design))
    changes = [change for _, _, *pair in table for change in pair]
    solved = None
    if basis.dense:  # a large set is solved by GMRES, variant by variant: stacking would only cost memory
        try:
            numbers, frequencies = _variants_together(design, model, basis, changes)
            solved = [((float(r), float(s)), f) for (r, s), f in zip(numbers, frequencies)]
        except (PhysicsError, ConvergenceError):  # e.g. an undamped variant exactly at resonance: which one, and why
            pass
    if solved is None:
        solved = [_one_variant(design, model, basis, change) for change in changes]
    rows = []
    for k, (name, tolerance, *_) in enumerate(table):
        pair = solved[2 * k : 2 * k + 2]
        variant_modes = [f for _, f in pair if not isinstance(f, str)]
        failure = next((f for _, f in reversed(pair) if isinstance(f, str)), "")
        resonance = _crossing(watched, modes, variant_modes) or failure
        (rp, sp), (rm, sm) = (n for n, _ in pair)
        rows.append(SensitivityRow(name, tolerance, rp, rm, sp, sm, resonance))
    return sorted(rows, key=lambda r: -r.worst)
