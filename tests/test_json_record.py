"""Every shipped scene's numbers stay put while the models move onto the one rigid body.

Every shipped scene through every command its kind takes, as the command's JSON document
(``fc.resonance``, ``fc.amplitudes`` with and without ``exact``, ``fc.sweep`` over speed and over
soil, ``fc.soil``, ``fc.check``, ``fc.runup`` (8 s up, 12 s down), ``fc.design`` where the scene
has a block, ``fc.platform``), compared with the documents recorded in
``tests/data/json_record.json.gz`` before the crank scene was read as a block with one machine:
every number to 1e-9 of its size (or 1e-12 in SI units, for round-off that should be zero), every
text and key the same; a refusal (an error's class and message) the same. Not a golden value (the
physics is tested against independent solutions elsewhere): a guard that a refactoring changes no
result a user or a CI script reads.

``python3 -m tests.test_json_record`` records the documents again (after a change of a number
that is meant, said in CHANGELOG.md).
"""

from __future__ import annotations

import gzip
import json
import math
from pathlib import Path

import pytest

ROOT = Path(__file__).resolve().parents[1]
RECORD = ROOT / "tests" / "data" / "json_record.json.gz"

#: Keys whose values differ from run to run or from machine to machine.
VOLATILE = frozenset({"fcalc_version", "source", "seconds", "elapsed", "elapsed_seconds", "wall_seconds"})

#: The commands run on each scene of a kind: name -> (API function, keyword arguments); a
#: ``{machine}`` in a value is the scene's first machine.
COMMANDS = {
    "crank_foundation": {
        "resonance": ("resonance", {}),
        "amplitudes": ("amplitudes", {}),
        "amplitudes_exact": ("amplitudes", {"exact": True}),
        "sweep_speed": ("sweep", {"speed": "100:900:41"}),
        "sweep_soil": ("sweep", {"soil": "0.5:1.5:21"}),
        "soil": ("soil", {}),
        "check": ("check", {}),
        "runup": ("runup", {"time": 8.0, "down": 12.0}),
        "design": ("design", {"vary": ["block.length=3:8", "block.width=2:5"], "points": 6}),
    },
    "block_foundation": {
        "resonance": ("resonance", {}),
        "amplitudes": ("amplitudes", {}),
        "sweep_speed": ("sweep", {"speed": "100:3000:31", "machine": "{machine}"}),
        "soil": ("soil", {}),
        "check": ("check", {}),
        "runup": ("runup", {"time": 8.0, "down": 12.0}),
        "design": ("design", {"vary": ["block.length=4:8", "block.width=3:6"], "points": 4}),
    },
    "platform": {
        "platform": ("platform", {}),
        "check": ("check", {}),
        "runup": ("runup", {"time": 8.0, "down": 12.0}),
    },
}


def scene_data(config: str) -> dict:
    """The scene's TOML document."""
    import tomllib

    return tomllib.loads((ROOT / "configs" / config).read_text())


def cases() -> list[tuple[str, str]]:
    """(config, command) of every shipped scene and every command of its kind; design only where
    the scene has a block to size."""
    found = []
    for path in sorted((ROOT / "configs").glob("*.toml")):
        data = scene_data(path.name)
        for command in COMMANDS[data["kind"]]:
            if command != "design" or "block" in data or "block" in data.get("foundation", {}):
                found.append((path.name, command))
    return found


def document(config: str, command: str) -> dict:
    """The command's JSON document of the scene, as ``fcalc COMMAND --json`` prints it, or the
    error it refuses the scene with (its class and message); paths relative to the checkout."""
    import foundation_calc as fc
    from foundation_calc.errors import FcalcError

    data = scene_data(config)
    name, kwargs = COMMANDS[data["kind"]][command]
    if "machines" in data:
        kwargs = {k: v.replace("{machine}", data["machines"][0]["name"]) if isinstance(v, str) else v
                  for k, v in kwargs.items()}
    try:
        found = fc.__getattr__(name)(ROOT / "configs" / config, **kwargs).to_dict()
    except FcalcError as error:
        found = {"error": type(error).__name__, "message": str(error)}
    return json.loads(json.dumps(found).replace(f"{ROOT}/", ""))  # paths as from the checkout's root


def same_phase(old: dict, new: dict) -> bool:
    """Whether the phases of two harmonics (``magnitude`` and ``phase`` [rad]) agree as angles (mod
    2π) to what their values resolve: 1e-9 rad, or the angle 1e-12 (the absolute floor of a
    number in SI units) subtends at the magnitude. The phase of a harmonic the physics makes zero
    is the angle of its round-off, any value; and -π and π are one angle."""
    turn = (new["phase"] - old["phase"] + math.pi) % (2.0 * math.pi) - math.pi
    return abs(turn) <= max(1e-9, 1e-12 / max(min(old["magnitude"], new["magnitude"]), 1e-300))


def error_differences(old: dict, new: dict, exact: dict, path: str) -> list[str]:
    """Where the errors of the approximations' harmonics (``errors.<method>.harmonics``,
    e = |approximation - exact|/|exact| [-]) differ beyond what their values resolve: 1e-9
    relative, or what the absolute floor 1e-12 of the two harmonics (in SI units) makes of e,
    1e-12 (1 + e)/|exact|. A harmonic the physics makes zero is, in the exact solution, the
    round-off of its Newton iteration: its error is a ratio of round-off, any value."""
    found = [f"{path}: keys {sorted(set(old) ^ set(new))}"] if set(old) != set(new) else []
    for key in old.keys() & new.keys():
        a, b = old[key], new[key]
        if not (isinstance(a, float) and isinstance(b, float)):
            found += differences(a, b, f"{path}.{key}")
            continue
        floor = 1e-12 * (1.0 + max(abs(a), abs(b))) / max(exact[key]["magnitude"], 1e-300)
        if abs(a - b) > max(1e-9 * max(abs(a), abs(b)), floor):
            found.append(f"{path}.{key}: {a!r}, now {b!r}")
    return found


def differences(old, new, path="") -> list[str]:
    """Where ``new`` differs from ``old``: numbers beyond 1e-9 relative (1e-12 absolute), a
    harmonic's phase as :func:`same_phase` judges it, any other value or key; volatile keys
    skipped."""
    if isinstance(old, dict) and isinstance(new, dict):
        found = [f"{path}: keys {sorted(set(old) ^ set(new))}"] if set(old) != set(new) else []
        phased = all(isinstance(d.get(k), float) for d in (old, new) for k in ("phase", "magnitude"))
        exact = new.get("approximations", {}).get("exact", {}).get("harmonics") if "errors" in new else None
        for key in old.keys() & new.keys():
            if key in VOLATILE or (phased and key == "phase"):
                continue
            if key == "errors" and exact is not None and isinstance(old[key], dict) and isinstance(new[key], dict):
                for method in sorted(old[key].keys() | new[key].keys()):
                    a, b = old[key].get(method), new[key].get(method)
                    where = f"{path}.errors.{method}"
                    if not (isinstance(a, dict) and isinstance(b, dict)):
                        found += differences(a, b, where)
                        continue
                    for part in sorted(a.keys() | b.keys()):
                        if part == "harmonics":
                            found += error_differences(a[part], b[part], exact, f"{where}.harmonics")
                        else:
                            found += differences(a.get(part), b.get(part), f"{where}.{part}")
                continue
            found += differences(old[key], new[key], f"{path}.{key}")
        if phased and not same_phase(old, new):
            found.append(f"{path}.phase: {old['phase']!r}, now {new['phase']!r}")
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


CASES = cases()


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
