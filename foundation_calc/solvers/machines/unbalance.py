"""A rotor's residual unbalance by its balance quality grade (ISO 21940-11, formerly ISO 1940-1).

The grade is G = e ω, so the rotating force is F = m_r e ω² = m_r G ω at the speed ω, turning
about the rotor's axis e in the positive sense (right-hand rule)::

    F(t) = F (a cos ωt + b sin ωt),    a ⊥ e,  b = e × a  (a right-handed pair)

two loads of order 1 a quarter period apart, both growing as ω² with the speed (the eccentricity
e = G/ω is the rotor's). The motor turns the unbalance's point mass about the shaft, m_r e².
"""

from __future__ import annotations

import math
from dataclasses import dataclass

from foundation_calc.solvers.machines.part import LoadRow, MachinePart, Number, Triple


def _cross(a, b) -> tuple[float, float, float]:
    return (a[1] * b[2] - a[2] * b[1], a[2] * b[0] - a[0] * b[2], a[0] * b[1] - a[1] * b[0])


def _unit(v) -> tuple[float, float, float]:
    n = math.hypot(*v)
    return tuple(c / n for c in v)


@dataclass(frozen=True)
class RotatingUnbalance(MachinePart):
    """A rotor's unbalance (module docstring).

    Attributes
    ----------
    rotor_mass : m_r [kg]
    grade_mm_s : G, e ω [mm/s] (as the standard names the grades)
    axis : the rotor's axis, any length (3,) [-]
    at : point on the axis where the unbalance acts, from O (3,) [m]
    """

    rotor_mass: float
    grade_mm_s: float
    axis: tuple
    at: tuple

    def pair(self) -> tuple[tuple, tuple, tuple]:
        """(e, a, b): the unit axis and the right-handed unit pair normal to it."""
        e = _unit(self.axis)
        trial = (1.0, 0.0, 0.0) if abs(e[0]) < 0.9 else (0.0, 1.0, 0.0)
        a = _unit(_cross(_cross(e, trial), e))
        return e, a, _cross(e, a)

    def force(self, omega: float) -> float:
        """F = m_r G ω [N] at the speed ω [rad/s]."""
        return self.rotor_mass * self.grade_mm_s * 1e-3 * omega

    def load_rows(self, omega: float, g: float) -> list[LoadRow]:
        """F a at phase 0 and F b at phase -π/2 (module docstring)."""
        _, a, b = self.pair()
        F = self.force(omega)
        return [LoadRow(1, tuple(F * c for c in a), [0.0, 0.0, 0.0], 0.0, self.at, True),
                LoadRow(1, tuple(F * c for c in b), [0.0, 0.0, 0.0], -math.pi / 2.0, self.at, True)]

    def carried_inertia(self, omega: float) -> float:
        """m_r e², e = G/ω [kg m²]."""
        return self.rotor_mass * (self.grade_mm_s * 1e-3 / omega) ** 2

    def assumption(self) -> str:
        """The sheet's phrase for an unbalance."""
        return "an unbalance from its balance grade, F = m_r G ω rotating normal to its axis"

    def sheet_text(self, omega: float) -> tuple:
        """F = m_r G ω substituted, the pair a, b and the point."""
        e, a, b = self.pair()
        F = math.hypot(*self.load_rows(omega, 0.0)[0].force)
        return ("unbalance F = m_r G ω = ", Number(self.rotor_mass), " kg × ", Number(self.grade_mm_s), " mm/s × ",
                Number(omega), " rad/s = ", Number(F), " N, turning about its axis e = ", Triple(e),
                " in the positive sense (right-hand rule): F(t) = F (a cos ωt + b sin ωt), a = ", Triple(a),
                ", b = e × a = ", Triple(b), ", acting at ", Triple(self.at), " m. In Q_n: F a at phase lag 0°,"
                " F b at 90°.")


__all__ = ["RotatingUnbalance"]
