"""Calculation sheets (``fcalc report``): PDF via typst, self-contained HTML, Markdown.

The sheet is built once as a format-neutral :class:`~foundation_calc.output.report.model.Sheet`
from the JSON documents of the single-scene commands; one module per format writes it. typst
and matplotlib (the ``report`` extra) are imported only when a sheet is made.
"""

from __future__ import annotations

import importlib.util
from pathlib import Path

#: File suffix -> format name.
FORMATS = {".pdf": "pdf", ".html": "html", ".htm": "html", ".md": "markdown"}

INSTALL_HINT = 'install the report extra: python3 -m pip install "foundation_calc[report]" (typst, matplotlib)'


def missing_packages(suffix: str) -> list[str]:
    """The packages of the report extra that a sheet in format ``suffix`` needs and are not installed."""
    needed = ["matplotlib"] + (["typst"] if FORMATS.get(suffix) == "pdf" else [])
    return [name for name in needed if importlib.util.find_spec(name) is None]


def write_sheet(sheet, path: Path) -> list[Path]:
    """Write ``sheet`` to ``path`` in the format its suffix names; returns every file written.

    A Markdown sheet's plots go beside it as ``<stem>-figureN.svg``. Every file is written by
    the rule of :mod:`foundation_calc.output.files`.
    """
    from foundation_calc.output.files import write_atomically

    kind = FORMATS[path.suffix.lower()]
    if kind == "html":
        from foundation_calc.output.report import html

        write_atomically(path, html.render(sheet))
        return [path]
    if kind == "markdown":
        from foundation_calc.output.report import markdown
        from foundation_calc.output.report.model import Figure

        svgs = [b.svg for s in sheet.sections for b in s.blocks if isinstance(b, Figure)]
        names = [f"{path.stem}-figure{n}.svg" for n in range(1, len(svgs) + 1)]
        for name, svg in zip(names, svgs):
            write_atomically(path.parent / name, svg)
        write_atomically(path, markdown.render(sheet, names))
        return [path, *(path.parent / name for name in names)]
    from foundation_calc.output.report import pdf

    write_atomically(path, pdf.render(sheet))
    return [path]
