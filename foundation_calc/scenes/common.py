"""Building blocks shared by every scene kind: model configuration, quantities, speeds.

Every physical field is declared with :func:`quantity`, so its description always carries the
paper's symbol and the SI unit; the JSON schema, the error messages and the docs read it there.
"""

from __future__ import annotations

from typing import Any

from pydantic import BaseModel, ConfigDict, Field, field_validator, model_validator

from foundation_calc.units import omega_from_hz, omega_from_rpm

#: Version of the scene format written by ``fcalc init`` and accepted by the loaders.
SCENE_SCHEMA_VERSION = 1


#: Smallest and largest magnitude of a non-zero number in a scene [SI units]. Designs sit far
#: inside (masses 1e1-1e7 kg, stiffnesses 1e4-1e10 N/m, amplitudes 1e-7-1e-2 m); outside it,
#: products and quotients of a few inputs overflow or underflow double precision.
MAGNITUDE_RANGE = (1e-15, 1e15)


class KeyProblem(ValueError):
    """A validator's problem with one key below the model that raises it (a table's rule that names
    its key, e.g. ``machines.1.mass``): the scene's error then names that key, not the table."""

    def __init__(self, key: str, message: str):
        super().__init__(message)
        #: the key's dotted path from the model that raises it ("machines.1.mass")
        self.key = key


class SceneModel(BaseModel):
    """Base of all scene models: unknown keys, NaN, inf and strings-for-numbers are rejected.

    Every number (also inside lists) must be 0 or within :data:`MAGNITUDE_RANGE`.
    """

    model_config = ConfigDict(extra="forbid", allow_inf_nan=False, strict=True, frozen=True)

    @field_validator("*", mode="after")
    @classmethod
    def _computable_magnitude(cls, value: Any) -> Any:
        low, high = MAGNITUDE_RANGE
        for number in value if isinstance(value, (tuple, list)) else (value,):
            if isinstance(number, float) and number != 0 and not low <= abs(number) <= high:
                raise ValueError(
                    f"must be 0 or of magnitude {low:g} to {high:g}"
                    " (beyond that the arithmetic overflows)"
                )
        return value


#: A length more than this many times the structure's own size is flagged as probably typed in
#: mm where m was meant (a plausibility warning, not an error) [-].
LENGTH_SCALE_FACTOR = 10.0


#: Range of a detuning band [-] (open at both ends) and of the orders it may name.
DETUNING_RANGE = (0.0, 1.0)
MAX_ORDER = 64


def detuning_bands(value: Any) -> float | dict[int, float]:
    """``[limits] detuning`` checked: a number in (0, 1), or a table order -> number in (0, 1)
    whose keys are whole orders 1 ... :data:`MAX_ORDER`; a message names the key, the value and
    the range.

    >>> detuning_bands({"1": 0.2, "3": 0.1}), detuning_bands(0.15)
    ({1: 0.2, 3: 0.1}, 0.15)
    """
    lo, hi = DETUNING_RANGE

    def band(v, where: str) -> float:
        if isinstance(v, bool) or not isinstance(v, (int, float)):
            raise ValueError(f"{where} must be a number in ({lo:g}, {hi:g}) [-], not {v!r}")
        if not lo < v < hi:
            raise ValueError(
                f"{where} = {v!r} is outside ({lo:g}, {hi:g}) [-]: a band is greater than {lo:g} and less than"
                f" {hi:g} (a relative distance: 0.2 is 20 %)"
            )
        return float(v)

    if isinstance(value, dict):
        if not value:
            raise ValueError("detuning = {} names no order: give a band per order, e.g. {1 = 0.2, 2 = 0.2}, or one number")
        bands = {}
        for key, v in value.items():
            text = str(key).strip()
            if not text.isdigit() or not 1 <= int(text) <= MAX_ORDER:
                raise ValueError(
                    f"detuning key {key!r} is not an order of the speed: keys are whole numbers 1 ... {MAX_ORDER}"
                    " (1 for ω, 2 for 2ω, ...)"
                )
            bands[int(text)] = band(v, f"detuning.{text}")
        return bands
    return band(value, "detuning")


def quantity(symbol: str, unit: str, text: str, default: Any = ..., **constraints: Any) -> Any:
    """A pydantic Field whose description reads ``"symbol [unit]: text"``."""
    return Field(default, description=f"{symbol} [{unit}]: {text}", **constraints)


def source(what: str, example: str) -> Any:
    """An optional ``source`` key: the document ``what`` comes from, printed beside it on the sheet."""
    return quantity(
        "-", "-", f"where {what} come from: a document (report, data sheet, clause), printed on the sheet",
        None, max_length=200, examples=[example],
    )


#: What the sheet prints beside a limit whose source the scene does not give.
NO_SOURCE = "scene value, no source given"


