"""The soil model's range of validity: the dimensionless frequency a0 of every judged mode and
harmonic against the range its soil method was fitted over.

A half-space method replaces the soil by springs and dashpots fitted to rigorous solutions over a
range of the dimensionless frequency a0 = ω b/V_s, b the length the method scales the footing by
(V_s the soil's shear wave velocity). Beyond it the springs and dashpots are extrapolated. Each support declares its
range (:meth:`~foundation_calc.solvers.supports.base.Support.validity`; the footing's by soil
method, :func:`~foundation_calc.solvers.supports.footing.footing_range`, the piles' in
:mod:`~foundation_calc.solvers.supports.piles`), e.g. ``"gazetas"``: a0 = ω B'/V_s, B' the shorter
half-side, a0 <= 2; ``"piles"``: a0 = ω d/V_s, d the pile diameter, a0 <= 1; frequency-independent
springs (``"coefficients"``, ``"sp26"``, ``"springs"``): no range of a0 applies.

On a stratum over bedrock (``[soil] stratum_depth``, :mod:`~foundation_calc.solvers.soil.stratum`)
the same judged frequencies are set against the layer's cutoffs, V_s/4H for the motions that shear
it (x, y, rz; the plane model's horizontal) and V_La/4H for those that compress it (z, rx, ry; the
plane model's vertical and rocking): below its cutoff a motion radiates nothing, its dashpot is the
material damping alone, and a resonance there is far less damped than on the half-space. Each such
frequency is a warning (:attr:`SoilValidity.below`), as an a0 beyond the range is.

The frequencies judged (:func:`soil_validity`): every natural frequency the resonance check judges,
with the motions whose springs hold at least :data:`MOTION_SHARE` of the mode's strain energy
(:func:`spring_shares`: a spring the mode barely strains cannot make its frequency wrong), and
every order n ω the resonance rule judges (order 1 always), with every motion (a harmonic loads
whichever springs its forces reach). The soil as given (a ``modulus_range`` scales V_s and the
modes' frequencies alike: their a0 stays).
"""

from __future__ import annotations

import math
from collections.abc import Iterable, Mapping
from dataclasses import dataclass

import numpy as np

#: Smallest share of a mode's strain energy held by one motion's spring for that motion to be
#: judged at the mode's frequency [-]: a spring holding 1 % of it moves the frequency by 0.5 %
#: for a 100 % error (dp/p = ½ Σ e_i dK_i/K_i), a tenth of the 5 % that fails any resonance.
MOTION_SHARE = 0.01

@dataclass(frozen=True)
class FittedRange:
    """The range of a0 a soil method holds over.

    Attributes
    ----------
    method : the soil method, as ``[soil] method`` names it
    a0_max : largest a0 of the fit [-]; None for a frequency-independent method
    definition : how the method forms a0 ("" when none applies)
    source : where the range comes from, or why none applies
    """

    method: str
    a0_max: float | None
    definition: str
    source: str

    @property
    def applies(self) -> bool:
        return self.a0_max is not None


def fitted_range(method: str) -> FittedRange:
    """The declared range of a footing's soil ``method`` (:func:`~foundation_calc.solvers.supports.footing.footing_range`)."""
    from foundation_calc.solvers.supports.footing import footing_range

    return FittedRange(method, *footing_range(method))


def characteristic_lengths(method: str, L: float, B: float) -> dict[str, float]:
    """The length b [m] of a0 = ω b/V_s of each motion by a footing's ``method`` on a base L (along
    x, the plane model's plane) × B [m]: the block's x, y, z, rx, ry, rz
    (:func:`~foundation_calc.solvers.supports.footing.footing_lengths`) and the plane model's
    horizontal (x), vertical (z) and rocking (about the axis normal to the plane, ry).

    >>> b = characteristic_lengths("lysmer", 6.0, 4.0)
    >>> round(b["z"], 4), round(b["rocking"], 4), round(characteristic_lengths("gazetas", 6.0, 4.0)["rz"], 4)
    (2.764, 3.0943, 2.0)
    """
    from foundation_calc.solvers.supports.footing import footing_lengths

    lengths = footing_lengths(method, L, B)
    return lengths | {"horizontal": lengths["x"], "vertical": lengths["z"], "rocking": lengths["ry"]}


