"""Isolators under a rigid body (paper 001's vibro-table, Bolotnik et al. [1]_): at each point r_i
three linear springs c_i1, c_i2, c_i3 along the fixed x, y, z axes, with a hysteretic loss factor η
and viscous dashpots β c_ij in parallel, as a :class:`~.base.Support`.

Points and axes are the body's (:mod:`foundation_calc.solvers.rigid_body`), from its reference
point O. The platform's O is its corner O1 (the paper's origin: r_1 = (0, 0, 0),
r_2 = (A, 0, 0), r_3 = (A, B, 0), r_4 = (0, B, 0)), not a block's centre of the base: the
interface's "at O" means at the body's reference point, whichever it is. Carried to O
(:func:`~foundation_calc.solvers.rigid_body.kinematics.springs_at`, the paper's potential (1.2))::

    K = Σ_i T_iᵀ diag(c_i1, c_i2, c_i3) T_i,   T_i = [I, -[r_i]×]                            (1)

6 × 6 and coupled (sway-rocking u_x-θ_y, u_y-θ_x and torsion with sway, from the points' offsets).
The loss factor makes the springs complex at a frequency Ω, K (1 + iη sgn Ω); with the dashpots
the force of the isolators is (K + i (η sgn Ω + β Ω) K) q (:func:`loss`). As springs and dashpots
at O (:meth:`Isolators.impedance`) that is K and the equivalent dashpots

    C(Ω) = (β + η/|Ω|) K       (Ω ≠ 0;  C = β K at Ω = 0, where a hysteretic force vanishes)     (2)

frequency dependent through η alone; iΩ C(Ω) is the exact complex part at every Ω. The
platform's harmonic balance keeps the complex-stiffness form
(:meth:`~foundation_calc.solvers.platform.dynamics.PeriodicSystem.dynamic_matrices`), which has no
time-domain form: the run-up takes η as modal damping (:mod:`foundation_calc.solvers.platform.runup`).

No range of validity applies: linear springs with a constant loss factor, no soil.

Under a body's weight W acting at its centre of mass r_G, the static motion of O is q = K⁻¹ F_W,
F_W = (0, 0, -W, -W y_G, W x_G, 0), and each isolator's vertical deflection δ_i = -(T_i q)_z
(:func:`static_deflections`; its load k_i3 δ_i). A block scene's ``[[isolators]]``
(:func:`build`) stand at points from the block's O, the centre of its base, and carry its weight:
``fcalc soil`` and the sheet list each one's deflection and load; the base bears on no soil.

References
----------
.. [1] N.N. Bolotnik, B.V. Gusev, Nguyen Truong, I.E. Kholmin, F.L. Chernousko, "Calculation of
   the parameters of a vibration mechanism with unbalanced vibration exciters", Izv. AN SSSR,
   MTT, 1986, Eq. (1.2).
"""

from __future__ import annotations

from dataclasses import dataclass

import numpy as np

from foundation_calc.solvers.rigid_body.kinematics import load_at, point_maps, springs_at
from foundation_calc.solvers.supports.base import Assumption, AtO, FrequencyTable, SoilSection, Validity
from foundation_calc.solvers.supports.sheet import Grid, Text

#: Why no range of validity applies.
NO_RANGE = "linear isolator springs with a constant loss factor: no range of frequency applies"


def loss(eta, beta, omega) -> np.ndarray:
    """η sgn Ω + β Ω, the isolators' complex part over K at the frequencies Ω [rad/s] (module
    docstring); η [-], β [s] broadcast with Ω.

    >>> loss(0.02, 0.001, np.array([-100.0, 0.0, 100.0])).round(12).tolist()
    [-0.12, 0.0, 0.12]
    """
    omega = np.asarray(omega, dtype=float)
    return eta * np.sign(omega) + beta * omega