class LimitSources(SceneModel):
    """The ``sources`` key of a ``[limits]`` table: where each limit comes from, by its key."""

    sources: dict[str, str] = quantity(
        "-", "-", "where each limit comes from, by its key (a code clause, the client's specification);"
        " a limit without one is printed as a scene value with no source given", {},
        examples=[{"amplitude": "client spec. S-123, 4.2"}],
    )

    @model_validator(mode="after")
    def _sources_name_limits(self):
        known = sorted(set(type(self).model_fields) - {"sources"})
        unknown = sorted(set(self.sources) - set(known))
        if unknown:
            raise ValueError(f"sources names {', '.join(unknown)}, not a limit of this scene kind (one of {', '.join(known)})")
        return self

    def source_of(self, key: str) -> str:
        """Where the limit ``key`` comes from, as the sheet prints it beside the limit."""
        if key in self.sources:
            return self.sources[key]
        return NO_SOURCE if key in self.model_fields_set else "fcalc's default, no source given"


class SpeedFields(SceneModel):
    """The operating speed, given as exactly one of ``omega``, ``frequency_hz``, ``speed_rpm``."""

    omega: float | None = quantity("ω", "rad/s", "angular speed of the shaft", None, gt=0, examples=[31.4159])
    frequency_hz: float | None = quantity("f", "Hz", "rotation frequency of the shaft", None, gt=0, examples=[5.0])
    speed_rpm: float | None = quantity("n", "rpm", "shaft speed in revolutions per minute", None, gt=0, examples=[300.0])

    @model_validator(mode="after")
    def _exactly_one_speed(self):
        given = [k for k in ("omega", "frequency_hz", "speed_rpm") if getattr(self, k) is not None]
        if len(given) != 1:
            got = "none" if not given else " and ".join(given)
            raise ValueError(
                "give the speed as exactly one of omega [rad/s], frequency_hz [Hz] or speed_rpm [rpm]"
                f" (got {got})"
            )
        return self

    @property
    def omega_rad_s(self) -> float:
        """The speed in rad/s, whichever way the scene gave it."""
        if self.omega is not None:
            return self.omega
        if self.frequency_hz is not None:
            return omega_from_hz(self.frequency_hz)
        return omega_from_rpm(self.speed_rpm)

    @property
    def speed_given_as(self) -> str:
        """Which of the three keys the scene used."""
        return next(k for k in ("omega", "frequency_hz", "speed_rpm") if getattr(self, k) is not None)


class RunTimes(SceneModel):
    """Start-up and run-down times of an [operation] table (``fcalc runup``): linear speed ramps
    from rest to the operating speed and back (on a block, every machine to its own speed)."""

    run_up_time: float | None = quantity(
        "T_up", "s", "time of the linear speed ramp from rest to the operating speed (fcalc runup)", None, gt=0,
        examples=[10.0],
    )
    run_down_time: float | None = quantity(
        "T_down", "s", "time of the linear speed ramp from the operating speed to rest (fcalc runup)", None, gt=0,
        examples=[20.0],
    )


class Drive(SceneModel):
    """A motor of limited torque that starts the machine (fcalc runup): the speed then follows
    the torque against the load instead of a prescribed ramp."""

    torque: float | None = quantity(
        "T", "N m", "torque the motor gives from rest to the operating speed, referred to the exciter shaft",
        None, gt=0, examples=[200.0],
    )
    power: float | None = quantity(
        "P", "W", "rated power (instead of torque): T = power / rated_speed", None, gt=0, examples=[7.5e3]
    )
    rated_speed: float | None = quantity(
        "ω_r", "rad/s", "speed at which the rated power is given, referred to the exciter shaft", None, gt=0,
        examples=[157.0],
    )
    inertia: float = quantity(
        "J", "kg m²", "moment of inertia of the motor, couplings and shafts referred to the exciter shaft;"
        " fcalc adds the unbalances' (platform, a block machine's [machines.unbalance] and [[machines.exciters]])"
        " or the crank mechanism's mean inertia", ge=0, examples=[5.0],
    )

    @model_validator(mode="after")
    def _one_torque(self):
        if (self.torque is None) == (self.power is None):
            raise ValueError("give the motor as exactly one of torque [N m] or power [W] (with rated_speed [rad/s])")
        if self.power is not None and self.rated_speed is None:
            raise ValueError("power [W] needs rated_speed [rad/s], the speed at which it is rated")
        if self.torque is not None and self.rated_speed is not None:
            raise ValueError("rated_speed [rad/s] goes with power [W]; with torque [N m] leave it out")
        return self

    @property
    def available_torque(self) -> float:
        """T [N m]: the given torque, or power / rated_speed."""
        return self.torque if self.torque is not None else self.power / self.rated_speed
