"""Modes and damped steady state of the block under its machines' loads.

Source: :mod:`foundation_calc.solvers.rigid_body` (modes: K v = p² M v; harmonic response:
(K - Ω² M + i Ω C) Z = Q) applied to Eq. (1) of :mod:`.model`, per machine and order, Ω = n ω.
A point P moves by u_P(t) = Σ Re(T_P Z e^{iΩt}).

Several machines at unrelated speeds: their sum is not periodic. Over a long time their phases
take every relative value, so the peak of the sum tends to the **sum of the machines' peaks**
(an upper bound, reached in the limit), each machine's peak being exact over its own period
(:func:`foundation_calc.solvers.numerics.trig_series.peak`). The mean square of the sum is the
sum of the mean squares of all harmonics, so **RMS values add as the root-sum-square of every
harmonic of every machine**: sqrt(Σ |V|²/2).

A soil whose springs and dashpots depend on frequency (Gazetas' impedance,
:mod:`foundation_calc.solvers.soil.impedance`) is given as ``impedance``: a function Ω -> (springs,
dashpots) at O, each (..., 6). Every order n is then solved with K(nω), C(nω) (the equations are
linear: order by order, the base's impedance at that order's frequency), and every mode j at its
own frequency, p_j = p_j(K(p_j)) with p_j(ω) the j-th lowest on the springs at ω
(:func:`consistent_modes`).
"""

from __future__ import annotations

from dataclasses import dataclass, replace

import numpy as np

from foundation_calc.errors import PhysicsError
from foundation_calc.solvers.block.model import BlockModel, Excitation
from foundation_calc.solvers.rigid_body.harmonic import harmonic_response
from foundation_calc.solvers.rigid_body.kinematics import point_maps
from foundation_calc.solvers.rigid_body.modes import MOTIONS, dominant_motions, eigen

#: Relative distance |nω - p|/p within which an undamped mode has no steady state [-].
RESONANT_MARGIN = 1e-6


@dataclass(frozen=True)
class BlockModes:
    """Undamped modes: frequencies p [rad/s] ascending, mass-normalised shapes (6, 6) as columns,
    the dominant motion of each (:data:`~foundation_calc.solvers.rigid_body.modes.MOTIONS`), and
    the modal damping ratios ζ = φᵀ C φ / (2 p) [-]. On a frequency-dependent soil each mode is
    taken at its own frequency (:func:`consistent_modes`) and ``static`` holds the frequencies on
    the static springs [rad/s] (None otherwise)."""

    frequencies: np.ndarray
    shapes: np.ndarray
    dominant: tuple[str, ...]
    damping: np.ndarray
    static: np.ndarray | None = None


@dataclass(frozen=True)
class ModeBatch:
    """The modes of a batch of blocks (a stack of :class:`~foundation_calc.solvers.block.model.BlockModel`
    matrices): frequencies (..., 6) [rad/s] (0 where unstable), shapes (..., 6, 6), the dominant
    motion as an index into :data:`~foundation_calc.solvers.rigid_body.modes.MOTIONS` (..., 6),
    damping ratios (..., 6) [-], the squared frequencies p² (..., 6) [rad²/s²] as solved, and
    ``stable`` (...): every squared frequency positive (on a frequency-dependent soil,
    :func:`consistent_batch`, on the static springs: a block that tips over, as ``fcalc check``
    judges it, :func:`consistent_modes`; a spring that turns negative at another mode's frequency,
    as a pile group's can, is no tipping); ``static_frequencies`` (..., 6) [rad/s]: on a
    frequency-dependent soil each mode's on the static springs; ``rootless`` (...): on a
    frequency-dependent soil, a block with a mode whose ω = p(K(ω)) has no root
    (:func:`consistent_batch` with ``rootless="nan"``; its modes are then the static springs' as a
    stand-in, its verdicts for the caller to fail), else None."""

    frequencies: np.ndarray
    shapes: np.ndarray
    dominant: np.ndarray
    damping: np.ndarray
    squared: np.ndarray
    stable: np.ndarray
    static_frequencies: np.ndarray | None = None
    rootless: np.ndarray | None = None


