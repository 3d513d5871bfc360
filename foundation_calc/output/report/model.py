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
    column that takes the page's free width (a signature box); ``literal`` the columns of scene keys,
    printed as typed (``c_z``, no subscript: :mod:`~foundation_calc.output.report.markup`)."""

    title: str
    header: tuple[str, ...]
    rows: tuple[tuple[str, ...], ...]
    numeric: tuple[bool, ...]
    wide: int | None = None
    literal: tuple[int, ...] = ()


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
class Cell:
    """Where a number is printed: the table whose title starts with ``table`` (the untitled table of
    the section titled ``section`` when ``table`` is empty), the row whose first cells are ``row``,
    the column headed ``column``; the ``index``-th number of the cell's text after ``after``."""

    table: str
    row: tuple[str, ...]
    column: str
    section: str = ""
    after: str = ""
    index: int = 0


@dataclass(frozen=True)
class Link:
    """A judged number as data: the number printed at ``result`` is ``formula`` (a name of
    :data:`foundation_calc.output.report.chain.FORMULAS`) of the numbers printed at ``inputs``
    (symbol, cell), so a checker (and a test) recomputes it from the sheet alone."""

    formula: str
    result: Cell
    inputs: tuple[tuple[str, Cell], ...]


@dataclass(frozen=True)
class Section:
    """A numbered section of the sheet; ``links``: the chains of the judged numbers it prints."""

    title: str
    blocks: tuple[Block, ...]
    links: tuple[Link, ...] = ()


@dataclass(frozen=True)
class Sheet:
    """The whole calculation sheet; ``header`` runs on every page before "page n of N"."""

    title: str
    sections: tuple[Section, ...] = field(default_factory=tuple)
    header: str = ""

    @property
    def chain(self) -> tuple[Link, ...]:
        """Every judged number's link, in the order of the sections."""
        return tuple(link for section in self.sections for link in section.links)


def table(title: str, header: tuple[str, ...], rows, numeric: tuple[bool, ...] | None = None, wide: int | None = None,
          literal: tuple[int, ...] = ()) -> Table:
    """A :class:`Table`; by default every column but the first is numeric."""
    rows = tuple(tuple(row) for row in rows)
    if numeric is None:
        numeric = (False,) + (True,) * (len(header) - 1)
    return Table(title, tuple(header), rows, tuple(numeric), wide, tuple(literal))
