"""Checks of a vibrating-platform design: exciter height, resonance margins, rocking.

Impossible designs never get here (the design raises PhysicsError, exit 3). What is checked:

- exciter height: WARN below the support plane (normal below resonance) or more than
  ``limits.exciter_height_ratio`` × ζ above it (the paper's 2.6 m is "highly undesirable");
- regime margin: FAIL when ω is within ``limits.detuning`` of the translational resonance
  sqrt(c0 / M_Σ), the mode the exciter drives (the verdict rule of
  :mod:`~foundation_calc.checks.resonance.rule`), with the amplitude u that restores
  the margin (Eq. (3.14));
- natural frequencies: the six 6-DOF modes by the same rule: a translation inside the band
  fails, any mode within 5 % fails, another mode inside the band warns;
- rocking: FAIL when the 6-DOF model's rocking exceeds ``limits.rocking_percent`` of u;
- tolerances: FAIL when a build tolerance of the sensitivity table brings a combination of the
  rotor speeds onto a natural frequency, WARN when one rocks the corners beyond the rocking limit.
"""

from __future__ import annotations

from dataclasses import dataclass

from foundation_calc.checks.outcomes import Outcome, worst
from foundation_calc.checks.resonance.rule import judge
from foundation_calc.checks.resonance.rule import outcome as rule_outcome
from foundation_calc.solvers.platform.design import PlatformDesign, amplitude_for_margin
from foundation_calc.solvers.platform.dynamics import Modes, natural_frequencies
from foundation_calc.solvers.platform.verification import (
    PlatformModel,
    SensitivityRow,
    Verification,
    build,
    sensitivity,
    verify,
)

MODE_NAMES = {
    "x": "translation x",
    "y": "translation y",
    "z": "vertical",
    "alpha": "rocking about x",
    "beta": "rocking about y",
    "gamma": "yaw",
}


@dataclass(frozen=True)
class Finding:
    """One check: its name, outcome, a sentence a designer can act on and the number behind it
    in a few words (``brief``, for one-line summaries such as ``fcalc check``)."""

    name: str
    outcome: Outcome
    message: str
    brief: str = ""


@dataclass(frozen=True)
class PlatformReport:
    """A design, its 6-DOF verification, modes, sensitivity table and findings."""

    design: PlatformDesign
    model: PlatformModel
    inertia_given: bool
    verification: Verification
    modes: Modes
    sensitivity: tuple[SensitivityRow, ...]
    findings: tuple[Finding, ...]

    @property
    def outcome(self) -> Outcome:
        return worst(f.outcome for f in self.findings)


def mode_margins(modes: Modes, omega) -> list[float]:
    """|ω - p| / p for each natural frequency p [-]."""
    return [abs(omega - p) / p for p in modes.frequencies]


def _height(d: PlatformDesign, ratio: float) -> Finding:
    if d.c < 0:
        regime = "normal below resonance" if d.sigma > 0 else "unusual above resonance"
        return Finding(
            "exciter height",
            Outcome.WARN,
            f"the exciter's axis point is c = {d.c:.4g} m, below the support plane ({regime});"
            " check that the structure can carry it there",
            f"c = {d.c:.4g} m",
        )
    if d.zeta > 0 and d.c > ratio * d.zeta:
        return Finding(
            "exciter height",
            Outcome.WARN,
            f"the exciter sits c = {d.c:.4g} m above the support plane, {d.c / d.zeta:.3g} × ζ"
            f" (limit {ratio:g} × ζ); lowering ζ lowers c (Eq. (3.15))",
            f"c = {d.c:.4g} m = {d.c / d.zeta:.3g} ζ",
        )
    return Finding("exciter height", Outcome.PASS, f"c = {d.c:.4g} m")


#: Modes the design drives: the exciter's force turns in the horizontal plane.
DRIVEN_MODES = ("x", "y")


