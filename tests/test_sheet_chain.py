"""Every judged number of every shipped scene's sheet follows from numbers printed on the same sheet.

Each sheet keeps its chain beside it (``output/report/chain.py``): for each judged number, the
formula's name and the cells that print its inputs. This test reads the sheet as a user gets it
(Markdown, HTML and the PDF's typst source), finds each cell (a missing one fails), and recomputes
each judged number from the printed inputs by its own transcription of the formula, never the
report's code. Tolerance: the printed precision. Each input is off by at most half a unit of its
last printed digit (a phase by 0.05°); the recomputed number moves by at most the sum of what each
such error moves it (first order, × 1.5 for the curvature of a quotient or a peak), and the result
is itself rounded by half a unit of its last digit. The scene's own inputs ([…] tables) are exact.

Numbers of a numerical solution (the run-up's time integration, the platform's harmonic balance)
are not closed forms of printed values: their links must cite the table that states them, and
they are listed in NUMERICAL (item 5 of issue 32 gives the run-up passages their closed form).
"""

from __future__ import annotations

import math
import re

import numpy as np
import pytest

from tests.conftest import sheet_configs
from tests.sheet_numbers import NUMBER, _SUPERSCRIPTS
from tests.sheet_reader import READERS, NotPrinted, cell_texts

SCENES = [p.stem for p in sheet_configs()]
FORMATS = tuple(READERS)

#: Formulas whose number is a numerical solution stated on the sheet, not recomputed here.
NUMERICAL = {"integration", "harmonic balance"}

#: SI factor of each unit a sheet prints after a number.
UNITS = {
    "µm": 1e-6, "mm/s": 1e-3, "mm": 1e-3, "m/s²": 1.0, "m/s": 1.0, "m²": 1.0, "m": 1.0, "kPa": 1e3, "Pa": 1.0,
    "kN": 1e3, "N/m": 1.0, "N m": 1.0, "N": 1.0, "t": 1e3, "kg": 1.0, "%": 1e-2, "rad/s": 1.0, "rad": 1.0,
}
_UNIT = re.compile(r"\s*(" + "|".join(re.escape(u) for u in sorted(UNITS, key=len, reverse=True)) + r")(?![\w/²])")
PHASE_HALF_ULP = 0.05  # degrees: phases print to 0.1°


class Printed(float):
    """A printed number in SI with ``half`` its rounding (half a unit of its last digit, SI)."""

    half: float

    def __new__(cls, value: float, half: float):
        self = super().__new__(cls, value)
        self.half = half
        return self


def _number(text: str, index: int = 0, exact: bool = False, raw: bool = False) -> Printed:
    """The ``index``-th number of ``text`` with the unit printed after it (SI unless ``raw``)."""
    text = text.replace("−", "-")
    found = list(NUMBER.finditer(text))
    if len(found) <= index:
        raise NotPrinted(f"no number {index} in {text!r}")
    match = found[index]
    literal = match.group(0)
    mantissa, _, power = literal.replace("e", "·10").partition("·10")
    exponent = int(power.translate(_SUPERSCRIPTS)) if power else 0
    decimals = len(mantissa.split(".")[1]) if "." in mantissa else 0
    value = float(mantissa) * 10.0**exponent
    half = 0.0 if exact else 0.5 * 10.0 ** (exponent - decimals)
    unit = _UNIT.match(text, match.end())
    factor = 1.0 if raw or unit is None else UNITS[unit.group(1)]
    return Printed(value * factor, half * factor)


def _phasor(text: str) -> tuple[float, float]:
    """A printed ``|z| ∠φ°`` (phase lag, Re(z e^{iΩt}) = |z| cos(Ωt − φ)) as (|z|, φ [°])."""
    if "∠" not in text:
        return _number(text), 0.0
    size, lag = text.split("∠")
    return _number(size), float(lag.rstrip("°").replace("−", "-"))


# --------------------------------------------------------------------------- transcriptions


def _item_parts(item: str) -> tuple[str, str, str]:
    """(point, direction, quantity) of an amplitude row: "G, x: peak displacement" or a code zone's
    "fan bearing RMS velocity (y), zone A"."""
    zone = re.match(r"^(.*) RMS (velocity|displacement) \((\w+)\), zone", item)
    if zone:
        return zone.group(1), zone.group(3), "RMS " + zone.group(2)
    head, quantity = item.rsplit(": ", 1)
    point, direction = head.rsplit(", ", 1)
    return point, direction, quantity


def _order(quantity: str) -> int:
    return {"displacement": 0, "velocity": 1, "acceleration": 2}[quantity.split()[-1]]


#: One revolution of a machine's shaft, ωt: a peak sampled at 1024 steps is low by at most
#: (n Δτ)²/8 ≈ 2·10⁻⁴ of it for the orders n ≤ 4 printed, a tenth of the printed precision.
TAU = np.linspace(0.0, 2.0 * np.pi, 1025)


