"""Sweep of a crank foundation's speed or soil stiffness: closed-form amplitudes, resonances, limits.

One call of the corrected first approximation on arrays (no Python object per point) gives the
peaks of x, y and θ at every point; the margins of every resonance condition come from the same
arithmetic as ``fcalc resonance`` (nearer of the zero-order and the averaged-inertia critical
speed). With base dashpots every point has a finite amplitude and a phase, at and through each
resonance; without them a point whose margin is below the first approximation's resonant margin
has no periodic solution: it is reported as resonant, never as an infinite amplitude.
"""

from __future__ import annotations

from dataclasses import dataclass

import numpy as np

from foundation_calc.checks.crank_resonance import design_frequencies
from foundation_calc.checks.limits import QUANTITIES, exceeds, limited_quantities
from foundation_calc.checks.outcomes import resonance_masks
from foundation_calc.solvers.crank.closed_form import first_approximation_motion, varied
from foundation_calc.solvers.crank.mechanism import CrankDesign
from foundation_calc.solvers.crank.resonance import CONDITIONS, condition_margin, critical_speed
from foundation_calc.solvers.crank.response import DOFS, point_series
from foundation_calc.solvers.numerics.trig_series import derivative, peak

#: What a sweep can vary: the crank speed [rad/s] or a factor [-] on both soil coefficients.
VARIABLES = ("omega", "soil_factor")

#: Points whose peaks are found together: peak() holds ~64 × 4 × 8 bytes per series and sample.
CHUNK = 4096

#: Status of a point, worst last.
STATUSES = ("pass", "warn", "fail", "resonant")

#: Harmonics of the first approximation reported per point (dof, n).
HARMONICS = (("y", 1), ("y", 2), ("x", 1), ("x", 3), ("theta", 1), ("theta", 3))


@dataclass(frozen=True)
class CriticalSpeed:
    """A resonance condition's critical speeds [rad/s] (zero-order and averaged-inertia operator)."""

    label: str
    source: str
    zero_order: float
    averaged: float


@dataclass(frozen=True)
class SweepReport:
    """Amplitudes and verdicts along a sweep (arrays of length n).

    Attributes
    ----------
    variable : ``"omega"`` or ``"soil_factor"``
    values : the swept values [rad/s or -]
    omega : crank speed at each point [rad/s]
    peaks : (n, 3) peak |x| [m], |y| [m], |θ| [rad]; 0 where ``resonant``
    resonant : no periodic solution of the first approximation (margin < 1e-6)
    margin : smallest relative distance from a resonance condition [-]
    nearest : index into :data:`~foundation_calc.solvers.crank.resonance.CONDITIONS` of that one
    points : scene point name -> (n, 2) peak horizontal and vertical displacement [m]
    over_limit : a peak of C (x, y) or of a point exceeds its limit (displacement, velocity or
        acceleration, whichever the scene limits; :mod:`~foundation_calc.checks.limits`)
    over_quantities : limited quantity -> where its peak exceeds the limit
    status : one of :data:`STATUSES` per point
    harmonics : "y1", "x1", ... (:data:`HARMONICS`) -> complex coefficient cos - i sin per point
        [m or rad]: amplitude ``abs``, phase lag φ = -``angle`` of q_n = A cos(nωt - φ)
    damped : the design has base dashpots
    critical : critical speeds inside the swept range (speed sweeps; empty for soil sweeps)
    """

    variable: str
    values: np.ndarray
    omega: np.ndarray
    peaks: np.ndarray
    resonant: np.ndarray
    margin: np.ndarray
    nearest: np.ndarray
    points: dict
    over_limit: np.ndarray
    over_quantities: dict
    status: np.ndarray
    harmonics: dict
    damped: bool
    critical: tuple[CriticalSpeed, ...]
    limits: dict
    detuning: float

    @property
    def amplitude_limit(self) -> float | None:
        """The displacement limit [m], or None."""
        return self.limits.get("displacement")


def _peaks(cos, sin):
    """:func:`peak` over the first axis in chunks of :data:`CHUNK`, so memory stays bounded."""
    return np.concatenate([peak(cos[i : i + CHUNK], sin[i : i + CHUNK]) for i in range(0, len(cos), CHUNK)])


