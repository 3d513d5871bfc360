"""Scene model of a block foundation's base and mass: ``[foundation]`` of kind ``crank_foundation``.

The base is given by its area and second moment or by its length and width; the mass properties
directly or from a concrete block and the machine on it (``[foundation.block]``,
``[foundation.machine]``). Values given both ways must agree within :data:`AGREEMENT`.
"""

from __future__ import annotations

from typing import ClassVar

from pydantic import model_validator

from foundation_calc.scenes.common import SceneModel, quantity
from foundation_calc.scenes.plausibility import RANGES, Remark

#: Relative difference within which a given value and the same value computed from other keys
#: (base_area from base_length × base_width, mass from the block…) count as agreeing [-]:
#: room for inputs rounded to 3 significant figures.
AGREEMENT = 5e-3


class Block(SceneModel):
    """A prismatic block of concrete (or another material) standing on its own footprint."""

    length: float = quantity("L_b", "m", "block length along the plane of motion (x)", gt=0, examples=[4.0])
    width: float = quantity("B_b", "m", "block width, normal to the plane of motion", gt=0, examples=[2.0])
    height: float = quantity("H_b", "m", "block height", gt=0, examples=[1.5])
    density: float = quantity(
        "ρ_c", "kg/m³", "density of the block's material (reinforced concrete about 2400-2500)", gt=0,
        examples=[2400.0],
    )


class Machine(SceneModel):
    """The machine on the block (frame and stator; the rod and the slider are in [mechanism])."""

    mass: float = quantity("m_m", "kg", "machine mass without rod and slider", gt=0, examples=[6000.0])
    cog_height: float = quantity(
        "h_m", "m", "height of the machine's centre of mass above the base, over the base's centroid", gt=0,
        examples=[2.0],
    )
    moment_of_inertia: float = quantity(
        "I_m", "kg m²", "about the machine's own centre of mass, axis normal to the plane of motion;"
        " default 0 (the machine as a point mass)", 0.0, ge=0,
    )


def _disagreement(key: str, unit: str, given: float, computed: float, source: str) -> str | None:
    """The message when ``given`` and ``computed`` differ by more than :data:`AGREEMENT`."""
    if abs(given - computed) <= AGREEMENT * abs(computed):
        return None
    return (
        f"foundation.{key} = {given:g} {unit} disagrees with {computed:.6g} {unit} from {source}"
        f" by {abs(given - computed) / computed:.2%} (they must agree within {AGREEMENT:.1%};"
        f" leave foundation.{key} out to use the computed value)"
    )


