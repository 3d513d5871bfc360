"""The scene's inputs echoed on a sheet: key, symbol, value and unit from the scene model itself.

Every scene field's description starts with ``symbol [unit]:``, so the sheet, the JSON schema
and the tables share one source. Limits on amplitudes, velocities and accelerations and the
platform's amplitude are shown in the chosen display units; everything else as given (SI). A
number the scene wrote with its unit (``length = "6000 mm"``) is shown in the key's unit with
what was written beside it: ``6 (written 6000 mm)``.
"""

from __future__ import annotations

import re

from pydantic import BaseModel

from foundation_calc.output.display_units import DisplayUnits
from foundation_calc.scenes.common import LimitSources
from foundation_calc.output.report.model import Paragraph, Section, table
from foundation_calc.output.report.numbers import echoed

_DESCRIPTION = re.compile(r"^\s*(?P<symbol>.*?)\s*\[(?P<unit>[^\]]*)\]\s*:\s*(?P<meaning>.*)$", re.S)

#: (group, key) -> display quantity of the fields shown in the chosen units.
DISPLAYED = {
    ("limits", "amplitude"): "amplitude",
    ("limits", "transient_amplitude"): "amplitude",
    ("limits", "settlement"): "amplitude",
    ("limits", "velocity"): "velocity",
    ("limits", "velocity_rms"): "velocity",
    ("limits", "acceleration"): "acceleration",
    ("limits", "acceleration_rms"): "acceleration",
    ("operation", "amplitude"): "amplitude",
}


def _value(value) -> str:
    if isinstance(value, float):
        return echoed(value)
    if isinstance(value, (list, tuple)):
        return ", ".join(map(_value, value)) if value else "none"
    return str(value)


def _shown(value, path: str, written: dict[str, str]) -> str:
    """The value of the key at ``path`` (dotted, from the scene's top), and, when the scene wrote
    it (or an element of it) with a unit, what was written: ``6000, 0, 2000 (written 6 kN, 0, 2 kN)``."""
    if isinstance(value, (list, tuple)):
        texts = [written.get(f"{path}.{i}") for i in range(len(value))]
        as_written = ", ".join(text or _value(item) for text, item in zip(texts, value)) if any(texts) else None
    else:
        as_written = written.get(path)
    return _value(value) if as_written is None else f"{_value(value)} (written {as_written})"


def _entries(value) -> bool:
    """True for a list of nested tables (a machine's ``loads``): shown as a table of its own."""
    return isinstance(value, (list, tuple)) and bool(value) and all(isinstance(v, BaseModel) for v in value)


def _described(field) -> tuple[str, str, str]:
    match = _DESCRIPTION.match(field.description or "")
    return match.group("symbol", "unit", "meaning") if match else ("", "", field.description or "")


def _columns(model_type, prefix: str = ""):
    """(label, path, field) of every key of an entry; a nested table's keys as ``at.height``."""
    for key, field in model_type.model_fields.items():
        nested = field.annotation if isinstance(field.annotation, type) and issubclass(field.annotation, BaseModel) else None
        if nested is not None:
            yield from _columns(nested, f"{prefix}{key}.")
        else:
            yield f"{prefix}{key}", field


def _flat(items) -> bool:
    """True when every column of every entry holds a plain value (no list of tables, no optional
    nested table): the entries fit one table, a row each."""
    return not any(isinstance(_get(item, path), BaseModel) or _entries(_get(item, path))
                   for item in items for path, _ in _columns(type(item)))


def _get(model, path: str):
    for key in path.split("."):
        model = getattr(model, key)
    return model


def _entries_table(title: str, items, path: str, written: dict[str, str]) -> tuple:
    """A row per entry and a column per key, headed ``key [unit]`` (loads, points), then what each
    key means, as one line; ``path`` is the entries' dotted path in the scene (``machines.0.loads``)."""
    columns = list(_columns(type(items[0])))
    header = tuple(path if _described(f)[1] in ("", "-") else f"{path} [{_described(f)[1]}]" for path, f in columns)
    rows = [tuple("-" if _get(item, key) is None else _shown(_get(item, key), f"{path}.{i}.{key}", written) for key, _ in columns)
            for i, item in enumerate(items)]
    numeric = tuple(not isinstance(_get(items[0], path), str) for path, _ in columns)
    meanings = "; ".join(f"{path}{'' if _described(f)[0] in ('', '-') else ' (' + _described(f)[0] + ')'}: {_described(f)[2]}"
                         for path, f in columns)
    return table(title, header, rows, numeric), Paragraph(meanings + ".")


