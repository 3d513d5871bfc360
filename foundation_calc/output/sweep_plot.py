"""The plot of ``fcalc sweep`` of a scene of any kind (:class:`~foundation_calc.checks.sweep.report.SweepReport`):
a crank scene's x, y peaks of C, a block's largest peaks over G and its points along x, y, z,
against the swept speed or soil factor (log scale), with the amplitude limit, the scene's own
speed or soil and the detuning bands (:func:`~foundation_calc.output.plots.mark_resonances`).
A long crank sweep streamed to CSV keeps only what its plot needs (:func:`plotted`)."""

from __future__ import annotations

import numpy as np

from foundation_calc.checks.resonance.rule import bands_text
from foundation_calc.output.sweep import FACTORED, method, of_plane, others


def plot_sweep(report, scene, path, units, name: str) -> None:
    """The sweep's plot: peaks against the swept variable, the limits, the operating point and the
    critical speeds with their detuning bands."""
    if of_plane(report):
        _plot_plane(report, path, units, name, scene.speed.omega_rad_s)
    elif report.variable == "soil_factor":
        _plot_soil(report, path, units, name)
    else:
        _plot_machine_speed(report, path, units, name)


def plotted(part):
    """What the plot of a streamed crank sweep keeps of one chunk: the swept values, x and y peaks, resonant."""
    return part.values.copy(), part.columns["peaks"][:, :2].copy(), part.resonant.copy()


def joined_plot(first, kept):
    """A report to plot from the first chunk and the :func:`plotted` parts of every chunk (only
    ``values``, ``peaks`` and ``resonant`` span the whole sweep)."""
    from dataclasses import replace

    values, peaks, resonant = (np.concatenate(parts) for parts in zip(*kept))
    return replace(first, values=values, resonant=resonant, columns={**first.columns, "peaks": peaks})


def _plot_plane(report, path, units, name: str, operating: float) -> None:
    """A crank scene's sweep: x, y peaks of C against the swept variable (log scale), none where
    resonant, the amplitude limit, and, as on the calculation sheet, the operating speed (or the
    scene's soil, factor 1) and the detuning band of each critical speed inside the range.
    ``operating``: the scene's speed [rad/s] for a speed sweep."""
    speed = report.variable == "omega"
    xs = np.asarray(units.convert("speed", np.asarray(report.values)) if speed else report.values, dtype=float)
    ok = ~np.asarray(report.resonant, dtype=bool)
    series = [(f"{dof} peak of C", np.where(ok, report.columns["peaks"][:, i], np.nan)) for i, dof in enumerate("xy")]
    marks = [(units.convert("speed", c.zero_order), c.label, c.source, c.band) for c in report.critical] if speed else []
    _plot(xs, series, report.limits, path, units, marks,
          (units.convert("speed", operating), "operating speed") if speed else (1.0, "the scene's soil (factor 1)"),
          f"speed [{units.label('speed')}]" if speed else "factor on the soil coefficients c_z, c_x, c_phi [-]",
          f"peak displacement [{units.label('amplitude')}]",
          f"{name}: {method(report)}\nshaded: the detuning band of each judged resonance ([limits] detuning ="
          f" {bands_text(report.detuning)}); red: the paper's, orange: others judged, grey: not judged", legend="best")


def _plot_machine_speed(report, path, units, name: str) -> None:
    """A block's speed sweep: the largest peaks along x, y, z over G and the points against the
    swept machine's speed (log scale), the amplitude limit, its speed in the scene, and the
    critical speed p_j / n of each of its conditions that can decide a row: a judged one with its detuning band, an order-1 one the
    rule does not judge as a grey line (:func:`~foundation_calc.output.plots.mark_resonances`);
    conditions that never decide are left out."""
    machine = report.setup["machine"]
    marks = [(units.convert("speed", c.critical), c.label.removeprefix(f"{c.machine}: "), "extra", c.band if c.judged else 0.0)
             for c in report.critical]
    _plot_largest(
        report, np.asarray(units.convert("speed", report.values), dtype=float), path, units, marks,
        (units.convert("speed", report.setup["speed"]), f"{machine}'s speed"), f"speed of {machine} [{units.label('speed')}]",
        f"{name}: sweep of {machine}'s speed ({others(report)})\nshaded: the detuning band of each judged"
        f" critical speed $p_j/n$ ([limits] detuning = {bands_text(report.detuning)}); grey: order 1, not judged",
    )


