"""Rigid or flexible support of a vibration code, classified from the foundation's own modes.

ISO 10816-3:2009, 3.4: the support of machine and foundation is *rigid* in a measuring direction
when the lowest natural frequency of the machine-support system in that direction is at least
25 % above the main excitation frequency (in most cases the rotational frequency), and
*flexible* otherwise; the zone boundaries of Annex A (:mod:`~foundation_calc.checks.codes`)
differ between the two. fcalc computes that system's modes, so it classifies the support
instead of asking for it; ``[limits] foundation`` overrides the classification ("given in the
scene"), which is still shown.

Which modes lie "in a measuring direction": a mode counts in direction d at a point P when it
carries at least :data:`DIRECTION_SHARE` of P's static compliance along d, (φ_Pd,j/p_j)² /
Σ_k (φ_Pd,k/p_k)² with φ_Pd,j the motion of P along d in mass-normalised mode j (the residue of
mode j in the point's direct receptance; a mode below that share would not show as a peak in a
bump test at P along d). Each judged point (the centre of mass and every ``[[points]]``, the
bearings where the code's velocity is measured) is classified in each direction the code judges
(horizontal and vertical in the plane of a crank foundation; x, y, z on a block), and its zone
is read in the table of the class of each direction
(:func:`~foundation_calc.checks.codes.point_zone`).

The main excitation frequency is the machine's speed; on a block carrying several machines, the
highest of their speeds (the support is rigid for every machine only if it is for the fastest).
"""

from __future__ import annotations

import math
from dataclasses import dataclass

import numpy as np

#: A mode this far above the main excitation frequency, or more, makes the support rigid in its
#: direction (ISO 10816-3:2009, 3.4: "at least 25 %") [-].
RIGID_RATIO = 1.25

#: The clause of the classification.
CLAUSE = "ISO 10816-3:2009, 3.4"

#: Smallest share of a point's static compliance along a direction carried by a mode for the mode
#: to lie in that direction (module docstring) [-]: at 1.25 times the speed a mode amplifies its
#: own share by 1/(1 - 0.64) = 2.8, so a 1 % share stays within 3 % of the point's motion.
DIRECTION_SHARE = 0.01


#: Why ``fcalc design``'s vectorised evaluators leave a scene whose code's support class the
#: modes decide to the full path (``fcalc check``'s, candidate by candidate).
PER_CANDIDATE = ("the code's support class is classified from each candidate's modes (no [limits] foundation),"
                 " which the batch does not do")


@dataclass(frozen=True)
class SupportClass:
    """The support class of one measuring direction at one point.

    Attributes
    ----------
    direction : the measuring direction (``"horizontal"``, ``"vertical"``; ``"x"``, ``"y"``, ``"z"``)
    support : the class the zone is read with: ``"rigid"`` or ``"flexible"``
    given : True when the scene's ``[limits] foundation`` gave it
    mode : the lowest mode in the direction (its name), None when no mode moves the point along it
    frequency : that mode's natural frequency [rad/s] (nan without one)
    excitation : the main excitation frequency [rad/s]
    by_modes : the class the modes give (``support`` unless the scene overrides it)
    """

    direction: str
    support: str
    given: bool
    mode: str | None
    frequency: float
    excitation: float
    by_modes: str

    @property
    def reason(self) -> str:
        """Why the modes give their class, e.g. ``"p1 = 8.92 Hz < 1.25 × 25 Hz = 31.25 Hz"``."""
        if self.mode is None:
            return f"no mode moves the point along {self.direction}"
        hz = 1.0 / (2.0 * math.pi)
        sign = ">=" if self.by_modes == "rigid" else "<"
        return (f"{self.mode} = {self.frequency * hz:.4g} Hz {sign} {RIGID_RATIO:g} × {self.excitation * hz:.4g} Hz"
                f" = {RIGID_RATIO * self.excitation * hz:.4g} Hz")

    @property
    def text(self) -> str:
        """E.g. ``"flexible, classified from the modes: p1 = 8.92 Hz < 1.25 × 25 Hz = 31.25 Hz"`` or
        ``"rigid, given in the scene (the modes: flexible, p1 = ...)"``."""
        if not self.given:
            return f"{self.support}, classified from the modes: {self.reason}"
        differs = "" if self.by_modes == self.support else f" (the modes: {self.by_modes}, {self.reason})"
        return f"{self.support}, given in the scene{differs}"

    def document(self) -> dict:
        return {"direction": self.direction, "support": self.support, "given": self.given, "mode": self.mode,
                "frequency": None if math.isnan(self.frequency) else self.frequency, "excitation": self.excitation,
                "ratio": RIGID_RATIO, "by_modes": self.by_modes, "text": self.text}


