"""A checking engineer reproduces the sheet's judged numbers from the sheet alone.

Each test reads the Markdown sheet as printed, takes the printed inputs of a number (the values a
hand calculation substitutes, the printed frequencies and speed) and evaluates them here,
independently of the report's code, then compares with the number the sheet prints elsewhere.
Tolerances come from the printed precision: a hand calculation prints its inputs to 4 significant
figures (each off by at most 5·10⁻⁴ relative; a quotient of a few of them, squared, drifts by a
few 10⁻³), the amplitude table to 3 (5·10⁻³). 1 % separates both from the defects these tests
guard against (y2 57 % low with the rod's l' instead of the rod and slider's).
"""

from __future__ import annotations

import math
import re

import pytest

from foundation_calc.cli.app import app
from tests.conftest import CONFIGS
from tests.sheet_numbers import numbers

#: Relative agreement of a number recomputed from printed (rounded) values with the printed one.
PRINTED = 1e-2

_SUPERSCRIPTS = str.maketrans("⁻⁰¹²³⁴⁵⁶⁷⁸⁹", "-0123456789")


def sheet(runner, tmp_path, name: str) -> str:
    """The Markdown sheet of the shipped scene ``name``."""
    out = tmp_path / (name + ".md")
    result = runner.invoke(app, ["report", str(CONFIGS / f"{name}.toml"), "-o", str(out)])
    assert result.exit_code in (0, 1), result.output
    return out.read_text(encoding="utf-8")


def table_rows(text: str, title_start: str) -> list[list[str]]:
    """The body rows of the first table whose bold title starts with ``title_start`` (cells unescaped)."""
    lines = text.splitlines()
    start = next(i for i, line in enumerate(lines) if line.startswith("**" + title_start))
    rows = []
    for line in lines[start + 2:]:
        if not line.startswith("|"):
            if rows:
                break
            continue
        cells = [c.strip().replace("\\", "") for c in line.strip("|").split("|")]
        if set(cells[0]) <= {"-", " "}:
            continue
        rows.append(cells)
    return rows[1:]  # the header


def evaluate(printed: str) -> float:
    """A hand calculation's substituted values as printed, evaluated: ``0.1 × 15.71² / √(…)``."""
    text = printed.replace("−", "-").replace("×", "*").replace("·10", "e").replace("√", "sqrt")
    text = re.sub(r"e([⁻⁰¹²³⁴⁵⁶⁷⁸⁹]+)", lambda m: "e" + m.group(1).translate(_SUPERSCRIPTS), text)
    text = text.replace("²", "**2").replace("³", "**3")
    return float(eval(text, {"__builtins__": {}}, {"sqrt": math.sqrt}))


def close(a: float, b: float, rel: float = PRINTED) -> bool:
    return abs(a - b) <= rel * max(abs(a), abs(b))


@pytest.mark.parametrize("name", ["compressor_medium_sand_lysmer", "frame_saw_soft_soil_runup"])
def test_first_approximation_y_follows_from_the_printed_formula(runner, tmp_path, name):
    """Item: the printed first approximation y1, y2 (with the slider mass m1 and the damping)
    gives the sheet's own first-approximation amplitudes (Amplitudes section, in mm)."""
    text = sheet(runner, tmp_path, name)
    chain = {row[0]: row for row in table_rows(text, "First approximation, vertical")}
    amplitudes = {row[0]: row for row in table_rows(text, "Amplitude per harmonic")}
    for n in (1, 2):
        _, formula, values, result, unit, _ = chain[f"y{n}"]
        assert unit == "m"
        (printed,) = numbers(result)
        assert close(evaluate(values), printed), (values, printed)
        (shown,) = numbers(amplitudes[f"y{n} [mm]"][1])  # the first approximation's column
        assert close(printed * 1e3, shown), (n, printed, shown)
    assert "m1" in chain["l'"][1] and "ζ_z" in chain["y1"][1]
    equation = next(line for line in text.splitlines() if line.startswith("- `y_c ="))
    assert "ζ_z" in equation and "m1" in equation  # the equation printed is the one evaluated