def static_deflections(points, stiffness, W, cog) -> np.ndarray:
    """δ_i = -(T_i K⁻¹ F_W)_z, each isolator's vertical deflection [m] (positive: compressed) under
    the weight W [N] at the centre of mass ``cog`` [m] from O (module docstring); ``points`` r_i
    (n, 3) [m] and ``stiffness`` c_ij (n, 3) [N/m] as :class:`Isolators`' (K regular).

    >>> square = [[-1.0, -1.0, 0.0], [1.0, -1.0, 0.0], [1.0, 1.0, 0.0], [-1.0, 1.0, 0.0]]
    >>> (static_deflections(square, [[1e5, 1e5, 2e5]] * 4, 8e3, [0.0, 0.0, 0.5]) * 1e3).round(6).tolist()
    [10.0, 10.0, 10.0, 10.0]
    """
    q = np.linalg.solve(springs_at(points, stiffness), load_at(cog, np.array([0.0, 0.0, -W]), np.zeros(3)))
    return -(point_maps(points) @ q)[:, 2]


@dataclass(frozen=True, eq=False)  # arrays: compared and hashed by identity
class Isolators:
    """Three-spring isolators at points of the body (module docstring), SI units.

    Attributes
    ----------
    points : r_i from O, (n, 3) [m]
    stiffness : c_ij, (n, 3), columns along x, y, z [N/m]
    eta : hysteretic loss factor η [-]
    beta : time constant β of the dashpots β c_ij [s]
    weight : (W [N], r_G (3,) [m] from O) of the body they carry, for the isolators' static
        deflections and loads (:func:`static_deflections`); None: not listed
    """

    points: np.ndarray
    stiffness: np.ndarray
    eta: float
    beta: float
    weight: tuple | None = None

    label = "isolators"
    method = "isolators"
    unscaled = "[[isolators]]: their springs are the rates a catalogue gives, not a soil's modulus to scale"
    #: the base stands on the isolators, not on soil: no bearing pressure (:func:`~.base.bears_on_soil`)
    base_bears = False
    #: why ``fcalc design`` does not size a block on them (:func:`~.base.unsized`)
    unsized = ("isolators", "a block on [[isolators]] is not sized by fcalc design: the isolators' places and springs"
               " are chosen with the block (a catalogue's series under its weight), not carried along by a resized"
               " one; check each trial block with fcalc check")

    @property
    def springs(self) -> np.ndarray:
        """K of (1), 6 × 6 [N/m, N/rad, N m/rad]."""
        return springs_at(self.points, self.stiffness)

    @property
    def frequency_dependent(self) -> bool:
        """True with a loss factor: its equivalent dashpots (2) fall as 1/|Ω|."""
        return self.eta > 0.0

    def impedance(self, omega) -> AtO:
        """K and C(Ω) of (1), (2) at the frequencies ``omega`` [rad/s], shape omega.shape + (6,)
        on the diagonal and (6, 6) off it (coupled)."""
        w = np.asarray(omega, dtype=float)
        safe = np.where(w == 0.0, 1.0, w)
        factor = np.where(w == 0.0, self.beta, loss(self.eta, self.beta, w) / safe)[..., None, None]
        K = np.broadcast_to(self.springs, w.shape + (6, 6))
        C = factor * K
        off = 1.0 - np.eye(6)
        return AtO(np.diagonal(K, axis1=-2, axis2=-1).copy(), np.diagonal(C, axis1=-2, axis2=-1).copy(),
                   (K * off, C * off))

    def validity(self) -> Validity:
        """None applies (:data:`NO_RANGE`)."""
        return Validity(self.method, None, "", NO_RANGE)

    def a0(self, omega) -> tuple:
        """No a0: the isolators are not a soil."""
        return None, "no a0: the isolators are springs, not a soil"

    def static(self) -> tuple | None:
        """(δ_i [m], k_i3 δ_i [N]) of every isolator under :attr:`weight` (:func:`static_deflections`), or None."""
        if self.weight is None:
            return None
        k = np.asarray(self.stiffness, dtype=float)
        delta = static_deflections(self.points, k, *self.weight)
        return delta, k[:, 2] * delta

    def soil_section(self, speeds) -> SoilSection:
        """The springs and the damping as data; with :attr:`weight`, each isolator's static
        deflection and load, also printed as a table (one column per isolator)."""
        document = {"points": np.asarray(self.points).tolist(), "stiffness": np.asarray(self.stiffness).tolist(),
                    "loss_factor": self.eta, "dashpot_time_constant": self.beta}
        if (static := self.static()) is None:
            return SoilSection({"isolators": document})
        delta, load = static
        document |= {"static_deflection": delta.tolist(), "static_load": load.tolist()}
        r, k = np.asarray(self.points, dtype=float), np.asarray(self.stiffness, dtype=float)
        rows = tuple((f"{axis}", "m", r[:, j].tolist()) for j, axis in enumerate("xyz"))
        rows += tuple((f"k_{axis}", "MN/m", (k[:, j] * 1e-6).tolist()) for j, axis in enumerate("xyz"))
        rows += (("δ_static", "mm", (delta * 1e3).tolist()), ("load", "kN", (load * 1e-3).tolist()))
        table = FrequencyTable(f"Isolators: {len(r)} under the block, at r_i from O; static deflection and load under"
                               f" the weight {self.weight[0] * 1e-3:.4g} kN", tuple(str(i + 1) for i in range(len(r))),
                               rows, 4)
        return SoilSection({"isolators": document}, (table, self.damping_text()))

    def damping_text(self) -> str:
        """The damping of the isolators in one line."""
        return (f"Damping: loss factor η = {self.eta:g} (C = η K/|Ω| at a frequency Ω), dashpots β = {self.beta:g} s"
                " (C = β K); K at O = Σ T_iᵀ diag(k_i) T_i, coupled [BC] (1.2).")

    def not_checked(self, limits) -> tuple[str, ...]:
        """The isolators' own terms, which no check judges."""
        return ("the isolators' rated load and travel against their static deflection and dynamic motion, their"
                " surge (coil resonance) and the floor or frame under them",)

    def assumptions(self) -> tuple[Assumption, ...]:
        """What the isolators model and how they act at O."""
        damping = []
        if self.eta > 0.0:
            damping.append(f"a hysteretic loss factor η = {self.eta:g} (complex springs K (1 + iη sgn Ω); as dashpots"
                           " at a frequency Ω, C = η K/|Ω|)")
        if self.beta > 0.0:
            damping.append(f"viscous dashpots β c_ij in parallel with the springs, β = {self.beta:.4g} s")
        return (Assumption("isolators", f"{len(self.points)} isolators, each three linear springs c_i1, c_i2, c_i3 along the"
                                   " fixed x, y, z axes at its point [BC] (1.2); "
                                   + ("; ".join(damping) if damping else "no damping") + "."),
                Assumption("base", "The springs act together at the reference point O (a platform's: its corner O1)"
                                   " as K = Σ T_iᵀ diag(c_i) T_i, coupled (sway with rocking and torsion through the"
                                   " points' offsets); linear, without lift-off; the ground beneath the isolators is"
                                   " rigid."))

    def sheet(self, model, orders) -> list:
        """The twelve springs as a table, with :attr:`weight` each isolator's static deflection and
        load, and K at O by (1)."""
        names = tuple(f"r_{i + 1} = ({p[0]:g}, {p[1]:g}, {p[2]:g}) m" for i, p in enumerate(np.asarray(self.points)))
        heads, values = ("isolator", "c_i1 (x)", "c_i2 (y)", "c_i3 (z)"), np.asarray(self.stiffness) * 1e-6
        if (static := self.static()) is not None:
            heads, values = heads + ("δ_i [mm]", "load [kN]"), np.column_stack([values, static[0] * 1e3, static[1] * 1e-3])
        return [Grid("Isolator springs [MN/m]", heads, names, values),
                Text("K at O = Σ_i T_iᵀ diag(c_i1, c_i2, c_i3) T_i, T_i = [I, -[r_i]×] [BC] (1.2): coupled; "
                     + ("C(Ω) = (β + η/|Ω|) K." if self.eta > 0.0 else "C = β K."))]


def build(scene, L, B, masses):
    """A block scene with ``[[isolators]]`` stands on them, its points from the block's O, carrying
    the scene's whole weight at its centre of mass (the scene's :meth:`isolated_weight`)."""
    if getattr(scene, "isolation", None) is None:  # given with [[isolators]] alone
        return None
    r = np.array([i.position for i in scene.isolators], dtype=float)
    k = np.array([i.stiffness for i in scene.isolators], dtype=float)
    return Isolators(r, k, scene.isolation.eta, scene.isolation.time_constant, scene.isolated_weight())


__all__ = ["NO_RANGE", "Isolators", "build", "loss", "static_deflections"]
