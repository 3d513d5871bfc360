"""Shared fixtures: the shipped configs, a CLI runner, scene documents to break."""

from __future__ import annotations

import copy
import os
import subprocess
from pathlib import Path

from foundation_calc.cli.app import BLAS_THREAD_VARIABLES

for _variable in BLAS_THREAD_VARIABLES:  # one thread, as fcalc's main() runs (before numpy is imported)
    os.environ.setdefault(_variable, "1")

import pytest  # noqa: E402
from typer.testing import CliRunner  # noqa: E402

from foundation_calc.scenes import read_toml  # noqa: E402

ROOT = Path(__file__).resolve().parents[1]
CONFIGS = ROOT / "configs"


def configs_of_kind(kind: str) -> list[Path]:
    """Every file in configs/ whose ``kind`` is ``kind``."""
    return sorted(p for p in CONFIGS.glob("*.toml") if read_toml(p).get("kind") == kind)


def mechanism_configs() -> list[Path]:
    """The crank_foundation files in configs/ with a [mechanism] (not a machine given by its loads only)."""
    return [p for p in configs_of_kind("crank_foundation") if "mechanism" in read_toml(p)]


def crank_on_piles(path: Path) -> bool:
    """Whether ``path`` is a crank scene on [piles], whose sway-rocking coupling the paper's closed forms
    do not take: every command reads the plane's one model with the group's K_xφ, C_xφ (the averaged
    operator; tests/test_crank_piles*.py), the first approximation is listed as not applicable."""
    data = read_toml(path)
    return data.get("kind") == "crank_foundation" and "piles" in data


def closed_form_configs() -> list[Path]:
    """:func:`mechanism_configs` on a footing, where the paper's closed forms apply (:func:`crank_on_piles`)."""
    return [p for p in mechanism_configs() if not crank_on_piles(p)]


def sheet_configs() -> list[Path]:
    """Every shipped scene whose calculation sheet fcalc report makes (all but :func:`crank_on_piles`)."""
    return [p for p in sorted(CONFIGS.glob("*.toml")) if not crank_on_piles(p)]


def on_terminal(args, **streams) -> tuple[subprocess.Popen, str]:
    """Run ``args`` with its stdout on a new pseudo-terminal (and stderr too, unless ``streams``
    names it); the finished process and what the terminal showed, lines ending in ``\\n``."""
    pty = pytest.importorskip("pty")
    main, child = pty.openpty()
    streams = {"stderr": child, **streams}
    process = subprocess.Popen(args, stdout=child, **streams)
    os.close(child)
    chunks = []
    while True:
        try:
            chunk = os.read(main, 65536)
        except OSError:  # the child closed the terminal
            break
        if not chunk:
            break
        chunks.append(chunk)
    os.close(main)
    process.wait()
    return process, b"".join(chunks).decode("utf-8").replace("\r\n", "\n")


def only_input_warnings(stderr: str, config: Path) -> bool:
    """True when ``stderr`` holds nothing but the plausibility warnings of the scene ``config``
    (every shipped scene has none but the contrived soft soil of frame_saw_soft_soil_runup.toml)."""
    from foundation_calc.scenes import parse_scene

    expected = parse_scene(read_toml(config), source=str(config)).plausibility_warnings()
    lines = [line for line in stderr.splitlines() if line.strip()]
    return all(line.startswith("warning: ") and any(line.endswith(w) for w in expected) for line in lines)


@pytest.fixture
def runner() -> CliRunner:
    return CliRunner()


@pytest.fixture
def frame_saw() -> dict:
    """A fresh copy of configs/frame_saw_extra_resonance.toml as a dict, to modify in a test."""
    return copy.deepcopy(read_toml(CONFIGS / "frame_saw_extra_resonance.toml"))


@pytest.fixture(scope="session")
def shipped_sheets() -> dict:
    """Each shipped scene's calculation sheet, made once for the session as ``fcalc report`` makes
    it (its plots left out: no judged number is read from a plot) and written in every format:
    ``{name: {"sheet": Sheet, "md": text, "html": text, "typ": the PDF's typst source}}``."""
    import warnings

    from foundation_calc.api.options import display_units
    from foundation_calc.api.report import SHEET_UNITS, sheet_sizing
    from foundation_calc.output.report import html, markdown, pdf
    from foundation_calc.output.report.documents import scene_sheet

    units = display_units(None, SHEET_UNITS)
    out = {}
    for path in sheet_configs():
        with warnings.catch_warnings():
            warnings.simplefilter("ignore")  # the plausibility warnings some shipped scenes carry
            sheet, _ = scene_sheet(path, "fcalc report", units, figures=False, fit_units=True, size=sheet_sizing)
        out[path.stem] = {"sheet": sheet, "md": markdown.render(sheet, []), "html": html.render(sheet),
                          "typ": pdf.source(sheet)[0]}
    return out
