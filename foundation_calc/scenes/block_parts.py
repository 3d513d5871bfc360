"""Parts of a ``block_foundation`` scene: the block, its machines and their loads, its points.

Axes (docs/block-foundation.md): origin O at the centre of the block's base, at base level;
x along the block's length, y along its width, z up. Rotations are right-handed about x, y, z.
"""

from __future__ import annotations

import math

from functools import cached_property
from typing import Annotated, ClassVar

from pydantic import Field, field_validator, model_validator

from foundation_calc.scenes.common import Drive, SceneModel, SpeedFields, quantity, source

#: Three components along (or about) x, y, z.
Vector = Annotated[list[float], Field(min_length=3, max_length=3)]


class BlockBody(SceneModel):
    """The foundation block: base length and width, and height with density or its mass properties.

    Height and density describe a homogeneous rectangular block standing on its base; mass, cog
    and inertia any other block (with pedestals, pits or openings)."""

    length: float = quantity("L", "m", "block length along x (the base's length)", gt=0, examples=[6.0])
    width: float = quantity("B", "m", "block width along y (the base's width)", gt=0, examples=[4.0])
    height: float | None = quantity("H", "m", "block height (with density)", None, gt=0, examples=[2.0])
    density: float | None = quantity(
        "ρ_c", "kg/m³", "density of the block's material, reinforced concrete about 2400-2500 (with height)",
        None, gt=0, examples=[2400.0],
    )
    mass: float | None = quantity("m_b", "kg", "block mass (instead of height and density)", None, gt=0, examples=[1.15e5])
    cog: Vector | None = quantity(
        "r_b", "m", "block's centre of mass [x, y, z] from O (with mass)", None, examples=[[0.0, 0.0, 1.0]]
    )
    inertia: Vector | None = quantity(
        "J_b", "kg m²", "block's moments of inertia [Ixx, Iyy, Izz] about its centre of mass, axes along x, y, z"
        " (with mass)", None, examples=[[1.9e5, 3.8e5, 5.0e5]],
    )
    embedment: float | None = quantity(
        "D", "m", "depth of the base below the ground surface, sidewalls in contact (soil methods 'gazetas' and"
        " 'pais_kausel', as a crank foundation's); default 0, a surface footing", None, ge=0, examples=[1.0],
    )

    @model_validator(mode="after")
    def _one_description(self):
        solid = self.height is not None or self.density is not None
        given = self.mass is not None or self.cog is not None or self.inertia is not None
        if solid == given:
            raise ValueError(
                "give the block as height [m] and density [kg/m³], or by mass [kg], cog [m] and inertia [kg m²]"
                + (" (not both)" if solid else "")
            )
        units = {"height": "m", "density": "kg/m³"} if solid else {"mass": "kg", "cog": "m", "inertia": "kg m²"}
        missing = [f"block.{k} [{unit}]" for k, unit in units.items() if getattr(self, k) is None]
        if missing:
            keys = [f"{k} [{unit}]" for k, unit in units.items()]
            how = "as a solid" if solid else "by its mass properties"
            raise ValueError(f"{' and '.join(missing)} missing: a block given {how} needs {', '.join(keys[:-1])}"
                             f" and {keys[-1]}")
        if self.inertia is not None and any(j < 0 for j in self.inertia):
            raise ValueError(f"block.inertia must be >= 0 kg m² each (got {list(self.inertia)})")
        if self.embedment and self.height is not None and self.embedment > self.height:
            raise ValueError(f"block.embedment = {self.embedment:g} m must not exceed block.height = {self.height:g} m"
                             " (the sidewalls in contact are the block's)")
        return self

    @property
    def mass_properties(self) -> tuple[float, Vector, Vector]:
        """(mass [kg], centre of mass from O [m], central moments [kg m²])."""
        if self.mass is not None:
            return self.mass, self.cog, self.inertia
        from foundation_calc.solvers.rigid_body.inertia import block_inertia

        m = self.length * self.width * self.height * self.density
        return m, (0.0, 0.0, self.height / 2.0), block_inertia(m, self.length, self.width, self.height)


