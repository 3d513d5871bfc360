"""The two consoles of fcalc: results on stdout, messages (errors, warnings) on stderr."""

from __future__ import annotations

from functools import cache
from typing import TYPE_CHECKING

if TYPE_CHECKING:  # rich.console costs ~10 ms to import: only the table path pays for it
    from rich.console import Console

#: JSON documents written by fcalc carry this version; it changes when a key is renamed or removed.
JSON_SCHEMA_VERSION = 1

OUTCOME_STYLE = {"pass": "bold green", "warn": "bold yellow", "fail": "bold red"}


#: Width of stdout when it is not a terminal (a file, a pipe, a CI log): wide enough that no
#: table is ever squeezed, so a file holds every column at its natural width.
UNLIMITED_WIDTH = 100_000


def keep_words_whole(table) -> None:
    """Give every column of a rich ``table`` at least the width of its longest word.

    When a table is wider than the terminal, rich narrows its columns and cuts what does not fit
    with "…". With this floor the text columns wrap between words and a number (one word) is
    never cut at any width; a table that cannot fit runs past the right edge instead. A cell
    that is a rich ``Text`` with ``no_wrap`` (a number with its unit, a quantity with its unit)
    counts as one word: it keeps its line whole.
    """
    from rich.cells import cell_len

    for column in table.columns:
        cells = (column.header, *column.cells)
        longest = max((cell_len(word) for cell in cells for word in _words(cell)), default=0)
        column.min_width = max(column.min_width or 0, longest)


def _words(cell) -> list[str]:
    """The words a cell may wrap between: its whole text for a rich ``Text`` with ``no_wrap``."""
    from rich.text import Text

    text = _plain_text(cell)
    return [text] if isinstance(cell, Text) and cell.no_wrap else text.split()


def _plain_text(cell) -> str:
    """A cell's text without markup ("" for another renderable)."""
    from rich.text import Text

    if isinstance(cell, Text):
        return cell.plain
    if isinstance(cell, str):  # markup only where a tag may be: parsing every number costs
        return Text.from_markup(cell).plain if "[" in cell else cell
    return ""


def column_widths(table, width: int) -> tuple[list[int], list[int], int]:
    """A table's columns' natural widths, their floors (each column's longest word: the
    ``min_width`` of :func:`keep_words_whole`) and the room ``width`` leaves for the columns'
    text, borders and padding taken off [terminal cells]."""
    from rich.cells import cell_len

    columns = table.columns
    natural = [max((cell_len(line) for cell in (c.header, *c.cells) for line in _plain_text(cell).splitlines()),
                   default=0) for c in columns]
    floor = [n if c.no_wrap else min(c.min_width or 0, n) for c, n in zip(columns, natural)]  # no_wrap: never narrowed
    return natural, floor, width - table._extra_width - sum(table._get_padding_width(i) for i in range(len(columns)))


def natural_width(table) -> int:
    """The terminal cells a rich ``table`` takes with no column wrapped: its columns' natural
    widths, borders and padding (a file's or a pipe's width, where nothing is squeezed)."""
    natural, _, room = column_widths(table, 0)
    return sum(natural) - room


def two_line_width(text: str) -> int:
    """The fewest terminal cells in which ``text`` wraps at its spaces into at most two lines.

    >>> two_line_width("pass 3ω=p1 72.4%/20%"), two_line_width("fail")
    (10, 4)
    """
    from rich.cells import cell_len

    splits = (max(cell_len(text[:i]), cell_len(text[i + 1:])) for i, c in enumerate(text) if c == " ")
    return min(splits, default=cell_len(text))


def column_room(table, index: int, width: int) -> int:
    """The terminal cells a ``width`` console leaves column ``index`` of a rich ``table``, its
    other columns wrapped down to their longest words (:func:`keep_words_whole`, called first)."""
    keep_words_whole(table)
    _, floor, room = column_widths(table, width)
    return room - sum(floor) + floor[index]


def widen(table, index: int, cells: int, width: int) -> None:
    """Give column ``index`` of a rich ``table`` at least ``cells`` terminal cells, as far as the
    table still fits ``width`` (:func:`column_room`): :func:`fit_columns` then narrows the others."""
    room = column_room(table, index, width)
    natural, floor, _ = column_widths(table, width)
    table.columns[index].min_width = max(floor[index], min(cells, natural[index], room))


def two_lines_for(table, index: int, texts, width: int) -> None:
    """Fit a rich ``table`` too wide for a ``width`` console so that column ``index`` (whose cells
    are ``texts``, plain) takes at most two lines a row where the other columns let it: the table
    drops its outer frame and edge padding (four cells more for the words) and the column gets the
    width of its longest text wrapped in two (:func:`two_line_width`, :func:`widen`)."""
    table.show_edge = table.pad_edge = False
    widen(table, index, max(map(two_line_width, texts), default=0), width)


