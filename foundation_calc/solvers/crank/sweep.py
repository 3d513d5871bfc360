"""The crank foundation's steady state along a sweep of speeds or soil factors, on arrays (no
Python object per point): the engine of ``fcalc sweep`` for the plane crank scene, as
:mod:`foundation_calc.solvers.block.sweep` is the block's.

- the corrected first approximation (4.11)-(4.14) of Krichever & Makarov at every point at once
  (:func:`~foundation_calc.solvers.crank.closed_form.first_approximation_motion`), on a
  frequency-dependent soil each harmonic n at n ω (:func:`frequency_consistent_motion`);
- on a support that couples sway with rocking, and where the first approximation steps aside, the
  averaged operator with the exact forcing, each harmonic n on the support at n ω, one batched
  3 × 3 solve per harmonic over the speeds (:func:`coupled_motion`);
- a scene's ``[[loads]]``: their linear steady state added (:func:`sweep_motion`);
- the peaks of C and of the scene's points, and the largest peak or RMS value of every limited
  quantity (:func:`located`), in chunks of :data:`CHUNK` points so that memory stays bounded.
"""

from __future__ import annotations

from dataclasses import dataclass, replace

import numpy as np

from foundation_calc.solvers.crank.closed_form import first_approximation_motion, soft_at_harmonic, varied
from foundation_calc.solvers.crank.loads import loads_response
from foundation_calc.solvers.crank.mechanism import CrankDesign
from foundation_calc.solvers.crank.response import PeriodicMotion, point_series, splice_harmonics, superpose
from foundation_calc.solvers.numerics.trig_series import derivative, peak, rms

#: Points whose peaks are found together: peak() holds ~64 × 4 × 8 bytes per series and sample.
CHUNK = 4096

#: The highest harmonic of the first approximation's series (4.11)-(4.14).
FIRST_APPROXIMATION_HARMONICS = 3


def chunked_peaks(cos, sin):
    """:func:`peak` over the first axis in chunks of :data:`CHUNK`, so memory stays bounded."""
    return np.concatenate([peak(cos[i : i + CHUNK], sin[i : i + CHUNK]) for i in range(0, len(cos), CHUNK)])


