"""Given loads of a machine (the vendor's data sheet): harmonics of fixed amplitude at multiples
of the machine's speed, each a force and a moment at a point, F cos(n ω t + φ).

They keep the amplitudes the vendor gives when the speed changes (not ``inertial``): the vendor's
loads hold at the machine's speed only.
"""

from __future__ import annotations

from dataclasses import dataclass

from foundation_calc.solvers.machines.part import LoadRow, MachinePart


@dataclass(frozen=True)
class GivenLoads(MachinePart):
    """A machine's given loads.

    Attributes
    ----------
    loads : (order n [-], force (3,) [N], moment (3,) [N m] about axes through the point, phase [rad],
        point from O (3,) [m]) each
    """

    loads: tuple

    def load_rows(self, omega: float, g: float) -> list[LoadRow]:
        """The loads as given, at any speed (module docstring)."""
        return [LoadRow(n, F, M, phase, at, False) for n, F, M, phase, at in self.loads]

    def assumption(self) -> str:
        """The sheet's phrase for given loads."""
        return "the vendor's loads as given, harmonic orders n at nω (amplitude, phase, point)"


__all__ = ["GivenLoads"]
