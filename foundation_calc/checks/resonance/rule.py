"""The resonance rule of every scene kind, stated once (docs/resonance-rule.md).

A machine running at ω excites a mode of natural frequency p through every harmonic n ω of its
forcing; the condition n ω = p has the critical speed ω_c = p/n and the margin |ω - ω_c|/ω_c.
Which conditions are *judged*, and how:

1. A condition is judged when it is one of the source's conditions (crank foundation: the paper's
   ω = k0, 2ω = k0, ω = p1,2, 3ω = p1,2; platform: the modes the exciters drive), or when its
   **forcing share** is at least :data:`FORCING_SHARE`. The forcing share of harmonic n on mode j
   is |φ_jᵀ F_n| / p_j (φ_j mass-normalised, F_n the generalised force of harmonic n), the square
   root of twice the strain energy of the mode's static response to that harmonic, divided by
   the largest such value over every harmonic and mode of the machine.
2. A judged condition fails inside its order's detuning band (``[limits] detuning``: one value
   for every order, or a value per order; an order the office leaves out has no band) and, whatever
   the band, within :data:`RESONANCE_FAIL_MARGIN`.
3. A condition of order 1 (the speed itself on a natural frequency) that is not judged fails
   within :data:`RESONANCE_FAIL_MARGIN` and warns inside the band of order 1.
4. Every other condition never decides a verdict; one inside its band is listed as information.

The **governing** condition is the one with the worst status and, among those, the smallest
ratio of its margin to the margin it needs (its band, at least :data:`RESONANCE_FAIL_MARGIN`),
over the conditions that can decide (rules 2 and 3). Every command names it with its margin.

Everything here works on numpy arrays: a leading axis of speeds or designs in front of the
conditions' axis gives one judgement per speed (``fcalc sweep``).
"""

from __future__ import annotations

from collections.abc import Mapping
from dataclasses import dataclass

import numpy as np

from foundation_calc.checks.outcomes import RESONANCE_FAIL_MARGIN, Outcome

#: Smallest forcing share [-] for which a higher harmonic's condition is judged. A harmonic with a
#: share s moves its mode, at resonance, by s/(2ζ) of the static response of the machine's
#: strongest harmonic in its most driven mode: below 1 % that is at most 10 % of the machine's own
#: vibration for a modal damping ratio ζ ≥ 5 %, within the ±20 % spread of the soil's stiffness.
FORCING_SHARE = 0.01

#: Status of a condition, in rising order of severity (codes of :attr:`Judgement.status`).
CLEAR, INFORMATION, WARN, FAIL = 0, 1, 2, 3
STATUS_NAMES = ("clear", "information", "warn", "fail")
_OUTCOMES = (Outcome.PASS, Outcome.PASS, Outcome.WARN, Outcome.FAIL)


@dataclass(frozen=True)
class Judgement:
    """The rule applied to conditions (arrays, conditions on the last axis).

    Attributes
    ----------
    judged : the condition can fail the design (rule 1) [bool]
    status : :data:`CLEAR`, :data:`INFORMATION`, :data:`WARN` or :data:`FAIL` per condition
    needed : the margin each condition needs [-]: its band, at least :data:`RESONANCE_FAIL_MARGIN`
        (inf for a condition that never decides)
    governing : index of the governing condition per leading index; -1 when none can decide
    """

    judged: np.ndarray
    status: np.ndarray
    needed: np.ndarray
    governing: np.ndarray

    @property
    def worst(self) -> np.ndarray:
        """The worst status per leading index (:data:`CLEAR` for no condition)."""
        return self.status.max(axis=-1, initial=CLEAR)


