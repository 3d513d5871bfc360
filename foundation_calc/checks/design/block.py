"""The block engine of the one batch checker (:mod:`.batch`): the checks of a ``block_foundation``
scene (``CHECKS["block_foundation"]``) over a batch of candidate blocks at once: the same equations as :func:`~foundation_calc.checks.amplitudes.machines.check_block`,
on stacks of matrices instead of one.

A candidate varies the block's length, width or height (:data:`VARIABLE_KEYS`, a block given by
height and density) and the sizes of its own its support lets a design vary (the support's
sizing hooks, :class:`~foundation_calc.solvers.supports.base.Sizing`: every candidate on the
support at its own sizes, e.g. a pile group's length and diameter); the machines, their loads
and the points move with the block's top and end faces as
:func:`~foundation_calc.checks.design.apply.moved` says (those on the top rise with it, those on
an end face follow the face), as ``fcalc check`` sees the scene of
:func:`~foundation_calc.checks.design.apply.apply`. For each candidate:

- the mass matrix of the block and the machines, the soil's six springs and damping of the base
  L × B (every soil method of :class:`~foundation_calc.scenes.block_soil.BlockSoil`, on arrays)
  and the weight's tilt: :meth:`~foundation_calc.scenes.block.BlockScene.model` with a stack;
- the six modes by one batched Cholesky reduction and ``eigh``
  (:func:`~foundation_calc.solvers.block.response.batch_modes`); on a frequency-dependent soil
  each at its own frequency (:func:`~foundation_calc.solvers.block.response.consistent_batch`),
  and each order's steady state with the springs and dashpots at n ω;
- ``resonance``: every order of every machine against every mode, forcing shares, judged by
  the resonance rule (:func:`~foundation_calc.checks.resonance.rule.judge`) over all the
  conditions of the candidate; the governing condition is the one ``fcalc check`` names;
- ``amplitudes``: the damped steady state per machine and order by one batched complex solve,
  peaks (machines' peaks added) and RMS values (root-sum-square) of G and the points against
  ``[limits]``, and the code zone of each point's largest RMS velocity;
- ``office``: eccentricity of the combined centre of mass, bearing pressure, mass ratio;
- ``inputs``: the plausibility warnings of the candidate's scene (a warning; no number): its
  positions off the block (more than 10 × the base's diagonal from O, below the base, beyond the
  footprint), its dimensions and the support's sizes against their ranges, the support's own
  warnings of its sizes (a pile group's L/d, active length and spacing), and the scene's findings
  that do not depend on the candidate;
- ``scene``: where the support's sizes make a scene ``fcalc check`` refuses (a pile group whose
  piles overlap: :meth:`~foundation_calc.solvers.supports.base.Sizing.size_errors`), the
  candidate fails it (utilisation inf) and passes every other check with no number, as the
  reference evaluator judges a scene it cannot build (:mod:`.reference`);
- ``runup``: not evaluated here (:data:`NOT_EVALUATED`).

Utilisation (demand over capacity, :mod:`.candidates`): resonance, the margin the governing
condition needs over its margin (above 1 it fails, or, for an order-1 condition the forcing
does not drive, warns); amplitudes, the largest value over its limit (peak or RMS, or RMS
velocity over the code zone's boundary that fails it); office, the largest of e/(e_max L),
q_max/q_a and μ_min/μ (eccentricity and mass ratio warn, the pressure fails). A block that tips
over or is unrestrained (a squared frequency not positive, which ``fcalc check`` reports as an
error) fails the resonance and amplitude checks with utilisation inf, and one that tips over (a
rocking spring at O no stiffer than W z_G, which ``fcalc check`` refuses) the office checks too.
"""

from __future__ import annotations

from dataclasses import dataclass
from types import SimpleNamespace

import numpy as np

from foundation_calc.checks.design.candidates import FAIL, PASS, WARN, Batch, CandidateVerdicts, failing, largest_ratio

#: The scene keys a candidate may vary [m].
VARIABLE_KEYS = ("block.length", "block.width", "block.height")