def _rows(group: str, model: BaseModel, units: DisplayUnits, path: str, written: dict[str, str]):
    for key, field in type(model).model_fields.items():
        value = getattr(model, key)
        if value is None or isinstance(value, BaseModel) or _entries(value):  # a nested table has its own block
            continue
        symbol, unit, meaning = _described(field)
        if isinstance(model, LimitSources):  # each limit's source beside it, not as a table of its own
            if key == "sources":
                continue
            meaning = f"{meaning}; source: {model.source_of(key)}"
        quantity = DISPLAYED.get((group.split("[")[0], key))
        if quantity is not None and isinstance(value, float):
            value, unit = units.convert(quantity, value), units.label(quantity)
        yield (key, symbol, _shown(value, f"{path}{key}", written), unit, meaning)


def inputs_section(scene: BaseModel, units: DisplayUnits, written: dict[str, str] | None = None) -> Section:
    """One table per group of the scene (``[foundation]``, ``[[points]]``…), as the model holds it;
    ``written``: the values the scene wrote with a unit, by dotted key (``block.length``)."""
    written = written or {}
    header = ("key", "symbol", "value", "unit", "meaning")
    blocks = []
    for name in type(scene).model_fields:
        if name == "project":  # the title block shows it
            continue
        value = getattr(scene, name)
        groups = [(f"[{name}]", value, f"{name}.")] if isinstance(value, BaseModel) else []
        groups += [
            (f"[{name}.{key}]", getattr(value, key), f"{name}.{key}.")
            for key in (type(value).model_fields if isinstance(value, BaseModel) else ())
            if isinstance(getattr(value, key), BaseModel)
        ]
        if _entries(value) and _flat(value):  # [[loads]], [[points]]: one table, a row per entry
            blocks += _entries_table(f"[[{name}]]", value, name, written)
            continue
        if isinstance(value, (list, tuple)):
            groups = [(f"[[{name}]] {i + 1}", item, f"{name}.{i}.") for i, item in enumerate(value) if isinstance(item, BaseModel)]
        for title, model, path in groups:
            rows = list(_rows(title.strip("[]").split("]")[0], model, units, path, written))
            blocks.append(table(title, header, rows, (False, False, True, False, False), literal=(0,)))
            for key in type(model).model_fields:
                if _entries(getattr(model, key)):
                    blocks += _entries_table(f"{title} {key}", getattr(model, key), f"{path}{key}", written)
                elif title.startswith("[[") and isinstance(getattr(model, key), BaseModel):  # [machines.unbalance]
                    nested = list(_rows(title.strip("[]").split("]")[0], getattr(model, key), units, f"{path}{key}.", written))
                    blocks.append(table(f"{title} {key}", header, nested, (False, False, True, False, False), literal=(0,)))
        if name == _springs_after(scene):
            blocks.append(_springs_table(scene))
    return Section("Inputs (the scene as validated)", tuple(blocks))


def _springs_after(scene) -> str | None:
    """The group of a crank scene's inputs its springs' table follows: ``[soil]``, or the support's
    own (``[piles]``) for a support without a soil method's chain in the plane; None for another kind."""
    if not hasattr(scene, "soil_springs"):
        return None
    from foundation_calc.output.report.plane_support import by_soil_method

    label = "soil" if by_soil_method(scene) else scene.support().label
    return label if label in type(scene).model_fields else "soil"


def _springs_table(scene) -> object:
    """The base springs and damping ratios the scene's soil method gives (what the solvers use); a
    support without a soil method's chain in the plane (a pile group): its springs and dashpots at O
    at rest (:func:`~foundation_calc.output.report.plane_support.rest_table`)."""
    from foundation_calc.output.report.plane_support import by_soil_method, rest_table

    if not by_soil_method(scene):
        return rest_table(scene)
    springs = scene.soil_springs()
    rows = [
        ("K_z", "vertical spring", "N/m"), ("K_x", "horizontal spring at the base", "N/m"),
        ("K_phi", "rocking spring about the base axis", "N m/rad"), ("xi_z", "vertical damping ratio", "-"),
        ("xi_x", "horizontal damping ratio", "-"), ("xi_phi", "rocking damping ratio", "-"),
    ]
    return table(
        f"[soil] springs by method {scene.soil.method_used!r}",
        ("quantity", "value", "unit", "meaning"),
        [(key, _value(float(getattr(springs, key))), unit, meaning) for key, meaning, unit in rows],
        (False, True, False, False), literal=(0,),
    )
