"""Scene model of kind ``platform``: a vibro-table on four three-spring isolators with one exciter.

Keys follow the scene contract of the platform note (Bolotnik, Chernousko et al., section 3):
``[platform]`` mass, length, width, cog, inertia; ``[exciter]`` rotor_mass, eccentricity,
position; ``[operation]`` omega | frequency_hz | speed_rpm, amplitude, regime; ``[isolators]``
vertical_reference or vertical. Added keys: ``platform.product_height``,
``isolators.horizontal_split``, ``isolators.loss_factor``, ``[[extra_exciters]]`` and
``[limits]``. All values are SI.
"""

from __future__ import annotations

from dataclasses import replace
from pathlib import Path
from typing import Annotated, Literal

from pydantic import Field, PrivateAttr, ValidationInfo, field_validator, model_validator

from foundation_calc.scenes.common import LENGTH_SCALE_FACTOR, Drive, LimitSources, SceneModel, SpeedFields, quantity
from foundation_calc.scenes.plausibility import Plausible, Remark
from foundation_calc.scenes.project import SceneHeader
from foundation_calc.solvers.constants import GRAVITY
from foundation_calc.solvers.platform.design import (
    REGIME_SIGN,
    PlatformDesign,
    design_from_position,
    design_from_vertical,
    position_from_vertical,
)
from foundation_calc.solvers.rigid_body.inertia import block_inertia
from foundation_calc.solvers.platform.verification import ExtraRotor, PlatformModel

#: The paper's worked example, used by ``fcalc platform`` when no scene is given.
DEFAULT_SCENE = Path(__file__).with_name("defaults") / "platform.toml"

#: Largest mismatch [m per m of platform size] between a given exciter.position and the (a, b)
#: that (3.9)-(3.10) derive from given vertical stiffnesses.
POSITION_MATCH = 1e-6

Positive = Annotated[float, Field(gt=0)]
Fraction = Annotated[float, Field(gt=0, lt=1)]


def _vector(symbol: str, unit: str, text: str, n: int, default=..., **extra):
    """A fixed-length list field whose description reads ``"symbol [unit]: text"``."""
    return Field(default, description=f"{symbol} [{unit}]: {text}", min_length=n, max_length=n, **extra)


class Platform(SceneModel):
    """The rigid platform with mould and concrete, without the rotor."""

    mass: float = quantity("M", "kg", "platform with mould and concrete, without the rotor", gt=0)
    length: float = quantity("A", "m", "side O1O2 of the support rectangle, along x'", gt=0)
    width: float = quantity("B", "m", "side O1O4 of the support rectangle, along y'", gt=0)
    cog: list[float] = _vector("(ξ, η, ζ)", "m", "centre of mass from corner O1, platform frame", 3)
    inertia: list[Positive] | None = _vector(
        "(J_x, J_y, J_z)", "kg m²", "central principal moments along x', y', z' (optional: else a"
        " homogeneous block A × B × product_height is assumed)", 3, None, examples=[[9.0e3, 1.7e4, 2.2e4]]
    )
    product_height: float | None = quantity(
        "H", "m", "height of the product box whose corners are checked (default 2ζ)", None, gt=0, examples=[1.3]
    )


class Exciter(SceneModel):
    """The single-shaft exciter with a vertical axis that the design places."""

    rotor_mass: float = quantity("m", "kg", "rotor mass", gt=0)
    eccentricity: float = quantity("l", "m", "distance from the axis to the rotor's centre of mass", gt=0)
    position: list[float] | None = _vector(
        "(a, b)", "m", "axis point in the platform frame; with isolators.vertical leave it out (or it must agree"
        " with (3.9)-(3.10))", 2, None
    )


class Operation(SpeedFields):
    """Speed, amplitude and regime."""

    amplitude: float = quantity("u", "m", "required amplitude of the circular motion", gt=0)
    regime: Literal["above", "below"] = quantity(
        "-", "-", '"above" resonance (sign - in (3.14)) or "below" (sign +)', "above"
    )
    run_up_time: float | None = quantity(
        "T_up", "s", "time of the linear speed ramp from rest to the operating speed (fcalc runup)", None, gt=0,
        examples=[5.0],
    )
    run_down_time: float | None = quantity(
        "T_down", "s", "time of the linear speed ramp from the operating speed to rest (fcalc runup)", None, gt=0,
        examples=[10.0],
    )


