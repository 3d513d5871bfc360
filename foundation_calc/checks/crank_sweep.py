"""Sweep of a crank foundation's speed or soil stiffness: closed-form amplitudes, resonances, limits.

One call of the corrected first approximation on arrays (no Python object per point) gives the
peaks of x, y and θ at every point; the margins of every resonance condition come from the same
arithmetic as ``fcalc resonance`` (nearer of the zero-order and the averaged-inertia critical
speed). A point whose margin is below the first approximation's resonant margin has no periodic
solution: it is reported as resonant, never as an infinite amplitude.
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
from foundation_calc.solvers.crank.response import point_series
from foundation_calc.solvers.numerics.trig_series import derivative, peak

#: What a sweep can vary: the crank speed [rad/s] or a factor [-] on both soil coefficients.
VARIABLES = ("omega", "soil_factor")

#: Points whose peaks are found together: peak() holds ~64 × 4 × 8 bytes per series and sample.
CHUNK = 4096

#: Status of a point, worst last.
STATUSES = ("pass", "warn", "fail", "resonant")


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


def _located(motion, omega, points, limits: dict):
    """Peak displacements of every point, name -> (n, 2) [m], and, per limited quantity, whether
    a peak of C (x, y) or of a point exceeds the limit (bool (n,)).

    The points go through :func:`point_series` and :func:`peak` together, as many at a time as
    make :data:`CHUNK` sweep points' worth of series.
    """
    w = omega[:, None]
    largest = {}
    for order, quantity in enumerate(QUANTITIES):  # C: x and y
        if quantity in limits:
            largest[quantity] = _peaks(*derivative(motion.cos[..., :2, :], motion.sin[..., :2, :], w, order)).max(axis=1)
    located = {}
    names = [name for name, _, _ in points]
    horizontal = np.array([u for _, u, _ in points], dtype=float)[:, None]
    height = np.array([H for _, _, H in points], dtype=float)[:, None]
    step = max(1, CHUNK // max(len(omega), 1))
    for i in range(0, len(names), step):
        cos, sin = point_series(motion, horizontal[i : i + step], height[i : i + step])  # (points, n, 2, K + 1)
        for order, quantity in enumerate(QUANTITIES):
            if order and quantity not in limits:
                continue
            found = peak(*derivative(cos, sin, w, order))  # (points, n, 2)
            if order == 0:
                located.update(zip(names[i : i + step], found))
            if quantity in limits:
                largest[quantity] = np.maximum(largest[quantity], found.max(axis=(0, 2)))
    return located, {quantity: exceeds(value, limits[quantity]) for quantity, value in largest.items()}


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
    zero, averaged = design_frequencies(batch)
    omega = np.broadcast_to(np.asarray(batch.omega, dtype=float), values.shape)
    margins = np.stack([np.broadcast_to(condition_margin(omega, zero, averaged, c), values.shape) for c in CONDITIONS])
    nearest = np.argmin(margins, axis=0)
    margin = np.take_along_axis(margins, nearest[None], axis=0)[0]
    driven = np.array([c.source == "paper" for c in CONDITIONS])[:, None]
    fails, inside = resonance_masks(margins, detuning, driven)
    fail, warn = fails.any(axis=0), (inside & ~fails).any(axis=0)
    limited = limited_quantities(limits)
    located, over_quantities = _located(motion, omega, points, limited)
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
        critical=critical,
        limits=limited,
        detuning=detuning,
    )


__all__ = ["STATUSES", "VARIABLES", "CriticalSpeed", "SweepReport", "sweep"]
