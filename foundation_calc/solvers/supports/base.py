"""The interface every support gives (:class:`Support`) and the plain data it answers with.

Axes and coordinates as :mod:`foundation_calc.solvers.rigid_body`: q = (u_x, u_y, u_z, θ_x, θ_y,
θ_z) of O, the centre of the base at base level. A support gives, at any frequency ω [rad/s], the
springs K(ω) and dashpots C(ω) it puts between the ground and O (:class:`AtO`: six on the
diagonal, and the off-diagonal terms of a support that couples its motions, a pile group's
sway-rocking), whether they depend on ω, the range its model holds over (:class:`Validity`), and
what the documents show of it: its part of ``fcalc soil`` (:class:`SoilSection`), of the
sheet's soil section (:mod:`.sheet`), the assumptions it rests on (:class:`Assumption`: what
it models, coupled or not at O, frequency-dependent or not, by which sources) and what the sheet
does not check of it (:func:`not_checked`). Everything here is plain data: the output layer
renders it.

Sizing (``fcalc design``) asks a support the hooks of :class:`Sizing`, each optional: a support
that leaves one out takes its default (:func:`sizing`), so one without sizes of its own costs
nothing. The scene keys of a support's own sizes that a design may vary are declared once, as
:class:`Variable` (a shipped support's module lists them in ``VARIABLES``; any other hands them to
:func:`~foundation_calc.solvers.supports.register` with its builder), so that a range names them
before any scene is read; the support of a scene then gives its own values of them
(:attr:`Sizing.sizes`), the scene with the support at a batch of candidate values
(:meth:`Sizing.sized`), the concrete it adds (:meth:`Sizing.concrete`), the warnings of each
candidate's sizes and the errors for which ``fcalc check`` refuses a candidate's scene
(:meth:`Sizing.size_warnings`, :meth:`Sizing.size_errors`), and the scene keys it places under
the base that move with a resized plan (:meth:`Sizing.plan_changes`). Whether its springs scale with one factor
over the soil's modulus range is :attr:`Support.unscaled`.
"""

from __future__ import annotations

from dataclasses import dataclass, field
from typing import Protocol

import numpy as np

#: The six motions at O, in the order of q.
MOTIONS = ("x", "y", "z", "rx", "ry", "rz")


@dataclass(frozen=True)
class AtO:
    """Springs and dashpots at O at one or more frequencies.

    Attributes
    ----------
    springs : the six springs on the diagonal, shape (...) + (6,) [N/m, N m/rad]
    dashpots : the six dashpots on the diagonal, shape (...) + (6,) [N s/m, N m s/rad]
    coupling : (K_c, C_c), the off-diagonal springs and dashpots, (...) + (6, 6) each, zero on
        the diagonal [N/m, N, N m/rad; ...]; None for a support whose motions are uncoupled at O
    """

    springs: np.ndarray
    dashpots: np.ndarray
    coupling: tuple | None = None

    @property
    def K(self) -> np.ndarray:
        """The full 6 × 6 springs at O, (...) + (6, 6)."""
        return _full(self.springs, None if self.coupling is None else self.coupling[0])

    @property
    def C(self) -> np.ndarray:
        """The full 6 × 6 dashpots at O, (...) + (6, 6)."""
        return _full(self.dashpots, None if self.coupling is None else self.coupling[1])


def _full(diagonal, off):
    full = np.asarray(diagonal, dtype=float)[..., None] * np.eye(6)
    return full if off is None else full + off


@dataclass(frozen=True)
class Validity:
    """The range of the dimensionless frequency a0 = ω b/V_s a support's model holds over.

    Attributes
    ----------
    method : the name the soil model's check reports it by (``[soil] method``, or ``"piles"``)
    a0_max : largest a0 of the fit [-]; None when no range applies (frequency-independent springs)
    definition : how a0 is formed ("" when none applies)
    source : where the range comes from, or why none applies
    V_s : the soil's shear wave velocity [m/s] (None when no range applies)
    lengths : motion -> b [m] of a0 (x, y, z, rx, ry, rz)
    cutoffs : (H [m], ω_s, ω_c [rad/s]) of a stratum over bedrock, the frequencies below which
        the shear and the compression motions radiate nothing; None without one
    """

    method: str
    a0_max: float | None
    definition: str
    source: str
    V_s: float | None = None
    lengths: dict = field(default_factory=dict)
    cutoffs: tuple | None = None


