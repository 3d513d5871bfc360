"""The checks of a ``block_foundation`` scene (``CHECKS["block_foundation"]``) over a batch of
candidate blocks at once: the same equations as :func:`~foundation_calc.checks.block.check_block`,
on stacks of matrices instead of one.

A candidate varies the block's length, width, height or density (:data:`VARIABLE_KEYS`); the
machines, their loads and the points move with the block as :func:`~.apply.moved` says (those on
the top rise with it, those on an end face follow the face), as ``fcalc check`` sees the scene of
:func:`~.apply.apply`. For each candidate:

- the mass matrix of the block and the machines, the soil's six springs and damping of the base
  L × B (every soil method of :class:`~foundation_calc.scenes.block_soil.BlockSoil`, on arrays)
  and the weight's tilt: :meth:`~foundation_calc.scenes.block.BlockScene.model` with a stack;
- the six modes by one batched Cholesky reduction and ``eigh``
  (:func:`~foundation_calc.solvers.block.response.batch_modes`); on a frequency-dependent soil
  each at its own frequency (:func:`~foundation_calc.solvers.block.response.consistent_batch`),
  and each order's steady state with the springs and dashpots at n ω;
- ``resonance``: every order of every machine against every mode, forcing shares, judged by
  the resonance rule (:func:`~foundation_calc.checks.resonance_rule.judge`) over all the
  conditions of the candidate; the governing condition is the one ``fcalc check`` names;
- ``amplitudes``: the damped steady state per machine and order by one batched complex solve,
  peaks (machines' peaks added) and RMS values (root-sum-square) of G and the points against
  ``[limits]``, and the code zone of each point's largest RMS velocity;
- ``office``: eccentricity of the combined centre of mass, bearing pressure, mass ratio;
- ``inputs``: the positions of the scene more than 10 × the base's diagonal from O, and machine
  speeds typed in rpm (a warning; no number);
- ``runup``: not evaluated here (:data:`NOT_EVALUATED`).

Utilisation (demand over capacity, :mod:`.candidates`): resonance, the margin the governing
condition needs over its margin (above 1 it fails, or, for an order-1 condition the forcing
does not drive, warns); amplitudes, the largest value over its limit (peak or RMS, or RMS
velocity over the code zone's boundary that fails it); office, the largest of e/(e_max L),
q_max/q_a and μ_min/μ (eccentricity and mass ratio warn, the pressure fails). A block that tips
over or is unrestrained (a squared frequency not positive, which ``fcalc check`` reports as an
error) fails the resonance and amplitude checks with utilisation inf.
"""

from __future__ import annotations

from types import SimpleNamespace

import numpy as np

from foundation_calc.checks.design.candidates import FAIL, PASS, WARN, Batch, CandidateVerdicts

#: The scene keys a candidate may vary [m, m, m, kg/m³].
VARIABLE_KEYS = ("block.length", "block.width", "block.height", "block.density")

#: Checks the batch does not evaluate, with why: outcome PASS and utilisation NaN for every
#: candidate, so the search must re-check its front-runners by the full path (``fcalc check``).
NOT_EVALUATED = {
    "runup": "the start-up and run-down are integrated in time (0.5-10 s a scene); judged by the re-check of the"
             " chosen designs only",
}

#: Outcome code of each status of :mod:`~foundation_calc.checks.resonance_rule` (clear, information, warn, fail).
_STATUS_OUTCOME = np.array([PASS, PASS, WARN, FAIL], dtype=np.int8)

_CODES = {"pass": PASS, "warn": WARN, "fail": FAIL}


def _candidates(scene, batch: Batch):
    """(L, B, H, ρ) of every candidate, (N,) each [m, m, m, kg/m³]: the scene's values where not varied."""
    unknown = sorted(set(batch) - set(VARIABLE_KEYS))
    if unknown:
        raise ValueError(f"{', '.join(unknown)} cannot vary for a block_foundation scene; the keys that can: {', '.join(VARIABLE_KEYS)}")
    block = scene.block
    if block.height is None and {"block.height", "block.density"} & set(batch):
        raise ValueError("block.height and block.density vary only for a block given by height and density (not by mass)")
    n = len(next(iter(batch.values()))) if batch else 1
    values = []
    for key in VARIABLE_KEYS:
        given = getattr(block, key.split(".")[1])
        values.append(np.broadcast_to(np.asarray(batch.get(key, np.nan if given is None else given), dtype=float), (n,)))
    return values