def batch_modes(model: BlockModel) -> ModeBatch:
    """The six modes of Eq. (1) of :mod:`.model` without damping, for one block or a stack; a
    block whose lowest squared frequency is not positive (to 1e-12 of the highest) is unstable."""
    p2, shapes = eigen(model.K, model.M, model.size)
    dominant = dominant_motions(shapes, model.mass, model.cog, np.diagonal(model.J_G, 0, -2, -1))
    stable = p2[..., 0] > 1e-12 * p2[..., -1]
    p = np.sqrt(np.maximum(p2, 0.0))
    dissipative = (model.C + np.swapaxes(model.C, -1, -2)) / 2.0  # φᵀ C φ of C's symmetric part: a gyroscopic D̄ adds none
    modal_c = np.sum(shapes * (dissipative @ shapes), axis=-2)
    return ModeBatch(p, shapes, dominant, modal_c / (2.0 * np.where(p > 0.0, p, np.inf)), p2, stable)


def block_modes(model: BlockModel) -> BlockModes:
    """The six modes of Eq. (1) of :mod:`.model` without damping (:func:`batch_modes` of one block).

    Raises
    ------
    PhysicsError
        when a squared frequency is not positive: a direction without a spring, or a block that
        tips over (its weight's moment W z_G above the rocking spring).
    """
    batch = batch_modes(model)
    dominant = tuple(MOTIONS[int(i)] for i in batch.dominant)
    if not batch.stable:
        raise PhysicsError(
            f"the block is unstable or unrestrained in {dominant[0]}: squared natural frequency {float(batch.squared[0]):.4g} rad²/s²"
            f" (the weight's overturning moment W z_G = {model.mass * 9.81 * model.cog[2]:.4g} N m per rad is"
            " at or above the rocking spring, or a spring is missing)",
            field="soil",
            hint="stiffen the rocking springs or lower the centre of mass",
        )
    return BlockModes(batch.frequencies, batch.shapes, dominant, batch.damping)


def _widened(model: BlockModel, n: int) -> BlockModel:
    """``model`` with ``n`` axes of length 1 after its batch's (before each array's own axes), so
    that it broadcasts against arrays with ``n`` more axes (several frequencies per block)."""
    def wide(a, own):
        a = np.asarray(a)
        return np.expand_dims(a, tuple(range(a.ndim - own, a.ndim - own + n)))

    return replace(model, M=wide(model.M, 2), K=wide(model.K, 2), C=wide(model.C, 2), mass=wide(model.mass, 0),
                   cog=wide(model.cog, 1), J_G=wide(model.J_G, 2), size=wide(model.size, 0), springs=wide(model.springs, 1),
                   coupling=None if model.coupling is None else wide(model.coupling, 2))