@dataclass(frozen=True)
class JudgedFrequency:
    """A frequency the checks judge and the motions whose springs matter there.

    ``at`` names it (``"p2"``, ``"2ω"``, ``"mode 5 (ry)"``, ``"fan: 2ω"``); ``omega`` [rad/s]."""

    at: str
    omega: float
    motions: tuple[str, ...]


@dataclass(frozen=True)
class A0Value:
    """a0 = ω b/V_s [-] of one motion at one judged frequency ``omega`` [rad/s], b = ``length`` [m]."""

    at: str
    omega: float
    motion: str
    length: float
    a0: float


#: The motions that shear the stratum (cutoff V_s/4H); the others compress it (cutoff V_La/4H).
SHEAR_MOTIONS = ("x", "y", "rz", "horizontal")


@dataclass(frozen=True)
class StratumCutoffs:
    """A stratum's depth ``H`` [m] and cutoff circular frequencies ``omega_s`` (shear: sway and
    torsion) and ``omega_c`` (compression: vertical and rocking) [rad/s]."""

    H: float
    omega_s: float
    omega_c: float

    def cutoff(self, motion: str) -> float:
        """The cutoff [rad/s] of ``motion`` (:data:`SHEAR_MOTIONS` shear the layer)."""
        return self.omega_s if motion in SHEAR_MOTIONS else self.omega_c

    @property
    def text(self) -> str:
        """The cutoffs in Hz, as the messages give them."""
        return (f"stratum H = {self.H:g} m over bedrock: f_s = V_s/4H = {self.omega_s / (2 * math.pi):.4g} Hz"
                f" (x, y, rz), f_c = V_La/4H = {self.omega_c / (2 * math.pi):.4g} Hz (z, rx, ry)")


