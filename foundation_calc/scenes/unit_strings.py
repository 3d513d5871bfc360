"""Numbers written with their unit (``length = "6000 mm"``, ``speed_rpm = "10 Hz"``) converted to
the unit each scene key declares, before the scene is validated.

Every physical key declares its unit in its description (``quantity(symbol, unit, ...)`` in
:mod:`foundation_calc.scenes.common`); that unit, not SI blindly, is the target: ``omega =
"600 rpm"`` becomes 62.83 rad/s, ``speed_rpm = "10 Hz"`` 600 rpm, ``frequency_hz = "600 rpm"``
10 Hz. A bare number stays as it is (the key's own unit). The conversion factors are pint's
(https://pint.readthedocs.io), imported only when a scene holds a string at a key with a unit;
one definition is changed: pint's hertz is 1/s, the same as a rad/s, so ``10 Hz`` would be
10 rad/s; here a hertz is a revolution per second (2π rad/s), as a shaft's frequency means.

A value whose dimension is not the key's (``block.length = "72 MPa"``) or that is not a number
with a unit (``"abc"``, ``"6000"``) is a :class:`~foundation_calc.errors.SceneError` naming the
key (the dotted path of the other scene errors), what was written and both dimensions.

>>> document = {"block": {"length": "6000 mm", "width": 4.0}, "machines": [{"speed": "600 rpm"}]}
>>> converted, written = with_unit_strings_converted("block_foundation", document)
>>> converted["block"], round(converted["machines"][0]["speed"], 6), written
({'length': 6.0, 'width': 4.0}, 62.831853, {'block.length': '6000 mm', 'machines.0.omega': '600 rpm'})
"""

from __future__ import annotations

import math
import re
from functools import lru_cache
from typing import Any

from foundation_calc.errors import SceneError

#: The units the scene keys declare -> the same unit in pint's notation.
KEY_UNITS = {
    "m": "m", "m²": "m**2", "m⁴": "m**4", "kg": "kg", "kg m²": "kg*m**2", "kg/m³": "kg/m**3",
    "N": "N", "N m": "N*m", "N/m": "N/m", "N/m³": "N/m**3", "N m/rad": "N*m/rad", "N s/m": "N*s/m",
    "N m s/rad": "N*m*s/rad", "Pa": "Pa", "W": "W", "s": "s", "m/s": "m/s", "m/s²": "m/s**2", "mm/s": "mm/s",
    "rad": "rad", "rad/s": "rad/s", "Hz": "Hz", "rpm": "rpm",
}

#: A dimension in words, by a unit that has it (the first unit of a dimension names it).
DIMENSION_NAMES = (
    ("m", "a length"), ("kg", "a mass"), ("s", "a time"), ("Pa", "a pressure (stress, modulus)"), ("N", "a force"),
    ("N*m", "a moment (torque, energy)"), ("N/m", "a stiffness (force per length)"),
    ("N/m**3", "a subgrade modulus (force per volume)"), ("kg/m**3", "a density"), ("m/s", "a velocity"),
    ("m/s**2", "an acceleration"), ("Hz", "a speed or frequency (per time)"), ("rad", "an angle or a pure number"),
    ("kg*m**2", "a moment of inertia"), ("m**2", "an area"), ("m**4", "a second moment of area"), ("W", "a power"),
    ("N*s/m", "a damping coefficient (force per velocity)"),
)

#: A decimal number as TOML or JSON write it (``6000``, ``-1.5``, ``2.5e3``).
NUMBER = r"[+-]?(?:[0-9]+(?:\.[0-9]*)?|\.[0-9]+)(?:[eE][+-]?[0-9]+)?"

#: A number, then its unit (``6000 mm``, ``1.8 t/m^3``, ``-2.5e3 N*m``); the unit may be absent
#: only to be named as missing.
_WRITTEN = re.compile(rf"^\s*(?P<number>{NUMBER})\s*(?P<unit>.*?)\s*$", re.S)

#: The JSON Schema of a number written with its unit (``fcalc schema``): a number, then a unit.
WRITTEN_SCHEMA = {
    "type": "string",
    "pattern": rf"^\s*{NUMBER}\s*[^\s0-9.+-].*$",
    "description": 'a number with its unit, converted to the key\'s unit, e.g. "6000 mm", "72 MPa", "600 rpm"',
}


#: What a unit is written with: names (µm, t, kN), spaces, ``* / ^ **``, parentheses, powers.
_UNIT_TEXT = re.compile(r"^[\w\s*/^().·°%²³⁴⁻¹-]+$")


@lru_cache(maxsize=1)
def registry():
    """pint's unit registry with a hertz of one revolution per second (see the module text)."""
    import pint

    units = pint.UnitRegistry(on_redefinition="ignore")  # redefine hertz without logging a warning
    units.define("hertz = revolution / second = Hz")
    units.define("@alias revolution = rev")  # "rev/min"
    return units


