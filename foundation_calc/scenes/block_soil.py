"""The ``[soil]`` table of a block foundation: explicit springs at O, or a soil method that gives
all six springs of the base.

``method = "springs"`` takes ``stiffness`` and ``dashpot`` as 6-vectors at O (x, y, z, about x,
about y, about z). ``"coefficients"`` takes Barkan's c_z, c_x, c_phi as for a crank foundation and
a torsion coefficient c_psi; the half-space and code methods keep the keys of
:class:`~foundation_calc.scenes.soil.Soil`. The scene reads and validates the keys; the springs
and damping ratios are :func:`~foundation_calc.solvers.supports.footing_springs.six_springs`.
"""

from __future__ import annotations

from typing import Annotated, ClassVar, Literal

from pydantic import Field, model_validator

from foundation_calc.scenes.common import quantity
from foundation_calc.scenes.soil import HALF_SPACE_METHODS, METHOD_KEYS, METHOD_REQUIRED, Soil
from foundation_calc.solvers.supports.footing_springs import BARKAN_TORSION_RATIO

#: Six components: along x, y, z and about x, y, z.
Six = Annotated[list[float], Field(min_length=6, max_length=6)]

#: The keys each method of a block's soil takes (besides ``method``).
BLOCK_METHOD_KEYS: dict[str, tuple[str, ...]] = {
    "springs": ("stiffness", "dashpot"),
    "coefficients": ("c_z", "c_x", "c_phi", "c_psi", "damping"),
    "lysmer": METHOD_KEYS["lysmer"],
    "gazetas": METHOD_KEYS["gazetas"],
    "pais_kausel": METHOD_KEYS["pais_kausel"],
    "sp26": METHOD_KEYS["sp26"],
}

class BlockSoil(Soil):
    """The soil under the block, by one method: springs (stiffness, dashpot at O), coefficients (c_z, c_x, c_phi, c_psi, damping), lysmer (shear_modulus or shear_wave_velocity, density, poisson, material_damping, stratum_depth)."""

    method_keys: ClassVar[dict[str, tuple[str, ...]]] = BLOCK_METHOD_KEYS
    no_method_text: ClassVar[str] = (
        'give soil.method = "springs" with stiffness [N/m, N m/rad] (and dashpot), "lysmer" with its keys, or'
        " Barkan's coefficients soil.c_z and soil.c_x [N/m³] (method \"coefficients\")"
    )

    method: Literal["springs", "coefficients", "lysmer", "gazetas", "pais_kausel", "sp26"] | None = quantity(
        "-", "-", 'how the six springs are found: "springs" (stiffness and dashpot at O given), "coefficients"'
        " (Barkan's c_z, c_x, c_phi, c_psi), \"lysmer\" (Richart-Hall-Woods analogs), \"gazetas\" (Gazetas 1991)"
        " or \"pais_kausel\" (Pais & Kausel 1988), both embedded by block.embedment, from shear_modulus or"
        " shear_wave_velocity, density, poisson, \"sp26\" (SP 26.13330 from deformation_modulus and soil_class); default"
        " \"coefficients\" when c_z is given", None,
        examples=["springs"],
    )
    stiffness: Six | None = quantity(
        "K", "N/m, N m/rad", "springs at O along x, y, z and about x, y, z", None,
        examples=[[1.2e9, 1.0e9, 1.5e9, 9.0e9, 1.4e10, 8.0e9]],
    )
    dashpot: Six | None = quantity(
        "C", "N s/m, N m s/rad", "dashpots at O along x, y, z and about x, y, z; default none", None,
        examples=[[3.0e7, 2.8e7, 4.0e7, 5.0e7, 8.0e7, 3.0e7]],
    )
    c_psi: float | None = quantity(
        "c_ψ", "N/m³", f"coefficient of elastic non-uniform shear (torsion about z), spring c_ψ J_z with J_z the"
        f" base's polar second moment; default {BARKAN_TORSION_RATIO:g} c_x (Barkan)", None, gt=0, examples=[4.2e7],
    )
    damping: list[float] | None = quantity(
        "ξ", "-", "damping ratios [ξ_z, ξ_x, ξ_phi] or [ξ_z, ξ_x, ξ_phi, ξ_psi] of the vertical, horizontal, rocking"
        " and torsional modes (ξ_psi default ξ_phi); default: undamped", None, min_length=3, max_length=4,
        examples=[[0.1, 0.1, 0.05]],
    )

    modulus_range: list[float] | None = quantity(
        "-", "-", "factors [low, high] on the soil's stiffness data (G or V_s², E, c_z, c_x, c_phi, c_psi, or the"
        " given stiffness, whose dashpots go with its square root); every spring and dashpot is recomputed from"
        " the factored data and a check passes only if it passes over the whole range (ACI 351.3R brackets the"
        " modulus, e.g. [0.5, 1.5]); default: the data as given",
        None, min_length=2, max_length=2, examples=[[0.5, 1.5]],
    )

    def factored(self, factor: float) -> BlockSoil:
        """This soil with its stiffness data multiplied by ``factor`` [-] (and no range): as
        :meth:`Soil.factored`, and c_ψ with the coefficients; given springs by ``factor`` and their
        dashpots by sqrt(factor) (a half-space's radiation dashpot ρ V_s A and a fixed damping ratio's
        2 ξ sqrt(K m) both go as the square root of the stiffness)."""
        if self.method_used != "springs":
            soil = super().factored(factor)
            return soil if self.c_psi is None else soil.model_copy(update={"c_psi": self.c_psi * factor})
        root = factor**0.5
        return self.model_copy(update={
            "stiffness": [k * factor for k in self.stiffness],
            "dashpot": None if self.dashpot is None else [c * root for c in self.dashpot],
            "modulus_range": None,
        })

    @property
    def rocking_key(self) -> str:
        """The key that sets the rocking springs: ``soil.stiffness`` given at O, else the method's
        (:attr:`Soil.rocking_key`)."""
        return "soil.stiffness" if self.method_used == "springs" else super().rocking_key

    @model_validator(mode="after")
    def _method_has_its_data(self):
        method = self.method_used
        required = ("stiffness",) if method == "springs" else METHOD_REQUIRED[method]
        missing = self.missing_text(required)
        if missing:
            raise ValueError(f"method {method!r} needs {missing}")
        if self.stiffness is not None and not all(k > 0 for k in self.stiffness):
            raise ValueError("soil.stiffness must be > 0 N/m (along x, y, z) and > 0 N m/rad (about them) in every"
                             f" direction, or the block is not restrained (got {list(self.stiffness)})")
        if self.dashpot is not None and any(c < 0 for c in self.dashpot):
            raise ValueError("soil.dashpot must be >= 0 N s/m (along x, y, z) and >= 0 N m s/rad (about them) in every"
                             f" direction (got {list(self.dashpot)})")
        if method in HALF_SPACE_METHODS and (self.shear_modulus is None) == (self.shear_wave_velocity is None):
            raise ValueError(f"method {method!r} needs exactly one of soil.shear_modulus [Pa] and soil.shear_wave_velocity [m/s]")
        return self
