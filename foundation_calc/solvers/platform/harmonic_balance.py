"""Steady state of the platform by harmonic balance over the combination frequencies of its rotors.

The linearised equations M(t) q'' + G(t) q' + K(t) q = F(t) of
:mod:`~foundation_calc.solvers.platform.dynamics` have coefficients that are trigonometric
polynomials in the rotor angles (harmonic vectors k = 0, ±e_j, ±2e_j). Their steady state is
q = q_s + Σ_n Q_n exp(i n·ω t) over integer harmonic vectors n, with q_s the static equilibrium
K_springs q_s = weight. Balancing harmonic m gives one block row of a sparse linear system::

    D(Ω_m) Q_m + Σ_{k≠0} A_k(Ω_{m-k}) Q_{m-k} = F_m - K_m q_s,        Ω_n = n·ω,        (HB)
    D(Ω) = K_0 + i (η sgn Ω + β Ω) K_springs + iΩ G_0 - Ω² M_0,
    A_k(Ω) = K_k + iΩ G_k - Ω² M_k.

Truncation. The retained harmonics grow from the forced ones: after each solve, the residual r_m
that the solution leaves on a neighbouring harmonic m gives the estimate D(Ω_m)⁻¹ r_m of Q_m;
every harmonic whose estimate exceeds :data:`TRUNCATION_TOL` times the largest response is
added and the system solved again, until none is. The order K is the largest |n|₁ retained; the
estimates left out, summed as peaks, are the reported truncation error. Harmonics next to a
resonance are large and therefore retained: the direct solve answers where a Neumann series in
the periodic terms diverges (a lightly damped combination resonance).

Solution. Up to :data:`DENSE_UNKNOWNS` unknowns the system is factorised densely; larger ones
(many rotors) are solved by GMRES preconditioned with the exact inverses of the diagonal blocks
D(Ω_m), which capture the resonant harmonics, starting from the previous solution.
"""

from __future__ import annotations

import copy
from dataclasses import dataclass

import numpy as np

from foundation_calc.errors import ConvergenceError, PhysicsError
from foundation_calc.solvers.platform.dynamics import PeriodicSystem, natural_frequencies, periodic_system, stack

#: A harmonic is retained when its estimated size exceeds this fraction of the largest one [-].
TRUNCATION_TOL = 1e-12

#: At most this many harmonic vectors are retained; beyond it the error estimate says what is lost.
MAX_HARMONICS = 6000

#: Systems with at most this many unknowns (6 per harmonic) are solved by dense LU.
DENSE_UNKNOWNS = 720

#: Frequencies closer than this fraction of the largest rotor speed are one frequency [-].
FREQUENCY_TOL = 1e-9

#: Relative residual at which GMRES stops [-]: the truncation tolerance, below which no harmonic counts.
GMRES_TOL = TRUNCATION_TOL

#: Tolerance variants drop nominal harmonics whose peaks sum to less than this fraction of the largest [-].
VARIANT_TOL = 1e-6

#: Layers of neighbouring frequencies added to a small basis of the tolerance variants, and the
#: size up to which they are added [-]: a variant rocks where a purely translating nominal does
#: not, and its rocking couples the forced harmonics to their neighbours (2ω ... 5ω of a single
#: rotor), which the nominal never needed. A larger basis came from a nominal that rocks already.
VARIANT_LAYERS = 2
VARIANT_SMALL_SET = 13

#: Relative residual at which a tolerance variant's solve stops [-] (well below VARIANT_TOL).
VARIANT_GMRES_TOL = 1e-9

#: Iterative refinement of a variant: at most this many steps, each shrinking the residual by this factor.
REFINEMENT_STEPS = 20
REFINEMENT_CONTRACTION = 0.5

#: An undamped diagonal block whose reciprocal condition number is below this is an exact resonance.
SINGULAR_RCOND = 1e-13


def combination_label(n) -> str:
    """A harmonic vector of the rotor speeds as text: (2, -1) -> "2ω1 − ω2", (1,) -> "ω".

    >>> combination_label((2, -1)), combination_label((1,)), combination_label((0, 3))
    ('2ω1 − ω2', 'ω', '3ω2')
    """
    names = ["ω"] if len(n) == 1 else [f"ω{j + 1}" for j in range(len(n))]
    text = ""
    for k, name in zip(n, names):
        if k == 0:
            continue
        sign = ("−" if k < 0 else "+") if text else ("−" if k < 0 else "")
        term = f"{abs(k) if abs(k) != 1 else ''}{name}"
        text += f" {sign} {term}" if text else f"{sign}{term}"
    return text or "0"