def required_detuning(detuning: float | Mapping[int, float], orders) -> np.ndarray:
    """The band [-] of each order: a plain ``detuning`` for every order, a mapping order -> band
    for the orders it names (0, no band, for the others).

    >>> required_detuning(0.2, [1, 3]).tolist(), required_detuning({1: 0.2, 3: 0.1}, [1, 2, 3]).tolist()
    ([0.2, 0.2], [0.2, 0.0, 0.1])
    """
    orders = np.asarray(orders, dtype=int)
    if isinstance(detuning, Mapping):
        return np.array([float(detuning.get(int(n), 0.0)) for n in orders.ravel()]).reshape(orders.shape)
    return np.full(orders.shape, float(detuning))


def judge(margin, order, share, required, source) -> Judgement:
    """Apply the rule (module docstring) to conditions.

    Parameters
    ----------
    margin : |ω - ω_c|/ω_c of each condition [-], shape (..., C)
    order : harmonic order n of each condition, shape (C,)
    share : forcing share of each condition [-], broadcastable to ``margin``
    required : detuning band of each condition's order [-] (:func:`required_detuning`), shape (C,)
    source : whether the condition is one of the source's, judged whatever its share, shape (C,)

    >>> j = judge([[0.15, 0.03, 0.04, 0.1]], [1, 4, 1, 6], [1.0, 0.5, 0.0, 1e-4], [0.2] * 4, [True, False, False, False])
    >>> j.status.tolist(), j.governing.tolist()
    ([[3, 3, 3, 1]], [1])
    """
    margin = np.asarray(margin, dtype=float)
    order = np.asarray(order)
    required = np.asarray(required, dtype=float)
    judged = np.broadcast_to(np.asarray(source, dtype=bool) | (np.asarray(share) >= FORCING_SHARE), margin.shape)
    first = np.broadcast_to(order == 1, margin.shape)
    floor = margin < RESONANCE_FAIL_MARGIN
    inside = margin < required
    fail = (judged & (inside | floor)) | (first & floor)
    warn = first & inside & ~fail
    info = ~judged & ~first & inside
    status = np.select([fail, warn, info], [FAIL, WARN, INFORMATION], CLEAR).astype(np.int8)
    deciding = judged | first
    needed = np.where(deciding, np.maximum(required, RESONANCE_FAIL_MARGIN), np.inf)
    ratio = np.where(deciding, margin / needed, np.inf)
    worst = np.where(deciding, status, -1).max(axis=-1, initial=-1)
    ratio = np.where(deciding & (status == worst[..., None]), ratio, np.inf)
    governing = np.where(worst >= 0, np.argmin(ratio, axis=-1) if ratio.shape[-1] else -1, -1)
    return Judgement(judged=judged, status=status, needed=needed, governing=governing)


def condition_phrase(label: str, margin: float, needed: float) -> str:
    """How every command names a condition and its margin: ``"3ω = p1 at 30.9% (needs 20%)"``.

    >>> condition_phrase("3ω = p1", 0.309, 0.2)
    '3ω = p1 at 30.9% (needs 20%)'
    """
    return f"{label} at {margin:.1%} (needs {needed:.0%})"


def bands_text(detuning) -> str:
    """The bands as the scene gave them: ``"0.2"`` or ``"{1 = 0.2, 2 = 0.2}"`` (TOML's words).

    >>> bands_text(0.2), bands_text({"2": 0.1, "1": 0.2})
    ('0.2', '{1 = 0.2, 2 = 0.1}')
    """
    if isinstance(detuning, Mapping):
        return "{" + ", ".join(f"{k} = {v:g}" for k, v in sorted(detuning.items(), key=lambda kv: int(kv[0]))) + "}"
    return f"{detuning:g}"


def outcome(status) -> Outcome:
    """The :class:`Outcome` of a status code (information and clear pass)."""
    return _OUTCOMES[int(status)]


__all__ = [
    "CLEAR",
    "FAIL",
    "FORCING_SHARE",
    "INFORMATION",
    "STATUS_NAMES",
    "WARN",
    "Judgement",
    "bands_text",
    "condition_phrase",
    "judge",
    "outcome",
    "required_detuning",
]
