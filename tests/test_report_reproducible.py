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


def plain(text: str) -> str:
    """The sheet's text with Markdown's backslash escapes removed, as a reader sees it."""
    return text.replace("\\", "")


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
        cells = [c.strip().replace("\\", "") for c in re.split(r"(?<!\\)\|", line.strip().strip("|"))]
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


def _margin_tolerance(omega: float, critical: float) -> float:
    """Half the printed 0.1 % of a margin plus what rounding ω and ω_c to 4 figures moves |ω/ω_c − 1|."""
    return 5e-4 + (omega / critical) * 1e-3


def _speed(text: str, label: str) -> float:
    """The operating speed [rad/s] of the sheet's derived-quantity row ``label``."""
    row = next(line for line in text.splitlines() if line.startswith(f"| {label} |"))
    return numbers(row.split("|")[2])[0]


@pytest.mark.parametrize("name", ["frame_saw_soft_soil_runup", "compressor_medium_sand_lysmer"])
def test_crank_margins_follow_from_the_printed_speeds(runner, tmp_path, name):
    """Every margin of the resonance table is |ω − ω_c|/ω_c to the nearer of its two printed
    critical speeds; the Checks table prints that critical speed beside the margin (the frame saw's
    ω = p2: 29.2 % from 20.27 rad/s, 29.4 % from the zero-order 20.23 rad/s); the sheet states the
    definitions and the governing margin with its numbers."""
    text = sheet(runner, tmp_path, name)
    omega = _speed(text, "ω, speed")
    for condition, _, critical, averaged, margin, *_ in table_rows(text, "Resonances: critical speeds"):
        c0, c1 = numbers(critical)[0], numbers(averaged)[0]
        (shown,) = numbers(margin)
        nearer = min((c0, c1), key=lambda c: abs(omega - c) / c)
        assert abs(abs(omega - nearer) / nearer - shown / 100) <= _margin_tolerance(omega, nearer), condition
    for row in table_rows(text, "Every check"):
        if row[0] == "resonance" and "critical" in row[1]:
            critical = numbers(row[1].split("critical ")[1])[0]
            (shown,) = numbers(row[2])
            assert abs(abs(omega - critical) / critical - shown / 100) <= _margin_tolerance(omega, critical), row[1]
    text = plain(text)
    assert "|nω − p|/p" in text and "nearer of the two" in text and "Forcing share of harmonic n" in text
    governing = re.search(r"Governing \(.*?\): (.*?), \|([\d.]+) − ([\d.]+)\|/([\d.]+) = ([\d.]+) %", text)
    w, c, _, shown = (float(governing.group(i)) for i in (2, 3, 4, 5))
    assert abs(abs(w - c) / c - shown / 100) <= _margin_tolerance(w, c)


def test_platform_margins_and_rocking_are_defined(runner, tmp_path):
    """The platform's margins are |ω − p|/p (read relative to ω its closest one, 11.1 %, would be
    9.98 %), and the sheet says what the rocking of the corners is."""
    text = sheet(runner, tmp_path, "platform_paper_example")
    omega = _speed(text, "ω, speed")
    for mode, frequency, margin in table_rows(text, "Natural frequencies (6-DOF"):
        (p,), (shown,) = numbers(frequency), numbers(margin)
        assert abs(abs(omega - p) / p - shown / 100) <= _margin_tolerance(omega, p), mode
    assert "|nω − p|/p" in plain(text) and "Rocking of the corners: " in text