class MachineLoad(SceneModel):
    """A harmonic load of a machine on the block (vendor data), each component amplitude · cos(n ω t + φ)."""

    name: str = quantity("-", "-", "label shown in reports", "", max_length=80, examples=["1st order"])
    order: int = quantity("n", "-", "multiple of the machine's speed: 1 at the speed, 2 at twice it, ...", ge=1, le=64, examples=[1])
    force: Vector = quantity("F", "N", "force amplitudes along x, y, z", [0.0, 0.0, 0.0], examples=[[6.0e3, 0.0, 2.0e3]])
    moment: Vector = quantity(
        "M", "N m", "moment amplitudes about axes through `at`, along x, y, z", [0.0, 0.0, 0.0], examples=[[0.0, 0.0, 0.0]]
    )
    phase: float = quantity("φ", "rad", "phase at t = 0", 0.0, examples=[0.0])
    at: Vector | None = quantity(
        "r_F", "m", "point of application [x, y, z] from O; default the machine's centre of mass", None,
        examples=[[0.8, 0.0, 3.0]],
    )

    @model_validator(mode="after")
    def _something_acts(self):
        if not any(self.force) and not any(self.moment):
            raise ValueError("give a non-zero force [N] or moment [N m] (all components are 0)")
        return self


class Unbalance(SceneModel):
    """A rotor's residual unbalance by its balance quality grade (ISO 21940-11, formerly ISO 1940-1).

    e ω = G, so the rotating force is m_r e ω² = m_r G ω at the machine's speed."""

    balance_grade_mm_s: float = quantity(
        "G", "mm/s", "balance quality grade, e·ω (G 6.3: 6.3; G 2.5: 2.5)", gt=0, le=4000, examples=[6.3]
    )
    rotor_mass: float = quantity("m_r", "kg", "mass of the rotor", gt=0, examples=[800.0])
    axis: Vector = quantity("e", "-", "direction of the rotor's axis (need not be a unit vector)", examples=[[1.0, 0.0, 0.0]])
    at: Vector | None = quantity(
        "r_r", "m", "point on the axis where the unbalance acts; default the machine's centre of mass", None,
        examples=[[-1.5, 0.0, 2.6]],
    )

    @model_validator(mode="after")
    def _axis_has_a_direction(self):
        if math.hypot(*self.axis) == 0.0:
            raise ValueError("unbalance.axis must not be [0, 0, 0]: give the rotor's axis direction, e.g. [1, 0, 0]")
        return self


