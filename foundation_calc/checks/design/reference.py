"""The reference evaluator: every candidate put into the scene (:func:`~.apply.apply`) and
checked by ``fcalc check``'s own path (:func:`~foundation_calc.checks.batch.run_checks`), one
candidate after the other.

Slow (milliseconds a candidate) and plainly right: it is what the vectorised evaluators are
tested and timed against, what re-checks the designs a search picks, and the evaluator of a kind
that has no vectorised one. It returns the same :class:`~.candidates.CandidateVerdicts`.

Utilisation of each check, read from the check's report (:func:`judged`):

- resonance: the margin the governing condition needs over its margin, needed / margin (the
  governing condition of the rule, as ``fcalc check`` names it; a crank scene's as given, its
  ``modulus_range`` judged in the outcome only);
- amplitudes: the largest value / limit over the limit rows and the code zones' boundaries;
  infinite when an order is resonant with an undamped mode (no steady state);
- office: value / allowed value (the mass ratio: required / ratio, a lower bound);
- runup: the largest transient / limit and motor torque needed / available;
- inputs (plausibility warnings): no number (NaN).

A check a candidate does not run (a run-up without limits) passes there with NaN; a candidate
whose scene cannot be built or computed (a :class:`~foundation_calc.errors.FcalcError`) fails
check ``"scene"`` (utilisation infinite) with the error as its reason.
"""

from __future__ import annotations

import math
from collections.abc import Mapping
from typing import Any

import numpy as np

from foundation_calc.checks.design.candidates import FAIL, PASS, WARN, Batch, CandidateVerdicts
from foundation_calc.errors import FcalcError

OUTCOME_CODES = {"pass": PASS, "warn": WARN, "fail": FAIL, "invalid": FAIL}


def _ratio(demand: float, capacity: float) -> float:
    return demand / capacity if capacity > 0 else math.inf


def _resonance(report) -> tuple[float, str]:
    from foundation_calc.checks.outcomes import RESONANCE_FAIL_MARGIN

    if hasattr(report, "nearest"):  # a block foundation
        from foundation_calc.checks.amplitudes.machines import condition_label

        row = report.nearest
        return _ratio(max(row.required, RESONANCE_FAIL_MARGIN), row.margin), condition_label(row)
    row = report.governing
    if row is None:
        return math.nan, "no resonance condition"
    return _ratio(row.needed, row.margin), row.condition.label


def _amplitudes(report) -> tuple[float, str]:
    if report.resonant:
        return math.inf, "resonant: no steady state"
    rows = [(row.ratio, f"{row.quantity} at {row.point} ({row.direction})") for row in report.limit_rows]
    rows += [(row.ratio, f"{row.table.title} at {row.point}") for row in report.zone_rows]
    return max(rows, default=(math.nan, "no limit"))


def _office(report) -> tuple[float, str]:
    rows = [(_ratio(row.limit, row.value) if row.name == "mass ratio" else _ratio(row.value, row.limit), row.name)
            for row in report.office if row.value is not None]  # a check that does not apply
    return max(rows, default=(math.nan, "no office rule"))


def _runup(report) -> tuple[float, str]:
    from foundation_calc.checks.runup import run_title

    rows = [(row.ratio, f"{row.point}, {run_title(row.run)}") for row in report.rows if row.ratio is not None]
    rows += [(_ratio(t.needed, t.available), f"motor torque{f' of {t.machine}' if t.machine else ''} at mode {t.mode + 1}") for t in report.torques]
    return max(rows, default=(math.nan, "nothing judged"))


#: check name -> its utilisation and what governs it, from the check's report.
UTILISATION = {"resonance": _resonance, "amplitudes": _amplitudes, "office": _office, "runup": _runup}


def _kind_of(run) -> str:
    """What a check without a number warns of, without the candidate's values (so that candidates
    tally by it): the plausibility warning's quantity, ``"block-to-machine mass ratio"``."""
    text = "".join(part for part in run.reason if isinstance(part, str))
    if run.check == "inputs" and ": " in text:
        return "outside the plausible range: " + text.split(": ", 1)[1].split(" (", 1)[0].split(" = ", 1)[0].strip()
    return text or run.check


def judged(run) -> tuple[int, float, str]:
    """(outcome code, utilisation, what governs) of one :class:`~foundation_calc.checks.batch.CheckRun`.

    Raises
    ------
    RuntimeError
        on a check that ended in an internal error (a bug in fcalc: never hidden as a failure).
    """
    if run.verdict == "internal":
        raise RuntimeError(f"check {run.check}: {run.problems[0][1] if run.problems else run.reason}")
    if run.verdict == "invalid":
        return FAIL, math.inf, "; ".join(part for part in run.reason if isinstance(part, str))
    utilisation = UTILISATION.get(run.check)
    value, reason = (math.nan, _kind_of(run)) if utilisation is None else utilisation(run.report)
    return OUTCOME_CODES[run.verdict], float(value), reason


def block_size(scene) -> tuple[float, float]:
    """(volume [m³], mass [kg]) of the scene's block; the volume with the concrete its support adds
    (:meth:`~foundation_calc.solvers.supports.base.Sizing.concrete`, a pile group's n π d²/4 L),
    the concrete a design pays for."""
    from foundation_calc.checks.design.apply import sizing_of

    block = scene.foundation.block if scene.kind == "crank_foundation" else scene.block
    volume = block.length * block.width * block.height
    return volume + float(sizing_of(scene).concrete()), volume * block.density


def evaluate(document: Mapping[str, Any], batch: Batch, source: str = "<design>") -> CandidateVerdicts:
    """Every candidate of ``batch`` put into the scene ``document`` and checked by
    :func:`~foundation_calc.checks.batch.run_checks` (module docstring)."""
    from foundation_calc.checks.batch import run_checks
    from foundation_calc.checks.design.apply import applied_document
    from foundation_calc.scenes import parse_scene

    keys = list(batch)
    count = len(next(iter(batch.values()))) if keys else 0
    volume, mass = np.full(count, np.nan), np.full(count, np.nan)
    found: dict[str, list[tuple[int, float, str]]] = {}
    for i in range(count):
        candidate = {key: float(batch[key][i]) for key in keys}
        applied = applied_document(document, candidate)
        try:
            scene = parse_scene(applied, source)
            volume[i], mass[i] = block_size(scene)
            results = {run.check: judged(run) for run in run_checks(scene)}
        except FcalcError as exc:
            results = {"scene": (FAIL, math.inf, str(exc))}
            block = applied["foundation"]["block"] if applied.get("kind") == "crank_foundation" else applied["block"]
            volume[i] = block["length"] * block["width"] * block["height"]
            mass[i] = volume[i] * block["density"]
        for name, result in results.items():
            found.setdefault(name, [(PASS, math.nan, "")] * count)[i] = result
    return _verdicts(volume, mass, found)


def _verdicts(volume: np.ndarray, mass: np.ndarray, found: dict[str, list[tuple[int, float, str]]]) -> CandidateVerdicts:
    outcome, utilisation, governing, reasons = {}, {}, {}, {}
    for name, column in found.items():
        texts = tuple(dict.fromkeys(reason for _, _, reason in column))
        outcome[name] = np.array([code for code, _, _ in column], dtype=np.int8)
        utilisation[name] = np.array([value for _, value, _ in column], dtype=float)
        governing[name] = np.array([texts.index(reason) for _, _, reason in column], dtype=int)
        reasons[name] = texts
    return CandidateVerdicts(volume, mass, outcome, utilisation, governing, reasons)


__all__ = ["UTILISATION", "block_size", "evaluate", "judged"]
