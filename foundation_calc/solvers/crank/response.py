"""Periodic motion of the foundation as trigonometric series: points, peaks, comparisons.

Each approximation (the paper's corrected first approximation, the averaged-operator closed
form, the exact harmonic balance) produces a :class:`PeriodicMotion`: the cosine and sine
coefficients of x [m], y [m] and θ [rad] for the harmonics n = 0 ... K of the crank speed ω.
"""

from __future__ import annotations

from dataclasses import dataclass, fields

import numpy as np

from foundation_calc.solvers.numerics.trig_series import analyse, derivative, peak, rms, sample

#: Degrees of freedom in the order of the first axis of :class:`PeriodicMotion` arrays.
DOFS = ("x", "y", "theta")

#: Directions of a point's displacement.
DIRECTIONS = ("horizontal", "vertical")


@dataclass(frozen=True)
class PeriodicMotion:
    """x(t), y(t), θ(t) = Σ_n cos[..., n] cos(nωt) + sin[..., n] sin(nωt).

    ``cos``, ``sin``: shape (..., 3, K + 1), rows x [m], y [m] (down), θ [rad]; ``omega`` [rad/s].
    """

    omega: object
    cos: np.ndarray
    sin: np.ndarray

    def coefficient(self, dof: str, n: int):
        """(cos, sin) coefficient of harmonic n of ``dof`` (0 beyond the series)."""
        i = DOFS.index(dof)
        if n >= self.cos.shape[-1]:
            return np.zeros_like(self.cos[..., i, 0]), np.zeros_like(self.cos[..., i, 0])
        return self.cos[..., i, n], self.sin[..., i, n]


@dataclass(frozen=True)
class Peaks:
    """Largest |value| over one revolution of a displacement, its velocity and acceleration.

    Arrays of the shape of the signals' leading dimensions [m, m/s, m/s²] (rad for θ).
    """

    displacement: object
    velocity: object
    acceleration: object


class Rms(Peaks):
    """RMS over one revolution of a displacement, its velocity and acceleration, the mean left out
    (fields as :class:`Peaks`)."""


def _with_derivatives(kind, measure, cos, sin, omega):
    """``kind(measure(q), measure(q'), measure(q''))`` of a series q."""
    return kind(*(measure(*derivative(cos, sin, omega, order)) for order in range(3)))


def peaks(cos, sin, omega) -> Peaks:
    """Peaks of a series and of its first two time derivatives (see :func:`trig_series.peak`)."""
    return _with_derivatives(Peaks, peak, cos, sin, omega)


def rms_values(cos, sin, omega) -> Rms:
    """RMS of a series and of its first two time derivatives (see :func:`trig_series.rms`)."""
    return _with_derivatives(Rms, rms, cos, sin, omega)


def motion_peaks(motion: PeriodicMotion) -> Peaks:
    """Peaks of x, y, θ (last axis of the result's arrays: x, y, θ)."""
    return peaks(motion.cos, motion.sin, np.asarray(motion.omega)[..., None])


#: |θ| [rad] up to which θ - sin θ is summed as its Taylor series (14 terms reach 1e-24 of the
#: first at 2 rad); beyond it sin θ < θ/2 and the difference loses at most one bit.
_SERIES_ANGLE = 2.0

#: (2j + 2)(2j + 3) for j = 14 ... 1: ratios of the Taylor terms θ^(2j+1)/(2j+1)! of θ - sin θ.
_TAYLOR_RATIOS = tuple(float((2 * j + 2) * (2 * j + 3)) for j in range(14, 0, -1))


