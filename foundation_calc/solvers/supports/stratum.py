"""A footing on a stratum over rigid bedrock (``[soil] stratum_depth``) in ``fcalc soil``: its static
factors on the half-space springs and its cutoff frequencies, as one line and as the JSON part
``stratum`` (SI; :mod:`~foundation_calc.solvers.soil.stratum`), for the block's support
(:mod:`.footing`) and the crank foundation's table alike. Motions: the block's x, y, z, rx, ry, rz (L
along x, in the plane of the crank foundation's motion)."""

from __future__ import annotations

import math


def stratum_cutoffs(soil) -> tuple[float, float, float] | None:
    """(H [m], ω_s, ω_c [rad/s]): the depth of the ``soil``'s stratum and the cutoffs below which
    its shear (sway, torsion) and compression (vertical, rocking) motions radiate nothing
    (:func:`~foundation_calc.solvers.soil.stratum.cutoff_frequencies`); None without ``stratum_depth``."""
    if getattr(soil, "stratum_depth", None) is None:
        return None
    from foundation_calc.solvers.soil.stratum import cutoff_frequencies

    omega_s, omega_c = cutoff_frequencies(soil.V_s, soil.poisson, soil.stratum_depth)
    return float(soil.stratum_depth), float(omega_s), float(omega_c)


def stratum_document(soil, L: float, B: float) -> dict | None:
    """The stratum under a base L × B [m]: depth, equivalent radii, the factor on each spring and the
    cutoffs [rad/s] (None without ``stratum_depth``)."""
    if getattr(soil, "stratum_depth", None) is None:
        return None
    from foundation_calc.solvers.soil.stratum import H_OVER_R_MIN, SOURCE, stratum_of

    along = stratum_of(L, B, soil.stratum_depth, soil.V_s, soil.poisson)  # rocking about y
    across = stratum_of(B, L, soil.stratum_depth, soil.V_s, soil.poisson)  # rocking about x
    factors = (along.eta_x, along.eta_x, along.eta_z, across.eta_r, along.eta_r, 1.0)
    return {
        "depth": soil.stratum_depth,
        "equivalent_radius": float(along.R),
        "h_over_r": soil.stratum_depth / float(along.R),
        "h_over_r_min": H_OVER_R_MIN,
        "factors": dict(zip(("x", "y", "z", "rx", "ry", "rz"), map(float, factors))),
        "cutoff_shear": float(along.omega_s),
        "cutoff_compression": float(along.omega_c),
        "source": SOURCE,
    }


def stratum_line(document: dict) -> str:
    """One line of :func:`stratum_document`: the factors and the cutoffs in Hz."""
    f = document["factors"]
    return (f"stratum H = {document['depth']:g} m over bedrock (H/R = {document['h_over_r']:.3g}): springs × η_x = η_y ="
            f" {f['x']:.4g}, η_z = {f['z']:.4g}, η_rx = {f['rx']:.4g}, η_ry = {f['ry']:.4g} (torsion 1); radiation"
            f" dashpots only at or above f_s = V_s/4H = {document['cutoff_shear'] / (2 * math.pi):.4g} Hz (x, y, rz) and"
            f" f_c = V_La/4H = {document['cutoff_compression'] / (2 * math.pi):.4g} Hz (z, rx, ry), material damping"
            f" alone below [{document['source']}]")


__all__ = ["stratum_cutoffs", "stratum_document", "stratum_line"]
