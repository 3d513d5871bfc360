"""The run-up section of a calculation sheet: every resonance passed, the motor, the envelope plot.

Read from the ``runup`` check's document (the one ``fcalc check`` judged) and, for the plot, its
report; shown whenever the scene is run up (a run time with a transient limit, or a drive).
"""

from __future__ import annotations

from foundation_calc.output.display_units import DisplayUnits
from foundation_calc.output.report.model import Figure, Paragraph, Section, table
from foundation_calc.output.report.numbers import DIGITS, figure, quantity

CLOSED_FORM_NOTE = (
    "closed form: the mode alone, Faddeeva envelope of the passage with the order's force, its inertial part"
    " growing as (Ω/ω)² (within +3 % for η ≤ 10⁻²); Lewis: the undamped asymptote [Le]; integrated: the same mode's motion"
    " in the time integration of the whole linear model; all modes: largest displacement of any point in"
    " the passage's window, at time t. Order: the harmonic of the shaft speed Ω that passes the mode."
    " η = (dΩ/dt)/ω_n² is the sweep rate, ζ the mode's damping ratio."
)


def _passages(key: str, run: dict, units: DisplayUnits):
    from foundation_calc.checks.runup import run_title
    from foundation_calc.output.runup import mode_label

    a, sp = units.label("amplitude"), units.label("speed")
    steady = run["steady_amplitude"]
    rows = (
        (
            mode_label(p["mode"] - 1, run.get("mode_names")), figure(units.convert("speed", p["natural_frequency"]), DIGITS["speed"]),
            f"{p['harmonic']:g}ω",
            figure(units.convert("speed", p["speed"]), DIGITS["speed"]), figure(p["sweep_rate"], 3), figure(p["damping_ratio"], 3),
            *(figure(units.convert("amplitude", p[k]), DIGITS["amplitude"]) for k in ("closed_form_peak", "lewis_peak", "integrated_peak")),
            figure(p["peak_time"], 3), figure(units.convert("amplitude", p["total_peak"]), DIGITS["amplitude"]),
            "-" if p["ratio_to_steady"] is None else figure(p["ratio_to_steady"], 3), p["point"],
        )
        for p in run["passages"]
    )
    title = (
        f"{run_title(key).capitalize()} in {figure(run['duration'], 3)} s ({'damped' if run['damped'] else 'undamped'});"
        f" steady amplitude at the operating speed {quantity(units, 'amplitude', steady)}"
    )
    # the units once in the title, not in every cell or heading, so thirteen columns fit the page
    shown_units = f". Speeds ω_n, Ω in {sp}; peaks in {a}; t in s"
    header = ("mode", "ω_n", "order", "at Ω", "η", "ζ", "closed form", "Lewis", "integrated", "at t", "all modes",
              "× steady", "point")
    if not run["passages"]:
        return Paragraph(f"{title}: no resonance that the loads drive is passed.")
    return table(title + shown_units, header, rows, (True,) * 12 + (False,))


def motor_documents(doc: dict) -> list[dict]:
    """The JSON documents of every motor of a ``fcalc runup`` document: the scene's [drive], then
    each block machine's [machines.drive]."""
    return [m for m in (doc.get("motor"), *(doc.get("motors") or {}).values()) if m]


def _motor(motor: dict, units: DisplayUnits):
    of = f" of {motor['machine']}" if motor.get("machine") else ""
    outcome = (
        f"reaches the operating speed at t = {figure(motor['time'], 3)} s" if motor["reached"]
        else f"sticks at Ω ≈ {quantity(units, 'speed', motor['stuck_speed'])}"
    )
    return table(
        f"Motor start-up{of} (Sommerfeld effect): torque {figure(motor['torque'], 4)} N m, shaft inertia"
        f" {figure(motor['inertia'], 4)} kg m²; {outcome}",
        ("mode", "harmonic", "at speed", "torque needed [N m]", "available [N m]", "ratio", "verdict"),
        (
            (str(t["mode"]), f"{t['harmonic']:g}ω", quantity(units, "speed", t["speed"]), figure(t["torque_needed"], 4),
             figure(t["torque_available"], 4), figure(t["ratio"], 3), t["verdict"].upper())
            for t in motor["sommerfeld"]
        ),
        (True, True, True, True, True, True, False),
    )


def envelope_figure(report, name: str, limit: float | None) -> Figure:
    """The run-up plot of ``fcalc runup --plot`` (envelope of the largest displacement and the shaft
    speed against time, per run) as SVG text."""
    import tempfile
    from pathlib import Path

    from foundation_calc.output.runup import plot_runup

    with tempfile.TemporaryDirectory(prefix="fcalc-runup-") as folder:
        path = Path(folder) / "envelope.svg"
        plot_runup(report, path, name, limit)
        svg = path.read_text(encoding="utf-8")
    caption = (
        "Start-up and run-down: envelope of the largest displacement of any point (over one period of the"
        " operating speed), the steady amplitude, the transient limit and the shaft speed; grey lines mark"
        " the resonances passed."
    )
    return Figure(svg[svg.index("<svg"):], caption)


def runup_section(doc: dict, report, scene, units: DisplayUnits, figures: bool = True) -> Section:
    """Passages of every run, the motor's start-up and (with ``figures``) the envelope plot."""
    from foundation_calc.output.report.runup_governing import governing_lines

    lines = governing_lines(scene, doc, units)
    blocks: list = []
    for key, run in doc["runs"].items():
        blocks += [_passages(key, run, units), *([lines[key]] if key in lines else [])]
    blocks.append(Paragraph(CLOSED_FORM_NOTE))
    blocks += [_motor(motor, units) for motor in motor_documents(doc)]
    blocks += [Paragraph(f"Warning: {w}") for w in doc["warnings"]]
    if figures:
        blocks.append(envelope_figure(report, scene.name or "run-up", scene.limits.transient_amplitude))
    return Section("Start-up and run-down", tuple(blocks))
