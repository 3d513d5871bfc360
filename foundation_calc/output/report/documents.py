"""Run the checks of one scene, as ``fcalc check`` does, and make its sheet from what they judged."""

from __future__ import annotations

from pathlib import Path

from foundation_calc.output.display_units import DisplayUnits
from foundation_calc.output.report.contents import crank_sections, operating_speed, platform_sections, sweep_series
from foundation_calc.output.report.assumptions import assumptions_section
from foundation_calc.output.report.conclusion import conclusion_section, not_real_note
from foundation_calc.output.report.inputs import inputs_section
from foundation_calc.output.report.methods import methods_section
from foundation_calc.output.report.model import Section, Sheet
from foundation_calc.output.report.references import cited, references_section
from foundation_calc.output.report.sizing import Size, design_request, sizing_blocks
from foundation_calc.output.report.title import page_header, sheet_title, title_block, title_section
from foundation_calc.output.report.verdict import checks_section, scene_verdict, summary_section

#: A sheet whose displacement limits are all below this [m] shows displacements in µm, not mm, so
#: its values and limits print as 1.35 µm ≤ 50.0 µm rather than 1.35·10⁻³ mm ≤ 0.0500 mm.
MICROMETRES_BELOW = 1e-4


def fitted_units(loaded, units: DisplayUnits) -> DisplayUnits:
    """``units`` with displacements in µm when the scene limits them below :data:`MICROMETRES_BELOW`
    (every displacement limit it gives) and the sheet's unit is mm."""
    from dataclasses import replace

    given = [v for v in (getattr(loaded.limits, k, None) for k in ("amplitude", "transient_amplitude")) if v is not None]
    small = bool(given) and max(given) < MICROMETRES_BELOW
    return replace(units, amplitude="µm") if small and units.amplitude == "mm" else units


#: Points of the sheet's crank sweep plot (its range: :func:`~.figures.sweep_factors`).
SWEEP_POINTS = 1001


def sweep_figure_of(loaded, units: DisplayUnits, omega: float, resonances: list[dict]):
    """The crank speed sweep plot of a crank scene (peaks of C, limits, detuning bands), over a
    range that shows every judged resonance of ``resonances`` (the resonance document's rows); on a
    support coupling sway with rocking, the averaged operator's peaks with the support at each
    harmonic's frequency, as ``fcalc sweep`` gives them."""
    import numpy as np

    from foundation_calc.checks.amplitudes.approximations import scene_vendor_loads
    from foundation_calc.checks.sweep.crank import scene_dynamic_soil, sweep
    from foundation_calc.output.report.figures import sweep_factors, sweep_figure
    from foundation_calc.output.sweep import sweep_document

    design = None if loaded.mechanism is None else loaded.design()
    omegas = loaded.speed.omega_rad_s * np.linspace(*sweep_factors(omega, resonances), SWEEP_POINTS)
    points = [(p.name, p.horizontal, p.height) for p in loaded.points]
    coupled = design is not None and design.coupled  # the one model, its support at each harmonic's frequency
    swept = sweep(design, "omega", omegas, loaded.limits, loaded.limits.detuning, points, scene_vendor_loads(loaded),
                  scene_dynamic_soil(loaded) if coupled else None)
    return sweep_figure(sweep_series(sweep_document(swept, loaded, "")), omega, units)


def exact_amplitudes(loaded) -> dict | None:
    """The ``amplitudes`` document with the exact periodic solution (``--exact``), for the
    accuracy statement; None for a machine given by its loads (already exact)."""
    if loaded.kind != "crank_foundation" or loaded.mechanism is None:
        return None
    from foundation_calc.checks.amplitudes.approximations import check_scene_amplitudes
    from foundation_calc.output.amplitudes import amplitudes_document

    return amplitudes_document(check_scene_amplitudes(loaded, exact=True), loaded, "")


def raise_unjudged(runs, source: str) -> None:
    """Raise as the single-scene commands would when a check could not judge the scene: a
    :class:`SceneError` for an invalid scene (exit 3), ``RuntimeError`` for a bug (exit 4)."""
    from foundation_calc.errors import SceneError

    for run in runs:
        if run.verdict == "invalid":
            raise SceneError(source, list(run.problems))
        if run.verdict == "internal":
            raise RuntimeError(f"check {run.check}: {run.problems[0][1]}")


def unbracketed(loaded) -> bool:
    """True for a scene on soil that does not bracket it (no ``[soil] modulus_range``)."""
    soil = getattr(loaded, "soil", None)
    return soil is not None and getattr(soil, "modulus_range", None) is None


