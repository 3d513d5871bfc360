"""Isolator stiffnesses and exciter placement of a vibrating platform that moves translationally.

Source: Bolotnik, Gusev, Nguyen, Kholmin, Chernousko [1]_, section 3, Eqs. (3.3)-(3.21), for one
single-shaft exciter with a vertical axis (δ1 = δ2 = 0). Corrections (see the platform note):

- (3.2), (3.5), (3.11), (3.15): the printed ξ is ζ, the height of the centre of mass;
- (3.21): c13 = (M + 4m) K / M = 1.005e8 N/m (the printed 4.005e8 N/m is c3);
- the static deflection z = -M_Σ g / c3 is negative (downward);
- the example's ω is 50π rad/s (25 Hz), not 50 rad/s.

Symbols: M platform mass, m rotor mass, l eccentricity, u required circular amplitude, ω speed,
(ξ, η, ζ) centre of mass from corner O1, A = O1O2 along x', B = O1O4 along y', (a, b, c) the
exciter's axis point, c_ij the stiffness of isolator i (corners O1..O4) along axis j (x, y, z),
c_j = Σ_i c_ij, M_Σ = M + m, σ = +1 below resonance and -1 above (the sign in (3.14)).

The vertical split when a, b and K are given: c33 = K and (c23 + c43)/2 = K. With
ρx = (Mξ + ma)/(A M_Σ) and ρy = (Mη + mb)/(B M_Σ) (the shares of the load carried by the
corners x = A and y = B, Eqs. (3.3)-(3.4)), this gives c3 = 4K/(ρx + ρy) and reduces to the
paper's c23 = c33 = c43 = K when ρx = ρy (the example).

Every function uses arithmetic only, so arguments may be floats or numpy arrays of designs.

References
----------
.. [1] N.N. Bolotnik, B.V. Gusev, Nguyen Truong, I.E. Kholmin, F.L. Chernousko, "Calculation of
   the parameters of a vibration mechanism with unbalanced vibration exciters", Izv. AN SSSR,
   MTT, 1986.
"""

from __future__ import annotations

from dataclasses import dataclass

import numpy as np

from foundation_calc.errors import PhysicsError

#: Sign σ of (3.14) for each regime: + below resonance, - above.
REGIME_SIGN = {"below": 1.0, "above": -1.0}

#: Relative distance |c0 - Mω²| / (Mω²) under which (3.11) is treated as singular.
SINGULAR_C0 = 1e-9

#: How far from the platform's corner O1 the exciter's axis point (a, b, c) may lie, in units of
#: the platform's larger side max(A, B) [-]. An exciter sits on or inside the structure it
#: drives; ten platform lengths away is no machine, only the sign of a unit typed wrongly (mm as
#: m) or of a design next to the singularity c0 = M ω² of (3.11).
EXCITER_REACH = 10.0

#: Names of the horizontal pair sums, in the order returned by :func:`horizontal_sums`.
HORIZONTAL_SUMS = ("c11+c21", "c31+c41", "c12+c42", "c22+c32")


def _any(mask) -> bool:
    return bool(np.any(mask))


def _first(values) -> float:
    return float(np.min(values))


def summed_stiffness(M, m, l, u, omega, sigma):
    """c0 = c1 = c2, the summed horizontal stiffness for a circular amplitude u, Eq. (3.14).

    Source: [1]_, Eqs. (3.1), (3.8), (3.14)::

        c0 = M_Σ ω² + σ m l ω² / u,   σ = +1 below resonance, -1 above

    Parameters
    ----------
    M : platform mass, without the rotor [kg]
    m : rotor mass [kg]
    l : eccentricity of the rotor [m]
    u : required amplitude of the circular motion [m]
    omega : rotor speed [rad/s]
    sigma : +1 below resonance, -1 above [-]

    >>> import math
    >>> round(summed_stiffness(2e4, 25.0, 0.2, 1e-3, 50 * math.pi, -1.0) / 1e8, 5)
    3.70727
    """
    return (M + m) * omega**2 + sigma * m * l * omega**2 / u


