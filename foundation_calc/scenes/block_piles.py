"""The ``[piles]`` table of a block foundation: a pile group under the block, the block's base its
rigid cap, and the data of the support that replaces the footing's springs by the group's (its
springs and dashpots: :mod:`foundation_calc.solvers.supports.piles`).

The soil around and under the piles is the scene's ``[soil]`` table (a half-space method's keys:
shear_modulus or shear_wave_velocity, density, poisson, material_damping), its modulus taken at
the depth of one pile diameter (EN 1998-5 Annex C's E_s) and varying with depth as
``soil_profile`` says. The group's springs and dashpots at O
(:func:`~foundation_calc.solvers.piles.cap.pile_group`, assembled by
:class:`~foundation_calc.solvers.supports.piles.Piles`) are frequency-dependent, with the
sway-rocking coupling of the piles' heads; the cap's own contact with the soil (``cap_contact``),
or the sidewalls of an embedded cap (``block.embedment``), add the footing's springs of the soil
method in parallel.
"""

from __future__ import annotations

from typing import Annotated, Literal

import numpy as np
from pydantic import Field, PrivateAttr, field_validator, model_validator

from foundation_calc.scenes.block_soil import BlockSoil
from foundation_calc.scenes.common import SceneModel, quantity
from foundation_calc.scenes.plausibility import Remark
from foundation_calc.scenes.soil import HALF_SPACE_METHODS
from foundation_calc.solvers.supports.pile_sizes import VALIDITY, closest, heads, shorter_than_active, slenderness_outside, too_close

#: A pile head in the base plane: [x, y] from O [m].
Head = Annotated[list[float], Field(min_length=2, max_length=2)]

class BlockPiles(SceneModel):
    """Piles under the block, their heads in the base plane, the base their rigid cap."""

    diameter: float = quantity("d", "m", "pile diameter", gt=0, examples=[0.6])
    length: float = quantity("L", "m", "pile length below the base", gt=0, examples=[15.0])
    modulus: float = quantity("E_p", "Pa", "Young's modulus of the pile's material (concrete about 3.0e10)", gt=0,
                              examples=[3.0e10])
    density: float = quantity("ρ_p", "kg/m³", "density of the pile's material (reinforced concrete about 2500)", gt=0,
                              examples=[2500.0])
    positions: list[Head] = quantity(
        "r_i", "m", "the pile heads [x, y] in the base plane, from O (the centre of the base)", min_length=1,
        examples=[[[-2.0, -1.2], [2.0, -1.2], [-2.0, 1.2], [2.0, 1.2]]],
    )
    head: Literal["fixed", "pinned"] = quantity(
        "-", "-", '"fixed" into the cap (the heads turn with it and carry moments) or "pinned" (free to turn)',
        examples=["fixed"],
    )
    soil_profile: Literal["uniform", "linear", "parabolic"] = quantity(
        "-", "-", "the soil's modulus with depth z below the base: \"uniform\" E_s, \"linear\" E_s z/d,"
        " \"parabolic\" E_s sqrt(z/d) (EN 1998-5 Table C.1), E_s = 3 G (the table's soil model) from [soil] at z = d",
        examples=["uniform"],
    )
    tip: Literal["floating", "end_bearing"] = quantity(
        "-", "-", '"floating" (the tip in the same soil) or "end_bearing" (the tip on rock); default "floating",'
        " the softer", "floating", examples=["end_bearing"],
    )
    cap_contact: bool = quantity(
        "-", "-", "whether the cap's base also bears on the soil (its footing springs of [soil]'s method in"
        " parallel); default false, as is usual (the soil settles away from a piled cap)", False,
    )

    @field_validator("positions")
    @classmethod
    def _apart(cls, positions):
        seen = {}
        for i, p in enumerate(positions):
            key = (round(p[0], 6), round(p[1], 6))
            if key in seen:
                raise ValueError(f"piles.positions[{i}] = {list(p)} m repeats piles.positions[{seen[key]}]")
            seen[key] = i
        return positions

    @model_validator(mode="after")
    def _do_not_overlap(self):
        xy = np.array(self.positions, dtype=float)
        S = np.hypot(*(xy[:, None, :] - xy[None, :, :]).transpose(2, 0, 1))
        S[np.diag_indices(len(xy))] = np.inf
        if S.min() < self.diameter:
            i, j = np.unravel_index(np.argmin(S), S.shape)
            raise ValueError(f"piles.positions[{i}] and [{j}] are {S.min():.4g} m apart, less than piles.diameter ="
                             f" {self.diameter:g} m: the piles overlap (centre distance >= d)")
        return self

    def related_findings(self, prefix: str, found: list) -> list:
        """L/d outside the range Randolph & Wroth's closed form was compared over (:data:`VALIDITY`)."""
        low, high = VALIDITY["slenderness"]
        ratio = self.length / self.diameter
        if not slenderness_outside(self.diameter, self.length):
            return []
        return [Remark(f"{prefix}length", f"{prefix}length/{prefix}diameter = {ratio:.3g} is outside {low:g}-{high:g},"
                                          " the range Randolph & Wroth's vertical stiffness was compared over")]


