"""A ``platform`` scene read as a ``block_foundation``: paper 001's platform is a rigid body on four
three-spring isolators carrying unbalanced exciters, which is a block on ``[[isolators]]`` with
``[[machines.exciters]]`` (docs/block-foundation.md). The commands of the one rigid body
(``fcalc resonance``, ``amplitudes``, ``sweep``, ``soil``) read a platform through
:func:`platform_as_block`; ``fcalc platform``, ``check``, ``report`` and ``runup`` keep the
platform's own design and verification.

Axes: the platform's origin is its corner O1 (x' along A, y' along B, z up); the block's O is the
centre of its base, so every position moves by -(A/2, B/2, 0) and the axes stay.
"""

from __future__ import annotations

import math

from pydantic import PrivateAttr

from foundation_calc.scenes.block import BlockScene
from foundation_calc.scenes.common import MAGNITUDE_RANGE, quantity

#: What the name of a platform read as a block adds to the platform's (the commands' headers show it).
READ_AS_BLOCK = "the platform read as a block on its isolators"

#: The name of the machine that carries the rotors turning at the operating speed.
MAIN_MACHINE = "exciter"


class PlatformAsBlock(BlockScene):
    """The block of :func:`platform_as_block`: a ``block_foundation`` whose plausibility findings
    are the platform scene's, named by the keys its file gives (the block's keys are fcalc's)."""

    name: str = quantity("-", "-", "the platform's name and what reading it as a block adds", "", max_length=400)
    _platform = PrivateAttr(default=None)

    def plausibility_findings(self) -> list:
        """The platform scene's findings (:meth:`~foundation_calc.scenes.platform.PlatformScene.plausibility_findings`)."""
        return self._platform.plausibility_findings()


def _at(position, shift) -> list[float]:
    """A position from O1 [m] as one from the block's O: less ``shift``, a difference below the
    smallest magnitude a scene holds (round-off of a centred design) written as 0."""
    return [0.0 if abs(p - s) < MAGNITUDE_RANGE[0] else float(p - s) for p, s in zip(position, shift)]


def _rotors(scene, design, shift) -> dict[float, list[dict]]:
    """|ω_j/ω| -> the ``[[machines.exciters]]`` tables of the rotors turning at that multiple of the
    speed: the designed exciter (vertical axis through (a, b, c), positive sense, φ0 = 0, as
    :func:`~foundation_calc.solvers.platform.verification.build` places it) and every
    ``[[extra_exciters]]`` rotor, its axis angles (1.3) as the vector e, its sense the sign of its
    speed ratio and its phase turned to the vector's t1
    (:func:`~foundation_calc.solvers.machines.exciter.phase_from_angles`)."""
    from foundation_calc.solvers.machines.exciter import phase_from_angles

    d = design
    groups = {1.0: [{"rotor_mass": d.m, "eccentricity": d.l, "axis": [0.0, 0.0, 1.0],
                     "at": _at((d.a, d.b, d.c), shift), "sense": 1.0, "phase": 0.0}]}
    for x in scene.extra_exciters:
        d1, d2 = x.axis
        e = [math.cos(d1) * math.sin(d2), math.sin(d1) * math.sin(d2), math.cos(d2)]
        groups.setdefault(abs(x.speed_ratio), []).append({
            "rotor_mass": x.rotor_mass, "eccentricity": x.eccentricity,
            "axis": [0.0 if abs(c) < MAGNITUDE_RANGE[0] else c for c in e], "at": _at(x.position, shift),
            "sense": math.copysign(1.0, x.speed_ratio), "phase": x.phase + phase_from_angles(d1, d2)})
    return groups