@dataclass(frozen=True)
class SoilValidity:
    """Every judged a0 of a scene and those beyond its method's fitted range; on a stratum, the
    judged frequencies below its cutoffs.

    ``V_s`` [m/s] is None and ``values`` empty for a method without a range."""

    fitted: FittedRange
    V_s: float | None
    values: tuple[A0Value, ...]
    stratum: StratumCutoffs | None = None

    @property
    def below(self) -> tuple[A0Value, ...]:
        """The judged values whose frequency lies below their motion's cutoff on the stratum (no
        radiation damping there), lowest frequency first; empty without a stratum."""
        if self.stratum is None:
            return ()
        return tuple(sorted((v for v in self.values if v.omega < self.stratum.cutoff(v.motion)),
                            key=lambda v: v.omega))

    @property
    def warns(self) -> bool:
        """True when an a0 lies beyond the range or a judged frequency below a stratum's cutoff."""
        return bool(self.beyond or self.below)

    @property
    def stratum_text(self) -> str:
        """The stratum's part of :attr:`text` (empty without a stratum)."""
        if self.stratum is None:
            return ""
        if not self.below:
            return f"; {self.stratum.text}: every judged frequency at or above its cutoff (radiation damping applies)"
        places = {}
        for v in self.below:
            places.setdefault(v.at, []).append(v.motion)
        where = "; ".join(f"at {at}: {', '.join(motions)}" for at, motions in places.items())
        return (f"; {self.stratum.text}: below the cutoff, no radiation damping (material damping only) {where}")

    @property
    def beyond(self) -> tuple[A0Value, ...]:
        """The values past the range, largest first."""
        if not self.fitted.applies:
            return ()
        return tuple(sorted((v for v in self.values if v.a0 > self.fitted.a0_max), key=lambda v: -v.a0))

    @property
    def largest(self) -> A0Value | None:
        return max(self.values, key=lambda v: v.a0, default=None)

    @property
    def text(self) -> str:
        """One line: the worst value past the range, the largest within it, or why none applies."""
        f = self.fitted
        if not f.applies:
            return f"method {f.method!r}: {f.source}"
        if not self.beyond:
            top = self.largest
            where = "" if top is None else f" (largest {top.a0:.3g}, {top.motion} at {top.at})"
            return (f"a0 within the range of soil method {f.method!r}, a0 <= {f.a0_max:g}, at every judged"
                    f" frequency{where}{self.stratum_text}")
        places = {}
        for v in self.beyond:
            places.setdefault(v.at, []).append(f"{v.motion} {v.a0:.3g}")
        where = "; ".join(f"at {at}: {', '.join(values)}" for at, values in places.items())
        return (f"a0 beyond the range of soil method {f.method!r} (a0 <= {f.a0_max:g}, {f.source}): {where};"
                f" its springs and damping there are extrapolated{self.stratum_text}")

    @property
    def brief(self) -> str:
        """The largest a0 past the range and the lowest frequency below a stratum's cutoff in a phrase
        (empty when neither is), for a check's reason."""
        phrases = []
        if self.beyond:
            top = self.beyond[0]
            phrases.append(f"soil model: a0 of {top.motion} = {top.a0:.3g} at {top.at} is beyond the range of soil"
                           f" method {self.fitted.method!r} (a0 <= {self.fitted.a0_max:g})")
        if self.below:
            low = self.below[0]
            phrases.append(f"soil model: {low.at} ({low.omega / (2 * math.pi):.4g} Hz) lies below the stratum's cutoff"
                           f" {self.stratum.cutoff(low.motion) / (2 * math.pi):.4g} Hz of {low.motion}: no radiation"
                           " damping there, material damping only")
        return "; ".join(phrases)

    def details(self) -> tuple[str, ...]:
        """A line per value past the range (``WARN ...``), for JUnit and the JSON documents."""
        f = self.fitted
        beyond = tuple(
            f"WARN soil model: a0 = ω b/V_s = {v.a0:.4g} > {f.a0_max:g} at {v.at} ({v.omega:.6g} rad/s), {v.motion}"
            f" (b = {v.length:.4g} m, V_s = {self.V_s:.4g} m/s): beyond the range of method {f.method!r} ({f.source})"
            for v in self.beyond
        )
        return beyond + tuple(
            f"WARN soil model: {v.at} ({v.omega:.6g} rad/s) lies below the cutoff {self.stratum.cutoff(v.motion):.6g}"
            f" rad/s of {v.motion} on the stratum (H = {self.stratum.H:g} m): no radiation damping, material damping only"
            for v in self.below
        )

    def document(self) -> dict:
        """The JSON part (SI units)."""
        f = self.fitted
        return {
            "method": f.method,
            "a0_max": f.a0_max,
            "definition": f.definition or None,
            "source": f.source,
            "shear_wave_velocity": self.V_s,
            "values": [{"at": v.at, "omega": v.omega, "motion": v.motion, "length": v.length, "a0": v.a0} for v in self.values],
            "beyond": [{"at": v.at, "omega": v.omega, "motion": v.motion, "length": v.length, "a0": v.a0} for v in self.beyond],
            "stratum": None if self.stratum is None else {
                "depth": self.stratum.H, "cutoff_shear": self.stratum.omega_s, "cutoff_compression": self.stratum.omega_c,
                "below": [{"at": v.at, "omega": v.omega, "motion": v.motion, "cutoff": self.stratum.cutoff(v.motion)}
                          for v in self.below],
            },
            "text": self.text,
        }


def soil_validity(method: str, V_s: float | None, lengths: Mapping[str, float],
                  frequencies: Iterable[JudgedFrequency], stratum: StratumCutoffs | None = None) -> SoilValidity:
    """a0 = ω b/V_s of every motion of every judged frequency against ``method``'s fitted range.

    Parameters
    ----------
    method : the soil method
    V_s : shear wave velocity of the soil [m/s] (unused by a method without a range)
    lengths : motion -> b [m] (:func:`characteristic_lengths`)
    frequencies : the judged frequencies and the motions judged at each
    stratum : the cutoffs of a stratum over bedrock (:func:`declared_range`), None on a half-space

    >>> v = soil_validity("lysmer", 170.0, characteristic_lengths("lysmer", 6.0, 4.0),
    ...                   [JudgedFrequency("p2", 140.56, ("horizontal", "rocking"))])
    >>> [(x.motion, round(x.a0, 3)) for x in v.beyond]
    [('rocking', 2.558), ('horizontal', 2.285)]
    """
    return judge_a0(fitted_range(method), V_s, lengths, frequencies, stratum)


