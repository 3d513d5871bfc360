"""The ``[soil]`` table of a crank-foundation scene: one method and the keys that method takes.

``method = "coefficients"`` (the default when ``c_z`` is given) takes Barkan's coefficients as the
paper does; ``"lysmer"``, ``"gazetas"`` and ``"pais_kausel"`` take the soil's shear modulus (or
shear wave velocity), density and Poisson's ratio; ``"sp26"`` takes the static deformation modulus and the
soil class. A key of another method, or a misspelt one, is an error that lists the method's keys.
"""

from __future__ import annotations

import difflib
import re
from typing import ClassVar, Literal

from pydantic import field_validator, model_validator

from foundation_calc.scenes.common import SceneModel, quantity, source
from foundation_calc.scenes.plausibility import judge
from foundation_calc.solvers.soil.sp26 import B0_BY_CLASS

SoilMethod = Literal["coefficients", "lysmer", "gazetas", "pais_kausel", "sp26"]
SOIL_METHODS: tuple[str, ...] = ("coefficients", "lysmer", "gazetas", "pais_kausel", "sp26")

#: The methods of the elastic half-space (shear modulus or V_s, density, Poisson's ratio).
HALF_SPACE_METHODS: tuple[str, ...] = ("lysmer", "gazetas", "pais_kausel")

#: The methods whose springs and dashpots change with frequency (and that take the embedment).
FREQUENCY_DEPENDENT_METHODS: tuple[str, ...] = ("gazetas", "pais_kausel")

_HALF_SPACE_KEYS = ("shear_modulus", "shear_wave_velocity", "density", "poisson", "material_damping", "stratum_depth")

#: The keys each method takes (besides ``method``), in the order the messages list them.
METHOD_KEYS: dict[str, tuple[str, ...]] = {
    "coefficients": ("c_z", "c_x", "c_phi", "damping"),
    "lysmer": _HALF_SPACE_KEYS,
    "gazetas": _HALF_SPACE_KEYS,
    "pais_kausel": _HALF_SPACE_KEYS,
    "sp26": ("deformation_modulus", "soil_class"),
}

#: Largest spread of the soil's stiffness a ``modulus_range`` may bracket (factors within 1/10 .. 10).
MODULUS_FACTOR_LIMITS = (0.1, 10.0)

#: The keys each method cannot do without (lysmer and gazetas need one of G, V_s besides).
METHOD_REQUIRED: dict[str, tuple[str, ...]] = {
    "coefficients": ("c_z", "c_x"),
    "lysmer": ("density", "poisson"),
    "gazetas": ("density", "poisson"),
    "pais_kausel": ("density", "poisson"),
    "sp26": ("deformation_modulus", "soil_class"),
}


def _method_keys(method: str) -> str:
    return ", ".join(METHOD_KEYS[method])


