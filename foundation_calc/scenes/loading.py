"""Read a scene file and validate it with the model of its ``kind``.

Every failure becomes a :class:`~foundation_calc.errors.SceneError` whose problems name the
field (dotted path), the offending value, the unit and the allowed range.
"""

from __future__ import annotations

from pathlib import Path
from typing import Any

from foundation_calc.errors import SceneError
from foundation_calc.scenes.files import read_toml
from foundation_calc.scenes.kinds import KIND_COMMANDS, KINDS, SCENE_TABLES, model_for_kind
from foundation_calc.scenes.validation import validate


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