def _block_body(L, B, H, rho, scene):
    """Mass [kg], centre of mass (N, 3) [m] and central inertia tensor (N, 3, 3) [kg m²] of each
    candidate block (:attr:`~foundation_calc.scenes.block_parts.BlockBody.mass_properties`)."""
    from foundation_calc.solvers.rigid_body.inertia import block_inertia, diagonal_matrices, inertia_tensor

    if scene.block.height is None:
        m, cog, J = scene.block.mass_properties
        return np.full(L.shape, m), np.broadcast_to(np.asarray(cog, dtype=float), L.shape + (3,)), inertia_tensor(J)
    m = L * B * H * rho
    cog = np.stack([np.zeros_like(H), np.zeros_like(H), H / 2.0], axis=-1)
    return m, cog, diagonal_matrices(np.stack(block_inertia(m, L, B, H), axis=-1))


def _resonance(scene, modes, excitations):
    """Outcome, utilisation, governing index and reasons of the ``resonance`` check
    (:func:`~foundation_calc.checks.block.resonance_rows` and ``BlockReport.nearest``)."""
    from foundation_calc.checks.block import condition_label
    from foundation_calc.checks.resonance_rule import judge, required_detuning
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
    rows = np.arange(len(margin))
    governing = verdict.governing
    utilisation = verdict.needed[rows, governing] / margin[rows, governing]
    outcome = _STATUS_OUTCOME[verdict.worst]
    motion = modes.dominant[rows, np.array([j - 1 for _, _, j in labels])[governing]]
    reasons = tuple(
        condition_label(SimpleNamespace(machine=name, order=n, mode=j, motion=m))
        for name, n, j in labels for m in MOTIONS
    )
    return outcome, utilisation, governing * len(MOTIONS) + motion, reasons


def _amplitudes(scene, model, modes, excitations, points, impedance=None):
    """Outcome, utilisation, governing index and reasons of the ``amplitudes`` check
    (:func:`~foundation_calc.checks.block.limit_rows`, :func:`~foundation_calc.checks.block.zone_rows`)."""
    from foundation_calc.checks.block import DIRECTIONS, LIMITED_VALUES
    from foundation_calc.checks.codes import TABLES, ZONES, code_zone_index, zone_verdicts
    from foundation_calc.checks.limits import exceeds, limited_quantities
    from foundation_calc.solvers.block.response import largest_peak, point_motion, resonances, resonant, velocity

    limits = scene.limits
    n = len(model.M)
    stuck = np.zeros(n, dtype=bool)
    for exc in excitations:
        stuck |= resonant(modes, resonances(modes, exc))
    quantities = {q: v for q, v in limited_quantities(limits).items() if q in LIMITED_VALUES}
    names = ["G"] + [p.name for p in scene.points]
    ratios, failed, reasons = [], np.zeros(n, dtype=bool), []
    worst = np.zeros(n, dtype=np.int8)
    if quantities or limits.code is not None:
        motion = point_motion(model, excitations, names[1:], points, frozenset(), impedance=impedance)
        rows = [f"at {p} ({d})" for p in names for d in DIRECTIONS]
        for quantity, limit in quantities.items():
            field = LIMITED_VALUES[quantity]
            if field in ("peak", "velocity_peak"):  # the largest peak of every point and direction, found exactly
                parts = [(U if field == "peak" else velocity(U, exc), exc.orders)
                         for U, exc in zip(motion.displacement, excitations)]
                largest, row = largest_peak([(Z.reshape(n, -1, Z.shape[-1]), orders) for Z, orders in parts])
            else:
                values = getattr(motion, field).reshape(n, -1)  # (N, P·3)
                row = np.argmax(values, axis=-1)
                largest = values[np.arange(n), row]
            ratio = np.full((n, len(rows)), -np.inf)
            ratio[np.arange(n), row] = largest / limit  # the other rows cannot govern
            ratios.append(ratio)
            failed |= exceeds(largest, limit)
            reasons += [f"{quantity} {r}" for r in rows]
        if limits.code is not None:
            table = TABLES[limits.code, limits.machine_group, limits.foundation]
            highest = ZONES.index(limits.acceptable_zone or "B")
            top = motion.velocity_rms.max(axis=-1)  # (N, P): each point's largest direction
            top_x = motion.displacement_rms.max(axis=-1)  # the more restrictive of the two decides
            index, by_x = code_zone_index(top, top_x, table)
            verdicts = np.array([_CODES[v.value] for v in zone_verdicts(limits.acceptable_zone)], dtype=np.int8)
            worst = verdicts[index].max(axis=-1)
            ratios.append(np.where(by_x, top_x / table.displacement_boundaries[highest], top / table.boundaries[highest]))
            reasons += [f"{table.title} zone at {p}" for p in names]
        worst = np.maximum(worst, np.where(failed, FAIL, PASS).astype(np.int8))
    reasons.append("an order is resonant with an undamped mode: no steady state")
    if ratios:
        ratio = np.concatenate(ratios, axis=-1)
        governing, utilisation = np.argmax(ratio, axis=-1), ratio.max(axis=-1)
    else:
        governing, utilisation = np.zeros(n, dtype=int), np.full(n, np.nan)
    outcome = np.where(stuck, FAIL, worst).astype(np.int8)
    governing = np.where(stuck, len(reasons) - 1, governing)
    return outcome, np.where(stuck, np.inf, utilisation), governing, tuple(reasons)