def located(motion: PeriodicMotion, omega, points, orders: dict, limited):
    """Peak displacements of every point, name -> (n, 2) [m], and the largest value over C (x, y)
    and the points of every ``limited`` quantity, quantity -> (n,) [SI].

    ``points``: (name, horizontal, height) [m] from C; ``orders``: every quantity a limit may bound
    -> (order of its time derivative, a peak (True) or an RMS value (False)), ``"displacement"``
    among them. The points go through :func:`point_series` and :func:`peak` together, as many at a
    time as make :data:`CHUNK` sweep points' worth of series.
    """
    w = omega[:, None]
    largest = {}
    for key in limited:  # C: x and y
        order, is_peak = orders[key]
        cos, sin = derivative(motion.cos[..., :2, :], motion.sin[..., :2, :], w, order)
        largest[key] = (chunked_peaks(cos, sin) if is_peak else rms(cos, sin)).max(axis=1)
    found_at = {}
    names = [name for name, _, _ in points]
    horizontal = np.array([u for _, u, _ in points], dtype=float)[:, None]
    height = np.array([H for _, _, H in points], dtype=float)[:, None]
    step = max(1, CHUNK // max(len(omega), 1))
    for i in range(0, len(names), step):
        cos, sin = point_series(motion, horizontal[i : i + step], height[i : i + step])  # (points, n, 2, K + 1)
        for key in {"displacement", *limited}:
            order, is_peak = orders[key]
            found = (peak if is_peak else rms)(*derivative(cos, sin, w, order))  # (points, n, 2)
            if key == "displacement":
                found_at.update(zip(names[i : i + step], found))
            if key in limited:
                largest[key] = np.maximum(largest[key], found.max(axis=(0, 2)))
    return found_at, largest


def varied_block(block, factor):
    """The loads' block on the soil × ``factor`` [-] (an array): springs × factor, dashpots ×
    sqrt(factor) (C = 2 ξ sqrt(K m) at fixed damping ratios)."""
    f = np.asarray(factor, dtype=float)
    r = np.sqrt(f)
    return replace(block, K_x=block.K_x * f, K_z=block.K_z * f, K_phi=block.K_phi * f,
                   C_x=block.C_x * r, C_z=block.C_z * r, C_phi=block.C_phi * r)


def at_harmonics(static, width: int, solve):
    """The motion whose harmonic n ≥ 1 is that of ``solve(n)`` (a (motion, resonant) pair on the
    springs at n ω) and whose mean is ``static``'s; and where any of them is resonant."""
    motions, resonant = [static[0]], np.asarray(static[1], dtype=bool)
    for n in range(1, width):
        motion, stuck = solve(n)
        motions.append(motion)
        resonant = resonant | np.asarray(stuck, dtype=bool)
    return splice_harmonics(motions), resonant


@dataclass(frozen=True)
class SweepMotion:
    """The steady state along (a chunk of) a sweep of n points.

    Attributes
    ----------
    motion : the periodic motion of C at every point (x, y [m], θ [rad])
    resonant : (n,) no periodic solution there
    omega : (n,) the speed at each point [rad/s]
    why : approximation key -> why it is left out at some points ({} where none is)
    batch : the mechanism's design at every point (None: no mechanism, or a support coupling sway
        with rocking, whose design does not vary along a speed sweep)
    block : the loads' block at every point (None: no loads)
    """

    motion: PeriodicMotion
    resonant: np.ndarray
    omega: np.ndarray
    why: dict
    batch: CrankDesign | None = None
    block: object = None


def sweep_motion(design: CrankDesign | None, variable: str, values, vendor=None, soil_at=None, blocks=None) -> SweepMotion:
    """The crank foundation's steady state at every point of a sweep of ``variable`` (``"omega"``
    [rad/s] or ``"soil_factor"`` [-]) over ``values`` (n,):

    - the mechanism of ``design`` (None: none): on a support coupling sway with rocking the
      averaged operator with the exact forcing (:func:`coupled_motion`); else the corrected first
      approximation at every point at once, on a frequency-dependent soil each harmonic at n ω
      (:func:`frequency_consistent_motion`);
    - ``vendor``: the scene's loads (``block``, ``loads``, ``omega`` [rad/s]), their linear steady
      state (:func:`~foundation_calc.solvers.crank.loads.loads_response`) added, on the block × the
      soil factor (:func:`varied_block`) or, on a frequency-dependent soil, each harmonic at n ω.

    ``soil_at(frequencies)``: (design, vendor loads) on a frequency-dependent soil's springs and
    dashpots at an array of frequencies [rad/s] (None: the soil does not depend on frequency);
    ``blocks``: the block's M, C, K on the support at an array of frequencies (:func:`plane_blocks`;
    None: the design's own at every frequency, :func:`static_blocks`)."""
    motion = resonant = batch = block = None
    why = {}
    if design is not None and design.coupled:
        motion, resonant = coupled_motion(design, values, static_blocks(design) if blocks is None else blocks)
        omega = values
    elif design is not None:
        batch = varied(design, **{variable: values})
        if soil_at is None:
            motion, resonant = first_approximation_motion(batch)
        else:
            motion, resonant, why = frequency_consistent_motion(design, values, lambda frequencies: soil_at(frequencies)[0],
                                                                blocks)
        resonant = np.asarray(resonant, dtype=bool)
        omega = np.broadcast_to(np.asarray(batch.omega, dtype=float), values.shape)
    if vendor is not None:
        block = varied_block(vendor.block, values) if variable == "soil_factor" else vendor.block
        omega = values if variable == "omega" else np.full(values.shape, vendor.omega)
        res = loads_response(block, omega, vendor.loads)
        loads_motion, stuck = res.motion, res.resonant
        if soil_at is not None:
            def solve(n):
                found = loads_response(soil_at(n * values)[1].block, omega, vendor.loads)
                return found.motion, found.resonant

            loads_motion, stuck = at_harmonics((loads_motion, stuck), loads_motion.cos.shape[-1], solve)
        loads_motion = PeriodicMotion(omega, np.nan_to_num(loads_motion.cos), np.nan_to_num(loads_motion.sin))
        motion = loads_motion if motion is None else superpose(motion, loads_motion)
        resonant = stuck if resonant is None else resonant | stuck
    return SweepMotion(motion, np.asarray(resonant, dtype=bool), omega, why, batch, block)


def frequency_consistent_motion(design: CrankDesign, omega, design_at, blocks):
    """The mechanism's steady state at each speed of ``omega`` [rad/s] (n,) on a frequency-dependent
    soil that does not couple sway with rocking, where it has none (bool (n,)), and why the first
    approximation is left out ({} where it is not), as ``fcalc amplitudes`` solves each speed;
    ``design_at(frequencies)``: the design on the soil's springs and dashpots at an array of
    frequencies [rad/s], ``blocks`` as :func:`coupled_motion` takes it:

    - the corrected first approximation, each harmonic n = 1 ... 3 on the springs and dashpots at
      n ω (:func:`at_harmonics`), the mean on the static springs;
    - at the speeds where it steps aside, the rocking spring at one of its harmonics' soil not
      exceeding P h (:func:`~foundation_calc.solvers.crank.closed_form.soft_at_harmonic`; the
      block stands at rest), the averaged operator with the exact forcing, each harmonic n at n ω
      (:func:`coupled_motion` on ``blocks``), which ``fcalc amplitudes`` judges there;
      ``not_applicable`` then holds the first approximation's refusal at the first such speed
      (:func:`~foundation_calc.solvers.crank.closed_form.require_first_approximation`, in
      amplitudes' words).

    The two series are laid side by side (:func:`side_by_side`)."""
    from foundation_calc.errors import NotApplicable
    from foundation_calc.solvers.crank.closed_form import require_first_approximation

    omega = np.asarray(omega, dtype=float)
    aside, why = np.zeros(omega.shape, dtype=bool), {}
    for n in range(1, FIRST_APPROXIMATION_HARMONICS + 1):
        soft = soft_at_harmonic(design_at(n * omega))
        if soft.any() and not why:
            try:
                first = omega[soft][:1]
                require_first_approximation(varied(design_at(n * first), omega=first))
            except NotApplicable as refused:
                why = {"first_approximation": f"not applicable: {refused.message}"}
        aside |= soft
    parts = []
    if not aside.all():
        w = omega[~aside]
        static = first_approximation_motion(varied(design, omega=w))
        parts.append((~aside, *at_harmonics(static, static[0].cos.shape[-1], lambda n: first_approximation_motion(
            varied(design_at(n * w), omega=w)))))
    if aside.any():
        parts.append((aside, *coupled_motion(design, omega[aside], blocks)))
    return (*side_by_side(omega, parts), why)


def side_by_side(omega, parts) -> tuple[PeriodicMotion, np.ndarray]:
    """One motion at the speeds ``omega`` [rad/s] (n,) of ``parts``, each (where: bool (n,), the
    motion of those points, their ``resonant``), the series of the shorter padded with zero
    harmonics; and where it is resonant (bool (n,))."""
    width = max(motion.cos.shape[-1] for _, motion, _ in parts)
    cos, sin = np.zeros(omega.shape + (3, width)), np.zeros(omega.shape + (3, width))
    resonant = np.zeros(omega.shape, dtype=bool)
    for where, motion, stuck in parts:
        K = motion.cos.shape[-1]
        cos[where, :, :K], sin[where, :, :K], resonant[where] = motion.cos, motion.sin, stuck
    return PeriodicMotion(omega, cos, sin), resonant


def coupled_motion(design: CrankDesign, omega, blocks):
    """The averaged operator's steady state of ``design`` at each speed of ``omega`` [rad/s] (n,),
    and where it has none (bool (n,)): the mechanism's M̄, C̄, K̄ and forcing at each speed
    (:class:`~foundation_calc.solvers.crank.batch.MechanismOperator` about ω, exact), the block's
    on the support at each harmonic's frequency n ω, n = 0 ... K (``blocks(frequencies)``: M, C, K
    (..., 3, 3) at an array of frequencies [rad/s], :func:`plane_blocks`; one call per harmonic, so
    that a pile group's impedance holds one chunk of frequencies at a time), and per harmonic

        (K̄(nω) + i nω C̄(nω) - n²ω² M̄) Z_n = F_n

    solved for every speed at once (:func:`~foundation_calc.solvers.crank.batch.harmonic_response`);
    resonant where a mode of the operator at ω that the dashpots leave undamped lies within the
    resonant margin of a harmonic (:func:`~foundation_calc.solvers.crank.batch.resonant_blocks`)."""
    from foundation_calc.solvers.crank.batch import MechanismOperator, harmonic_response, resonant_blocks

    omega = np.asarray(omega, dtype=float)
    mech = MechanismOperator.of(design, "omega")
    M_m, C_m, K_m, fc, fs = mech.at(omega)
    parts = [blocks(n * omega) for n in range(mech.harmonics + 1)]  # one harmonic at a time: the support's memory
    M, C, K = (np.stack([part[i] for part in parts], axis=1) for i in range(3))  # (n, K + 1, 3, 3)
    resonant, _ = resonant_blocks(M_m + M[:, 1], C[:, 1], K_m + K[:, 1], omega[:, None])
    Z = harmonic_response(M_m[:, None] + M, C_m[:, None] + C, K_m[:, None] + K, omega[:, None], fc, fs, mech.harmonics,
                          per_harmonic=True, decoupled=mech.decoupled)
    Z = np.where(resonant[:, None, None], 0.0, Z)
    return PeriodicMotion(omega, Z.real, -Z.imag), resonant


def static_blocks(design: CrankDesign):
    """``blocks`` of :func:`coupled_motion` on a frequency-independent support: the design's own at every frequency."""
    from foundation_calc.solvers.crank.averaged import block_matrices

    found = block_matrices(design)
    return lambda frequencies: tuple(np.broadcast_to(A, np.shape(frequencies) + (3, 3)) for A in found)


def plane_blocks(support, base_area: float, base_second_moment: float, design: CrankDesign):
    """M, C, K (..., 3, 3) of ``design``'s block (:func:`~foundation_calc.solvers.crank.averaged.block_matrices`)
    on ``support`` (a :class:`~foundation_calc.solvers.supports.base.Support` under a base of
    ``base_area`` [m²] and ``base_second_moment`` [m⁴]) at the frequencies given (an array [rad/s]),
    its sway-rocking coupling included (:func:`~foundation_calc.solvers.supports.plane_footing.plane`):
    the springs and dashpots the scene's design at a frequency takes, read for every frequency at
    once. The static stability in rocking is the scene's (its design at rest); a pile group's
    rocking spring at a frequency past its interaction peaks may fall below P h there without
    making the steady state any less defined."""
    from foundation_calc.solvers.crank.averaged import block_matrices
    from foundation_calc.solvers.supports.plane_footing import plane

    def at(frequencies):
        shape = np.shape(frequencies)
        (K_x, K_z, K_phi), (C_x, C_z, C_phi), (K_xphi, C_xphi) = (
            tuple(np.broadcast_to(v, (np.size(frequencies),)).reshape(shape) for v in part)
            for part in plane(support.impedance(np.ravel(frequencies)), support.label))
        return block_matrices(replace(design, c=K_z / base_area, c1=K_x / base_area, c_phi=K_phi / base_second_moment,
                                      C_x=C_x, C_z=C_z, C_phi=C_phi, K_xphi=K_xphi, C_xphi=C_xphi))

    return at


__all__ = ["CHUNK", "FIRST_APPROXIMATION_HARMONICS", "SweepMotion", "at_harmonics", "chunked_peaks", "coupled_motion",
           "frequency_consistent_motion", "located", "plane_blocks", "side_by_side", "static_blocks", "sweep_motion", "varied_block"]
