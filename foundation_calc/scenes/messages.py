"""Turn pydantic validation errors into messages an engineer can act on.

Each message names the field by its dotted path, the value that was given, the quantity's symbol
and unit (from the field's description) and the allowed range (from its constraints), e.g.::

    mechanism.rod_length: must be > 0 (got -1.2) -- l, length of the connecting rod [m]
"""

from __future__ import annotations

from typing import Any

from pydantic import BaseModel, ValidationError
from pydantic.fields import FieldInfo

_BOUND_SYMBOLS = {"gt": ">", "ge": ">=", "lt": "<", "le": "<="}


def _field_info(model: type[BaseModel], loc: tuple[Any, ...]) -> FieldInfo | None:
    """Follow ``loc`` through nested models and return the FieldInfo it ends on."""
    info = None
    current: Any = model
    for part in loc:
        if isinstance(part, int):
            continue
        fields = getattr(current, "model_fields", None)
        if not fields or part not in fields:
            return None
        info = fields[part]
        current = info.annotation
        # unwrap Optional[...] / X | None and list[...] to reach a nested model
        for arg in getattr(current, "__args__", ()) or ():
            if isinstance(arg, type) and issubclass(arg, BaseModel):
                current = arg
    return info


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


def describe_validation_error(model: type[BaseModel], exc: ValidationError) -> list[tuple[str, str]]:
    """Return ``(dotted location, message)`` pairs for every error in ``exc``."""
    problems = []
    for err in exc.errors(include_url=False):
        loc = tuple(err["loc"])
        path = ".".join(str(p) for p in loc)
        kind = err["type"]
        if kind == "extra_forbidden":
            problems.append((path, "unknown key (misspelt, or not part of this scene kind)"))
            continue
        msg = err["msg"]
        if msg.startswith("Value error, "):
            msg = msg[len("Value error, "):]
        info = _field_info(model, loc)
        details = []
        given = err.get("input")
        if kind != "missing" and not isinstance(given, dict):
            details.append(f"got {_shorten(given)}")
        if info is not None:
            rng = allowed_range(info)
            if rng and kind not in ("greater_than", "greater_than_equal", "less_than", "less_than_equal"):
                details.append(f"allowed {rng}")
            if info.description:
                details.append(info.description)
        problems.append((path, msg + (f" ({'; '.join(details)})" if details else "")))
    return problems
