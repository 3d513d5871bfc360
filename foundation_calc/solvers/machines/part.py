"""The one interface of a machine's parts on a rigid body (each part gives its own matrices, as
the elements of a rotor do in ROSS [1]_): given loads, an unbalance, crank mechanisms, ...

A machine is its frame (mass, centre of mass, inertia: the scene's) and its parts, all turning or
acting at the machine's speed ω. Each part gives, about the body's reference point O (axes and
coordinates of :mod:`foundation_calc.solvers.rigid_body`):

- its time-averaged mass properties (:meth:`MachinePart.mass_properties`), added to the body's
  mass matrix as one more body (None: the part adds no mass);
- its periodic inertia M(φ), D(φ), S(φ), φ = ωt, sampled over one revolution
  (:meth:`MachinePart.periodic_inertia`; only parts with :attr:`MachinePart.periodic`), which the
  exact periodic solution takes (:mod:`foundation_calc.solvers.block.periodic_inertia`), and
  the mean of its D(φ) over a revolution, the part's mean gyroscopic coupling D̄
  (:meth:`MachinePart.gyroscopic`), which the block's averaged operator keeps in its C as it keeps
  the mean mass in M;
- its forcing harmonics at the speed as loads at points (:meth:`MachinePart.load_rows`, each
  :class:`LoadRow`), which :func:`~foundation_calc.solvers.block.model.excitation` carries to O
  as Q_n, the rows whose amplitude grows as ω² marked ``inertial``, those of the moving weight
  (which no speed changes) marked ``weight``;
- the rotating inertia the machine's motor turns besides its own (:meth:`MachinePart.carried_inertia`);
- its derivation for the calculation sheet as plain data (:meth:`MachinePart.sheet_text`): text
  and numbers (:class:`Number`, :class:`Triple`) that the sheet formats, and the phrase of the
  sheet's assumptions that says how its kind forces the body (:meth:`MachinePart.assumption`).

The checks, the sheets and the solvers see only this interface: a new kind of part is one module
that subclasses :class:`MachinePart`, and the scene's builder of it.

References
----------
.. [1] ROSS, rotordynamic open-source software, petrobras/ross: elements (shaft, disk, bearing)
   each give their own mass, stiffness and damping matrices, the rotor assembles them.
"""

from __future__ import annotations

from dataclasses import dataclass
from typing import ClassVar, NamedTuple

import numpy as np


#: Phases per revolution on which :meth:`MachinePart.gyroscopic` averages D(φ).
GYROSCOPIC_SAMPLES = 64


class LoadRow(NamedTuple):
    """One harmonic load of order n at the machine's speed ω: force F and moment M (about axes
    through ``at``), each component amplitude · cos(n ω t + phase).

    Attributes
    ----------
    order : n [-]
    force : F (3,) [N]
    moment : M (3,) [N m]
    phase : φ [rad]
    at : point of application from O (3,) [m]
    inertial : the amplitude grows as ω² when the speed changes (an unbalance's, a mechanism's
        inertia forces); given loads keep theirs
    weight : the moment of the moving weight (a crank mechanism's rods and sliders, an exciter's
        rotor): independent of the speed in every command, a sweep's and a start-up's alike, where
        a start-up takes the vendor's given loads as the inertia forces they stand for
    """

    order: int
    force: object
    moment: object
    phase: float
    at: object
    inertial: bool
    weight: bool = False


@dataclass(frozen=True)
class Number:
    """A number on the sheet, to ``digits`` significant figures, in the unit its text names."""

    value: float
    digits: int = 4


@dataclass(frozen=True)
class Triple:
    """Three components on the sheet, (x, y, z), 4 significant figures each."""

    values: tuple[float, float, float]


class MachinePart:
    """One part of a machine (module docstring). Subclasses give :meth:`load_rows` and what else
    they have; the defaults are a part without mass, periodic inertia, carried inertia or text."""

    #: True when the part has an angle-dependent inertia (:meth:`periodic_inertia`)
    periodic: ClassVar[bool] = False

    def mass_properties(self) -> tuple[float, np.ndarray, np.ndarray] | None:
        """Time-averaged mass [kg], centre of mass from O (3,) [m], central inertia tensor (3, 3)
        [kg m²]; None for a part without mass."""
        return None

    def periodic_inertia(self, omega: float, g: float, N: int) -> tuple[np.ndarray, np.ndarray, np.ndarray] | None:
        """M(φ_j), D(φ_j), S(φ_j) (N, 6, 6) at the N phases φ_j = 2πj/N of one revolution at speed
        ω [rad/s], gravity g [m/s²] (means included); None without periodic inertia."""
        return None

    def gyroscopic(self, omega: float) -> np.ndarray | None:
        """D̄, the mean over a revolution of the part's D(φ) at speed ω [rad/s] (:meth:`periodic_inertia`),
        (6, 6) [kg/s, kg m/s; kg m/s, kg m²/s]; None without periodic inertia. D(φ) does not depend on
        gravity; its mean is taken on :data:`GYROSCOPIC_SAMPLES` phases, exact for a D(φ) whose
        Fourier series ends below that order (an exciter's ends at 2; a crank mechanism takes its
        own sampling). D̄ is skew-symmetric, -[h]× in the rotations, h the part's mean angular
        momentum relative to the body (it grows as ω, and a shift of the part along the body leaves it).

        >>> MachinePart().gyroscopic(10.0) is None
        True
        """
        if not self.periodic:
            return None
        return self.periodic_inertia(omega, 0.0, GYROSCOPIC_SAMPLES)[1].mean(axis=0)

    def load_rows(self, omega: float, g: float) -> list[LoadRow]:
        """The part's forcing at speed ω [rad/s], gravity g [m/s²], as loads at points."""
        raise NotImplementedError

    def carried_inertia(self, omega: float) -> float:
        """Moment of inertia the machine's motor turns with this part at speed ω [kg m²]."""
        return 0.0

    def sheet_text(self, omega: float) -> tuple | None:
        """The part's derivation on the calculation sheet at speed ω: strings, :class:`Number`
        and :class:`Triple` in reading order (the sheet puts the machine's name before it); None
        when the loads' table says all."""
        return None

    def assumption(self) -> str | None:
        """How the sheet's assumptions say this kind of part forces the body (one phrase, the
        same for every part of the kind); None when it says nothing of its own."""
        return None


__all__ = ["GYROSCOPIC_SAMPLES", "LoadRow", "MachinePart", "Number", "Triple"]