def exciter_height(M, m, omega, zeta, c0, g):
    """Height c of the exciter's axis point above the support plane, Eq. (3.11) with ζ for ξ.

    Source: [1]_, Eq. (3.11) (printed with ξ; the derivation gives ζ)::

        c = (ω² g M_Σ - g c0 - M ω⁴ ζ) / (ω² (c0 - M ω²)),   c0 ≠ M ω²

    With c0 from (3.14) this is (3.15): c = (m g l - M u ζ ω²)/(m ω² (u - l)) above resonance
    and c = -(M u ζ ω² + g m l)/(m ω² (u + l)) below (the exciter is then below the plane).

    Parameters
    ----------
    M : platform mass [kg]
    m : rotor mass [kg]
    omega : rotor speed [rad/s]
    zeta : height of the platform's centre of mass above the support plane [m]
    c0 : summed horizontal stiffness c1 = c2 [N/m]
    g : acceleration of gravity [m/s²]

    >>> import math
    >>> w = 50 * math.pi
    >>> round(exciter_height(2e4, 25.0, w, 0.65, summed_stiffness(2e4, 25.0, 0.2, 1e-3, w, -1.0), 9.81), 4)
    2.6127
    """
    w2 = omega**2
    return (w2 * g * (M + m) - g * c0 - M * w2 * w2 * zeta) / (w2 * (c0 - M * w2))


def position_from_vertical(M, m, xi, eta, A, B, c13, c23, c33, c43):
    """Exciter position (a, b) that makes the static deflection tilt-free, Eqs. (3.9)-(3.10).

    Source: [1]_::

        a = (c23 + c33) A M_Σ / (c3 m) - M ξ / m,   b = (c33 + c43) B M_Σ / (c3 m) - M η / m

    Parameters
    ----------
    M, m : platform and rotor mass [kg]
    xi, eta : centre of mass from corner O1 along x' and y' [m]
    A, B : sides O1O2 and O1O4 [m]
    c13, c23, c33, c43 : vertical stiffnesses of the isolators at O1..O4 [N/m]

    >>> a, b = position_from_vertical(2e4, 25.0, 1.5, 1.0, 3.0, 2.0, 1.005e8, 1e8, 1e8, 1e8)
    >>> abs(a) < 1e-9 and abs(b) < 1e-9
    True
    """
    c3 = c13 + c23 + c33 + c43
    Ms = M + m
    a = (c23 + c33) * A * Ms / (c3 * m) - M * xi / m
    b = (c33 + c43) * B * Ms / (c3 * m) - M * eta / m
    return a, b


def load_shares(M, m, xi, eta, A, B, a, b):
    """ρx = (Mξ + ma)/(A M_Σ) and ρy = (Mη + mb)/(B M_Σ): the shares of c3 that (3.3)-(3.4)
    require on the corners x' = A (c23 + c33) and y' = B (c33 + c43) [-].

    >>> load_shares(2e4, 25.0, 1.5, 1.0, 3.0, 2.0, 0.0, 0.0) == (2e4 / 2 / 20025,) * 2
    True
    """
    Ms = M + m
    return (M * xi + m * a) / (A * Ms), (M * eta + m * b) / (B * Ms)


def vertical_from_position(M, m, xi, eta, A, B, a, b, K):
    """Vertical stiffnesses c13, c23, c33, c43 for a given exciter position and reference K.

    Source: [1]_, Eqs. (3.3)-(3.4), (3.18), (3.21), corrected c13. With c33 = K and
    (c23 + c43)/2 = K::

        c3 = 4K / (ρx + ρy),  c23 = c3 ρx - K,  c43 = c3 ρy - K,  c13 = c3 (1 - ρx - ρy) + K

    For a = b = 0 and a centred centre of mass (ρx = ρy = M/(2M_Σ)) this is the paper's
    c23 = c33 = c43 = K, c13 = (M + 4m) K / M, c3 = 4 K M_Σ / M.

    Parameters
    ----------
    M, m : platform and rotor mass [kg]
    xi, eta : centre of mass from corner O1 [m]
    A, B : sides of the support rectangle [m]
    a, b : exciter axis point in the body frame [m]
    K : reference vertical stiffness, c33 [N/m]

    >>> c = vertical_from_position(2e4, 25.0, 1.5, 1.0, 3.0, 2.0, 0.0, 0.0, 1e8)
    >>> [round(x / 1e8, 9) for x in c]
    [1.005, 1.0, 1.0, 1.0]
    """
    rx, ry = load_shares(M, m, xi, eta, A, B, a, b)
    c3 = 4.0 * K / (rx + ry)
    return c3 * (1.0 - rx - ry) + K, c3 * rx - K, K + 0.0 * c3, c3 * ry - K