def _office(scene, model, L, B, m_b):
    """Outcome, utilisation, governing index and reasons of the ``office`` check
    (:func:`~foundation_calc.checks.office.office_rows`)."""
    from foundation_calc.checks.office import bearing_pressure
    from foundation_calc.solvers.constants import GRAVITY

    limits = scene.limits
    e_x, e_y = model.cog[:, 0], model.cog[:, 1]
    ratios = [np.abs(e_x) / L / limits.eccentricity, np.abs(e_y) / B / limits.eccentricity]
    outcomes = [np.where(r > 1.0, WARN, PASS) for r in ratios]  # abs(e)/L > e_max warns
    reasons = ["eccentricity x", "eccentricity y"]
    if limits.bearing_pressure is not None:
        q = bearing_pressure(model.mass * GRAVITY, e_x, e_y, L, B)
        ratios.append(q / limits.bearing_pressure)
        outcomes.append(np.where(q > limits.bearing_pressure, FAIL, PASS))
        reasons.append("bearing pressure")
    mu = m_b / sum(m.mass for m in scene.machines)
    ratios.append(limits.mass_ratio / mu)
    outcomes.append(np.where(mu < limits.mass_ratio, WARN, PASS))
    reasons.append("mass ratio")
    ratio = np.stack(ratios, axis=-1)
    outcome = np.max(np.stack(outcomes, axis=-1), axis=-1).astype(np.int8)
    return outcome, ratio.max(axis=-1), np.argmax(ratio, axis=-1), tuple(reasons)


def _inputs(scene, L, B, move):
    """Outcome and governing index of the ``inputs`` check (plausibility warnings): a position
    (moved with the block by ``move``) more than 10 × the candidate's base diagonal from O, or a
    speed typed in rpm."""
    from foundation_calc.scenes.block import too_far

    size = np.sqrt(L * L + B * B)
    far = np.zeros(L.shape, dtype=bool)
    for position in scene.plausible_lengths().values():
        far |= too_far(move(position), size)
    fast = bool(scene.speed_warnings())
    outcome = np.where(far | fast, WARN, PASS).astype(np.int8)
    governing = np.where(far, 1, np.where(fast, 2, 0))
    reasons = ("no input outside its plausible range", "a position from O more than 10 × the base's diagonal (mm typed as m?)",
               "a machine speed above the plausible range (rpm typed as rad/s?)")
    return outcome, governing, reasons


