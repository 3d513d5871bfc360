"""Report of ``fcalc check``: a summary table, one JSON document, JUnit XML for CI servers.

JUnit layout (read by Jenkins, GitLab, GitHub test reporters): one ``<testsuite>`` per scene file,
one ``<testcase>`` per check of that scene (``name`` = the check, ``classname`` = the scene path
with ``/`` as ``.``, ``file`` = the path). A failing check carries ``<failure>``, a scene that
cannot be used or an internal error carries ``<error>``, each with the reason; a warning passes
(``--strict`` makes it a failure) and its reason is in ``<system-out>``. A scene that does not
load has a single test case, ``load``.
"""

from __future__ import annotations

import re
from collections.abc import Iterable
import xml.etree.ElementTree as ET
from collections import Counter
from dataclasses import replace
from pathlib import Path, PurePath

from foundation_calc.checks.batch import CheckRun, SceneRun, exit_code
from foundation_calc.errors import NonFiniteError
from foundation_calc.output.console import (JSON_SCHEMA_VERSION, OUTCOME_STYLE, Hanging, column_room, json_text, stdout,
                                            two_line_width, with_version)
from foundation_calc.output.display_units import CONVERSIONS, DisplayUnits
from foundation_calc.output.files import write_atomically

_SI = DisplayUnits()
_VERDICT_STYLE = {**OUTCOME_STYLE, "invalid": "bold magenta", "internal": "bold magenta"}


def _reason(run: CheckRun, units: DisplayUnits) -> str:
    """The reason of a run in ``units``; for problems, one ``field: message`` per line."""
    if run.problems and run.verdict == "invalid":
        return "\n".join(f"{loc}: {msg}" if loc else msg for loc, msg in run.problems)
    return units.render(run.reason)


def _verdict(run: CheckRun, strict: bool) -> str:
    return "fail" if strict and run.verdict == "warn" else run.verdict


def counts(scenes: list[SceneRun], strict: bool = False) -> dict[str, int]:
    """How many checks ended in each verdict (every verdict present, zero or not)."""
    tally = Counter(_verdict(run, strict) for scene in scenes for run in scene.runs)
    return {verdict: tally[verdict] for verdict in _VERDICT_STYLE}


def scene_counts(scenes: list[SceneRun], strict: bool = False) -> dict[str, int]:
    """How many scenes ended in each verdict, a scene's verdict being its worst check's
    (every verdict present, zero or not); skipped files are not scenes and not counted."""
    rank = list(_VERDICT_STYLE)
    tally = Counter(
        max((_verdict(run, strict) for run in scene.runs), key=rank.index, default="pass")
        for scene in scenes
        if not scene.skipped
    )
    return {verdict: tally[verdict] for verdict in _VERDICT_STYLE}


def _tally(counted: dict[str, int]) -> str:
    return ", ".join(f"{n} {verdict}" for verdict, n in counted.items() if n) or "none"


def _plural(n: int, noun: str) -> str:
    return f"{n} {noun}{'s' * (n != 1)}"


def _common_folder(sources: list[str]) -> str:
    """The folder all sources share (``""`` when they share none), to print names short."""
    import os

    folders = [os.path.dirname(s) for s in sources]
    if not folders or not all(folders) or len({os.path.isabs(f) for f in folders}) > 1:
        return ""  # some in the working folder, or absolute and relative paths mixed
    common = os.path.commonpath(folders)
    return common if all(f == common or f.startswith(common + os.sep) for f in folders) else ""


#: Where a reason starts under its row on a narrow terminal [terminal cells]; its wrapped lines
#: hang two cells further in (:class:`~foundation_calc.output.console.Hanging`).
REASON_INDENT = 4


def _check_table(title, rows, columns):
    """A table of the check rows (their cells: plain text, the verdict as markup)."""
    from rich.table import Table
    from rich.text import Text

    table = Table(title=title, title_justify="left")
    for col in columns:
        table.add_column(col)
    for row in rows:
        table.add_row(*(cell if k == len(row) - 2 else Text(cell) for k, cell in enumerate(row)))
    return table


