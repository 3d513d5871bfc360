"""``fc.sweep``: amplitudes and verdicts along a speed or soil sweep (``fcalc sweep``), as
arrays and, with pandas, a DataFrame."""

from __future__ import annotations

import re
from dataclasses import dataclass
from typing import Any

from foundation_calc.api.resonance import KINDS
from foundation_calc.api.result import Result, command_result
from foundation_calc.api.scene import Scene, scene_of

#: Unit suffixes accepted after a speed range -> display unit label.
SPEED_UNITS = {"rpm": "rpm", "rad/s": "rad/s", "hz": "Hz"}
DEFAULT_POINTS = 101
MAX_POINTS = 100_000
#: What ``to_frame`` needs and how to get it.
PANDAS_HINT = 'to_frame() needs pandas: python3 -m pip install "foundation_calc[frame]" (or pandas itself)'

_RANGE = re.compile(r"^\s*([^:\s]+?)\s*(?::\s*([^:\s]+?)\s*(?::\s*(\d+))?)?\s*([a-zA-Z/]*)\s*$")


def parse_range(text: str, option: str, units: dict[str, str] | None = None, default_unit: str = "") -> tuple[float, float, int, str]:
    """``FROM:TO[:N][UNIT]`` or ``VALUE[UNIT]`` (one point) -> (from, to, n, unit label); a
    :class:`~foundation_calc.errors.UsageError` names the option.

    >>> parse_range("250", "--speed", SPEED_UNITS, "rpm"), parse_range("10:60:6rad/s", "--speed", SPEED_UNITS, "rpm")
    ((250.0, 250.0, 1, 'rpm'), (10.0, 60.0, 6, 'rad/s'))
    """
    from foundation_calc.errors import UsageError

    def bad(message: str) -> UsageError:
        return UsageError(message, f"'{option}'")

    match = _RANGE.match(text)
    if not match:
        raise bad(f"{text!r} is not FROM:TO[:N] or one value, e.g. 100:600:251 or 250")
    lo_text, hi_text, n_text, unit = match.groups()
    hi_text = lo_text if hi_text is None else hi_text  # one value: a single-point sweep
    try:
        lo, hi = float(lo_text), float(hi_text)
    except ValueError:
        raise bad(f"{text!r}: FROM and TO must be numbers") from None
    if units is None and unit:
        raise bad(f"{text!r}: a factor takes no unit")
    if units is not None:
        if unit and unit.lower() not in units:
            raise bad(f"unknown unit {unit!r}; use one of {', '.join(units)}")
        unit = units[unit.lower()] if unit else default_unit
    if lo == hi:
        n = int(n_text) if n_text else 1
        if n != 1:
            raise bad(f"{text!r}: FROM = TO is one point; N must be 1 (or leave it out)")
    else:
        n = int(n_text) if n_text else DEFAULT_POINTS
    if not (0.0 < lo <= hi < float("inf")):
        raise bad(f"{text!r}: need 0 < FROM <= TO (finite numbers)")
    if lo < hi and not 2 <= n <= MAX_POINTS:
        raise bad(f"{text!r}: N must be between 2 and {MAX_POINTS}")
    return lo, hi, n, unit


@dataclass(frozen=True)
class Plan:
    """A sweep asked for, options checked and scene loaded: ``variable`` (``"omega"`` [rad/s] or
    ``"soil_factor"`` [-]) over ``values``, the unit the speed range was written in (``""`` for a
    factor), and for a block the index of the swept machine and whether it runs ``alone``."""

    scene: Scene
    variable: str
    values: Any
    unit: str
    machine: int | None = None
    alone: bool = False


