"""JSON Schema of a scene kind, from its pydantic model (``fcalc schema KIND``).

Editors that validate TOML against a JSON Schema (taplo / Even Better TOML in VS Code, JetBrains
IDEs with a TOML schema plugin) then flag a misspelt key, a string for a number or a negative
mass while the scene is typed; every property carries the field's ``"symbol [unit]: text"``.

>>> schema = scene_schema("crank_foundation")
>>> schema["$id"], schema["properties"]["kind"]["const"]
('urn:foundation-calc:scene:crank_foundation:v1', 'crank_foundation')
"""

from __future__ import annotations

from foundation_calc.scenes.common import SCENE_SCHEMA_VERSION
from foundation_calc.scenes.kinds import model_for_kind
from foundation_calc.scenes.unit_strings import WRITTEN_SCHEMA, key_units

JSON_SCHEMA_DIALECT = "https://json-schema.org/draft/2020-12/schema"


def scene_schema(kind: str) -> dict:
    """The JSON Schema (draft 2020-12) of scenes of ``kind``, with ``$id`` and ``title``; a key
    with a unit takes a number or a number with its unit as text (``"6000 mm"``)."""
    schema = model_for_kind(kind).model_json_schema()
    for table in (schema, *schema.get("$defs", {}).values()):
        table["properties"] = {
            key: _or_written(prop) if key_units(prop.get("description")) else prop
            for key, prop in table.get("properties", {}).items()
        }
    return {
        "$schema": JSON_SCHEMA_DIALECT,
        "$id": f"urn:foundation-calc:scene:{kind}:v{SCENE_SCHEMA_VERSION}",
        **schema,
        "title": f"foundation_calc scene of kind {kind!r} (format version {SCENE_SCHEMA_VERSION})",
    }


#: The keys of a number's own schema (its bounds); the rest (description, examples) stays outside.
_NUMBER_KEYS = frozenset({"type", "minimum", "maximum", "exclusiveMinimum", "exclusiveMaximum"})


def _or_written(node: dict) -> dict:
    """``node`` with every number in it (alone, in ``anyOf``, as list items) a number or
    :data:`~foundation_calc.scenes.unit_strings.WRITTEN_SCHEMA`.

    >>> _or_written({"type": "number", "exclusiveMinimum": 0, "title": "Mass"})["anyOf"][0]
    {'type': 'number', 'exclusiveMinimum': 0}
    """
    if node.get("type") == "number":
        rest = {key: value for key, value in node.items() if key not in _NUMBER_KEYS}
        return {**rest, "anyOf": [{key: value for key, value in node.items() if key in _NUMBER_KEYS}, WRITTEN_SCHEMA]}
    out = dict(node)
    if isinstance(out.get("anyOf"), list):  # number | null -> number | text | null
        branches = [_or_written(branch) for branch in out["anyOf"]]
        out["anyOf"] = [inner for branch in branches for inner in (branch["anyOf"] if branch.keys() == {"anyOf"} else [branch])]
    if isinstance(out.get("items"), dict):
        out["items"] = _or_written(out["items"])
    return out
