"""The six springs at O of a footing and the damping ratios of its uncoupled motions, by the soil
method of its ``[soil]`` table: given at O (``"springs"``), Barkan's coefficients
(``"coefficients"``), SP 26.13330 (``"sp26"``), Lysmer's analogs (``"lysmer"``), Gazetas' or Pais &
Kausel's impedances (``"gazetas"``, ``"pais_kausel"``), each in both vertical planes, with torsion,
on a half-space or on a stratum over bedrock.

``soil`` is the soil's data, read as attributes named as the keys of ``[soil]`` (``method_used``,
``stiffness``, ``c_z``, ``c_x``, ``c_phi``, ``c_psi``, ``damping``, ``G``, ``V_s``, ``density``,
``poisson``, ``material_damping``, ``deformation_modulus``, ``soil_class``, ``stratum_depth``): the
scene reads and validates them, this module computes.
"""

from __future__ import annotations

#: SP 26.13330 (SNiP 2.02.05-87): the torsion coefficient C_ψ = C_z and damping ξ_ψ = 0.3 ξ_z [-],
#: as the code is usually quoted (its printed clause has not been checked here). The elastic
#: half-space gives C_ψ/C_z ≈ 1.3-2.1 (tests/test_soil_closed_forms.py): a softer torsion spring.
SP26_TORSION = (1.0, 0.3)

#: c_ψ / c_x of Barkan (1948), ch. 4: the coefficient of elastic non-uniform shear (torsion) is
#: about 1.5 times that of uniform shear [-], as usually quoted (the printed text has not been
#: checked here); the elastic half-space gives 1.9-2.4 (tests/test_soil_closed_forms.py).
BARKAN_TORSION_RATIO = 1.5


def six_springs(soil, L, B, M, J_O, omega=0.0, D=0.0, section=None) -> tuple[list, list | None]:
    """Springs at O [N/m, N m/rad] along x, y, z, about x, y, z, and the damping ratios
    [ξ_x, ξ_y, ξ_z, ξ_rx, ξ_ry, ξ_rz] of the uncoupled motions (None for dashpots given at O).

    Parameters
    ----------
    soil : the soil's data (module docstring)
    L, B : the base's length (along x) and width (along y) [m]
    M : total mass [kg] (the half-space methods' mass ratio; SP 26's mean pressure)
    J_O : moments of inertia about the axes x, y, z through O [kg m²]
    omega : the frequencies [rad/s] at which a frequency-dependent method takes them; the other
        methods ignore it
    D : the base's embedment [m] (sidewalls in contact), taken by ``"gazetas"`` and ``"pais_kausel"``
    section : (A [m²], I_x, I_y [m⁴]), the base's area and second moments about x and y as a scene
        gives them (the crank foundation's S and I1), taken by ``"coefficients"`` and ``"sp26"``;
        default (None) the rectangle's L B, L B³/12, B L³/12

    L, B, M, each of J_O and omega may be arrays over a batch of candidate blocks and frequencies;
    the springs and ratios broadcast.

    Coefficients (Barkan): K_x = K_y = c_x A, K_z = c_z A, K_rx = c_φ I_x, K_ry = c_φ I_y,
    K_rz = c_ψ J_z with J_z = I_x + I_y (A, I_x, I_y: ``section``). Lysmer, Gazetas,
    Pais & Kausel, SP 26: the crank foundation's plane method in each vertical plane
    (:func:`planes`), on a stratum by :func:`~foundation_calc.solvers.soil.stratum.on_stratum`.

    >>> from types import SimpleNamespace
    >>> soil = SimpleNamespace(method_used="coefficients", c_z=5.0e7, c_x=3.5e7, c_phi=None, c_psi=None, damping=None)
    >>> springs, ratios = six_springs(soil, 4.0, 2.0, 3.0e4, (1.0, 1.0, 1.0))
    >>> [round(k / 1e6, 2) for k in springs]
    [280.0, 280.0, 400.0, 133.33, 533.33, 700.0]
    """
    method = soil.method_used
    if method == "springs":
        return list(soil.stiffness), None
    if method != "coefficients":  # a half-space method or SP 26
        along, across, (k_t, xi_t) = planes(soil, L, B, M, J_O, omega, D, section)
        if soil.stratum_depth is not None:
            from foundation_calc.solvers.soil.stratum import on_stratum, torsion_on_stratum

            H, xi_m = soil.stratum_depth, soil.material_damping or 0.0
            along = on_stratum(along, L, B, H, soil.V_s, soil.poisson, xi_m, omega)
            across = on_stratum(across, B, L, H, soil.V_s, soil.poisson, xi_m, omega)
            xi_t = torsion_on_stratum(xi_t, H, soil.V_s, xi_m, omega)
        springs = [along.K_x, across.K_x, along.K_z, across.K_phi, along.K_phi, k_t]
        return springs, [along.xi_x, across.xi_x, along.xi_z, across.xi_phi, along.xi_phi, xi_t]
    A, I_x, I_y = base_section(L, B, section)
    c_phi = soil.c_z if soil.c_phi is None else soil.c_phi
    c_psi = getattr(soil, "c_psi", None)  # a crank foundation's [soil] has no c_psi: Barkan's ratio
    c_psi = BARKAN_TORSION_RATIO * soil.c_x if c_psi is None else c_psi
    xi = list(soil.damping or (0.0, 0.0, 0.0))
    xi_z, xi_x, xi_phi = xi[:3]
    xi_psi = xi[3] if len(xi) == 4 else xi_phi
    springs = [soil.c_x * A, soil.c_x * A, soil.c_z * A, c_phi * I_x, c_phi * I_y, c_psi * (I_x + I_y)]
    return springs, [xi_x, xi_x, xi_z, xi_phi, xi_phi, xi_psi]