class HarmonicSet:
    """Distinct frequencies Ω = n·ω of harmonic vectors n, with an exact lookup by frequency.

    Harmonic vectors of equal frequency (rotors at equal speeds: ω1 and ω2 = ω1 give e1 and e2)
    are one unknown of (HB): its equations only see time. Each frequency keeps the vector of lowest
    order |n|₁ that reached it, for the truncation order and for naming a resonance.
    """

    def __init__(self, vectors, omega, tolerance: float) -> None:
        order = np.argsort(omega, kind="stable")
        self.vectors = np.asarray(vectors, dtype=int)[order]
        self.omega = np.asarray(omega, dtype=float)[order]
        self.tolerance = tolerance

    def __len__(self) -> int:
        return len(self.omega)

    def find(self, omega) -> np.ndarray:
        """Row number of each frequency in the set (within the tolerance), -1 where absent."""
        omega = np.asarray(omega, dtype=float)
        last = len(self.omega) - 1
        if last < 0:
            return np.full(omega.shape, -1)
        pos = np.searchsorted(self.omega, omega)
        lo, hi = np.maximum(pos - 1, 0), np.minimum(pos, last)  # (np.clip costs more on small sets)
        nearest = np.where(np.abs(self.omega[lo] - omega) <= np.abs(self.omega[hi] - omega), lo, hi)
        return np.where(np.abs(self.omega[nearest] - omega) <= self.tolerance, nearest, -1)

    def neighbours(self, keys, speeds) -> "HarmonicSet":
        """The frequencies n·ω + k·ω (n in the set, k in ``keys``) not yet in the set."""
        near = (self.vectors[:, None, :] + np.asarray(keys)[None, :, :]).reshape(-1, self.vectors.shape[1])
        found = distinct(near, near @ speeds, self.tolerance)
        return found.subset(self.find(found.omega) < 0)

    def subset(self, rows) -> "HarmonicSet":
        return HarmonicSet(self.vectors[rows], self.omega[rows], self.tolerance)

    def union(self, more: "HarmonicSet", Q, more_Q):
        """This set and the disjoint set ``more``, with their amplitudes (rows) merged alike."""
        joined = HarmonicSet(np.vstack([self.vectors, more.vectors]), np.concatenate([self.omega, more.omega]), self.tolerance)
        order = np.argsort(np.concatenate([self.omega, more.omega]), kind="stable")
        return joined, np.vstack([Q, more_Q])[order]


def distinct(vectors, omega, tolerance: float) -> HarmonicSet:
    """One row per distinct frequency (gaps above ``tolerance`` separate them), keeping the vector
    of lowest order |n|₁ of each."""
    vectors, omega = np.asarray(vectors, dtype=int), np.asarray(omega, dtype=float)
    if len(omega) == 0:
        return HarmonicSet(vectors, omega, tolerance)
    by_omega = np.argsort(omega, kind="stable")
    cluster = np.empty(len(omega), dtype=int)
    cluster[by_omega] = np.cumsum(np.concatenate([[1], np.diff(omega[by_omega]) > tolerance])) - 1
    order = np.lexsort((np.abs(vectors).sum(axis=1), cluster))
    first = order[np.concatenate([[True], np.diff(cluster[order]) > 0])]
    return HarmonicSet(vectors[first], omega[first], tolerance)


@dataclass(frozen=True)
class SteadyState:
    """Steady response q(t) = static + Σ Q(Ω) e^{iΩt} over the retained frequencies (Ω and -Ω both
    present; q real).

    Attributes
    ----------
    static : static equilibrium under gravity (x, y, z [m], α, β, γ [rad])
    vectors : a harmonic vector n of each frequency (the one of lowest order), shape (H, N)
    omega : the frequencies Ω = n·ω, ascending, shape (H,) [rad/s]
    amplitudes : their complex amplitudes Q(Ω), shape (H, 6) [m, rad]
    system : the assembled equations
    order : truncation order K, the largest |n|₁ retained
    truncation_error : estimated peak motion of the harmonics left out [m]
    """

    static: np.ndarray
    vectors: np.ndarray
    omega: np.ndarray
    amplitudes: np.ndarray
    system: PeriodicSystem
    order: int
    truncation_error: float

    def _at_zero(self) -> np.ndarray:
        return np.abs(self.omega) <= _tolerance(self.system)

    @property
    def mean(self) -> np.ndarray:
        """Static equilibrium plus the mean offset from the periodic terms."""
        return self.static + self.amplitudes[self._at_zero()].sum(axis=0).real

    def peaks(self, maps) -> np.ndarray:
        """Peak over time of |T q_dyn(t)| for each map T in ``maps`` (shape (C, k, 6)), summed over
        frequencies (exact for one frequency: the orbit of 2 Re(X e^{iθ}) is an ellipse with
        semi-major axis sqrt(2 (|X|² + |X·X|)))."""
        return orbit_peaks(maps, self.amplitudes[self.positive])

    @property
    def positive(self) -> np.ndarray:
        """Which frequencies are positive (not round-off of zero): the amplitudes that make the motion."""
        return (self.omega > 0) & ~self._at_zero()