def _series_peak(orders: list[tuple[float, float, complex]], k: int, rms: bool) -> float:
    """(n, Ω, u_n) of one shaft: the peak over a revolution of Σ Re((iΩ)^k u_n e^{i n ωt}), or
    Σ |Ω^k u_n|²/2 (to be added over machines and rooted) for an RMS."""
    if rms:
        return sum(abs(W**k * u) ** 2 / 2.0 for n, W, u in orders if n > 0)
    series = sum(((1j * W) ** k * u * np.exp(1j * n * TAU)).real for n, W, u in orders)
    return float(np.abs(series).max()) if np.ndim(series) else abs(series)


def _block_motion(values: dict, parts, direction: str, k: int, rms: bool) -> float:
    """A block point's peak (peaks of the machines added) or RMS of derivative ``k``."""
    axis = "xyz".index(direction)
    if "M" in values:  # G from M's first moments: (M x_G, M y_G, M z_G)/M
        r = np.array([values["M x_G"], -values["−M y_G"], values["M z_G"]]) / values["M"]
    else:
        r = np.array([values["r_x"], values["r_y"], values["r_z"]])
    machines: dict[str, list] = {}
    for row in values["Z"]:
        Z = np.array([abs_ * np.exp(-1j * math.radians(lag)) for abs_, lag in row["Z"]])
        u = Z[:3] + np.cross(Z[3:], r)
        machines.setdefault(row["machine"], []).append((row["n"], row["Ω"], u[axis]))
    total = [_series_peak(orders, k, rms) for orders in machines.values()]
    return math.sqrt(sum(total)) if rms else sum(total)


def _crank_motion(values: dict, direction: str, k: int, rms: bool) -> float:
    """A crank point's x + height·θ (horizontal) or y + horizontal·θ (vertical), peak or RMS."""
    orders = []
    for row in values["Z"]:
        x, y, th = (abs_ * np.exp(-1j * math.radians(lag)) for abs_, lag in row["Z"])
        u = x + values.get("height", 0.0) * th if direction == "horizontal" else y + values.get("horizontal", 0.0) * th
        orders.append((row["n"], row["Ω"], u))
    value = _series_peak(orders, k, rms)
    return math.sqrt(value) if rms else value


def recompute(formula: str, values: dict) -> float:
    """The judged number from the printed inputs ``values`` (SI), by the formula's name."""
    if formula == "ratio":
        value, limit = values["value"], values["limit"]
        return limit / value if values["at least"] else value / limit
    if formula in ("detuning", "closest detuning"):
        omega = values["n_rpm"] * math.pi / 30.0 if "n_rpm" in values else values["ω"]
        n = int(re.search(r"(\d*)ω =", values["condition"]).group(1) or 1) if "condition" in values else 1
        margins = [abs(omega - p / n) / (p / n) for p in values["p"]]
        return min(margins)  # the nearer critical speed (a crank's two), or the closest mode
    if formula == "quotient":
        return values["a"] / values["b"] if "b" in values else values["a"]
    if formula == "bearing pressure":
        L, B = values["L"], values["B"]
        return values["W"] / (L * B) * (1 + 6 * abs(values["e_x"]) / L + 6 * abs(values["e_y"]) / B)
    if formula == "maximum":
        return max(values["x"])
    point, direction, quantity = _item_parts(values["item"])
    rms = quantity.startswith("RMS")
    if formula in ("block peak", "block rms"):
        return _block_motion(values, point, direction, _order(quantity), rms)
    if formula in ("crank peak", "crank rms"):
        return _crank_motion(values, direction, _order(quantity), rms)
    raise AssertionError(f"no transcription of formula {formula!r}")


# --------------------------------------------------------------------------- reading the inputs


def _exact(cell: dict) -> bool:
    """The scene's own inputs, echoed as given (an inputs table's title starts with "[")."""
    return cell["table"].startswith("[")


def _z_rows(rows: list[dict]) -> list[dict]:
    """A Z table's rows: machine (a block's), n, Ω [rad/s], the printed (|z|, φ) per coordinate."""
    out = []
    for row in rows:
        omega = next(v for h, v in row.items() if h.startswith(("Ω = nω", "nω")))
        coordinates = [h for h in row if h in ("u_x", "u_y", "u_z", "θ_x", "θ_y", "θ_z", "x_n [m]", "y_n [m]", "θ_n [rad]")]
        out.append({"machine": row.get("machine", ""), "n": int(row["n"]), "Ω": _number(omega),
                    "Z": [_phasor(row[h]) for h in coordinates]})
    return out


