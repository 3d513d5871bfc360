"""Scene model of kind ``crank_foundation``: a block foundation carrying a crank-slider machine.

Keys and units follow the scene contract of Krichever & Makarov's problem (see docs/crank-foundation.md). All
values are SI. Rules that involve two fields (l' < l, r < l, mu <= 0.5) are checked here so the
message names the field to change.
"""

from __future__ import annotations

from typing import TYPE_CHECKING, Literal

from pydantic import ValidationInfo, field_validator, model_validator

from foundation_calc.errors import PhysicsError
from foundation_calc.scenes.common import (
    LENGTH_SCALE_FACTOR,
    Drive,
    LimitSources,
    RunTimes,
    SceneModel,
    SpeedFields,
    detuning_bands,
    quantity,
    source,
)
from foundation_calc.scenes.block_piles import BlockPiles, PiledSoil, piled
from foundation_calc.scenes.foundation import Foundation
from foundation_calc.scenes.plausibility import Plausible, Remark, culprit_error, judge
from foundation_calc.scenes.soil import OnSoil, Soil
from foundation_calc.scenes.stratum import stratum_error, stratum_remarks
from foundation_calc.scenes.project import SceneHeader, SheetOptions
from foundation_calc.solvers.constants import GRAVITY
from foundation_calc.solvers.crank.mechanism import CrankDesign, lump_slider

if TYPE_CHECKING:
    from foundation_calc.solvers.crank.loads import HarmonicLoads, RigidBlock
    from foundation_calc.solvers.crank.plane import PlaneFoundation

#: Largest ratio of the mechanism's moving mass to the total mass for which the small-parameter
#: method of the paper is claimed to hold.
MU_MAX = 0.5


class Mechanism(SpeedFields):
    """The crank-slider machine; the crank turns at constant speed relative to the foundation."""

    crank_radius: float = quantity("r", "m", "crank radius", gt=0)
    rod_length: float = quantity("l", "m", "connecting-rod length, crank pin M' to slider pin M''", gt=0)
    rod_mass: float = quantity("m", "kg", "connecting-rod mass", gt=0)
    rod_cog_to_crank_pin: float = quantity(
        "l'", "m", "distance C1M' from the rod's centre of mass to the crank pin; 0 < l' < l", gt=0
    )
    rod_radius_of_gyration: float = quantity("ρ", "m", "radius of gyration of the rod about C1", gt=0)
    crank_axis_to_cog: float = quantity(
        "a", "m", "distance from the crank axis A to C along the guide; positive when A is above C"
    )
    slider_mass: float = quantity(
        "m1", "kg", "mass carried by the slider (saw frame, piston, ram)", 0.0, ge=0
    )
    drive_on_foundation: bool = quantity(
        "-", "-", "true when the motor's reaction torque acts on the foundation", True
    )

    @field_validator("rod_length")
    @classmethod
    def _rod_longer_than_crank(cls, rod_length: float, info: ValidationInfo) -> float:
        r = info.data.get("crank_radius")
        if r is not None and not r < rod_length:
            raise ValueError(
                f"must be longer than crank_radius = {r:g} m (λ = r/l = {r / rod_length:.4g} must be < 1)"
            )
        return rod_length

    @field_validator("rod_cog_to_crank_pin")
    @classmethod
    def _cog_on_the_rod(cls, l1: float, info: ValidationInfo) -> float:
        rod_length = info.data.get("rod_length")
        if rod_length is not None and not l1 < rod_length:
            raise ValueError(f"must be less than rod_length = {rod_length:g} m (0 < l' < l)")
        return l1


#: Vibration codes with zone tables (``checks/codes.py`` holds the tables; a test keeps the two equal).
CODE_NAMES = ("ISO 10816-3",)


