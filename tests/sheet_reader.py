"""A checker's reading of a calculation sheet, whatever its format: its sections, its tables as
printed (cells unescaped) and the machine-readable chain kept beside it.

Written independently of the writers (``output/report/markdown.py``, ``html.py``, ``pdf.py``): it
reads the text a user gets, so a number that is not printed cannot be found.
"""

from __future__ import annotations

import html
import json
import re
from dataclasses import dataclass, field
from html.parser import HTMLParser


@dataclass
class PrintedTable:
    title: str
    header: list[str]
    rows: list[list[str]]


@dataclass
class PrintedSection:
    title: str
    tables: list[PrintedTable] = field(default_factory=list)


@dataclass
class Printed:
    """A sheet as read back: its sections with their tables, and its chain (JSON)."""

    sections: list[PrintedSection]
    chain: dict

    def tables(self):
        return [t for s in self.sections for t in s.tables]


# --------------------------------------------------------------------------- Markdown


def _md_unescape(text: str) -> str:
    return html.unescape(re.sub(r"\\(.)", r"\1", text))


def _md_cells(line: str) -> list[str]:
    return [_md_unescape(c.strip()) for c in re.split(r"(?<!\\)\|", line.strip()[1:-1])]


def read_markdown(text: str) -> Printed:
    lines = text.splitlines()
    sections: list[PrintedSection] = []
    i = 0
    while i < len(lines):
        line = lines[i]
        heading = re.match(r"^## \d+\. (.*)$", line)
        if heading:
            sections.append(PrintedSection(_md_unescape(heading.group(1))))
        elif line.startswith("|") and sections:
            title = ""
            if i >= 2 and lines[i - 1] == "" and re.fullmatch(r"\*\*.*\*\*", lines[i - 2]):
                title = _md_unescape(lines[i - 2][2:-2])
            header = _md_cells(line)
            rows = []
            i += 2  # the separator
            while i < len(lines) and lines[i].startswith("|"):
                rows.append(_md_cells(lines[i]))
                i += 1
            sections[-1].tables.append(PrintedTable(title, header, rows))
            continue
        i += 1
    found = re.search(r"<!-- fcalc-chain (.*) -->", text)
    return Printed(sections, json.loads(found.group(1)) if found else {})


# --------------------------------------------------------------------------- HTML


class _HTMLSheet(HTMLParser):
    def __init__(self):
        super().__init__(convert_charrefs=True)
        self.sections: list[PrintedSection] = []
        self.text: list[str] | None = None
        self.table: PrintedTable | None = None
        self.row: list[str] | None = None
        self.chain = ""
        self.in_chain = False

    def handle_starttag(self, tag, attrs):
        if tag in ("h2", "caption", "th", "td"):
            self.text = []
        elif tag == "table":
            self.table = PrintedTable("", [], [])
        elif tag == "tr":
            self.row = []
        elif tag == "script" and ("id", "fcalc-chain") in attrs:
            self.in_chain = True
        elif tag == "sup" and self.text is not None:
            self.text.append("^{")  # fcalc's plain form of an exponent
        elif tag == "sub" and self.text is not None:
            self.text.append("_")  # and of a subscript

    def handle_endtag(self, tag):
        if tag in ("sup", "sub") and self.text is not None:
            self.text.append("}" if tag == "sup" else "")
            return
        text = "".join(self.text or ())
        if tag == "h2":
            self.sections.append(PrintedSection(text.split(". ", 1)[1]))
        elif tag == "caption":
            self.table.title = text
        elif tag in ("th", "td"):
            self.row.append(text)
        elif tag == "tr":
            if self.table.header:
                self.table.rows.append(self.row)
            else:
                self.table.header = self.row
        elif tag == "table":
            self.sections[-1].tables.append(self.table)
            self.table = None
        elif tag == "script":
            self.in_chain = False
        if tag in ("h2", "caption", "th", "td"):
            self.text = None

    def handle_data(self, data):
        if self.in_chain:
            self.chain += data
        elif self.text is not None:
            self.text.append(data)