def horizontal_sums(M, m, omega, xi, eta, A, B, a, b, c0):
    """The four horizontal pair sums that stop the platform from yawing, Eqs. (3.6)-(3.8).

    Source: [1]_, Eqs. (3.6)-(3.8) (equivalently (3.16)-(3.17) once (3.9)-(3.10), (3.14) hold)::

        c31 + c41 = [ω² (M η + m b) + b (c0 - M_Σ ω²)] / B,   c11 + c21 = c0 - (c31 + c41)
        c22 + c32 = [ω² (M ξ + m a) + a (c0 - M_Σ ω²)] / A,   c12 + c42 = c0 - (c22 + c32)

    Example (a = b = 0, centred): (3.19) c22 + c32 = c31 + c41 = Mω²/2 and
    (3.20) c11 + c21 = c12 + c42 = ω² ((M + 2m)/2 - m l / u).

    Parameters
    ----------
    M, m : platform and rotor mass [kg]
    omega : rotor speed [rad/s]
    xi, eta : centre of mass from corner O1 [m]
    A, B : sides of the support rectangle [m]
    a, b : exciter axis point [m]
    c0 : summed horizontal stiffness (3.14) [N/m]

    Returns
    -------
    (c11 + c21, c31 + c41, c12 + c42, c22 + c32) [N/m]

    >>> import math
    >>> w = 50 * math.pi
    >>> s = horizontal_sums(2e4, 25.0, w, 1.5, 1.0, 3.0, 2.0, 0.0, 0.0,
    ...                     summed_stiffness(2e4, 25.0, 0.2, 1e-3, w, -1.0))
    >>> [round(x / 1e8, 4) for x in s]
    [1.2399, 2.4674, 1.2399, 2.4674]
    """
    w2 = omega**2
    excess = c0 - (M + m) * w2
    s_y_back = (w2 * (M * eta + m * b) + b * excess) / B
    s_x_right = (w2 * (M * xi + m * a) + a * excess) / A
    return c0 - s_y_back, s_y_back, c0 - s_x_right, s_x_right


@dataclass(frozen=True)
class PlatformDesign:
    """A complete translational design (SI units; arrays allowed in every field).

    Attributes
    ----------
    M, m, l, u, omega, xi, eta, zeta, A, B, g : the inputs (see module docstring)
    sigma : +1 below resonance, -1 above
    c0 : c1 = c2, summed horizontal stiffness (3.14) [N/m]
    a, b, c : exciter axis point in the body frame (3.9)-(3.11) [m]
    stiffness : c_ij, shape (4, 3): rows isolators O1..O4, columns x, y, z [N/m]
    """

    M: object
    m: object
    l: object
    u: object
    omega: object
    xi: object
    eta: object
    zeta: object
    A: object
    B: object
    g: object
    sigma: object
    c0: object
    a: object
    b: object
    c: object
    stiffness: np.ndarray

    @property
    def M_sigma(self):
        """M_Σ = M + m [kg]."""
        return self.M + self.m

    @property
    def c3(self):
        """Summed vertical stiffness c3 = Σ c_i3 [N/m]."""
        return self.stiffness[:, 2].sum(axis=0)

    @property
    def static_deflection(self):
        """Static vertical displacement z = -M_Σ g / c3 [m] (negative: downward), Eq. (3.1)."""
        return -self.M_sigma * self.g / self.c3

    @property
    def horizontal_sums(self) -> dict:
        """The four pair sums of (3.16)-(3.20) by name [N/m]."""
        s = self.stiffness
        return {
            "c11+c21": s[0, 0] + s[1, 0],
            "c31+c41": s[2, 0] + s[3, 0],
            "c12+c42": s[0, 1] + s[3, 1],
            "c22+c32": s[1, 1] + s[2, 1],
        }

    @property
    def translation_frequency(self):
        """Natural frequency of the horizontal translation sqrt(c0 / M_Σ) [rad/s]."""
        return (self.c0 / self.M_sigma) ** 0.5

    @property
    def regime_margin(self):
        """Relative distance of ω from the translational resonance, |ω/p - 1| [-]."""
        return abs(self.omega / self.translation_frequency - 1.0)

    @property
    def singularity_distance(self):
        """|c0 - M ω²| / (M ω²) [-]: (3.11) is singular at 0."""
        w2 = self.omega**2
        return abs(self.c0 - self.M * w2) / (self.M * w2)