def with_unit_strings_converted(kind: str, document: dict[str, Any], source: str = "<scene>") -> tuple[dict, dict]:
    """The scene ``document`` of ``kind`` with every value written with a unit converted to its
    key's unit, and the values as written by the dotted path of their field (``speed`` is
    ``omega``); ``document`` itself is left as it is.
    A value that cannot be converted is a :class:`SceneError` (see :func:`unit_strings_converted`).
    """
    converted, written, problems = unit_strings_converted(kind, document)
    if problems:
        raise SceneError(source, problems)
    return converted, written


def unit_strings_converted(kind: str, document: dict[str, Any]) -> tuple[dict, dict, list[tuple[str, str]]]:
    """The scene ``document`` of ``kind`` with what converts converted, the values as written by
    dotted key, and ``(dotted key, message)`` of each value that does not convert (left as
    written). A document of bare numbers comes back unchanged and pint is not imported.
    """
    from foundation_calc.scenes.kinds import model_for_kind

    written: dict[str, Any] = {}
    problems: list[tuple[str, str]] = []
    return _table(model_for_kind(kind), document, "", written, problems), written, problems


def kept_as_written(new: Any, converted: Any, raw: Any) -> Any:
    """``new`` (a changed copy of the ``converted`` scene document) with every value it left
    unchanged back as the user wrote it in ``raw`` (``"6000 mm"``), for a scene written back to
    its file (``fcalc design --write``).

    >>> kept_as_written({"a": 7.2, "b": 2.0, "c": [1.0, 5.0]}, {"a": 6.0, "b": 2.0, "c": [1.0, 2.0]},
    ...                 {"a": "6000 mm", "b": "2 m", "c": ["1 m", "2 m"]})
    {'a': 7.2, 'b': '2 m', 'c': ['1 m', 5.0]}
    """
    if isinstance(new, dict) and isinstance(converted, dict) and isinstance(raw, dict):
        return {key: kept_as_written(value, converted.get(key), raw.get(key)) for key, value in new.items()}
    if isinstance(new, list) and isinstance(converted, list) and isinstance(raw, list) and len(new) == len(raw) == len(converted):
        return [kept_as_written(*values) for values in zip(new, converted, raw)]
    return raw if isinstance(raw, str) and new == converted else new


def _table(model: type, data: Any, path: str, written: dict, problems: list) -> Any:
    """``data`` (a table of ``model``) with its keys' unit strings converted."""
    if not isinstance(data, dict):
        return data
    fields = model.model_fields
    renamed = getattr(model, "renamed_keys", {})
    out = {}
    for key, value in data.items():
        name = renamed.get(key, key)  # named by the field's path, as the scene's other errors are
        info = fields.get(name)
        found: list[tuple[str, str]] = []
        out[key] = value if info is None else _value(info, value, f"{path}{name}", written, found)
        problems += [(where, text if name == key else f"{text} (written as {key})") for where, text in found]
    return out


