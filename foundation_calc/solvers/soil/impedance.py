"""Frequency-dependent impedance K_i(ω) + iω C_i(ω) of a rigid rectangular footing, surface or embedded.

Sources
-------
.. [1] G. Gazetas, "Formulas and charts for impedances of surface and embedded foundations",
   J. Geotech. Eng. 117(9), 1991: Table 1 (surface: K_i(ω) = K_i k_i(a0), radiation dashpots
   C_z = ρ V_La A_b c̃_z, C_y = ρ V_s A_b c̃_y, C_r = ρ V_La I_b c̃_r), Table 2 (embedded: each
   sidewall adds ρ V_s per unit area where it shears the soil and ρ V_La where it pushes it).
.. [2] J. Pais, E. Kausel, "Approximate formulas for dynamic stiffnesses of rigid foundations",
   Soil Dyn. Earthq. Eng. 7(4), 1988, as tabulated in NIST GCR 12-917-21 (2012), Table 2-3a:
   closed forms of the dynamic stiffness modifiers α_i(a0) and of the frequency shape of the
   rocking and torsional radiation.

Footing 2L' × 2B', L' >= B' (half-sides), r = L'/B', a0 = ω B'/V_s (B' the shorter half-side),
V_La = 3.4 V_s/(π (1 - ν)). Stiffness modifiers ([2], Table 2-3a; the same for embedded
footings, note to Table 2-3b)::

    k_z  = 1 - (0.4 + 0.2/r) a0² / (10/(1 + 3 (r - 1)) + a0²)
    k_x  = k_y = 1
    k_rx = 1 - (0.55 + 0.01 sqrt(r - 1)) a0² / (2.4 - 0.4/r³ + a0²)     rocking about the long axis
    k_ry = 1 - 0.55 a0² / (0.6 + 1.4/r³ + a0²)                          rocking about the short axis
    k_t  = 1 - (0.33 - 0.03 sqrt(r - 1)) a0² / (0.8/(1 + 0.33 (r - 1)) + a0²)   torsion about z

Radiation dashpots, with a the half-side in the plane of motion, b the other, d = D the sidewall
height (full contact), I_b = (4/3) a³ b the base's second moment about the rocking axis::

    C_z = ρ V_La A_b + ρ V_s 4 D (a + b)
    C_h = ρ V_s A_b + ρ V_s 4 a D + ρ V_La 4 b D
    C_φ = [ρ V_La I_b + ρ V_s (4 b D a² + (4/3) D a³)] c̃_r(a0) + (4/3) D³ (ρ V_La b + ρ V_s a)
    c̃_r(a0) = a0² / (c_r + a0²),   c_r = 1.8/(1 + 1.75 (r - 1)) about the short axis,
                                   c_r = 2.2 - 0.4/r³ about the long axis

Torsion of a surface footing (the closed forms here; Gazetas' or Pais & Kausel's static K_t,
:mod:`~foundation_calc.solvers.soil.torsion`, :mod:`~foundation_calc.solvers.soil.pais_kausel`),
J_t = (4/3) L' B' (L'² + B'²) the base's polar second moment::

    K_t(ω) = K_t k_t(a0),    C_t = ρ V_s J_t c̃_t(a0),    c̃_t(a0) = a0² / (1.4/(1 + 3 (r - 1)^0.7) + a0²)

C_t is [2]'s β_zz (C = 2 K α β/ω, its 1/α cancelling) and [1]'s Table 1 C_t = ρ V_s J_t c̃_t:
every point of the base shears the soil below it, whence the high-frequency limit ρ V_s J_t
(Veletsos' exact one for a disk, ρ V_s π r⁴/2); like rocking, torsion radiates nothing at low
frequency (c̃_t ~ a0²).

The base terms are [1]'s Table 1 at c̃_z = c̃_y = 1 (its charts stay within about 10 % of that for
a0 < 1.5 and r <= 4). The rocking coefficient c̃_r rises from 0 (rocking radiates nothing at
low frequency) to 1 (the chart's high-frequency limit) with the frequency shape of [2]'s
β_xx, β_yy, whose two forms coincide for a square (1.8 = 2.2 - 0.4). The sidewall terms follow
[1]'s Table 2 wall by wall: a wall normal to the motion pushes the soil (V_La) as it translates
and shears it as it rises and falls with the rocking; a wall parallel to the motion shears it in
both; the walls' vertical motion radiates with the base's shape c̃_r, their horizontal motion
(θ z over the depth, ∫ z² = D³/3) like a translating wall, at every frequency.

Arithmetic and ``numpy`` ufuncs only: every argument may be an array (a frequency sweep, a
sampled soil, a batch of footings) and the results broadcast.
"""

