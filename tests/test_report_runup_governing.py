"""The run-up's judged peaks beside the closed form of their governing passage, reproduced from the
sheet alone.

The sheet's start-up and run-down peaks come from a time integration. Beside each, the governing
passage is worked by hand (``output/report/runup_governing.py``): the sweep rate from the ramp's
time, Lewis' undamped peak 1.467/√η [Le], the steady resonance peak 1/(2ζ√(1 − ζ²)), the smaller
times the static deflection, and its difference from the integration. Here each printed step is
evaluated from its printed values, and x_p is transcribed independently from the inputs the sheet
prints elsewhere (the passage table's ω_i, r, ζ, F_m, ρ_P; ω and T in its title; the integrated
peak in the run-up section), for every scene kind that runs up. Tolerances: 1 % for a number
recomputed from 4-figure inputs (:data:`tests.test_report_reproducible.PRINTED`); the integrated
peak of the run-up table has 3 figures (5·10⁻³), so Δ [%] within 0.6 of a point.
"""

from __future__ import annotations

import math
import re

import pytest

from tests.sheet_numbers import numbers
from tests.test_report_reproducible import PRINTED, close, evaluate, plain, sheet, table_rows

#: A block with one machine that passes its modes on a 10 s start-up (tests/test_runup_block.py)
#: with a transient limit, so that the sheet runs it up.
LIMIT = "\n[limits]\ntransient_amplitude = 1.0e-3\n"

#: For a slow sweep (ζ/√η ≥ 3) the closed form is within this of the time integration: the steady
#: peak 1/(2ζ√(1 − ζ²)) is the slow limit of the damped passage, reached within 1 % by a constant
#: force and within 4 % by an unbalance at ζ = 0.15 (its force still rising after the resonance);
#: 5 % separates that from an undamped Lewis bound (×4.6 here) or a missing √(1 − ζ²).
SLOW = 5e-2


def _block_sheet(runner, tmp_path) -> str:
    from foundation_calc.cli.app import app
    from tests.test_runup_block import SCENE

    path = tmp_path / "block_runup.toml"
    path.write_text(SCENE + LIMIT, encoding="utf-8")
    out = tmp_path / "block_runup.md"
    result = runner.invoke(app, ["report", str(path), "-o", str(out)])
    assert result.exit_code in (0, 1), result.output
    return out.read_text(encoding="utf-8")


def _chain_rows(text: str, title: str) -> dict[str, list[str]]:
    """A hand calculation's rows by symbol (its header's first cell is empty, which
    :func:`table_rows` takes for a separator: its first row would be dropped as the header)."""
    lines = text.splitlines()
    start = next(i for i, line in enumerate(lines) if plain(line).startswith("**" + title))
    rows = {}
    for line in lines[start + 4:]:  # title, blank, header, separator
        if not line.startswith("|"):
            break
        cells = [c.strip().replace("\\", "") for c in re.split(r"(?<!\\)\|", line.strip().strip("|"))]
        rows[cells[0]] = cells
    return rows


def _chains(text: str) -> dict[str, dict[str, list[str]]]:
    """Run title ("Start-up", "Start-up of pump" ...) -> the governing chain's rows by symbol."""
    out = {}
    for line in plain(text).splitlines():
        if ": governing passage by hand" in line and line.startswith("**"):
            run = line.strip("*").split(": governing passage by hand")[0]
            out[run] = _chain_rows(text, line.strip("*"))
    return out


def _passage_columns(text: str, run: str) -> tuple[dict[str, list[str]], list[str], float, float]:
    """The passage table of ``run`` in the Methods: rows by symbol, its column heads, T and ω."""
    line = next(x for x in plain(text).splitlines() if x.startswith(f"**{run}: each resonance passed"))
    T, omega = numbers(line.split("T = ")[1])[0], numbers(line.split("ω = ")[1])[0]
    lines = plain(text).splitlines()
    head = lines[lines.index(line) + 2]
    heads = [c.strip() for c in head.strip().strip("|").split("|")]
    return _chain_rows(text, line.strip("*")), heads, T, omega


def _integrated(text: str, run: str, mode: str, order: str) -> float:
    """The integrated peak [mm] of the passage ``mode``, ``order`` in the run-up section's table."""
    title = next(x for x in plain(text).splitlines() if x.startswith(f"**{run} in "))
    for row in table_rows(text, title.strip("*")):
        if row[0] == mode and row[2] == order:
            return numbers(row[8])[0]
    raise AssertionError((run, mode, order))