def consistent_batch(model: BlockModel, impedance, rootless: str = "raise") -> ModeBatch:
    """The six modes of Eq. (1) of :mod:`.model` on the soil ``impedance`` (module docstring), each
    at its own frequency, of one block or of a batch: the j-th lowest frequency p_j solves
    p = p_j(K(p)), p_j(ω) the j-th lowest on the springs at ω
    (:func:`~foundation_calc.solvers.soil.impedance.consistent_frequency`: the springs fall with
    frequency, so p_j(ω) does too and the root is one and bracketed; the six roots are every root
    of det(K(ω) - ω² M) = 0). A mode that softens more than another (rocking) passes it by rank
    at its own frequency, where it is found. Its shape, dominant motion and damping ratio are those
    of the springs and dashpots at p_j; ``static_frequencies`` gives each mode's frequency on the
    static springs, of the static mode of the nearest shape (:func:`nearest_shapes`).
    ``impedance(ω)`` takes ω shaped as the batch with one or two more axes (..., m[, k]): the six
    modes' roots are sought together (m = 6; k trial frequencies each in the scan of
    :func:`~foundation_calc.solvers.soil.impedance.consistent_frequency`), element by element, each
    as if alone; a batch of more than :data:`~foundation_calc.solvers.soil.impedance.AT_ONCE` / 6
    blocks one mode at a time (m = 1), so that the soil's arrays stay the batch's size.
    ``rootless``: ``"raise"``, a mode without a root raises the PhysicsError; ``"nan"`` (a batch of
    candidates), such a block keeps its static modes as a stand-in, marked in ``rootless``."""
    from foundation_calc.solvers.soil.impedance import AT_ONCE, consistent_frequency

    static = batch_modes(model)  # a block that tips over keeps p = 0, its fixed point
    together = np.size(model.mass) * 6 <= AT_ONCE
    roots = np.zeros_like(static.frequencies)
    for js in ([list(range(6))] if together else [[j] for j in range(6)]):
        def frequencies(omega, js=js):
            """Mode js[i]'s frequency on the springs at ω_i: ``omega`` (..., len(js)), or (..., len(js), k)
            with k trial frequencies each."""
            more = omega.ndim - static.frequencies.ndim + 1  # the axes past the batch's: 1 or 2
            wide = _widened(model, more)
            K, C = wide.soil_matrices(*impedance(omega))
            p = batch_modes(replace(wide, K=K, C=C)).frequencies[..., js]  # (..., ω_i, [k,] js)
            return np.moveaxis(np.diagonal(p, 0, -1 - more, -1), -1, -more)

        roots[..., js] = consistent_frequency(frequencies, static.frequencies[..., js], trials=True,
                                              mode=f"mode {js[0] + 1}" if len(js) == 1 else "", rootless=rootless)
    lost = np.isnan(roots).any(axis=-1)
    roots = np.where(lost[..., None], static.frequencies, roots)

    def alone(omega):
        K, C = model.soil_matrices(*impedance(omega))
        return batch_modes(replace(model, K=K, C=C))

    found = [alone(roots[..., j]) for j in range(6)]
    p, dominant, damping, squared = (np.stack([getattr(m, a)[..., j] for j, m in enumerate(found)], -1)
                                     for a in ("frequencies", "dominant", "damping", "squared"))
    shapes = np.stack([m.shapes[..., :, j] for j, m in enumerate(found)], -1)
    order = np.argsort(p, axis=-1)  # ascending by the proof; round-off may swap equal roots
    sort = lambda a: np.take_along_axis(a, order, -1)  # noqa: E731
    shapes = np.take_along_axis(shapes, order[..., None, :], -1)
    pairs = nearest_shapes(static.shapes, shapes, model.M)
    return ModeBatch(sort(p), shapes, sort(dominant), sort(damping), sort(squared), static.stable,
                     np.take_along_axis(static.frequencies, pairs, -1), lost if rootless == "nan" else None)


def nearest_shapes(before: np.ndarray, after: np.ndarray, M: np.ndarray) -> np.ndarray:
    """For each mode of ``after`` (shapes as columns, (..., 6, 6)), the index of the mode of
    ``before`` of the nearest shape, each used once (..., 6): the pairs of the largest
    |φ_bᵀ M φ_a| taken greedily, largest first (the mass-normalised shapes' modal assurance)."""
    near = np.abs(np.einsum("...ib,...ij,...ja->...ba", before, M, after))  # (..., before, after)
    pairs = np.zeros(near.shape[:-2] + (near.shape[-1],), dtype=int)
    for _ in range(near.shape[-1]):
        flat = np.argmax(near.reshape(near.shape[:-2] + (-1,)), axis=-1)
        b, a = np.divmod(flat, near.shape[-1])
        np.put_along_axis(pairs, a[..., None], b[..., None], -1)
        np.put_along_axis(near, b[..., None, None], -1.0, -2)  # b is taken: its row out
        np.put_along_axis(near, a[..., None, None], -1.0, -1)  # a is paired: its column out
    return pairs


def consistent_modes(model: BlockModel, impedance) -> BlockModes:
    """:func:`consistent_batch` of one block, as :func:`block_modes` gives its modes (``static``:
    the static frequency of each mode)."""
    block_modes(model)  # a block that tips over on the static springs: the same error
    batch = consistent_batch(model, impedance)
    return BlockModes(batch.frequencies, batch.shapes, tuple(MOTIONS[int(i)] for i in batch.dominant), batch.damping,
                      batch.static_frequencies)


@dataclass(frozen=True)
class Resonances:
    """Every order of one machine against every mode.

    Attributes
    ----------
    orders : (H,) orders n
    critical : (H, 6) speeds n ω = p_j [rad/s], i.e. p_j / n
    margin : (H, 6) |n ω - p_j| / p_j [-]
    share : (H, 6) forcing share |φ_jᵀ Q_n| / p_j of order n on mode j, over its largest value
        for the machine [-] (the resonance rule's measure of what a harmonic drives)

    For a batch of blocks (:class:`ModeBatch`) critical, margin and share are stacks (..., H, 6).
    """

    orders: np.ndarray
    critical: np.ndarray
    margin: np.ndarray
    share: np.ndarray


