"""Optional matplotlib figures (``--plot FILE.png``); matplotlib is the ``plot`` extra.

matplotlib is imported only here and only when a plot is asked for; without it the commands say
how to install it (``pip install "foundation_calc[plot]"``) before doing any work.
"""

from __future__ import annotations

import importlib.util
from pathlib import Path

INSTALL_HINT = 'install the plot extra: python3 -m pip install "foundation_calc[plot]" (or: pip install matplotlib)'


def plotting_available() -> bool:
    """True when matplotlib can be imported."""
    return importlib.util.find_spec("matplotlib") is not None


def new_figure(width: float = 8.0, height: float = 5.0):
    """A figure and its axes drawn off screen: a bare matplotlib Figure, so neither pyplot (a third
    of a second to import) nor a display backend is loaded; :func:`save` writes it."""
    from matplotlib.figure import Figure

    fig = Figure(figsize=(width, height), layout="constrained")
    return fig, fig.subplots()


#: Formats ``--plot`` writes, by the file's suffix.
FORMATS = (".png", ".svg", ".pdf")

#: Labels of critical speeds closer than this fraction of the plotted range are staggered.
LABEL_GAP = 0.04


#: Height of a level of staggered labels, as a fraction of the axes; a white box under each label,
#: so a curve or another line never runs through its text.
LEVEL_STEP = 0.24
LABEL_BOX = {"facecolor": "white", "alpha": 0.8, "edgecolor": "none", "pad": 0.6}


def label_level(last: list[float], at: float, gap: float) -> int:
    """The lowest level whose last label is at least ``gap`` left of ``at`` (a new level when none
    is; labels are placed left to right), recorded in ``last``: no two labels overlap.

    >>> last = []
    >>> [label_level(last, x, 1.0) for x in (0.0, 0.5, 0.7, 1.2, 3.0)]
    [0, 1, 2, 0, 0]
    """
    level = next((k for k, x in enumerate(last) if at - x >= gap), len(last))
    last[level:level + 1] = [at]
    return level


def mark_resonances(ax, marks, operating: float | None, lo: float, hi: float, operating_label: str = "operating speed") -> None:
    """Shade the detuning band of each critical speed and label it; draw the operating speed.

    ``marks``: (centre, label, source, band) in the plot's speed unit, band [-] (0: no band, a
    condition that is not judged); the paper's conditions red, other judged ones orange, the rest
    a grey line; labels of close speeds staggered.
    """
    last: list[float] = []  # the speed of the last label on each level
    for centre, label, source, band in sorted(m for m in marks if lo <= m[0] <= hi):
        colour = "tab:red" if source == "paper" else "tab:orange" if band > 0 else "grey"
        if band > 0:
            ax.axvspan(centre * (1 - band), centre * (1 + band), color=colour, alpha=0.12, linewidth=0)
        ax.axvline(centre, color=colour, linewidth=0.6, alpha=0.6)
        level = label_level(last, centre, LABEL_GAP * (hi - lo))
        ax.text(centre, 0.98 - LEVEL_STEP * level, label, rotation=90, va="top", ha="right", fontsize=7,
                transform=ax.get_xaxis_transform(), bbox=LABEL_BOX)
    if operating is not None:
        ax.axvline(operating, color="black", linewidth=1.5, label=operating_label)
    if hi > lo:
        ax.set_xlim(lo, hi)


#: Font size of a plot's title [pt].
TITLE_SIZE = 8


def title(ax, text: str) -> None:
    """Set the plot's title, wrapped at draw time to the figure's width so that a long scene name
    stays inside the picture (each ``\n`` in ``text`` still starts a line)."""
    ax.set_title(text, fontsize=TITLE_SIZE, wrap=True)


def save(fig, path: str | Path) -> None:
    """Write the figure in the format of the path's suffix (PNG without one), drawn in memory and
    written by the rule of :mod:`foundation_calc.output.files` (a regular file replaced whole, a
    FIFO or a device written in place); unreferenced, the figure is freed."""
    import io

    from foundation_calc.output.files import write_atomically

    buffer = io.BytesIO()
    fig.savefig(buffer, dpi=120, format=Path(path).suffix[1:].lower() or "png")
    write_atomically(path, buffer.getvalue())


__all__ = ["FORMATS", "INSTALL_HINT", "mark_resonances", "new_figure", "plotting_available", "save", "title"]