def _platform_sections(loaded, documents: dict, units: DisplayUnits, exact: bool, figures: bool) -> tuple[Section, ...]:
    from foundation_calc.output.report.figures import platform_modes_figure

    plots = (platform_modes_figure(documents["design"], loaded.limits.detuning, units),) if figures else ()
    return platform_sections(documents, units, plots)


def _block_sections(loaded, documents: dict, units: DisplayUnits, exact: bool, figures: bool) -> tuple[Section, ...]:
    from foundation_calc.output.report.block_accuracy import block_accuracy_section

    plots = ()
    if figures:
        from foundation_calc.output.report.figures import block_sweep_figures

        plots = (Section("Plots", block_sweep_figures(loaded, units, documents["resonance"])),)
    return (*plots, block_accuracy_section(loaded, documents.get("amplitudes", {}).get("periodic_inertia")))


def _crank_sections(loaded, documents: dict, units: DisplayUnits, exact: bool, figures: bool) -> tuple[Section, ...]:
    resonance = documents["resonance"]
    plots = (sweep_figure_of(loaded, units, operating_speed(resonance), resonance["resonances"]),) if figures else ()
    return crank_sections(documents, plots, units, exact_amplitudes(loaded) if exact else None)


#: Each scene kind's own sections besides its checks: the check documents they read, and their
#: maker (loaded scene, documents, units, --exact, figures) -> sections.
KIND_SECTIONS = {
    "platform": ({"design"}, _platform_sections),
    "block_foundation": ({"resonance"}, _block_sections),
    "crank_foundation": ({"resonance", "amplitudes"}, _crank_sections),
}


def _kind_sections(loaded, documents: dict, units: DisplayUnits, exact: bool, figures: bool) -> tuple[Section, ...]:
    """What a scene kind shows besides its checks (:data:`KIND_SECTIONS`; nothing for a kind
    without its own sections, or when a document they read is missing)."""
    needs, sections = KIND_SECTIONS.get(loaded.kind, (None, None))
    if sections is None or not needs <= documents.keys():
        return ()
    return sections(loaded, documents, units, exact, figures)


def scene_sheet(path: Path, command: str, units: DisplayUnits, exact: bool = False, figures: bool = True,
                fit_units: bool = False, size: Size | None = None):
    """Load the scene at ``path``, run the checks ``fcalc check`` runs on it and return its sheet
    and the :class:`~foundation_calc.checks.batch.SceneRun` (whose exit code is ``fcalc check``'s);
    ``figures=False`` leaves the plots out (matplotlib's part of the time); ``fit_units``: the
    displacement unit was not chosen (:func:`fitted_units`); ``size`` sizes a failing scene that
    asks for it in ``[report] design`` (:mod:`~foundation_calc.output.report.sizing`; without it
    the sheet prints no sizing)."""
    from foundation_calc.checks.batch import SceneRun, run_checks
    from foundation_calc.output.check_report import result_document
    from foundation_calc.scenes.loading import load_scene_as_written

    source = str(path)
    loaded, written = load_scene_as_written(path)
    units = fitted_units(loaded, units) if fit_units else units
    runs = run_checks(loaded)
    raise_unjudged(runs, source)
    request = design_request(loaded, source)
    sizing = ()
    if request is not None and size is not None and scene_verdict(runs) == "fail":
        sizing = tuple(sizing_blocks(*size(path, *request)))
    warnings = tuple(loaded.plausibility_warnings())
    scene_run = SceneRun(source, loaded.kind, loaded.name, runs, loaded, warnings=warnings)
    documents = {run.check: result_document(run.check, run.report, loaded) for run in runs}
    title = title_block(path, loaded, command)
    note = not_real_note(path.read_text(encoding="utf-8", errors="replace"))
    sections = [title_section(title, note), summary_section(runs, warnings, units),
                conclusion_section(runs, documents, units, note, unbracketed(loaded), sizing), inputs_section(loaded, units, written),
                assumptions_section(loaded, runs)]
    sections += _kind_sections(loaded, documents, units, exact, figures)
    methods = methods_section(loaded, documents, units)
    sections += [methods] if methods is not None else []
    if "runup" in documents:
        from foundation_calc.output.report.runup_section import runup_section

        report = next(run.report for run in runs if run.check == "runup")
        sections.append(runup_section(documents["runup"], report, loaded, units, figures))
    from foundation_calc.output.report.validity_section import validity_section

    validity = validity_section(loaded, documents)
    sections += [validity] if validity is not None else []
    sections.append(checks_section(runs, documents, loaded, units))
    if cited(sections):  # a sheet that cites nothing has no empty References table
        sections.append(references_section(sections))
    return Sheet(sheet_title(title), tuple(sections), page_header(title)), scene_run
