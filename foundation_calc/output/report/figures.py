"""Plots of a calculation sheet as SVG text (matplotlib, imported only when a sheet is made)."""

from __future__ import annotations

import io

from foundation_calc.output.display_units import DisplayUnits
from foundation_calc.output.plots import new_figure
from foundation_calc.output.report.contents import SweepSeries
from foundation_calc.output.report.model import Figure

#: Labels of critical speeds closer than this fraction of the plotted range are staggered.
LABEL_GAP = 0.04


def _bands(detuning) -> str:
    """``"±20 %"`` for one band, ``"1ω ±20 %, 2ω ±20 %"`` for a band per order."""
    if isinstance(detuning, dict):
        return ", ".join(f"{k}ω ±{v:.0%}" for k, v in sorted(detuning.items(), key=lambda kv: int(kv[0])))
    return f"±{detuning:.0%}"


def sweep_figure(series: SweepSeries, operating_omega: float, units: DisplayUnits) -> Figure:
    """Peaks of C against the crank speed [rad/s] with the operating speed and the detuning bands shaded."""
    import matplotlib.pyplot as plt

    fig, ax = new_figure(7.0, 3.6)
    xs = [units.convert("speed", w) for w in series.omega]
    for label, peaks in series.peaks.items():
        ys = [float("nan") if p is None else units.convert("amplitude", p) for p in peaks]
        ax.semilogy(xs, ys, label=f"peak {label}")
    limit = series.amplitude_limit
    if limit is not None:
        ax.axhline(units.convert("amplitude", limit), color="red", linestyle="--", label="amplitude limit")
    lo, hi = min(xs), max(xs)
    shown = sorted(
        (units.convert("speed", omega), label, source, band) for label, source, omega, band in series.critical
        if lo <= units.convert("speed", omega) <= hi
    )
    previous, level = -float("inf"), 0
    for centre, label, source, band in shown:
        colour = "tab:red" if source == "paper" else "tab:orange"
        ax.axvspan(centre * (1 - band), centre * (1 + band), color=colour, alpha=0.12, linewidth=0)
        level = (level + 1) % 3 if centre - previous < LABEL_GAP * (hi - lo) else 0  # stagger close labels
        previous = centre
        ax.text(centre, 0.98 - 0.22 * level, label, rotation=90, va="top", ha="right", fontsize=7,
                transform=ax.get_xaxis_transform())
    ax.axvline(units.convert("speed", operating_omega), color="black", linewidth=1.5, label="operating speed")
    ax.set_xlim(lo, hi)
    ax.set_xlabel(f"crank speed [{units.label('speed')}]")
    ax.set_ylabel(f"peak displacement [{units.label('amplitude')}]")
    ax.grid(True, which="both", alpha=0.3)
    fig.legend(fontsize=7, loc="outside upper center", ncols=4)
    buffer = io.StringIO()
    fig.savefig(buffer, format="svg")
    plt.close(fig)
    svg = buffer.getvalue()
    svg = svg[svg.index("<svg"):]  # drop the XML prolog and DOCTYPE so the SVG can sit inline in HTML
    caption = (
        f"Closed-form peaks ({series.method}) against the crank speed; shaded: the detuning band of each"
        f" resonance's order ({_bands(series.detuning)}; red: the paper's conditions, orange: the others);"
        " black line: the operating speed."
    )
    return Figure(svg, caption)
