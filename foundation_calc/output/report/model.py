"""The calculation sheet as a format-neutral document: sections of text, tables, equations, figures.

Every string in it is plain text (scene and point names included); the writers for PDF (typst),
HTML and Markdown escape it, so no user text is ever read as markup.
"""

from __future__ import annotations

from dataclasses import dataclass, field


@dataclass(frozen=True)
class Paragraph:
    """A paragraph of plain text."""

    text: str


@dataclass(frozen=True)
class Table:
    """A table of plain-text cells; ``numeric`` marks the right-aligned columns; ``wide`` names a
    column that takes the page's free width (a signature box)."""

    title: str
    header: tuple[str, ...]
    rows: tuple[tuple[str, ...], ...]
    numeric: tuple[bool, ...]
    wide: int | None = None


@dataclass(frozen=True)
class Equation:
    """An equation used by the sheet: typst math, a plain-text form, its source and any correction."""

    typst: str
    plain: str
    source: str
    correction: str = ""


@dataclass(frozen=True)
class Figure:
    """A plot as a self-contained SVG document."""

    svg: str
    caption: str


Block = Paragraph | Table | Equation | Figure


@dataclass(frozen=True)
class Section:
    """A numbered section of the sheet."""

    title: str
    blocks: tuple[Block, ...]


@dataclass(frozen=True)
class Sheet:
    """The whole calculation sheet; ``header`` runs on every page before "page n of N"."""

    title: str
    sections: tuple[Section, ...] = field(default_factory=tuple)
    header: str = ""


def table(title: str, header: tuple[str, ...], rows, numeric: tuple[bool, ...] | None = None, wide: int | None = None) -> Table:
    """A :class:`Table`; by default every column but the first is numeric."""
    rows = tuple(tuple(row) for row in rows)
    if numeric is None:
        numeric = (False,) + (True,) * (len(header) - 1)
    return Table(title, tuple(header), rows, tuple(numeric), wide)