def orbit_peaks(maps, amplitudes) -> np.ndarray:
    """Peak over time of |T q(t)| for q(t) = Σ 2 Re(Q_f e^{iΩ_f t}) over ``amplitudes`` Q_f of positive
    frequencies (shape (..., F, 6)) and each map T of ``maps`` (shape (..., C, k, 6)): the sum of the
    semi-major axes sqrt(2 (|X|² + |X·X|)), X = T Q_f, of the orbits (exact for one frequency); shape
    (..., C) [m]."""
    X = np.einsum("...ckj,...fj->...cfk", np.asarray(maps, dtype=float), amplitudes)
    size = np.abs(X) ** 2
    return np.sqrt(2.0 * (size.sum(axis=-1) + np.abs((X * X).sum(axis=-1)))).sum(axis=-1)


def _weights(length: float) -> np.ndarray:
    """Sizes of (x, y, z, α, β, γ) in metres: rotations times the platform's diagonal."""
    return np.array([1.0, 1.0, 1.0, length, length, length])


@dataclass(frozen=True)
class _Couplings:
    """The periodic coefficients of (HB) merged by frequency: offsets Ω_k (k ≠ 0) and, for each,
    K_k, G_k, M_k summed over the harmonic vectors k of that frequency."""

    offsets: HarmonicSet
    stiff: np.ndarray
    gyro: np.ndarray
    mass: np.ndarray

    @property
    def stacked(self) -> np.ndarray:
        """[K_kᵀ; G_kᵀ; M_kᵀ] (18×6 each), so that [Q, iΩQ, -Ω²Q] @ W_k = (A_k(Ω) Q)ᵀ."""
        return np.swapaxes(np.concatenate([self.stiff, self.gyro, self.mass], axis=-1), -1, -2)


def _gathered(rows, values, size: int) -> np.ndarray:
    """Σ of ``values`` (shape (..., n, k...)) into ``size`` rows along axis -3 (for k = (6, 6)) or
    -2 (for k = (6,)), row ``rows[i]`` receiving ``values[..., i, ...]``, in order of i."""
    axis = -3 if values.ndim >= 3 and values.shape[-2:] == (6, 6) else -2
    moved = np.moveaxis(values, axis, 0)
    total = np.zeros((size,) + moved.shape[1:], dtype=complex)
    np.add.at(total, rows, moved)
    return np.moveaxis(total, 0, axis)


def _couplings(system: PeriodicSystem, tolerance: float) -> _Couplings:
    """(Of a single system or of a :func:`~foundation_calc.solvers.platform.dynamics.stack`.)"""
    keys = system.keys[1:]
    offsets = distinct(keys, system.frequencies(keys), tolerance)
    row = offsets.find(system.frequencies(keys))
    parts = (system.stiff[..., 1:, :, :], system.gyro[..., 1:, :, :], system.mass[..., 1:, :, :])
    return _Couplings(offsets, *(_gathered(row, part, len(offsets)) for part in parts))