class Limits(LimitSources):
    """What the checks compare against: peak and RMS limits, a vibration code, the detuning."""

    amplitude: float | None = quantity(
        "u_max", "m", "largest allowed peak displacement of C and of every point, each direction", None, gt=0,
        examples=[2.0e-4],
    )
    velocity: float | None = quantity(
        "v_max", "m/s", "largest allowed peak velocity", None, gt=0, examples=[5.0e-3]
    )
    acceleration: float | None = quantity(
        "a_max", "m/s²", "largest allowed peak acceleration", None, gt=0, examples=[0.3]
    )
    amplitude_rms: float | None = quantity(
        "u_rms,max", "m", "largest allowed RMS displacement (mean left out), each point and direction", None, gt=0,
        examples=[5.0e-5],
    )
    velocity_rms: float | None = quantity(
        "v_rms,max", "m/s", "largest allowed RMS velocity, each point and direction", None, gt=0, examples=[2.8e-3]
    )
    acceleration_rms: float | None = quantity(
        "a_rms,max", "m/s²", "largest allowed RMS acceleration, each point and direction", None, gt=0, examples=[0.2]
    )
    code: Literal[CODE_NAMES] | None = quantity(
        "-", "-", "vibration code whose zones A/B/C/D judge the RMS velocity and displacement of C and of"
        " every point", None,
        examples=["ISO 10816-3"],
    )
    machine_group: Literal[1, 2] | None = quantity(
        "-", "-", "machine group of the code (ISO 10816-3: 1 above 300 kW, 2 from 15 to 300 kW)", None, examples=[2]
    )
    foundation: Literal["rigid", "flexible"] | None = quantity(
        "-", "-", "support class of the code (ISO 10816-3, 3.4); default: classified from the modes, rigid in a"
        " direction whose lowest natural frequency is at least 1.25 × the speed", None, examples=["rigid"]
    )
    acceptable_zone: Literal["A", "B"] | None = quantity(
        "-", "-", "highest zone that passes; default: A passes, B warns, C and D fail", None, examples=["B"]
    )
    machine_power: float | None = quantity(
        "P", "W", "rated power of the machine, to check its group of the code", None, gt=0, examples=[160e3]
    )
    detuning: float | dict[int, float] = quantity(
        "δ", "-", "required relative distance of the speed from every judged resonance: one band,"
        " or a band per order, e.g. {1 = 0.2, 2 = 0.2, 3 = 0.1}; each band > 0 and < 1",
        0.2, examples=[0.2, {"1": 0.2, "2": 0.2, "3": 0.1}],
    )
    bearing_pressure: float | None = quantity(
        "q_a", "Pa", "allowable static bearing pressure of the soil under the base", None, gt=0, examples=[1.5e5]
    )
    settlement: float | None = quantity(
        "s_a", "m", "allowable static settlement W/K_z of the base on the soil method's vertical spring"
        " (office check)", None, gt=0, examples=[0.01],
    )
    transient_amplitude: float | None = quantity(
        "u_tr", "m", "largest allowed displacement of C and of every point during start-up and run-down"
        " (fcalc runup); default: none", None, gt=0, examples=[1.0e-3],
    )

    @field_validator("detuning", mode="before")
    @classmethod
    def _detuning_bands(cls, value):
        return detuning_bands(value)

    @field_validator("code", mode="before")
    @classmethod
    def _known_code(cls, code):
        if code == "ISO 20816-3":
            raise ValueError(
                "ISO 20816-3 is not available: its zone tables have not been checked against ISO 10816-3's;"
                ' write code = "ISO 10816-3" to judge with ISO 10816-3:2009, Annex A'
            )
        return code

    @model_validator(mode="after")
    def _code_class_complete(self):
        given = {k: getattr(self, k) for k in ("machine_group", "foundation", "acceptable_zone", "machine_power")}
        if self.code is None:
            stray = [k for k, v in given.items() if v is not None]
            if stray:
                raise ValueError(f"{', '.join(stray)} need code (e.g. code = \"ISO 10816-3\")")
        else:
            if given["machine_group"] is None:
                raise ValueError(f"code = {self.code!r} needs machine_group (1 or 2)")
        return self


class PointOfAction(SceneModel):
    """Where a load acts on the block, relative to its centre of mass C."""

    horizontal: float = quantity("u", "m", "horizontal offset from C, positive in +x", 0.0, examples=[0.8])
    height: float = quantity("H", "m", "height above C (negative: below C)", 0.0, examples=[1.2])