def judge_a0(fitted: FittedRange, V_s: float | None, lengths: Mapping[str, float],
             frequencies: Iterable[JudgedFrequency], stratum: StratumCutoffs | None = None) -> SoilValidity:
    """:func:`soil_validity` against the range ``fitted``."""
    if not fitted.applies:
        return SoilValidity(fitted, None, ())
    values = tuple(
        A0Value(f.at, float(f.omega), motion, lengths[motion], float(f.omega) * lengths[motion] / V_s)
        for f in frequencies if not math.isnan(f.omega)
        for motion in f.motions
    )
    return SoilValidity(fitted, float(V_s), values, stratum)


def spring_shares(springs: np.ndarray, motion: np.ndarray) -> np.ndarray:
    """Share of each spring in each mode's strain energy, k_i q_ij² / Σ_i k_i q_ij² [-], shape (D, J):
    ``springs`` (J, D) the springs each mode was solved on, ``motion`` (D, J) each spring's
    motion in each mode.

    >>> spring_shares(np.array([[1.0, 3.0]]), np.array([[1.0], [1.0]])).ravel().tolist()
    [0.25, 0.75]
    """
    energy = np.asarray(springs, dtype=float).T * np.asarray(motion, dtype=float) ** 2
    return energy / energy.sum(axis=0, keepdims=True)


def mode_frequencies(labels, frequencies, shares: np.ndarray, motions) -> list[JudgedFrequency]:
    """Each mode with the motions holding at least :data:`MOTION_SHARE` of its strain energy."""
    return [
        JudgedFrequency(label, float(p), tuple(m for i, m in enumerate(motions) if shares[i, j] >= MOTION_SHARE))
        for j, (label, p) in enumerate(zip(labels, frequencies))
    ]


def plane_validity(method: str, V_s, L: float, B: float, frequencies: Mapping[str, float], block_at,
                   speeds: Mapping[str, float], stratum: StratumCutoffs | None = None) -> SoilValidity:
    """:func:`soil_validity` of the plane model: the modes ``frequencies`` (name -> p [rad/s]) of
    the block ``block_at(ω)`` with the motions they strain, and ``speeds`` (name -> ω [rad/s],
    e.g. the judged orders n ω) with every motion (:func:`plane_judged`); ``stratum`` as
    :func:`soil_validity` takes it."""
    if not fitted_range(method).applies:
        return soil_validity(method, V_s, {}, ())
    from foundation_calc.solvers.crank.modes import plane_modes

    judged = plane_judged(plane_modes(frequencies, block_at), speeds)
    return soil_validity(method, V_s, characteristic_lengths(method, L, B), judged, stratum)


def plane_judged(modes, speeds: Mapping[str, float]) -> list[JudgedFrequency]:
    """The plane model's judged frequencies: each of ``modes``
    (:class:`~foundation_calc.solvers.crank.modes.PlaneModes`) with the base motions whose direct
    springs hold at least :data:`MOTION_SHARE` of its strain energy in them (:func:`spring_shares`),
    and ``speeds`` (name -> ω [rad/s]) with every motion."""
    from foundation_calc.solvers.crank.modes import BASE_MOTIONS

    shares = spring_shares(modes.springs, modes.base_motion())
    judged = mode_frequencies(modes.labels, modes.frequencies, shares, BASE_MOTIONS)
    return judged + [JudgedFrequency(at, w, BASE_MOTIONS) for at, w in speeds.items()]


def declared_range(support) -> tuple[FittedRange, StratumCutoffs | None]:
    """The range a support declares (:meth:`~foundation_calc.solvers.supports.base.Support.validity`)
    and its stratum's cutoffs, as the checks judge them."""
    declared = support.validity()
    cutoffs = None if declared.cutoffs is None else StratumCutoffs(*declared.cutoffs)
    return FittedRange(declared.method, declared.a0_max, declared.definition, declared.source), cutoffs