def frameless(table):
    """A copy of a rich ``table`` without its outer frame and edge padding (as :func:`fit_columns`
    prints a table whose words do not fit with them)."""
    from copy import copy

    bare = copy(table)
    bare.show_edge = bare.pad_edge = False
    return bare


def fits(table, width: int) -> bool:
    """Whether a rich ``table`` fits ``width`` terminal cells with no word cut (its columns wrapped
    at most down to their longest words)."""
    keep_words_whole(table)
    _, floor, room = column_widths(table, width)
    return sum(floor) <= room


def split_to_fit(table, width: int) -> list:
    """A rich ``table`` whose words do not fit ``width`` terminal cells even without its frame, as
    tables that do, one under the other: each repeats the first column (what names the rows: a
    harmonic, a speed) with the next columns in order, as few tables as fit (filled greedily) and
    their columns as even in number as still fit; the first keeps the title. A table that fits is
    returned alone, as it is."""
    from copy import copy

    columns = table.columns

    def part(indices: list[int]):
        piece = copy(table)
        piece.columns = [copy(columns[i]) for i in indices]
        return piece

    if len(columns) < 3 or fits(frameless(table), width):
        return [table]
    groups, current = [], [0]
    for i in range(1, len(columns)):
        if len(current) > 1 and not fits(frameless(part([*current, i])), width):
            groups.append(current)
            current = [0]
        current.append(i)
    groups.append(current)
    size = -(-(len(columns) - 1) // len(groups))  # as many parts, as even as they fit
    even = [[0, *range(start, min(start + size, len(columns)))] for start in range(1, len(columns), size)]
    if len(even) == len(groups) and all(fits(frameless(part(indices)), width) for indices in even):
        groups = even
    parts = [part(indices) for indices in groups]
    for piece in parts[1:]:
        piece.title = None
    return parts


def whole_if_fits(table, width: int, names, columns=None, rows=None, title=None):
    """A copy of a rich ``table`` (of its ``columns``, ``rows`` and ``title`` where given) whose
    columns headed ``names`` keep each cell on one line (``no_wrap``: names and short phrases, a
    machine, a point, "not judged"), if it fits ``width`` terminal cells so (its frame dropped,
    its other columns wrapped at words, :func:`fit_columns`); else None."""
    from copy import copy

    piece = copy(table)
    piece.columns = [copy(c) for c in (table.columns if columns is None else columns)]
    piece.rows = table.rows if rows is None else rows
    piece.title = table.title if title is None else title
    for column in piece.columns:
        column.no_wrap = column.no_wrap or column.header in names
    return piece if fits(frameless(piece), width) else None


def names_whole(table, width: int, names, grouped: bool = False) -> list:
    """A rich ``table`` as the tables to print on a ``width`` console with the cells of its columns
    headed ``names`` each on one line: the table so where it fits (:func:`whole_if_fits`); else,
    if ``grouped`` (its first column names runs of rows, a machine on each of its rows), one table
    per run without that column, the run's name as its title (under the table's own for the
    first), where each fits so; else the table as it is, its names wrapped at words. In a file or
    a pipe (unlimited width) that is the table, its lines unchanged."""
    from copy import copy
    from itertools import groupby

    whole = whole_if_fits(table, width, names)
    if whole is not None:
        return [whole]
    if grouped and len(table.columns) > 1:
        pieces, start = [], 0
        for name, run in groupby(table.columns[0]._cells):
            stop = start + len(list(run))
            columns = [copy(c) for c in table.columns[1:]]
            for column in columns:
                column._cells = column._cells[start:stop]
            pieces.append(whole_if_fits(table, width, names, columns, table.rows[start:stop],
                                        f"{table.title}\n{name}" if not pieces else name))
            start = stop
        if all(piece is not None for piece in pieces):
            return pieces
    return [table]


def fit_columns(table, width: int) -> None:
    """Cap the widest columns of a rich ``table`` so that it fits ``width`` terminal cells, each
    column at least as wide as its longest word (:func:`keep_words_whole`, called first).

    Rich narrows a table that is too wide by levelling its widest columns, and a column held at
    its longest word then pushes the table past the edge even where narrower columns could have
    given way. Here the columns' widths are levelled down to one cap C, the largest that fits
    (each column max(its longest word, min(its natural width, C))), so a table fits whenever its
    words do. A table that fits as it is is left alone; one whose words alone are wider drops its
    outer frame and the padding at its edges (four cells) first, and runs past the edge if its
    words still do not fit.
    """
    columns = table.columns
    if not columns:
        return
    natural, floor, room = column_widths(table, width)
    if sum(floor) > room and table.show_edge:
        table.show_edge = table.pad_edge = False
        natural, floor, room = column_widths(table, width)
    if sum(natural) <= room or sum(floor) > room:
        return

    def total(cap: int) -> int:
        return sum(max(f, min(n, cap)) for f, n in zip(floor, natural))

    low, high = 0, max(natural)  # total(low) <= room < total(high)
    while high - low > 1:
        mid = (low + high) // 2
        low, high = (mid, high) if total(mid) <= room else (low, mid)
    spare = room - total(low)
    for column, f, n in zip(columns, floor, natural):
        cap = max(f, min(n, low))
        if cap < n and spare > 0 and cap == low:  # the cells left over go to the first capped columns
            cap, spare = cap + 1, spare - 1
        if cap < n:
            column.max_width = cap


def title_apart(console, table):
    """A rich ``table`` whose title is left-justified, as its title above a copy of it without
    one: the title then wraps at the ``console``'s width, at words, where rich wraps it at the
    table's own (a 58-cell table's 80-cell title took two lines of 58 on an 80-column terminal).
    Another table is returned as it is."""
    from copy import copy

    from rich.console import Group
    from rich.style import Style

    if not table.title or table.title_justify != "left":
        return table
    style = Style.pick_first(table.title_style, "table.title")
    title = console.render_str(table.title, style=style, highlight=False) if isinstance(table.title, str) else table.title
    untitled = copy(table)
    untitled.title = None
    return Group(title, untitled)


#: Spaces and tabs ending a line, with any style codes among them (kept) [regular expression].
_TRAILING_SPACE = r"(?:[ \t]|\x1b\[[0-9;]*m)+$"


def strip_trailing_spaces(text: str) -> str:
    r"""``text`` without the spaces and tabs that end its lines (style codes among them are kept).

    Rich pads a table's title, and the lines it wraps, to the table's width: in a file or a pipe
    these are only trailing spaces, which ``diff``, ``git`` and editors flag.

    >>> strip_trailing_spaces("Natural frequencies   \n┃ mode ┃\n")
    'Natural frequencies\n┃ mode ┃\n'
    """
    import re

    return re.sub(_TRAILING_SPACE, lambda m: "".join(re.findall(r"\x1b\[[0-9;]*m", m.group())), text, flags=re.M)


@cache
def _console_class():
    """The class of fcalc's consoles (built on first use: rich is imported only then)."""
    from rich.console import Console
    from rich.table import Table

    class FcalcConsole(Console):
        """A rich console whose tables cut no word (:func:`keep_words_whole`) and fit a terminal
        (:func:`fit_columns`); in a file or a pipe (``piped``) its width is unlimited and its lines
        end without spaces (:func:`strip_trailing_spaces`)."""

        def __init__(self, piped: bool, **kwargs):
            self.piped = piped
            kwargs.setdefault("width", UNLIMITED_WIDTH if piped else None)
            super().__init__(highlight=False, **kwargs)

        def print(self, *objects, **kwargs):
            if not self.piped:  # a file or a pipe: every table whole, at its natural width
                objects = [part for item in objects
                           for part in (split_to_fit(item, self.width) if isinstance(item, Table) else [item])]
            for item in objects:
                if isinstance(item, Table):
                    keep_words_whole(item)
                    fit_columns(item, self.width)
            kwargs.setdefault("crop", False)  # a line wider than the terminal wraps, never loses its end
            if not self.piped:
                super().print(*(title_apart(self, o) if isinstance(o, Table) else o for o in objects), **kwargs)
                return
            with self.capture() as captured:
                super().print(*objects, **kwargs)
            try:
                self.file.write(strip_trailing_spaces(captured.get()))
                self.file.flush()
            except BrokenPipeError:
                self.on_broken_pipe()

    return FcalcConsole


@cache
def stdout() -> Console:
    """Console for results: on a terminal its tables are fitted to it (:func:`fit_columns`); in a
    file or a pipe of unlimited width, so that no table is ever squeezed, and its lines end
    without spaces (:func:`strip_trailing_spaces`). No table cuts a word."""
    import sys

    class ResultConsole(_console_class()):
        def on_broken_pipe(self) -> None:
            """Leave a closed stdout to the CLI, which exits 141 as documented (rich exits 1)."""
            raise BrokenPipeError

    return ResultConsole(not sys.stdout.isatty(), emoji=False)  # ":name:" in user text stays text


@cache
def stderr() -> Console:
    """Console for messages; never mixed into JSON on stdout. As :func:`stdout`, of unlimited
    width in a file or a pipe: a message is one line there (:class:`Hanging` wraps it on a
    terminal only)."""
    import sys

    return _console_class()(not sys.stderr.isatty(), stderr=True)


class Hanging:
    """Console text that wraps at words with a hanging indent: its first line at the console's
    width, the lines after it ``indent`` cells in (by default two more than the line's own leading
    spaces), so that what starts the line (``error:``, a field's name, a note's name) stands out
    on the left. Each line of ``text`` (console markup, or a rich ``Text``) is wrapped so; in a
    file or a pipe, whose width is unlimited, it stays one line."""

    def __init__(self, text, indent: int | None = None):
        self.text = text
        self.indent = indent

    def __rich_console__(self, console, options):
        from rich.text import Text

        text = console.render_str(self.text) if isinstance(self.text, str) else self.text
        width = options.max_width
        lines = []
        for line in text.split("\n", allow_blank=True):
            lead = len(line.plain) - len(line.plain.lstrip(" "))
            indent = min(lead + 2 if self.indent is None else self.indent, width // 2)  # half the width stays for words
            head, *_ = line.wrap(console, width) or [line]
            rest = line[len(head.plain):]
            rest = rest[len(rest.plain) - len(rest.plain.lstrip(" ")):]
            lines.append(head)
            if rest.plain:
                lines.extend(Text(" " * indent) + part for part in rest.wrap(console, width - indent))
        for line in lines:
            line.rstrip()
        yield Text("\n").join(lines)


def warning_line(text: str) -> Hanging:
    """A warning for stderr, ``warning: text`` (``text`` plain, not markup)."""
    from rich.markup import escape

    return Hanging(f"[bold yellow]warning[/]: {escape(text)}", len("warning: "))


def verdict_text(outcome: str, strict: bool = False) -> str:
    """An outcome as styled console markup, e.g. ``[bold red]FAIL[/]``; with ``strict`` a
    warning is shown as the failure it counts as."""
    if strict and outcome == "warn":
        return f"[{OUTCOME_STYLE['fail']}]FAIL[/] (a warning, failing with --strict)"
    return f"[{OUTCOME_STYLE[outcome]}]{outcome.upper()}[/]"


def json_text(value) -> str:
    """``value`` as JSON text (indent 2): characters as they are when stdout is Unicode, escaped
    (``\\u00e9``) when it is not, so the text always reaches the reader whole.

    Raises
    ------
    NonFiniteError
        when a number in ``value`` is NaN or infinite (JSON has none), naming its path.
    """
    import json
    import sys

    from foundation_calc.errors import NonFiniteError

    encoding = (getattr(sys.stdout, "encoding", None) or "").lower().replace("-", "").replace("_", "")
    try:
        return json.dumps(value, indent=2, ensure_ascii=not encoding.startswith("utf"), allow_nan=False)
    except ValueError:
        found = NonFiniteError.find(value)
        if found is None:
            raise
        raise found from None


def with_version(document: dict) -> dict:
    """``document`` with ``fcalc_version`` (version and commit) after its ``schema_version``."""
    from foundation_calc.version import version

    head = {k: document[k] for k in ("schema_version",) if k in document}
    return {**head, "fcalc_version": version(), **document}


def print_json(document: dict) -> None:
    """Write one JSON document to stdout (:func:`json_text`); a result document (one with a
    ``schema_version``) carries fcalc's version, with its commit, right after it."""
    if "schema_version" in document:
        document = with_version(document)
    text = json_text(document)  # whole before a byte is written: a refused document leaves no half
    print(text)


def fmt(value: float, digits: int = 5) -> str:
    """A number with ``digits`` significant figures, for tables."""
    return f"{value:.{digits}g}"


#: Relative size below which a computed value is round-off of the solver, not a result [-]:
#: double precision carries 1e-16, and the 6-DOF and harmonic-balance solves lose at most four
#: digits to conditioning, so anything under 1e-12 of the quantity's own scale is noise.
ROUNDOFF = 1e-12


def fmt_scaled(value: float, scale: float, digits: int = 5) -> str:
    """Like :func:`fmt`, but ``0`` when ``|value| < ROUNDOFF × scale``: a value the solver cannot
    tell from zero (``scale`` is the size of the quantity it belongs to, e.g. the amplitude u).

    >>> fmt_scaled(2.93e-15, 100.0), fmt_scaled(-1.46e-19, 1e-4), fmt_scaled(3.1e-5, 1e-4)
    ('0', '0', '3.1e-05')
    """
    return "0" if abs(value) < ROUNDOFF * abs(scale) else fmt(value, digits)


def titled_table(title: str, columns, right=()):
    """A rich table whose ``title`` may name units in brackets (``[mm]``): kept as text, not read
    as markup; the ``right`` columns right-justified."""
    import re

    from rich.table import Table

    table = Table(title=re.sub(r"(?<!\\)\[([^\]\s]*)\]", r"\\[\1]", title), title_justify="left")
    for col in columns:
        table.add_column(col, justify="right" if col in right else "left")
    return table
