"""The crank foundation's footing (``kind = "crank_foundation"``, paper 000's plane problem): the
footing of :mod:`.footing` on the scene's ``[soil]``, in the paper's symbols.

Two things differ from a block's footing, both from how the paper writes its base and its body:

- Barkan's coefficients and SP 26 take the base's area S and second moment I1 as the scene gives
  them (K_z = c S, K_x = c1 S, K_φ = c_φ I1), the half-space methods its rectangle L × B
  (``foundation.dimensions``); a candidate block of another base is its rectangle's.
- The body is the plane's (:func:`plane_masses`): the total mass M_tot = M + m + m1 on the
  translations and I_0 = I_c + M_tot h² about the base's axis, which set the half-space methods'
  mass ratios and the dashpots 2 ξ √(K m) of the damping ratios
  (:func:`~foundation_calc.solvers.soil.dashpots.dashpots_from_ratios`).

Everything else (the springs of each method, the stratum, the range of a0, the sheet's items) is
the footing's, but the sheet's statement of the soil model, which it gives in the plane and in the
paper's symbols (:data:`PLANE_MODELS`). :func:`plane` reads a support's springs and dashpots in the plane of the motion
(K_x, K_z, K_φ; C_x, C_z, C_φ at O), the closed forms' supports.
"""

from __future__ import annotations

import numpy as np

from foundation_calc.solvers.soil.springs import SoilSprings
from foundation_calc.solvers.supports.base import Assumption
from foundation_calc.solvers.supports.footing import Footing
from foundation_calc.solvers.supports.footing_springs import six_springs

#: The motions of the plane at O, in q's order: u_x, u_z, θ_y.
PLANE = (0, 2, 4)

_HALF_SPACE = ("Uniform elastic half-space under a rigid surface base, {springs} in the plane of the motion, with L in"
               " it; radiation dashpots plus material damping. Frequency-dependent: every harmonic n is solved with"
               " K(nω), C(nω) and every mode at its own frequency.")

#: soil.method -> how the plane's springs and dashpots at O are found (the sheet's assumptions), in the paper's symbols.
PLANE_MODELS = {
    "coefficients": "Winkler springs from Barkan's coefficients [Ba]: K_z = c S, K_x = c1 S, K_φ = c_φ I1 (c_φ default"
                    " c); dashpots 2 ξ √(K m) of each uncoupled motion from the given damping ratios (m: M_tot, or"
                    " I_0 = I_c + M_tot h² in rocking). Frequency-independent.",
    "lysmer": "Uniform elastic half-space under a rigid surface base, Lysmer's and Hall's analogs in the plane of the"
              " motion [RHW] (equivalent radius per motion; mass ratios of M_tot and I_0 = I_c + M_tot h²): radiation"
              " plus material damping. Frequency-independent, fitted for a0 < 1.5.",
    "gazetas": _HALF_SPACE.format(springs="Gazetas' stiffnesses and radiation dashpots of the rectangle [Ga]"),
    "pais_kausel": _HALF_SPACE.format(springs="Pais & Kausel's stiffnesses with their frequency modifiers [PK] and"
                                              " Gazetas' dashpots"),
    "sp26": "The code's coefficients C_z, C_x, C_φ from the deformation modulus and the soil class: K_z = C_z S,"
            " K_x = C_x S, K_φ = C_φ I1; damping ratios of the code [SP26]. Frequency-independent.",
}


def plane_masses(M_tot, I_0) -> np.ndarray:
    """The body's diagonal of M about O, (..., 6) [kg, kg m²], as the plane gives it: M_tot [kg] on
    the three translations and I_0 [kg m²] about the three axes through O. The plane problem knows
    its inertia about y alone; about x and z the value sets only the out-of-plane dashpots and
    mass ratios, which the plane never reads (arrays broadcast: a batch of blocks)."""
    M_tot, I_0 = np.broadcast_arrays(np.asarray(M_tot, dtype=float), np.asarray(I_0, dtype=float))
    return np.stack([M_tot, M_tot, M_tot, I_0, I_0, I_0], axis=-1)


