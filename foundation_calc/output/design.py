"""What ``fcalc design`` prints: the search's grid and resolution, the reserve asked, the cheapest
passing design with its checks (and the check that holds it on a limit, if one does), the Pareto
set of volume against worst margin, why the cheaper candidates fail, the re-check by ``fcalc
check``'s path, the keys written; the same as one JSON document (SI units), and as a plot.

The designs shown are judged by the full path (the re-check's verdicts): what ``fcalc check``
would say of each.
"""

from __future__ import annotations

import math
from dataclasses import dataclass
from pathlib import Path

import numpy as np

from foundation_calc.checks.design.candidates import CandidateVerdicts
from foundation_calc.checks.design.recheck import OUTCOME_NAMES, Disagreement
from foundation_calc.checks.design.reserve import ON_LIMIT, bound, on_limit
from foundation_calc.checks.design.search import Front, Search, worst_margin

#: Pareto designs shown, re-checked and written to JSON at most (evenly spread over the front).
PARETO_SHOWN = 12


@dataclass(frozen=True)
class Sizing:
    """A finished search and its re-check: ``designs`` are the best (first) and the shown Pareto
    designs (none when nothing passes: then the closest candidate alone), ``full`` the full path's
    verdicts on them, ``evaluator`` the name of what judged the grid, ``pareto_failing`` how many
    Pareto designs of the batch's checks the re-check found failing a deferred check (left out);
    ``written_changes`` the keys ``--write`` changed (:class:`~foundation_calc.output.scene_edit.Change`)."""

    source: str
    name: str
    found: Search
    designs: Front
    full: CandidateVerdicts
    disagreements: tuple[Disagreement, ...]
    evaluator: str
    chunk: int
    written: str | None = None
    pareto_failing: int = 0
    written_changes: tuple = ()


def _finite(value: float) -> float | None:
    return float(value) if math.isfinite(value) else None


def _design(sizing: Sizing, i: int) -> dict:
    full = sizing.full
    checks = {
        name: {
            "outcome": OUTCOME_NAMES[int(full.outcome[name][i])],
            "utilisation": _finite(full.utilisation[name][i]),
            "governing": full.reasons[name][full.governing[name][i]],
        }
        for name in full.outcome
    }
    return {"values": sizing.designs.design(i), "volume": float(full.volume[i]), "mass": float(full.mass[i]),
            "worst_margin": _finite(worst_margin(full)[i]),
            "outcome": OUTCOME_NAMES[int(full.worst_outcome[i])], "checks": checks}


def _axes(found: Search) -> list[dict]:
    return [{"key": a.variable.key, "unit": a.variable.unit, "low": float(a.values[0]), "high": float(a.values[-1]),
             "points": len(a.values), "step": a.step, "refined_step": found.refined_steps.get(a.variable.key)}
            for a in found.grid.axes]


def design_document(sizing: Sizing) -> dict:
    """The JSON document of ``fcalc design`` (SI units; a utilisation or margin that is no finite
    number, such as a check that judges none or a design that cannot be built, is null)."""
    found = sizing.found
    designs = [_design(sizing, i) for i in range(len(sizing.designs.volume))]
    document = {
        "schema_version": 1,
        "command": "design",
        "scene": sizing.source,
        "name": sizing.name,
        "evaluator": sizing.evaluator,
        "strict": found.strict,
        "margin": found.margin,
        "grid": {"candidates": found.grid.size, "axes": _axes(found), "chunk": sizing.chunk, "chunks": found.chunks,
                 "seconds": found.seconds},
        "refinement": {"candidates": found.refined_candidates, "improved": found.improved_by_refinement} if found.refined_steps else None,
        "passed": found.found,
        "best": designs[0] if found.found else None,
        "on_limit": _on_limit(sizing) if found.found else None,
        "at_range_end": found.at_range_end,
        "pareto": designs if found.found else [],
        "pareto_size": len(found.pareto.volume) if found.found else 0,
        "closest": None if found.found else designs[0],
        "fails_everywhere": found.fails_everywhere,
        "cheaper_candidates": found.cheaper_count,
        "cheaper_failures": _failures(found.cheaper_failures),
        "unevaluated": {"count": found.unevaluated_count,
                        "errors": [{"error": kind, "count": n, "example": example, "message": message}
                                   for kind, (n, example, message) in found.unevaluated.items()]},
        "deferred": _deferred(sizing),
        "recheck": {"designs": len(designs), "agree": not sizing.disagreements,
                    "disagreements": [{"values": d.design, "check": d.check, "search": d.search, "fcalc_check": d.full}
                                      for d in sizing.disagreements]},
        "written": sizing.written,
        "written_changes": [{"key": c.key, "from": c.old, "to": c.new} for c in sizing.written_changes],
    }
    return document


