"""The ``[[isolators]]`` and ``[isolation]`` tables of a block foundation: an inertia block on spring
isolators instead of soil (a fan, pump or compressor isolated from a floor).

Each isolator is three linear springs along the fixed x, y, z axes at its point (the platform's
model, :class:`~foundation_calc.solvers.supports.isolators.Isolators`), its position from O, the
centre of the block's base, as every position of a block scene. One ``[isolation]`` table gives
the damping of all of them, as catalogues give it: a loss factor η (elastomers), or a damping ratio
ξ (steel springs, about 0.005-0.01; taken as the loss factor η = 2 ξ, which gives the ratio ξ at
every resonance whatever the speed), and/or dashpots β k in parallel with every spring (β [s]).

Validation: at least three isolators, not on one line (a line of points leaves the rotation about
it unrestrained); springs >= 0 with every isolator stiff vertically; the springs together restrain
all six motions (K at O positive definite); under the weight every isolator is compressed (none
pulled: the weight's line of action within the isolators).
"""

from __future__ import annotations

from typing import Annotated

import numpy as np
from pydantic import Field, model_validator

from foundation_calc.scenes.common import SceneModel, quantity

#: A triple along x, y, z.
Triple = Annotated[list[float], Field(min_length=3, max_length=3)]

#: K at O is taken as singular when its smallest eigenvalue, with the points' lengths scaled to the
#: isolators' spread, is below this fraction of its largest [-] (double precision cannot tell less
#: from none).
UNRESTRAINED = 1e-9


class BlockIsolator(SceneModel):
    """One isolator under the block: three springs along x, y, z at its point."""

    position: Triple = quantity(
        "r_i", "m", "the isolator's point of action [x, y, z] from O (the centre of the block's base; z = 0 under"
        " the base, z > 0 on a bracket above it)", examples=[[-1.1, -0.7, 0.0]],
    )
    stiffness: Triple = quantity(
        "(k_x, k_y, k_z)", "N/m", "the isolator's springs along x, y and z (a catalogue's horizontal and vertical"
        " spring rates)", examples=[[2.4e5, 2.4e5, 3.0e5]],
    )

    @model_validator(mode="after")
    def _springs(self):
        k = self.stiffness
        if any(not np.isfinite(v) or v < 0.0 for v in k):
            raise ValueError(f"stiffness = {list(k)} N/m: every spring rate must be >= 0 (k_x, k_y, k_z along x, y, z)")
        if k[2] <= 0.0:
            raise ValueError(f"stiffness = {list(k)} N/m: k_z must be > 0 (an isolator carries the block's weight)")
        return self

    def related_findings(self, prefix: str, found: list) -> list:
        """The first spring rate given (> 0) outside the isolators' plausible range
        (:data:`~foundation_calc.scenes.plausibility.RANGES` ``["isolator_stiffness"]``; N/mm typed as N/m)."""
        from foundation_calc.scenes.plausibility import RANGES

        judged = (RANGES["isolator_stiffness"].judge(f"{prefix}stiffness[{j}]", k) for j, k in enumerate(self.stiffness) if k > 0)
        return next(([f] for f in judged if f is not None), [])


class Isolation(SceneModel):
    """The damping of every isolator: a loss factor or a damping ratio, and/or dashpots."""

    loss_factor: float | None = quantity(
        "η", "-", "hysteretic loss factor of every spring (elastomer mounts 0.05-0.2); leave it out with damping_ratio",
        None, ge=0, lt=1, examples=[0.1],
    )
    damping_ratio: float | None = quantity(
        "ξ", "-", "damping ratio of the isolators as a catalogue gives it (steel springs 0.005-0.01, with damper"
        " 0.02-0.1): taken as the loss factor η = 2 ξ; leave it out with loss_factor", None, ge=0, lt=0.5,
        examples=[0.01],
    )
    time_constant: float = quantity(
        "β", "s", "viscous dashpots β k in parallel with every spring k (a dashpot c per spring: β = c/k);"
        " default none", 0.0, ge=0, lt=1, examples=[1.0e-3],
    )

    @model_validator(mode="after")
    def _one_hysteresis(self):
        if self.loss_factor is not None and self.damping_ratio is not None:
            raise ValueError(f"give isolation.loss_factor (η = {self.loss_factor:g}) or isolation.damping_ratio"
                             f" (ξ = {self.damping_ratio:g}, η = 2 ξ), not both")
        return self

    @property
    def eta(self) -> float:
        """η [-]: the loss factor given, else 2 ξ, else 0."""
        if self.loss_factor is not None:
            return self.loss_factor
        return 2.0 * (self.damping_ratio or 0.0)


def isolators_error(isolators: list[BlockIsolator], W: float, cog) -> str | None:
    """Why ``isolators`` cannot carry a body of weight ``W`` [N] whose centre of mass is ``cog`` [m]
    from O, or None: fewer than three, on one line, K at O singular (a motion they leave free), an
    isolator pulled under the weight (tension: the weight outside them)."""
    from foundation_calc.solvers.rigid_body.kinematics import springs_at
    from foundation_calc.solvers.supports.isolators import static_deflections

    r = np.array([i.position for i in isolators], dtype=float)
    k = np.array([i.stiffness for i in isolators], dtype=float)
    if len(r) < 3:
        return f"give at least three [[isolators]] (got {len(r)}): fewer leave the block free to rock"
    spread = r - r.mean(axis=0)
    size = float(np.abs(spread).max())
    if size == 0.0 or np.linalg.matrix_rank(spread / size, tol=1e-6) < 2:
        return (f"the {len(r)} isolators' positions lie on one line: the block is free to turn about it;"
                " place them around the centre of mass (at least three not on a line)")
    scale = np.diag([1.0, 1.0, 1.0, 1.0 / size, 1.0 / size, 1.0 / size])
    values, vectors = np.linalg.eigh(scale @ springs_at(r, k) @ scale)
    if values[0] <= UNRESTRAINED * values[-1]:
        motions = ("u_x", "u_y", "u_z", "θ_x", "θ_y", "θ_z")
        free = ", ".join(f"{v:+.2f} {m}" for v, m in zip(vectors[:, 0], motions) if abs(v) > 0.05)
        return (f"the isolators' springs leave a motion of the block without stiffness ({free}): give k_x and k_y"
                " at enough isolators to restrain sway and torsion")
    load = static_deflections(r, k, W, cog) * k[:, 2]
    if (pulled := np.flatnonzero(load < -1e-9 * W)).size:
        i = int(pulled[0])
        return (f"isolators[{i}] at {list(isolators[i].position)} m is pulled ({load[i] / 1e3:.4g} kN) under the"
                f" weight {W / 1e3:.4g} kN acting at the centre of mass ({cog[0]:.3g}, {cog[1]:.3g}) m: the"
                " isolators must surround it; move them under the centre of mass or stiffen those nearest it")
    return None


__all__ = ["UNRESTRAINED", "BlockIsolator", "Isolation", "isolators_error"]