class _Operator:
    """The left side of (HB) on a set of harmonics (block rows and columns)."""

    def __init__(self, system: PeriodicSystem, couplings: _Couplings, harmonics: HarmonicSet, links=None) -> None:
        self.couplings = couplings
        self.harmonics = harmonics
        self.diagonal = system.dynamic_matrices(harmonics.omega)
        self.blocks = couplings.stacked
        self.links = links if links is not None else self.links_for(harmonics.omega)

    def part(self, i: int) -> "_Operator":
        """The operator of system ``i`` of a stack."""
        c = self.couplings
        one = copy.copy(self)
        one.couplings = _Couplings(c.offsets, c.stiff[i], c.gyro[i], c.mass[i])
        one.diagonal, one.blocks = self.diagonal[i], self.blocks[i]
        return one

    def links_for(self, omega) -> list[tuple[np.ndarray, np.ndarray]]:
        """For each coupling offset Ω_k: which of the frequencies ``omega`` (Ω_m) have Ω_m - Ω_k in
        the set, and the set's row numbers of those."""
        links = []
        for w_k in self.couplings.offsets.omega:
            src = self.harmonics.find(omega - w_k)
            hit = np.nonzero(src >= 0)[0]
            links.append((hit, src[hit]))
        return links

    def coupled(self, Q, links, rows: int) -> np.ndarray:
        """Σ_{k≠0} A_k(Ω_m - Ω_k) Q(Ω_m - Ω_k) for ``rows`` block rows described by ``links``."""
        w = self.harmonics.omega[:, None]
        Z = np.concatenate([Q, 1j * w * Q, -w * w * Q], axis=-1)
        out = np.zeros(Q.shape[:-2] + (rows, 6), dtype=complex)
        for p, (hit, src) in enumerate(links):
            if len(hit):
                out[..., hit, :] += Z[..., src, :] @ self.blocks[..., p, :, :]
        return out

    def apply(self, Q) -> np.ndarray:
        """(HB) left side for amplitudes Q (shape (H, 6); of a stack of systems (V, H, 6))."""
        return np.einsum("...hij,...hj->...hi", self.diagonal, Q) + self.coupled(Q, self.links, Q.shape[-2])

    def dense(self) -> np.ndarray:
        """The whole matrix, shape (6H, 6H) (of a stack of systems: (V, 6H, 6H))."""
        H = len(self.harmonics)
        lead = self.diagonal.shape[:-3]
        A = np.zeros(lead + (H, H, 6, 6), dtype=complex)
        idx = np.arange(H)
        A[..., idx, idx, :, :] = self.diagonal
        c = self.couplings
        for p, (hit, src) in enumerate(self.links):
            w = self.harmonics.omega[src][:, None, None]
            at = (Ellipsis, p, None, slice(None), slice(None))
            A[..., hit, src, :, :] += c.stiff[at] + 1j * w * c.gyro[at] - w * w * c.mass[at]
        return np.swapaxes(A, -3, -2).reshape(lead + (6 * H, 6 * H))


def _loads(system: PeriodicSystem, static: np.ndarray, tolerance: float) -> tuple[HarmonicSet, np.ndarray]:
    """Frequencies and values of the right side F_m - K_m q_s of (HB)."""
    vectors = np.concatenate([system.force_keys, system.keys[1:]])
    spill = -(system.stiff[..., 1:, :, :] @ static[..., None, :, None])[..., 0]
    values = np.concatenate([system.force, spill], axis=-2)
    where = distinct(vectors, system.frequencies(vectors), tolerance)
    return where, _gathered(where.find(system.frequencies(vectors)), values, len(where))


def _right_side(harmonics: HarmonicSet, loads) -> np.ndarray:
    where, values = loads
    rhs = np.zeros(values.shape[:-2] + (len(harmonics), 6), dtype=complex)
    row = harmonics.find(where.omega)
    rhs[..., row[row >= 0], :] = values[..., row >= 0, :]
    return rhs


def _solve(op: _Operator, rhs: np.ndarray, guess: np.ndarray, rtol: float = GMRES_TOL) -> np.ndarray:
    """Solve (HB): dense LU for small sets, else GMRES from ``guess`` preconditioned by the inverses
    of the diagonal blocks, to relative residual ``rtol``."""
    H = len(rhs)
    if 6 * H <= DENSE_UNKNOWNS:
        return np.linalg.solve(op.dense(), rhs.ravel()).reshape(H, 6)
    from scipy.sparse.linalg import LinearOperator, gmres

    inverse = np.linalg.inv(op.diagonal)
    n = 6 * H
    A = LinearOperator((n, n), matvec=lambda x: op.apply(x.reshape(H, 6)).ravel(), dtype=complex)
    P = LinearOperator((n, n), matvec=lambda x: np.einsum("hij,hj->hi", inverse, x.reshape(H, 6)).ravel(), dtype=complex)
    x, info = gmres(A, rhs.ravel(), x0=guess.ravel(), rtol=rtol, atol=0.0, restart=60, maxiter=20, M=P)
    if info != 0:
        raise ConvergenceError(f"the harmonic balance over {H} frequencies did not converge (GMRES, {info} iterations)")
    return x.reshape(H, 6)