class Load(SceneModel):
    """A harmonic load of the machine on the block (vendor data): amplitude · cos(n ω t + φ).

    Each component (horizontal, vertical force, moment) varies as its amplitude · cos(n ω t + φ).
    """

    name: str = quantity("-", "-", "label shown in reports", "", max_length=80, examples=["1st order, crank"])
    order: int = quantity(
        "n", "-", "multiple of the speed: 1 at the speed, 2 at twice it, ...", ge=1, le=64, examples=[1]
    )
    horizontal: float = quantity("F_x", "N", "amplitude of the horizontal force, along +x", 0.0, examples=[12.0e3])
    vertical: float = quantity(
        "F_y", "N", "amplitude of the vertical force, along +y (positive downward)", 0.0, examples=[4.0e3]
    )
    moment: float = quantity("M", "N m", "amplitude of a couple turning +x toward +y", 0.0, examples=[2.0e3])
    phase: float = quantity(
        "φ", "rad", "phase φ at t = 0 (crank angle 0 when there is a [mechanism])", 0.0, examples=[1.5708]
    )
    at: PointOfAction = quantity("-", "-", "point of action of the forces; default C", PointOfAction())
    source: str | None = source("the load's values (the vendor's data sheet)", "vendor data sheet DS-3, table 2")

    @model_validator(mode="after")
    def _something_acts(self):
        if self.horizontal == 0 and self.vertical == 0 and self.moment == 0:
            raise ValueError("give at least one of horizontal [N], vertical [N], moment [N m] (all are 0)")
        return self


class Operation(RunTimes, SpeedFields):
    """The machine's speed, for a scene whose machine is given by its loads only, and its start-up
    and run-down (fcalc runup)."""

    @model_validator(mode="after")
    def _exactly_one_speed(self):  # replaces SpeedFields': with a [mechanism] the table has no speed
        given = [k for k in ("omega", "frequency_hz", "speed_rpm") if getattr(self, k) is not None]
        if len(given) > 1:
            raise ValueError(
                "give the speed as exactly one of omega [rad/s], frequency_hz [Hz] or speed_rpm [rpm]"
                f" (got {' and '.join(given)})"
            )
        return self

    @property
    def gives_speed(self) -> bool:
        """True when the table gives the speed (a machine given by its loads)."""
        return any(getattr(self, k) is not None for k in ("omega", "frequency_hz", "speed_rpm"))


class Point(SceneModel):
    """A point of the foundation whose vibration the norms limit (edge of the block, a bearing)."""

    name: str = quantity(
        "-", "-", "label shown in reports", min_length=1, max_length=80, examples=["top edge, machine side"]
    )
    horizontal: float = quantity(
        "u", "m", "horizontal position from the centre of mass C, positive in +x", examples=[2.5]
    )
    height: float = quantity("H", "m", "height above the centre of mass C (negative: below C)", examples=[1.3])


def _number(x):
    """A float of a scalar (a 0-d array too), an array as it is: springs taken at one frequency or at
    an array of them (a frequency-dependent soil along a sweep)."""
    return float(x) if getattr(x, "ndim", 0) == 0 else x


def _largest(x) -> float:
    """The largest element of an array, or the float itself."""
    return float(x.max()) if getattr(x, "ndim", 0) else float(x)