def _regime(d: PlatformDesign, detuning: float) -> Finding:
    p = d.translation_frequency
    side = "below" if d.sigma > 0 else "above"
    text = f"ω = {d.omega:.5g} rad/s is {d.regime_margin:.1%} {side} the translational resonance sqrt(c0/M_Σ) = {p:.5g} rad/s"
    outcome = rule_outcome(judge([d.regime_margin], [1], [1.0], [detuning], [True]).status[0])
    brief = f"{d.regime_margin:.1%} from sqrt(c0/M_Σ) = {p:.5g} rad/s"
    if outcome is Outcome.PASS:
        return Finding("regime margin", outcome, text, brief)
    u_max = amplitude_for_margin(d.M, d.m, d.l, d.sigma, detuning)
    return Finding(
        "regime margin",
        outcome,
        f"{text}, inside the required {detuning:.0%}: u <= {u_max:.4g} m (now {d.u:.4g} m) or a larger"
        " unbalance m l moves it away (Eq. (3.14))",
        brief,
    )


def _modes(modes: Modes, omega, detuning: float) -> Finding:
    margins = mode_margins(modes, omega)
    driven = [dom in DRIVEN_MODES for dom in modes.dominant]
    count = len(driven)
    verdict = judge(margins, [1] * count, [float(d) for d in driven], [detuning] * count, driven)
    rows = [
        (rule_outcome(status), f"{MODE_NAMES[dom]} {p:.5g} rad/s (margin {mg:.1%})")
        for p, dom, mg, status in zip(modes.frequencies, modes.dominant, margins, verdict.status)
    ]
    outcome = worst(o for o, _ in rows)
    if outcome is Outcome.PASS:
        return Finding("natural frequencies", outcome, f"all six are at least {detuning:.0%} from ω")
    close = [text for o, text in rows if o is not Outcome.PASS]
    return Finding(
        "natural frequencies",
        outcome,
        f"within {detuning:.0%} of ω: " + ", ".join(close) + " (any deviation from the design excites them)",
        ", ".join(text for o, text in rows if o is outcome),
    )


def damping_text(model: PlatformModel) -> str:
    """The isolators' damping in words: "loss factor η = 0.01, damping ratio D = 0.02" or "none"."""
    parts = [f"loss factor η = {model.eta:g}"] if model.eta > 0 else []
    parts += [f"damping ratio D = {model.damping_ratio:g}"] if model.damping_ratio > 0 else []
    return ", ".join(parts) or "none"


#: A rocking below this [% of u] is the 6-DOF solve's round-off (1e-12 of u, the tables' rule): said as 0.
ROCKING_ROUND_OFF = 1e-10


def _rocking(v: Verification, limit: float, model: PlatformModel) -> Finding:
    why = f" with the isolators' damping ({damping_text(model)})" if model.damped else ""
    shown = v.rocking_percent if v.rocking_percent >= ROCKING_ROUND_OFF else 0.0
    text = f"rocking {shown:.3g} % of u{why} (limit {limit:g} %)"
    return Finding("rocking", Outcome.FAIL if v.rocking_percent > limit else Outcome.PASS, text, f"{shown:.3g} % of u")


def _tolerances(rows, limit: float) -> Finding:
    resonant = [r for r in rows if r.resonance]
    if resonant:
        return Finding(
            "tolerances",
            Outcome.FAIL,
            "; ".join(f"resonant within {r.tolerance} {r.parameter}: {r.resonance}" for r in resonant),
            f"{resonant[0].parameter} {resonant[0].tolerance}: {resonant[0].resonance}",
        )
    worst = rows[0]
    text = (
        f"the largest effect, {worst.tolerance} on {worst.parameter}, rocks or offsets the corners"
        f" {worst.worst:.3g} % of u (rocking limit {limit:g} %)"
    )
    return Finding("tolerances", Outcome.WARN if worst.worst > limit else Outcome.PASS, text, f"{worst.parameter} {worst.worst:.3g} % of u")


def check_platform(design: PlatformDesign, model: PlatformModel, limits, inertia_given: bool) -> PlatformReport:
    """Verify ``design`` on the 6-DOF model and compare with ``limits`` (a scene's [limits])."""
    v = verify(design, model)
    modes = natural_frequencies(*build(design, model), v.state.system)
    rows = tuple(sensitivity(design, model, v, modes.frequencies))
    findings = (
        _height(design, limits.exciter_height_ratio),
        _regime(design, limits.detuning),
        _modes(modes, design.omega, limits.detuning),
        _rocking(v, limits.rocking_percent, model),
        _tolerances(rows, limits.rocking_percent),
    )
    return PlatformReport(design, model, inertia_given, v, modes, rows, findings)