def read_inputs(sheet, link: dict) -> tuple[dict, list]:
    """The link's inputs as printed, and the roundings a checker perturbs: (symbol, index, half)."""
    values: dict = {}
    for name, cell in link["inputs"]:
        text = cell_texts(sheet, cell)
        if name == "Z":
            values["Z"] = _z_rows(text)
        elif name in ("condition", "item"):
            values[name] = text
        elif name in ("p", "x"):
            found = [r for r in (text if isinstance(text, list) else [text])]
            for entry in found:
                for t in (entry.values() if isinstance(entry, dict) else [entry]):
                    if NUMBER.search(t.replace("−", "-")):
                        values.setdefault(name, []).append(_number(t, raw=(name == "x")))
        elif name == "peaks" or name == "torque" or name == "rocking":
            values[name] = text  # a numerical solution's table: its cells must be printed
        else:
            values[name] = _number(text, cell.get("index", 0), exact=_exact(cell))
    return values, link["formula"]


def _perturbed(values: dict):
    """Each rounding of an input in turn: ``values`` with that input moved by its half unit."""
    for name, v in values.items():
        if isinstance(v, Printed) and v.half:
            yield {**values, name: Printed(v + v.half, 0.0)}
        elif name in ("p", "x"):
            for j, x in enumerate(v):
                if x.half:
                    yield {**values, name: [*v[:j], Printed(x + x.half, 0.0), *v[j + 1:]]}
        elif name == "Z":
            for r, row in enumerate(v):
                for c, (size, lag) in enumerate(row["Z"]):
                    for moved in ((Printed(size + size.half, 0.0), lag), (size, lag + PHASE_HALF_ULP)):
                        rows = [dict(x) for x in v]
                        rows[r]["Z"] = [*row["Z"][:c], moved, *row["Z"][c + 1:]]
                        yield {**values, "Z": rows}


# --------------------------------------------------------------------------- the sheets


@pytest.fixture(scope="module")
def sheets(shipped_sheets):
    """Each shipped scene's sheet in every format, read back as a checker reads it."""
    return {name: {fmt: READERS[fmt](texts[fmt]) for fmt in FORMATS} for name, texts in shipped_sheets.items()}


_RECOMPUTED: dict[str, tuple[float, float]] = {}


def _recomputed(formula: str, values: dict) -> tuple[float, float]:
    """The number and the bound of its printed inputs' rounding (module docstring); the formats
    print the same texts, so each is computed once."""
    key = repr((formula, sorted((k, repr(v)) for k, v in values.items())))
    if key not in _RECOMPUTED:
        got = recompute(formula, values)
        _RECOMPUTED[key] = got, 1.5 * sum(abs(recompute(formula, moved) - got) for moved in _perturbed(values))
    return _RECOMPUTED[key]


def _judged_rows(sheet) -> list[list[str]]:
    table = next(t for t in sheet.tables() if t.title.startswith("Every check"))
    return [r for r in table.rows if NUMBER.search(r[2].replace("−", "-"))]


@pytest.mark.parametrize("fmt", FORMATS)
@pytest.mark.parametrize("name", SCENES)
def test_every_judged_number_follows_from_the_sheet(sheets, name, fmt):
    """Every value and ratio of the Checks table is a link's result, each link's inputs are printed
    on the sheet, and the formula on the printed inputs gives the printed number."""
    sheet = sheets[name][fmt]
    links = sheet.chain["links"]
    results = {(tuple(l["result"]["row"]), l["result"]["column"]) for l in links}
    for row in _judged_rows(sheet):
        assert ((row[0], row[1]), "value") in results, f"{name}: no chain for {row[:3]}"
        if row[4] not in ("-", "inf"):
            assert ((row[0], row[1]), "ratio") in results, f"{name}: no chain for the ratio of {row[:3]}"
    for link in links:
        printed_text = cell_texts(sheet, link["result"])
        values, formula = read_inputs(sheet, link)  # NotPrinted: an input missing from the sheet
        if formula in NUMERICAL:
            continue
        raw = formula == "maximum"
        if formula == "ratio":
            values["at least"] = cell_texts(sheet, dict(link["inputs"])["limit"]).startswith("≥")
        shown = _number(printed_text, raw=raw)
        got, bound = _recomputed(formula, values)
        bound += shown.half
        assert abs(got - shown) <= bound + 1e-12 * abs(shown), (
            f"{name} ({fmt}): {formula} of {link['result']['row']} gives {got:.6g}, printed {printed_text!r} (± {bound:.3g})"
        )


def test_a_missing_input_fails(sheets):
    """The reading fails when a cited input is not on the sheet (the Modes table left out)."""
    import copy

    sheet = copy.deepcopy(sheets["block_two_machines"]["md"])
    link = next(l for l in sheet.chain["links"] if l["formula"] == "detuning")
    read_inputs(sheet, link)
    for section in sheet.sections:
        section.tables = [t for t in section.tables if not t.title.startswith("Modes")]
    with pytest.raises(NotPrinted):
        read_inputs(sheet, link)