#: Candidates evaluated together: stacks of this many 6×6 matrices stay in the processor's cache
#: (10⁵ candidates take about 40 % longer in one piece than in pieces of this size).
PIECE = 16_384

#: Checks the batch does not evaluate, with why: outcome PASS and utilisation NaN for every
#: candidate, so the search must re-check its front-runners by the full path (``fcalc check``).
NOT_EVALUATED = {
    "runup": "the start-up and run-down are integrated in time (0.5-10 s a scene); judged by the re-check of the"
             " chosen designs only",
    "modulus_range crossings on a frequency-dependent soil": "over a soil's modulus_range the resonance and amplitude"
             " checks are judged at the grid factors fcalc check takes, but on a frequency-dependent soil (gazetas) not"
             " at the factors between them where a critical speed crosses a machine's speed (their amplitude peak);"
             " the re-check of the chosen designs judges those",
}


def _dimensions(scene, batch: Batch):
    """(the block's keys :data:`VARIABLE_KEYS` -> the scene's values; the batch). Raises ValueError
    for a block given by its mass."""
    if scene.block.height is None:
        raise ValueError("the block's dimensions vary only for a block given by length, width, height and density (not by mass)")
    return {key: getattr(scene.block, key.split(".")[1]) for key in VARIABLE_KEYS}, batch


def _placing(scene, L, B, H):
    """position [m] -> its positions (N, 3) on the candidate blocks (:func:`~foundation_calc.checks.design.apply.moved`)."""
    from foundation_calc.checks.design.apply import moved

    old = (scene.block.length, scene.block.width, scene.block.height)
    return lambda position: moved(position, old, (L, B, H))


def _resonance(scene, modes, excitations):
    """Outcome, utilisation, governing index and reasons of the ``resonance`` check
    (:func:`~foundation_calc.checks.amplitudes.machines.resonance_rows` and ``BlockReport.nearest``)."""
    from foundation_calc.checks.amplitudes.machines import condition_label
    from foundation_calc.checks.resonance.batch import governing_verdicts
    from foundation_calc.checks.resonance.rule import judge, required_detuning
    from foundation_calc.solvers.block.response import resonances
    from foundation_calc.solvers.rigid_body.modes import MOTIONS

    margins, shares, orders, labels = [], [], [], []
    for exc in excitations:
        res = resonances(modes, exc)
        margins.append(res.margin.reshape(len(res.margin), -1))
        shares.append(res.share.reshape(len(res.share), -1))
        orders.append(np.repeat(exc.orders, 6))
        labels += [(exc.name, int(n), j + 1) for n in exc.orders for j in range(6)]
    margin, share, order = np.concatenate(margins, -1), np.concatenate(shares, -1), np.concatenate(orders)
    required = required_detuning(scene.limits.detuning, order)
    verdict = judge(margin, order, share, required, np.zeros(order.shape, dtype=bool))
    governing = verdict.governing
    motion = modes.dominant[np.arange(len(margin)), np.array([j - 1 for _, _, j in labels])[governing]]
    reasons = tuple(
        condition_label(SimpleNamespace(machine=name, order=n, mode=j, motion=m))
        for name, n, j in labels for m in MOTIONS
    )
    return *governing_verdicts(verdict, margin), governing * len(MOTIONS) + motion, reasons