class MachineCrank(SceneModel):
    """One throw (cylinder) of a crank machine: Krichever & Makarov's crank-slider mechanism placed
    anywhere on the block (solvers.machines.crank_mechanism). The crank turns at the machine's
    speed by the right-hand rule about ``shaft_axis``; the parts that do not move (frame, motor,
    cylinders) are the machine's mass, cog and inertia."""

    crank_centre: Vector = quantity("A", "m", "a point on the crankshaft axis [x, y, z] from O, in the throw's plane",
                                    examples=[[0.0, -0.4, 3.0]])
    shaft_axis: Vector = quantity("n", "-", "crankshaft direction (need not be a unit vector); the crank turns by the"
                                  " right-hand rule about it", examples=[[0.0, 1.0, 0.0]])
    slider_axis: Vector = quantity("s", "-", "direction from the crank centre along the slider's line towards the"
                                   " slider, normal to shaft_axis (need not be a unit vector)", examples=[[0.0, 0.0, 1.0]])
    crank_angle: float = quantity("α", "rad", "the throw's crank angle at t = 0 from its own top dead centre (pin towards"
                                  " its own slider), positive about shaft_axis", 0.0, examples=[0.0])
    crank_radius: float = quantity("r", "m", "crank radius (half the stroke)", gt=0, examples=[0.11])
    rod_length: float = quantity("l", "m", "connecting rod length, crank pin to slider pin (> crank_radius)", gt=0,
                                 examples=[0.5])
    rod_mass: float = quantity("m", "kg", "connecting rod mass", ge=0, examples=[65.0])
    rod_cog_to_crank_pin: float = quantity("l'", "m", "distance from the rod's centre of mass to the crank pin"
                                           " (0 ... rod_length)", ge=0, examples=[0.15])
    rod_radius_of_gyration: float = quantity(
        "ρ", "m", "rod's radius of gyration about every axis through its centre of mass normal to it (slender: none"
        " about its length)", ge=0, examples=[0.17],
    )
    slider_mass: float = quantity("m1", "kg", "mass moving with the slider (piston, piston rod, crosshead)", 0.0, ge=0,
                                  examples=[140.0])
    rotating_mass: float = quantity("m_r", "kg", "the crank's and counterweight's net unbalance (with rotating_radius)",
                                    0.0, ge=0, examples=[0.0])
    rotating_radius: float = quantity("r_r", "m", "radius of the net unbalance from the shaft axis", 0.0, ge=0,
                                      examples=[0.0])
    rotating_angle: float = quantity("β", "rad", "angle of the net unbalance from the crank pin, positive about"
                                     " shaft_axis (a counterweight opposite the pin: π)", 0.0, examples=[0.0])

    @model_validator(mode="after")
    def _a_mechanism(self):
        from foundation_calc.solvers.machines.crank_mechanism import PERPENDICULAR

        n, s = self.shaft_axis, self.slider_axis
        for key, v in (("shaft_axis", n), ("slider_axis", s)):
            if math.hypot(*v) == 0.0:
                raise ValueError(f"{key} must not be [0, 0, 0]: give a direction, e.g. [0, 1, 0]")
        cos = sum(a * b for a, b in zip(n, s)) / (math.hypot(*n) * math.hypot(*s))
        if abs(cos) > PERPENDICULAR:
            raise ValueError(f"slider_axis {list(s)} must be normal to shaft_axis {list(n)} (their angle is"
                             f" {math.degrees(math.acos(max(-1.0, min(1.0, cos)))):.4g}°, wanted 90°)")
        if not self.rod_length > self.crank_radius:
            raise ValueError(f"rod_length l = {self.rod_length:g} m must exceed crank_radius r = {self.crank_radius:g} m"
                             " (the rod could not follow the crank)")
        if self.rod_cog_to_crank_pin > self.rod_length:
            raise ValueError(f"rod_cog_to_crank_pin l' = {self.rod_cog_to_crank_pin:g} m must lie on the rod"
                             f" (0 ... rod_length = {self.rod_length:g} m)")
        if (self.rotating_mass > 0.0) != (self.rotating_radius > 0.0):
            raise ValueError("give rotating_mass [kg] and rotating_radius [m] together (or neither)")
        if self.rod_mass + self.slider_mass + self.rotating_mass == 0.0:
            raise ValueError("the throw has no moving mass: give rod_mass, slider_mass or rotating_mass [kg]")
        return self

    def throw(self):
        """The solver's :class:`~foundation_calc.solvers.machines.crank_mechanism.CrankThrow`."""
        from foundation_calc.solvers.machines.crank_mechanism import crank_throw

        return crank_throw(self.crank_centre, self.shaft_axis, self.slider_axis, self.crank_angle, self.crank_radius,
                           self.rod_length, self.rod_mass, self.rod_cog_to_crank_pin, self.rod_radius_of_gyration,
                           self.slider_mass, self.rotating_mass, self.rotating_radius, self.rotating_angle)


