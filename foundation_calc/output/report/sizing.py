"""The sizing a failing scene's sheet prints when the scene asks for it (``[report] design``).

``[report] design = ["block.length=4:8", ...]`` (and ``design_step``) are the ranges and step of
``fcalc design --vary ... --step`` (docs/design.md). The ranges are read on every sheet of the
scene, so a misspelt key is an invalid scene (exit 3, field ``report.design``) whether or not the
scene fails; the search runs only on a sheet whose verdict is a failure, and the sheet prints from
its JSON document (``fcalc design --json``): the cheapest design that passes every check, its
varied values, volume, mass and worst margin (1 − the largest utilisation), each check's
utilisation and what governs it; or, when none passes, that none does, the checks that fail on
every candidate and the closest candidate.
"""

from __future__ import annotations

from collections.abc import Callable

from foundation_calc.output.report.model import Paragraph, table

#: The scene key the ranges are read from, as an invalid scene's message names it.
FIELD = "report.design"


def design_request(loaded, source: str) -> tuple[list[str], float | None] | None:
    """``(ranges, step)`` of the scene's ``[report] design`` (the scene read from ``source``), or
    None when it asks for no sizing.

    Raises
    ------
    SceneError
        ``report.design`` names a key that cannot vary (or not in this scene: a crank scene without
        ``[foundation.block]``, ``piles.*`` without ``[piles]``), a range that is not KEY=LO:HI, a
        bound outside the key's plausible range, or a grid too large (the message of ``fcalc design``).
    """
    options = getattr(loaded, "report", None)
    if options is None or not options.design:
        return None
    from foundation_calc.checks.design.apply import VaryError, applied_document
    from foundation_calc.checks.design.grid import grid, parse_range
    from foundation_calc.errors import SceneError

    try:
        ranges = [parse_range(text) for text in options.design]
        grid(loaded.kind, ranges, options.design_step)
        applied_document(loaded.model_dump(exclude_none=True), {r.key: r.low for r in ranges})  # keys the scene has
    except VaryError as exc:
        raise SceneError(source, [(FIELD, str(exc))]) from None
    return list(options.design), options.design_step


def _ranges_text(document: dict) -> str:
    axes = document["grid"]["axes"]
    ranges = ", ".join(f"{a['key']} {a['low']:g} to {a['high']:g} {a['unit']}" for a in axes)
    refined = next((a["refined_step"] for a in axes if a["refined_step"]), None)
    steps = f"step {axes[0]['step']:.3g} m" + (f", refined to {refined:.3g} m near the answer" if refined else "")
    return f"fcalc design over {ranges} ({steps}; {document['grid']['candidates']} candidates)"


def _checks_table(title: str, design: dict):
    rows = [(name, c["outcome"].upper(), _number(c["utilisation"]), c["governing"])
            for name, c in design["checks"].items()]
    return table(title, ("check", "verdict", "utilisation", "governed by"), rows, (False, False, True, False))


def _number(value: float | None) -> str:
    return "-" if value is None else f"{value:.3g}"


def _utilisation(design: dict) -> str:
    return _number(None if design["worst_margin"] is None else 1.0 - design["worst_margin"])


def _values(design: dict) -> str:
    return ", ".join(f"{key} = {value:g} m" for key, value in design["values"].items())


def sizing_blocks(document: dict, code: int) -> list:
    """The conclusion's paragraphs and table of a sizing: ``document`` is ``fcalc design --json``'s,
    ``code`` its exit code (module docstring)."""
    if not document:  # the office rules no dimension changes: design does not search
        return [Paragraph("Sizing (fcalc design, asked by the scene's [report] design): not searched, the scene fails"
                          " office rules that no dimension changes (see Checks).")]
    if code == 4:
        raise RuntimeError("fcalc design's re-check disagrees with its search on the sheet's sizing")
    searched = _ranges_text(document)
    best = document["best"]
    if best is not None:
        words = (f"Sizing asked by the scene ([report] design): {searched}. The cheapest design that passes every"
                 f" check is {_values(best)}: volume {best['volume']:.4g} m³, mass {best['mass'] / 1e3:.4g} t, worst"
                 f" margin {_number(best['worst_margin'])} (1 − the largest utilisation below).")
        if document["on_limit"]:
            words += (f" It lies on a limit ({document['on_limit']['check']}: {document['on_limit']['governing']}):"
                      " a small change in the data may fail it.")
        if document["at_range_end"]:
            ends = ", ".join(f"the {end} end of {key}" for key, end in document["at_range_end"].items())
            words += f" It takes {ends}: a cheaper design may lie beyond the range searched."
        return [Paragraph(words), _checks_table("Cheapest passing design: its checks", best)]
    closest = document["closest"]
    everywhere = ", ".join(document["fails_everywhere"]) or "none (each candidate fails some check)"
    words = (f"Sizing asked by the scene ([report] design): {searched}. No design in these ranges passes; checks that fail"
             f" on every candidate: {everywhere}. The closest to passing is {_values(closest)}: volume"
             f" {closest['volume']:.4g} m³, worst utilisation {_utilisation(closest)} (1 at the limit).")
    return [Paragraph(words), _checks_table("Closest design (none passes): its checks", closest)]


#: What sizes a scene for its sheet: (scene file, ranges, step) -> (design document, exit code).
Size = Callable[..., tuple[dict, int]]