@pytest.fixture(scope="module")
def sheets(tmp_path_factory):
    from typer.testing import CliRunner

    runner, tmp = CliRunner(), tmp_path_factory.mktemp("sheets")
    return {"crank": sheet(runner, tmp, "frame_saw_soft_soil_runup"), "platform": sheet(runner, tmp, "platform_damped"),
            "block": _block_sheet(runner, tmp)}


@pytest.mark.parametrize("kind", ["crank", "platform", "block"])
def test_every_step_of_the_governing_passage_follows_from_its_printed_values(sheets, kind):
    """Each printed step of every run's governing passage is its printed values evaluated."""
    chains = _chains(sheets[kind])
    assert chains, kind
    for run, rows in chains.items():
        for symbol in ("Ω̇", "Ω̇_r", "η_r", "x_st", "A_L", "β", "A_ss", "A_p", "x_p"):
            _, formula, values, result, *_ = rows[symbol]
            computed = min(evaluate(v) for v in values[4:-1].split(", ")) if values.startswith("min(") else evaluate(values)
            assert close(computed, numbers(result)[0]), (kind, run, symbol, values, result)


@pytest.mark.parametrize("kind", ["crank", "platform", "block"])
def test_the_closed_form_is_transcribed_from_the_sheets_inputs(sheets, kind):
    """x_p = min(1.467/√η, 1/(2ζ√(1 − ζ²))) F_m ρ_P/ω_i², η = r ω/(T ω_i²), from the passage
    table's printed column of the governing mode (ω, T from its title), and Δ against the
    integrated peak of the run-up section's table: both as the chain and the section print them."""
    text = sheets[kind]
    assert _chains(text), kind
    for run, rows in _chains(text).items():
        title = next(x for x in plain(text).splitlines() if x.startswith(f"**{run}: governing passage by hand"))
        mode, order = title.split(", mode ")[1].split(" at ")[0].rsplit(", ", 1)
        columns, heads, T, omega = _passage_columns(text, run)
        j = heads.index(f"mode {mode}, {order}")
        w, r, zeta, F_m, rho = (numbers(columns[s][j])[0] for s in ("ω_i", "r", "ζ", "F_m", "ρ_P"))
        eta = r * omega / (T * w * w)
        amplification = min(1.467 / math.sqrt(eta), 1.0 / (2.0 * zeta * math.sqrt(1.0 - zeta * zeta)))
        x_p = amplification * F_m * rho / (w * w)
        assert close(x_p, numbers(rows["x_p"][3])[0]), (kind, run, x_p, rows["x_p"])
        integrated = _integrated(text, run, mode, order) * 1e-3
        delta = 100.0 * (x_p / integrated - 1.0)
        assert abs(delta - numbers(rows["Δ"][3])[0]) <= 0.6 + 100 * PRINTED * abs(x_p / integrated), (kind, run, delta)
        lines = plain(text).splitlines()
        start = next(i for i, x in enumerate(lines) if x.startswith(f"**{run} in "))
        line = next(x for x in lines[start:] if x.startswith("Governing passage (worked by hand in the Methods)"))
        assert f"mode {mode.split(' ')[0]}, {order} at" in line
        assert close(numbers(line.split("x_st = ")[1])[0], x_p * 1e3), line  # mm
        assert abs(numbers(line.split("Δ = ")[1])[0] - delta) <= 0.6 + 100 * PRINTED * abs(x_p / integrated), line


def test_closed_form_against_the_integration_on_a_slow_sweep():
    """The frame saw run down in 60 s passes k0 (ζ = 0.15) at η = 1.5·10⁻³, ζ/√η = 3.9: the
    chain's closed form is within :data:`SLOW` of the time integration of the whole model."""
    from foundation_calc.checks.runup import check_runup
    from foundation_calc.output.report.runup_governing import governing_blocks
    from foundation_calc.output.runup import runup_document
    from foundation_calc.scenes import load_scene
    from tests.conftest import CONFIGS

    scene = load_scene(CONFIGS / "frame_saw_soft_soil_runup.toml")
    (passage,) = governing_blocks(scene, runup_document(check_runup(scene, None, 60.0), scene, ""))
    v = passage.values
    assert v["beta"] >= 3.0 and v["A_p"] == v["A_ss"]
    assert abs(v["x_p"] / v["x_int"] - 1.0) <= SLOW, (v["x_p"], v["x_int"])