from __future__ import annotations

from dataclasses import dataclass

import numpy as np

#: Largest a0 = ω B'/V_s of the fits of [2] (Pais & Kausel fitted a0 <= 2; Gazetas' charts end at 2).
A0_FITTED = 2.0

#: Where :func:`consistent_frequency` looks for the root when p(ω) is not monotonic (a pile group's
#: springs rise and fall with frequency): these multiples of the static frequency [-].
SCAN = np.geomspace(0.2, 5.0, 49)

#: Most frequencies [-] one evaluation of the springs takes in :func:`consistent_frequency`'s scan
#: (``trials``) and in :func:`~foundation_calc.solvers.block.response.consistent_batch`: a larger
#: batch takes its trial frequencies, and its modes, one at a time (the soil's arrays stay about
#: the batch's size).
AT_ONCE = 16_384

#: Where :data:`A0_FITTED` comes from.
A0_SOURCE = "Pais & Kausel (1988), fitted for a0 <= 2; Gazetas (1991), charts to a0 = 2"


@dataclass(frozen=True)
class Impedance:
    """Dynamic springs and radiation dashpots of a footing at one frequency (floats or arrays).

    Attributes
    ----------
    a0 : dimensionless frequency ω B'/V_s [-]
    K_z, K_x, K_phi : dynamic springs K k(a0) [N/m, N/m, N m/rad] (horizontal along, rocking
        about the axis normal to, the plane of motion)
    C_z, C_x, C_phi : radiation dashpots [N s/m, N s/m, N m s/rad] (material damping excluded)
    """

    a0: object
    K_z: object
    K_x: object
    K_phi: object
    C_z: object
    C_x: object
    C_phi: object


def stiffness_modifiers(a0, r):
    """k_z, k_rx, k_ry of Pais & Kausel ([2], Table 2-3a): (vertical, rocking about the long axis,
    rocking about the short axis) [-]; the horizontal modifiers are 1.

    Parameters
    ----------
    a0 : ω B'/V_s [-]
    r : L'/B' >= 1 [-]

    >>> [round(float(k), 4) for k in stiffness_modifiers(1.0, 1.0)]
    [0.9455, 0.8167, 0.8167]
    """
    a2 = a0 * a0
    k_z = 1.0 - (0.4 + 0.2 / r) * a2 / (10.0 / (1.0 + 3.0 * (r - 1.0)) + a2)
    k_rx = 1.0 - (0.55 + 0.01 * np.sqrt(r - 1.0)) * a2 / (2.4 - 0.4 / r**3 + a2)
    k_ry = 1.0 - 0.55 * a2 / (0.6 + 1.4 / r**3 + a2)
    return k_z, k_rx, k_ry


def rocking_radiation_coefficient(a0, r, about_short_axis):
    """c̃_r(a0) = a0²/(c_r + a0²) of the module docstring [-]: 0 at rest, 1 at high frequency.

    Parameters
    ----------
    a0 : ω B'/V_s [-]
    r : L'/B' >= 1 [-]
    about_short_axis : True when the footing rocks about its short axis (L' in the plane of motion)

    >>> round(float(rocking_radiation_coefficient(1.0, 1.0, True)), 4)
    0.3571
    """
    c_r = np.where(about_short_axis, 1.8 / (1.0 + 1.75 * (r - 1.0)), 2.2 - 0.4 / r**3)
    a2 = a0 * a0
    return a2 / (c_r + a2)