class PlaneFooting(Footing):
    """The footing (:class:`~.footing.Footing`'s arguments) whose coefficient and SP 26 springs take
    ``section`` = (S [m²], I_x, I1 [m⁴]), the base's area and second moments about x and y."""

    def __init__(self, soil, L, B, masses, D, section):
        super().__init__(soil, L, B, masses, D)
        self.section = section

    def springs(self, L, B, m, omega) -> tuple:
        """:meth:`Footing.springs` with the base's ``section`` (:func:`~.footing_springs.six_springs`)."""
        extra = (1,) * (np.ndim(L) - np.ndim(self.L))  # the axes :meth:`_at` gave L past the batch's
        section = tuple(np.reshape(v, np.shape(v) + extra) for v in self.section)
        return *six_springs(self.soil, L, B, m[..., 0], np.moveaxis(m[..., 3:], -1, 0), omega, self.D, section), None

    def assumptions(self) -> tuple[Assumption, ...]:
        """The plane's soil model (:data:`PLANE_MODELS`) and the footing's base row."""
        return (Assumption("soil", PLANE_MODELS[self.method]), *super().assumptions()[1:])

    def plane_springs(self, omega) -> SoilSprings:
        """The plane's springs K_z, K_x, K_φ and damping ratios ξ_z, ξ_x, ξ_φ at ``omega`` [rad/s], as the
        paper's chain and a batch of candidate blocks take them (floats for one block at one frequency)."""
        omega, m, L, B = self._at(omega)
        springs, ratios, _ = self.springs(L, B, m, omega)
        (K_x, K_z, K_phi), (xi_x, xi_z, xi_phi) = ([_number(v[i]) for i in PLANE] for v in (springs, ratios))
        return SoilSprings(K_z=K_z, K_x=K_x, K_phi=K_phi, xi_z=xi_z, xi_x=xi_x, xi_phi=xi_phi)


def _number(x):
    """A float of a scalar (a 0-d array too), an array as it is."""
    return float(x) if np.ndim(x) == 0 else x


def plane_dashpots(springs: SoilSprings, M_tot, I_0) -> dict:
    """C_x, C_z, C_phi [N s/m, N m s/rad] of the plane ``springs``' damping ratios under a body of total
    mass M_tot [kg] and I_0 [kg m²] about the base's axis
    (:func:`~foundation_calc.solvers.soil.dashpots.dashpots_from_ratios`); exactly 0 undamped."""
    if all(np.max(np.abs(xi)) == 0.0 for xi in (springs.xi_z, springs.xi_x, springs.xi_phi)):
        return {"C_x": 0.0, "C_z": 0.0, "C_phi": 0.0}
    from foundation_calc.solvers.soil.dashpots import dashpots_from_ratios

    d = dashpots_from_ratios(springs.xi_z, springs.xi_x, springs.xi_phi, K_z=springs.K_z, K_x=springs.K_x,
                             K_phi=springs.K_phi, M_tot=M_tot, I_0=I_0)
    return {"C_x": _number(d.C_x), "C_z": _number(d.C_z), "C_phi": _number(d.C_phi)}


def plane_footing(soil, L, B, S, I1, masses, D) -> PlaneFooting:
    """The footing on ``soil`` under a base L × B [m] of area S [m²] and second moment I1 [m⁴] about y
    (about x the rectangle's L B³/12), a body of diagonal ``masses`` (..., 6), embedded D [m]."""
    return PlaneFooting(soil, L, B, masses, D, (S, L * B**3 / 12.0, I1))


def build(scene, L, B, masses):
    """A crank foundation stands on its ``[soil]``: under its own base the section it gives (S,
    I1), under another (a candidate block's, arrays) that base's rectangle."""
    if getattr(scene, "kind", None) != "crank_foundation":
        return None
    f = scene.foundation
    own = np.ndim(L) == 0 and np.ndim(B) == 0 and (float(L), float(B)) == tuple(map(float, f.dimensions))
    S, I1 = (f.base_area, f.base_second_moment) if own else (L * B, B * L**3 / 12.0)
    return plane_footing(scene.soil, L, B, S, I1, masses, f.embedment or 0.0)


#: An off-diagonal term at most this times √(|K_ii K_jj|) (of C: √(|C_ii C_jj|)) is round-off of the
#: support's assembly (a pile group's symmetric heads), not a coupling [-].
NEGLIGIBLE = 1e-9

