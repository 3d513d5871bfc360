"""``fc.report``: a calculation sheet of a scene to file (``fcalc report``)."""

from __future__ import annotations

import os
from collections.abc import Mapping
from dataclasses import dataclass, field
from pathlib import Path

from foundation_calc.api.result import Result, worst
from foundation_calc.api.scene import Scene, scene_of

#: Units of a sheet's tables unless ``units`` names others: amplitudes in mm, velocities in mm/s
#: (the vibration codes' zones are in mm/s); speeds in rad/s with Hz beside them.
SHEET_UNITS = ("mm", "mm/s")


def chosen_amplitude(tokens: list[str] | None) -> bool:
    """True when ``--units`` names the displacement unit (else the sheet fits it to the scene)."""
    from foundation_calc.output.display_units import named_quantities

    return "amplitude" in named_quantities(tokens or [])


@dataclass(frozen=True, eq=False)
class SheetResult(Result):
    """A :class:`~foundation_calc.api.result.Result` of ``report``: ``files`` are the files written
    (the sheet, and a Markdown sheet's figures beside it); ``report`` is the sheet itself."""

    files: tuple[Path, ...] = field(default=())


def check_output(path: Path, hint: str) -> None:
    """Raise a usage error when ``path`` has no sheet format or the report extra is missing."""
    from foundation_calc.errors import UsageError
    from foundation_calc.output.report import FORMATS, INSTALL_HINT, missing_packages

    if path.suffix.lower() not in FORMATS:
        raise UsageError(f"{path}: the file must end in .pdf, .html or .md", hint)
    missing = missing_packages(path.suffix.lower())
    if missing:
        raise UsageError(f"{', '.join(missing)} not installed: {INSTALL_HINT}", hint)


def sheet_sizing(path: Path, vary: list[str], step: float | None) -> tuple[dict, int]:
    """What a sheet prints of ``fcalc design`` (:mod:`foundation_calc.output.report.sizing`): the
    ``--json`` document and exit code of sizing the scene at ``path`` over ``vary`` by ``step`` [m];
    a range design cannot search is the scene's ``report.design`` error (exit 3)."""
    from foundation_calc.api.design import design
    from foundation_calc.errors import SceneError, UsageError
    from foundation_calc.output.report.sizing import FIELD

    try:
        found = design(path, vary=vary, step=step)
    except UsageError as exc:
        raise SceneError(str(path), [(FIELD, str(exc))]) from None
    return found.to_dict(), int(found.exit_code)


def report(scene, *, output: str | os.PathLike | None = None, exact: bool = False, units: list[str] | None = None,
           validation: bool = False, command: str | None = None) -> SheetResult:
    """Write the calculation sheet of a scene: the verdict of every check ``fc.check`` runs on it,
    inputs, derived quantities, the equations with their sources, every check's rows and plots.

    Parameters
    ----------
    scene : Scene or path
        A scene of any kind, given as a file (the sheet names the file and its SHA-256).
    output : str or os.PathLike, optional
        ``-o``: ``FILE.pdf``, ``FILE.html`` or ``FILE.md``; default: the scene's file with ``.pdf``.
    exact : bool
        ``--exact``: a crank scene's sheet also states the closed forms' errors against the exact
        solution.
    units : list of str, optional
        ``--units``: units of the sheet's tables, e.g. ``["mm,rpm"]`` (default mm and mm/s).
    validation : bool
        ``--validation``: append the validation record of ``fcalc validate``.
    command : str, optional
        What the title block says made the sheet; default ``foundation_calc.report(<scene>)``.

    Returns
    -------
    SheetResult
        ``to_dict()`` is the scene's entry of ``fcalc check --json`` (the sheet shows these very
        checks), ``exit_code`` that of ``fcalc report`` (``fcalc check``'s, warnings passing);
        ``files`` the files written.

    Raises
    ------
    SceneError
        An invalid scene, or a check that cannot judge it.
    UsageError
        A scene given as a mapping, an output without a sheet format, or the report extra missing.
    """
    import json
    from dataclasses import replace

    from foundation_calc.api.options import display_units, writable_path, writing
    from foundation_calc.errors import UsageError
    from foundation_calc.output.check_report import json_entry
    from foundation_calc.output.report import write_sheet
    from foundation_calc.output.report.documents import scene_sheet

    file = None if isinstance(scene, Mapping) else scene.path if isinstance(scene, Scene) else Path(scene)
    if file is None:
        raise UsageError("a calculation sheet is made of a scene file (it names the file and its SHA-256)", "SCENE")
    path = Path(output) if output is not None else file.with_suffix(".pdf")
    check_output(path, "'-o'")
    writable_path(path, "-o")
    shown = display_units(units, SHEET_UNITS)
    loaded = scene_of(scene)
    sheet, checked = scene_sheet(loaded.path, command or f"foundation_calc.report({loaded.source!r})", shown, exact,
                                 fit_units=not chosen_amplitude(units), size=sheet_sizing)
    if validation:
        from foundation_calc.output.report.validation import validation_section
        from foundation_calc.validation.cases import run_record

        sheet = replace(sheet, sections=(*sheet.sections, validation_section(run_record())))
    with writing(path, "-o"):
        written = write_sheet(sheet, path)
    entry = json.loads(json_entry(checked)[1])
    verdict = worst(c["verdict"] for c in entry["checks"])
    return SheetResult("report", entry, int(checked.exit_code(strict=False)), verdict, loaded, sheet, files=tuple(written))