def _require_regular(system: PeriodicSystem, harmonics: HarmonicSet, diagonal, length: float, natural) -> None:
    """Raise PhysicsError when an undamped diagonal block is singular (an exact resonance); of a
    stack of systems, for the first system that has one (``natural(i)`` its frequencies)."""
    if system.damped or len(harmonics) == 0:
        return
    scale = np.diag(1.0 / _weights(length))
    rcond = 1.0 / np.linalg.cond(scale @ diagonal @ scale)
    if rcond.ndim > 1:
        for i in np.nonzero(~np.all(rcond > SINGULAR_RCOND, axis=1))[0][:1]:
            _require_regular(system, harmonics, diagonal[i], length, lambda: natural(i))
        return
    bad = np.nonzero(~(rcond > SINGULAR_RCOND))[0]
    if len(bad) == 0:
        return
    row = bad[np.lexsort((rcond[bad], harmonics.omega[bad] < 0))[0]]  # the positive frequency first
    n, w = harmonics.vectors[row], abs(float(harmonics.omega[row]))
    modes = natural()
    p = float(modes[np.argmin(np.abs(modes - w))])
    raise PhysicsError(
        f"the 6-DOF response is undefined: the combination {combination_label(tuple(int(x) for x in n))}"
        f" = {w:.6g} rad/s of the rotor speeds falls on the natural frequency {p:.6g} rad/s of the"
        " undamped platform",
        field="isolators.loss_factor",
        hint="move the speeds or the stiffnesses, or give the isolators' damping (loss_factor > 0)",
    )


def steady_state(platform, rotors, max_order: int | None = None) -> SteadyState:
    """Steady-state response of the platform to its rotors by harmonic balance (module docstring).

    ``max_order``: retain no harmonic of order |n|₁ above it (for convergence studies; by default
    the tolerance alone decides).

    Raises
    ------
    PhysicsError
        when the platform is not restrained (its spring stiffness matrix is singular) or, without
        damping, a combination of the rotor speeds falls exactly on a natural frequency.
    ConvergenceError
        when the iterative solve of a very large harmonic set fails to converge.

    >>> from foundation_calc.solvers.platform.dynamics import RigidPlatform, block_inertia, inertia_about_corner, rotor
    >>> p = RigidPlatform(2e4, (1.5, 1.0, 0.65), inertia_about_corner(2e4, (1.5, 1.0, 0.65),
    ...     block_inertia(2e4, 3.0, 2.0, 1.3)), 3.0, 2.0, np.full((4, 3), 1e8), 0.0, 9.81)
    >>> s = steady_state(p, [rotor(25.0, 0.2, (1.5, 1.0, 0.65), 0.0, 0.0, 100.0, 0.0)])
    >>> round(float(s.static[2]) * 1e4, 4), s.order
    (-4.9111, 5)
    """
    system = periodic_system(platform, rotors)
    length = float(np.hypot(platform.A, platform.B))
    weights = _weights(length)
    tolerance = _tolerance(system)
    couplings = _couplings(system, tolerance)
    static = _static(system)
    loads = _loads(system, static, tolerance)
    zero = HarmonicSet(np.zeros_like(system.keys[:1]), np.zeros(1), tolerance)
    forced = loads[0].subset(zero.find(loads[0].omega) < 0)
    harmonics, Q = zero.union(forced, np.zeros((1, 6), dtype=complex), np.zeros((len(forced), 6), dtype=complex))

    def natural():
        return natural_frequencies(platform, rotors, system).frequencies

    while True:
        op = _Operator(system, couplings, harmonics)
        _require_regular(system, harmonics, op.diagonal, length, natural)
        Q = _solve(op, _right_side(harmonics, loads), Q)
        candidates = harmonics.neighbours(couplings.offsets.vectors, system.speeds)
        estimate = _estimates(system, op, candidates, Q, loads, length, natural)
        size = np.max(np.abs(estimate * weights), axis=1)
        # keep the largest, leave out the smallest while their sum stays within the tolerance
        by_size = np.argsort(size)
        left = np.cumsum(size[by_size]) <= TRUNCATION_TOL * float(np.max(np.abs(Q * weights)))
        wanted = by_size[~left][::-1]
        if max_order is not None:
            wanted = wanted[np.abs(candidates.vectors[wanted]).sum(axis=1) <= max_order]
        wanted = wanted[: max(MAX_HARMONICS - len(harmonics), 0)]
        mirror = candidates.find(-candidates.omega[wanted])  # q is real: Q(-Ω) = conj Q(Ω)
        chosen = np.zeros(len(candidates), dtype=bool)  # wanted ∪ mirror, ascending (np.union1d imports numpy.ma)
        chosen[wanted] = True
        chosen[mirror[mirror >= 0]] = True
        wanted = np.flatnonzero(chosen)
        if len(wanted) == 0:
            break
        harmonics, Q = harmonics.union(candidates.subset(wanted), Q, estimate[wanted])
    order = int(np.max(np.abs(harmonics.vectors).sum(axis=1)))
    # a harmonic left out would move a point by at most twice its amplitude
    return SteadyState(static, harmonics.vectors, harmonics.omega, Q, system, order, 2.0 * float(np.sum(size)))