def _amplitudes(scene, model, modes, excitations, points, impedance=None):
    """Outcome, utilisation, governing index and reasons of the ``amplitudes`` check
    (:func:`~foundation_calc.checks.amplitudes.report.judge`), by the one batch judge
    (:func:`~foundation_calc.checks.amplitudes.batch.judge_batch`): a peak is the exact largest of
    the machines' combined motion over every point and direction, at its row alone (the other rows
    cannot govern: -inf); an RMS value, every row's."""
    from foundation_calc.checks.amplitudes.batch import judge_batch
    from foundation_calc.checks.amplitudes.machines import DIRECTIONS, LIMITED_VALUES
    from foundation_calc.solvers.block.response import acceleration, largest_peak, point_motion, resonances, resonant, velocity

    n = len(model.M)
    stuck = np.zeros(n, dtype=bool)
    for exc in excitations:
        stuck |= resonant(modes, resonances(modes, exc))
    # the peak fields of PointMotion -> the series of a machine's displacement amplitudes U whose peak each holds
    rates = {"peak": lambda U, exc: U, "velocity_peak": velocity, "acceleration_peak": acceleration}
    names = ["G"] + [p.name for p in scene.points]
    motion = []  # the points' motion, solved once when first asked

    def values(quantity):
        if not motion:
            motion.append(point_motion(model, excitations, names[1:], points, frozenset(), impedance=impedance))
        field = LIMITED_VALUES[quantity]
        if field not in rates:
            return getattr(motion[0], field)  # (N, points, 3)
        parts = [(rates[field](U, exc), exc.orders) for U, exc in zip(motion[0].displacement, excitations)]
        largest, row = largest_peak([(Z.reshape(n, -1, Z.shape[-1]), orders) for Z, orders in parts])
        found = np.full((n, len(names) * len(DIRECTIONS)), -np.inf)
        found[np.arange(n), row] = largest
        return found.reshape(n, len(names), len(DIRECTIONS))

    return judge_batch(names, DIRECTIONS, values, scene.limits, [(exc.name, exc.omega) for exc in excitations],
                       [(stuck, "an order is resonant with an undamped mode: no steady state")])


def _office(scene, model, L, B, m_b):
    """Outcome, utilisation, governing index and reasons of the ``office`` check
    (:func:`~foundation_calc.checks.office.office_rows`)."""
    from foundation_calc.checks.office import bearing_pressure, settlement
    from foundation_calc.solvers.constants import GRAVITY
    from foundation_calc.solvers.supports.base import bears_on_soil

    limits = scene.limits
    e_x, e_y = model.cog[:, 0], model.cog[:, 1]
    ratios = [np.abs(e_x) / L / limits.eccentricity, np.abs(e_y) / B / limits.eccentricity]
    outcomes = [np.where(r > 1.0, WARN, PASS) for r in ratios]  # abs(e)/L > e_max warns
    reasons = ["eccentricity x", "eccentricity y"]
    if limits.bearing_pressure is not None and bears_on_soil(scene.support()):  # as office_rows judges it
        q = bearing_pressure(model.mass * GRAVITY, e_x, e_y, L, B)
        ratios.append(q / limits.bearing_pressure)
        outcomes.append(np.where(q > limits.bearing_pressure, FAIL, PASS))
        reasons.append("bearing pressure")
    if limits.settlement is not None:
        s = settlement(model.mass * GRAVITY, model.springs[..., 2])
        ratios.append(s / limits.settlement)
        outcomes.append(np.where(s > limits.settlement, FAIL, PASS))
        reasons.append("settlement")
    mu = m_b / sum(m.total_mass for m in scene.machines)
    ratios.append(limits.mass_ratio / mu)
    outcomes.append(np.where(mu < limits.mass_ratio, WARN, PASS))
    reasons.append("mass ratio")
    outcome = np.max(np.stack(outcomes, axis=-1), axis=-1).astype(np.int8)
    return outcome, *largest_ratio(ratios, len(L)), tuple(reasons)