def _over(motion, omega, points, limits: dict, displacements) -> dict:
    """Limited quantity -> bool array: a peak of C (x, y) or of a point exceeds the limit.

    ``displacements``: the displacement peaks already found, (n, ≥ 2) arrays of C (x, y first)
    and of each point; they are reused, not searched again.
    """
    series = [(motion.cos[..., :2, :], motion.sin[..., :2, :])]  # x, y of C
    series += [point_series(motion, u, H) for _, u, H in points]
    over = {}
    for order, quantity in enumerate(QUANTITIES):
        if quantity not in limits:
            continue
        if order == 0:
            largest = np.max([peaks[:, :2].max(axis=1) for peaks in displacements], axis=0)
        else:
            w = omega[:, None]
            largest = np.max([_peaks(*derivative(c, s, w, order)).max(axis=1) for c, s in series], axis=0)
        over[quantity] = exceeds(largest, limits[quantity])
    return over


def sweep(design: CrankDesign, variable: str, values, limits, detuning: float, points=()) -> SweepReport:
    """Sweep ``variable`` (``"omega"`` [rad/s] or ``"soil_factor"`` [-]) over ``values``.

    ``limits``: the scene's ``[limits]`` (amplitude, velocity, acceleration [m, m/s, m/s²] or
    None), checked as ``fcalc amplitudes`` checks them; ``points``: (name, horizontal, height)
    [m] of body points relative to C, as the scene's ``[[points]]``; their peaks come from the
    same series (rigid-body motion, exact in θ).

    Raises
    ------
    PhysicsError
        when a point of the sweep is unstable in rocking (a soil factor too small).
    """
    if variable not in VARIABLES:
        raise ValueError(f"variable must be one of {VARIABLES}, not {variable!r}")
    values = np.asarray(values, dtype=float)
    batch = varied(design, **{variable: values})
    motion, resonant = first_approximation_motion(batch)
    peaks = _peaks(motion.cos, motion.sin)  # displacement only: (n, 3)
    located = {name: _peaks(*point_series(motion, u, H)) for name, u, H in points}
    zero, averaged = design_frequencies(batch)
    omega = np.broadcast_to(np.asarray(batch.omega, dtype=float), values.shape)
    margins = np.stack([np.broadcast_to(condition_margin(omega, zero, averaged, c), values.shape) for c in CONDITIONS])
    nearest = np.argmin(margins, axis=0)
    margin = np.take_along_axis(margins, nearest[None], axis=0)[0]
    driven = np.array([c.source == "paper" for c in CONDITIONS])[:, None]
    fails, inside = resonance_masks(margins, detuning, driven)
    fail, warn = fails.any(axis=0), (inside & ~fails).any(axis=0)
    limited = limited_quantities(limits)
    over_quantities = _over(motion, omega, points, limited, [peaks, *located.values()])
    over = np.zeros(values.shape, dtype=bool)
    for mask in over_quantities.values():
        over |= mask
    status = np.where(resonant, "resonant", np.where(fail | over, "fail", np.where(warn, "warn", "pass")))
    critical = ()
    if variable == "omega":
        lo, hi = values.min(), values.max()
        critical = tuple(
            CriticalSpeed(c.label, c.source, float(w0), float(w1))
            for c in CONDITIONS
            for w0, w1 in [(critical_speed(getattr(zero, c.mode), c.harmonic), critical_speed(getattr(averaged, c.mode), c.harmonic))]
            if lo <= max(w0, w1) and min(w0, w1) <= hi
        )
    return SweepReport(
        variable=variable,
        values=values,
        omega=omega,
        peaks=peaks,
        resonant=np.asarray(resonant, dtype=bool),
        margin=margin,
        nearest=nearest,
        points=located,
        over_limit=over,
        over_quantities=over_quantities,
        status=status,
        harmonics={
            f"{dof}{n}": motion.cos[..., DOFS.index(dof), n] - 1j * motion.sin[..., DOFS.index(dof), n]
            for dof, n in HARMONICS
        },
        damped=bool(np.any(np.array([design.C_x, design.C_z, design.C_phi]) > 0.0)),
        critical=critical,
        limits=limited,
        detuning=detuning,
    )


__all__ = ["HARMONICS", "STATUSES", "VARIABLES", "CriticalSpeed", "SweepReport", "sweep"]