def block_document(scene, design) -> dict:
    """The ``block_foundation`` document of a platform scene (module docstring) and its ``design``
    (:class:`~foundation_calc.solvers.platform.design.PlatformDesign`): its body as the block, the
    exciters' machines of parts alone (``mass = 0``: their housings are part of the body); the
    isolators the design chooses ((3.8)-(3.21)) at the corners O1..O4; the rotors by speed, one machine per multiple of the speed
    (:func:`_rotors`); the isolators' loss factor η and their dashpots 2 D c_ij/ω as the time
    constant β = 2 D/ω; the detuning and transient amplitude as limits; the run times and drive;
    the points O1 and the product box's eight corners (those ``fcalc platform`` verifies)."""
    from foundation_calc.solvers.platform.verification import product_corners

    p, d = scene.platform, design
    omega = scene.operation.omega_rad_s
    shift = (d.A / 2.0, d.B / 2.0, 0.0)
    cog = _at(p.cog, shift)
    corners = ((0.0, 0.0, 0.0), (d.A, 0.0, 0.0), (d.A, d.B, 0.0), (0.0, d.B, 0.0))
    machines = [{"name": MAIN_MACHINE if ratio == 1.0 else f"exciters at {ratio:g} ω", "mass": 0.0, "cog": cog,
                 "omega": ratio * omega, "exciters": rotors}
                for ratio, rotors in _rotors(scene, d, shift).items()]
    if scene.drive is not None:
        machines[0]["drive"] = scene.drive.model_dump(exclude_unset=True)
    limits = {k: v for k, v in scene.limits.model_dump(exclude_unset=True).items() if k in ("detuning", "transient_amplitude")}
    sources = {k: v for k, v in scene.limits.sources.items() if k in limits}
    operation = scene.operation.model_dump(include={"run_up_time", "run_down_time"}, exclude_none=True)
    isolators = scene.isolators
    document = {
        "kind": "block_foundation",
        "name": f"{scene.name} ({READ_AS_BLOCK})" if scene.name else READ_AS_BLOCK,
        "block": {"length": d.A, "width": d.B, "mass": p.mass, "cog": cog, "inertia": list(scene.inertia)},
        "machines": machines,
        "isolators": [{"position": _at(r, shift), "stiffness": [float(c) for c in k]}
                      for r, k in zip(corners, d.stiffness)],
        "isolation": {"loss_factor": isolators.loss_factor} | (
            {"time_constant": 2.0 * isolators.damping_ratio / omega} if isolators.damping_ratio else {}),
        "points": [{"name": "O1", "at": _at((0.0, 0.0, 0.0), shift)}] + [
            {"name": f"corner {i + 1}", "at": _at(c, shift)}
            for i, c in enumerate(product_corners(d.A, d.B, scene.product_height).tolist())],
        "limits": limits | ({"sources": sources} if sources else {}),
    }
    for key in ("project", "require"):
        if getattr(scene, key) is not None:
            document[key] = getattr(scene, key).model_dump(exclude_unset=True)
    return document | ({"operation": operation} if operation else {})


def platform_as_block(scene, source: str = "<scene>") -> PlatformAsBlock:
    """The platform ``scene`` read as a validated block (:func:`block_document`,
    :class:`PlatformAsBlock`), ``source`` naming it in an error.

    Raises
    ------
    PhysicsError
        The platform cannot be designed (:meth:`~foundation_calc.scenes.platform.PlatformScene.design`),
        or tips over or is not restrained on the designed isolators
        (:func:`~foundation_calc.solvers.platform.dynamics.natural_frequencies`), named by its keys.
    """
    from foundation_calc.scenes.validation import validate
    from foundation_calc.solvers.platform.dynamics import natural_frequencies
    from foundation_calc.solvers.platform.verification import build

    design = scene.design()
    natural_frequencies(*build(design, scene.model()))  # a platform that tips over, refused in its own keys
    block = validate(PlatformAsBlock, block_document(scene, design), source)
    block._platform = scene
    return block


__all__ = ["MAIN_MACHINE", "READ_AS_BLOCK", "PlatformAsBlock", "block_document", "platform_as_block"]