def _inputs(scene, sizing, sizes, L, B, H):
    """Outcome and governing index of the ``inputs`` check (plausibility warnings), as ``fcalc
    check`` finds them on each candidate's scene: a position not on the candidate's block
    (:func:`~foundation_calc.scenes.block.placement`: mm typed as m, below the base, beyond the
    footprint), a dimension or a size of the support (``sizes``, key -> (N,)) outside its plausible
    range, the support's own warnings of its sizes (``sizing``'s
    :meth:`~foundation_calc.solvers.supports.base.Sizing.size_warnings`), a stratum shallower than
    twice the candidate base's equivalent radius (:func:`~foundation_calc.scenes.stratum.shallow`),
    or any finding of the scene that does not depend on the candidate (the soil, the machines, the
    limits)."""
    from foundation_calc.checks.design.apply import moved_positions
    from foundation_calc.checks.design.supported import fixed_findings, sizes_outside
    from foundation_calc.scenes.block import placement
    from foundation_calc.scenes.plausibility import KEYS, RANGES
    from foundation_calc.scenes.stratum import shallow

    positions = scene.positions()
    warned = sizing.size_warnings(sizes, L, B)
    fixed = bool(fixed_findings(scene, scene.base, lambda key: key in positions or key in VARIABLE_KEYS, sizes, warned))
    outside = np.zeros(L.shape, dtype=bool)
    for key, values in zip(VARIABLE_KEYS, (L, B, H)):
        outside |= RANGES[KEYS[key]].outside(values)
    support_outside = sizes_outside(sizes, L.shape)
    placed = np.zeros(L.shape, dtype=int)  # the first position off the block names the reason
    block = (scene.block.length, scene.block.width, scene.block.height)
    for position in moved_positions(scene, block, (L, B, H)).values():
        placed = np.where(placed == 0, placement(position, L, B), placed)
    own = np.where(support_outside, 7, np.where(warned.which > 0, 7 + warned.which, 0))
    governing = np.where(placed > 0, placed, np.where(outside, 4, np.where(own > 0, own, np.where(
        shallow(scene.soil, L, B), 6, 5 if fixed else 0))))
    reasons = ("no input outside its plausible range", "a position from O more than 10 × the base's diagonal (mm typed as m?)",
               "a position below the block's base", "a position beyond the block's footprint",
               "a block dimension outside its plausible range", "an input value outside its plausible range",
               "soil.stratum_depth less than twice the base's equivalent radius",
               "a size of the support outside its plausible range", *warned.reasons)
    return np.where(governing > 0, WARN, PASS).astype(np.int8), governing, reasons


def evaluate(scene, batch: Batch) -> CandidateVerdicts:
    """Every check of ``fcalc check`` (module docstring) on every candidate of ``batch``
    (:data:`VARIABLE_KEYS` -> (N,) values in SI units), by the one batch checker
    (:func:`~foundation_calc.checks.design.batch.evaluate`) with this kind's engine.

    Raises
    ------
    ValueError
        for a key not in :data:`VARIABLE_KEYS`, or a block given by its mass (no dimensions to vary).
    NotImplementedError
        for a code whose support class the modes of each candidate decide (no ``[limits] foundation``),
        and over the soil's modulus range for a support whose springs do not scale with one factor
        (:attr:`~foundation_calc.solvers.supports.base.Support.unscaled`: the batch scales them so,
        :mod:`.block_range`; a pile group's, EN 1998-5 Table C.1, K ∝ E_s^(1 - n)).
    """
    from foundation_calc.checks.design.batch import Engine, evaluate as checked

    engine = Engine(kind="block_foundation", piece=PIECE, runup="not evaluated for a batch: " + NOT_EVALUATED["runup"],
                    dimensions=_dimensions, refuse=lambda scene: None, density=lambda scene: scene.block.density,
                    prepare=lambda scene: None, judge=_judge)
    return checked(scene, batch, engine)


#: What governs a check whose outcome the soil's modulus range makes worse than the data as given.
RANGE_REASON = "the soil's modulus range (a stiffness factor within it; fcalc check names which)"


def dynamics(scene, built, checks=("resonance", "amplitudes"), modes=None):
    """check -> (outcome, utilisation, governing, reasons) of the resonance and amplitude checks on
    the candidates ``built`` (:class:`Built`; a block that tips over fails both, as does one with a
    mode without a natural frequency, :func:`~foundation_calc.solvers.block.response.consistent_batch`);
    ``modes``: their modes, if the caller has them already."""
    from foundation_calc.solvers.block.response import batch_modes, consistent_batch
    from foundation_calc.solvers.soil.impedance import rootless_reason

    model, excitations = built.model, built.excitations
    if modes is None:
        modes = batch_modes(model) if built.impedance is None else consistent_batch(model, built.impedance, "nan")
    unstable = ~modes.stable
    rootless = np.zeros_like(unstable) if modes.rootless is None else modes.rootless & ~unstable
    found = {}
    for check in checks:
        o, u, g, r = (_resonance(scene, modes, excitations) if check == "resonance"
                      else _amplitudes(scene, model, modes, excitations, built.points, built.impedance))
        r = r + ("the block tips over or is unrestrained (a squared natural frequency is not positive)",
                 f"{rootless_reason('')} (fcalc check: invalid scene)")
        found[check] = (*failing(unstable | rootless, o, u, g, np.where(unstable, len(r) - 2, len(r) - 1)), r)
    return found


