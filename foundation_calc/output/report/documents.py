"""Run the checks of one scene and make the sheet: the same result documents as ``--json``."""

from __future__ import annotations

import hashlib
from datetime import datetime, timezone
from pathlib import Path

from foundation_calc import __version__
from foundation_calc.output.display_units import DisplayUnits
from foundation_calc.output.report.contents import (
    TitleBlock,
    crank_sheet,
    operating_speed,
    platform_sheet,
    sweep_series,
)
from foundation_calc.output.report.inputs import inputs_section
from foundation_calc.output.report.model import Sheet

#: Speed range of the sheet's sweep plot, as factors on the operating speed, and its points.
SWEEP_RANGE = (0.05, 2.5)
SWEEP_POINTS = 1001


def title_block(path: Path, name: str, command: str) -> TitleBlock:
    """The title block of a sheet for the scene file at ``path``."""
    digest = hashlib.sha256(path.read_bytes()).hexdigest()
    date = datetime.now(timezone.utc).strftime("%Y-%m-%d %H:%M:%S")
    return TitleBlock(name or path.name, str(path), digest, __version__, date, command)


def crank_documents(loaded, source: str, exact: bool) -> dict:
    """The ``resonance``, ``amplitudes`` and speed-``sweep`` JSON documents of a crank scene."""
    import numpy as np

    from foundation_calc.checks.crank_amplitudes import check_scene_amplitudes, scene_vendor_loads
    from foundation_calc.checks.crank_resonance import check_scene_resonances
    from foundation_calc.checks.crank_sweep import sweep
    from foundation_calc.output.crank_amplitudes import amplitudes_document
    from foundation_calc.output.crank_resonance import resonance_document
    from foundation_calc.output.sweep_report import sweep_document

    resonance = check_scene_resonances(loaded)
    amplitudes = check_scene_amplitudes(loaded, exact=exact)
    design = None if loaded.mechanism is None else loaded.design()
    omegas = loaded.speed.omega_rad_s * np.linspace(*SWEEP_RANGE, SWEEP_POINTS)
    points = [(p.name, p.horizontal, p.height) for p in loaded.points]
    swept = sweep(design, "omega", omegas, loaded.limits, loaded.limits.detuning, points, scene_vendor_loads(loaded))
    return {
        "resonance": resonance_document(resonance, loaded, source),
        "amplitudes": amplitudes_document(amplitudes, loaded, source),
        "sweep": sweep_document(swept, source, loaded.name, loaded.plausibility_warnings()),
    }


def platform_documents(loaded, source: str) -> dict:
    """The ``platform`` JSON document of a platform scene."""
    from foundation_calc.checks.platform import check_platform
    from foundation_calc.output.platform import platform_document

    report = check_platform(loaded.design(), loaded.model(), loaded.limits, loaded.inertia_given)
    return {"platform": platform_document(report, loaded, source, loaded.operation.speed_given_as)}


def scene_sheet(path: Path, command: str, units: DisplayUnits, exact: bool = False) -> tuple[Sheet, dict]:
    """Load the scene at ``path``, run its checks and return its sheet and the JSON documents."""
    from foundation_calc.scenes import parse_scene, read_toml

    loaded = parse_scene(read_toml(path), source=str(path))
    title = title_block(path, loaded.name, command)
    inputs = inputs_section(loaded, units)
    if loaded.kind == "platform":
        docs = platform_documents(loaded, str(path))
        return platform_sheet(title, inputs, docs["platform"], loaded.limits.model_dump(), units), docs
    from foundation_calc.output.report.figures import sweep_figure

    docs = crank_documents(loaded, str(path), exact)
    figure = sweep_figure(sweep_series(docs["sweep"]), operating_speed(docs["resonance"]), units)
    return crank_sheet(title, inputs, docs["resonance"], docs["amplitudes"], (figure,), units), docs
