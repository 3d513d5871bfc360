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
    """A figure and its axes drawn off screen (Agg backend: no display needed)."""
    import matplotlib

    matplotlib.use("Agg")
    import matplotlib.pyplot as plt

    return plt.subplots(figsize=(width, height), layout="constrained")


def save(fig, path: str | Path) -> None:
    """Write the figure as PNG and release it."""
    import matplotlib.pyplot as plt

    fig.savefig(path, dpi=120)
    plt.close(fig)


__all__ = ["INSTALL_HINT", "new_figure", "plotting_available", "save"]