def theta_minus_sine(theta):
    """θ - sin θ [rad] to full relative precision (written out, it keeps only the digits of θ
    beyond those it shares with sin θ: none of θ³/6 below |θ| ~ 1e-8).

    >>> print(f"{float(theta_minus_sine(1e-5)):.14e}")  # θ³/6 - θ⁵/120
    1.66666666665833e-16
    """
    theta = np.asarray(theta, dtype=float)
    t = theta * theta
    # the terms beyond the first whose size, at the largest |θ| summed, is below 2⁻⁶⁰ of θ³/6
    largest = min(float(t.max(initial=0.0)), _SERIES_ANGLE**2)
    terms, size = 0, 1.0
    for ratio in _TAYLOR_RATIOS[::-1]:
        size *= largest / ratio
        if size < 2.0**-60:
            break
        terms += 1
    small = np.minimum(t, _SERIES_ANGLE**2)  # the series serves |θ| <= _SERIES_ANGLE only: bounded, it cannot overflow
    taylor = 1.0
    for ratio in _TAYLOR_RATIOS[len(_TAYLOR_RATIOS) - terms :]:
        taylor = 1.0 - small / ratio * taylor
    return np.where(np.abs(theta) <= _SERIES_ANGLE, theta * small / 6.0 * taylor, theta - np.sin(theta))


def rotation_series(motion: PeriodicMotion):
    """sin θ and cos θ - 1 as series up to twice the motion's harmonics, shape (..., 2, 2K + 1).

    sin θ = θ - (θ - sin θ) and cos θ - 1 = -2 sin²(θ/2): θ keeps its own coefficients, and only
    the small remainders are sampled at 8K + 4 phases and analysed again (their round-off is
    relative to their own size, ~θ²). Exact for the θ² terms; the θ³ terms beyond 2K are below
    1e-12 relative for |θ| < 1e-3 rad.
    """
    K = motion.cos.shape[-1] - 1
    theta = sample(motion.cos[..., 2, :], motion.sin[..., 2, :], 8 * K + 4)
    half = np.sin(0.5 * theta)
    small_cos, small_sin = analyse(np.stack([-theta_minus_sine(theta), -2.0 * half * half], axis=-2), 2 * K)
    widen = [(0, 0)] * (motion.cos.ndim - 2) + [(0, K)]
    small_cos[..., 0, :] += np.pad(motion.cos[..., 2, :], widen)
    small_sin[..., 0, :] += np.pad(motion.sin[..., 2, :], widen)
    return small_cos, small_sin


def point_series(motion: PeriodicMotion, horizontal, height):
    """Horizontal and vertical displacement [m] of a body point as series, shape (..., 2, 2K + 1).

    The point sits ``horizontal`` [m] from C (in +x) and ``height`` [m] above C; its
    displacement is the rigid-body motion X + (R(θ) - I) b, b = (horizontal, -height) in body
    axes, that is (x + (cos θ - 1) u + H sin θ, y + u sin θ - (cos θ - 1) H): linear in u and H,
    so every point is a combination of x, y and the two series of :func:`rotation_series`.
    """
    K = motion.cos.shape[-1] - 1
    widen = [(0, 0)] * (motion.cos.ndim - 1) + [(0, K)]
    u, H = np.asarray(horizontal, dtype=float)[..., None], np.asarray(height, dtype=float)[..., None]
    parts = []
    for xy, (sine, cosine_1) in zip((np.pad(motion.cos, widen), np.pad(motion.sin, widen)),
                                    (np.moveaxis(part, -2, 0) for part in rotation_series(motion))):
        x, y = xy[..., 0, :], xy[..., 1, :]
        parts.append(np.stack([x + u * cosine_1 + H * sine, y + u * sine - H * cosine_1], axis=-2))
    return parts[0], parts[1]


def point_peaks(motion: PeriodicMotion, horizontal, height) -> Peaks:
    """Peaks of a point's horizontal and vertical motion (last axis: horizontal, vertical)."""
    cos, sin = point_series(motion, horizontal, height)
    return peaks(cos, sin, np.asarray(motion.omega)[..., None])


