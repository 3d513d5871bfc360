"""A calculation sheet as PDF, typeset by typst (the ``typst`` package ships its compiler).

The typst source is written in code mode: every piece of user text is a typst string literal,
so no scene or point name is ever read as markup; only the equations are typst math.
"""

from __future__ import annotations

import math
import tempfile
from pathlib import Path

from foundation_calc.output.report.chain import chain_document
from foundation_calc.output.report.markup import pieces
from foundation_calc.output.report.model import Equation, Figure, Paragraph, Sheet, Table

PREAMBLE = """#set text(size: 9pt)
#set par(justify: false)
#set heading(numbering: "1.")
#show table.cell.where(y: 0): strong
"""

#: A table with a text cell longer than this wraps its text columns longer than SHORT_CHARS.
WRAP_CHARS = 40
SHORT_CHARS = 24

#: Tables longer than this (rows, or characters of text) may break across pages, their header
#: repeated; shorter ones (up to half a page of one-line rows) stay whole and move to the next page
#: rather than leave a row or two behind. A table taller than a page must break or it runs off the page.
UNBREAKABLE_ROWS = 24
UNBREAKABLE_CHARS = 2500

#: A table that may break starts on a new page when less than this is left of the page (its title,
#: header and three rows), so no title or lone first row is left at the foot of a page: an empty
#: unbreakable block this tall goes first (to the next page when it does not fit) and the space it
#: took is given back.
ORPHAN_SPACE = "3.2cm"


def string(text: str) -> str:
    """``text`` as a typst string literal."""
    escaped = text.replace("\\", "\\\\").replace('"', '\\"').replace("\n", "\\n").replace("\r", "\\r")
    return f'"{escaped}"'


#: How each piece of :func:`~foundation_calc.output.report.markup.pieces` is set.
_SET = {"super": "super({})", "sub": "sub({})", "text": "{}"}


def text(plain: str, subscripts: bool = True) -> str:
    """``plain`` as typst: a string literal, with each exponent ``^{…}`` set as a superscript and
    each subscript (``Z_n``; not with ``subscripts=False``, a column of scene keys) as a subscript,
    still from string literals only (:mod:`~foundation_calc.output.report.markup`).

    >>> text("Re(Z_n e^{i nωt})")
    '{ "Re(Z"; sub("n"); " e"; super("i nωt"); ")" }'
    >>> text("c_z", subscripts=False)
    '"c_z"'
    """
    parts = pieces(plain, subscripts)
    if len(parts) <= 1 and (not parts or parts[0][0] == "text"):
        return string(plain)
    return "{ " + "; ".join(_SET[kind].format(string(p)) for kind, p in parts) + " }"


def _table(t: Table) -> str:
    align = ", ".join("right" if n else "left" for n in t.numeric)
    cells = [text(h) for h in t.header] + [text(c, j not in t.literal) for row in t.rows for j, c in enumerate(row)]
    columns = ", ".join(["auto"] * len(t.header))
    width = [max((len(row[j]) for row in t.rows), default=0) for j in range(len(t.header))]
    if t.wide is not None:  # the sign boxes: the signature column takes the free width
        columns = ", ".join("1fr" if j == t.wide else "auto" for j in range(len(t.header)))
    elif max((width[j] for j in range(len(t.header)) if not t.numeric[j]), default=0) > WRAP_CHARS:
        # long text wraps: every text column longer than SHORT_CHARS shares the free width in
        # proportion to the geometric mean of its mean and longest cells (a hand calculation's
        # formula and values both), so a long item column is not squeezed by a source printed
        # once and "as above" below it
        mean = [sum(len(row[j]) for row in t.rows) / max(len(t.rows), 1) for j in range(len(t.header))]
        shares = [min(math.ceil(math.sqrt(mean[j] * width[j])), WRAP_CHARS * 2) if not t.numeric[j] and width[j] > SHORT_CHARS else 0
                  for j in range(len(t.header))]
        columns = ", ".join(f"{share}fr" if share else "auto" for share in shares)
    inset = "8pt" if t.wide is not None else "2.5pt"  # a sign box is tall enough to sign in
    body = (
        f"table(columns: ({columns},), align: ({align},), inset: (x: 4pt, y: {inset}),"
        f" stroke: 0.4pt + gray, table.header({', '.join(cells[:len(t.header)])}), {', '.join(cells[len(t.header):])})"
    )
    title = f"strong({text(t.title)}), " if t.title else ""
    long = len(t.rows) > UNBREAKABLE_ROWS or sum(map(len, (c for row in t.rows for c in row))) > UNBREAKABLE_CHARS
    if not long:
        return f"#block(breakable: false, width: 100%, stack(spacing: 4pt, {title}{body}))\n"
    guard = f"#block(breakable: false, height: {ORPHAN_SPACE}, width: 100%)\n#v(-{ORPHAN_SPACE}, weak: false)\n"
    return f"{guard}#block(breakable: true, width: 100%, stack(spacing: 4pt, {title}{body}))\n"


def _block(block, figures: list[str]) -> str:
    if isinstance(block, Paragraph):
        return f"#par({text(block.text)})\n"
    if isinstance(block, Table):
        return _table(block)
    if isinstance(block, Equation):
        fix = f" #text(fill: rgb(\"#7a2000\"), {string('Correction: ' + block.correction)})" if block.correction else ""
        return f"#block(breakable: false)[$ {block.typst} $ #text(size: 8pt)[#{string(block.source)}]{fix}]\n"
    if isinstance(block, Figure):
        name = f"figure{len(figures) + 1}.svg"
        figures.append(block.svg)
        return f"#figure(image({string(name)}, width: 100%), caption: {text(block.caption)})\n"
    raise TypeError(type(block).__name__)


def _page(header: str) -> str:
    """A4 pages headed "``header`` · page n of N"."""
    return (
        '#set page(paper: "a4", margin: (x: 1.6cm, y: 1.8cm), header: context {'
        f" set text(size: 8pt, fill: luma(80)); {text(header + ' · page ')} + str(counter(page).get().first())"
        ' + " of " + str(counter(page).final().first()) })\n'
    )


def source(sheet: Sheet) -> tuple[str, list[str]]:
    """The typst source of the sheet and the SVG texts of its figures (``figureN.svg``)."""
    figures: list[str] = []
    parts = [_page(sheet.header or sheet.title), PREAMBLE, f"#align(center, text(size: 14pt, weight: \"bold\", {text(sheet.title)}))\n"]
    for section in sheet.sections:
        parts.append(f"#heading(level: 1, {string(section.title)})\n")
        parts += [_block(b, figures) for b in section.blocks]
    if sheet.chain:  # kept in the source for a checker's tool: typst query sheet.typ "<fcalc-chain>"
        parts.append(f"#metadata({string(chain_document(sheet.chain))}) <fcalc-chain>\n")
    return "".join(parts), figures


def render(sheet: Sheet) -> bytes:
    """The PDF bytes of the sheet."""
    import typst

    text, figures = source(sheet)
    with tempfile.TemporaryDirectory(prefix="fcalc-report-") as folder:
        root = Path(folder)
        (root / "sheet.typ").write_text(text, encoding="utf-8")
        for number, svg in enumerate(figures, 1):
            (root / f"figure{number}.svg").write_text(svg, encoding="utf-8")
        return typst.compile(str(root / "sheet.typ"), root=str(root), format="pdf")