class MachineExciter(SceneModel):
    """One rotor of an unbalanced vibration exciter: a point mass off its axis, turning at the machine's speed.

    Paper 001's single-shaft exciter (Bolotnik et al., :mod:`~foundation_calc.solvers.machines.exciter`).
    A two-shaft directional exciter is two tables on parallel axes with opposite ``sense``: their
    forces add along the line where both rotors stand at t = 0 and cancel across it."""

    rotor_mass: float = quantity("m", "kg", "mass of the rotor's unbalanced part (its eccentric mass)", gt=0,
                                 examples=[25.0])
    eccentricity: float = quantity("l", "m", "distance from the axis to the rotor's centre of mass", gt=0,
                                   examples=[0.05])
    axis: Vector = quantity(
        "e", "-", "direction of the rotor's axis (need not be a unit vector); paper 001's angles are"
        " e/|e| = (cos δ1 sin δ2, sin δ1 sin δ2, cos δ2)", examples=[[0.0, 1.0, 0.0]],
    )
    at: Vector | None = quantity(
        "ρ", "m", "a point of the rotor's axis [x, y, z] from O; default the machine's centre of mass", None,
        examples=[[0.0, 0.3, 1.2]],
    )
    sense: float = quantity("σ", "-", "+1: the rotor turns positively about axis (right-hand rule), -1: against it",
                            1.0, examples=[-1])
    phase: float = quantity(
        "φ0", "rad", "the rotor's angle at t = 0 about axis from t1, towards t2 = e × t1 (t1 horizontal, normal to"
        " axis: e × z/|e × z|, or -y for a vertical axis)", 0.0, examples=[0.0],
    )

    @field_validator("axis")
    @classmethod
    def _axis_has_a_direction(cls, axis: list[float]) -> list[float]:
        if math.hypot(*axis) == 0.0:
            raise ValueError("must not be [0, 0, 0]: give the rotor's axis direction, e.g. [0, 1, 0] (shaft along y)")
        return axis

    @field_validator("sense")
    @classmethod
    def _one_of_two_senses(cls, sense: float) -> float:
        if sense not in (1.0, -1.0):
            raise ValueError("must be +1 (turning positively about axis, right-hand rule) or -1 (against it)")
        return sense

    def part(self, cog):
        """The solver's :class:`~foundation_calc.solvers.machines.exciter.UnbalancedExciter`, its axis
        through ``at`` or else ``cog`` [m] (the machine's centre of mass)."""
        from foundation_calc.solvers.machines.exciter import UnbalancedExciter, axis_angles

        delta1, delta2 = axis_angles(self.axis)
        rho = tuple(float(c) for c in (self.at or cog))
        return UnbalancedExciter(self.rotor_mass, self.eccentricity, rho, delta1, delta2, self.phase, self.sense)


