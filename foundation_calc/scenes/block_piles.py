"""The ``[piles]`` table of a block foundation: a pile group under the block, the block's base its
rigid cap, and the support that replaces the footing's springs by the group's.

The soil around and under the piles is the scene's ``[soil]`` table (a half-space method's keys:
shear_modulus or shear_wave_velocity, density, poisson, material_damping), its modulus taken at
the depth of one pile diameter (EN 1998-5 Annex C's E_s) and varying with depth as
``soil_profile`` says. The group's springs and dashpots at O
(:func:`~foundation_calc.solvers.piles.cap.pile_group`) are frequency-dependent, with the
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

#: A pile head in the base plane: [x, y] from O [m].
Head = Annotated[list[float], Field(min_length=2, max_length=2)]

#: The ranges the single pile's closed forms were fitted or verified over (module docstrings of
#: :mod:`~foundation_calc.solvers.piles.single` and :mod:`~foundation_calc.solvers.piles.group`):
#: E_p/E_s (Gazetas 1991 fitted Table C.1 over 300-10 000; fcalc warns from 100), L/d (Randolph &
#: Wroth compared with the continuum for L/d 10-100), S/d (Dobry & Gazetas verified 2-10 against
#: Kaynia & Kausel; wider spacings tend to independent piles, which their form keeps).
VALIDITY = {"stiffness_ratio": (100.0, 1.0e4), "slenderness": (10.0, 100.0), "spacing": 2.0}


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

    def spacings(self) -> np.ndarray:
        """The distances between every two pile axes [m], (n, n), 0 on the diagonal."""
        xy = np.array(self.positions, dtype=float)
        return np.hypot(*(xy[:, None, :] - xy[None, :, :]).transpose(2, 0, 1))

    def related_findings(self, prefix: str, found: list) -> list:
        """L/d outside the range Randolph & Wroth's closed form was compared over (:data:`VALIDITY`)."""
        low, high = VALIDITY["slenderness"]
        ratio = self.length / self.diameter
        if low <= ratio <= high:
            return []
        return [Remark(f"{prefix}length", f"{prefix}length/{prefix}diameter = {ratio:.3g} is outside {low:g}-{high:g},"
                                          " the range Randolph & Wroth's vertical stiffness was compared over")]