class Soil(SceneModel):
    """The soil under the base, by one method: coefficients (c_z, c_x, c_phi, damping), lysmer, gazetas or pais_kausel (shear_modulus or shear_wave_velocity, density, poisson, material_damping, stratum_depth), sp26 (deformation_modulus, soil_class)."""

    #: What a missing ``[soil]`` table needs, for the message (no single key is required).
    required_keys_text: ClassVar[str] = (
        'c_z, c_x (Barkan\'s coefficients), or method = "lysmer", "gazetas", "pais_kausel" or "sp26" and its keys'
    )

    source: str | None = source("the soil's values (the soil report)", "soil report GR-12, table 3")
    method: SoilMethod | None = quantity(
        "-", "-", 'how the springs are found: "coefficients" (Barkan\'s c_z, c_x given), "lysmer"'
        ' (Richart-Hall-Woods analogs), "gazetas" (Gazetas 1991), "pais_kausel" (Pais & Kausel 1988),'
        ' "sp26" (SP 26.13330 from the static'
        ' modulus); default "coefficients" when c_z is given', None, examples=["lysmer"],
    )
    c_z: float | None = quantity("c", "N/m³", "coefficient of elastic uniform compression", None, gt=0, examples=[4.0e7])
    c_x: float | None = quantity("c1", "N/m³", "coefficient of elastic uniform shear", None, gt=0, examples=[2.8e7])
    c_phi: float | None = quantity(
        "c_φ", "N/m³", "coefficient of elastic non-uniform compression (rocking); default c_z, the paper's choice",
        None, gt=0, examples=[8.0e7],
    )
    damping: list[float] | None = quantity(
        "ξ", "-", "damping ratios [ξ_z, ξ_x, ξ_phi] of the vertical, horizontal and rocking modes;"
        " default: undamped", None, min_length=3, max_length=3, examples=[[0.1, 0.1, 0.05]],
    )
    shear_modulus: float | None = quantity(
        "G", "Pa", "small-strain shear modulus of the soil (or give shear_wave_velocity)", None, gt=0,
        examples=[7.2e7],
    )
    shear_wave_velocity: float | None = quantity(
        "V_s", "m/s", "shear wave velocity of the soil, G = ρ V_s² (or give shear_modulus)", None, gt=0,
        examples=[200.0],
    )
    density: float | None = quantity("ρ_s", "kg/m³", "mass density of the soil", None, gt=0, examples=[1800.0])
    poisson: float | None = quantity(
        "ν", "-", "Poisson's ratio of the soil (0.5: saturated clay, undrained)", None, ge=0, le=0.5, examples=[0.33]
    )
    material_damping: float | None = quantity(
        "D_m", "-", "material (hysteretic) damping ratio of the soil, added to each radiation damping"
        " ratio; typically 0.02-0.05; default 0", None, ge=0, le=0.3, examples=[0.03],
    )
    stratum_depth: float | None = quantity(
        "H", "m", "depth of the soil layer from the ground surface to rigid bedrock (lysmer, gazetas, pais_kausel):"
        " the springs stiffen (Kausel 1974) and the radiation dashpots vanish below the layer's cutoff frequencies"
        " V_s/4H (sway, torsion) and V_La/4H (vertical, rocking); default: no bedrock (a half-space)",
        None, gt=0, examples=[6.0],
    )
    deformation_modulus: float | None = quantity(
        "E", "Pa", "static deformation modulus of the soil from the site investigation (not 2G(1+ν) from V_s)",
        None, gt=0, examples=[3.0e7],
    )
    modulus_range: list[float] | None = quantity(
        "-", "-", "factors [low, high] on the soil's stiffness data (G or V_s², E, or c_z, c_x, c_phi); every"
        " spring and dashpot is recomputed from the factored data and a check passes only if it passes over"
        " the whole range (ACI 351.3R brackets the modulus, e.g. [0.5, 1.5]); default: the data as given",
        None, min_length=2, max_length=2, examples=[[0.5, 1.5]],
    )
    soil_class: Literal["sand", "sandy_loam", "loam", "clay", "coarse"] | None = quantity(
        "-", "-", "soil class of SP 26.13330, sets b0 [1/m]: "
        + ", ".join(f"{k} {v:g}" for k, v in B0_BY_CLASS.items()), None, examples=["sand"],
    )

    #: The keys each method takes; a kind with other methods (the block's) sets its own.
    method_keys: ClassVar[dict[str, tuple[str, ...]]] = METHOD_KEYS
    #: Keys of every method for the soil's uncertainty (a kind whose checks do not judge a range sets none).
    range_keys: ClassVar[tuple[str, ...]] = ("modulus_range",)
    #: What to say when neither a method nor c_z is given.
    no_method_text: ClassVar[str] = (
        'give soil.method = "lysmer", "gazetas", "pais_kausel" or "sp26" with its keys, or Barkan\'s'
        " coefficients soil.c_z and soil.c_x [N/m³] (method \"coefficients\")"
    )

    @model_validator(mode="before")
    @classmethod
    def _keys_of_the_method(cls, data):
        if not isinstance(data, dict):
            return data
        method = data.get("method")
        if method is None:
            if "c_z" not in data:
                raise ValueError(cls.no_method_text)
            method = "coefficients"
        if not isinstance(method, str) or method not in cls.method_keys:
            return data  # the field's own validation names the allowed methods
        allowed = set(cls.method_keys[method]) | {"method", "source", *cls.range_keys}
        keys = ", ".join((*cls.method_keys[method], *cls.range_keys))
        for key in data:
            if key in allowed:
                continue
            owners = [m for m, keys_of in cls.method_keys.items() if key in keys_of]
            if owners:
                names = [repr(m) for m in owners]
                named = names[0] if len(names) == 1 else f"{', '.join(names[:-1])} and {names[-1]}"
                raise ValueError(
                    f"soil.{key} is a key of method{'s' if len(names) > 1 else ''} {named}, not of"
                    f" {method!r}; the keys of {method!r} are {keys}"
                )
            close = difflib.get_close_matches(str(key), sorted(allowed), n=1, cutoff=0.6)
            hint = f" (did you mean {close[0]}?)" if close else ""
            raise ValueError(f"soil.{key!s:.60} is not a key of method {method!r}{hint}; its keys are {keys}")
        return data

    @field_validator("damping")
    @classmethod
    def _ratios_in_range(cls, damping):
        if damping is not None and not all(0.0 <= xi < 1.0 for xi in damping):
            raise ValueError(f"each damping ratio must be in [0, 1): got {list(damping)}")
        return damping

    @field_validator("modulus_range")
    @classmethod
    def _range_in_order(cls, factors):
        low, high = MODULUS_FACTOR_LIMITS
        if factors is not None and not low <= factors[0] <= factors[1] <= high:
            raise ValueError(f"must be [low, high] factors with {low:g} <= low <= high <= {high:g} [-]")
        return factors

    def factored(self, factor: float) -> Soil:
        """This soil with its stiffness data multiplied by ``factor`` [-] (and no range): c_z, c_x,
        c_phi; G (V_s by sqrt(factor)); or the deformation modulus E. Damping ratios, density,
        Poisson's ratio and the soil class stay."""
        method = self.method_used
        if method == "coefficients":
            c_z = self.c_z * factor
            update = {"c_z": c_z, "c_x": self.c_x * factor, "c_phi": None if self.c_phi is None else self.c_phi * factor}
        elif method == "sp26":
            update = {"deformation_modulus": self.deformation_modulus * factor}
        elif self.shear_modulus is not None:
            update = {"shear_modulus": self.shear_modulus * factor}
        else:
            update = {"shear_wave_velocity": self.shear_wave_velocity * factor**0.5}
        return self.model_copy(update=update | {"modulus_range": None})

    def missing_text(self, keys) -> str:
        """``soil.c_x [N/m³], soil.soil_class``: the ``keys`` this soil leaves out, each with the unit
        its field declares (none for text and ratios), for a method's message; "" if none is missing."""
        fields = type(self).model_fields
        units = {k: re.search(r"\[([^\]]+)\]", fields[k].description or "") for k in keys}
        return ", ".join(f"soil.{k}" + (f" [{u[1]}]" if u and u[1] != "-" else "") for k, u in units.items()
                         if getattr(self, k) is None)

    @model_validator(mode="after")
    def _method_has_its_data(self):
        method = self.method_used
        missing = self.missing_text(METHOD_REQUIRED[method])
        if missing:
            raise ValueError(f"method {method!r} needs {missing} (its keys: {_method_keys(method)})")
        if method in HALF_SPACE_METHODS and (self.shear_modulus is None) == (self.shear_wave_velocity is None):
            raise ValueError(
                f"method {method!r} needs exactly one of soil.shear_modulus [Pa] and"
                " soil.shear_wave_velocity [m/s]"
            )
        return self

    @property
    def method_used(self) -> str:
        """The method in force: the one given, else ``"coefficients"``."""
        return self.method or "coefficients"

    @property
    def frequency_dependent(self) -> bool:
        """True when the method's springs and dashpots change with frequency (``"gazetas"``,
        ``"pais_kausel"``, and any half-space method on a stratum, whose radiation stops below the layer's
        cutoff frequencies); Barkan's coefficients, Lysmer's analogs and SP 26 are frequency-independent."""
        return self.method_used in FREQUENCY_DEPENDENT_METHODS or self.stratum_depth is not None

    @property
    def G(self) -> float:
        """Shear modulus [Pa], given or ρ V_s² (half-space methods only)."""
        if self.shear_modulus is not None:
            return self.shear_modulus
        return self.density * self.shear_wave_velocity**2

    @property
    def V_s(self) -> float:
        """Shear wave velocity [m/s], given or sqrt(G/ρ) (half-space methods only)."""
        if self.shear_wave_velocity is not None:
            return self.shear_wave_velocity
        return (self.shear_modulus / self.density) ** 0.5

    def related_findings(self, prefix: str, found: list) -> list:
        """The derived V_s = sqrt(G/ρ) outside the range of shear wave velocities, when G and ρ
        themselves are plausible (``found``: the soil's findings): a slow V_s then means a static
        modulus where a dynamic one is meant (:func:`~foundation_calc.scenes.plausibility.findings`
        judges the keys themselves)."""
        if found or self.method_used not in HALF_SPACE_METHODS or self.shear_wave_velocity is not None:
            return []
        return judge(f"V_s = sqrt({prefix}shear_modulus/{prefix}density)", self.V_s, "shear_wave_velocity")

    @property
    def rocking_key(self) -> str:
        """The key of the scene's soil method that sets the rocking spring K_φ."""
        method = self.method_used
        if method == "coefficients":
            return "soil.c_phi" if self.c_phi is not None else "soil.c_z"
        if method == "sp26":
            return "soil.deformation_modulus"
        return "soil.shear_modulus" if self.shear_modulus is not None else "soil.shear_wave_velocity"

    @property
    def not_rocking(self) -> tuple[str, ...]:
        """The keys of the soil that no rocking spring depends on (never the culprit of a block that
        tips over): Barkan's c_x and c_ψ, and c_z when c_φ is given."""
        return ("soil.c_x", "soil.c_psi") + (("soil.c_z",) if self.c_phi is not None else ())

    def methods_allowed(self) -> tuple[str, ...]:
        """Every method the data allow: the half-space data feed Lysmer, Gazetas and Pais & Kausel."""
        if self.method_used in HALF_SPACE_METHODS:
            return HALF_SPACE_METHODS
        return (self.method_used,)


class OnSoil:
    """A scene standing on a ``soil`` (a :class:`Soil`) whose stiffness a modulus factor scales."""

    def with_modulus_factor(self, factor: float):
        """This scene on the soil whose stiffness data are multiplied by ``factor`` [-]
        (:meth:`Soil.factored`; the copy has no ``modulus_range``)."""
        return self.model_copy(update={"soil": self.soil.factored(factor)})
