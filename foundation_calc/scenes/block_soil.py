"""The ``[soil]`` table of a block foundation: explicit springs at O, or a soil method that gives
all six springs of the base.

``method = "springs"`` takes ``stiffness`` and ``dashpot`` as 6-vectors at O (x, y, z, about x,
about y, about z). ``"coefficients"`` takes Barkan's c_z, c_x, c_phi as for a crank foundation and
a torsion coefficient c_psi; the half-space and code methods keep the keys of
:class:`~foundation_calc.scenes.soil.Soil`.
"""

from __future__ import annotations

from typing import Annotated, ClassVar, Literal

from pydantic import Field, model_validator

from foundation_calc.scenes.common import quantity
from foundation_calc.scenes.soil import HALF_SPACE_METHODS, METHOD_KEYS, METHOD_REQUIRED, Soil

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

#: SP 26.13330 (SNiP 2.02.05-87): the torsion coefficient C_ψ = C_z and damping ξ_ψ = 0.3 ξ_z [-],
#: as the code is usually quoted (its printed clause has not been checked here). The elastic
#: half-space gives C_ψ/C_z ≈ 1.3-2.1 (tests/test_soil_closed_forms.py): a softer torsion spring.
SP26_TORSION = (1.0, 0.3)

#: c_ψ / c_x of Barkan (1948), ch. 4: the coefficient of elastic non-uniform shear (torsion) is
#: about 1.5 times that of uniform shear [-], as usually quoted (the printed text has not been
#: checked here); the elastic half-space gives 1.9-2.4 (tests/test_soil_closed_forms.py).
BARKAN_TORSION_RATIO = 1.5


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
        missing = [k for k in required if getattr(self, k) is None]
        if missing:
            raise ValueError(f"method {method!r} needs {', '.join('soil.' + k for k in missing)}")
        for key in ("stiffness", "dashpot"):
            values = getattr(self, key)
            if values is not None and any(v < 0 for v in values):
                raise ValueError(f"soil.{key} must be >= 0 in every direction (got {list(values)})")
        if method in HALF_SPACE_METHODS and (self.shear_modulus is None) == (self.shear_wave_velocity is None):
            raise ValueError(f"method {method!r} needs exactly one of soil.shear_modulus [Pa] and soil.shear_wave_velocity [m/s]")
        if self.stiffness is not None and not all(self.stiffness):
            raise ValueError(f"soil.stiffness must be > 0 in every direction, or the block is not restrained (got {list(self.stiffness)})")
        return self

    def six_springs(self, L: float, B: float, M: float, J_O, omega=0.0, D=0.0) -> tuple[list, list | None]:
        """Springs at O [N/m, N m/rad] along x, y, z, about x, y, z, and the damping ratios
        [ξ_x, ξ_y, ξ_z, ξ_rx, ξ_ry, ξ_rz] of the uncoupled motions (None for explicit dashpots);
        L, B: the base's length (x) and width (y) [m]; M: total mass [kg]; J_O: moments of inertia
        about the axes through O [kg m²] (the half-space methods' mass ratios). L, B, M and each of
        J_O may be arrays over a batch of candidate blocks; the springs and ratios broadcast.
        ``omega``: the frequencies [rad/s] at which a frequency-dependent method (``"gazetas"``)
        takes them (an array broadcasts as well); the other methods ignore it. ``D``: the base's
        embedment [m] (sidewalls in contact), taken by ``"gazetas"`` and ``"pais_kausel"``.

        Coefficients (Barkan): K_x = K_y = c_x A, K_z = c_z A, K_rx = c_φ I_x, K_ry = c_φ I_y,
        K_rz = c_ψ J_z with A = L B, I_x = L B³/12, I_y = B L³/12, J_z = I_x + I_y. Lysmer,
        Gazetas, SP 26: the crank foundation's method in each vertical plane (:meth:`_planes`).
        """
        method = self.method_used
        if method == "springs":
            return list(self.stiffness), None
        if method in (*HALF_SPACE_METHODS, "sp26"):
            along, across, (k_t, xi_t) = self._planes(L, B, M, J_O, omega, D)
            if self.stratum_depth is not None:  # solvers/soil/stratum.py: a layer over bedrock
                from foundation_calc.solvers.soil.stratum import torsion_on_stratum

                along, across = self.with_stratum(along, L, B, omega), self.with_stratum(across, B, L, omega)
                xi_t = torsion_on_stratum(xi_t, self.stratum_depth, self.V_s, self.material_damping or 0.0, omega)
            springs = [along.K_x, across.K_x, along.K_z, across.K_phi, along.K_phi, k_t]
            return springs, [along.xi_x, across.xi_x, along.xi_z, across.xi_phi, along.xi_phi, xi_t]
        A, I_x, I_y = L * B, L * B**3 / 12.0, B * L**3 / 12.0
        c_phi = self.c_z if self.c_phi is None else self.c_phi
        c_psi = BARKAN_TORSION_RATIO * self.c_x if self.c_psi is None else self.c_psi
        xi = list(self.damping or (0.0, 0.0, 0.0))
        xi_z, xi_x, xi_phi = xi[:3]
        xi_psi = xi[3] if len(xi) == 4 else xi_phi
        springs = [self.c_x * A, self.c_x * A, self.c_z * A, c_phi * I_x, c_phi * I_y, c_psi * (I_x + I_y)]
        return springs, [xi_x, xi_x, xi_z, xi_phi, xi_phi, xi_psi]

    @property
    def support_method(self) -> str:
        """The method whose range of validity the soil check judges (:mod:`~foundation_calc.checks.soil_validity`):
        the soil's, or ``"piles"`` for a pile group."""
        return self.method_used

    def coupling(self, L, B, M, J_O, omega=0.0, D=0.0):
        """Off-diagonal springs and dashpots at O (K, C), each omega.shape + (6, 6), of a support that
        couples its motions (a pile group, :class:`~foundation_calc.scenes.block_piles.PiledSoil`);
        None for a footing on the soil, whose six springs are uncoupled at O. Arguments as
        :meth:`six_springs`."""
        return None

    def _planes(self, L: float, B: float, M: float, J_O, omega=0.0, D=0.0):
        """The plane method twice, in the plane of x (sliding x, rocking about y, with L in the
        plane) and of y (sliding y, rocking about x), and the torsion: (along, across, (k_ψ, ξ_ψ)).
        Torsion: Reissner-Sagoci's analog (lysmer), Gazetas' or Pais & Kausel's static K_t with
        Pais & Kausel's modifier k_t(a0) and radiation C_t = ρ V_s J_t c̃_t(a0) (gazetas, pais_kausel;
        :func:`~foundation_calc.solvers.soil.impedance.footing_torsion`), ξ_ψ =
        C_t/(2 sqrt(K_t(ω) J_z)) plus the material damping, C_ψ = C_z and ξ_ψ = 0.3 ξ_z (sp26,
        SNiP 2.02.05-87). Gazetas' or Pais & Kausel's springs and dashpots in both planes and in
        torsion at the frequencies ``omega`` [rad/s], embedded ``D`` [m] as the crank foundation's
        plane (each plane's embedment factors and sidewall dashpots; the other horizontal axis and
        rocking axis are the plane of B's), and their static torsion spring times its embedment
        factor (:mod:`~foundation_calc.solvers.soil.torsion_embedment`; no torsional sidewall
        dashpot)."""
        method, xi_m = self.method_used, self.material_damping or 0.0
        if method == "sp26":
            from foundation_calc.solvers.constants import GRAVITY
            from foundation_calc.solvers.soil.sp26 import B0_BY_CLASS, sp26_springs

            A, I_x, I_y = L * B, L * B**3 / 12.0, B * L**3 / 12.0
            b0, p_m = B0_BY_CLASS[self.soil_class], M * GRAVITY / A
            along = sp26_springs(self.deformation_modulus, b0, A, I_y, p_m)
            across = sp26_springs(self.deformation_modulus, b0, A, I_x, p_m)
            ratio, damping = SP26_TORSION
            return along, across, (ratio * along.K_z / A * (I_x + I_y), damping * along.xi_z)
        if method == "lysmer":
            from foundation_calc.solvers.soil.lysmer import lysmer_springs
            from foundation_calc.solvers.soil.torsion import lysmer_torsion

            return (lysmer_springs(self.G, self.density, self.poisson, L, B, M, J_O[1], xi_m),
                    lysmer_springs(self.G, self.density, self.poisson, B, L, M, J_O[0], xi_m),
                    lysmer_torsion(self.G, self.density, L, B, J_O[2], xi_m))
        if method == "pais_kausel":
            from foundation_calc.solvers.soil.pais_kausel import pais_kausel_springs as springs
            from foundation_calc.solvers.soil.pais_kausel import pais_kausel_torsion as torsion
            from foundation_calc.solvers.soil.torsion_embedment import pais_kausel_torsion_embedment as embedded
        else:
            from foundation_calc.solvers.soil.gazetas import gazetas_springs as springs
            from foundation_calc.solvers.soil.torsion import gazetas_torsion as torsion
            from foundation_calc.solvers.soil.torsion_embedment import gazetas_torsion_embedment as embedded

        from foundation_calc.solvers.soil.impedance import footing_torsion

        K_t, C_t = footing_torsion(torsion(self.G, L, B) * embedded(L, B, D), self.G, self.density, L, B, omega)
        return (springs(self.G, self.density, self.poisson, L, B, D, M, J_O[1], xi_m, omega),
                springs(self.G, self.density, self.poisson, B, L, D, M, J_O[0], xi_m, omega),
                (K_t, C_t / (2.0 * (K_t * J_O[2]) ** 0.5) + xi_m))