def reasons_fit(table, reasons: list[str], width: int) -> bool:
    """Whether the reason column (the last) of a check ``table`` on a ``width`` console leaves
    every line of every reason at most two lines (:func:`~foundation_calc.output.console.two_line_width`)."""
    room = column_room(table, -1, width)
    return all(two_line_width(line) <= room for reason in reasons for line in reason.splitlines())


def reasons_under_rows(rows) -> list:
    """The check rows of a narrow terminal: scene, check and verdict aligned on one line, the
    reason under it, ``REASON_INDENT`` cells in, wrapped at words across the terminal's width."""
    from rich.cells import cell_len
    from rich.text import Text

    heads = ("scene", "check", "verdict")
    cells = [(Text(row[0]), Text(row[1]), Text.from_markup(row[2])) for row in rows]
    widths = [max(cell_len(text.plain) for text in column) for column in zip(map(Text, heads), *cells)]

    def line(texts) -> Text:
        joined = Text("  ").join(text + " " * (w - cell_len(text.plain)) for text, w in zip(texts, widths))
        joined.rstrip()
        return joined

    shown = [Hanging(line([Text(head, style="bold") for head in heads]))]
    for texts, row in zip(cells, rows):
        reason = "\n".join(" " * REASON_INDENT + part for part in row[3].splitlines())
        shown += [Hanging(line(texts)), *([Hanging(Text(reason))] if reason else [])]
    return shown


def print_check_table(scenes: list[SceneRun], units: DisplayUnits, strict: bool = False, verbose: bool = False) -> None:
    """One line per scene and check (scene, check, verdict, reason), then the counts of scenes
    and of checks. An invalid scene shows its first problem (all of them with ``verbose``; they
    are also on stderr, in the JSON document and in JUnit); ``verbose`` adds each check's details.
    On a terminal where the reason column would wrap a reason to more than two lines, each
    reason is printed whole under its row instead (:func:`reasons_under_rows`; docs/ci.md)."""
    import os

    from rich.text import Text

    checked = [scene for scene in scenes if not scene.skipped]
    folder = _common_folder([scene.source for scene in checked])
    title = f"fcalc check: scenes in {folder}{os.sep}" if folder else "fcalc check"
    rows = []
    for scene in checked:
        shown = os.path.relpath(scene.source, folder) if folder else scene.source
        for run in scene.runs:
            verdict = _verdict(run, strict)
            lines = _reason(run, units).splitlines() or [""]
            if run.problems and run.verdict == "invalid" and not verbose and len(lines) > 1:
                more = len(lines) - 1
                lines = [lines[0], f"(+{more} more problem{'s' * (more > 1)}, on stderr)"]
            if verbose:
                lines += list(run.details)
            rows.append((shown, run.check, f"[{_VERDICT_STYLE[verdict]}]{verdict.upper()}[/]", "\n".join(lines)))
    out = stdout()
    table = _check_table(Text(title), rows, ("scene", "check", "verdict", "reason"))
    if reasons_fit(table, [row[3] for row in rows], out.width):  # a file, a pipe, a wide terminal
        out.print(table)
    else:
        out.print(Text(title), *reasons_under_rows(rows))
    skipped = [f"{scene.source} ({scene.skip_note})" for scene in scenes if scene.skipped]
    if skipped:
        out.print(Hanging(Text("skipped: " + ", ".join(skipped)), len("skipped: ")))
    out.print(Hanging(
        f"{_plural(len(checked), 'scene')}: {_tally(scene_counts(scenes, strict))}"
        f" ({_plural(sum(len(s.runs) for s in checked), 'check')}: {_tally(counts(scenes, strict))})"
        f"{'; warnings fail (--strict)' if strict else ''}; exit code {int(exit_code(scenes, strict))}",
    ))


def _values_si(values) -> dict:
    return {
        name: {"quantity": quantity, "value": value, "unit": next(iter(CONVERSIONS[quantity]))}
        for name, (quantity, value) in values.items()
    }


