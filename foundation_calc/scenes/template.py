"""A starting scene file of any kind, every key written out and documented (``fcalc init``).

The values are those of the shipped example of the kind (``scenes/defaults/<kind>.toml``),
completed with the model's defaults. tomli-w writes the values; the comments are composed here
from the pydantic field descriptions (``"symbol [unit]: text"``) and constraints, so the
template, the JSON schema and the error messages read the same source. Keys that are unset in
the example (optional keys, alternatives such as the other two ways of giving the speed) are
written commented out, with the equivalent value where there is one and otherwise the field's
example value, so that every commented-out key is valid TOML when uncommented.

>>> text = scene_template("crank_foundation")
>>> "mass = 100000.0" in text and "# M [kg]: block and machine frame" in text
True
>>> "# omega = 26.1799" in text  # the example gives speed_rpm = 250
True
"""

from __future__ import annotations

import tomllib
import typing
from pathlib import Path
from typing import Any

import tomli_w
from pydantic import BaseModel
from pydantic.fields import FieldInfo

from foundation_calc.scenes.common import SpeedFields
from foundation_calc.scenes.kinds import model_for_kind
from foundation_calc.scenes.loading import parse_scene
from foundation_calc.scenes.messages import allowed_range
from foundation_calc.units import speed_triplet

DEFAULTS = Path(__file__).with_name("defaults")


def example_path(kind: str) -> Path:
    """The shipped example scene of ``kind``."""
    return DEFAULTS / f"{kind}.toml"


def _nested_model(annotation: Any) -> tuple[type[BaseModel] | None, bool]:
    """The model inside ``annotation`` (``Model``, ``Model | None``, ``list[Model]``), and whether it is a list."""
    if isinstance(annotation, type) and issubclass(annotation, BaseModel):
        return annotation, False
    origin = typing.get_origin(annotation)
    for arg in typing.get_args(annotation):
        model, _ = _nested_model(arg)
        if model is not None:
            return model, origin is list
    return None, False


def _comment(info: FieldInfo) -> str:
    text = (info.description or "").removeprefix("- [-]: ")
    rng = allowed_range(info)
    if rng:
        text += f"; allowed {rng}"
    if not info.is_required():
        text += "; optional"
    return f"# {text}"


def _value_line(key: str, value: Any) -> str:
    """``key = value`` in TOML; a list of numbers stays on one line, a table of plain values inline."""
    if isinstance(value, dict):
        items = ", ".join(_value_line(k, v) for k, v in value.items())
        return f"{tomli_w.dumps({key: 0}).partition(' = ')[0]} = {{ {items} }}"
    if isinstance(value, list) and not any(isinstance(item, (dict, list)) for item in value):
        items = ", ".join(_value_line("v", item).partition(" = ")[2] for item in value)
        return f"{tomli_w.dumps({key: 0}).partition(' = ')[0]} = [{items}]"
    return tomli_w.dumps({key: value}).rstrip("\n")


def _alternatives(model: type[BaseModel], values: dict) -> dict[str, Any]:
    """Equivalent values for unset keys: the other two ways of giving the speed."""
    if issubclass(model, SpeedFields):
        given = next(k for k in ("omega", "frequency_hz", "speed_rpm") if values.get(k) is not None)
        omega = speed_triplet(1.0)  # rad/s -> (1, Hz, rpm) factors
        in_rad_s = values[given] / omega[given]
        return {k: round(in_rad_s * omega[k], 6) for k in omega}
    return {}


def _section(model: type[BaseModel], values: dict | None, header: str, lines: list[str], *, array: bool = False) -> None:
    """Append ``[header]`` (or ``[[header]]``) and its keys; everything commented out when ``values`` is None."""
    off = "# " if values is None else ""
    values = values or {}
    if header:
        lines += ["", f"# {(model.__doc__ or '').strip().splitlines()[0]}"]
        lines.append(f"{off}[[{header}]]" if array else f"{off}[{header}]")
    alternatives = _alternatives(model, values) if not off else {}
    tables = []
    for key, info in model.model_fields.items():
        nested, is_list = _nested_model(info.annotation)
        if nested is not None:
            tables.append((key, nested, is_list))
            continue
        value = values.get(key)
        lines.append(_comment(info))
        if value is None or value == {} or off:
            default = None if info.is_required() else info.get_default(call_default_factory=True)
            shown = alternatives.get(key, value if value is not None else default)
            if shown is None or shown == {}:
                shown = info.examples[0]  # every optional or nested field carries one
            lines.append(f"# {_value_line(key, shown)}")
        else:
            lines.append(_value_line(key, value))
    for key, nested, is_list in tables:
        name = f"{header}.{key}" if header else key
        value = values.get(key)
        if is_list:
            for item in value or [None]:  # an empty list is shown as one commented-out entry
                _section(nested, None if off else item, name, lines, array=True)
        else:
            _section(nested, None if off else value, name, lines)


def scene_template(kind: str) -> str:
    """The text of a starting scene of ``kind``: the shipped example, every key documented.

    The text is checked to load back to the example before it is returned.
    """
    model = model_for_kind(kind)
    example = parse_scene(tomllib.loads(example_path(kind).read_text(encoding="utf-8")), str(example_path(kind)))
    values = example.model_dump(mode="json")
    lines = [
        f"# Scene of kind {kind!r} for foundation_calc (fcalc), started from the shipped example.",
        "# Every key is listed with its symbol, unit [SI] and allowed range; commented-out keys",
        "# are optional or alternatives. Check it with `fcalc check FILE`; editor validation:",
        f"# `fcalc schema {kind} > {kind}.schema.json` (see docs/commands.md).",
        "# A number may be written as text with its unit, converted to the key's unit [in brackets]",
        "# (a bare number is in the key's unit), e.g.",
        '#   length = "6000 mm"   density = "2.4 t/m^3"   speed_rpm = "10 Hz"   phase = "90 deg"',
        '#   force = ["6 kN", 0, "2 kN"]   shear_modulus = "72 MPa"   inertia = ["10 t*m^2", 0, 0]',
    ]
    _section(model, values, "", lines)
    text = "\n".join(lines) + "\n"
    if parse_scene(tomllib.loads(text), "template") != example:
        raise AssertionError(f"the {kind} template does not load back to its example")  # a bug
    return text