def base_section(L, B, section=None) -> tuple:
    """(A [m²], I_x, I_y [m⁴]) of the base: ``section`` as given, else the rectangle L × B's
    (L B, L B³/12, B L³/12)."""
    return (L * B, L * B**3 / 12.0, B * L**3 / 12.0) if section is None else tuple(section)


def planes(soil, L, B, M, J_O, omega=0.0, D=0.0, section=None):
    """The plane method twice, in the plane of x (sliding x, rocking about y, with L in the plane)
    and of y (sliding y, rocking about x), and the torsion: (along, across, (k_ψ, ξ_ψ)), on a
    half-space (arguments as :func:`six_springs`).

    Torsion: Reissner-Sagoci's analog (lysmer), Gazetas' or Pais & Kausel's static K_t with Pais &
    Kausel's modifier k_t(a0) and radiation C_t = ρ V_s J_t c̃_t(a0) (gazetas, pais_kausel;
    :func:`~foundation_calc.solvers.soil.impedance.footing_torsion`), ξ_ψ = C_t/(2 sqrt(K_t(ω) J_z))
    plus the material damping, C_ψ = C_z and ξ_ψ = 0.3 ξ_z (sp26, SNiP 2.02.05-87,
    :data:`SP26_TORSION`). Gazetas' or Pais & Kausel's springs and dashpots in both planes and in
    torsion at the frequencies ``omega`` [rad/s], embedded ``D`` [m] as the crank foundation's
    plane (each plane's embedment factors and sidewall dashpots; the other horizontal axis and
    rocking axis are the plane of B's), and their static torsion spring times its embedment factor
    (:mod:`~foundation_calc.solvers.soil.torsion_embedment`; no torsional sidewall dashpot)."""
    method, xi_m = soil.method_used, soil.material_damping or 0.0
    if method == "sp26":
        from foundation_calc.solvers.constants import GRAVITY
        from foundation_calc.solvers.soil.sp26 import B0_BY_CLASS, sp26_springs

        A, I_x, I_y = base_section(L, B, section)
        b0, p_m = B0_BY_CLASS[soil.soil_class], M * GRAVITY / A
        along = sp26_springs(soil.deformation_modulus, b0, A, I_y, p_m)
        across = sp26_springs(soil.deformation_modulus, b0, A, I_x, p_m)
        ratio, damping = SP26_TORSION
        return along, across, (ratio * along.K_z / A * (I_x + I_y), damping * along.xi_z)
    G, rho, nu = soil.G, soil.density, soil.poisson
    if method == "lysmer":
        from foundation_calc.solvers.soil.lysmer import lysmer_springs
        from foundation_calc.solvers.soil.torsion import lysmer_torsion

        return (lysmer_springs(G, rho, nu, L, B, M, J_O[1], xi_m), lysmer_springs(G, rho, nu, B, L, M, J_O[0], xi_m),
                lysmer_torsion(G, rho, L, B, J_O[2], xi_m))
    if method == "pais_kausel":
        from foundation_calc.solvers.soil.pais_kausel import pais_kausel_springs as springs
        from foundation_calc.solvers.soil.pais_kausel import pais_kausel_torsion as torsion
        from foundation_calc.solvers.soil.torsion_embedment import pais_kausel_torsion_embedment as embedded
    else:
        from foundation_calc.solvers.soil.gazetas import gazetas_springs as springs
        from foundation_calc.solvers.soil.torsion import gazetas_torsion as torsion
        from foundation_calc.solvers.soil.torsion_embedment import gazetas_torsion_embedment as embedded

    from foundation_calc.solvers.soil.impedance import footing_torsion

    K_t, C_t = footing_torsion(torsion(G, L, B) * embedded(L, B, D), G, rho, L, B, omega)
    return (springs(G, rho, nu, L, B, D, M, J_O[1], xi_m, omega), springs(G, rho, nu, B, L, D, M, J_O[0], xi_m, omega),
            (K_t, C_t / (2.0 * (K_t * J_O[2]) ** 0.5) + xi_m))


__all__ = ["BARKAN_TORSION_RATIO", "SP26_TORSION", "base_section", "planes", "six_springs"]