class BlockMachine(SpeedFields):
    """A machine on the block: its mass properties, its own speed and its loads, unbalance, cranks or exciters."""

    name: str = quantity("-", "-", "label shown in reports", min_length=1, max_length=80, examples=["compressor"])
    mass: float = quantity(
        "m_m", "kg", "machine mass, its frame's without its parts' (rotors, rods, sliders); 0 for a machine of parts"
        " alone (exciters' rotors, crank throws' moving masses) with no frame of its own", ge=0, examples=[12.0e3],
    )
    cog: Vector = quantity("r_m", "m", "machine's centre of mass [x, y, z] from O", examples=[[0.5, 0.0, 2.8]])
    inertia: Vector = quantity(
        "J_m", "kg m²", "moments of inertia about its own centre of mass, axes along x, y, z; default 0 (a point mass)",
        [0.0, 0.0, 0.0], examples=[[1.0e4, 2.0e4, 2.0e4]],
    )
    loads: list[MachineLoad] = quantity("-", "-", "the vendor's dynamic loads, one entry per order and phase", [])
    unbalance: Unbalance | None = quantity("-", "-", "a rotating unbalance by its balance quality grade", None)
    cranks: list[MachineCrank] = quantity(
        "-", "-", "crank mechanisms driven at the machine's speed, one per throw (cylinder): their moving parts'"
        " mean mass is added to the machine's, their inertia forces are its loads", [],
    )
    exciters: list[MachineExciter] = quantity(
        "-", "-", "unbalanced vibration exciters driven at the machine's speed, one table per rotor (a vibrating"
        " table, a screen; a two-shaft directional exciter is two rotors of opposite sense): each rotor's mean mass is"
        " added to the machine's, its rotating force m l ω² is a load, its angle-dependent inertia is checked", [],
        max_length=16,
    )
    drive: Drive | None = quantity(
        "-", "-", "the motor that starts this machine (fcalc runup), as a crank scene's [drive]; without it the"
        " machine is run up along [operation]'s ramp", None,
    )
    source: str | None = source("the machine's mass, loads and unbalance (the vendor's data sheet)", "vendor data sheet DS-7, rev. 2")

    #: Other names of keys: ``speed`` [rad/s] is ``omega`` (the issue's scene contract writes it so).
    renamed_keys: ClassVar[dict[str, str]] = {"speed": "omega"}

    @model_validator(mode="before")
    @classmethod
    def _speed_is_omega(cls, data):
        """A renamed key (:attr:`renamed_keys`) read as its field; both given is an error."""
        for other, key in cls.renamed_keys.items():
            if isinstance(data, dict) and other in data:
                if key in data:
                    raise ValueError(f"give {other} [rad/s] or {key} [rad/s], not both (they are the same key)")
                data = {(key if k == other else k): v for k, v in data.items()}
        return data

    @model_validator(mode="after")
    def _machine_checks(self):
        if any(j < 0 for j in self.inertia):
            raise ValueError(f"inertia must be >= 0 kg m² each (got {list(self.inertia)})")
        return self

    @cached_property
    def parts_by_kind(self) -> tuple[tuple, ...]:
        """The machine's parts (:class:`~foundation_calc.solvers.machines.part.MachinePart`), one
        tuple per builder of :data:`MACHINE_PARTS`, in its order (built once: a scene is frozen)."""
        return tuple(tuple(build(self)) for build in MACHINE_PARTS)

    @property
    def parts(self) -> tuple:
        """Every part of the machine (:attr:`parts_by_kind`, flat)."""
        return tuple(part for kind in self.parts_by_kind for part in kind)

    @property
    def periodic_parts(self) -> tuple:
        """The parts with an angle-dependent inertia (crank mechanisms, exciters' rotors)."""
        return tuple(part for part in self.parts if part.periodic)

    @cached_property
    def gyroscopic(self):
        """Its parts' mean gyroscopic coupling D̄ at its speed, summed (6, 6) [kg/s, ..., kg m²/s]
        (:meth:`~foundation_calc.solvers.machines.part.MachinePart.gyroscopic`); None when no part
        has periodic inertia, or their D̄ cancel (two rotors of a directional exciter): its skew part
        (the symmetric part is the mean of a time derivative, round-off), entries below 1e-12 of the
        largest of the parts' D̄ their round-off."""
        import numpy as np

        each = [part.gyroscopic(self.omega_rad_s) for part in self.periodic_parts]
        if not each:
            return None
        total = sum(each)
        total = (total - total.T) / 2.0
        scale = max(float(np.abs(D).max()) for D in each)
        total = np.where(np.abs(total) > 1e-12 * scale, total, 0.0)
        return total if np.any(total) else None

    @property
    def carried_inertia(self) -> float:
        """What the motor turns besides its [drive] inertia (the platform's m l²): its parts' (an
        unbalance's m_r e², e = G/ω) [kg m²]; 0 for none."""
        return sum(part.carried_inertia(self.omega_rad_s) for part in self.parts)

    def load_rows(self) -> list:
        """Every part's loads at the machine's speed (:class:`~foundation_calc.solvers.machines.part.LoadRow`:
        order, force [N], moment [N m], phase [rad], point [m], inertial)."""
        from foundation_calc.solvers.constants import GRAVITY

        return [row for part in self.parts for row in part.load_rows(self.omega_rad_s, GRAVITY)]

    @property
    def total_mass(self) -> float:
        """The machine's mass with its parts' (a crank's rods, sliders, rotating masses) [kg]."""
        return self.mass + sum(body[0] for body in self.bodies())

    def frameless_error(self, key: str) -> tuple[str, str] | None:
        """Why the machine, ``key`` in the scene (``machines[1]``), cannot be left without a frame,
        as (its key at fault, ``mass`` or ``inertia``; the sentence), or None: ``mass = 0`` is a machine of parts alone (a platform's exciters, whose housing is
        the platform), which needs parts with mass (exciters' rotors, crank throws' rods, sliders
        and rotating masses; given loads and an unbalance carry none, so a machine of those alone
        would have no mass for the mass ratio or the plausibility checks to judge) and no moment of
        inertia of its own (no frame to carry it)."""
        if self.mass > 0.0:
            return None
        if self.total_mass <= 0.0:
            return "mass", (f"{key}.mass = 0 kg, and its parts carry no mass: only a machine whose exciters' rotors or crank"
                    " throws' moving masses carry mass may leave out its frame (given loads and an unbalance have none);"
                    f" give {key}.mass > 0 kg, the machine's frame, casing and rotors")
        if any(j > 0.0 for j in self.inertia):
            return "inertia", (f"{key}.inertia = {list(self.inertia)} kg m² needs {key}.mass > 0 kg: a machine of parts alone"
                    " (mass = 0) has no frame to carry a moment of inertia; remove inertia or give the frame's mass")
        return None

    def bodies(self) -> list:
        """Its parts' time-averaged mass properties, (mass [kg], centre of mass [m] (3,), central
        inertia tensor [kg m²] (3, 3)) each, of the parts that have mass."""
        return [body for part in self.parts if (body := part.mass_properties()) is not None]

    def crank_throws(self) -> list:
        """The cranks as the solver's throws (:meth:`MachineCrank.throw`)."""
        return [crank.throw() for crank in self.cranks]