def _on_limit(sizing: Sizing) -> dict | None:
    """The check that holds the answer on a limit (:func:`~foundation_calc.checks.design.reserve.on_limit`), or None."""
    found = on_limit(sizing.full, 0, sizing.found.margin)
    return None if found is None else {"check": found.check, "governing": found.governing,
                                       "utilisation": found.utilisation, "limit": found.limit}


def _failures(counts: dict[str, int]) -> list[dict]:
    return [{"check": r.partition(": ")[0], "reason": r.partition(": ")[2], "count": n}
            for r, n in sorted(counts.items(), key=lambda item: -item[1])]


def _deferred(sizing: Sizing) -> dict | None:
    """The checks the search's evaluator deferred to fcalc check's path, and what that path found."""
    found = sizing.found
    if not found.deferred:
        return None
    return {"checks": list(found.deferred), "full_path_checks": found.confirmations, "bound": found.bound,
            "failed": found.deferred_failed, "failures": _failures(found.deferred_failures),
            "unconfirmed": found.unconfirmed, "pareto_failing": sizing.pareto_failing}


def _number(value: float | None, digits: int = 3) -> str:
    return "-" if value is None else f"{value:.{digits}g}"


def _values_text(values: dict[str, float]) -> str:
    return " × ".join(f"{v:.3f}" for v in values.values())


def print_design(sizing: Sizing) -> None:
    """The tables of ``fcalc design`` on stdout (module docstring)."""
    from rich.markup import escape
    from rich.table import Table

    from foundation_calc.output.console import OUTCOME_STYLE, stdout

    console = stdout()
    document = design_document(sizing)
    found = sizing.found
    console.print(f"[bold]fcalc design[/]: {escape(sizing.source)}" + (f" — {escape(sizing.name)}" if sizing.name else ""))
    sizes = " × ".join(str(len(a.values)) for a in found.grid.axes) + " = " if len(found.grid.axes) > 1 else ""
    console.print(f"grid: {sizes}{found.grid.size} candidates in {found.chunks} chunk{'s' * (found.chunks != 1)}"
                  f" of at most {sizing.chunk}, {found.seconds:.2f} s ({escape(sizing.evaluator)})")
    for a in document["grid"]["axes"]:
        refined = f", refined to {a['refined_step']:.3g}" if a["refined_step"] else ""
        console.print(f"  {a['key']}: {a['low']:g} to {a['high']:g} {a['unit']}, step {a['step']:.3g} {a['unit']}{refined}")
    if found.refined_steps:
        result = "found a cheaper design" if found.improved_by_refinement else "found none cheaper"
        console.print(f"refinement: {found.refined_candidates} candidates cheaper than the cheapest within one grid step of it,"
                      f" {result}")
    if found.margin is not None:
        console.print(f"reserve: every utilisation at most {bound(found.margin):.4g} (--margin {found.margin:g}),"
                      " a warning's too")
    _print_deferred(console, document["deferred"], found.found)
    _print_unevaluated(console, document["unevaluated"])
    keys = found.grid.keys
    if found.found:
        best = document["best"]
        console.print(f"\n[bold]cheapest passing design[/]: {_values_text(best['values'])} m ({', '.join(keys)}),"
                      f" volume {best['volume']:.4g} m³, mass {best['mass'] / 1e3:.4g} t,"
                      f" worst margin {_number(best['worst_margin'])}")
        _print_on_limit(console, document["on_limit"], found.margin)
        if found.at_range_end:
            ends = ", ".join(f"the {end} end of {key}" for key, end in found.at_range_end.items())
            console.print(f"[bold yellow]note[/]: it takes {ends}: a cheaper design may lie beyond the range searched")
    else:
        best = document["closest"]
        everywhere = ", ".join(found.fails_everywhere) or "none (each candidate fails some check)"
        reserve = "" if found.margin is None else f" with the reserve {found.margin:g}"
        console.print(f"\n[bold red]no candidate passes[/]{reserve} ({found.grid.size} of {found.grid.size} fail); checks that"
                      f" fail on every candidate: {escape(everywhere)}")
        console.print(f"closest to passing: {_values_text(best['values'])} m ({', '.join(keys)}), volume {best['volume']:.4g} m³:"
                      f" worst utilisation {_number(None if best['worst_margin'] is None else 1 - best['worst_margin'])}"
                      + (" (1 at the limit)" if found.margin is None else f" (at most {bound(found.margin):.4g} to pass)"))
    checks = Table(title=None, show_edge=False)
    for header in ("check", "verdict", "utilisation", "governed by"):
        checks.add_column(header, overflow="fold")
    for name, check in best["checks"].items():
        style = OUTCOME_STYLE[check["outcome"]]
        checks.add_row(name, f"[{style}]{check['outcome'].upper()}[/]", _number(check["utilisation"]), escape(check["governing"]))
    console.print(checks)
    if found.found:
        _print_pareto(console, document, keys)
    if document["cheaper_failures"]:
        cheaper = "cheaper candidates" if found.found else "candidates"
        reserve = "" if found.margin is None else " (or lack the reserve)"
        table = Table(title=f"why the {document['cheaper_candidates']} {cheaper} fail{reserve}", show_edge=False)
        for header in ("check", "governed by", "candidates"):
            table.add_column(header, overflow="fold")
        for row in document["cheaper_failures"]:
            table.add_row(row["check"], escape(row["reason"]), str(row["count"]))
        console.print(table)
    _print_recheck(sizing, document)


