"""Turn pydantic validation errors into messages an engineer can act on.

Each message names the field by its dotted path, the value that was given, the quantity's symbol
and unit (from the field's description) and the allowed range (from its constraints), e.g.::

    mechanism.rod_length: must be > 0 (got -1.2) -- l, length of the connecting rod [m]
"""

from __future__ import annotations

import difflib
from typing import Any

from pydantic import BaseModel, ValidationError
from pydantic.fields import FieldInfo

from foundation_calc.scenes.common import KeyProblem

_BOUND_SYMBOLS = {"gt": ">", "ge": ">=", "lt": "<", "le": "<="}


def _walk(model: type[BaseModel], loc: tuple[Any, ...]) -> tuple[FieldInfo | None, Any]:
    """Follow ``loc`` through nested models: the FieldInfo it ends on and the model (or type)
    that field holds; ``(None, None)`` when ``loc`` leaves the models."""
    info, current = None, model
    for part in loc:
        if isinstance(part, int):
            continue
        fields = getattr(current, "model_fields", None)
        if not fields or part not in fields:
            return None, None
        info = fields[part]
        current = _nested(info.annotation)
    return info, current


def _field_info(model: type[BaseModel], loc: tuple[Any, ...]) -> FieldInfo | None:
    """The FieldInfo that ``loc`` ends on."""
    return _walk(model, loc)[0]


def _model_at(model: type[BaseModel], loc: tuple[Any, ...]) -> type[BaseModel] | None:
    """The model whose fields are the keys at ``loc`` (the table that holds the key)."""
    return nested_model(_walk(model, loc)[1])


def _nested(annotation: Any) -> Any:
    """``Model`` out of ``Model``, ``Model | None`` or ``list[Model]``; else the annotation."""
    if isinstance(annotation, type) and issubclass(annotation, BaseModel):
        return annotation
    for arg in getattr(annotation, "__args__", ()) or ():
        found = _nested(arg)
        if isinstance(found, type) and issubclass(found, BaseModel):
            return found
    return annotation


def nested_model(annotation: Any) -> type[BaseModel] | None:
    """The model of a nested table (``Model``, ``Model | None``, ``list[Model]``), or None."""
    found = _nested(annotation)
    return found if isinstance(found, type) and issubclass(found, BaseModel) else None


def _unknown_key(model: type[BaseModel], loc: tuple[Any, ...]) -> str:
    """The message for a key the scene kind does not have, with the nearest known key."""
    table = _model_at(model, loc[:-1])
    known = list(table.model_fields) if table is not None else []
    close = difflib.get_close_matches(str(loc[-1]), known, n=1, cutoff=0.6)
    hint = f"; did you mean {close[0]}?" if close else (f"; the keys here are {', '.join(known)}" if known else "")
    return f"unknown key (misspelt, or not part of this scene kind){hint}"


def _missing_table(info: FieldInfo | None) -> str:
    """For a whole missing table: the keys it needs."""
    nested = nested_model(info.annotation) if info is not None else None
    if nested is None:
        return ""
    required = [name for name, field in nested.model_fields.items() if field.is_required()]
    keys = getattr(nested, "required_keys_text", None) or ", ".join(required)
    return f"a table with {keys}" if keys else "a table"


def allowed_range(info: FieldInfo) -> str:
    """The constraints of a field as text, e.g. ``"> 0"`` or ``">= 0 and < 1"``."""
    parts = []
    for item in info.metadata:
        for name, symbol in _BOUND_SYMBOLS.items():
            bound = getattr(item, name, None)
            if bound is not None:
                parts.append(f"{symbol} {bound:g}" if isinstance(bound, float) else f"{symbol} {bound}")
    return " and ".join(parts)


def _shorten(value: Any, limit: int = 60) -> str:
    text = repr(value)
    return text if len(text) <= limit else text[: limit - 3] + "..."


def _is_table(value: Any) -> bool:
    """A TOML table or an array of tables (``[[machines]]``): the message names its key and the
    entry at fault, and repeating the tables' text would bury that."""
    return isinstance(value, dict) or (isinstance(value, list) and any(isinstance(item, dict) for item in value))