def _given_loads(machine: BlockMachine) -> list:
    """``[[machines.loads]]`` as :class:`~foundation_calc.solvers.machines.loads.GivenLoads` (at the
    machine's centre of mass where ``at`` is not given)."""
    if not machine.loads:
        return []
    from foundation_calc.solvers.machines.loads import GivenLoads

    return [GivenLoads(tuple((ld.order, ld.force, ld.moment, ld.phase, ld.at or machine.cog) for ld in machine.loads))]


def _unbalance(machine: BlockMachine) -> list:
    """``[machines.unbalance]`` as :class:`~foundation_calc.solvers.machines.unbalance.RotatingUnbalance`."""
    u = machine.unbalance
    if u is None:
        return []
    from foundation_calc.solvers.machines.unbalance import RotatingUnbalance

    return [RotatingUnbalance(u.rotor_mass, u.balance_grade_mm_s, tuple(u.axis), u.at or machine.cog)]


def _cranks(machine: BlockMachine) -> list:
    """``[[machines.cranks]]`` as one :class:`~foundation_calc.solvers.machines.crank_mechanism.CrankMechanism`,
    its harmonics given at the machine's centre of mass (so that they move with it)."""
    if not machine.cranks:
        return []
    from foundation_calc.solvers.machines.crank_mechanism import CrankMechanism

    return [CrankMechanism(tuple(machine.crank_throws()), machine.cog)]


def _exciters(machine: BlockMachine) -> list:
    """``[[machines.exciters]]`` as :class:`~foundation_calc.solvers.machines.exciter.UnbalancedExciter`,
    one per rotor (:meth:`MachineExciter.part`)."""
    return [exciter.part(machine.cog) for exciter in machine.exciters]


#: Builders of a machine's parts from its keys, each machine -> list of parts: a new kind of part
#: is its solver module and one builder here. The sheet describes the parts kind by kind, in this order.
MACHINE_PARTS: list = [_given_loads, _unbalance, _cranks, _exciters]


class BlockPoint(SceneModel):
    """A point of the block whose vibration the limits bound (a bearing, an edge)."""

    name: str = quantity("-", "-", "label shown in reports", min_length=1, max_length=80, examples=["crankshaft bearing"])
    at: Vector = quantity("r_P", "m", "position [x, y, z] from O", examples=[[0.8, 0.0, 3.0]])
