"""Plots of a calculation sheet as SVG text (matplotlib, imported only when a sheet is made)."""

from __future__ import annotations

import io

from foundation_calc.output.display_units import DisplayUnits
from foundation_calc.checks.resonance.rule import bands_text
from foundation_calc.output.plots import LABEL_BOX, mark_resonances, new_figure
from foundation_calc.output.report.contents import SweepSeries
from foundation_calc.output.report.model import Figure


#: Speed range of a sheet's sweep plot, as factors on the operating speed (at least: see
#: :func:`sweep_factors`).
SWEEP_RANGE = (0.05, 2.5)


def sweep_factors(omega: float, resonances: list[dict]) -> tuple[float, float]:
    """The sweep plot's speed range as factors on the operating speed ``omega``: :data:`SWEEP_RANGE`,
    widened so that every judged resonance (its critical speed and detuning band) is on the plot.

    >>> sweep_factors(10.0, [{"judged": True, "critical_speed": {"omega": 40.0}, "required": 0.2}])
    (0.05, 5.28)
    """
    top = max((r["critical_speed"]["omega"] * (1 + r["required"]) * 1.1 / omega for r in resonances if r["judged"]),
              default=0.0)
    return SWEEP_RANGE[0], round(max(SWEEP_RANGE[1], top), 2)


def sweep_figure(series: SweepSeries, operating_omega: float, units: DisplayUnits) -> Figure:
    """Peaks of C against the crank speed [rad/s] with the operating speed and the detuning bands shaded."""
    fig, ax = new_figure(7.0, 3.6)
    xs = [units.convert("speed", w) for w in series.omega]
    for label, peaks in series.peaks.items():
        ys = [float("nan") if p is None else units.convert("amplitude", p) for p in peaks]
        ax.semilogy(xs, ys, label=f"peak {label}")
    limit = series.amplitude_limit
    if limit is not None:
        ax.axhline(units.convert("amplitude", limit), color="red", linestyle="--", label="amplitude limit")
    lo, hi = min(xs), max(xs)
    marks = [(units.convert("speed", omega), label, source, band) for label, source, omega, band in series.critical]
    mark_resonances(ax, marks, units.convert("speed", operating_omega), lo, hi)
    ax.set_xlabel(f"crank speed [{units.label('speed')}]")
    ax.set_ylabel(f"peak displacement [{units.label('amplitude')}]")
    ax.grid(True, which="both", alpha=0.3)
    fig.legend(fontsize=7, loc="outside upper center", ncols=4)
    buffer = io.StringIO()
    fig.savefig(buffer, format="svg")
    svg = buffer.getvalue()
    svg = svg[svg.index("<svg"):]  # drop the XML prolog and DOCTYPE so the SVG can sit inline in HTML
    caption = (
        f"Closed-form peaks ({series.method}) against the crank speed; shaded: the detuning band of each"
        f" judged resonance's order ([limits] detuning = {bands_text(series.detuning)}; red: the paper's"
        " conditions, orange: other judged ones, grey: not judged);"
        " black line: the operating speed."
    )
    return Figure(svg, caption)


def platform_modes_figure(doc: dict, detuning: float, units: DisplayUnits) -> Figure:
    """The platform's six natural frequencies (6-DOF, undamped) on the speed axis, each with its
    ±detuning band, and the operating speed: how far the design sits from every mode."""
    fig, ax = new_figure(7.0, 2.6)
    omega = doc["speed"]["omega"]
    modes = sorted((units.convert("speed", f["omega"]), f["mode"]) for f in doc["natural_frequencies"])
    for level, (centre, label) in enumerate(modes):
        ax.axvspan(centre * (1 - detuning), centre * (1 + detuning), color="tab:red", alpha=0.12, linewidth=0)
        ax.axvline(centre, color="tab:red", linewidth=1.0)
        ax.text(centre, 0.97 - 0.16 * (level % 4), f" {label}", va="top", ha="left", fontsize=7,
                transform=ax.get_xaxis_transform(), bbox=LABEL_BOX)  # legible over the next modes' lines
    ax.axvline(units.convert("speed", omega), color="black", linewidth=1.5, label="operating speed")
    top = max(max(c for c, _ in modes), units.convert("speed", omega)) * 1.25
    ax.set_xlim(0.0, top)
    ax.set_yticks([])
    ax.set_xlabel(f"speed [{units.label('speed')}]")
    ax.grid(True, axis="x", alpha=0.3)
    fig.legend(fontsize=7, loc="outside upper center")
    buffer = io.StringIO()
    fig.savefig(buffer, format="svg")
    svg = buffer.getvalue()
    caption = (
        f"Natural frequencies of the platform on its isolators (6-DOF, undamped) with the ±{detuning:.0%}"
        " detuning band of [limits] detuning shaded; black line: the operating speed."
    )
    return Figure(svg[svg.index("<svg"):], caption)


#: Points of a block sheet's sweep of each machine's speed (the crank sheet's range, :func:`sweep_factors`).
BLOCK_SWEEP_POINTS = 401


def block_sweep_figures(loaded, units: DisplayUnits, resonance: dict) -> tuple[Figure, ...]:
    """One speed sweep plot per machine of a block scene (``fcalc sweep``'s plot: the largest peaks
    over G and the points, the amplitude limit, the machine's critical speeds with their bands),
    the other machines at their own speeds, over a range that shows each judged resonance of the
    machine (``resonance``: the resonance check's document)."""
    import tempfile
    from pathlib import Path

    import numpy as np

    from foundation_calc.checks.sweep.block import sweep_block
    from foundation_calc.output.sweep_plot import plot_sweep
    figures = []
    for k, (name, speed) in enumerate(resonance["machines"].items()):
        own = [r for r in resonance["resonances"] if r["machine"] == name]
        sweep = sweep_block(loaded, k, speed["omega"] * np.linspace(*sweep_factors(speed["omega"], own), BLOCK_SWEEP_POINTS))
        with tempfile.TemporaryDirectory(prefix="fcalc-sweep-") as folder:
            path = Path(folder) / "sweep.svg"
            plot_sweep(sweep, loaded, path, units, loaded.name or "block")
            svg = path.read_text(encoding="utf-8")
        caption = (
            f"Sweep of {name}'s speed, the other machines at their own: the largest peak displacement over G and"
            " the points along x, y, z (steady state, as the amplitudes check), the amplitude limit, and the"
            f" critical speed p_j/n of each of {name}'s conditions that can decide, with its detuning band."
        )
        figures.append(Figure(svg[svg.index("<svg"):], caption))
    return tuple(figures)