def describe_validation_error(model: type[BaseModel], exc: ValidationError) -> list[tuple[str, str]]:
    """Return ``(dotted location, message)`` pairs for every error in ``exc``."""
    problems = []
    for err in exc.errors(include_url=False):
        loc = tuple(err["loc"])
        problem = (err.get("ctx") or {}).get("error")
        if isinstance(problem, KeyProblem):  # a table's rule about one of its keys: that key
            loc += tuple(int(p) if p.isdigit() else p for p in problem.key.split("."))
        path = ".".join(str(p) for p in loc)
        kind = err["type"]
        if kind == "extra_forbidden":
            problems.append((path, _unknown_key(model, loc)))
            continue
        info = _field_info(model, loc)
        msg = _plain(err, info)
        details = []
        given = err.get("input")
        if kind != "missing" and not _is_table(given) and not _names_value(msg, given):
            details.append(f"got {_shorten(given)}")
        table = _missing_table(info) if kind == "missing" else ""
        if table:
            details.append(table)
        elif info is not None and not (isinstance(problem, KeyProblem) and (info.description or "").startswith("- [-]: ")):
            # (a rule's sentence about a table already says what the table is)
            rng = allowed_range(info)
            if rng and kind not in ("greater_than", "greater_than_equal", "less_than", "less_than_equal"):
                details.append(f"allowed {rng}")
            if info.description:
                details.append(info.description.removeprefix("- [-]: "))  # no symbol, no unit: the text alone
        problems.append((path, msg + (f" ({'; '.join(details)})" if details else "")))
    return problems


#: pydantic's error types -> the same rule in an engineer's words (``{...}`` from the error's context).
_PLAIN = {
    "missing": "missing",
    "greater_than": "must be > {gt}",
    "greater_than_equal": "must be >= {ge}",
    "less_than": "must be < {lt}",
    "less_than_equal": "must be <= {le}",
    "float_type": "must be a number",
    "float_parsing": "must be a number",
    "int_type": "must be a whole number",
    "int_parsing": "must be a whole number",
    "int_from_float": "must be a whole number",
    "finite_number": "must be a finite number",
    "string_type": "must be text (in quotes)",
    "bool_type": "must be true or false",
    "bool_parsing": "must be true or false",
    "list_type": "must be a list [a, b, ...]",
    "dict_type": "must be a table",
    "model_type": "must be a table",
    "string_too_long": "must be at most {max_length} characters long",
    "string_too_short": "must be at least {min_length} characters long",
}


def _plain(err: dict, info: FieldInfo | None) -> str:
    """The message of one pydantic error in an engineer's words (:data:`_PLAIN`); a validator's
    own message as it is written."""
    kind = err["type"]
    context = {key: f"{value:g}" if isinstance(value, float) else value for key, value in (err.get("ctx") or {}).items()}
    if kind in ("too_short", "too_long"):
        bounds = {name: getattr(item, name) for item in (info.metadata if info else ()) for name in ("min_length", "max_length") if getattr(item, name, None) is not None}
        if bounds.get("min_length") is not None and bounds.get("min_length") == bounds.get("max_length"):
            return f"must have {bounds['min_length']} items"
        return f"must have at least {context['min_length']} items" if kind == "too_short" else f"must have at most {context['max_length']} items"
    if kind in _PLAIN:
        try:
            return _PLAIN[kind].format(**context)
        except (KeyError, IndexError):
            pass
    msg = err["msg"].removeprefix("Value error, ").removeprefix("Assertion failed, ")
    return "must be" + msg[len("Input should be"):] if msg.startswith("Input should be") else msg


def _names_value(message: str, value: Any) -> bool:
    """True when ``message`` already names ``value`` (a validator's ``detuning = 2 is outside ...``
    or ``(got ...)``), so that no second "got" follows it."""
    if "(got " in message:
        return True
    if isinstance(value, bool) or not isinstance(value, (int, float, str)):
        return False
    import re

    texts = {str(value), repr(value)} | ({f"{value:g}"} if isinstance(value, (int, float)) else set())
    return any(re.search(rf"=\s*{re.escape(text)}(?![\w.])", message) for text in texts)
