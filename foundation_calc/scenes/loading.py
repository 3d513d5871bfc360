"""Read a scene file and validate it with the model of its ``kind``.

Every failure becomes a :class:`~foundation_calc.errors.SceneError` whose problems name the
field (dotted path), the offending value, the unit and the allowed range.
"""

from __future__ import annotations

import importlib
import tomllib
from pathlib import Path
from typing import Any

from foundation_calc.errors import SceneError

#: scene kind -> "module:Model"; a module is imported only when a scene of its kind is read.
KINDS: dict[str, str] = {
    "crank_foundation": "foundation_calc.scenes.crank:CrankScene",
    "block_foundation": "foundation_calc.scenes.block:BlockScene",
    "platform": "foundation_calc.scenes.platform:PlatformScene",
}

#: scene kind -> the single-scene commands that take it (for messages that point the way).
KIND_COMMANDS: dict[str, tuple[str, ...]] = {
    "crank_foundation": ("resonance", "amplitudes", "sweep", "soil"),
    "platform": ("platform",),
    "block_foundation": ("resonance", "amplitudes", "sweep", "runup", "soil", "check", "report"),
}

#: Top-level tables of the scene kinds (of :data:`KINDS`, and ``block``/``machines`` of the block
#: foundation): a TOML file with any of them is a scene, with or without its kind line.
SCENE_TABLES = frozenset({
    "foundation", "soil", "mechanism", "operation", "loads", "limits", "drive", "points",
    "platform", "exciter", "isolators", "extra_exciters", "block", "machines",
})

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


def model_for_kind(kind: str) -> type:
    """Return the pydantic model class of a scene kind (imported on first use)."""
    module_name, _, class_name = KINDS[kind].partition(":")
    return getattr(importlib.import_module(module_name), class_name)


def parse_scene(data: dict[str, Any], source: str = "<scene>", expect: str | tuple[str, ...] | None = None):
    """Validate a scene document (already parsed TOML) and return its model instance.

    ``expect`` names the kind (or kinds) the caller takes; a scene of another kind is a
    :class:`SceneError`.
    """
    return parse_scene_as_written(data, source, expect)[0]


def parse_scene_as_written(data: dict[str, Any], source: str = "<scene>", expect: str | tuple[str, ...] | None = None):
    """:func:`parse_scene`, and the values the scene wrote with their unit by dotted key
    (``{"block.length": "6000 mm"}``; numbers written with a unit are converted first)."""
    kind = data.get("kind")
    if not isinstance(kind, str) or kind not in KINDS:
        raise SceneError(source, [_kind_problem(data, kind)])
    expect_kind(kind, expect, source)
    from foundation_calc.scenes.unit_strings import unit_strings_converted

    data, written, unit_problems = unit_strings_converted(kind, data)  # "6000 mm" -> 6.0; pint only if written so
    if not unit_problems:
        return validate(model_for_kind(kind), data, source), written
    try:  # the scene's other problems too, all in one message
        validate(model_for_kind(kind), data, source)
    except SceneError as exc:
        named = {where for where, _ in unit_problems}
        unit_problems += [(where, text) for where, text in exc.problems if where not in named]
    raise SceneError(source, unit_problems)


def expect_kind(kind: str, expect: str | tuple[str, ...] | None, source: str) -> None:
    """Raise :class:`SceneError` unless a scene of ``kind`` is one that ``expect`` names (a kind,
    several, or None for any): the problem names the commands that take the scene."""
    expected = (expect,) if isinstance(expect, str) else expect
    if expected is not None and kind not in expected:
        commands = " or ".join(f"fcalc {c}" for c in KIND_COMMANDS[kind])
        needs = " or ".join(f'"{k}"' for k in expected)
        raise SceneError(source, [("kind", f'this command needs a {needs} scene (got "{kind}": use {commands})')])


def validate(model: type, data: dict[str, Any], source: str, prefix: str = ""):
    """``model`` validated from ``data``, or a :class:`SceneError` whose problems name each field
    (``prefix`` + dotted path), its value, unit and allowed range."""
    from pydantic import ValidationError

    from foundation_calc.scenes.messages import describe_validation_error

    try:
        return model.model_validate(data)
    except ValidationError as exc:
        problems = describe_validation_error(model, exc)
        raise SceneError(source, [(f"{prefix}{loc}" if loc else prefix.rstrip("."), msg) for loc, msg in problems]) from None
    except RecursionError:
        raise SceneError(source, [("", "is nested too deeply")]) from None


def is_scene(data: dict[str, Any]) -> bool:
    """True when a TOML document is meant as a scene: it has a ``kind`` or a scene table
    (:data:`SCENE_TABLES`); ``pyproject.toml`` or ``.taplo.toml`` have neither."""
    return "kind" in data or not SCENE_TABLES.isdisjoint(data)


def _kind_problem(data: dict[str, Any], kind: Any) -> tuple[str, str]:
    """The problem of a document without a known ``kind``: empty, kind line lost, or unknown."""
    allowed = ", ".join(f'"{k}"' for k in KINDS)
    first = f'kind = "{next(iter(KINDS))}"'
    if not data:
        return "", f"is empty: a scene file holds a kind line ({first}, or one of {allowed}) and its tables; fcalc init KIND writes one"
    if kind is None:
        tables = ", ".join(f"[{name}]" for name in data if name in SCENE_TABLES)
        has = f"the file has scene tables ({tables}) but no kind line" if tables else "no kind line"
        return "kind", f"missing: {has}; it must be one of {allowed}, written at the top of the file, e.g. {first}"
    return "kind", f"must be one of {allowed} (got {kind!r})"


def read_scene(path: str | Path) -> dict[str, Any]:
    """The scene document at ``path`` with the office defaults of the nearest ``fcalc.toml``
    (:func:`~foundation_calc.scenes.project.with_office_defaults`)."""
    from foundation_calc.scenes.project import with_office_defaults

    return with_office_defaults(read_toml(path), path)


def load_scene(path: str | Path, expect: str | tuple[str, ...] | None = None):
    """Read, parse and validate the scene file at ``path`` (with its office defaults)."""
    return parse_scene(read_scene(path), source=str(path), expect=expect)


def load_scene_as_written(path: str | Path):
    """:func:`load_scene`, and the values the file wrote with their unit by dotted key (for the
    sheet's inputs)."""
    return parse_scene_as_written(read_scene(path), source=str(path))