class PiledSoil(BlockSoil):
    """The scene's soil with the pile group standing in it: the data of a block's support on piles
    (:class:`~foundation_calc.solvers.supports.piles.Piles` computes its springs and dashpots at O);
    the soil's own keys are the user's ``[soil]``."""

    _piles: BlockPiles = PrivateAttr()
    _plan: tuple[float, float] = PrivateAttr()
    _dims: tuple | None = PrivateAttr(default=None)

    @classmethod
    def on(cls, soil: BlockSoil, piles: BlockPiles, plan: tuple[float, float]) -> PiledSoil:
        """``soil`` carrying ``piles`` under a base of ``plan`` (L, B) [m] (the positions' scale)."""
        if soil.method_used not in HALF_SPACE_METHODS:
            raise ValueError(f"[piles] stand in a soil given by its shear modulus or shear wave velocity, density and"
                             f" Poisson's ratio: soil.method = {soil.method_used!r} gives none; use"
                             f" {', '.join(repr(m) for m in HALF_SPACE_METHODS)}")
        piled = cls.model_validate(soil.model_dump(exclude_unset=True))
        piled._piles, piled._plan = piles, tuple(plan)
        return piled

    def with_dimensions(self, d, L) -> PiledSoil:
        """This support with the piles' diameter ``d`` and length ``L`` [m] replaced (arrays over a batch of
        candidate designs, ``fcalc design``; their axis the candidates' leading one)."""
        copy = self.model_copy()
        copy._piles, copy._plan, copy._dims = self._piles, self._plan, (np.asarray(d, dtype=float), np.asarray(L, dtype=float))
        return copy

    @property
    def piles(self) -> BlockPiles:
        """The ``[piles]`` table."""
        return self._piles

    @property
    def plan(self) -> tuple[float, float]:
        """(L, B) [m]: the base the positions are given under (they scale with a candidate base)."""
        return self._plan

    @property
    def dimensions(self) -> tuple | None:
        """(d, L) [m] of :meth:`with_dimensions` (arrays over a batch of candidates), or None: the table's."""
        return self._dims

    @property
    def frequency_dependent(self) -> bool:
        """A pile group's springs and dashpots always depend on frequency."""
        return True

    @property
    def rocking_key(self) -> str:
        """The key that sets the rocking springs: the piles' positions (their arms)."""
        return "piles.positions"

    def related_findings(self, prefix: str, found: list) -> list:
        """The soil's own (:meth:`Soil.related_findings`) and where the piles leave the ranges of
        their closed forms (:data:`VALIDITY`, :mod:`~foundation_calc.solvers.supports.pile_sizes`):
        E_p/E_s, the length against the active length (Table C.1 holds for flexible piles,
        L >= l_a) and the spacing."""
        p, remarks = self._piles, list(super().related_findings(prefix, found))
        E_s = 3.0 * self.G  # EN 1998-5 Annex C: the soil model's Young's modulus, 3 G
        low, high = VALIDITY["stiffness_ratio"]
        ratio = p.modulus / E_s
        if not low <= ratio <= high:
            remarks.append(Remark("piles.modulus", f"E_p/E_s = {ratio:.4g} (E_s = 3 G = {E_s:.4g} Pa) is outside"
                                  f" {low:g}-{high:g}, the range of EN 1998-5 Table C.1's fits"))
        short, l_a = shorter_than_active(p.diameter, p.length, E_s, p.modulus, p.soil_profile)
        if short:
            remarks.append(Remark("piles.length", f"piles.length = {p.length:g} m is shorter than the active length"
                                  f" l_a = {l_a:.3g} m: the piles are not flexible, and Table C.1 (flexible piles)"
                                  " overstates their lateral stiffness"))
        S_min = float(closest(*heads(p.positions, self._plan, *self._plan)))
        if too_close(S_min, p.diameter):
            remarks.append(Remark("piles.positions", f"the closest piles are {S_min:.3g} m = {S_min / p.diameter:.3g} d"
                                  f" apart, below the {VALIDITY['spacing']:g} d Dobry & Gazetas' factors were"
                                  " verified from"))
        return remarks


#: How far [m] a pile head may lie outside the base's edge (round-off of a position typed at the edge).
ON_BASE = 1e-3


def piled(soil, piles: BlockPiles, plan: tuple[float, float], *, stratum_key: str = "soil.stratum_depth") -> PiledSoil:
    """``soil`` with ``piles`` standing in it under a base of ``plan`` (L, B) [m]
    (:meth:`PiledSoil.on`), the one place a scene's support becomes a pile group, for a block and a
    crank scene alike. Raises ValueError for a stratum under the piles (not modelled) and for a pile
    head outside the base (the base is their cap; O its centre)."""
    if getattr(soil, "stratum_depth", None) is not None:
        raise ValueError(
            f"{stratum_key} = {soil.stratum_depth:g} m with [piles]: a layer over rock under piles is not"
            " modelled (the piles' springs and dashpots are those of a deep soil); remove the key, and for"
            ' piles that reach the rock give piles.tip = "end_bearing"'
        )
    L, B = plan
    for i, (x, y) in enumerate(piles.positions):
        if abs(x) > L / 2.0 + ON_BASE or abs(y) > B / 2.0 + ON_BASE:
            raise ValueError(f"piles.positions[{i}] = [{x:g}, {y:g}] m is outside the block's base (|x| <= L/2 ="
                             f" {L / 2.0:g} m, |y| <= B/2 = {B / 2.0:g} m; O is the centre of the base): the base is"
                             " the piles' cap")
    return PiledSoil.on(soil, piles, plan)


__all__ = ["ON_BASE", "BlockPiles", "PiledSoil", "VALIDITY", "piled"]