class Foundation(SceneModel):
    """The rigid block (foundation and machine frame, without the rod and the slider).

    The base is given by ``base_length`` and ``base_width`` or by ``base_area`` and
    ``base_second_moment``; the mass properties by ``mass``, ``moment_of_inertia`` and
    ``cog_height`` or by ``[foundation.block]`` and ``[foundation.machine]``. A value given both
    ways must agree within :data:`AGREEMENT`; the computed one fills a value left out.
    """

    #: What a missing ``[foundation]`` table needs, for the message (no single key is required).
    required_keys_text: ClassVar[str] = (
        "mass, moment_of_inertia, cog_height (or [foundation.block]) and base_area, base_second_moment"
        " (or base_length, base_width)"
    )

    mass: float | None = quantity(
        "M", "kg", "block and machine frame, without rod and slider (or from [foundation.block])", None, gt=0,
        examples=[1.0e5],
    )
    moment_of_inertia: float | None = quantity(
        "I_c", "kg m²", "about the block's centre of mass C, axis normal to the plane of motion", None, gt=0,
        examples=[4.5e5],
    )
    cog_height: float | None = quantity(
        "h", "m", "height of the centre of mass C above the base", None, gt=0, examples=[1.5]
    )
    base_area: float | None = quantity(
        "S", "m²", "area of the base in contact with the soil (or base_length × base_width)", None, gt=0,
        examples=[30.0],
    )
    base_second_moment: float | None = quantity(
        "I1", "m⁴", "second moment of the base area about its centroidal axis normal to the plane"
        " (or base_width × base_length³/12)", None, gt=0, examples=[90.0],
    )
    base_length: float | None = quantity(
        "L", "m", "base length along x, in the plane of motion", None, gt=0, examples=[6.0]
    )
    base_width: float | None = quantity(
        "B", "m", "base width, normal to the plane of motion", None, gt=0, examples=[5.0]
    )
    embedment: float | None = quantity(
        "D", "m", "depth of the base below the ground surface, sidewalls in contact (Gazetas' method);"
        " default 0, a surface footing", None, ge=0, examples=[1.0],
    )
    block: Block | None = quantity("-", "-", "the block whose mass properties are computed", None)
    machine: Machine | None = quantity("-", "-", "the machine on the block (needs [foundation.block])", None)

    @model_validator(mode="after")
    def _fill_computed(self):
        problems: list[str] = []
        base = self._base_dimensions(problems)
        if base is not None:
            L, B = base
            for key, unit, value in (("base_area", "m²", L * B), ("base_second_moment", "m⁴", B * L**3 / 12.0)):
                self._set_or_compare(key, unit, value, "the base's length and width", problems)
        missing = [k for k in ("base_area", "base_second_moment") if getattr(self, k) is None]
        if missing and not problems:
            fields = type(self).model_fields
            problems.extend(
                f"foundation.{k} is missing (allowed > 0; {fields[k].description}); give it, or"
                " foundation.base_length and foundation.base_width [m]"
                for k in missing
            )
        if self.machine is not None and self.block is None:
            problems.append("foundation.machine needs [foundation.block] (the block it stands on)")
        if self.block is not None:
            for key, unit, value in self._block_properties():
                self._set_or_compare(key, unit, value, "[foundation.block] and [foundation.machine]", problems)
        absent = [k for k in ("mass", "moment_of_inertia", "cog_height") if getattr(self, k) is None]
        if absent:
            fields = type(self).model_fields
            problems.extend(
                f"foundation.{k} is missing (allowed > 0; {fields[k].description}); give it, or"
                " [foundation.block] (length, width, height, density) to compute it"
                for k in absent
            )
        if problems:
            raise ValueError("; ".join(problems))
        return self

    def _block_properties(self) -> list[tuple[str, str, float]]:
        """(key, unit, value) of the mass, moment of inertia and cog height of block and machine."""
        from foundation_calc.solvers.crank.block import block_with_machine

        b, m = self.block, self.machine
        props = block_with_machine(
            b.length, b.width, b.height, b.density,
            0.0 if m is None else m.mass,
            0.0 if m is None else m.cog_height,
            0.0 if m is None else m.moment_of_inertia,
        )
        return [("mass", "kg", float(props.M)), ("moment_of_inertia", "kg m²", float(props.I_c)),
                ("cog_height", "m", float(props.h))]

    def _base_dimensions(self, problems: list[str]) -> tuple[float, float] | None:
        """(L, B) from base_length and base_width, else from the block's footprint, else None."""
        L, B = self.base_length, self.base_width
        if (L is None) != (B is None):
            problems.append("give both foundation.base_length and foundation.base_width [m], or neither")
            return None
        if self.block is not None:
            if L is None:
                return self.block.length, self.block.width
            for key, value, own in (("base_length", L, self.block.length), ("base_width", B, self.block.width)):
                found = _disagreement(key, "m", value, own, "the block's footprint")
                if found:
                    problems.append(found)
        return None if L is None else (L, B)

    def _set_or_compare(self, key: str, unit: str, value: float, source: str, problems: list[str]) -> None:
        """Fill ``key`` with the computed ``value``, or check that the given one agrees with it."""
        given = getattr(self, key)
        if given is None:
            self.__dict__[key] = value  # frozen once validated; filling a left-out value is validation
        else:
            found = _disagreement(key, unit, given, value, source)
            if found:
                problems.append(found)

    def given(self, key: str) -> bool:
        """True when the scene file gives ``key`` (not computed from other keys)."""
        return key in self.model_fields_set

    def related_findings(self, prefix: str, found: list) -> list:
        """A base given by S and I1 alone whose rectangle lies outside the plausible plan dimensions,
        when the foundation's keys themselves are plausible (``found``: their findings;
        :func:`~foundation_calc.scenes.plausibility.findings` judges the keys the scene gives, a value
        computed from other keys through them)."""
        if self.given("base_second_moment") and not self.given("base_length") and self.block is None and not found:
            return self._base_rectangle_findings()
        return []

    def _base_rectangle_findings(self) -> list:
        """I1 that makes the base a rectangle outside the plausible plan dimensions, given S."""
        L, B = self.dimensions
        plausible = RANGES["block_length"]
        if all(plausible.low <= side <= plausible.high for side in (L, B)):
            return []
        return [Remark(
            "foundation.base_second_moment",
            f"foundation.base_second_moment = {self.base_second_moment:.5g} m⁴ with foundation.base_area ="
            f" {self.base_area:.5g} m² is a rectangle {L:.4g} m × {B:.4g} m (L = sqrt(12 I1/S) in the plane of"
            f" motion, B = S/L), outside the plausible {plausible.quantity}, {plausible.low:g} to"
            f" {plausible.high:g} m [{plausible.source}]; check both values and their units (m⁴, m²)",
        )]

    def lengths_given(self) -> dict[str, float]:
        """The heights of centres of mass that the scene gives, by key as written [m]."""
        found = {"foundation.cog_height": self.cog_height} if self.given("cog_height") else {}
        if self.machine is not None:
            found["foundation.machine.cog_height"] = self.machine.cog_height
        return found

    @property
    def dimensions(self) -> tuple[float, float]:
        """(L, B) of the rectangular base: given, the block's, or from S and I1 (L = sqrt(12 I1/S), B = S/L) [m]."""
        if self.base_length is not None:
            return self.base_length, self.base_width
        if self.block is not None:
            return self.block.length, self.block.width
        L = (12.0 * self.base_second_moment / self.base_area) ** 0.5
        return L, self.base_area / L


__all__ = ["AGREEMENT", "Block", "Foundation", "Machine"]
