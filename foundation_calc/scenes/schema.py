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
from foundation_calc.scenes.loading import model_for_kind

JSON_SCHEMA_DIALECT = "https://json-schema.org/draft/2020-12/schema"


def scene_schema(kind: str) -> dict:
    """The JSON Schema (draft 2020-12) of scenes of ``kind``, with ``$id`` and ``title``."""
    schema = model_for_kind(kind).model_json_schema()
    return {
        "$schema": JSON_SCHEMA_DIALECT,
        "$id": f"urn:foundation-calc:scene:{kind}:v{SCENE_SCHEMA_VERSION}",
        **schema,
        "title": f"foundation_calc scene of kind {kind!r} (format version {SCENE_SCHEMA_VERSION})",
    }