def resonances(modes: BlockModes, exc: Excitation, omega=None) -> Resonances:
    """Margins of the machine's orders from every mode at its speed (or at ``omega`` [rad/s]), of
    one block or of a batch (:class:`ModeBatch`)."""
    omega = exc.omega if omega is None else omega
    p = modes.frequencies[..., None, :]
    n = exc.orders[:, None].astype(float)
    static = np.hypot(exc.Q.real @ modes.shapes, exc.Q.imag @ modes.shapes) / p  # (..., H, 6): |φ_jᵀ Q_n| / p_j
    share = static / static.max(axis=(-2, -1), keepdims=True)
    return Resonances(exc.orders, p / n, np.abs(n * omega - p) / p, share)


def resonant(modes: BlockModes, res: Resonances) -> np.ndarray:
    """True when an order sits within :data:`RESONANT_MARGIN` of an undamped mode (no steady
    state); one bool per block of a batch."""
    return np.any((res.margin < RESONANT_MARGIN) & (modes.damping[..., None, :] <= 0.0), axis=(-2, -1))


def complex_amplitudes(model: BlockModel, exc: Excitation, omega=None, impedance=None) -> np.ndarray:
    """Z of (K - (nω)² M + i nω C) Z = Q_n for every order, shape (..., H, 6) [m, rad], at the
    machine's speed or at the speeds ``omega`` (any shape) [rad/s] (an unbalance's load grows as
    ω², :meth:`~foundation_calc.solvers.block.model.Excitation.loads_at`); at the machine's speed
    the block may be a batch (stacks (..., 6, 6) give (..., H, 6)); on the soil ``impedance``
    (module docstring) each order with K(nω), C(nω). C holds the machines' mean gyroscopic
    coupling at their speeds (:class:`~foundation_calc.solvers.block.model.BlockModel`); at the
    speeds ``omega`` this machine's grows with them
    (:meth:`~foundation_calc.solvers.block.model.Excitation.damping_change`)."""
    if impedance is not None:
        speeds = np.asarray(exc.omega if omega is None else omega, dtype=float)
        Omega = np.broadcast_to(speeds[..., None] * exc.orders, np.shape(model.K)[:-2] + speeds.shape + exc.orders.shape)
        K, C = model.soil_matrices(*impedance(Omega))
        batch = np.ndim(model.M) - 2
        M = np.expand_dims(model.M, tuple(range(batch, Omega.ndim)))
        if omega is None:
            return harmonic_response(K, C, M, exc.Q, Omega)
        return harmonic_response(K, C + _per_order(exc.damping_change(speeds)), M, exc.loads_at(speeds), Omega)
    if omega is None:
        K, C, M = (np.asarray(A)[..., None, :, :] for A in (model.K, model.C, model.M))
        return harmonic_response(K, C, M, exc.Q, exc.omega * exc.orders)
    omega = np.asarray(omega, dtype=float)
    C = model.C + _per_order(exc.damping_change(omega))
    return harmonic_response(model.K, C, model.M, exc.loads_at(omega), omega[..., None] * exc.orders)


def _per_order(change):
    """A change of C at each speed, speeds + (6, 6), with an axis for the orders: speeds + (1, 6, 6)."""
    return np.expand_dims(change, -3) if np.ndim(change) else change