def evaluate(scene, batch: Batch) -> CandidateVerdicts:
    """Every check of ``fcalc check`` (module docstring) on every candidate of ``batch``
    (:data:`VARIABLE_KEYS` -> (N,) values in SI units).

    Raises
    ------
    ValueError
        for a key not in :data:`VARIABLE_KEYS`, or a varied height or density of a block given by its mass.
    NotImplementedError
        for a soil given with ``modulus_range``: its checks over the range are judged by ``fcalc
        check``'s path (the search then uses it, candidate by candidate).
    """
    if getattr(scene.soil, "modulus_range", None) is not None:
        raise NotImplementedError("the soil's modulus_range is judged by fcalc check's path alone")
    with np.errstate(divide="ignore", invalid="ignore"):  # a block that tips over has p = 0: judged below
        return _evaluate(scene, batch)


def _mover(scene, L, B, H):
    """position [m] -> (N, 3): where it is on each candidate block (:func:`~.apply.moved`); a
    block given by its mass keeps its height, so only its faces move."""
    from foundation_calc.checks.design.apply import moved

    block = scene.block
    old = (block.length, block.width, block.height if block.height is not None else 0.0)
    new = (L, B, H if block.height is not None else 0.0)
    return lambda position: moved(position, old, new)


def _evaluate(scene, batch: Batch) -> CandidateVerdicts:
    from foundation_calc.checks.runup import judged
    from foundation_calc.solvers.block.model import excitation
    from foundation_calc.solvers.block.response import batch_modes, consistent_batch

    L, B, H, rho = _candidates(scene, batch)
    m_b, cog_b, J_b = _block_body(L, B, H, rho, scene)
    move = _mover(scene, L, B, H)
    model = scene.model(base=(L, B), block=(m_b, cog_b, J_b), machine_cogs=[move(m.cog) for m in scene.machines])
    excitations = [excitation(m.name, m.omega_rad_s, [(*row[:4], move(row[4]), row[5]) for row in m.load_rows()])
                   for m in scene.machines]
    points = np.stack([move(p.at) for p in scene.points], axis=-2) if scene.points else []
    impedance = None
    if scene.soil.frequency_dependent:  # each mode at its own frequency, each order at n ω, as check_block
        def impedance(omega):
            return scene.soil_impedance(omega, base=(L, B), block=(m_b, cog_b, J_b),
                                        machine_cogs=[move(m.cog) for m in scene.machines])
    modes = batch_modes(model) if impedance is None else consistent_batch(model, impedance)
    unstable = ~modes.stable
    found = {"inputs": _inputs(scene, L, B, move)}
    outcome, utilisation, governing, reasons = {}, {}, {}, {}
    for check, (o, u, g, r) in (("resonance", _resonance(scene, modes, excitations)),
                                ("amplitudes", _amplitudes(scene, model, modes, excitations, points, impedance))):
        r = r + ("the block tips over or is unrestrained (a squared natural frequency is not positive)",)
        outcome[check] = np.where(unstable, FAIL, o).astype(np.int8)
        utilisation[check] = np.where(unstable, np.inf, u)
        governing[check] = np.where(unstable, len(r) - 1, g)
        reasons[check] = r
    o, g, r = found["inputs"]
    outcome["inputs"], utilisation["inputs"], governing["inputs"], reasons["inputs"] = o, np.full(len(L), np.nan), g, r
    if judged(scene):
        outcome["runup"] = np.full(len(L), PASS, dtype=np.int8)
        utilisation["runup"] = np.full(len(L), np.nan)
        governing["runup"] = np.zeros(len(L), dtype=int)
        reasons["runup"] = ("not evaluated for a batch: " + NOT_EVALUATED["runup"],)
    o, u, g, r = _office(scene, model, L, B, m_b)
    outcome["office"], utilisation["office"], governing["office"], reasons["office"] = o, u, g, r
    order = [c for c in ("inputs", "resonance", "amplitudes", "runup", "office") if c in outcome]  # as fcalc check reports them
    volume = L * B * H if scene.block.height is not None else np.full(len(L), np.nan)
    return CandidateVerdicts(
        volume=volume, mass=np.asarray(m_b, dtype=float),
        outcome={c: outcome[c] for c in order}, utilisation={c: utilisation[c] for c in order},
        governing={c: governing[c] for c in order}, reasons={c: reasons[c] for c in order},
        deferred=tuple(c for c in order if c in NOT_EVALUATED),
    )


__all__ = ["NOT_EVALUATED", "VARIABLE_KEYS", "evaluate"]