@dataclass(frozen=True)
class Built:
    """Candidate blocks on a scene's soil: their model (stacks), every machine's loads, the points
    (N, P, 3) [m] (or (P, 3), the same on every block), the soil's impedance ω -> (springs,
    dashpots) of a frequency-dependent soil (else None) and the blocks' masses [kg]; :func:`dynamics`
    reads the first four (a sample of one block's soil, :mod:`~foundation_calc.checks.soil_sample.block`,
    gives no other)."""

    model: object
    excitations: list
    points: np.ndarray
    impedance: object
    block_mass: np.ndarray


def _built(scene, L, B, H) -> Built:
    """The candidate blocks L × B × H [m] on ``scene`` (:class:`Built`)."""
    from foundation_calc.solvers.block.batch_design import block_bodies
    from foundation_calc.solvers.block.model import excitation

    block = block_bodies(L, B, H, scene.block.density)
    place = _placing(scene, L, B, H)
    cogs = [place(m.cog) for m in scene.machines]
    model = scene.model(base=(L, B), block=block, machine_cogs=cogs)
    excitations = [excitation(m.name, m.omega_rad_s, [row._replace(at=place(row.at)) for row in m.load_rows()])
                   for m in scene.machines]
    points = np.stack([place(p.at) for p in scene.points], axis=-2) if scene.points else np.zeros((0, 3))
    impedance = None
    if scene.support((L, B), block, cogs).frequency_dependent:  # each mode at its own frequency, each order at n ω

        def impedance(omega):
            return scene.soil_impedance(omega, base=(L, B), block=block, machine_cogs=cogs)

    return Built(model, excitations, points, impedance, block[0])


def _judge(scene, _, support, L, B, H, sizes) -> dict:
    """check -> (outcome, utilisation, governing, reasons) of the resonance, amplitude, inputs and
    office checks of the blocks (L, B, H) on ``support`` at their ``sizes`` (key -> (N,))."""
    with np.errstate(divide="ignore", invalid="ignore"):  # a block that tips over has p = 0: judged below
        scene = support.sized(scene, sizes)  # every candidate on its support at its own sizes
        inputs = _inputs(scene, support, sizes, L, B, H)
        built = _built(scene, L, B, H)
        found = dynamics(scene, built)
        if getattr(scene.soil, "modulus_range", None) is not None:
            from foundation_calc.checks.design.block_range import judged
            from foundation_calc.checks.design.modulus_range import over_range

            found = over_range(scene, found, judged(scene, (L, B, H), _built, dynamics), RANGE_REASON)
        o, g, r = inputs
        found["inputs"] = (o, np.full(len(L), np.nan), g, r)
        found["office"] = _unless_tipped(built.model, _office(scene, built.model, L, B, built.block_mass))
    return found


def _unless_tipped(model, check):
    """``check`` (outcome, utilisation, governing, reasons) with every candidate that tips over
    failing it, utilisation inf: a rocking spring at O no stiffer than the weight's overturning
    moment (K_rx or K_ry less W z_G not positive), which ``fcalc check`` refuses as an invalid
    scene, every check with it (:meth:`~foundation_calc.scenes.block.BlockScene.stable_model`)."""
    o, u, g, r = check
    tips = ~(np.diagonal(model.K, axis1=-2, axis2=-1)[..., 3:5] > 0.0).all(axis=-1)
    r = (*r, "the block tips over (fcalc check: invalid scene)")
    return (*failing(tips, o, u, g, len(r) - 1), r)


__all__ = ["NOT_EVALUATED", "VARIABLE_KEYS", "Built", "dynamics", "evaluate"]