def result_document(check: str, report, scene) -> dict:
    """The JSON document of the single-scene command behind ``check`` for its ``report`` on
    ``scene``, without what the ``check`` document says once (schema version, command, scene);
    empty for a check that did not run (``report`` is ``None``)."""
    if report is None:
        return {}
    if check == "requirements":  # the office's rules (checks/requirements.py)
        document = {"requirements": [{"rule": r.rule, "given": r.given, "verdict": r.outcome.value, "source": r.source} for r in report]}
    elif check == "runup":
        from foundation_calc.output.runup import runup_document

        document = runup_document(report, scene, "")
    elif check == "resonance":
        from foundation_calc.output.resonance import resonance_document

        document = resonance_document(report, scene, "")
    elif check == "amplitudes":
        from foundation_calc.output.amplitudes import amplitudes_document

        document = amplitudes_document(report, scene, "")
    elif check == "office":
        from foundation_calc.output.amplitudes.office import office_document

        document = office_document(report, scene, "")
    else:
        from foundation_calc.output.platform import platform_document

        document = platform_document(report, scene, "", scene.operation.speed_given_as)
    if check == "runup":  # the scene's plausibility warnings are the scene entry's; the run's own stay
        document["warnings"] = list(report.warnings)
    skipped = ("schema_version", "command", "scene") + (() if check == "runup" else ("warnings",))
    return {k: v for k, v in document.items() if k not in skipped}


def scene_entry(scene: SceneRun, strict: bool = False) -> dict:
    """One entry of the ``scenes`` list of the ``fcalc check`` document."""
    return {
        "source": scene.source,
        "kind": scene.kind or None,
        "name": scene.name,
        "exit_code": int(scene.exit_code(strict)),
        "warnings": list(scene.warnings),
        "checks": [
            {
                "check": run.check,
                "verdict": _verdict(run, strict),
                "reason": _reason(run, _SI),
                "values": _values_si(run.values),
                "problems": [{"field": loc, "message": msg} for loc, msg in run.problems],
                "details": list(run.details),
                "result": result_document(run.check, run.report, scene.scene),
            }
            for run in scene.runs
        ],
    }


def _summary(scenes: list[SceneRun], strict: bool) -> dict:
    return {
        "skipped": [scene.source for scene in scenes if scene.skipped],
        "exit_code": int(exit_code(scenes, strict)),
        "counts": counts(scenes, strict),
        "scene_counts": scene_counts(scenes, strict),
    }


def _head(strict: bool) -> dict:
    return with_version({"schema_version": JSON_SCHEMA_VERSION, "command": "check", "strict": strict})


def check_document(scenes: list[SceneRun], strict: bool = False) -> dict:
    """The JSON document of ``fcalc check`` (every number SI); :func:`stream_check_json` writes the
    same text scene by scene."""
    return {**_head(strict), "scenes": [scene_entry(s, strict) for s in scenes if not s.skipped], **_summary(scenes, strict)}


def json_entry(scene: SceneRun, strict: bool = False) -> tuple[SceneRun, str | None]:
    """A checked scene as :meth:`~foundation_calc.checks.batch.SceneRun.light` and its entry of
    the document as JSON text (None for a skipped file): what a batch keeps of a scene.

    A check whose entry holds NaN or inf (which JSON cannot carry) becomes ``invalid`` with the
    number's path as its problem, in the entry and in the light run alike; the batch goes on.
    """
    if scene.skipped:
        return scene.light(), None
    entry = scene_entry(scene, strict)
    runs = list(scene.runs)
    for k, (run, checked) in enumerate(zip(scene.runs, entry["checks"])):
        found = NonFiniteError.find(checked)
        if found is not None:
            runs[k] = CheckRun(run.check, "invalid", (str(found),), problems=(("", str(found)),))
    if runs != list(scene.runs):
        scene = replace(scene, runs=tuple(runs))
        entry = scene_entry(scene, strict)
    return scene.light(), json_text(entry)


def _member(key: str, value) -> str:
    """``"key": value`` as a member of the top-level object of an ``indent=2`` dump."""
    return "\n  " + json_text(key) + ": " + json_text(value).replace("\n", "\n  ")