def _split_table(sums, vertical, split):
    """The 4×3 table from the four horizontal pair sums, the four verticals and the split."""
    s_front, s_back, s_left, s_right = sums
    f1, f3, f1y, f2y = split
    col_x = [f1 * s_front, (1.0 - f1) * s_front, f3 * s_back, (1.0 - f3) * s_back]
    col_y = [f1y * s_left, f2y * s_right, (1.0 - f2y) * s_right, (1.0 - f1y) * s_left]
    zero = 0.0 * (s_front + vertical[0])
    return np.array([[col_x[i] + zero, col_y[i] + zero, vertical[i] + zero] for i in range(4)])


def require_positive_c0(M, m, l, u, omega, sigma, c0) -> None:
    """Raise :class:`PhysicsError` when (3.14) gives c0 <= 0 or c0 = M ω² (3.11 singular)."""
    if _any(c0 <= 0.0):
        u_min = m * l / (M + m)
        raise PhysicsError(
            f"c0 = c1 = c2 = {_first(c0):.6g} N/m is not positive: above resonance (3.14) gives"
            f" c0 = M_Σ ω² (1 - m l/(M_Σ u)), so the amplitude u must exceed m l / M_Σ = {u_min:.6g} m",
            field="operation.amplitude",
            hint=f"require u > {u_min:.6g} m, or choose regime = \"below\"",
        )
    near = np.abs(c0 - M * omega**2) / (M * omega**2)
    if _any(near <= SINGULAR_C0):
        raise PhysicsError(
            f"c0 = M ω² (relative distance {_first(near):.3g}): the exciter height (3.11) is"
            " infinite; above resonance this happens at u = l",
            field="operation.amplitude",
            hint=f"move u away from the eccentricity l = {np.max(l):.6g} m",
        )


def amplitude_for_margin(M, m, l, sigma, margin):
    """Largest amplitude u [m] whose design keeps the speed ``margin`` away from the
    translational resonance p = sqrt(c0/M_Σ); any smaller u keeps it farther.

    From (3.14), (p/ω)² = 1 + σ q with q = m l/(M_Σ u). Above resonance (σ = -1) the margin
    ω/p - 1 = 1/sqrt(1 - q) - 1 grows with q; below (σ = +1) 1 - ω/p = 1 - 1/sqrt(1 + q) does
    too. So a smaller u (or a larger unbalance m l) moves the resonance away, and the margin d is
    reached at q = 1 - 1/(1 + d)² above and q = 1/(1 - d)² - 1 below (d < 1).

    >>> round(amplitude_for_margin(2e4, 25.0, 0.2, -1.0, 0.2) * 1e3, 4)
    0.8172
    """
    q = 1.0 - 1.0 / (1.0 + margin) ** 2 if sigma < 0 else 1.0 / (1.0 - margin) ** 2 - 1.0
    return m * l / ((M + m) * q)