def judged_orders(rows) -> list[int]:
    """The orders n the resonance rule judges on any mode (``rows``:
    :class:`~foundation_calc.checks.resonance.report.ResonanceRow`), and 1 (the speed) always, ascending."""
    orders = {1}
    for row in rows:
        if row.judged:
            orders.add(int(row.order))
    return sorted(orders)


def _order_label(n: int) -> str:
    return f"{n if n > 1 else ''}ω"


def crank_validity(scene, report) -> SoilValidity:
    """The soil model's validity of a ``crank_foundation`` scene at the modes k0, p1, p2 of its
    resonance ``report`` (:class:`~foundation_calc.checks.resonance.report.ResonanceReport`, on a
    frequency-dependent support each at its own frequency) and every order the rule judges, against
    the range its support declares (:meth:`~foundation_calc.solvers.supports.base.Support.validity`;
    the plane's horizontal, vertical and rocking motions are the support's x, z and ry). On a support
    coupling the plane (a pile group) the modes are the one model's the resonance check solves
    (:func:`~foundation_calc.checks.resonance.frequencies.scene_plane_modes`), each judged with the motions
    whose direct springs K_x, K_z, K_φ at O it strains."""
    from foundation_calc.checks.resonance.frequencies import scene_plane_modes

    support = scene.support()
    declared = support.validity()
    fitted, cutoffs = declared_range(support)
    if not fitted.applies:
        return SoilValidity(fitted, None, ())
    zero = report.zero_order
    modes = {m: float(getattr(zero, m)) for m in ("k0", "p1", "p2")}
    speeds = {_order_label(n): n * report.omega for n in judged_orders(report.rows)}
    b = declared.lengths
    lengths = b | {"horizontal": b["x"], "vertical": b["z"], "rocking": b["ry"]}
    judged = plane_judged(scene_plane_modes(scene, modes), speeds)
    return judge_a0(fitted, declared.V_s, lengths, judged, cutoffs)


def block_validity(scene, report) -> SoilValidity:
    """The soil model's validity of a ``block_foundation`` scene at its six modes (with the
    motions each strains) and every machine's orders the rule judges (``report``: a
    :class:`~foundation_calc.checks.amplitudes.machines.BlockReport`), against the range its support declares
    (:meth:`~foundation_calc.solvers.supports.base.Support.validity`)."""
    from foundation_calc.solvers.rigid_body.modes import MOTIONS

    support = scene.support()
    declared = support.validity()
    fitted, cutoffs = declared_range(support)
    if not fitted.applies:
        return SoilValidity(fitted, None, ())
    modes = report.modes
    springs = np.asarray(support.impedance(modes.frequencies if support.frequency_dependent else 0.0).springs)
    shares = spring_shares(np.broadcast_to(springs, (len(modes.frequencies), 6)), modes.shapes)  # (6 modes, 6 springs)
    labels = [f"mode {j + 1} ({motion})" for j, motion in enumerate(modes.dominant)]
    judged = mode_frequencies(labels, modes.frequencies, shares, MOTIONS)
    harmonics: dict[float, list[str]] = {}  # machines at one speed share their orders' frequencies
    for machine, speed in report.speeds.items():
        for n in judged_orders([r for r in report.resonance.rows if r.machine == machine]):
            harmonics.setdefault(n * speed, []).append((machine, n))
    several = len(report.speeds) > 1
    for omega, orders in harmonics.items():
        names = ", ".join(f"{m}: {_order_label(n)}" if several else _order_label(n) for m, n in orders)
        judged.append(JudgedFrequency(names, omega, MOTIONS))
    return judge_a0(fitted, declared.V_s, declared.lengths, judged, cutoffs)


__all__ = ["MOTION_SHARE", "SHEAR_MOTIONS", "A0Value", "FittedRange", "JudgedFrequency",
           "SoilValidity", "StratumCutoffs",
           "block_validity", "characteristic_lengths", "crank_validity", "declared_range", "fitted_range", "judge_a0",
           "judged_orders",
           "mode_frequencies", "plane_judged", "plane_validity", "soil_validity", "spring_shares"]