class PiledSoil(BlockSoil):
    """The scene's soil with the pile group standing in it: the support of a block on piles. Its
    springs and dashpots at O are the group's (:meth:`impedance`), with the footing's where the cap
    bears on the soil or is embedded; the soil's own keys are the user's ``[soil]``."""

    _piles: BlockPiles = PrivateAttr()
    _plan: tuple[float, float] = PrivateAttr()
    _dims: tuple | None = PrivateAttr(default=None)
    _last: tuple | None = PrivateAttr(default=None)  # (arguments, matrices) of the last call: six_springs, then coupling

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
    def frequency_dependent(self) -> bool:
        """A pile group's springs and dashpots always depend on frequency."""
        return True

    @property
    def support_method(self) -> str:
        """``"piles"``: the range of validity judged is the piles' (:data:`~foundation_calc.solvers.piles.single.A0_FITTED`)."""
        return "piles"

    @property
    def rocking_key(self) -> str:
        """The key that sets the rocking springs: the piles' positions (their arms)."""
        return "piles.positions"

    def group(self, L, B, omega):
        """The group's impedance K + iω C at O, complex omega.shape + (6, 6), the positions scaled
        with the base L × B [m] (arrays over a batch of candidate blocks)."""
        from foundation_calc.solvers.piles.cap import pile_group

        p = self._piles
        xy = np.array(p.positions, dtype=float)
        L0, B0 = self._plan
        x = xy[:, 0] * (np.asarray(L, dtype=float)[..., None] / L0)
        y = xy[:, 1] * (np.asarray(B, dtype=float)[..., None] / B0)
        d, length = (p.diameter, p.length) if self._dims is None else (
            np.reshape(v, np.shape(v) + (1,) * (np.ndim(L) - np.ndim(v))) for v in self._dims)
        return pile_group(x, y, d, length, p.modulus, p.density, self.G, self.poisson, self.density,
                          self.material_damping or 0.0, p.soil_profile, p.tip == "end_bearing", p.head == "pinned",
                          omega)

    def _footing(self, L, B, M, J_O, omega, D):
        """The cap's own springs and radiation dashpots (diagonal, six each) where it touches the soil:
        the whole footing with ``cap_contact``, else the embedded sidewalls only (embedded less
        surface), else none."""
        m = [M, M, M, *J_O]
        if not self._piles.cap_contact and not np.any(np.asarray(D) > 0):
            return 0.0, 0.0
        xi_m = self.material_damping or 0.0

        def parts(depth):
            springs, ratios = BlockSoil.six_springs(self, L, B, M, J_O, omega, depth)
            return np.stack(np.broadcast_arrays(*springs), -1), np.stack(np.broadcast_arrays(
                *[2.0 * (r - xi_m) * np.sqrt(k * mi) for r, k, mi in zip(ratios, springs, m)]), -1)

        K, C = parts(D)
        if self._piles.cap_contact:
            return K, C
        K0, C0 = parts(0.0)
        return K - K0, C - C0

    def matrices(self, L, B, M, J_O, omega=0.0, D=0.0):
        """(K, C) at O, each omega.shape + (6, 6): the group's and the cap's footing (:meth:`_footing`)."""
        from foundation_calc.solvers.piles.cap import springs_and_dashpots

        own = (self.G, self.poisson, self.density, self.material_damping or 0.0, *(self._dims or ()))  # copies share _last
        args = [np.asarray(a, dtype=float) for a in (L, B, M, *J_O, omega, D, *own)]
        if self._last is not None and len(self._last[0]) == len(args) and all(
                a.shape == b.shape and np.array_equal(a, b) for a, b in zip(self._last[0], args)):
            return self._last[1]
        K, C = springs_and_dashpots(lambda w: self.group(L, B, w), omega)
        K_f, C_f = self._footing(L, B, M, J_O, omega, D)
        eye = np.eye(6)
        found = K + np.asarray(K_f)[..., None] * eye, C + np.asarray(C_f)[..., None] * eye
        self._last = (args, found)
        return found

    def six_springs(self, L, B, M, J_O, omega=0.0, D=0.0):
        """The diagonal of :meth:`matrices`: springs at O and the damping ratios ξ_i = C_ii/(2 sqrt(|K_ii| m_i))
        plus the soil's material damping, m_i the mass (translations) or the moment of inertia about
        the axis through O (rotations), as :meth:`BlockSoil.six_springs` gives them (a group's dynamic
        spring can be negative at high frequency, where the interaction of its piles makes it so)."""
        K, C = self.matrices(L, B, M, J_O, omega, D)
        k, c = np.diagonal(K, 0, -2, -1), np.diagonal(C, 0, -2, -1)
        m = [M, M, M, *J_O]
        xi_m = self.material_damping or 0.0
        springs = [k[..., i] for i in range(6)]
        return springs, [c[..., i] / (2.0 * np.sqrt(np.abs(k[..., i]) * m[i])) + xi_m for i in range(6)]

    def coupling(self, L, B, M, J_O, omega=0.0, D=0.0):
        """The off-diagonal parts of :meth:`matrices` (K, C), each omega.shape + (6, 6): the heads'
        sway-rocking coupling and the group's."""
        K, C = self.matrices(L, B, M, J_O, omega, D)
        off = 1.0 - np.eye(6)
        return K * off, C * off

    def related_findings(self, prefix: str, found: list) -> list:
        """The soil's own (:meth:`Soil.related_findings`) and where the piles leave the ranges of
        their closed forms (:data:`VALIDITY`): E_p/E_s, the length against the active length
        (Table C.1 holds for flexible piles, L >= l_a) and the spacing."""
        from foundation_calc.solvers.piles.single import active_length

        p, remarks = self._piles, list(super().related_findings(prefix, found))
        E_s = 3.0 * self.G  # EN 1998-5 Annex C: the soil model's Young's modulus, 3 G
        low, high = VALIDITY["stiffness_ratio"]
        ratio = p.modulus / E_s
        if not low <= ratio <= high:
            remarks.append(Remark("piles.modulus", f"E_p/E_s = {ratio:.4g} (E_s = 3 G = {E_s:.4g} Pa) is outside"
                                  f" {low:g}-{high:g}, the range of EN 1998-5 Table C.1's fits"))
        l_a = float(active_length(E_s, p.modulus, p.diameter, p.soil_profile))
        if p.length < l_a:
            remarks.append(Remark("piles.length", f"piles.length = {p.length:g} m is shorter than the active length"
                                  f" l_a = {l_a:.3g} m: the piles are not flexible, and Table C.1 (flexible piles)"
                                  " overstates their lateral stiffness"))
        S = p.spacings()
        if len(S) > 1:
            S_min = S[~np.eye(len(S), dtype=bool)].min()
            if S_min < VALIDITY["spacing"] * p.diameter:
                remarks.append(Remark("piles.positions", f"the closest piles are {S_min:.3g} m = {S_min / p.diameter:.3g} d"
                                      f" apart, below the {VALIDITY['spacing']:g} d Dobry & Gazetas' factors were"
                                      " verified from"))
        return remarks


__all__ = ["BlockPiles", "PiledSoil", "VALIDITY"]