def stream_check_json(entries: Iterable[tuple[SceneRun, str | None]], strict: bool = False, write=None) -> list[SceneRun]:
    """Write the ``fcalc check`` document (the text of ``json.dumps(check_document(...), indent=2)``)
    while the scenes of ``entries`` (from :func:`json_entry`) come in, holding only their light
    runs, which it returns. Nothing is written when no entry is a scene."""
    write = write or _stdout_write
    scenes: list[SceneRun] = []
    opened = False
    for scene, text in entries:
        scenes.append(scene)
        if text is None:
            continue
        if not opened:
            write("{" + ",".join(_member(k, v) for k, v in _head(strict).items()) + ',\n  "scenes": [')
        write(("," if opened else "") + "\n    " + text.replace("\n", "\n    "))
        opened = True
    if opened:
        write("\n  ]" + "".join("," + _member(k, v) for k, v in _summary(scenes, strict).items()) + "\n}\n")
    return scenes


def _stdout_write(text: str) -> None:
    import sys

    sys.stdout.write(text)


#: Characters XML 1.0 cannot carry at all (control characters, surrogates, U+FFFE/U+FFFF).
_NOT_XML = re.compile("[^\t\n\r\x20-\ud7ff\ue000-\ufffd\U00010000-\U0010ffff]")


def _xml_safe(text: str) -> str:
    return _NOT_XML.sub("\ufffd", text)


def _classname(source: str) -> str:
    path = PurePath(source)
    return ".".join(part for part in path.with_suffix("").parts if part not in ("/", "..", "."))


def junit_xml(scenes: list[SceneRun], strict: bool = False, interrupted: str = "") -> str:
    """The run as JUnit XML text (reasons in SI units). A run stopped early (``interrupted``: why)
    is named so and ends with a suite ``fcalc check`` whose test case ``interrupted`` is an error."""
    root = ET.Element("testsuites", name="fcalc check (interrupted)" if interrupted else "fcalc check")
    totals = Counter()
    if interrupted:
        suite = ET.SubElement(root, "testsuite", name="fcalc check", tests="1", failures="0", errors="1")
        case = ET.SubElement(suite, "testcase", name="interrupted", classname="fcalc.check", time="0")
        ET.SubElement(case, "error", message=interrupted, type="interrupted").text = (
            f"{interrupted}; the other scenes were not checked"
        )
        totals.update(tests=1, errors=1)
    for scene in (scene for scene in scenes if not scene.skipped):
        suite = ET.SubElement(root, "testsuite", name=scene.source)
        tally = Counter()
        for run in scene.runs:
            verdict = _verdict(run, strict)
            case = ET.SubElement(
                suite, "testcase", name=run.check, classname=_classname(scene.source), file=scene.source
            )
            case.set("time", f"{run.seconds:.6f}")
            reason = _reason(run, _SI)
            text = "\n".join((reason, *run.details))
            if verdict == "fail":
                ET.SubElement(case, "failure", message=reason, type="fail").text = text
                tally["failures"] += 1
            elif verdict in ("invalid", "internal"):
                ET.SubElement(case, "error", message=reason, type=verdict).text = reason
                tally["errors"] += 1
            else:
                ET.SubElement(case, "system-out").text = f"{verdict.upper()}: {text}"
            tally["tests"] += 1
        for key in ("tests", "failures", "errors"):
            suite.set(key, str(tally[key]))
        suite.set("time", f"{sum(run.seconds for run in scene.runs):.6f}")
        totals["time"] += sum(run.seconds for run in scene.runs)
        totals.update(tally)
    for key in ("tests", "failures", "errors"):
        root.set(key, str(totals[key]))
    root.set("time", f"{totals['time']:.6f}")
    ET.indent(root)
    for element in root.iter():
        element.text = element.text and _xml_safe(element.text)
        for key, value in element.attrib.items():
            element.set(key, _xml_safe(value))
    return ET.tostring(root, encoding="unicode", xml_declaration=True) + "\n"


def write_junit(path: str | Path, scenes: list[SceneRun], strict: bool = False, interrupted: str = "") -> None:
    """Write :func:`junit_xml` to ``path`` (:mod:`foundation_calc.output.files`: a regular file
    atomically, a FIFO or a device in place); the report of an ``interrupted`` run does not wait
    for a FIFO's reader (the signals that would end the wait are ignored by then)."""
    write_atomically(path, junit_xml(scenes, strict, interrupted), wait=not interrupted)
