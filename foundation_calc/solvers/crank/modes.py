"""The mode shapes of a crank foundation's plane model (x, y, θ of the centre of mass C), each
mode on the soil's springs at its own frequency, for the checks that ask where a mode moves: the
soil model's range of validity (:mod:`~foundation_calc.checks.soil_validity`, which springs a mode
strains) and the support class of a vibration code (:mod:`~foundation_calc.checks.support`, which
directions a mode moves a point in).

The operator is the block's Eq. (2) of :mod:`~foundation_calc.solvers.crank.loads` (mass
diag(M_tot, M_tot, I_c), the base springs K_x on x − h θ, K_z on y, K_φ on θ and the weight's
−P h), whose frequencies are the paper's zero-order k0, p1, p2 (4.5)-(4.7). On a
frequency-dependent soil the mode p_j is the eigenvector of the operator on the springs K(p_j)
whose eigenvalue is p_j² (p_j solves p = p(K(p)), so p_j² is an eigenvalue there).

On a support that couples sway with rocking (a pile group: K_xφ, C_xφ at O) no uncoupled block
holds the plane: the modes are those of the one model the resonance check solves
(:func:`~foundation_calc.solvers.crank.averaged.plane_frequencies`), the averaged operator M̄, K̄
with the coupling, by its solver (:func:`~foundation_calc.solvers.crank.averaged.natural_modes`),
each mode on the springs at its own frequency p_j, where it is the eigenvector whose eigenvalue is
p_j² (the mode of that rank there, as the resonance check names it), mass-normalised on M̄
(:func:`coupled_plane_modes`). The frequencies there are read as the root search reads them
(``at_rest`` False at p_j ≠ 0): a negative eigenvalue of K̄(p_j) is no real frequency (0), so its
mode is never taken for p_j, where sqrt|λ| would offer it when |λ| is near p_j².
"""

from __future__ import annotations

import math
from collections.abc import Callable, Mapping
from dataclasses import dataclass

import numpy as np

#: The plane model's base springs, in the order of :attr:`PlaneModes.springs`.
BASE_MOTIONS = ("horizontal", "vertical", "rocking")


@dataclass(frozen=True)
class PlaneModes:
    """Modes of the plane model (SI units).

    Attributes
    ----------
    labels : the modes' names, e.g. ``("k0", "p1", "p2")`` (a block that tips over has none of p1, p2)
    frequencies : (J,) natural frequencies [rad/s]
    shapes : (3, J) mass-normalised shapes, rows x [m], y [m], θ [rad] of C
    springs : (J, 3) the base springs K_x [N/m], K_z [N/m], K_φ [N m/rad] each mode was solved on
    h : height of C above the base [m]
    """

    labels: tuple[str, ...]
    frequencies: np.ndarray
    shapes: np.ndarray
    springs: np.ndarray
    h: float

    def base_motion(self) -> np.ndarray:
        """(3, J) motion of the base springs in each mode: x − h θ, y, θ (:data:`BASE_MOTIONS`)."""
        x, y, theta = self.shapes
        return np.array([x - self.h * theta, y, theta])

    def point_motion(self, horizontal: float, height: float) -> np.ndarray:
        """(2, J) horizontal and vertical motion, x + H θ and y + u θ (linear), of the point
        ``horizontal`` = u [m] from C along +x and ``height`` = H [m] above C, in each mode."""
        x, y, theta = self.shapes
        return np.array([x + height * theta, y + horizontal * theta])


def _modes(frequencies: Mapping[str, float], mode_at: Callable) -> PlaneModes:
    """The modes ``frequencies`` (name -> p [rad/s]; nan: left out), ``mode_at(p)`` giving the
    mass-normalised shape (3,) whose frequency is p on the springs at p, those springs K_x, K_z,
    K_φ at O and h [m]."""
    labels, found, shapes, springs, h = [], [], [], [], 0.0
    for label, p in frequencies.items():
        if math.isnan(p):
            continue
        shape, at, h = mode_at(p)
        labels.append(label)
        found.append(p)
        shapes.append(shape)
        springs.append(at)
    return PlaneModes(tuple(labels), np.array(found), np.array(shapes).T.reshape(3, -1), np.array(springs).reshape(-1, 3), h)


def plane_modes(frequencies: Mapping[str, float], block_at: Callable) -> PlaneModes:
    """The shapes of the modes ``frequencies`` (name -> p [rad/s]; nan: left out) of the block
    ``block_at(ω)`` (a :class:`~foundation_calc.solvers.crank.loads.RigidBlock` on the springs at
    ω), each on the springs at its own frequency (module docstring)."""
    from foundation_calc.solvers.crank.loads import matrices
    from foundation_calc.solvers.numerics.symmetric_modes import symmetric_modes

    def mode_at(p):
        block = block_at(p)
        M, K, _ = matrices(block)
        squared, vectors = symmetric_modes(K, M)
        j = int(np.argmin(np.abs(np.sqrt(np.clip(squared, 0.0, None)) - p)))
        return vectors[:, j], (float(block.K_x), float(block.K_z), float(block.K_phi)), float(block.h)

    return _modes(frequencies, mode_at)


def coupled_plane_modes(frequencies: Mapping[str, float], design_at: Callable) -> PlaneModes:
    """The shapes of the modes ``frequencies`` (name -> p [rad/s]; nan: left out) of the one model
    in the plane of the design ``design_at(ω)`` (a
    :class:`~foundation_calc.solvers.crank.mechanism.CrankDesign` on the support at ω, its
    sway-rocking coupling included), each at its own frequency (module docstring); ``springs`` are
    the support's direct springs K_x, K_z, K_φ at O there."""
    from foundation_calc.solvers.crank.averaged import averaged_operator, natural_modes

    def mode_at(p):
        d = design_at(p)
        M, _, K, _, _ = averaged_operator(d)
        natural, vectors = natural_modes(M, K, at_rest=p == 0.0)  # the springs at p: signed, as the root search
        v = vectors[:, int(np.argmin(np.abs(natural - p)))]
        return v / math.sqrt(float(v @ M @ v)), (float(d.c1 * d.S), float(d.c * d.S), float(d.c_phi * d.I1)), float(d.h)

    return _modes(frequencies, mode_at)


__all__ = ["BASE_MOTIONS", "PlaneModes", "coupled_plane_modes", "plane_modes"]