def _amplitudes_for_height(d: "PlatformDesign", reach: float) -> str:
    """Amplitudes u > 0 for which (3.11) with (3.14) puts the exciter within |c| <= ``reach``.

    c is a linear-fractional function of c0, and c0 of 1/u, so c(u) = ±reach has one root each:
    c0 = (ω² g M_Σ - M ω⁴ ζ ± reach M ω⁴)/(±reach ω² + g), u = σ m l ω²/(c0 - M_Σ ω²). Between
    these roots and the pole u = l (above resonance) c(u) is monotonic, so testing one point of
    each interval finds the amplitudes that work.
    """
    M, m, l, w2, zeta, g, sg = d.M, d.m, d.l, d.omega**2, d.zeta, d.g, d.sigma
    Ms = M + m

    def height(u):
        c0 = summed_stiffness(M, m, l, u, d.omega, sg)
        return float("inf") if c0 == M * w2 else exciter_height(M, m, d.omega, zeta, c0, g)  # (3.11)'s pole

    cuts = [-sg * l] if sg < 0 else []
    for target in (reach, -reach):
        c0 = (w2 * g * Ms - M * w2 * w2 * zeta + target * M * w2 * w2) / (target * w2 + g)
        if c0 != Ms * w2:
            cuts.append(sg * m * l * w2 / (c0 - Ms * w2))
    edges = [0.0] + sorted(u for u in cuts if u > 0.0) + [float("inf")]
    spans = []
    for lo, hi in zip(edges, edges[1:]):
        probe = 2.0 * lo + 1.0 if hi == float("inf") else (lo + hi) / 2.0
        if abs(height(probe)) <= reach:
            if hi == float("inf"):
                spans.append(f"u > {lo:.6g} m")
            else:
                spans.append(f"{lo:.6g} m < u < {hi:.6g} m" if lo > 0.0 else f"u < {hi:.6g} m")
    return " or ".join(spans) or "no amplitude u"


def require_buildable_position(d: "PlatformDesign", position_given: bool) -> None:
    """Raise :class:`PhysicsError` when the exciter's axis point (a, b, c) lies more than
    :data:`EXCITER_REACH` × max(A, B) from the corner O1: no real machine has it there.

    The hint gives what brings it back: for c the amplitudes u (Eqs. (3.11), (3.14)); for a, b
    given through the vertical stiffnesses the load share (c23 + c33)/c3 or (c33 + c43)/c3 of
    (3.9)-(3.10), a = ((c23 + c33)/c3 · A M_Σ - M ξ)/m.
    """
    reach = EXCITER_REACH * max(_first(d.A), _first(d.B))
    Ms = d.M + d.m
    for name, value in (("c", d.c), ("a", d.a), ("b", d.b)):
        worst = float(np.max(np.abs(value)))
        if worst <= reach:
            continue
        where = f"{name} = {_first(value) if _first(value) == -worst else worst:.6g} m"
        if name == "c":
            hint = f"|c| <= {reach:.6g} m for {_amplitudes_for_height(d, reach)} at this speed"
            field = "operation.amplitude"  # c follows from u by (3.11), (3.14): no key of its own
        elif position_given:
            hint = f"give |{name}| <= {reach:.6g} m"
            field = "exciter.position"
        else:
            side, centre, share = (d.A, d.xi, "(c23 + c33)/c3") if name == "a" else (d.B, d.eta, "(c33 + c43)/c3")
            lo, hi = ((d.M * centre + s * d.m * reach) / (side * Ms) for s in (-1.0, 1.0))
            hint = f"|{name}| <= {reach:.6g} m needs {_first(lo):.6g} < {share} < {_first(hi):.6g} (Eqs. (3.9)-(3.10))"
            field = "isolators.vertical"
        raise PhysicsError(
            f"the exciter's axis point comes out at {where}, more than {EXCITER_REACH:g} × max(A, B)"
            f" = {reach:.6g} m from the platform: no machine can be built so",
            field=field,
            hint=hint,
        )


def _u_range(p, q, sigma) -> str:
    """Amplitudes u > 0 with p + σ q / u > 0, as text."""
    if p > 0:
        bound = -sigma * q / p
        return "any amplitude u" if bound <= 0 else f"u > {bound:.6g} m"
    if p < 0 and sigma * q > 0:
        return f"u < {sigma * q / -p:.6g} m"
    if p == 0 and sigma * q > 0:
        return "any amplitude u"
    return "no amplitude u"


