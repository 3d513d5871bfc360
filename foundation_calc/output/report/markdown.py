"""A calculation sheet as Markdown; user text is escaped so it never turns into markup."""

from __future__ import annotations

import re

from foundation_calc.output.report.chain import chain_document
from foundation_calc.output.report.model import Equation, Figure, Paragraph, Sheet, Table

#: Characters that can start markup anywhere in a line. Every block starts with fcalc's own text or
#: "|", so the line-start-only markers (``-``, ``1.``, ``>``) need no escape.
_SPECIAL = re.compile(r"([\\`*_{}\[\]#+!|$~^])")


def escape(text: str) -> str:
    """``text`` as literal Markdown: markup characters backslash-escaped, ``< > &`` as entities.

    >>> print(escape("a_b *c* [d](e) <f>"))
    a\\_b \\*c\\* \\[d\\](e) &lt;f&gt;
    """
    text = text.replace("&", "&amp;").replace("<", "&lt;").replace(">", "&gt;")
    return _SPECIAL.sub(r"\\\1", text).replace("\n", " ")


def _table(t: Table) -> list[str]:
    lines = [f"**{escape(t.title)}**", ""] if t.title else []
    lines.append("| " + " | ".join(map(escape, t.header)) + " |")
    lines.append("|" + "|".join(" ---: " if n else " --- " for n in t.numeric) + "|")
    lines += ["| " + " | ".join(map(escape, row)) + " |" for row in t.rows]
    return lines + [""]


def render(sheet: Sheet, figure_names: list[str]) -> str:
    """The Markdown text; figures are referenced as the SVG files ``figure_names`` (in order)."""
    lines = [escape(sheet.header or sheet.title), "", f"# {escape(sheet.title)}", ""]
    figures = iter(figure_names)
    for number, section in enumerate(sheet.sections, 1):
        lines += [f"## {number}. {escape(section.title)}", ""]
        for block in section.blocks:
            if isinstance(block, Paragraph):
                lines += [escape(block.text), ""]
            elif isinstance(block, Table):
                lines += _table(block)
            elif isinstance(block, Equation):
                lines += [f"- `{block.plain}` — {escape(block.source)}"]
                if block.correction:
                    lines += [f"  - correction: {escape(block.correction)}"]
            elif isinstance(block, Figure):
                lines += [f"![{escape(block.caption)}]({next(figures)})", "", escape(block.caption), ""]
        lines.append("")
    if sheet.chain:  # kept beside the sheet for a checker's tool: a comment, not shown
        text = chain_document(sheet.chain).replace("--", "\\u002d-")  # "--" would end the comment
        lines += [f"<!-- fcalc-chain {text} -->", ""]
    return "\n".join(lines)
