"""Read a scene file's text and its TOML, every failure a :class:`~foundation_calc.errors.SceneError`
naming the file."""

from __future__ import annotations

import tomllib
from pathlib import Path
from typing import Any

from foundation_calc.errors import SceneError

#: Largest scene file read [bytes]; a design is a few hundred bytes.
MAX_SCENE_BYTES = 1_000_000


def read_toml(path: str | Path) -> dict[str, Any]:
    """Return the TOML document at ``path`` as a dict, or raise :class:`SceneError`."""
    return parse_toml(read_text(path), str(path))


def read_text(path: str | Path) -> str:
    """The text of the scene file at ``path`` (UTF-8, a byte-order mark dropped, at most
    :data:`MAX_SCENE_BYTES`), or raise :class:`SceneError`."""
    source = str(path)
    try:
        with open(path, "rb") as handle:  # never more than the limit: the path may be /dev/zero
            raw = handle.read(MAX_SCENE_BYTES + 1)
    except IsADirectoryError:
        raise SceneError(source, [("", "is a folder, not a scene file; fcalc check FOLDER checks every scene in it")]) from None
    except (OSError, ValueError) as exc:  # ValueError: a NUL byte in the path
        raise SceneError(source, [("", f"cannot be read: {getattr(exc, 'strerror', None) or exc}")]) from None
    if len(raw) > MAX_SCENE_BYTES:
        raise SceneError(
            source, [("", f"is over {MAX_SCENE_BYTES} bytes; a scene file must be under that")]
        )
    try:
        return raw.decode("utf-8").removeprefix("\ufeff")  # Windows editors may write a BOM
    except UnicodeDecodeError as exc:
        raise SceneError(source, [("", f"is not UTF-8 text (byte {exc.start})")]) from None


def parse_toml(text: str, source: str) -> dict[str, Any]:
    """The TOML document ``text`` (of the file ``source``) as a dict, or raise :class:`SceneError`."""
    try:
        return tomllib.loads(text)
    except tomllib.TOMLDecodeError as exc:
        raise SceneError(source, [("", f"is not valid TOML: {exc}")]) from None
    except RecursionError:
        raise SceneError(source, [("", "is not valid TOML: nested too deeply")]) from None
    except ValueError:  # an integer longer than Python converts (sys.get_int_max_str_digits())
        raise SceneError(source, [("", f"cannot be read: {_overlong_number(text)}")]) from None


def _overlong_number(text: str) -> str:
    """Where a scene has a number too long to read, as text naming its line and key."""
    import re
    import sys

    limit = sys.get_int_max_str_digits()
    for number, line in enumerate(text.splitlines(), start=1):
        found = re.search(rf"\d{{{limit},}}", line)
        if found:
            key = line.partition("=")[0].strip() if "=" in line[: found.start()] else ""
            named = f", key {key}" if key else ""
            return (
                f"line {number}{named}: a number with {len(found.group())} digits (at most {limit} can be read;"
                " a physical input needs a handful)"
            )
    return "a value cannot be converted"