#: The one coupling of the plane's motions a crank scene takes: u_x with θ_y (a pile group's sway-rocking).
SWAY_ROCKING = (0, 4)


def plane(at, name: str) -> tuple:
    """((K_x, K_z, K_φ), (C_x, C_z, C_φ), (K_xφ, C_xφ)) at O of a support's springs and dashpots
    ``at`` (:class:`~.base.AtO`), the plane's motions u_x, u_z, θ_y [N/m, N m/rad; N s/m, N m s/rad]
    and the sway-rocking coupling of u_x with θ_y [N/rad; N s/rad] (0 for an uncoupled support).

    The crank's plane model takes that one coupling (a pile group's); any other coupling of a
    motion of the plane (an off-diagonal term in the rows of u_x, u_z, θ_y but u_x with θ_y)
    raises :class:`~foundation_calc.errors.PhysicsError` naming the support ``name``, never
    dropped. Couplings among the motions out of the plane alone (u_y, θ_x, θ_z) are not read: the
    crank's body and forcing leave those motions at rest. What cannot take the sway-rocking
    coupling refuses it where it is called (:func:`require_uncoupled`; a design's closed forms by
    its own :attr:`~foundation_calc.solvers.crank.mechanism.CrankDesign.coupled`)."""
    zero = 0.0 * at.springs[..., 0]
    if at.coupling is None:
        return (tuple(at.springs[..., i] for i in PLANE), tuple(at.dashpots[..., i] for i in PLANE), (zero, zero))
    K_c, C_c = (np.asarray(at.coupling[i]) for i in (0, 1))
    i, j = SWAY_ROCKING
    scale = [np.sqrt(np.abs(d[..., PLANE, None] * d[..., None, :])) for d in (at.springs, at.dashpots)]
    off = np.stack([np.where(np.abs(A[..., PLANE, :]) > NEGLIGIBLE * s, A[..., PLANE, :], 0.0)
                    for A, s in zip((K_c, C_c), scale)])
    # the rows of u_x and θ_y are 0 and 2 of PLANE: their terms in the columns of θ_y and u_x
    off[..., PLANE.index(i), j] = off[..., PLANE.index(j), i] = 0.0
    if np.any(off != 0.0):
        from foundation_calc.errors import PhysicsError

        raise PhysicsError(
            f"the support {name} couples the motions of the plane at O other than u_x with θ_y (the sway-rocking a"
            " symmetric pile group gives); the crank foundation's plane model takes that one coupling", field="soil",
            hint="describe the foundation as a block_foundation scene, whose 6-DOF model takes a coupled support")
    return (tuple(at.springs[..., k] for k in PLANE), tuple(at.dashpots[..., k] for k in PLANE),
            (K_c[..., i, j], C_c[..., i, j]))


def require_uncoupled(coupling, name: str) -> None:
    """Raise :class:`~foundation_calc.errors.PhysicsError` naming the support ``name`` when its
    sway-rocking coupling ``coupling`` = (K_xφ, C_xφ) [N/rad; N s/rad] (:func:`plane`'s) is not 0:
    for what takes the plane's three springs and dashpots uncoupled (the paper's soil-method chain,
    the rigid block under a machine given by its loads), which must refuse the coupling, never
    drop it."""
    if not any(np.any(np.asarray(part) != 0.0) for part in coupling):
        return
    from foundation_calc.errors import PhysicsError

    raise PhysicsError(
        f"the support {name} couples the motions of the plane at O (its K or C has off-diagonal terms in the rows of"
        " u_x, u_z, θ_y); the crank foundation's closed forms take three uncoupled springs and dashpots", field="soil",
        hint="the crank's commands take a support's sway-rocking coupling (a pile group) by the plane's one model;"
             " for another coupling describe the foundation as a block_foundation scene, whose 6-DOF model"
             " takes a coupled support")


__all__ = ["PLANE", "PLANE_MODELS", "SWAY_ROCKING", "PlaneFooting", "build", "plane", "plane_dashpots", "plane_footing", "plane_masses",
           "require_uncoupled"]