def plan(scene, speed: str | float | None = None, soil: str | float | None = None, machine: str | None = None,
         alone: bool = False) -> Plan:
    """The :class:`Plan` of ``fc.sweep``'s arguments (see there); the options are checked before
    the scene is read, as the command checks them."""
    import numpy as np

    from foundation_calc.errors import UsageError

    if (speed is None) == (soil is None):
        raise UsageError("give exactly one of --speed and --soil", "'--speed' / '--soil'")
    if speed is not None:
        from foundation_calc.units import omega_from_hz, omega_from_rpm

        lo, hi, n, unit = parse_range(str(speed), "--speed", SPEED_UNITS, "rpm")
        to_omega = {"rpm": omega_from_rpm, "Hz": omega_from_hz, "rad/s": lambda v: v}[unit]
        variable, values = "omega", to_omega(np.linspace(lo, hi, n))
    else:
        lo, hi, n, unit = parse_range(str(soil), "--soil")
        variable, values = "soil_factor", np.linspace(lo, hi, n)
    loaded = scene_of(scene, KINDS, platform_as_block=True)
    if loaded.kind != "block_foundation":
        if machine is not None or alone:
            raise UsageError("--machine and --alone choose among the machines of a block_foundation scene",
                             "'--machine'" if machine is not None else "'--alone'")
        return Plan(loaded, variable, values, unit)
    if variable != "omega":
        from foundation_calc.checks.sweep.block import refusal

        if machine is not None or alone:
            raise UsageError("--machine and --alone choose the machine whose speed is swept; a soil sweep runs every"
                             " machine at its own speed", "'--machine'" if machine is not None else "'--alone'")
        if (why := refusal(loaded.model)) is not None:
            raise UsageError(why, "'--soil'")
        return Plan(loaded, variable, values, unit)
    names = [m.name for m in loaded.model.machines]
    if machine is None and len(names) > 1:
        raise UsageError(f"the scene has {len(names)} machines: name the one to sweep ({', '.join(names)})", "'--machine'")
    if machine is not None and machine not in names:
        import difflib

        close = difflib.get_close_matches(machine, names, n=1)
        hint = f" (did you mean {close[0]!r}?)" if close else ""
        raise UsageError(f"no machine {machine!r}{hint}; the scene's machines: {', '.join(names)}", "'--machine'")
    return Plan(loaded, variable, values, unit, names.index(machine) if machine is not None else 0, alone)


def chunks(planned: Plan):
    """The sweep of a crank scene's :class:`Plan` in chunks (memory: one chunk at a time)."""
    from foundation_calc.checks.sweep.crank import scene_sweep_chunks

    return scene_sweep_chunks(planned.scene.model, planned.variable, planned.values)


def swept(planned: Plan, report=None) -> "SweepResult":
    """The :class:`SweepResult` of a :class:`Plan`; ``report``: a crank sweep's report when the
    caller has joined its :func:`chunks` already."""
    from foundation_calc.checks.sweep import scene_sweep
    from foundation_calc.output.sweep import sweep_document

    model = planned.scene.model
    if report is None:
        report = scene_sweep(model, planned.variable, planned.values, planned.machine, planned.alone)
    document = sweep_document(report, model, planned.scene.source)
    result = command_result("sweep", document, 0, planned.scene, report)
    return SweepResult(**{name: getattr(result, name) for name in result.__dataclass_fields__}, variable=planned.variable)