class Isolators(SceneModel):
    """Vertical stiffnesses (given or from K), the split of the horizontal sums, damping."""

    vertical_reference: float | None = quantity(
        "K", "N/m", "c33 = K and (c23 + c43)/2 = K (the paper's c23 = c33 = c43 = K when centred)", None, gt=0
    )
    vertical: list[Positive] | None = _vector(
        "(c13, c23, c33, c43)", "N/m", "explicit vertical stiffnesses; a, b then follow from (3.9)-(3.10)", 4, None,
        examples=[[1.005e8, 1.0e8, 1.0e8, 1.0e8]],
    )
    horizontal_split: list[Fraction] = _vector(
        "(s1, s3, s4, s2)", "-", "shares c11/(c11+c21), c31/(c31+c41), c12/(c12+c42), c22/(c22+c32)",
        4, [0.5, 0.5, 0.5, 0.5],
    )
    loss_factor: float = quantity("η", "-", "hysteretic loss factor of every spring", 0.0, ge=0, lt=1)
    damping_ratio: float = quantity(
        "D", "-", "viscous damping ratio at the operating speed: a dashpot 2 D c_ij / ω in parallel with every spring",
        0.0, ge=0, lt=1,
    )

    @field_validator("vertical")
    @classmethod
    def _one_vertical_rule(cls, vertical, info: ValidationInfo):
        if vertical is not None and info.data.get("vertical_reference") is not None:
            raise ValueError("give either vertical_reference (K) or vertical (c13, c23, c33, c43), not both")
        return vertical


class ExtraExciter(SceneModel):
    """An additional rotor, for verification only (the design places the main exciter)."""

    rotor_mass: float = quantity("m_j", "kg", "rotor mass", gt=0, examples=[6.0])
    eccentricity: float = quantity(
        "l_j", "m", "distance from the axis to the rotor's centre of mass", gt=0, examples=[0.1]
    )
    position: list[float] = _vector("(a_j, b_j, c_j)", "m", "axis point in the platform frame", 3, examples=[[2.0, 0.5, 0.3]])
    axis: list[float] = _vector("(δ1, δ2)", "rad", "axis angles of Eq. (1.3); (0, 0) is vertical", 2, [0.0, 0.0])
    speed_ratio: float = quantity(
        "ω_j/ω", "-", "signed speed as a multiple of the operating speed (-1: counter-rotating)", 1.0
    )
    phase: float = quantity("φ_j0", "rad", "rotor angle at t = 0 (the main rotor has 0)", 0.0)

    @field_validator("speed_ratio")
    @classmethod
    def _turns(cls, ratio: float) -> float:
        if ratio == 0.0:
            raise ValueError("must not be 0 (a rotor at rest is not an exciter)")
        return ratio


class Limits(LimitSources):
    """What the checks compare against."""

    detuning: float = quantity(
        "δ", "-", "required relative distance of ω from every natural frequency", 0.2, gt=0, lt=1
    )
    rocking_percent: float = quantity(
        "-", "% of u", "largest allowed rocking of the product's corners relative to its centre of mass", 5.0, gt=0
    )
    exciter_height_ratio: float = quantity(
        "c/ζ", "-", "warn when the exciter is more than this many ζ above the support plane", 3.0, gt=0
    )
    transient_amplitude: float | None = quantity(
        "u_tr", "m", "largest allowed displacement of the centre of mass and the product's corners during"
        " start-up and run-down (fcalc runup); default: none", None, gt=0, examples=[5.0e-3],
    )


#: What a warning about a value given on the command line advises instead (formatted with the value).
OPTION_ADVICE = {"operation.omega": "use --rpm {value:g}", "operation.speed_rpm": "use --hz {value:g}",
                 "operation.frequency_hz": "use --rpm {value:g}"}