class VariantBasis:
    """What the tolerance variants of a design share: the nominal's frequencies that matter, the
    index tables of the operator on them and, for a small set, the nominal operator's inverse.

    Harmonics are dropped from the nominal set, smallest first, while the sum of their peaks stays
    below :data:`VARIANT_TOL` times the largest; then up to :data:`VARIANT_LAYERS` layers of
    neighbouring frequencies are added while the set has at most :data:`VARIANT_SMALL_SET`, since
    a variant may rock where the nominal does not. Up to :data:`DENSE_UNKNOWNS` unknowns the inverse is kept (dense);
    larger sets are solved by GMRES from the nominal amplitudes.
    """

    def __init__(self, nominal: SteadyState, length: float) -> None:
        weights = _weights(length)
        size = np.max(np.abs(nominal.amplitudes * weights), axis=1)
        by_size = np.argsort(size)
        dropped = by_size[np.cumsum(size[by_size]) <= VARIANT_TOL * float(np.max(size))]
        keep = np.ones(len(size), dtype=bool)
        keep[dropped] = False
        tolerance = _tolerance(nominal.system)
        whole = HarmonicSet(nominal.vectors, nominal.omega, tolerance)
        keep[whole.find(-nominal.omega[keep])] = True  # q is real: Ω and -Ω together
        keep[nominal.omega == 0.0] = True
        couplings = _couplings(nominal.system, tolerance)
        harmonics, amplitudes = whole.subset(keep), nominal.amplitudes[keep]
        for _ in range(VARIANT_LAYERS):
            more = harmonics.neighbours(couplings.offsets.vectors, nominal.system.speeds)
            if len(more) == 0 or len(harmonics) + len(more) > VARIANT_SMALL_SET:
                break
            harmonics, amplitudes = harmonics.union(more, amplitudes, np.zeros((len(more), 6), dtype=complex))
        self.system = nominal.system
        self.length = length
        self.harmonics = harmonics
        self.amplitudes = amplitudes
        self.order = max(nominal.order, int(np.max(np.abs(harmonics.vectors).sum(axis=1))))
        self.truncation_error = nominal.truncation_error + 2.0 * float(np.sum(size[~keep]))
        op = _Operator(nominal.system, couplings, self.harmonics)
        self.links = op.links
        self.positive = self.harmonics.omega > tolerance
        self.dense = 6 * len(self.harmonics) <= DENSE_UNKNOWNS
        self.inverse = np.linalg.inv(op.dense()) if self.dense else None


def steady_state_near(basis: VariantBasis, platform, rotors, system: PeriodicSystem | None = None) -> SteadyState:
    """Steady state of a system close to the nominal one of ``basis`` (a tolerance variant: the same
    rotors and speeds, stiffnesses or positions changed by a per cent), on the basis' frequencies,
    started from the nominal amplitudes (refined with the nominal operator's inverse, or by GMRES).
    ``system``: the variant's equations when already assembled.

    A change that makes a dropped harmonic resonant needs a natural frequency to cross a
    combination of the speeds of high order; the sensitivity table watches the low orders
    (:data:`~foundation_calc.solvers.platform.verification.WATCHED_ORDER`) separately.

    Raises
    ------
    PhysicsError
        as :func:`steady_state`.
    """
    system = system if system is not None else periodic_system(platform, rotors)
    static, Q = steady_states_near(basis, stack([system]), lambda i: natural_frequencies(platform, rotors, system).frequencies)
    vectors, omega = basis.harmonics.vectors, basis.harmonics.omega
    return SteadyState(static[0], vectors, omega, Q[0], system, basis.order, basis.truncation_error)


