"""Validate a table of a scene with its pydantic model, every failure a
:class:`~foundation_calc.errors.SceneError` whose problems name the field (dotted path), the
offending value, the unit and the allowed range."""

from __future__ import annotations

from typing import Any

from foundation_calc.errors import SceneError


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