def _linear_window(lo, hi, offset, slope, name) -> str:
    """Values x with lo < offset + slope x < hi, as text naming x."""
    if slope == 0:
        return f"no {name}"
    x1, x2 = sorted(((lo - offset) / slope, (hi - offset) / slope))
    return f"{x1:.6g} m < {name} < {x2:.6g} m"


def require_feasible_horizontal(d: PlatformDesign, position_given: bool) -> None:
    """Raise :class:`PhysicsError` naming the first non-positive horizontal pair sum.

    Each sum is ω² (p + σ q / u) in u, and each pair (c22+c32, c12+c42) needs
    0 < M ξ + a k < A c0/ω² with k = (c0 - M ω²)/ω² (for b: η, B), so the hint gives the range
    of u and of a or b that makes it positive.
    """
    M, m, l, Ms, sg = d.M, d.m, d.l, d.M_sigma, d.sigma
    sums = d.horizontal_sums
    k = (d.c0 - M * d.omega**2) / d.omega**2
    terms = {  # p, q of ω²(p + σ q/u) for each sum; (coordinate, offset, side) for the window
        "c11+c21": (Ms - (M * d.eta + m * d.b) / d.B, m * l * (1.0 - d.b / d.B), ("b", M * d.eta, d.B)),
        "c31+c41": ((M * d.eta + m * d.b) / d.B, m * l * d.b / d.B, ("b", M * d.eta, d.B)),
        "c12+c42": (Ms - (M * d.xi + m * d.a) / d.A, m * l * (1.0 - d.a / d.A), ("a", M * d.xi, d.A)),
        "c22+c32": ((M * d.xi + m * d.a) / d.A, m * l * d.a / d.A, ("a", M * d.xi, d.A)),
    }
    for name, (p, q, (coord, offset, side)) in terms.items():
        value = float(np.min(sums[name]))
        if value > 0.0:
            continue
        window = _linear_window(0.0, side * float(np.min(d.c0)) / float(np.min(d.omega)) ** 2, offset, k, coord)
        how = (
            f"exciter position {window} (with the other coordinate fixed)"
            if position_given
            else f"vertical stiffnesses that put the exciter at {window} via (3.9)-(3.10)"
        )
        raise PhysicsError(
            f"the horizontal pair sum {name} = {value:.6g} N/m is not positive, so no isolator"
            " split can realise the design",
            field=f"isolators.{name}",
            hint=f"it is positive for {_u_range(float(p), float(q), float(sg))} at this a, b; or for {how}",
        )


def require_feasible_vertical(M, m, xi, eta, A, B, a, b) -> None:
    """Raise :class:`PhysicsError` when the K-rule of :func:`vertical_from_position` gives a
    non-positive vertical stiffness; the hint gives the range of a (or b) and of c33/c3."""
    Ms = M + m
    rx, ry = load_shares(M, m, xi, eta, A, B, a, b)
    rx, ry = float(np.min(rx)), float(np.min(ry))
    lo, hi = max(0.0, rx + ry - 1.0), min(rx, ry)
    family = (
        f"any explicit split with {lo:.6g} < c33/c3 < {hi:.6g} (give isolators.vertical)"
        if lo < hi
        else "no vertical split at this a, b: (3.3)-(3.4) need 0 < ρx, ρy and ρx + ρy < 1 + min(ρx, ρy)"
    )
    checks = (
        ("c13", rx + ry < 4.0 / 3.0, f"a < {(A * Ms * (4.0 / 3.0 - ry) - M * xi) / m:.6g} m"),
        ("c23", 3.0 * rx > ry, f"a > {(A * Ms * ry / 3.0 - M * xi) / m:.6g} m"),
        ("c43", 3.0 * ry > rx, f"b > {(B * Ms * rx / 3.0 - M * eta) / m:.6g} m"),
    )
    if rx + ry <= 0.0:
        raise PhysicsError(
            f"c3 = 4K/(ρx + ρy) is not positive (ρx = {rx:.6g}, ρy = {ry:.6g}): the exciter"
            " position puts the weight outside the support rectangle",
            field="exciter.position",
            hint=f"move a, b so that (Mξ + ma)/A + (Mη + mb)/B > 0; {family}",
        )
    for name, ok, fix in checks:
        if not ok:
            raise PhysicsError(
                f"the vertical stiffness {name} comes out non-positive with c33 = K and"
                f" (c23 + c43)/2 = K (ρx = {rx:.6g}, ρy = {ry:.6g})",
                field=f"isolators.{name}",
                hint=f"positive for {fix} (other coordinate fixed), or {family}",
            )