def _plot_soil(report, path, units, name: str) -> None:
    """A block's soil sweep: the largest peaks along x, y, z over G and the points against the
    factor (log scale), the amplitude limit, the scene's soil (factor 1), and shaded the factors
    where the resonance rule warns or fails (a judged condition inside its band), half-way to the
    next factors (:func:`_plot_largest`)."""
    xs = np.asarray(report.values, dtype=float)
    half = np.diff(xs).min() / 2.0 if len(xs) > 1 else 0.05 * xs[0]
    inside = np.isin(report.rows.resonance_status, ("warn", "fail"))
    _plot_largest(report, xs, path, units, [], (1.0, "the scene's soil (factor 1)"), f"{FACTORED} [-]",
                  f"{name}: sweep of the {FACTORED} (every machine at its own speed)\nshaded: a judged resonance"
                  f" inside its band ([limits] detuning = {bands_text(report.detuning)})",
                  [(x - half, x + half) for x in xs[inside]])


def _plot_largest(report, xs, path, units, marks, operating, xlabel: str, heading: str, shaded=()) -> None:
    """The plot of every block sweep: the largest peaks along x, y, z over G and the points (the
    ``peak`` column (N, 3) [m]) against ``xs`` (N,) (:func:`_plot`)."""
    series = [(f"peak {direction}", report.columns["peak"][:, d]) for d, direction in enumerate("xyz")]
    _plot(xs, series, report.limits, path, units, marks, operating, xlabel,
          f"largest peak displacement over G and the points [{units.label('amplitude')}]", heading, shaded)


def _plot(xs, series, limits: dict, path, units, marks, operating, xlabel: str, ylabel: str, heading: str, shaded=(),
          legend: str = "lower right") -> None:
    """The plot of every kind's sweep: each of ``series`` (label, displacement (N,) [m]; NaN: none)
    against ``xs`` (N,) on a log scale, the amplitude limit of ``limits``, ``marks`` and
    ``operating`` (the scene's own value, its label) as
    :func:`~foundation_calc.output.plots.mark_resonances` draws them over the swept range (a
    tenth either side of one point), and the x-ranges ``shaded`` [(lo, hi)], labelled as inside a
    detuning band."""
    from foundation_calc.output.plots import mark_resonances, new_figure, save, title

    fig, ax = new_figure()
    marker = "o" if len(xs) == 1 else None
    for label, values in series:
        ax.semilogy(xs, np.asarray(units.convert("amplitude", values), dtype=float), label=label, marker=marker)
    if "displacement" in limits:
        ax.axhline(units.convert("amplitude", limits["displacement"]), color="red", linestyle="--", label="amplitude limit")
    for k, (lo, hi) in enumerate(shaded):
        ax.axvspan(lo, hi, color="orange", alpha=0.25, lw=0, label=None if k else "inside a detuning band")
    lo, hi = float(xs.min()), float(xs.max())
    if hi == lo:  # one point: show a tenth either side
        lo, hi = 0.9 * lo, 1.1 * hi
    mark_resonances(ax, marks, operating[0], lo, hi, operating[1])
    ax.set_xlabel(xlabel)
    ax.set_ylabel(ylabel)
    title(ax, heading)
    ax.grid(True, which="both", alpha=0.3)
    ax.legend(fontsize=8, loc=legend)
    save(fig, path)


__all__ = ["joined_plot", "plot_sweep", "plotted"]
