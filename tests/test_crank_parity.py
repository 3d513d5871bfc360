"""The crank foundation's numbers stay put while its model moves onto the one rigid body.

Every shipped ``crank_foundation`` scene through every command's JSON document (``fc.resonance``,
``fc.amplitudes`` with and without ``exact``, ``fc.sweep`` over speed and over soil, ``fc.soil``,
``fc.check``, ``fc.runup`` (8 s up, 12 s down), ``fc.design`` where it has a block),
compared with the documents recorded in ``tests/data/crank_parity.json.gz`` before the crank
scene was read as a block with one machine: every number to 1e-9 of its size (or 1e-12 in SI
units, for round-off that should be zero), every text and key the same. Not a golden value (the
physics is tested against independent solutions elsewhere): a guard that a refactoring changes
no result a user or a CI script reads.

``python3 -m tests.test_crank_parity`` records the documents again (after a change of a number
that is meant, said in CHANGELOG.md).
"""

from __future__ import annotations

import gzip
import json
from pathlib import Path

import pytest

ROOT = Path(__file__).resolve().parents[1]
RECORD = ROOT / "tests" / "data" / "crank_parity.json.gz"

#: Keys whose values differ from run to run or from machine to machine.
VOLATILE = frozenset({"fcalc_version", "source", "seconds", "elapsed", "elapsed_seconds", "wall_seconds"})

#: The commands run on each scene: name -> (API function, keyword arguments, applies(scene)).
COMMANDS = {
    "resonance": ("resonance", {}, None),
    "amplitudes": ("amplitudes", {}, None),
    "amplitudes_exact": ("amplitudes", {"exact": True}, None),
    "sweep_speed": ("sweep", {"speed": "100:900:41"}, None),
    "sweep_soil": ("sweep", {"soil": "0.5:1.5:21"}, None),
    "soil": ("soil", {}, None),
    "check": ("check", {}, None),
    "runup": ("runup", {"time": 8.0, "down": 12.0}, None),
    "design": ("design", {"vary": ["block.length=3:8", "block.width=2:5"], "points": 6}, "block"),
}


def crank_configs() -> list[str]:
    """The shipped scenes of kind crank_foundation, by name."""
    return sorted(p.name for p in (ROOT / "configs").glob("*.toml") if 'kind = "crank_foundation"' in p.read_text())


def applies(config: str, need: str | None) -> bool:
    """True when the scene has what the command needs (its ``[operation]``, its ``[foundation.block]``)."""
    import tomllib

    if need is None:
        return True
    data = tomllib.loads((ROOT / "configs" / config).read_text())
    return need in data or need in data.get("foundation", {})


def document(config: str, command: str) -> dict:
    """The command's JSON document of the scene, as ``fcalc COMMAND --json`` prints it, or the
    error it refuses the scene with (its class and message)."""
    import foundation_calc as fc
    from foundation_calc.errors import FcalcError

    name, kwargs, _ = COMMANDS[command]
    try:
        return fc.__getattr__(name)(ROOT / "configs" / config, **kwargs).to_dict()
    except FcalcError as error:
        return {"error": type(error).__name__, "message": str(error)}


def differences(old, new, path="") -> list[str]:
    """Where ``new`` differs from ``old``: numbers beyond 1e-9 relative (1e-12 absolute), any
    other value or key; volatile keys skipped."""
    if isinstance(old, dict) and isinstance(new, dict):
        found = [f"{path}: keys {sorted(set(old) ^ set(new))}"] if set(old) != set(new) else []
        for key in old.keys() & new.keys():
            if key not in VOLATILE:
                found += differences(old[key], new[key], f"{path}.{key}")
        return found
    if isinstance(old, list) and isinstance(new, list):
        if len(old) != len(new):
            return [f"{path}: {len(old)} items, now {len(new)}"]
        return [d for i, (a, b) in enumerate(zip(old, new)) for d in differences(a, b, f"{path}[{i}]")]
    numbers = (int, float)
    if isinstance(old, numbers) and isinstance(new, numbers) and not isinstance(old, bool) and not isinstance(new, bool):
        if abs(old - new) <= max(1e-9 * max(abs(old), abs(new)), 1e-12):
            return []
        return [f"{path}: {old!r}, now {new!r}"]
    return [] if old == new else [f"{path}: {old!r}, now {new!r}"]


CASES = [(c, k) for c in crank_configs() for k, (_, _, need) in COMMANDS.items() if applies(c, need)]


@pytest.fixture(scope="module")
def recorded() -> dict:
    with gzip.open(RECORD, "rt", encoding="utf-8") as f:
        return json.load(f)


def test_every_case_is_recorded(recorded):
    """A new shipped crank scene or command is recorded before it is guarded."""
    assert sorted(recorded) == sorted(f"{c} {k}" for c, k in CASES)


@pytest.mark.parametrize("config,command", CASES, ids=[f"{c[:-5]}-{k}" for c, k in CASES])
def test_same_numbers_as_recorded(recorded, config, command):
    found = differences(recorded[f"{config} {command}"], document(config, command))
    assert not found, "\n".join(found[:20])


def record() -> None:
    """Write every case's document to :data:`RECORD`."""
    RECORD.parent.mkdir(exist_ok=True)
    documents = {f"{c} {k}": document(c, k) for c, k in CASES}
    with gzip.open(RECORD, "wt", encoding="utf-8") as f:
        json.dump(documents, f, sort_keys=True)


if __name__ == "__main__":
    record()