def classify(labels, frequencies, motion: np.ndarray, directions, excitation: float, given: str | None = None
             ) -> tuple[SupportClass, ...]:
    """The support class of each direction at one point (module docstring).

    Parameters
    ----------
    labels : (J,) the modes' names
    frequencies : (J,) their natural frequencies [rad/s]
    motion : (D, J) the point's motion along each direction in each mass-normalised mode
    directions : (D,) the directions' names
    excitation : the main excitation frequency [rad/s]
    given : the scene's class, which overrides the modes', or None

    >>> [c.support for c in classify(["a", "b"], [10.0, 20.0], np.array([[1.0, 0.0], [0.0, 1.0]]), ["x", "z"], 10.0)]
    ['flexible', 'rigid']
    """
    p = np.asarray(frequencies, dtype=float)
    compliance = (np.asarray(motion, dtype=float) / np.where(p > 0.0, p, np.inf)) ** 2
    total = compliance.sum(axis=-1, keepdims=True)
    share = compliance / np.where(total > 0.0, total, 1.0)
    found = []
    for d, direction in enumerate(directions):
        inside = [j for j in np.argsort(p, kind="stable") if share[d, j] >= DIRECTION_SHARE and total[d, 0] > 0.0]
        if inside:
            j = int(inside[0])
            mode, frequency = str(labels[j]), float(p[j])
            by_modes = "rigid" if frequency >= RIGID_RATIO * excitation else "flexible"
        else:
            mode, frequency, by_modes = None, math.nan, "rigid"
        found.append(SupportClass(direction, given or by_modes, given is not None, mode, frequency, float(excitation),
                                  by_modes))
    return tuple(found)


def crank_supports(scene, frequencies) -> dict[str, tuple[SupportClass, ...]]:
    """Point name -> the support class (horizontal, vertical) of C and of every point of a
    ``crank_foundation`` scene whose modes k0, p1, p2 have ``frequencies``
    (:class:`~foundation_calc.solvers.crank.frequencies.NaturalFrequencies`, rad/s; on a
    frequency-dependent soil each at its own frequency; on a support coupling sway with rocking, a
    pile group, the one model's modes the resonance check reports:
    :func:`~foundation_calc.checks.resonance.frequencies.scene_plane_modes`); the main excitation is the speed."""
    from foundation_calc.checks.resonance.frequencies import scene_plane_modes

    modes = scene_plane_modes(scene, {m: float(getattr(frequencies, m)) for m in ("k0", "p1", "p2")})
    excitation = scene.speed.omega_rad_s
    given = scene.limits.foundation
    points = [("C", 0.0, 0.0), *((p.name, p.horizontal, p.height) for p in scene.points)]
    return {name: classify(modes.labels, modes.frequencies, modes.point_motion(u, H), ("horizontal", "vertical"),
                           excitation, given)
            for name, u, H in points}


def block_supports(scene, modes, cog) -> dict[str, tuple[SupportClass, ...]]:
    """Point name -> the support class (x, y, z) of the centre of mass G (at ``cog`` [m] from O)
    and of every point of a ``block_foundation`` scene with ``modes``
    (:class:`~foundation_calc.solvers.block.response.BlockModes`); the main excitation is the
    highest machine speed."""
    from foundation_calc.solvers.rigid_body.kinematics import point_maps

    labels = [f"mode {j + 1} ({motion})" for j, motion in enumerate(modes.dominant)]
    excitation = max(m.omega_rad_s for m in scene.machines)
    at = np.array([cog, *(p.at for p in scene.points)], dtype=float)
    motion = point_maps(at) @ modes.shapes  # (points, 3, 6)
    given = scene.limits.foundation
    names = ["G", *(p.name for p in scene.points)]
    return {name: classify(labels, modes.frequencies, motion[i], ("x", "y", "z"), excitation, given)
            for i, name in enumerate(names)}


def governing_support(row) -> str:
    """The support class of a zone row's governing direction (``row.direction_text``) in a phrase
    with the clause, e.g. ``"support flexible, classified from the modes: ... (ISO 10816-3:2009, 3.4)"``;
    empty for a row without classes."""
    found = [c for c in row.support if c.direction == row.direction_text]
    return f"support {found[0].text} ({CLAUSE})" if found else ""


def support_lines(supports: dict[str, tuple[SupportClass, ...]]) -> list[str]:
    """The classification in a few lines: per direction, the points that share a class and its
    reason (one line when every point agrees)."""
    if not supports:
        return []
    lines = []
    directions = [c.direction for c in next(iter(supports.values()))]
    for d, direction in enumerate(directions):
        groups: dict[str, list[str]] = {}
        for name, classes in supports.items():
            groups.setdefault(classes[d].text, []).append(name)
        for text, names in groups.items():
            where = "every point" if len(groups) == 1 else ", ".join(f'"{n}"' for n in names)
            lines.append(f"{direction} at {where}: {text}")
    return lines


__all__ = ["CLAUSE", "DIRECTION_SHARE", "PER_CANDIDATE", "RIGID_RATIO", "SupportClass", "block_supports", "classify", "crank_supports", "governing_support",
           "support_lines"]