def point_rms(motion: PeriodicMotion, horizontal, height) -> Rms:
    """RMS values of a point's horizontal and vertical motion (last axis: horizontal, vertical)."""
    cos, sin = point_series(motion, horizontal, height)
    return rms_values(cos, sin, np.asarray(motion.omega)[..., None])


def superpose(a: PeriodicMotion, b: PeriodicMotion) -> PeriodicMotion:
    """The sum of two periodic motions at the same speed (linear superposition), harmonics padded
    to the longer series."""
    K = max(a.cos.shape[-1], b.cos.shape[-1])

    def padded(c):
        return np.concatenate([c, np.zeros(c.shape[:-1] + (K - c.shape[-1],))], axis=-1)

    return PeriodicMotion(a.omega, padded(a.cos) + padded(b.cos), padded(a.sin) + padded(b.sin))


def splice_harmonics(motions: list[PeriodicMotion]) -> PeriodicMotion:
    """Harmonic n of ``motions[n]``: the steady state of a foundation whose springs depend on
    frequency, each harmonic solved with the springs at its own frequency n ω (the system is
    linear in the base's impedance, harmonic by harmonic). ``motions[1]`` gives ω."""
    width = max(m.cos.shape[-1] for m in motions)
    shape = np.broadcast_shapes(*(m.cos.shape[:-1] for m in motions)) + (width,)
    cos, sin = np.zeros(shape), np.zeros(shape)
    for n, m in enumerate(motions):
        if n < m.cos.shape[-1]:
            cos[..., n], sin[..., n] = m.cos[..., n], m.sin[..., n]
    return PeriodicMotion(motions[1].omega, cos, sin)


def relative_error(approx, exact):
    """|approx - exact| / |exact| [-] (arrays or complex); 0 where both are 0."""
    diff = np.abs(np.asarray(approx) - np.asarray(exact))
    size = np.abs(np.asarray(exact))
    return np.where(size == 0.0, np.where(diff == 0.0, 0.0, 1.0), diff / np.where(size == 0.0, 1.0, size))


#: Points evaluated in one array operation; bounds the memory of a scene with many points.
POINT_CHUNK = 1024


def located(motion: PeriodicMotion, points) -> tuple[dict[str, Peaks], dict[str, Rms]]:
    """Peaks and RMS values of C and of every point (objects with ``name``, ``horizontal``,
    ``height`` [m]), each a point's (horizontal, vertical) values (:func:`point_peaks`,
    :func:`point_rms`), all points of a chunk of :data:`POINT_CHUNK` in one array operation."""
    names = ["C", *(p.name for p in points)]
    horizontal = np.array([0.0, *(p.horizontal for p in points)])
    height = np.array([0.0, *(p.height for p in points)])
    chunks = [
        (point_peaks(motion, horizontal[i : i + POINT_CHUNK], height[i : i + POINT_CHUNK]),
         point_rms(motion, horizontal[i : i + POINT_CHUNK], height[i : i + POINT_CHUNK]))
        for i in range(0, len(names), POINT_CHUNK)
    ]
    peaks = {f.name: np.concatenate([getattr(pk, f.name) for pk, _ in chunks]) for f in fields(Peaks)}
    rms = {f.name: np.concatenate([getattr(rm, f.name) for _, rm in chunks]) for f in fields(Rms)}
    return (
        {name: Peaks(**{q: values[i] for q, values in peaks.items()}) for i, name in enumerate(names)},
        {name: Rms(**{q: values[i] for q, values in rms.items()}) for i, name in enumerate(names)},
    )


__all__ = [
    "DIRECTIONS",
    "DOFS",
    "POINT_CHUNK",
    "PeriodicMotion",
    "Peaks",
    "Rms",
    "motion_peaks",
    "peaks",
    "point_peaks",
    "point_rms",
    "point_series",
    "rotation_series",
    "theta_minus_sine",
    "relative_error",
    "rms_values",
    "located",
    "splice_harmonics",
    "superpose",
]
