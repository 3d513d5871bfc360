"""`fcalc schema KIND`: the JSON Schema of the scene models agrees with what the loader accepts."""

from __future__ import annotations

import json

import pytest

from foundation_calc.cli.app import app
from foundation_calc.scenes import KINDS, read_toml
from tests.conftest import CONFIGS


def _schema(runner, kind: str) -> dict:
    result = runner.invoke(app, ["schema", kind])
    assert result.exit_code == 0 and result.stderr == ""
    return json.loads(result.stdout)


@pytest.mark.parametrize("kind", sorted(KINDS))
def test_schema_document(runner, kind):
    schema = _schema(runner, kind)
    assert schema["$schema"] == "https://json-schema.org/draft/2020-12/schema"
    assert schema["$id"] == f"urn:foundation-calc:scene:{kind}:v1"
    assert kind in schema["title"]
    assert schema["properties"]["kind"]["const"] == kind
    assert schema["additionalProperties"] is False  # a misspelt key is flagged in the editor too
    for definition in schema["$defs"].values():
        assert definition.get("additionalProperties") is False
        for name, prop in definition["properties"].items():
            assert "[" in prop["description"], (definition["title"], name)  # symbol [unit]: text


def _resolve(schema: dict, node: dict) -> dict:
    ref = node.get("$ref") or next((a["$ref"] for a in node.get("anyOf", ()) if "$ref" in a), None)
    return schema["$defs"][ref.rsplit("/", 1)[-1]] if ref else node


@pytest.mark.parametrize("config", sorted(CONFIGS.glob("*.toml")), ids=lambda p: p.name)
def test_every_key_of_the_shipped_scenes_is_in_the_schema(runner, config):
    """A light structural validation (no jsonschema dependency): keys, required keys, number types."""
    document = read_toml(config)
    schema = _schema(runner, document["kind"])

    def walk(node: dict, values: dict, where: str) -> None:
        assert set(node.get("required", ())) <= set(values), where
        for key, value in values.items():
            assert key in node["properties"], f"{where}{key}"
            prop = _resolve(schema, node["properties"][key])
            if isinstance(value, dict):
                walk(prop, value, f"{where}{key}.")
            elif isinstance(value, list) and value and isinstance(value[0], dict):
                for item in value:
                    walk(_resolve(schema, prop.get("items", {})), item, f"{where}{key}[].")

    walk(schema, document, "")


def test_mass_bound_matches_the_loader(runner):
    schema = _schema(runner, "crank_foundation")
    mass = schema["$defs"]["Foundation"]["properties"]["mass"]  # optional: may come from [foundation.block]
    number = next(branch for branch in mass["anyOf"] if branch.get("type") == "number")
    assert number["exclusiveMinimum"] == 0
    assert "[kg]" in mass["description"]


def test_unknown_kind_is_a_usage_error(runner):
    result = runner.invoke(app, ["schema", "chimney"])
    assert result.exit_code == 2
    assert "crank_foundation" in result.output


@pytest.mark.parametrize("config", sorted(CONFIGS.glob("*.toml")), ids=lambda p: p.name)
def test_shipped_scenes_validate_and_broken_ones_do_not(runner, config):
    """With the jsonschema package (optional, as an editor would use the schema)."""
    jsonschema = pytest.importorskip("jsonschema")
    document = read_toml(config)
    validator = jsonschema.Draft202012Validator(_schema(runner, document["kind"]))
    assert not list(validator.iter_errors(document))
    section = next(k for k, v in document.items() if isinstance(v, dict))
    for broken in ({**document, "kind": "other"}, {**document, section: {**document[section], "typo": 1}}):
        assert list(validator.iter_errors(broken))
