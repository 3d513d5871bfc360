"""Independent reference model of the crank foundation, written from the physics, not from fcalc.

Mass and stiffness matrices are assembled the long way: the stiffness from the soil's generalized
forces (Barkan: uniform compression c, shear c1, with the weight's overturning term) applied to
unit displacements; the averaged mass matrix by sampling the mechanism's kinematics over one
revolution, with the slider as a separate point mass (not lumped into the rod).
"""

from __future__ import annotations

import numpy as np
from scipy.linalg import eigh

G = 9.81


def soil_forces(q, *, M_tot, h, S, I1, c, c1, c_phi=None, g=G):
    """Generalized soil forces (x, y, θ) for a small displacement q, y downward (paper (3.2)-(3.4));
    rocking spring c_phi I1 (default c I1, the paper's)."""
    x, y, th = q
    P = M_tot * g
    c_phi = c if c_phi is None else c_phi
    fx = -c1 * S * (x - h * th)
    fy = -c * S * y
    mth = h * c1 * S * x - (c1 * h * h * S + c_phi * I1 - P * h) * th
    return np.array([fx, fy, mth])


def stiffness_matrix(**soil):
    """K with K q = -Q(q): columns from unit displacements."""
    return -np.column_stack([soil_forces(e, **soil) for e in np.eye(3)])


def mechanism_points(phi, *, a, r, l):
    """Body coordinates (u, v downward) of the crank pin M' and slider pin M''."""
    psi = np.arcsin(r / l * np.sin(phi))
    crank_pin = np.stack([-r * np.sin(phi), -a + r * np.cos(phi)])
    slider_pin = np.stack([np.zeros_like(phi), -a + r * np.cos(phi) + l * np.cos(psi)])
    return crank_pin, slider_pin


def averaged_mass_matrix(*, M, I_c, m, l1, rho, m1, a, r, l, samples=4096):
    """Mass matrix of block + rod + slider (point mass), averaged over one crank revolution."""
    phi = np.linspace(0.0, 2.0 * np.pi, samples, endpoint=False)
    crank_pin, slider_pin = mechanism_points(phi, a=a, r=r, l=l)
    rod_cog = (l - l1) / l * crank_pin + l1 / l * slider_pin
    mm = np.zeros((3, 3))
    mm[0, 0] = mm[1, 1] = M + m + m1
    for mass, pt, own in ((m, rod_cog, m * rho**2), (m1, slider_pin, 0.0)):
        # velocity of a body point at p for generalized velocity (x', y', θ'): (x' - p_v θ', y' + p_u θ')
        mm[0, 2] += np.mean(-mass * pt[1])
        mm[1, 2] += np.mean(mass * pt[0])
        mm[2, 2] += np.mean(mass * (pt[0] ** 2 + pt[1] ** 2)) + own
    mm[2, 0], mm[2, 1] = mm[0, 2], mm[1, 2]
    mm[2, 2] += I_c
    return mm


def frequencies(K, Mm):
    """Natural frequencies [rad/s], ascending, by a generalized symmetric eigen-solve."""
    return np.sqrt(eigh(K, Mm, eigvals_only=True))


def scaled_scene(*, mass, inertia, height, area, second, c_z, c_x, mu, lam, cog, omega=31.4, drive_on=True):
    """A crank_foundation scene document scaled from the frame saw by decades (``10**arg``).

    ``mu``, ``lam`` (λ = r/l) and ``cog`` (l'/l) are given directly; the rod mass follows from μ.
    Used by the property tests to reach every corner of the input domain.
    """
    M = 1e5 * 10**mass
    return {
        "kind": "crank_foundation",
        "foundation": {
            "mass": M, "moment_of_inertia": 4.5e5 * 10**inertia, "cog_height": 1.5 * 10**height,
            "base_area": 30.0 * 10**area, "base_second_moment": 90.0 * 10**second,
        },
        "soil": {"c_z": 4e7 * 10**c_z, "c_x": 4e7 * 10**c_z * 0.7 * 10**c_x},
        "mechanism": {
            "omega": omega, "crank_radius": 1.2 * lam, "rod_length": 1.2,
            "rod_mass": mu / (1 - mu) * M * 0.999999, "rod_cog_to_crank_pin": 1.2 * cog,
            "rod_radius_of_gyration": 0.35, "crank_axis_to_cog": 2.0, "drive_on_foundation": drive_on,
        },
    }


def make_p1_equal_p2(scene: dict) -> dict:
    """Modify a crank scene in place so that p1 = p2 (almost): a0 = b1 and a vanishing coupling.

    h → 1e-6 m kills the coupling a1 b0; I1 is chosen so that (c1 h² S + c I1 − P h)/I_c = c1 S/M_tot.
    """
    f, s = scene["foundation"], scene["soil"]
    f["cog_height"] = 1e-6
    M_tot = f["mass"] + scene["mechanism"]["rod_mass"] + scene["mechanism"].get("slider_mass", 0.0)
    f["base_second_moment"] = (s["c_x"] * f["base_area"] / M_tot * f["moment_of_inertia"]
                               - s["c_x"] * f["cog_height"] ** 2 * f["base_area"]
                               + M_tot * G * f["cog_height"]) / s["c_z"]
    return scene