@dataclass(frozen=True)
class FrequencyTable:
    """A table at several frequencies: one column per frequency (``heads``), rows (label, unit,
    values in that unit), ``digits`` significant figures."""

    title: str
    heads: tuple
    rows: tuple
    digits: int = 4


@dataclass(frozen=True)
class SoilSection:
    """A support's own part of ``fcalc soil``: the keys it adds to the JSON (SI), and what is
    printed after the springs' table (lines of text and :class:`FrequencyTable`, in order)."""

    document: dict
    printed: tuple = ()


@dataclass(frozen=True)
class Assumption:
    """One row of the sheet's assumptions a support states: ``topic`` (``"soil"``, or the support's
    own name such as ``"isolators"``: what its springs and dashpots model, by which sources, and
    whether they depend on frequency; ``"base"``: how they act at O, coupled or not, and what the
    model leaves out) and its ``text``."""

    topic: str
    text: str


class Support(Protocol):
    """What carries the body (module docstring); for sizing, optionally the hooks of :class:`Sizing`."""

    #: the support as the ``fcalc soil`` title names it (``"'gazetas'"``, ``"piles"``)
    label: str
    #: the soil method in force (``fcalc soil``'s JSON ``method``; the sheet's ``soil.method``)
    method: str

    @property
    def frequency_dependent(self) -> bool:
        """True when K and C change with frequency."""

    #: the support and why its springs do not scale with one factor on the soil's modulus, so that a
    #: sample of the soil's stiffness (one factor per draw), and a design's batch over the soil's
    #: modulus range, do not apply ("[piles]: the group's springs do not scale ..."); None when they do
    unscaled: str | None

    def impedance(self, omega) -> AtO:
        """Springs and dashpots at O at the frequencies ``omega`` [rad/s] (:class:`AtO`, shape
        omega.shape + (6,) for one body; a batch's leading axes first)."""

    def validity(self) -> Validity:
        """The range its model holds over."""

    def a0(self, omega) -> tuple:
        """(a0 at the frequencies ``omega`` [rad/s], or None when none applies; what a0 is) for the
        columns of ``fcalc soil``."""

    def soil_section(self, speeds) -> SoilSection:
        """Its own part of ``fcalc soil``; ``speeds``: machine -> its speed ω [rad/s]."""

    def assumptions(self) -> tuple[Assumption, ...]:
        """The rows of the sheet's assumptions it states (:class:`Assumption`)."""

    def sheet(self, model, orders) -> list:
        """Its part of the sheet's soil section (:mod:`.sheet`'s items): how its springs and
        dashpots at O are found; ``model``, the body's (its static M, K, C); ``orders``: (name, n,
        column head, ω [rad/s]) of every frequency the response and the modes took it at."""

    # Optional: def not_checked(self, limits) -> tuple[str, ...], what the sheet's "not checked"
    # row says of the support (:func:`not_checked`; without it, :data:`NOT_CHECKED`).
    # Optional: base_bears: bool, whether the base bears on the soil (:func:`bears_on_soil`; without it, True).
    # Optional: unsized: (scene key, why) when ``fcalc design`` cannot size a block on it (:func:`unsized`).


@dataclass(frozen=True)
class Variable:
    """A scene key a design may vary (``--vary KEY=LO:HI``): a size of a support, or a block's dimension.

    Attributes
    ----------
    key : the scene key, dotted as written (``"piles.length"``)
    text : what it is, as a message names it (``"pile length"``)
    where : the scenes that have it, as a message names them (``"a scene with [piles]"``)
    unit : its unit [SI]
    low, high : its bounds [unit]; None: the plausible range of the key
        (:data:`~foundation_calc.scenes.plausibility.KEYS`), what real foundations measure
    """

    key: str
    text: str
    where: str
    unit: str = "m"
    low: float | None = None
    high: float | None = None