def torsion_modifier(a0, r):
    """k_t(a0) of Pais & Kausel ([2], Table 2-3a; module docstring) [-], torsion about the vertical.

    Parameters
    ----------
    a0 : ω B'/V_s [-]
    r : L'/B' >= 1 [-]

    >>> round(float(torsion_modifier(1.0, 1.0)), 4), round(float(torsion_modifier(1.5, 1.0)), 4)
    (0.8167, 0.7566)
    """
    a2 = a0 * a0
    return 1.0 - (0.33 - 0.03 * np.sqrt(r - 1.0)) * a2 / (0.8 / (1.0 + 0.33 * (r - 1.0)) + a2)


def torsion_radiation_coefficient(a0, r):
    """c̃_t(a0) = a0²/(1.4/(1 + 3 (r - 1)^0.7) + a0²) of the module docstring [-]: 0 at rest, 1 at
    high frequency.

    Parameters
    ----------
    a0 : ω B'/V_s [-]
    r : L'/B' >= 1 [-]

    >>> round(float(torsion_radiation_coefficient(1.0, 1.0)), 4)
    0.4167
    """
    a2 = a0 * a0
    return a2 / (1.4 / (1.0 + 3.0 * (r - 1.0) ** 0.7) + a2)


def footing_torsion(K_t, G, rho, L, B, omega):
    """(K_t(ω) [N m/rad], C_t(ω) [N m s/rad]) of a surface footing in torsion about the vertical at
    the circular frequency ``omega`` (module docstring).

    Parameters
    ----------
    K_t : static torsional spring [N m/rad]
    G : shear modulus of the soil [Pa]
    rho : mass density of the soil [kg/m³]
    L, B : the base's full sides, in either order [m]
    omega : circular frequency [rad/s]; 0 gives K_t and no radiation

    >>> K, C = footing_torsion(1.0, 7.2e7, 1800.0, 4.0, 4.0, 100.0)   # a0 = 1
    >>> round(float(K), 4), round(float(C) / (1800.0 * 200.0 * 4.0**4 / 6.0), 4)
    (0.8167, 0.4167)
    """
    V_s = np.sqrt(G / rho)
    short_half = np.minimum(L, B) / 2.0
    r = np.maximum(L, B) / 2.0 / short_half
    a0 = omega * short_half / V_s
    J_t = L * B * (L * L + B * B) / 12.0
    return K_t * torsion_modifier(a0, r), rho * V_s * J_t * torsion_radiation_coefficient(a0, r)


def footing_impedance(K_z, K_x, K_phi, G, rho, nu, L, B, D, omega) -> Impedance:
    """Springs and radiation dashpots at the circular frequency ``omega`` (module docstring).

    Parameters
    ----------
    K_z, K_x, K_phi : static springs of the footing (Gazetas' Tables 1-2, embedment included)
        [N/m, N/m, N m/rad]
    G : shear modulus of the soil [Pa]
    rho : mass density of the soil [kg/m³]
    nu : Poisson's ratio of the soil [-]
    L : base length along the plane of motion [m]
    B : base width, normal to the plane of motion [m]
    D : embedment depth, sidewall in contact over all of it; 0 for a surface footing [m]
    omega : circular frequency [rad/s]; 0 gives the static springs and the low-frequency dashpots

    >>> z = footing_impedance(1.0, 1.0, 1.0, 7.2e7, 1800.0, 1.0 / 3.0, 4.0, 4.0, 0.0, 100.0)
    >>> round(float(z.a0), 3), round(float(z.K_phi), 4)
    (1.0, 0.8167)
    """
    V_s = np.sqrt(G / rho)
    V_La = 3.4 * V_s / (np.pi * (1.0 - nu))
    long_half, short_half = np.maximum(L, B) / 2.0, np.minimum(L, B) / 2.0
    r = long_half / short_half
    a, b = L / 2.0, B / 2.0
    a0 = omega * short_half / V_s
    k_z, k_rx, k_ry = stiffness_modifiers(a0, r)
    about_short = L >= B
    c_r = rocking_radiation_coefficient(a0, r, about_short)
    A_b = 4.0 * a * b
    I_b = 4.0 / 3.0 * a**3 * b
    return Impedance(
        a0=a0,
        K_z=K_z * k_z,
        K_x=K_x * np.ones_like(a0),
        K_phi=K_phi * np.where(about_short, k_ry, k_rx),
        C_z=rho * (V_La * A_b + V_s * 4.0 * D * (a + b)) * np.ones_like(a0),
        C_x=rho * (V_s * A_b + V_s * 4.0 * a * D + V_La * 4.0 * b * D) * np.ones_like(a0),
        C_phi=rho * ((V_La * I_b + V_s * (4.0 * b * D * a**2 + 4.0 / 3.0 * D * a**3)) * c_r
                     + 4.0 / 3.0 * D**3 * (V_La * b + V_s * a)),
    )