def sweep(scene, *, speed: str | float | None = None, soil: str | float | None = None, machine: str | None = None,
          alone: bool = False) -> "SweepResult":
    """Amplitudes along a sweep of the speed or of a factor on the soil, each point judged (the
    resonance condition that governs there with its margin, and every limit exceeded). A picture,
    not a check: the exit code is 0.

    Parameters
    ----------
    scene : Scene, path or mapping
        A ``crank_foundation`` or ``block_foundation`` scene (:func:`~foundation_calc.api.scene.load`),
        or a ``platform`` read as its block on its isolators (:meth:`~foundation_calc.scenes.platform.PlatformScene.as_block`).
    speed : str or float, optional
        ``--speed``: ``"FROM:TO[:N][UNIT]"``, N points (default 101) in rpm unless a unit follows
        (rpm, rad/s, hz), e.g. ``"100:600:251"`` or ``"10:60rad/s"``; one value is one point.
    soil : str or float, optional
        ``--soil``: ``"FROM:TO[:N]"``, a factor on the soil's stiffness data [-] (Barkan's
        coefficients; G, or V_s by its square root; SP 26's E; a block's given springs, their
        dashpots by its square root; a pile group recomputed from its factored soil), e.g.
        ``"0.5:1.5:41"``; not for a block on ``[[isolators]]``. Give exactly one of ``speed`` and
        ``soil``.
    machine : str, optional
        ``--machine``: a block's machine whose speed is swept (needed when it has several; not
        with ``soil``: every machine then runs at its own speed).
    alone : bool
        ``--alone``: a block's swept machine alone, the others standing still (not with ``soil``).

    Returns
    -------
    SweepResult
        ``to_dict()`` is the document of ``fcalc sweep --json``; ``columns`` its points as
        arrays, ``to_frame()`` as a pandas DataFrame.

    Raises
    ------
    SceneError
        An invalid scene, or a scene of another kind.
    UsageError
        A range that cannot be read, both or neither of ``speed`` and ``soil``, a machine the scene
        does not have.
    """
    return swept(plan(scene, speed, soil, machine, alone))


@dataclass(frozen=True, eq=False)
class SweepResult(Result):
    """A :class:`~foundation_calc.api.result.Result` of ``sweep`` whose points are also arrays.

    ``variable`` is the swept quantity: ``"omega"`` [rad/s] or ``"soil_factor"`` [-].
    """

    variable: str = "omega"

    @property
    def columns(self) -> dict[str, Any]:
        """The document's ``points`` as one numpy array per key, SI units: nested keys joined by
        ``.`` (``harmonics.y1.amplitude``, ``peak.x``); numbers as floats (NaN where a point has
        none, e.g. a resonant point's amplitudes), flags as booleans, texts and lists as objects."""
        return columns(self.document["points"])

    @property
    def values(self):
        """The swept values: the speeds [rad/s] or the soil factors [-]."""
        return self.columns[self.variable]

    def to_frame(self):
        """:attr:`columns` as a pandas DataFrame, one row per point.

        Raises
        ------
        ImportError
            pandas is not installed (the optional ``frame`` extra).
        """
        try:
            import pandas
        except ImportError as exc:
            raise ImportError(PANDAS_HINT) from exc
        return pandas.DataFrame(self.columns)


def flat(row: dict, prefix: str = "") -> dict:
    """A row with its nested dicts' keys joined by ``.``.

    >>> flat({"omega": 1.0, "peak": {"x": 2.0, "y": None}, "over_limits": []})
    {'omega': 1.0, 'peak.x': 2.0, 'peak.y': None, 'over_limits': []}
    """
    out = {}
    for key, value in row.items():
        if isinstance(value, dict):
            out.update(flat(value, f"{prefix}{key}."))
        else:
            out[f"{prefix}{key}"] = value
    return out


def columns(rows: list[dict]) -> dict[str, Any]:
    """``rows`` (dicts, nested ones :func:`flat`) as one array per key, keys in the order first
    met: floats with NaN for a missing or null value, booleans, or objects (texts, lists).

    >>> cols = columns([{"omega": 1.0, "x": None, "ok": True}, {"omega": 2.0, "x": 3.0, "ok": False}])
    >>> cols["omega"].tolist(), cols["x"].tolist(), cols["ok"].dtype.name
    ([1.0, 2.0], [nan, 3.0], 'bool')
    """
    import numpy as np

    flats = [flat(row) for row in rows]
    keys = list(dict.fromkeys(key for row in flats for key in row))
    out = {}
    for key in keys:
        cells = [row.get(key) for row in flats]
        present = [c for c in cells if c is not None]
        if present and all(isinstance(c, bool) for c in cells):
            out[key] = np.array(cells, dtype=bool)
        elif all(isinstance(c, (int, float)) and not isinstance(c, bool) for c in present):
            out[key] = np.array([np.nan if c is None else c for c in cells], dtype=float)
        else:
            out[key] = np.empty(len(cells), dtype=object)
            out[key][:] = cells
    return out