@dataclass(frozen=True)
class SizeFindings:
    """What ``fcalc check`` finds of each of a batch of candidates' sizes: its warnings, or the
    errors for which it refuses the candidate's scene.

    Attributes
    ----------
    which : per candidate, 0 for none, else 1 + the index in ``reasons`` of the first that applies
    reasons : what each finds, without a candidate's numbers (so that candidates tally by it)
    keys : the scene keys whose plausibility findings these judge: a finding of a scene under one
        of them is the candidate's, not the scene's as given (warnings only)
    """

    which: np.ndarray
    reasons: tuple = ()
    keys: tuple = ()


class Sizing:
    """The sizing hooks of a support (module docstring) and their defaults: a support with no
    sizes a design may vary, that adds no concrete and warns of nothing of its own."""

    @property
    def sizes(self) -> dict:
        """Scene key -> the scene's value [the key's unit] of each of its sizes a design may vary."""
        return {}

    def sized(self, scene, values):
        """The scene with its support at candidate ``values`` (key -> (N,) of :attr:`sizes`' keys,
        those not given the scene's): its support built from it (``scene.support(...)``) is then
        the candidates' batch."""
        return scene

    def concrete(self, values=None):
        """The concrete volume it adds [m³] at ``values`` (as :meth:`sized`; None or a key left out:
        the scene's), (N,) or a float."""
        return 0.0

    def size_warnings(self, values, L, B) -> SizeFindings:
        """The warnings of candidates ``values`` (as :meth:`sized`) on bases L × B [m] ((N,) each)."""
        return SizeFindings(np.zeros(np.shape(L), dtype=int))

    def size_errors(self, values, L, B) -> SizeFindings:
        """The candidates (as :meth:`size_warnings`) whose scene ``fcalc check`` refuses for their
        sizes (a pile group whose piles overlap): ``reasons`` the same for every batch of a scene."""
        return SizeFindings(np.zeros(np.shape(L), dtype=int))

    def plan_changes(self, old, new) -> dict:
        """Scene key -> its new value, of what it places under the base when the plan (L, B) [m]
        changes from ``old`` to ``new`` (a design's written scene)."""
        return {}


#: The hooks of :class:`Sizing`, by name.
SIZING_HOOKS = ("sizes", "sized", "concrete", "size_warnings", "size_errors", "plan_changes")


def sizing(support):
    """The sizing hooks of ``support``: its own, and :class:`Sizing`'s defaults for those it leaves out."""
    if isinstance(support, Sizing):
        return support
    from types import SimpleNamespace

    default = Sizing()
    return SimpleNamespace(**{name: getattr(support, name, getattr(default, name)) for name in SIZING_HOOKS})


#: What the sheet says is not checked of a support that does not say it itself.
NOT_CHECKED = ("the support's static capacity and settlement, and the dynamic forces in it",)


def not_checked(support, limits) -> tuple[str, ...]:
    """What is not checked of ``support`` under the scene's ``limits`` (its ``[limits]``), phrases
    in lower case for the sheet's "not checked" row: its own ``not_checked(limits)`` (each support
    names its own terms: the footing's static bearing pressure and settlement W/K_z, the piles'
    capacity and strength), or :data:`NOT_CHECKED` for a support without one."""
    own = getattr(support, "not_checked", None)
    return NOT_CHECKED if own is None else tuple(own(limits))


def bears_on_soil(support) -> bool:
    """Whether the base of ``support`` bears on the soil, so that a static pressure under it means
    something (the office check's bearing pressure): its own ``base_bears`` (a footing: True; a pile
    group: its ``piles.cap_contact``), or True for a support without one."""
    return bool(getattr(support, "base_bears", True))


def unsized(support) -> tuple[str, str] | None:
    """(the scene key that names it, why) when ``fcalc design`` cannot size a block on ``support``
    (its own ``unsized``: the isolators, whose places and springs a resized block does not carry
    along), else None."""
    return getattr(support, "unsized", None)


__all__ = ["MOTIONS", "NOT_CHECKED", "SIZING_HOOKS", "Assumption", "AtO", "FrequencyTable", "SizeFindings", "Sizing",
           "SoilSection", "Support", "Validity", "Variable", "bears_on_soil", "not_checked", "sizing", "unsized"]