def steady_states_near(basis: VariantBasis, systems: PeriodicSystem, natural) -> tuple[np.ndarray, np.ndarray]:
    """Static equilibria (V, 6) and amplitudes (V, H, 6) on the basis' frequencies of a stack of
    variants ``systems`` (:func:`~foundation_calc.solvers.platform.dynamics.stack`), solved
    together as :func:`steady_state_near` solves one; ``natural(i)``: the natural frequencies of
    variant i [rad/s], for the message of an exact resonance.

    Raises
    ------
    PhysicsError
        as :func:`steady_state`, for the first variant that has no steady state.
    """
    if not (np.array_equal(systems.speeds, basis.system.speeds) and np.array_equal(systems.keys, basis.system.keys)):
        raise ValueError("steady_state_near needs the nominal's rotors and speeds")
    tolerance = _tolerance(systems)
    op = _Operator(systems, _couplings(systems, tolerance), basis.harmonics, basis.links)
    _require_regular(systems, basis.harmonics, op.diagonal, basis.length, natural)
    static = _static(systems)
    rhs = _right_side(basis.harmonics, _loads(systems, static, tolerance))
    return static, _refined(op, rhs, basis)


def _refined(op: _Operator, rhs: np.ndarray, basis: VariantBasis) -> np.ndarray:
    """Each variant of a stack (``rhs``: (V, H, 6)) from the nominal amplitudes: iterative refinement
    Q ← Q + A₀⁻¹ (F - A Q) with the nominal inverse A₀⁻¹ until the residual is below
    :data:`VARIANT_GMRES_TOL` of F; a direct solve (or GMRES for a large set) for a variant whose
    residual does not contract (far from the nominal) and every variant of a set too large to keep
    the inverse."""
    V, H = rhs.shape[:2]
    Q = np.array(np.broadcast_to(basis.amplitudes, rhs.shape))
    goal = VARIANT_GMRES_TOL * np.linalg.norm(rhs, axis=(1, 2))
    last, active, direct = np.full(V, np.inf), np.full(V, basis.dense), np.full(V, not basis.dense)
    for _ in range(REFINEMENT_STEPS if basis.dense else 0):
        residual = rhs - op.apply(Q)
        size = np.linalg.norm(residual, axis=(1, 2))
        active &= size > goal
        stuck = active & (size > REFINEMENT_CONTRACTION * last)
        direct |= stuck
        active &= ~stuck
        if not active.any():
            break
        last = size
        Q[active] += (residual[active].reshape(-1, 6 * H) @ basis.inverse.T).reshape(-1, H, 6)
    direct |= active
    for i in np.nonzero(direct)[0]:
        Q[i] = _solve(op.part(i), rhs[i], Q[i], VARIANT_GMRES_TOL)
    return Q


def _tolerance(system: PeriodicSystem) -> float:
    """:data:`FREQUENCY_TOL` in rad/s for the rotor speeds of ``system``."""
    return FREQUENCY_TOL * max(float(np.max(np.abs(system.speeds))), 1.0)


def _estimates(system, op: _Operator, candidates: HarmonicSet, Q, loads, length, natural) -> np.ndarray:
    """D(Ω_m)⁻¹ r_m for harmonics m outside the set: their estimate from the residual r_m = the
    right side minus what the retained harmonics spill onto m."""
    spill = op.coupled(Q, op.links_for(candidates.omega), len(candidates))
    residual = _right_side(candidates, loads) - spill
    diagonal = system.dynamic_matrices(candidates.omega)
    _require_regular(system, candidates, diagonal, length, natural)
    return np.linalg.solve(diagonal, residual[..., None])[..., 0]


def _static(system: PeriodicSystem) -> np.ndarray:
    """Static equilibrium q_s from K_springs q_s = weight and its moment about O1."""
    try:
        return np.linalg.solve(system.springs, system.static_load[..., None])[..., 0]
    except np.linalg.LinAlgError:
        raise PhysicsError(
            "the platform is not restrained: the isolators' stiffness matrix is singular",
            field="isolators",
            hint="every direction needs a spring: check the horizontal sums and the vertical stiffnesses",
        ) from None