def read_html(text: str) -> Printed:
    parser = _HTMLSheet()
    parser.feed(text)
    return Printed(parser.sections, json.loads(parser.chain) if parser.chain else {})


# --------------------------------------------------------------------------- typst source

_LITERAL = re.compile(r'"((?:[^"\\]|\\.)*)"')
#: A piece of text: a string literal, or a code block of literals, superscripts and subscripts.
_TEXT = re.compile(r'\{ (?:[^{}"]|"(?:[^"\\]|\\.)*")* \}|"(?:[^"\\]|\\.)*"')


def _typst_string(literal: str) -> str:
    return re.sub(r"\\(.)", lambda m: {"n": "\n", "r": "\r"}.get(m.group(1), m.group(1)), literal)


def _typst_text(piece: str) -> str:
    """A text piece as plain text, a superscript as ``^{…}`` and a subscript as ``_…`` (fcalc's plain form)."""
    if not piece.startswith("{"):
        return _typst_string(piece[1:-1])
    parts = re.findall(r'(super\(|sub\()?"((?:[^"\\]|\\.)*)"', piece)
    marks = {"super(": "^{{{}}}", "sub(": "_{}", "": "{}"}
    return "".join(marks[mark].format(_typst_string(t)) for mark, t in parts)


def read_typst(text: str) -> Printed:
    sections: list[PrintedSection] = []
    chain = {}
    for line in text.splitlines():
        if line.startswith("#heading(level: 1, "):
            sections.append(PrintedSection(_typst_string(_LITERAL.search(line).group(1))))
        elif line.startswith("#block(") and "table(columns: (" in line:
            count = len(re.search(r"table\(columns: \((.*?),\)", line).group(1).split(", "))
            literals = [_typst_text(s) for s in _TEXT.findall(line)]
            title = literals.pop(0) if "strong(" in line.split("table(", 1)[0] else ""
            header, body = literals[:count], literals[count:]
            sections[-1].tables.append(PrintedTable(title, header, [body[k:k + count] for k in range(0, len(body), count)]))
        elif line.startswith("#metadata(") and line.endswith("<fcalc-chain>"):
            chain = json.loads(_typst_string(_LITERAL.search(line).group(1)))
    return Printed(sections, chain)


READERS = {"md": read_markdown, "html": read_html, "typ": read_typst}


# --------------------------------------------------------------------------- cells


class NotPrinted(LookupError):
    """A cell the chain names is not on the sheet."""


def find_table(sheet: Printed, cell: dict) -> PrintedTable:
    if not cell["table"]:
        section = next((s for s in sheet.sections if s.title == cell.get("section")), None)
        table = None if section is None else next((t for t in section.tables if not t.title), None)
    else:
        tables = sheet.tables()
        table = next((t for t in tables if t.title == cell["table"]), None) or next(
            (t for t in tables if t.title.startswith(cell["table"])), None)
    if table is None:
        raise NotPrinted(f"no table {cell['table'] or cell.get('section')!r}")
    return table


def cell_texts(sheet: Printed, cell: dict) -> list[dict[str, str]] | str:
    """The printed text of ``cell``; for a row ``["*"]`` or a column ``"*"`` the rows as
    {header: text} (every row, or the one named)."""
    table = find_table(sheet, cell)
    key = list(cell["row"])
    rows = table.rows if key == ["*"] else [r for r in table.rows if r[:len(key)] == key][:1]
    if not rows:
        raise NotPrinted(f"no row {key} in {table.title!r}")
    if cell["column"] == "*" or key == ["*"]:
        return [dict(zip(table.header, r)) for r in rows]
    if cell["column"] not in table.header:
        raise NotPrinted(f"no column {cell['column']!r} in {table.title!r}")
    text = rows[0][table.header.index(cell["column"])]
    if cell.get("after"):
        if cell["after"] not in text:
            raise NotPrinted(f"{cell['after']!r} not in {text!r}")
        text = text.split(cell["after"], 1)[1]
    return text