class PlatformScene(Plausible, SceneHeader):
    """A scene of kind ``platform``."""

    kind: Literal["platform"] = quantity("-", "-", 'scene kind, always "platform"')
    platform: Platform
    exciter: Exciter
    operation: Operation
    isolators: Isolators
    extra_exciters: list[ExtraExciter] = Field(
        default_factory=list, description="- [-]: further rotors for the 6-DOF verification", max_length=16
    )
    limits: Limits = Limits()
    drive: Drive | None = None
    #: scene key -> how the user gave it, for a value given on the command line ("operation.amplitude" -> "--amp")
    _given_as: dict[str, str] = PrivateAttr(default_factory=dict)

    def given_on_command_line(self, names: dict[str, str]) -> "PlatformScene":
        """Record that the values of the keys in ``names`` came from the command-line options named
        there, so that warnings and errors name the option the user typed; returns the scene."""
        self._given_as.update(names)
        return self

    def key_as_given(self, key: str) -> str:
        """``key``, or the command-line option that gave its value."""
        return self._given_as.get(key, key)

    def related_findings(self, prefix: str, found: list) -> list:
        """An exciter eccentricity more than :data:`~foundation_calc.scenes.common.LENGTH_SCALE_FACTOR`
        × the platform (mm typed as m); the table judges every other key
        (:func:`~foundation_calc.scenes.plausibility.findings`)."""
        if self.exciter.eccentricity <= LENGTH_SCALE_FACTOR * max(self.platform.length, self.platform.width):
            return []
        return [Remark("exciter.eccentricity", f"exciter.eccentricity = {self.exciter.eccentricity:g} m"
                       " exceeds the platform; was it typed in mm?")]

    def plausibility_findings(self) -> list:
        """The table's findings (:class:`~foundation_calc.scenes.plausibility.Plausible`), a value
        given on the command line named by its option (``--amp``) with the option's advice."""
        return [f if self.key_as_given(f.key) == f.key else replace(f, key=self.key_as_given(f.key), advice=OPTION_ADVICE.get(f.key, ""))
                for f in super().plausibility_findings()]

    @model_validator(mode="after")
    def _position_or_vertical(self):
        iso, pos = self.isolators, self.exciter.position
        if iso.vertical is None and iso.vertical_reference is None:
            raise ValueError(
                "isolators: give vertical_reference (K) [N/m] or vertical = [c13, c23, c33, c43] [N/m]"
            )
        if iso.vertical is not None and pos is not None:
            p = self.platform
            a, b = position_from_vertical(
                p.mass, self.exciter.rotor_mass, p.cog[0], p.cog[1], p.length, p.width, *iso.vertical
            )
            if max(abs(a - pos[0]), abs(b - pos[1])) > POSITION_MATCH * max(1.0, p.length, p.width):
                raise ValueError(
                    f"exciter.position = {list(pos)} m contradicts isolators.vertical: with these four"
                    f" vertical stiffnesses (3.9)-(3.10) put the exciter at (a, b) = ({a:.6g}, {b:.6g}) m;"
                    " leave exciter.position out (or give vertical_reference instead of vertical)"
                )
        return self

    @property
    def product_height(self) -> float:
        """H [m]: the scene's product_height, else 2|ζ| (at least a tenth of the shorter side)."""
        p = self.platform
        if p.product_height is not None:
            return p.product_height
        return max(2.0 * abs(p.cog[2]), 0.1 * min(p.length, p.width))

    @property
    def inertia_given(self) -> bool:
        """True when the scene gives the platform's central moments of inertia."""
        return self.platform.inertia is not None

    @property
    def inertia(self) -> tuple:
        """Central principal moments [kg m²]: the scene's, else a homogeneous block A × B × H."""
        p = self.platform
        if p.inertia is not None:
            return tuple(p.inertia)
        return block_inertia(p.mass, p.length, p.width, self.product_height)

    def design(self) -> PlatformDesign:
        """Design the isolators and the exciter height (raises PhysicsError when impossible)."""
        p, e, op, iso = self.platform, self.exciter, self.operation, self.isolators
        common = dict(
            M=p.mass, m=e.rotor_mass, l=e.eccentricity, u=op.amplitude, omega=op.omega_rad_s,
            xi=p.cog[0], eta=p.cog[1], zeta=p.cog[2], A=p.length, B=p.width,
            sigma=REGIME_SIGN[op.regime], g=GRAVITY, split=tuple(iso.horizontal_split),
        )
        if iso.vertical is not None:
            return design_from_vertical(**common, vertical=tuple(iso.vertical))
        a, b = e.position if e.position is not None else (0.0, 0.0)
        return design_from_position(**common, a=a, b=b, K=iso.vertical_reference)

    def model(self) -> PlatformModel:
        """Inertia, damping, product box and extra rotors of the 6-DOF verification."""
        extra = tuple(
            ExtraRotor(x.rotor_mass, x.eccentricity, tuple(x.position), x.axis[0], x.axis[1], x.speed_ratio, x.phase)
            for x in self.extra_exciters
        )
        return PlatformModel(
            self.inertia, self.isolators.loss_factor, self.product_height, extra, self.isolators.damping_ratio
        )

    def as_block(self, source: str = "<scene>"):
        """This platform read as a validated ``block_foundation`` on its designed isolators with its
        exciters as a machine's (:func:`~foundation_calc.scenes.platform_block.platform_as_block`),
        ``source`` naming it in an error."""
        from foundation_calc.scenes.platform_block import platform_as_block

        return platform_as_block(self, source)