def consistent_frequency(frequency_at, omega_static, *, rtol=1e-10, trials=False, mode="", rootless="raise", every=None):
    """The root of ω = p(K(ω)): the natural frequency of a mode whose springs depend on frequency.

    ``frequency_at(omega)`` returns the mode's frequency p(ω) [rad/s] on the springs taken at
    ``omega``, the mode being the same rank (j-th lowest) at every ω; arrays of frequencies (a
    batch of blocks, a sampled soil) are solved together, element by element.

    Existence and uniqueness: every stiffness modifier of the module docstring (and the torsional
    one, :func:`torsion_modifier`) is 1 - c a0²/(d + a0²) with 0 <= c < 1 and d > 0 (torsion's
    c = 0.33 - 0.03 sqrt(r - 1) stays positive up to r = 122), so no spring rises with ω and each
    stays above its a0 → ∞ limit K (1 - c) > 0. The stiffness matrix K(ω) (springs on its
    diagonal, the weight's tilt constant) then falls in the Loewner order while the mass matrix
    stays, so each eigenvalue by rank falls too (Weyl's monotonicity): p(ω) is continuous,
    non-increasing and bounded, and g(ω) = p(ω) - ω strictly decreasing. With p_s = p(0) the
    static frequency, g(p_s) = p(p_s) - p_s <= 0 and, at p_1 = p(p_s) <= p_s,
    g(p_1) = p(p_1) - p_1 >= 0: exactly one root, in [p(p_s), p_s]. Springs that stiffen with
    frequency (a pile group's: the Winkler pile's dynamic stiffness and Dobry & Gazetas' group
    rise with ω in places) give p(p_s) > p_s: where p rises more slowly than ω, g(p_s) >= 0 >=
    g(p(p_s)) and the root lies in [p_s, p(p_s)], bracketed the same way. Where neither interval
    brackets a root (p(ω) not monotonic: Dobry & Gazetas' group springs rise and fall with ω), g
    is sampled at the multiples :data:`SCAN` of p_s and the crossing from g >= 0 to g <= 0 nearest
    p_s is bracketed (one root of several is then chosen: the nearest). Beyond a0 = :data:`A0_FITTED`
    the fits are extrapolated but keep these properties: the root exists, as good as the
    extrapolated fits. A mode followed by its shape instead of its rank has no such property:
    where two modes trade places its frequency jumps between them, and a plain iteration
    ω_{k+1} = p(K(ω_k)) on it can cycle for ever (0.8 % of plausible blocks did).

    The root is bracketed from the start and the bracket only shrinks: regula falsi with the
    Illinois modification (the retained end's value halved when the same end is kept twice), and a
    bisection whenever two steps have not halved the bracket, so that every three steps at least
    halve it (about 8 evaluations of p at ``rtol`` = 1e-10; at most 3 log2(p_s/(p rtol))).

    Parameters
    ----------
    frequency_at : callable ω -> p(K(ω)) [rad/s], non-increasing in ω
    omega_static : the mode's frequency on the static springs, p(0) [rad/s]; 0 (a block that
        tips over) is its own root
    rtol : relative width of the final bracket [-]
    trials : True when ``frequency_at`` also takes a last axis of trial frequencies per element,
        (...) + (k,) -> (...) + (k,): the scan of :data:`SCAN` is then one call, not one per
        multiple (when it holds at most :data:`AT_ONCE` frequencies)
    mode : the mode's name in the error (``"p2"``, ``"mode 3"``)
    rootless : ``"raise"``: a mode without a root raises; ``"nan"``: its root is NaN (a batch of
        candidates, each failing alone: :func:`rootless_reason`)
    every : a list, for one mode (a scalar ``omega_static``): when the scan of :data:`SCAN` runs, it
        receives every root [rad/s] between its samples where p(ω) - ω changes sign, ascending
        (the root returned among them; several: the mode has several frequencies, one chosen)

    Returns
    -------
    The root [rad/s], the midpoint of the final bracket: an array shaped as ``omega_static``, a
    float for a scalar.

    Raises
    ------
    PhysicsError
        when ω = p(ω) has no root between 0.2 and 5 × p_s (springs that stiffen with frequency
        faster than the mode's frequency rises), naming ``mode`` and the range scanned [rad/s];
        with ``rootless="nan"`` never.

    >>> round(consistent_frequency(lambda w: 100.0 * (1.0 - 0.001 * w) ** 0.5, 100.0), 6)
    95.124922
    """
    from foundation_calc.errors import PhysicsError

    hi = np.asarray(omega_static, dtype=float)
    g_hi = frequency_at(hi) - hi
    lo = hi + g_hi  # p(p_s)
    g_lo = frequency_at(lo) - lo
    tol = rtol * np.abs(hi)
    rising = lo > hi  # springs that stiffen with frequency (a pile group's): the root in [p_s, p(p_s)]
    lo, hi, g_lo, g_hi = (np.where(rising, hi, lo), np.where(rising, lo, hi),
                          np.where(rising, g_hi, g_lo), np.where(rising, g_lo, g_hi))
    lost = ((g_hi > 0.0) | (g_lo < 0.0)) & (np.abs(hi - lo) > tol)
    if np.any(lost):  # p(ω) not monotonic (a pile group's): the crossing of ω = p(ω) nearest p_s on a grid
        grid = hi[..., None] * np.where(lost[..., None], SCAN, 1.0)  # the others asked again where they were
        at_once = trials and grid.size <= AT_ONCE
        g = (frequency_at(grid) if at_once else np.stack([frequency_at(grid[..., k]) for k in range(len(SCAN))], axis=-1)) - grid
        down = (g[..., :-1] >= 0.0) & (g[..., 1:] <= 0.0)
        k = np.argmin(np.where(down, np.abs(np.log(SCAN[:-1])), np.inf), axis=-1)
        found = np.take_along_axis(down, k[..., None], -1)[..., 0]
        pick = lost & found
        at = (lambda a: np.take_along_axis(a, k[..., None], -1)[..., 0])
        lo, g_lo = np.where(pick, at(grid[..., :-1]), lo), np.where(pick, at(g[..., :-1]), g_lo)
        hi, g_hi = np.where(pick, at(grid[..., 1:]), hi), np.where(pick, at(g[..., 1:]), g_hi)
        lost &= ~found
        if every is not None and np.ndim(omega_static) == 0 and bool(found):
            every.extend(_roots_between(frequency_at, grid, g))
    if np.any(lost) and rootless == "raise":
        centre = float(np.max(np.where(lost, hi, 0.0)))
        raise PhysicsError(f"{rootless_reason(mode, SCAN[0] * centre, SCAN[-1] * centre)} ({SCAN[0]:g} to {SCAN[-1]:g} ×"
                           f" {centre:.4g} rad/s: the mode's frequency on the soil's springs p(ω) crosses ω nowhere there)",
                           field="soil", hint=ROOTLESS_HINT)
    lo = np.where(lost, hi, lo)  # a rootless mode's bracket closed at once, its root NaN at the end
    g_lo, g_hi = np.where(lost, 0.0, g_lo), np.where(lost, 0.0, g_hi)
    g_lo, g_hi = np.maximum(g_lo, 0.0), np.minimum(g_hi, 0.0)  # lo = hi for a frequency-independent mode
    kept = np.zeros(hi.shape)  # +1: lo was moved last, -1: hi was
    widths = [2.0 * (hi - lo)] * 2  # the first two steps are secant steps
    for _ in range(3 * 64):
        width = hi - lo
        done = (width <= rtol * hi) | (g_lo == 0.0) | (g_hi == 0.0) | np.isnan(width)
        if np.all(done):
            root = np.where(lost, np.nan, np.where(g_lo == 0.0, lo, np.where(g_hi == 0.0, hi, lo + width / 2.0)))
            return root if root.ndim else float(root)  # a float for a float, as frequency_at gives
        slope = g_lo - g_hi  # > 0 where not done
        secant = lo + g_lo * width / np.where(done, 1.0, slope)
        halve = (width > widths[-2] / 2.0) | ~((secant > lo) & (secant < hi))
        x = np.where(done, lo, np.where(halve, lo + width / 2.0, secant))
        g = frequency_at(x) - x
        up = (g > 0.0) & ~done  # the root lies above x
        down = (g < 0.0) & ~done
        on = (g == 0.0) & ~done
        g_hi = np.where(up & (kept > 0), g_hi / 2.0, g_hi)  # Illinois: the end kept twice weighs half
        g_lo = np.where(down & (kept < 0), g_lo / 2.0, g_lo)
        lo, g_lo = np.where(up | on, x, lo), np.where(up, g, np.where(on, 0.0, g_lo))
        hi, g_hi = np.where(down | on, x, hi), np.where(down, g, np.where(on, 0.0, g_hi))
        kept = np.where(up, 1.0, np.where(down, -1.0, kept))
        widths = [widths[-1], width]
    raise ArithmeticError(f"ω = p(K(ω)): the bracket did not close in {3 * 64} steps (a bug: it halves every three)")


