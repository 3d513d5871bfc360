"""Plots of a calculation sheet as SVG text (matplotlib, imported only when a sheet is made)."""

from __future__ import annotations

import io

from foundation_calc.output.display_units import DisplayUnits
from foundation_calc.output.plots import new_figure
from foundation_calc.output.report.model import Figure

#: Labels of critical speeds closer than this fraction of the plotted range are staggered.
LABEL_GAP = 0.04


def sweep_figure(doc: dict, operating_omega: float, units: DisplayUnits) -> Figure:
    """Peaks of C against the crank speed with the operating speed and the detuning bands shaded.

    ``doc`` is the JSON document of ``fcalc sweep`` over the speed (SI units).
    """
    import matplotlib.pyplot as plt

    fig, ax = new_figure(7.0, 3.6)
    rows = doc["points"]
    xs = [units.convert("speed", r["omega"]) for r in rows]
    for key, label in (("y_peak", "y of C"), ("x_peak", "x of C")):
        ys = [float("nan") if r[key] is None else units.convert("amplitude", r[key]) for r in rows]
        ax.semilogy(xs, ys, label=f"peak {label}")
    limit = doc["limits"]["amplitude"]
    if limit is not None:
        ax.axhline(units.convert("amplitude", limit), color="red", linestyle="--", label="amplitude limit")
    band = doc["limits"]["detuning"]
    lo, hi = min(xs), max(xs)
    shown = sorted(
        (units.convert("speed", c["zero_order"]), c) for c in doc["critical_speeds"]
        if lo <= units.convert("speed", c["zero_order"]) <= hi
    )
    previous, level = -float("inf"), 0
    for centre, c in shown:
        colour = "tab:red" if c["source"] == "paper" else "tab:orange"
        ax.axvspan(centre * (1 - band), centre * (1 + band), color=colour, alpha=0.12, linewidth=0)
        level = (level + 1) % 3 if centre - previous < LABEL_GAP * (hi - lo) else 0  # stagger close labels
        previous = centre
        ax.text(centre, 0.98 - 0.22 * level, c["condition"], rotation=90, va="top", ha="right", fontsize=7,
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
        f"Closed-form peaks ({doc['method']}) against the crank speed; shaded: the ±{band:.0%} detuning"
        " band of each resonance (red: the paper's conditions, orange: extra ones); black line: the operating speed."
    )
    return Figure(svg, caption)
