"""A calculation sheet as one self-contained, printable HTML file (inline CSS and SVG, no network)."""

from __future__ import annotations

from html import escape as _escape

from foundation_calc.output.report.chain import chain_document
from foundation_calc.output.report.markup import pieces
from foundation_calc.output.report.model import Equation, Figure, Paragraph, Sheet, Table

STYLE = """
body { font-family: "DejaVu Sans", Arial, sans-serif; font-size: 10pt; max-width: 190mm; margin: 1em auto; }
h1 { font-size: 15pt; } h2 { font-size: 12pt; border-bottom: 1px solid #888; margin-top: 1.4em; page-break-after: avoid; }
table { border-collapse: collapse; margin: 0.5em 0 1em; page-break-inside: avoid; }
caption { text-align: left; font-weight: bold; padding-bottom: 0.2em; }
th, td { border: 1px solid #aaa; padding: 2px 6px; vertical-align: top; }
th { background: #eee; } td.n { text-align: right; white-space: nowrap; font-variant-numeric: tabular-nums; }
td { overflow-wrap: break-word; } td.n.w { white-space: normal; } table.long { width: 100%; }
.eq { margin: 0.4em 0; page-break-inside: avoid; } .eq code { font-size: 10pt; } .src { color: #444; } .fix { color: #7a2000; }
figure { margin: 0.5em 0; page-break-inside: avoid; } figure svg { width: 100%; height: auto; }
@page { size: A4; margin: 15mm; }
table.signs { width: 100%; } table.signs td { height: 2.2em; } table.signs td:last-child { width: 45%; }
.header { font-size: 8pt; color: #555; border-bottom: 1px solid #ccc; }
"""


#: The HTML of each piece of :func:`~foundation_calc.output.report.markup.pieces`.
_TAGS = {"super": "<sup>{}</sup>", "sub": "<sub>{}</sub>", "text": "{}"}


def escape(text: str, subscripts: bool = True) -> str:
    """``text`` as HTML text, each exponent ``^{…}`` as a superscript and each subscript (``Z_n``;
    not with ``subscripts=False``, a column of scene keys) as a subscript, escaped like the rest.

    >>> escape("Re(Z_n e^{i nωt}) <b>")
    'Re(Z<sub>n</sub> e<sup>i nωt</sup>) &lt;b&gt;'
    """
    return "".join(_TAGS[kind].format(_escape(p)) for kind, p in pieces(text, subscripts))


#: A numeric cell longer than this may wrap; a table with a text cell longer than LONG_TEXT takes
#: the page's width, so its text columns are not squeezed by the numbers (as in the PDF).
NOWRAP_CHARS = 16
LONG_TEXT = 40


def _cell(text: str, numeric: bool, literal: bool = False) -> str:
    wraps = len(text) > NOWRAP_CHARS or "∠" in text  # a magnitude ∠ phase may break before its phase
    kind = (' class="n w"' if wraps else " class=n") if numeric else ""
    return f"<td{kind}>{escape(text, not literal)}</td>"


def _table(t: Table) -> str:
    head = "".join(f"<th>{escape(h)}</th>" for h in t.header)
    body = "".join("<tr>" + "".join(_cell(c, n, j in t.literal) for j, (c, n) in enumerate(zip(row, t.numeric))) + "</tr>"
                   for row in t.rows)
    caption = f"<caption>{escape(t.title)}</caption>" if t.title else ""
    long = any(len(c) > LONG_TEXT for row in t.rows for c, n in zip(row, t.numeric) if not n)
    wide = ' class="signs"' if t.wide is not None else ' class="long"' if long else ""
    return f"<table{wide}>{caption}<thead><tr>{head}</tr></thead><tbody>{body}</tbody></table>"


def _block(block) -> str:
    if isinstance(block, Paragraph):
        return f"<p>{escape(block.text)}</p>"
    if isinstance(block, Table):
        return _table(block)
    if isinstance(block, Equation):
        fix = f'<br><span class="fix">Correction: {escape(block.correction)}</span>' if block.correction else ""
        return f'<div class="eq"><code>{escape(block.plain)}</code><br><span class="src">{escape(block.source)}</span>{fix}</div>'
    if isinstance(block, Figure):
        return f"<figure>{block.svg}<figcaption>{escape(block.caption)}</figcaption></figure>"
    raise TypeError(type(block).__name__)


def render(sheet: Sheet) -> str:
    """The HTML text of the sheet."""
    parts = [
        "<!DOCTYPE html>",
        '<html lang="en"><head><meta charset="utf-8">',
        f"<title>{_escape(sheet.title)}</title><style>{STYLE}</style></head><body>",
        f'<div class="header">{escape(sheet.header or sheet.title)}</div>',
        f"<h1>{escape(sheet.title)}</h1>",
    ]
    for number, section in enumerate(sheet.sections, 1):
        parts.append(f"<h2>{number}. {escape(section.title)}</h2>")
        parts += [_block(b) for b in section.blocks]
    if sheet.chain:  # kept beside the sheet for a checker's tool (no "<" in it: it cannot close the script)
        parts.append(f'<script type="application/json" id="fcalc-chain">{chain_document(sheet.chain)}</script>')
    parts.append("</body></html>")
    return "\n".join(parts)