class CrankScene(Plausible, OnSoil, SceneHeader):
    """A scene of kind ``crank_foundation``."""

    kind: Literal["crank_foundation"] = quantity("-", "-", 'scene kind, always "crank_foundation"')
    foundation: Foundation
    soil: Soil
    piles: BlockPiles | None = quantity(
        "-", "-", "a pile group under the block, its base the rigid cap: the group's springs and dashpots replace"
        " the footing's ([soil] gives the soil around the piles; the block's keys, docs/block-foundation.md); optional",
        None,
    )
    mechanism: Mechanism | None = quantity(
        "-", "-", "the crank-slider machine; leave out when the machine is given by its [[loads]]", None
    )
    operation: Operation | None = quantity(
        "-", "-", "the speed, when there is no [mechanism] (omega, frequency_hz or speed_rpm); run_up_time and"
        " run_down_time for fcalc runup", None
    )
    loads: list[Load] = quantity(
        "-", "-", "harmonic loads of the machine on the block (vendor data), instead of or beside [mechanism]", []
    )
    limits: Limits = Limits()
    drive: Drive | None = None
    points: list[Point] = quantity(
        "-", "-", "points whose displacement, velocity and acceleration amplitudes are checked", []
    )
    report: SheetOptions | None = quantity(
        "-", "-", "what the calculation sheet adds: design, the ranges over which the sheet of a failing scene"
        " sizes the block (fcalc design); optional", None
    )

    @field_validator("points")
    @classmethod
    def _distinct_point_names(cls, points: list[Point]) -> list[Point]:
        seen, repeated = {"C"}, set()  # C, the centre of mass, is always reported under that name
        for point in points:
            (repeated if point.name in seen else seen).add(point.name)
        repeated = sorted(repeated)
        if repeated:
            raise ValueError(f"point names must be distinct and not 'C' (the centre of mass): {', '.join(repeated)}")
        return points

    def related_findings(self, prefix: str, found: list) -> list:
        """Values implausible against the rest of the scene (the table judges each key on its own,
        :func:`~foundation_calc.scenes.plausibility.findings`): a length of the machine, a load or a
        point more than :data:`~foundation_calc.scenes.common.LENGTH_SCALE_FACTOR` × the
        foundation's size sqrt(S) away (mm typed as m), and the block-to-machine mass ratio.
        """
        size = self.foundation.base_area**0.5
        mech = self.mechanism
        machine = {} if mech is None else {
            "mechanism.crank_radius": mech.crank_radius,
            "mechanism.rod_length": mech.rod_length,
            "mechanism.crank_axis_to_cog": mech.crank_axis_to_cog,
        }
        lengths = {
            **self.foundation.lengths_given(),
            **machine,
            **{f"loads[{i}].at.horizontal": load.at.horizontal for i, load in enumerate(self.loads)},
            **{f"loads[{i}].at.height": load.at.height for i, load in enumerate(self.loads)},
            **{f"points[{i}].horizontal": p.horizontal for i, p in enumerate(self.points)},
            **{f"points[{i}].height": p.height for i, p in enumerate(self.points)},
        }
        far = [
            Remark(key, f"{key} = {value:g} m is {abs(value) / size:.3g} × the foundation's size sqrt(S) = {size:.3g} m;"
                   " was it typed in mm?")
            for key, value in lengths.items()
            if abs(value) > LENGTH_SCALE_FACTOR * size
        ]
        return far + self._mass_ratio_findings(found + far) + stratum_remarks(self.soil, *self.foundation.dimensions)

    def _mass_ratio_findings(self, found: list) -> list:
        """The block-to-machine mass ratio against the rule of thumb, for a scene that gives
        ``[foundation.block]`` and ``[foundation.machine]`` whose own values are plausible."""
        f = self.foundation
        if f.block is None or f.machine is None or any(x.key.startswith("foundation.") for x in found):
            return []
        b, mech = f.block, self.mechanism
        block = b.length * b.width * b.height * b.density
        keys = "foundation.machine.mass" + ("" if mech is None else " + mechanism.rod_mass + mechanism.slider_mass")
        machine = f.machine.mass + (0.0 if mech is None else mech.rod_mass + mech.slider_mass)
        name = "mass_ratio_rotating" if mech is None else "mass_ratio_reciprocating"
        key = f"block-to-machine mass ratio ([foundation.block] {block:.5g} kg / ({keys}) {machine:.5g} kg)"
        return judge(key, block / machine, name)

    @model_validator(mode="after")
    def _machine_and_speed(self):
        if self.mechanism is None and not self.loads:
            raise ValueError("give the machine as [mechanism] or by its [[loads]] (or both)")
        if self.mechanism is not None and self.operation is not None and self.operation.gives_speed:
            raise ValueError(
                "[mechanism] gives the speed: leave the speed out of [operation] (it is for a machine given by its"
                " loads; run_up_time and run_down_time may stay)"
            )
        if self.mechanism is None and (self.operation is None or not self.operation.gives_speed):
            raise ValueError("a machine given by its [[loads]] needs its speed: [operation] speed_rpm, omega or frequency_hz")
        return self

    @model_validator(mode="after")
    def _stratum_below_base(self):
        if (error := stratum_error(self.soil, self.foundation.embedment or 0.0, "foundation.embedment")) is not None:
            raise ValueError(error)
        return self

    @model_validator(mode="after")
    def _piles_carry_the_block(self):
        """The support: a pile group when ``[piles]`` is given, as a block's
        (:func:`~foundation_calc.scenes.block_piles.piled`), its heads under the base L × B."""
        if self.piles is None or isinstance(self.soil, PiledSoil):
            return self
        object.__setattr__(self, "soil", piled(self.soil, self.piles, self.foundation.dimensions))
        return self

    @property
    def embedment(self) -> float:
        """D: the base's depth below the ground surface [m], 0 for a surface footing."""
        return self.foundation.embedment or 0.0

    @property
    def speed(self) -> SpeedFields:
        """The section that gives the speed (its ``omega_rad_s``, ``speed_given_as``)."""
        return self.mechanism if self.mechanism is not None else self.operation

    @model_validator(mode="after")
    def _mechanism_is_small(self):
        if self.mechanism is None:
            return self
        moving = self.mechanism.rod_mass + self.mechanism.slider_mass
        mu = moving / (self.foundation.mass + moving)
        if mu > MU_MAX:
            raise ValueError(
                f"mechanism.rod_mass + mechanism.slider_mass = {moving:g} kg makes μ = {mu:.4g};"
                f" the method needs μ = (m + m1)/(M + m + m1) <= {MU_MAX}"
            )
        return self

    @property
    def total_mass(self) -> float:
        """M_tot = M + m + m1 [kg]: block, machine frame, rod and slider (M alone for a machine given
        by its loads)."""
        mech = self.mechanism
        return self.foundation.mass + (0.0 if mech is None else mech.rod_mass + mech.slider_mass)

    def support(self, base=None, masses=None):
        """What carries the block (:func:`~foundation_calc.solvers.supports.support_of`: the footing on
        ``[soil]`` in the paper's symbols, :mod:`~foundation_calc.solvers.supports.plane_footing`,
        unless a registered support takes the scene), under the plane's body: M_tot and
        I_0 = I_c + M_tot h² about the base's axis (:func:`plane_masses`). ``base`` (L, B) [m] and
        ``masses`` (..., 6) [kg, kg m²] replace the scene's own."""
        from foundation_calc.solvers.supports import support_of
        from foundation_calc.solvers.supports.plane_footing import plane_masses

        f = self.foundation
        if masses is None:
            masses = plane_masses(self.total_mass, f.moment_of_inertia + self.total_mass * f.cog_height**2)
        return support_of(self, *(f.dimensions if base is None else base), masses)

    def in_plane(self, soil_frequency=0.0) -> tuple:
        """((K_x, K_z, K_φ), (C_x, C_z, C_φ), (K_xφ, C_xφ), the support's method) at O of
        :meth:`support` at ``soil_frequency`` [rad/s]
        (:func:`~foundation_calc.solvers.supports.plane_footing.plane`: the support's coupling of
        u_x with θ_y, a pile group's, 0 on an uncoupled support; any other coupling of the plane's
        motions is a PhysicsError), each a float (an array at an array of frequencies); raises
        PhysicsError (:meth:`require_stable_rocking`) for a block that tips over.

        Stability is judged on the support's springs at rest (ω = 0), whatever ``soil_frequency``:
        tipping over under the weight (paper (3.4)) is a statement about the static equilibrium, and
        a frequency-dependent support's springs at ω are the real part of an impedance (a pile
        group's K_x(ω) may dip near zero, making K_xφ²/K_x explode), not a static stiffness. The
        6-DOF block judges its stability on the static springs alike (:mod:`~foundation_calc.checks.amplitudes.machines`)."""
        *found, support = self._support_in_plane(soil_frequency)
        return *found, support.method

    def _support_in_plane(self, soil_frequency) -> tuple:
        """:meth:`in_plane`'s springs, dashpots and coupling, then the support itself (its label
        names it in a refusal)."""
        from foundation_calc.solvers.supports.plane_footing import plane

        support = self.support()
        springs, dashpots, coupling = plane(support.impedance(soil_frequency), support.label)
        springs, dashpots, coupling = (tuple(map(_number, v)) for v in (springs, dashpots, coupling))
        at_rest = springs, coupling
        if support.frequency_dependent and _largest(abs(soil_frequency)) != 0.0:
            static, _, static_coupling = plane(support.impedance(0.0), support.label)
            at_rest = tuple(map(_number, static)), tuple(map(_number, static_coupling))
        self.require_stable_rocking(at_rest[0][2], at_rest[0][0], at_rest[1][0])
        return springs, dashpots, coupling, support

    def soil_springs(self, method: str | None = None, omega=0.0):
        """K_z, K_x, K_φ and damping ratios (:class:`~foundation_calc.solvers.soil.springs.SoilSprings`) of
        the footing on the soil by ``method`` (default: the scene's own) at ``omega`` [rad/s] (arrays
        welcome): :meth:`support`'s
        :meth:`~foundation_calc.solvers.supports.plane_footing.PlaneFooting.plane_springs`."""
        scene = self if method is None else self.model_copy(update={"soil": self.soil.model_copy(update={"method": method})})
        support = scene.support()
        if not hasattr(support, "plane_springs"):  # a pile group, a registered support: no soil method's chain
            from foundation_calc.solvers.supports.plane_footing import plane, require_uncoupled

            require_uncoupled(plane(support.impedance(omega), support.label)[2], support.label)  # stops here, by name
            raise PhysicsError(
                f"the support {support.label} gives no soil method's springs and damping ratios in the plane, which the"
                " crank's soil comparison derives by hand", field="soil",
                hint="describe the foundation as a block_foundation scene, whose sheet takes any support")
        return support.plane_springs(omega)

    def base_dashpots(self, springs, M_tot: float) -> dict[str, float]:
        """C_x, C_z, C_phi of the springs' damping ratios under the scene's block of total mass M_tot [kg]
        (:func:`~foundation_calc.solvers.supports.plane_footing.plane_dashpots`)."""
        from foundation_calc.solvers.supports.plane_footing import plane_dashpots

        f = self.foundation
        return plane_dashpots(springs, M_tot, f.moment_of_inertia + M_tot * f.cog_height**2)

    def require_stable_rocking(self, K_phi, K_x=1.0, K_xphi=0.0) -> None:
        """Raise :class:`PhysicsError` when the soil's rocking spring K_φ = c_φ I1 [N m/rad] (the
        softest of an array) does not exceed
        the weight's overturning moment P h (paper (3.4); docs/crank-foundation.md, "The model");
        on a support coupling sway with rocking (K_xφ [N/rad], K_x [N/m]), when K_φ - K_xφ²/K_x
        does not (:func:`~foundation_calc.solvers.crank.frequencies.rocking_stability_margin`).

        The message names the likely culprit, an implausible soil or foundation value
        (:meth:`plausibility_findings`: a modulus in MPa for Pa, a block height in mm), or else
        the keys of the scene file that set K_φ, I1 and h.
        """
        from foundation_calc.solvers.crank.frequencies import coupled_rocking_stiffness, stability_margin_formula

        f, coupled = self.foundation, bool(_largest(abs(K_xphi)) != 0.0)
        K_phi = -_largest(-coupled_rocking_stiffness(K_phi, K_x, K_xphi))
        overturning = self.total_mass * GRAVITY * f.cog_height
        if K_phi > overturning:
            return
        culprits = [x for x in self.plausibility_findings()
                    if any(part in x.key for part in ("soil.", "foundation.")) and x.key not in self.soil.not_rocking]
        stiffness = "net of the support's sway-rocking coupling, K_φ - K_xφ²/K_x," if coupled else "K_φ = c_φ·I1"
        text = (
            f"the foundation is unstable in rocking: the soil's rocking stiffness {stiffness}"
            f" = {K_phi:.4g} N m"
            f" does not exceed the overturning moment of the weight P·h = {overturning:.4g} N m"
            f" ({stability_margin_formula(coupled)} = {K_phi / overturning - 1.0:.4g})"
        )
        spring = self.soil.rocking_key
        base = "foundation.base_second_moment" if f.given("base_second_moment") else (
            "foundation.base_length" if f.given("base_length") else "foundation.block.length")
        height = "foundation.cog_height" if f.given("cog_height") else "foundation.block.height" + (
            "" if f.machine is None else " and foundation.machine.cog_height")
        raise culprit_error(text, culprits, spring, f"increase {spring} or {base}, or lower {height}")

    def block(self, soil_frequency: float = 0.0) -> RigidBlock:
        """The block (with the whole machine's mass) on its support's springs and dashpots at O
        (:meth:`in_plane`), for the loads; a frequency-dependent support takes them at ``soil_frequency`` [rad/s].
        The block takes three uncoupled springs: a support coupling sway with rocking (a pile group) is a
        PhysicsError naming it (:func:`~foundation_calc.solvers.supports.plane_footing.require_uncoupled`)."""
        from foundation_calc.solvers.crank.loads import RigidBlock
        from foundation_calc.solvers.supports.plane_footing import require_uncoupled

        f = self.foundation
        (K_x, K_z, K_phi), (C_x, C_z, C_phi), coupling, support = self._support_in_plane(soil_frequency)
        require_uncoupled(coupling, support.label)
        return RigidBlock(M_tot=self.total_mass, I_c=f.moment_of_inertia, h=f.cog_height, K_x=K_x, K_z=K_z,
                          K_phi=K_phi, C_x=C_x, C_z=C_z, C_phi=C_phi, g=GRAVITY)

    def harmonic_loads(self) -> HarmonicLoads | None:
        """The scene's ``[[loads]]`` as solver arrays (None without loads)."""
        if not self.loads:
            return None
        import numpy as np

        from foundation_calc.solvers.crank.loads import HarmonicLoads

        columns = zip(*((ld.order, ld.horizontal, ld.vertical, ld.moment, ld.phase, ld.at.horizontal, ld.at.height) for ld in self.loads))
        return HarmonicLoads(*(np.array(c, dtype=int if i == 0 else float) for i, c in enumerate(columns)))

    def design(self, soil_frequency: float = 0.0) -> CrankDesign:
        """The scene's numbers as solver inputs (SI, paper's symbols, slider lumped into the rod).

        A frequency-dependent support (its ``frequency_dependent``) takes its springs and dashpots at
        ``soil_frequency`` [rad/s], 0 for the static springs. A support coupling u_x with θ_y (a pile
        group) gives its K_xφ, C_xφ to the design, always: what takes them (the plane's one model,
        the averaged operator, the exact solution) reads them, and the paper's closed forms, which
        take three uncoupled springs, refuse or step aside by the design's own
        :attr:`~foundation_calc.solvers.crank.mechanism.CrankDesign.coupled`
        (:func:`~foundation_calc.solvers.crank.closed_form.design_first_approximation`,
        :func:`~foundation_calc.solvers.crank.natural.design_frequencies`).

        The support's springs at O (:meth:`in_plane`) map to c = K_z/S, c1 = K_x/S, c_φ = K_φ/I1
        (Barkan's coefficients pass through unchanged), its dashpots to C_x, C_z, C_φ. Raises
        PhysicsError naming ``mechanism`` for a machine given by its loads only, and
        (:meth:`in_plane`) for a block that tips over or a support that couples the plane's motions
        otherwise than u_x with θ_y.
        """
        f, s, mech = self.foundation, self.soil, self.mechanism
        if mech is None:
            raise PhysicsError(
                "this command needs the crank mechanism; the scene gives the machine by its [[loads]] only",
                field="mechanism",
            )
        rod = lump_slider(
            m=mech.rod_mass,
            l=mech.rod_length,
            l1=mech.rod_cog_to_crank_pin,
            rho=mech.rod_radius_of_gyration,
            m1=mech.slider_mass,
        )
        (K_x, K_z, K_phi), (C_x, C_z, C_phi), (K_xphi, C_xphi), method = self.in_plane(soil_frequency)
        if method == "coefficients":
            c, c1, c_phi = s.c_z, s.c_x, (s.c_z if s.c_phi is None else s.c_phi)
        else:
            c, c1, c_phi = K_z / f.base_area, K_x / f.base_area, K_phi / f.base_second_moment
        return CrankDesign(
            M=f.mass,
            I_c=f.moment_of_inertia,
            h=f.cog_height,
            S=f.base_area,
            I1=f.base_second_moment,
            c=c,
            c1=c1,
            c_phi=c_phi,
            C_x=C_x,
            C_z=C_z,
            C_phi=C_phi,
            omega=mech.omega_rad_s,
            r=mech.crank_radius,
            l=mech.rod_length,
            a=mech.crank_axis_to_cog,
            rod=rod,
            drive_on_foundation=mech.drive_on_foundation,
            g=GRAVITY,
            K_xphi=K_xphi,
            C_xphi=C_xphi,
            soil_frequency=soil_frequency,
        )

    def plane_model(self, soil_frequency: float = 0.0) -> PlaneFoundation:
        """The scene as the one rigid-body model (:mod:`foundation_calc.solvers.crank.plane`): the
        block (M, I_c at C) on the base's springs and dashpots at O, carrying the mechanism as one
        crank throw in the x-z plane; the soil at ``soil_frequency`` [rad/s] as :meth:`design`."""
        from foundation_calc.solvers.crank.plane import plane_foundation

        return plane_foundation(self.design(soil_frequency))
