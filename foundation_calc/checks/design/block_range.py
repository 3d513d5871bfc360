"""The block's engine of the one modulus-range checker (:mod:`.modulus_range`): the soil's modulus
range (``[soil] modulus_range``) over a batch of candidate blocks: the resonance and amplitude checks at the stiffness factors where ``fcalc check`` evaluates them
(:mod:`~foundation_calc.checks.soil_range`): the resonances at the factors of its grid, the
amplitudes at those of its coarser grid, and both at every factor where a critical speed
p_j / n crosses a machine's speed and the resonance rule judges that condition there.

The crossings in closed form: every soil method's springs are proportional to the factor f
(:meth:`~foundation_calc.scenes.block_soil.BlockSoil.factored` scales G or V_s², E, the
coefficients or the given stiffness) and its dashpots to sqrt(f) (a damping ratio ξ that does not
depend on the modulus, C = 2 ξ sqrt(K m); given dashpots by sqrt(f)), so that

    K(f) = f K_s + K_W,   C(f) = sqrt(f) C(1)                                                (1)

with K_s the springs at f = 1 and K_W the weight's tilt. On a frequency-dependent soil (Gazetas,
Pais & Kausel) the springs are G times a function of a0 = ω B / V_s with V_s = sqrt(G / ρ), and the
dashpots ρ V_s times one (or 2 ξ sqrt(K m) with ξ a function of a0), so that at every frequency

    K(f, ω) = f K(1, ω / sqrt(f)),   C(f, ω) = sqrt(f) C(1, ω / sqrt(f))                     (2)

of which (1) is the frequency-independent case (checked against the factored scene for every
method: tests/test_soil_range_kinds.py). Mode j's frequency equals Ω = n ω where
det(f K_s + K_W - Ω² M) = 0: f is an eigenvalue of the symmetric K_s^(-1/2) (Ω² M - K_W) K_s^(-1/2)
(one batched ``eigvalsh`` per machine and order), which ``fcalc check`` finds instead by Brent's
method between grid factors (to 1e-10).
"""

from __future__ import annotations

from dataclasses import replace

import numpy as np


def scaled(model, factor):
    """The block of ``model`` (the soil as given) on the soil scaled by ``factor`` (N,), Eq. (1)."""
    from foundation_calc.solvers.rigid_body.inertia import diagonal_matrices

    f = np.asarray(factor, dtype=float)
    K_s = diagonal_matrices(model.springs)
    return replace(model, K=f[:, None, None] * K_s + (model.K - K_s), C=np.sqrt(f)[:, None, None] * model.C,
                   springs=f[:, None] * model.springs)


def scaled_impedance(impedance, factor):
    """The soil ``impedance`` (ω -> (springs, dashpots), each ω.shape + (6,)) scaled by ``factor``
    (N,), Eq. (2): ω's leading axis is the factors'."""
    f = np.asarray(factor, dtype=float)

    def at(omega):
        omega = np.asarray(omega, dtype=float)
        g = f.reshape(f.shape + (1,) * (omega.ndim - f.ndim))
        springs, dashpots = impedance(omega / np.sqrt(g))
        return g[..., None] * springs, np.sqrt(g)[..., None] * dashpots

    return at


def on_factors(model, factor):
    """One block's ``model`` (the soil as given) on the soil scaled by each ``factor`` (N,): a batch
    of N blocks, Eq. (1)."""
    n = len(factor)
    batch = replace(model, M=np.broadcast_to(model.M, (n, 6, 6)), K=np.broadcast_to(model.K, (n, 6, 6)),
                    C=np.broadcast_to(model.C, (n, 6, 6)), mass=np.full(n, model.mass), cog=np.broadcast_to(model.cog, (n, 3)),
                    J_G=np.broadcast_to(model.J_G, (n, 3, 3)), size=np.full(n, model.size),
                    springs=np.broadcast_to(model.springs, (n, 6)))
    return scaled(batch, factor)


def crossings(scene, model, excitations, low, high):
    """Yield (factor (N,), valid (N,), scaled model): for every machine, order and root of Eq. (1),
    the factor where a critical speed crosses the machine's speed, valid where it lies within
    (low, high), the block is stable there and the rule judges the condition (1 elsewhere)."""
    from foundation_calc.checks.resonance.rule import judge, required_detuning
    from foundation_calc.solvers.block.response import batch_modes, resonances
    from foundation_calc.solvers.rigid_body.inertia import diagonal_matrices

    rows = np.arange(len(model.M))
    root = 1.0 / np.sqrt(np.broadcast_to(model.springs, model.K.shape[:-1]))
    weight = model.K - diagonal_matrices(model.springs)
    for exc in excitations:
        for h, n in enumerate(exc.orders):
            Omega = n * exc.omega
            factors = np.linalg.eigvalsh((Omega**2 * model.M - weight) * root[:, :, None] * root[:, None, :])
            for k in range(factors.shape[-1]):
                inside = (factors[:, k] > low) & (factors[:, k] < high)
                if not inside.any():
                    continue
                f = np.where(inside, factors[:, k], 1.0)
                at = scaled(model, f)
                modes = batch_modes(at)
                res = resonances(modes, exc)
                j = np.argmin(res.margin[:, h, :], axis=-1)
                verdict = judge(res.margin[rows, h, j][:, None], [n], res.share[rows, h, j][:, None],
                                required_detuning(scene.limits.detuning, [n]), [False])
                yield f, inside & modes.stable & verdict.judged[:, 0], at


def judged(scene, dimensions, built, dynamics):
    """The block's engine of :func:`~foundation_calc.checks.design.modulus_range.over_range` for the
    candidates ``dimensions`` (L, B, H (N,) each [m]): a generator of the elements (candidate, factor)
    it judges, first at the crossings of Eq. (1) (module docstring: in closed form, where the crank's
    engine bisects), then factor by factor of the grids on the factored scene, as ``fcalc check``
    builds it; a candidate that already fails a check is not judged again for it (``open``).
    ``built(scene, L, B, H)`` (the candidates on a scene's soil) and ``dynamics(scene, built, checks)``
    are the evaluator's (:mod:`~foundation_calc.checks.design.block`). On a frequency-dependent
    support Eq. (1) does not hold: there the crossings are not added
    (:data:`~foundation_calc.checks.design.block.NOT_EVALUATED`)."""
    low, high = scene.soil.modulus_range
    checks = ("resonance", "amplitudes")

    def judged_at(on, candidates, active, checks):
        for check, (outcome, utilisation, governing, reasons) in dynamics(on, candidates, checks).items():
            yield check, active, outcome, utilisation, governing, reasons

    def elements(grids, open):
        active = open(checks)
        if not scene.support().frequency_dependent and len(active):  # first where the range is most likely to fail
            candidates = built(scene, *(d[active] for d in dimensions))
            for _, valid, at in crossings(scene, candidates.model, candidates.excitations, low, high):
                for check, who, *verdicts, reasons in judged_at(scene, replace(candidates, model=at), active, checks):
                    yield (check, who[valid], *(v[valid] for v in verdicts), reasons)
        grid = {check: set(factors) for check, factors in grids.items()}
        for factor in sorted(grid["resonance"] | grid["amplitudes"]):
            at_factor = tuple(check for check in checks if factor in grid[check])
            active = open(at_factor)
            if len(active):
                on = scene.with_modulus_factor(factor)
                yield from judged_at(on, built(on, *(d[active] for d in dimensions)), active, at_factor)

    return elements


__all__ = ["crossings", "judged", "on_factors", "scaled", "scaled_impedance"]