def _complete(M, m, l, u, omega, xi, eta, zeta, A, B, sigma, g, a, b, vertical, split, position_given):
    c0 = summed_stiffness(M, m, l, u, omega, sigma)
    require_positive_c0(M, m, l, u, omega, sigma, c0)
    sums = horizontal_sums(M, m, omega, xi, eta, A, B, a, b, c0)
    design = PlatformDesign(
        M=M, m=m, l=l, u=u, omega=omega, xi=xi, eta=eta, zeta=zeta, A=A, B=B, g=g, sigma=sigma,
        c0=c0, a=a, b=b, c=exciter_height(M, m, omega, zeta, c0, g),
        stiffness=_split_table(sums, vertical, split),
    )
    require_feasible_horizontal(design, position_given)
    require_buildable_position(design, position_given)
    return design


def design_from_position(M, m, l, u, omega, xi, eta, zeta, A, B, sigma, g, a, b, K, split) -> PlatformDesign:
    """Design for a given exciter position (a, b) and reference vertical stiffness K.

    Source: [1]_, Eqs. (3.3)-(3.21) with the corrections of the module docstring. The vertical
    stiffnesses follow :func:`vertical_from_position`, the horizontal sums
    :func:`horizontal_sums`, split by ``split`` = (c11/(c11+c21), c31/(c31+c41),
    c12/(c12+c42), c22/(c22+c32)) (0.5 each in the example).

    Raises
    ------
    PhysicsError
        when a stiffness comes out non-positive (the message names it and the range of u, a or
        b that fixes it) or when c0 = M ω².

    >>> import math
    >>> d = design_from_position(2e4, 25.0, 0.2, 1e-3, 50 * math.pi, 1.5, 1.0, 0.65, 3.0, 2.0,
    ...                          -1.0, 9.81, 0.0, 0.0, 1e8, (0.5,) * 4)
    >>> round(float(d.c3) / 1e8, 4), round(float(d.static_deflection) * 1e4, 3), round(d.c, 4)
    (4.005, -4.905, 2.6127)
    """
    require_feasible_vertical(M, m, xi, eta, A, B, a, b)
    vertical = vertical_from_position(M, m, xi, eta, A, B, a, b, K)
    return _complete(M, m, l, u, omega, xi, eta, zeta, A, B, sigma, g, a, b, vertical, split, True)


def design_from_vertical(M, m, l, u, omega, xi, eta, zeta, A, B, sigma, g, vertical, split) -> PlatformDesign:
    """Design for four given vertical stiffnesses (c13, c23, c33, c43); a, b from (3.9)-(3.10).

    Source: [1]_, Eqs. (3.8)-(3.17) with the corrections of the module docstring.

    Raises
    ------
    PhysicsError
        as :func:`design_from_position`.

    >>> import math
    >>> d = design_from_vertical(2e4, 25.0, 0.2, 1e-3, 50.0, 1.5, 1.0, 0.65, 3.0, 2.0, -1.0,
    ...                          9.81, (1.005e8, 1e8, 1e8, 1e8), (0.5,) * 4)
    >>> round(d.c0 / 1e7, 5), round(d.c, 4)
    (3.75625, 2.6091)
    """
    a, b = position_from_vertical(M, m, xi, eta, A, B, *vertical)
    return _complete(M, m, l, u, omega, xi, eta, zeta, A, B, sigma, g, a, b, vertical, split, False)