def _roots_between(frequency_at, grid, g) -> list[float]:
    """Every root [rad/s] of p(ω) - ω between consecutive samples ``grid`` (one mode's) where its
    values ``g`` change sign, each refined by Brent's method to round-off, ascending."""
    from scipy.optimize import brentq

    grid, g = np.ravel(grid), np.ravel(g)
    changes = np.nonzero((g[:-1] > 0.0) != (g[1:] > 0.0))[0]
    return [float(brentq(lambda w: float(frequency_at(w)) - w, grid[k], grid[k + 1], xtol=1e-12, rtol=1e-12))
            for k in changes]


def rootless_reason(mode: str, low=None, high=None) -> str:
    """Why a mode has no natural frequency: ω = p(K(ω)) has no root between ``low`` and ``high``
    [rad/s] that :func:`consistent_frequency`'s scan finds (p(ω) - ω changes sign between none of
    its :data:`SCAN` samples: a crossing narrower than their spacing, 7 %, can hide between them),
    or, without them, between the multiples :data:`SCAN` of its static frequency (a batch's reason,
    the same for every candidate).

    >>> rootless_reason("p2", 80.0, 2000.0)
    'mode p2 has no natural frequency: ω = p(K(ω)) has no root found between 80 and 2000 rad/s'
    """
    where = (f"{SCAN[0]:g} and {SCAN[-1]:g} × its static frequency" if low is None
             else f"{low:.4g} and {high:.4g} rad/s")
    name = "a mode" if not mode else mode if mode.startswith("mode") else f"mode {mode}"
    return f"{name} has no natural frequency: ω = p(K(ω)) has no root found between {where}"


#: What to change when a mode has no natural frequency (:func:`consistent_frequency`).
ROOTLESS_HINT = "the soil's springs must not stiffen with frequency faster than the mode's frequency rises"


__all__ = ["A0_FITTED", "A0_SOURCE", "AT_ONCE", "Impedance", "ROOTLESS_HINT", "SCAN", "consistent_frequency", "rootless_reason", "footing_impedance", "footing_torsion",
           "rocking_radiation_coefficient", "stiffness_modifiers", "torsion_modifier", "torsion_radiation_coefficient"]