def _print_on_limit(console, found: dict | None, margin: float | None) -> None:
    """The note that the answer sits on a limit, naming the check that holds it there."""
    from rich.markup import escape

    if found is None:
        return
    where = f"{escape(found['check'])} ({escape(found['governing'])}) at utilisation {found['utilisation']:.4g}"
    if margin:
        console.print(f"[bold yellow]on a limit[/]: {where}, within {ON_LIMIT:.0%} of the bound {found['limit']:.4g}"
                      f" that the reserve {margin:g} sets")
    else:
        console.print(f"[bold yellow]on a limit[/]: {where}, within {ON_LIMIT:.0%} of its limit: a small change in the"
                      " data (a soil's stiffness, a machine's speed) may fail it; --margin M asks every check for a reserve")


def print_written(sizing: Sizing) -> None:
    """The file ``--write`` wrote and the keys it changed in it."""
    from rich.markup import escape

    from foundation_calc.output.console import stdout

    console = stdout()
    changes = sizing.written_changes
    console.print(f"written: {escape(sizing.written)}", soft_wrap=True)  # the path whole, the words below wrap
    console.print(f"  the scene's text, {len(changes)} key{'s' * (len(changes) != 1)} changed, comments and layout kept:")
    for change in changes:
        after = "commented out" if change.new is None else f"-> {change.new}"
        console.print(f"  {change.key}: {change.old} {after}", soft_wrap=True, markup=False)


def _print_deferred(console, deferred: dict | None, passed: bool) -> None:
    """What the search left to fcalc check's path and what that path found."""
    from rich.markup import escape

    if deferred is None:
        return
    checks = ", ".join(deferred["checks"])
    console.print(f"deferred to fcalc check's path: {checks} (not evaluated in the batch);"
                  f" {deferred['full_path_checks']} full-path check{'s' * (deferred['full_path_checks'] != 1)}"
                  f" of the candidates passing the others, cheapest first (at most {deferred['bound']})")
    if deferred["failed"]:
        reasons = "; ".join((row["reason"] if row["check"] in deferred["checks"] else f"{row['check']}: {row['reason']}")
                            + f" ({row['count']})" for row in deferred["failures"])
        cheaper = "cheaper candidates pass" if passed else "candidates pass"
        console.print(f"  {deferred['failed']} {cheaper} the batch checks but fail {checks}: {escape(reasons)}")
    if deferred["unconfirmed"]:
        console.print(f"  [bold yellow]note[/]: {deferred['unconfirmed']} more candidates pass the batch checks, not judged"
                      f" by the full path (the bound of {deferred['bound']} reached)")
    if deferred["pareto_failing"]:
        console.print(f"  {deferred['pareto_failing']} Pareto design{'s' * (deferred['pareto_failing'] != 1)} of the"
                      f" batch checks fail {checks} by the full path: left out of the Pareto set")


def _print_unevaluated(console, unevaluated: dict) -> None:
    """How many candidates could not be evaluated, by the kind of error, with an example of each."""
    from rich.markup import escape

    from foundation_calc.output.console import Hanging

    if not unevaluated["count"]:
        return
    count = unevaluated["count"]
    console.print(f"[bold yellow]note[/]: {count} candidate{'s' * (count != 1)} could not be evaluated (left out of the search):")
    for row in unevaluated["errors"]:
        console.print(Hanging(f"  {row['error']} ({row['count']}), e.g. {_values_text(row['example'])} m: {escape(row['message'])}"))


