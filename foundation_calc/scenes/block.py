"""Scene model of kind ``block_foundation``: a rigid block in six degrees of freedom carrying
several machines, each at its own speed, on springs and dashpots at its base.

Axes (docs/block-foundation.md): origin O at the centre of the block's base, at base level;
x along the block's length, y along its width, z up; rotations right-handed about x, y, z.
"""

from __future__ import annotations

from typing import Literal

from pydantic import field_validator, model_validator

from foundation_calc.scenes.block_isolators import BlockIsolator, Isolation, isolators_error
from foundation_calc.scenes.block_parts import BlockBody, BlockMachine, BlockPoint
from foundation_calc.scenes.block_piles import BlockPiles, PiledSoil, piled
from foundation_calc.scenes.block_soil import BlockSoil
from foundation_calc.scenes.common import LENGTH_SCALE_FACTOR, KeyProblem, RunTimes, quantity
from foundation_calc.scenes.crank import Limits
from foundation_calc.scenes.plausibility import Plausible, Remark, culprit_error, key_pattern
from foundation_calc.scenes.project import SceneHeader, SheetOptions
from foundation_calc.scenes.soil import FREQUENCY_DEPENDENT_METHODS, OnSoil
from foundation_calc.scenes.stratum import stratum_error, stratum_remarks

#: How far [m] a position may lie beyond the block's footprint or below its base and still count
#: as on it: coordinates are typed to the millimetre (a point on an edge or a corner is on the block).
ON_BLOCK = 1e-3

#: Largest crank radius over rod length λ = r/l of a plausible crank throw (real rods: λ 0.14-0.4).
CRANK_RATIO = 0.5

#: What each code of :func:`placement` says about a position, after its key and value.
PLACEMENT_TEXTS = {
    1: "is more than {far:g} × the base's diagonal {size:.3g} m from O; was it typed in mm?",
    2: "is below the block's base (z < 0; O is the centre of the base, z up); was z measured downward, or"
       " from the block's top?",
    3: "is outside the block's footprint (|x| <= L/2 = {x:g} m, |y| <= B/2 = {y:g} m; O is the centre of the"
       " base); was it measured from a corner?",
}


def placement(position, L, B):
    """Where positions [m] from O, shape (..., 3), lie on a block whose base is L × B [m] (floats,
    or arrays over a batch of candidate blocks that broadcast with the positions' leading axes):
    0 on the block (its footprint |x| <= L/2, |y| <= B/2, at or above its base z = 0, to
    :data:`ON_BLOCK`), 1 more than :data:`~foundation_calc.scenes.common.LENGTH_SCALE_FACTOR` ×
    the base's diagonal from O (probably mm typed as m), 2 below the base, 3 beyond the footprint.

    >>> placement([[0.5, 0.0, 2.0], [0.5, 0.0, -1.0], [4.0, 0.0, 1.0], [0.0, 0.0, 900.0]], 6.0, 4.0).tolist()
    [0, 2, 3, 1]
    """
    import numpy as np

    p = np.asarray(position, dtype=float)
    far = np.max(np.abs(p), axis=-1) > LENGTH_SCALE_FACTOR * np.hypot(L, B)
    below = p[..., 2] < -ON_BLOCK
    beyond = (np.abs(p[..., 0]) > L / 2.0 + ON_BLOCK) | (np.abs(p[..., 1]) > B / 2.0 + ON_BLOCK)
    return np.where(far, 1, np.where(below, 2, np.where(beyond, 3, 0)))


class BlockLimits(Limits):
    """What the checks compare against: the crank foundation's limits (bearing_pressure among them), and the office checks'."""

    amplitude: float | None = quantity(
        "u_max", "m", "largest allowed peak displacement of G and of every point, each direction", None, gt=0,
        examples=[5.0e-5],
    )
    eccentricity: float = quantity(
        "e_max", "-", "largest allowed horizontal distance of the combined centre of mass from the base centroid,"
        " as a fraction of the base dimension in that direction (ACI 351.3R: 0.05)", 0.05, gt=0, lt=0.5,
    )
    mass_ratio: float = quantity(
        "μ_min", "-", "smallest foundation-to-machine mass ratio (rules of thumb: 3 for rotating machines,"
        " 5 for reciprocating ones)", 3.0, gt=0, examples=[5.0],
    )


