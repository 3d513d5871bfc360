"""A scene file edited in place: the user's TOML text with the values that changed written into it
and the keys left out commented out, every comment, the keys' order, blank lines and the layout of
arrays kept (``fcalc design --write``).

tomlkit parses the text into a document that keeps its formatting; the differences between the
document the text holds and the new one (:func:`differences`) are written into it one value at
a time: a scalar keeps its line and its comment (a comment set in a column keeps its column), an
array element its place in the array (an array on one line stays on one line, one laid out a
number a line with comments stays so); a key the new document adds follows its table's last key.
A number is written rounded to ``decimals`` (the grid's precision: 2.1, not 2.0999999999999996),
as an integer where the file had an integer and the value is whole. A key the new document
leaves out is commented out, line and comment kept, with a note after it (a key of an inline
table, which holds no comment, is removed). The edited text is read back: it must hold the new
document, or :func:`edited_scene` raises (a bug).
"""

from __future__ import annotations

import tomllib
import uuid
from collections.abc import Iterator, Mapping
from dataclasses import dataclass
from typing import Any

import tomlkit
from tomlkit.items import InlineTable

#: A key of the path of a value: a table's key or an array's index.
Path = tuple[str | int, ...]

#: A key one of two documents does not have.
_ABSENT = object()


@dataclass(frozen=True)
class Change:
    """One key the edit changed: its dotted path (``machines[0].cog``), the value the file had and
    the one written (None: commented out)."""

    key: str
    old: Any
    new: Any


@dataclass(frozen=True)
class EditedScene:
    """The edited text and the keys it changed, in the file's order."""

    text: str
    changes: tuple[Change, ...]


def _number(value: Any) -> bool:
    return isinstance(value, (int, float)) and not isinstance(value, bool)


def _tidy(value: Any, old: Any, decimals: int) -> Any:
    """``value`` as it is written: a float rounded to ``decimals`` (no -0.0), an integer where the
    file had one and the value is whole."""
    if not isinstance(value, float):
        return value
    value = round(value, decimals) + 0.0
    if _number(old) and not isinstance(old, float) and value.is_integer():
        return int(value)
    return value


def differences(old: Any, new: Any, decimals: int, path: Path = ()) -> Iterator[tuple[Path, Any, Any]]:
    """(path, value in ``old``, value written) of every value of ``new`` that differs from ``old``
    once written (:func:`_tidy`), ``_ABSENT`` for a key only one of them has; tables and arrays of
    the same length are compared item by item."""
    if isinstance(old, Mapping) and isinstance(new, Mapping):
        for key in old:
            yield from differences(old[key], new.get(key, _ABSENT), decimals, (*path, key))
        for key in new:
            if key not in old:
                yield (*path, key), _ABSENT, _tidy(new[key], None, decimals)
    elif isinstance(old, list) and isinstance(new, list) and len(old) == len(new):
        for i, (a, b) in enumerate(zip(old, new)):
            yield from differences(a, b, decimals, (*path, i))
    elif new is _ABSENT:
        yield path, old, _ABSENT
    else:
        written = _tidy(new, old, decimals)
        same = written == old if _number(old) and _number(written) else (type(written) is type(old) and written == old)
        if not same:
            yield path, old, written


def _dotted(path: Path) -> str:
    return "".join(f"[{p}]" if isinstance(p, int) else f".{p}" for p in path).lstrip(".")


def _changes(found: list[tuple[Path, Any, Any]], old: Mapping, new_doc: Mapping) -> tuple[Change, ...]:
    """One :class:`Change` per key: an element of an array of numbers is reported as its array."""
    changes: dict[Path, Change] = {}
    for path, before, after in found:
        while path and isinstance(path[-1], int) and _number(before if before is not _ABSENT else after):
            path = path[:-1]
            before, after = _at(old, path), _at(new_doc, path)
        changes.setdefault(path, Change(_dotted(path), None if before is _ABSENT else before,
                                        None if after is _ABSENT else after))
    return tuple(changes.values())


def _at(document: Any, path: Path) -> Any:
    for key in path:
        document = document[key]
    return document


def edited_scene(text: str, new: Mapping[str, Any], *, decimals: int, note: str) -> EditedScene:
    """``text`` (a TOML document) edited to hold the document ``new`` (module docstring); ``note``
    follows each commented-out key.

    Raises
    ------
    RuntimeError
        when the edited text does not read back as ``new`` (a bug in the edit).
    """
    old = tomllib.loads(text)
    document = tomlkit.parse(text)
    found = list(differences(old, new, decimals))
    left_out: dict[str, str] = {}
    lines: dict[Path, str] = {}  # each written key's text before the edit
    for path, before, written in found:
        parent, key = _at(document, path[:-1]), path[-1]
        if before is _ABSENT:
            parent.append(key, written)  # after the table's last key (set as parent[key], tomlkit glues it to a comma)
        elif written is not _ABSENT:
            line = _key_path(path)
            lines.setdefault(line, _at(document, line).as_string())
            parent[key] = written
        elif isinstance(parent, InlineTable):  # the table again without the key (deleted, tomlkit leaves its space)
            kept = tomlkit.inline_table()
            for name, item in parent.items():
                if name != key:
                    kept.append(name, item)
            _at(document, path[:-2])[path[-2]] = kept
        else:  # a placeholder, replaced below by the line commented out
            token = f"fcalc-left-out-{uuid.uuid4().hex}"
            left_out[token] = parent[key].as_string()
            parent[key] = token
    for line, before in lines.items():
        _align(_at(document, line), before)
    edited = tomlkit.dumps(document)
    if left_out:
        edited = "".join(_comment_out(line, left_out, note) for line in edited.splitlines(keepends=True))
    written_doc = tomllib.loads(edited)
    wrong = [_dotted(p) for p, _, _ in differences(written_doc, new, decimals)]
    if wrong:
        raise RuntimeError(f"the edited scene does not hold the new values at {', '.join(wrong)}")
    return EditedScene(edited, _changes(found, old, written_doc))


def _key_path(path: Path) -> Path:
    """``path`` up to its last table key: the key whose line holds the value."""
    last = max(i for i, key in enumerate(path) if isinstance(key, str))
    return path[: last + 1]


#: Inline comments set off by more spaces than this are taken to stand in a column.
_COLUMN = 2


def _align(item: Any, before: str) -> None:
    """Keep the column of the comment after ``item`` (a value on one line whose text was
    ``before``): the spaces before the comment take up the change of the value's length."""
    trivia, after = getattr(item, "trivia", None), item.as_string()
    if trivia is None or not trivia.comment or "\n" in before + after:
        return
    spaces = trivia.comment_ws
    if len(spaces) > _COLUMN and not spaces.strip(" "):
        trivia.comment_ws = " " * max(len(spaces) - len(after) + len(before), _COLUMN)


def _comment_out(line: str, left_out: dict[str, str], note: str) -> str:
    """``line`` commented out with its value restored and ``note`` after it, if it holds a placeholder."""
    for token, value in left_out.items():
        quoted = f'"{token}"'
        if quoted in line:
            body = line.rstrip("\r\n")
            ending, indent = line[len(body):], len(body) - len(body.lstrip())
            body = body.replace(quoted, value)
            return f"{body[:indent]}# {body[indent:]}  # {note}{ending}"
    return line


__all__ = ["Change", "EditedScene", "differences", "edited_scene"]