@dataclass(frozen=True)
class PointMotion:
    """Steady motion of named points, per machine and order, and its combination.

    Attributes
    ----------
    names : point names, ``"G"`` (the centre of mass) first
    machines : machine names
    orders : per machine, its orders (H_m,)
    omegas : per machine, its speed [rad/s]
    displacement : per machine, complex amplitudes (P, 3, H_m) [m] along x, y, z: u(t) = Re(Z e^{i n ω t})
    rotation : per machine, complex rotation amplitudes (3, H_m) [rad] about x, y, z
    peak : (P, 3) peak displacement over time, machines' peaks added [m]
    velocity_peak : (P, 3) [m/s], likewise
    velocity_rms : (P, 3) root-sum-square of every harmonic's RMS velocity [m/s]
    displacement_rms : (P, 3) [m]
    rotation_peak : (3,) [rad]
    acceleration_peak : (P, 3) peak acceleration, machines' peaks added [m/s²]; order n of Z
        accelerates by -(nω)² Z
    acceleration_rms : (P, 3) root-sum-square of every harmonic's RMS acceleration [m/s²]

    A batch of blocks puts its axis (...) in front of every array; a peak not asked for is None.
    """

    names: tuple[str, ...]
    machines: tuple[str, ...]
    orders: tuple[np.ndarray, ...]
    omegas: tuple[float, ...]
    displacement: tuple[np.ndarray, ...]
    rotation: tuple[np.ndarray, ...]
    peak: np.ndarray | None
    velocity_peak: np.ndarray | None
    velocity_rms: np.ndarray
    displacement_rms: np.ndarray
    rotation_peak: np.ndarray | None
    acceleration_peak: np.ndarray | None
    acceleration_rms: np.ndarray


def velocity(U: np.ndarray, exc: Excitation) -> np.ndarray:
    """Complex velocity amplitudes i n ω U of displacement amplitudes U (..., H) of machine ``exc``'s orders."""
    return U * (1j * exc.omega * exc.orders)


def acceleration(U: np.ndarray, exc: Excitation) -> np.ndarray:
    """Complex acceleration amplitudes (i n ω)² U = -(n ω)² U of displacement amplitudes U (..., H)."""
    return velocity(velocity(U, exc), exc)


def series_peak(Z: np.ndarray, orders: np.ndarray) -> np.ndarray:
    """Peak over one period of Σ_n Re(Z_n e^{inφ}) for each row of Z (..., H); |Z_n| for one order."""
    from foundation_calc.solvers.numerics.trig_series import peak

    if len(orders) == 1:
        return np.abs(Z[..., 0])
    K = int(orders.max())
    a = np.zeros(Z.shape[:-1] + (K + 1,), dtype=complex)
    a[..., orders] = Z
    return peak(a.real, -a.imag)


#: Phases per period at which :func:`largest_peak` samples a series for its bounds.
BOUND_SAMPLES = 8


def largest_peak(parts) -> tuple[np.ndarray, np.ndarray]:
    """The largest over the rows r of Σ_m peak_m(r), and its row (the first where several tie):
    the peak of a point's motion along one direction when several machines' peaks add (module
    docstring), for a batch of blocks without searching every row's peak.

    ``parts``: per machine, (Z, orders) with Z (N, R, H_m) complex amplitudes of its orders
    (H_m,). A single order's peak is |Z|. Several orders are sampled at :data:`BOUND_SAMPLES`
    phases of spacing Δφ: the largest sample s is a lower bound of the peak, and the peak is at
    most s + Σ n²|Z_n| Δφ²/8 (within Δφ/2 of a sample |q| falls by at most max|q''| Δφ²/8) and at
    most Σ|Z_n|. Only the rows whose upper bound reaches the largest lower bound of their block
    can hold the largest peak; their peaks are searched exactly (:func:`series_peak`, as the
    single block's), so the result is the single block's to round-off.

    Returns (N,) the largest peak and (N,) its row index.
    """
    lower = upper = 0.0
    step = 2.0 * np.pi / BOUND_SAMPLES
    for Z, orders in parts:
        size = np.abs(Z)
        if len(orders) == 1:
            lower, upper = lower + size[..., 0], upper + size[..., 0]
            continue
        re, im = np.moveaxis(Z.real, -1, 0).copy(), np.moveaxis(Z.imag, -1, 0).copy()  # (H, N, R) each
        sampled = np.zeros(size.shape[:-1])
        for k in range(BOUND_SAMPLES):  # |Re(Σ Z_n e^{inφ})| at φ = k Δφ, one phase at a time (memory of one row set)
            phase = orders * k * step
            q = sum(re[h] * np.cos(phase[h]) - im[h] * np.sin(phase[h]) for h in range(len(orders)))
            np.maximum(sampled, np.abs(q), out=sampled)
        bend = (size * orders.astype(float) ** 2).sum(-1) * step * step / 8.0
        lower, upper = lower + sampled, upper + np.minimum(size.sum(-1), sampled + bend)
    # rows in block order; every block keeps at least the row of its largest lower bound
    block, row = np.nonzero(upper >= lower.max(axis=-1, keepdims=True))
    exact = sum(series_peak(Z[block, row], orders) for Z, orders in parts)
    starts = np.flatnonzero(np.diff(block, prepend=-1))
    largest = np.maximum.reduceat(exact, starts)
    top = np.flatnonzero(exact == np.repeat(largest, np.diff(starts, append=len(block))))
    first = top[np.unique(block[top], return_index=True)[1]]
    return largest, row[first]