def _print_pareto(console, document: dict, keys: list[str]) -> None:
    """The Pareto set, a row a design; where it does not fit ``console`` with no column wrapped (a
    narrow terminal), "governed by" gets two lines' width and the numbers' headers wrap."""
    from rich.markup import escape
    from rich.table import Table

    from foundation_calc.output.console import natural_width, two_lines_for

    shown, size = len(document["pareto"]), document["pareto_size"]
    title = f"Pareto set: volume against worst margin ({shown} of {size} designs)"
    table = Table(title=title, show_edge=False)
    for header in (*[name + " [m]" for name in _short_names(keys)], "volume [m³]", "mass [t]", "worst margin", "governed by"):
        table.add_column(escape(header), justify="right" if header != "governed by" else "left", overflow="fold")
    governed = []
    for design in document["pareto"]:
        top = max(design["checks"].items(), key=lambda item: -math.inf if item[1]["utilisation"] is None else item[1]["utilisation"])
        governed.append(f"{top[0]}: {top[1]['governing']}")
        table.add_row(*[f"{v:.3f}" for v in design["values"].values()], f"{design['volume']:.4g}", f"{design['mass'] / 1e3:.4g}",
                      _number(design["worst_margin"]), escape(governed[-1]))
    if natural_width(table) > console.width:
        two_lines_for(table, -1, governed, console.width)
    console.print(table)


def _short_names(keys: list[str]) -> list[str]:
    """Each varied key by its shortest dotted ending that no other key shares: ``length`` and
    ``width`` of a block, ``block.length`` beside ``piles.length`` (a crank scene's
    ``foundation.block.length`` too: the 80 columns of a terminal hold its Pareto set).

    >>> _short_names(["foundation.block.length", "piles.length"])
    ['block.length', 'piles.length']
    """
    parts = [key.split(".") for key in keys]

    def ending(words, n):
        return ".".join(words[-n:])

    names = []
    for words in parts:
        n = 1
        while n < len(words) and sum(ending(other, n) == ending(words, n) for other in parts) > 1:
            n += 1
        names.append(ending(words, n))
    return names


def _print_recheck(sizing: Sizing, document: dict) -> None:
    from rich.markup import escape

    from foundation_calc.output.console import Hanging, stderr, stdout

    count = document["recheck"]["designs"]
    if not sizing.disagreements:
        stdout().print(f"re-check by fcalc check's path: {count} design{'s' * (count != 1)}, every check agrees")
        return
    stderr().print(f"[bold red]DISAGREEMENT[/] between the search and fcalc check's path on {len(sizing.disagreements)}"
                   f" check{'s' * (len(sizing.disagreements) != 1)} of {count} designs (a bug in fcalc: please report it"
                   " with the scene file):")
    for found in sizing.disagreements:
        stderr().print(Hanging(f"  {escape(found.text)}"))


def plot_design(sizing: Sizing, path: str | Path) -> None:
    """Worst margin against volume: the sampled candidates (passing green, failing grey), the
    Pareto set and the cheapest passing design; margins below -1 drawn at -1."""
    from foundation_calc.output.plots import new_figure, save

    found = sizing.found
    fig, ax = new_figure()
    volume, margin, ok = found.sample
    shown = np.clip(np.nan_to_num(margin, nan=-1.0, neginf=-1.0), -1.0, None)
    ax.scatter(volume[~ok], shown[~ok], s=4, color="0.7", label="fails", rasterized=True)
    ax.scatter(volume[ok], shown[ok], s=4, color="tab:green", alpha=0.5, label="passes", rasterized=True)
    if found.found:
        front = found.pareto
        ax.plot(front.volume, front.margin, "-o", color="tab:blue", markersize=3, label="Pareto set")
        ax.plot(front.volume[:1], front.margin[:1], "*", color="tab:red", markersize=14,
                label=f"cheapest passing: {front.volume[0]:.3g} m³")
    ax.axhline(0.0, color="black", linewidth=0.8)
    if found.margin:
        ax.axhline(found.margin, color="tab:orange", linewidth=0.8, linestyle="--", label=f"reserve {found.margin:g}")
    ax.set_xlabel("block volume [m³]")
    ax.set_ylabel("worst margin 1 - max utilisation [-] (below -1 at -1)")
    ax.set_title(sizing.name or sizing.source, fontsize=10)
    ax.legend(loc="lower right", fontsize=8)
    save(fig, path)


__all__ = ["PARETO_SHOWN", "Sizing", "design_document", "plot_design", "print_design", "print_written"]