def _value(info, value: Any, path: str, written: dict, problems: list) -> Any:
    """The value of one key: a nested table (or list of tables) walked, a number with a unit
    converted to the key's unit (element by element in a list)."""
    from foundation_calc.scenes.messages import nested_model

    nested = nested_model(info.annotation)
    if nested is not None:
        if isinstance(value, list):
            return [_table(nested, item, f"{path}.{i}.", written, problems) for i, item in enumerate(value)]
        return _table(nested, value, f"{path}.", written, problems)
    units = key_units(info.description)
    if not units:
        return value
    if isinstance(value, str):
        return _converted(value, units[0], path, written, problems)
    if isinstance(value, list) and any(isinstance(item, str) for item in value):
        per_item = max(1, len(value) // len(units))  # [N/m, N m/rad]: three forces, then three moments
        return [
            _converted(item, units[min(i // per_item, len(units) - 1)], f"{path}.{i}", written, problems)
            if isinstance(item, str) else item
            for i, item in enumerate(value)
        ]
    return value


def key_units(description: str | None) -> tuple[str, ...]:
    """The units a key declares (``"l [m]: ..."`` -> ``("m",)``; a 6-vector's ``[N/m, N m/rad]``
    -> both), or ``()`` for a key without a unit (a name, a method, a ratio [-]).

    >>> key_units("K [N/m, N m/rad]: springs"), key_units("ν [-]: Poisson's ratio"), key_units(None)
    (('N/m', 'N m/rad'), (), ())
    """
    found = re.match(r"^[^\[]*\[([^\]]*)\]:", description or "")
    if not found:
        return ()
    units = tuple(unit.strip() for unit in found.group(1).split(","))
    return units if all(unit in KEY_UNITS for unit in units) else ()


def _converted(text: str, unit: str, path: str, written: dict, problems: list) -> Any:
    """``text`` (a number and its unit) in ``unit`` (one of :data:`KEY_UNITS`); a problem naming
    ``path`` when it is not a quantity or has another dimension (``text`` then stays)."""
    units = registry()
    target = units.parse_units(KEY_UNITS[unit])
    this_key = f"this key is {dimension_name(target.dimensionality)} [{unit}]"
    match = _WRITTEN.match(text)
    if match is None or not match.group("unit"):
        problems.append((path, f"must be a number (got {text!r}): a bare number in {unit}, or with its unit as text,"
                               f" e.g. \"{_example(unit)}\"; {this_key}"))
        return text
    given = _unit(match.group("unit"))
    if given is None:
        problems.append((path, f"{text!r}: {match.group('unit')!r} is not a unit fcalc knows; {this_key}"))
        return text
    if given.dimensionality != target.dimensionality:
        problems.append((path, f"{text} is {dimension_name(given.dimensionality)}; {this_key}"))
        return text
    if _per_time_alone(given):
        problems.append((path, f"{text} does not say what turns: write revolutions as rpm or Hz (\"600 rpm\","
                               f" \"10 Hz\") or an angle per time (\"62.8 rad/s\"); {this_key}"))
        return text
    value = _in_unit(match.group("number"), given, target)
    if not math.isfinite(value):
        problems.append((path, f"{text} is beyond the numbers fcalc computes with (it overflows); {this_key}"))
        return text
    written[path] = text
    return value


def _in_unit(number: str, given, target) -> float:
    """The decimal ``number`` in ``given`` units, in ``target`` units. A factor that is a whole
    number one way (1000 mm in a m, 1000 kg in a t) is applied in decimal arithmetic, so that
    ``"110 mm"`` is the float nearest 0.11, the number typed in m (``110 × 0.001`` in floats is
    0.11000000000000001); others (° -> rad, rpm -> rad/s) multiply as fcalc's own conversions do.

    >>> units = registry()
    >>> _in_unit("110", units.mm, units.m), _in_unit("5", units.um, units.m), _in_unit("218.7", units.t, units.kg)
    (0.11, 5e-06, 218700.0)
    """
    from decimal import Decimal, DecimalException

    factor = float(registry().Quantity(1.0, given).to(target).magnitude)
    inverse = float(registry().Quantity(1.0, target).to(given).magnitude)
    try:
        if _whole(inverse) > 1:
            return float(Decimal(number) / _whole(inverse))
        if _whole(factor) >= 1:
            return float(Decimal(number) * _whole(factor))
    except DecimalException:  # beyond the decimal context (9e999999 t): inf, named by the caller
        return math.inf
    return float(number) * factor


def _whole(factor: float) -> int:
    """``factor`` as a whole number when it is one to round-off (pint's 1e8 cm⁴ in a m⁴ is
    99999999.99999999), else 0."""
    if not math.isfinite(factor) or factor < 1:
        return 0
    whole = round(factor)
    return whole if abs(factor - whole) <= 1e-12 * factor else 0


def _per_time_alone(unit) -> bool:
    """True for a speed written as a count per time without what is counted (``1/min``,
    ``s^-1``): pint reads it as radians per time, an engineer often means revolutions (a factor 2π
    apart), so fcalc asks for rpm, Hz or rad/s."""
    time = registry().parse_units("s").dimensionality
    return bool(unit.dimensionality == 1 / time) and all(
        registry().parse_units(name).dimensionality == time for name in unit._units
    )


def _unit(text: str):
    """The pint unit written as ``text`` (``kN*m/rad``, ``t/m^3``, ``kg m²``), or None when it is
    not one: other characters than a unit's, a name pint does not know, or an expression its
    parser rejects (which it does with TokenError, AssertionError, ZeroDivisionError, ...)."""
    if not _UNIT_TEXT.match(text):
        return None
    try:
        unit = registry().parse_units(text)
    except Exception:  # a parser of free text fails in many ways; each means "not a unit"
        return None
    return unit if all(math.isfinite(power) for power in unit.dimensionality.values()) else None


def dimension_name(dimensionality) -> str:
    """A dimension in words (:data:`DIMENSION_NAMES`), or pint's ``[mass] / [time]`` for another."""
    units = registry()
    for unit, name in DIMENSION_NAMES:
        if units.parse_units(unit).dimensionality == dimensionality:
            return name
    return f"of dimension {dimensionality}"


def _example(unit: str) -> str:
    """A written value in a key's unit, for a message (``"6000 mm"`` for a length)."""
    return {"m": "6000 mm", "kg": "2.5 t", "Pa": "72 MPa", "kg/m³": "1.8 t/m^3", "rad": "90 deg", "N": "6 kN",
            "rad/s": "600 rpm", "rpm": "600 rpm", "Hz": "10 Hz"}.get(unit, f"1 {KEY_UNITS[unit]}")