#: The peaks over time :func:`point_motion` can search (the RMS values cost nothing and are always given).
PEAKS = frozenset({"peak", "velocity_peak", "acceleration_peak", "rotation_peak"})


def point_motion(model: BlockModel, excitations, names, points, peaks=PEAKS, impedance=None, given=None) -> PointMotion:
    """Steady motion of G and of ``points`` (P, 3) [m] from O under every machine (module
    docstring: peaks add, RMS values add as root-sum-square), of one block or of a batch (stacks
    in ``model``, and points (..., P, 3) where they move with the block); ``peaks``: the peaks of
    :data:`PEAKS` to search (the others are None); on the soil ``impedance`` if given.
    ``given``: per machine, in ``excitations``' order, None for its first approximation
    (:func:`complex_amplitudes`) or its own harmonics (Z (..., H, 6) [m, rad], orders (H,)) at its
    speed, e.g. the exact periodic solution of its periodic inertia
    (:func:`~foundation_calc.solvers.block.periodic_inertia.exact_response`)."""
    cog = np.asarray(model.cog)
    fixed = np.asarray(points, dtype=float)
    fixed = fixed if fixed.ndim >= 2 else fixed.reshape(-1, 3)  # (P, 3), or (..., P, 3) for a batch
    batch = np.broadcast_shapes(cog.shape[:-1], fixed.shape[:-2])
    at = np.concatenate([np.broadcast_to(cog[..., None, :], batch + (1, 3)), np.broadcast_to(fixed, batch + fixed.shape[-2:])],
                        axis=-2)
    T = point_maps(at)  # (..., P, 3, 6)
    disp, rot = [], []
    vsq = usq = asq = np.zeros(at.shape)
    found = {name: 0.0 for name in peaks}
    given = (None,) * len(excitations) if given is None else given
    excitations = [exc if own is None else replace(exc, orders=np.asarray(own[1]), Q=None, Q_inertial=None, Q_weight=None)
                   for exc, own in zip(excitations, given)]  # a machine's given harmonics: its orders, no loads
    for exc, own in zip(excitations, given):
        Z = complex_amplitudes(model, exc, impedance=impedance) if own is None else np.asarray(own[0])  # (..., H, 6)
        U = np.einsum("...pij,...hj->...pih", T, Z)  # (..., P, 3, H)
        V, A = velocity(U, exc), acceleration(U, exc)
        R = np.swapaxes(Z[..., 3:], -1, -2)  # (..., 3, H)
        disp.append(U)
        rot.append(R)
        for name, series in (("peak", U), ("velocity_peak", V), ("acceleration_peak", A), ("rotation_peak", R)):
            if name in found:
                found[name] = found[name] + series_peak(series, exc.orders)
        vsq = vsq + (np.abs(V) ** 2).sum(-1) / 2.0
        usq = usq + (np.abs(U) ** 2).sum(-1) / 2.0
        asq = asq + (np.abs(A) ** 2).sum(-1) / 2.0
    return PointMotion(
        tuple(["G", *names]), tuple(e.name for e in excitations), tuple(e.orders for e in excitations),
        tuple(e.omega for e in excitations), tuple(disp), tuple(rot), found.get("peak"), found.get("velocity_peak"),
        np.sqrt(vsq), np.sqrt(usq), found.get("rotation_peak"), found.get("acceleration_peak"), np.sqrt(asq),
    )


__all__ = [
    "BlockModes",
    "ModeBatch",
    "PEAKS",
    "PointMotion",
    "Resonances",
    "acceleration",
    "batch_modes",
    "block_modes",
    "largest_peak",
    "complex_amplitudes",
    "nearest_shapes",
    "consistent_batch",
    "consistent_modes",
    "point_motion",
    "resonances",
    "resonant",
    "series_peak",
    "velocity",
]