class BlockOperation(RunTimes):
    """Start-up and run-down of every machine (fcalc runup): each runs from rest to its own speed
    in the same time, as the platform's and crank foundation's [operation] tables give them."""


class BlockScene(Plausible, OnSoil, SceneHeader):
    """A scene of kind ``block_foundation``."""

    kind: Literal["block_foundation"] = quantity("-", "-", 'scene kind, always "block_foundation"')
    block: BlockBody
    machines: list[BlockMachine] = quantity("-", "-", "the machines on the block, each with its own speed", min_length=1)
    soil: BlockSoil | None = quantity(
        "-", "-", "the soil under the block (its method and data); leave it out for a block on [[isolators]]", None
    )
    isolators: list[BlockIsolator] = quantity(
        "-", "-", "spring isolators under the block instead of soil (an inertia block), one table per isolator;"
        " with [isolation]", []
    )
    isolation: Isolation | None = quantity(
        "-", "-", "the damping of the [[isolators]]: loss_factor or damping_ratio, and/or time_constant", None
    )
    piles: BlockPiles | None = quantity(
        "-", "-", "a pile group under the block, its base the rigid cap: the group's springs and dashpots replace"
        " the footing's ([soil] gives the soil around the piles); optional", None
    )
    points: list[BlockPoint] = quantity("-", "-", "points whose vibration is checked (besides the centre of mass)", [])
    limits: BlockLimits = BlockLimits()
    operation: BlockOperation | None = quantity(
        "-", "-", "run-up and run-down times of the machines (fcalc runup); optional", None
    )
    report: SheetOptions | None = quantity(
        "-", "-", "what the calculation sheet adds: design, the ranges over which the sheet of a failing scene"
        " sizes the block (fcalc design); optional", None
    )

    @field_validator("machines")
    @classmethod
    def _distinct_machines(cls, machines: list[BlockMachine]) -> list[BlockMachine]:
        names = [m.name for m in machines]
        repeated = sorted({n for n in names if names.count(n) > 1})
        if repeated:
            raise ValueError(f"machine names must be distinct: {', '.join(repeated)}")
        for m in machines:
            if not m.parts:
                raise ValueError(f"machine {m.name!r} needs [[machines.loads]], [machines.unbalance], [[machines.cranks]]"
                                 " or [[machines.exciters]]")
        return machines

    @field_validator("points")
    @classmethod
    def _distinct_points(cls, points: list[BlockPoint]) -> list[BlockPoint]:
        seen, repeated = {"G"}, set()  # G, the centre of mass, is always reported under that name
        for point in points:
            (repeated if point.name in seen else seen).add(point.name)
        if repeated:
            raise ValueError(f"point names must be distinct and not 'G' (the centre of mass): {', '.join(sorted(repeated))}")
        return points

    @model_validator(mode="after")
    def _frames(self):
        """A machine of parts alone (``mass = 0``) only where
        :meth:`~foundation_calc.scenes.block_parts.BlockMachine.frameless_error` allows it."""
        for i, m in enumerate(self.machines):
            if (error := m.frameless_error(f"machines[{i}]")) is not None:
                raise KeyProblem(f"machines.{i}.{error[0]}", error[1])
        return self

    @model_validator(mode="after")
    def _soil_or_isolators(self):
        """One support: ``[soil]`` (with ``[piles]`` if any), or ``[[isolators]]`` with ``[isolation]``
        that carry the block (:func:`~foundation_calc.scenes.block_isolators.isolators_error`)."""
        if not self.isolators:
            if self.soil is None:
                raise KeyProblem("soil", "give [soil] (the soil under the block) or [[isolators]] with [isolation]"
                                 " (spring isolators under it)")
            if self.isolation is not None:
                raise KeyProblem("isolation", "[isolation] is the damping of [[isolators]]: give the isolators, or remove it")
            return self
        if self.soil is not None or self.piles is not None:
            given = "[soil]" if self.piles is None else "[soil] and [piles]"
            raise KeyProblem("isolators", f"give [[isolators]] or {given}, not both: the block stands on one support")
        if self.isolation is None:
            raise KeyProblem("isolation", "[[isolators]] need [isolation] with loss_factor [-] or damping_ratio [-] (η = 2 ξ),"
                             " and/or time_constant [s]; give damping_ratio = 0 for undamped springs")
        if self.block.embedment:
            raise KeyProblem("block.embedment", f"block.embedment = {self.block.embedment:g} m: a block on [[isolators]] is not"
                             " embedded in soil; remove the key")
        if (error := isolators_error(self.isolators, *self.isolated_weight())) is not None:
            raise ValueError(error)
        return self

    def isolated_weight(self) -> tuple[float, list[float]]:
        """(W [N], r_G [m] from O): the weight of the block with every machine (their time-averaged
        mass properties) and its centre of mass."""
        import numpy as np

        from foundation_calc.solvers.constants import GRAVITY

        masses, centres, _ = self._bodies()
        m = float(sum(masses))
        cog = sum(mi * np.asarray(c, dtype=float) for mi, c in zip(masses, centres)) / m
        return m * GRAVITY, cog.tolist()

    @model_validator(mode="after")
    def _embedment_has_its_method(self):
        if self.soil is None:
            return self
        if self.block.embedment and self.soil.method_used not in FREQUENCY_DEPENDENT_METHODS:
            raise KeyProblem(
                "block.embedment",
                f"block.embedment = {self.block.embedment:g} m is taken by soil methods 'gazetas' and 'pais_kausel'"
                f" only; method {self.soil.method_used!r} takes the base as a surface footing (remove the key, or"
                " choose one of those methods)"
            )
        if (error := stratum_error(self.soil, self.embedment, "block.embedment")) is not None:
            raise ValueError(error)
        return self

    @model_validator(mode="after")
    def _piles_carry_the_block(self):
        """The support: a pile group when ``[piles]`` is given (:class:`~foundation_calc.scenes.block_piles.PiledSoil`,
        the one place a support other than the footing's soil is chosen), its heads under the base."""
        if self.piles is None or isinstance(self.soil, PiledSoil):
            return self
        object.__setattr__(self, "soil", piled(self.soil, self.piles, self.base))
        return self

    @property
    def embedment(self) -> float:
        """D: the base's depth below the ground surface [m], 0 for a surface footing."""
        return self.block.embedment or 0.0

    @property
    def base(self) -> tuple[float, float]:
        """(L, B): the base's length along x and width along y [m]."""
        return self.block.length, self.block.width

    def positions(self) -> dict[str, list[float]]:
        """The positions [m] from O that the scene gives, by key as written: every machine's centre
        of mass, its loads', unbalance's and exciters' points, the checked points, and the block's centre of
        mass when the block is given by its mass."""
        found = {} if self.block.cog is None else {"block.cog": self.block.cog}
        for i, m in enumerate(self.machines):
            found[f"machines[{i}].cog"] = m.cog
            found |= {f"machines[{i}].loads[{j}].at": ld.at for j, ld in enumerate(m.loads) if ld.at is not None}
            if m.unbalance is not None and m.unbalance.at is not None:
                found[f"machines[{i}].unbalance.at"] = m.unbalance.at
            found |= {f"machines[{i}].cranks[{j}].crank_centre": c.crank_centre for j, c in enumerate(m.cranks)}
            found |= {f"machines[{i}].exciters[{j}].at": e.at for j, e in enumerate(m.exciters) if e.at is not None}
        return found | {f"points[{k}].at": p.at for k, p in enumerate(self.points)}

    def carried_positions(self) -> dict[str, str]:
        """Key of each of :meth:`positions` that a machine carries rigidly -> the key of that
        machine's centre of mass: a crank mechanism's centres, whose mean mass and harmonics the
        model gives at, and moves with, the machine's centre of mass
        (:data:`~foundation_calc.scenes.block_parts.MACHINE_PARTS`). A resized block
        (``fcalc design``) moves them by their machine's displacement; every other position by its
        own place on the block."""
        return {f"machines[{i}].cranks[{j}].crank_centre": f"machines[{i}].cog"
                for i, m in enumerate(self.machines) for j in range(len(m.cranks))}

    def related_findings(self, prefix: str, found: list) -> list:
        """The positions that are not on the block (:func:`placement`): more than
        :data:`~foundation_calc.scenes.common.LENGTH_SCALE_FACTOR` × the base's diagonal from O (mm
        typed as m), below its base or beyond its footprint (measured from a corner, or downward);
        an exciter's eccentricity beyond half the block's smaller side unless the table judged it
        (``found``); the table judges every other key (:func:`~foundation_calc.scenes.plausibility.findings`)."""
        judged = {f.key for f in found}
        positions = self.positions()
        L, B = self.base
        codes = placement(list(positions.values()), L, B).tolist() if positions else []
        sizes = {"far": LENGTH_SCALE_FACTOR, "size": (L * L + B * B) ** 0.5, "x": L / 2.0, "y": B / 2.0}
        found = [Remark(key, f"{key} = {list(value)} m " + PLACEMENT_TEXTS[code].format(**sizes))
                 for (key, value), code in zip(positions.items(), codes) if code]
        for i, m in enumerate(self.machines):
            for j, c in enumerate(m.cranks):
                lam = c.crank_radius / c.rod_length
                if lam > CRANK_RATIO:
                    found.append(Remark(f"machines[{i}].cranks[{j}].rod_length", (
                        f"machines[{i}].cranks[{j}]: λ = crank_radius/rod_length = {lam:.3g} is above {CRANK_RATIO:g}; connecting"
                        " rods of compressors and engines are 2.5 to 7 crank radii long (λ 0.14-0.4): was the stroke typed"
                        " as the crank radius, or the rod measured between other points?")))
        for i, m in enumerate(self.machines):
            if m.unbalance is not None and m.unbalance.rotor_mass > m.mass > 0.0:
                key = f"machines[{i}].unbalance.rotor_mass"
                found.append(Remark(key, f"{key} = {m.unbalance.rotor_mass:g} kg exceeds the machine's mass"
                                         f" machines[{i}].mass = {m.mass:g} kg, which includes its rotor; are both in kg"
                                         " (one typed in t is 1000 × low)?"))
        half = min(L, B) / 2.0
        for i, m in enumerate(self.machines):
            for j, e in enumerate(m.exciters):
                key = f"machines[{i}].exciters[{j}].eccentricity"
                if e.eccentricity > half and key not in judged:
                    found.append(Remark(key, f"{key} = {e.eccentricity:g} m exceeds half the block's smaller side"
                                             f" ({half:g} m): the rotor would sweep beyond the block; was it typed in mm?"))
        return found + ([] if self.soil is None else stratum_remarks(self.soil, L, B))

    def stable_model(self):
        """:meth:`model` of the scene as it is, for the checks.

        Raises
        ------
        PhysicsError
            when the block tips over: a rocking spring at O no stiffer than the weight's
            overturning moment W z_G (docs/block-foundation.md), naming the likely culprit, an
            implausible input the springs or the weight depend on (a modulus typed in MPa, a block
            in mm), or else the key that sets the rocking springs.
        """
        import numpy as np

        from foundation_calc.solvers.constants import GRAVITY

        model = self.model()
        rocking = np.diagonal(model.K)[3:5]  # K_rx, K_ry less W z_G (block_model)
        if (rocking > 0.0).all():
            return model
        axis = "x" if not rocking[0] > 0.0 else "y"
        spring, tilt = float(model.springs[3 if axis == "x" else 4]), float(model.mass * GRAVITY * model.cog[2])
        text = (f"the block tips over about {axis}: its rocking spring K_r{axis} = {spring:.4g} N m/rad at O does not"
                f" exceed the overturning moment of the weight W z_G = {tilt:.4g} N m per rad"
                f" (K_r{axis}/(W z_G) - 1 = {spring / tilt - 1.0:.4g})")
        weight = ("machines[].mass", "machines[].cog")
        not_rocking = () if self.soil is None else self.soil.not_rocking
        culprits = [x for x in self.plausibility_findings() if x.key not in not_rocking
                    and (x.key.startswith(("soil.", "block.", "V_s", "isolators")) or key_pattern(x.key) in weight)]
        lower = "lower the centre of mass (block.height, machines[].cog)"
        if self.soil is None:
            raise culprit_error(text, culprits, "isolators", "spread the isolators wider (isolators[].position) or stiffen"
                                f" them (isolators[].stiffness k_z), or {lower}")
        key = self.soil.rocking_key
        raise culprit_error(text, culprits, key, f"stiffen {key}, or {lower}")

    def _bodies(self, block=None, machine_cogs=None):
        """(masses, cogs, central inertias) of the block, every machine's frame (none for a machine
        of parts alone, ``mass = 0``) and every machine's parts with mass (their time-averaged mass
        properties, moved with their machine; ``block`` and ``machine_cogs`` as :meth:`model` takes them)."""
        import numpy as np

        m_b, r_b, J_b = self.block.mass_properties if block is None else block
        cogs = [m.cog for m in self.machines] if machine_cogs is None else list(machine_cogs)
        framed = [(m, cog) for m, cog in zip(self.machines, cogs) if m.mass > 0.0]  # parts alone: no frame body
        masses, centres, inertias = ([m_b] + [m.mass for m, _ in framed], [r_b] + [c for _, c in framed],
                                     [J_b] + [m.inertia for m, _ in framed])
        for machine, cog in zip(self.machines, cogs):
            for mass, centre, inertia in machine.bodies():
                masses.append(mass)
                centres.append(centre + (np.asarray(cog, dtype=float) - np.asarray(machine.cog, dtype=float)))
                inertias.append(inertia)
        return masses, centres, inertias

    def support(self, base=None, block=None, machine_cogs=None):
        """What carries the block (:func:`~foundation_calc.solvers.supports.support_of`: its
        ``[[isolators]]``, a pile group on ``[piles]``, else the footing on ``[soil]``), under the body of :meth:`model`'s masses;
        ``base``, ``block`` and ``machine_cogs`` as :meth:`model` takes them (a batch of candidates)."""
        import numpy as np

        from foundation_calc.solvers.rigid_body.inertia import bodies_mass_matrix
        from foundation_calc.solvers.supports import support_of

        L, B = self.base if base is None else base
        M = bodies_mass_matrix(*self._bodies(block, machine_cogs))
        return support_of(self, L, B, np.diagonal(M, 0, -2, -1))

    def soil_impedance(self, omega, base=None, block=None, machine_cogs=None):
        """The six springs [N/m, N m/rad] and dashpots [N s/m, N m s/rad] at O, each of shape
        omega.shape + (6,), at the frequencies ``omega`` [rad/s] (:meth:`support`'s impedance:
        a frequency-dependent support's K(ω), C(ω), the others' constants); ``base``, ``block``
        and ``machine_cogs`` as :meth:`model` takes them (a batch of N candidates): ``omega``'s
        leading axis is then the batch's. A support with coupled springs (a pile group's
        sway-rocking) adds their off-diagonal K and C, each omega.shape + (6, 6)."""
        at = self.support(base, block, machine_cogs).impedance(omega)
        return (at.springs, at.dashpots) + (() if at.coupling is None else at.coupling)

    def model(self, base=None, block=None, machine_cogs=None):
        """The block with every machine on its support's springs and dashpots at O
        (:func:`~foundation_calc.solvers.block.model.block_model`), a frequency-dependent
        support's taken at ω = 0 (:meth:`soil_impedance` gives them at any frequency), and the
        machines' mean gyroscopic coupling in C (:meth:`gyroscopic`).

        ``base`` (L, B) [m] and ``block`` (mass [kg], centre of mass (..., 3) [m], central inertia
        tensor (..., 3, 3) [kg m²]) replace the scene's own, as arrays over a batch of candidate
        blocks (``fcalc design``): the model's matrices are then stacks; ``machine_cogs`` (one
        (..., 3) [m] per machine) the machines' centres of mass, moved with each candidate's block."""
        from foundation_calc.solvers.block.model import block_model
        from foundation_calc.solvers.constants import GRAVITY

        L, B = self.base if base is None else base
        at = self.support(base, block, machine_cogs).impedance(0.0)
        return block_model(*self._bodies(block, machine_cogs), at.springs, GRAVITY, (L * L + B * B) ** 0.5,
                           dashpots=at.dashpots, coupling=at.coupling, gyroscopic=self.gyroscopic())

    def gyroscopic(self):
        """The machines' mean gyroscopic coupling Σ D̄ at their speeds (6, 6) [kg/s, ..., kg m²/s]
        (:attr:`~foundation_calc.scenes.block_parts.BlockMachine.gyroscopic`), which :meth:`model`
        adds to C; None when no machine has one."""
        found = [m.gyroscopic for m in self.machines if m.gyroscopic is not None]
        return sum(found) if found else None

    def excitations(self):
        """Every machine's loads at its speed (:class:`~foundation_calc.solvers.block.model.Excitation`)."""
        from foundation_calc.solvers.block.model import excitation

        return [excitation(m.name, m.omega_rad_s, m.load_rows(), m.gyroscopic) for m in self.machines]
