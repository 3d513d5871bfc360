"""fcalc validate: the record passes, each case can fail, and the manual shows its output.

The cases' own evidence is their source (a printed value or an independent method); these tests
check that the record is computed as documented: every case fails when fcalc's value moves by
twice its tolerance, the printed references are the numbers compared, the command exits 1 on a
failing case, the table fits 80 columns, and the manual's Validation page (docs/validation.md) is the output of
``fcalc validate --markdown`` (so it cannot drift).
"""

from __future__ import annotations

import dataclasses
import json
import os
import re
import subprocess
import sys
from pathlib import Path

import pytest
from rich.cells import cell_len
from rich.console import Console
from rich.table import Table

from foundation_calc.output import validation as out
from foundation_calc.output.console import keep_words_whole
from foundation_calc.validation.cases import all_cases, run_record
from foundation_calc.validation.record import evaluate
from foundation_calc.references import REFERENCES

VALIDATION_PAGE = Path(__file__).resolve().parents[1] / "docs" / "validation.md"
FCALC = (sys.executable, "-m", "foundation_calc")
BEGIN = "<!-- validation record: output of `fcalc validate --markdown` -->"
END = "<!-- end of validation record -->"


@pytest.fixture(scope="module")
def results():
    return run_record()


def _fcalc(*args: str) -> subprocess.CompletedProcess:
    return subprocess.run((*FCALC, *args), capture_output=True, text=True, check=False,
                          env={**os.environ, "COLUMNS": "80"})


def test_the_record_passes_with_at_least_12_cases_from_independent_sources(results):
    document = json.loads(json.dumps(out.record_document(results), allow_nan=False))  # as --json prints it
    assert document["command"] == "validate" and document["passed"] is True
    assert len(document["cases"]) >= 12
    assert all(case["verdict"] == "pass" for case in document["cases"])
    sources = {case["source"] for case in document["cases"]}
    assert sources >= {"DR", "RHW", "Le", "ISO", "BC", "FC"}
    assert set(document["references"]) == sources
    assert len({case["key"] for case in document["cases"]}) == len(document["cases"])


def test_every_case_fails_when_fcalc_moves_by_twice_its_tolerance(results):
    for r in results:
        case = r.case
        step = 2.0 * case.tolerance * (max(abs(v) for v in out._values(r.reference)) if case.relative else 1.0)

        def moved(value=r.value, step=step):
            return tuple(v + step for v in value) if isinstance(value, tuple) else value + step

        assert not evaluate(dataclasses.replace(case, fcalc=moved)).passed, case.key


def test_printed_references_are_the_numbers_compared():
    for case in all_cases():
        assert case.source in REFERENCES, case.key
        if case.printed is not None:
            printed = tuple(float(v) for v in case.printed.split(" / "))
            expected = case.reference if isinstance(case.reference, tuple) else (case.reference,)
            assert printed == expected, case.key


def test_a_failing_case_exits_1(monkeypatch):
    from typer.testing import CliRunner

    from foundation_calc.cli.app import build_app
    from foundation_calc.validation import cases

    wrong = dataclasses.replace(all_cases()[0], reference=1.7)
    monkeypatch.setattr(cases, "all_cases", lambda: (wrong,))
    result = CliRunner().invoke(build_app(("validate",)), ["validate"])
    assert result.exit_code == 1, result.output
    assert "FAIL" in result.output and "1 cases: 0 pass, 1 fail" in result.output


class TerminalOf80(Console):
    """An 80-column terminal that prints tables as fcalc's stdout console does (words kept whole)."""

    def __init__(self):
        super().__init__(width=80, record=True, force_terminal=True, color_system=None)

    def print(self, *objects, **kwargs):
        for item in objects:
            if isinstance(item, Table):
                keep_words_whole(item)
        super().print(*objects, crop=False, **kwargs)


def test_the_table_fits_80_columns(results, monkeypatch):
    console = TerminalOf80()
    monkeypatch.setattr(out, "stdout", lambda: console)
    out.print_record(results)
    text = console.export_text()
    assert max(cell_len(line) for line in text.splitlines()) <= 80  # terminal cells: Ω̇ is one
    assert "…" not in text and "685.9425" in text and "[DR]" in text


def test_the_validation_page_is_the_command_output():
    """Also the command's exit code in CI: 0 when every case passes."""
    run = _fcalc("validate", "--markdown")
    assert run.returncode == 0, run.stdout + run.stderr
    page = VALIDATION_PAGE.read_text(encoding="utf-8")
    found = re.search(re.escape(BEGIN) + r"\n(.*?)" + re.escape(END), page, re.S)
    assert found, f"docs/validation.md lacks the markers {BEGIN!r} ... {END!r}"
    assert found.group(1) == run.stdout, "docs/validation.md out of date: paste the output of `fcalc validate --markdown`"


def test_report_validation_appends_the_record_to_the_sheet(tmp_path, results):
    """The sheet ends with the record: every case with the numbers fcalc validate prints, and
    its sources in full."""
    from tests.conftest import CONFIGS

    sheet = tmp_path / "sheet.md"
    run = _fcalc("report", str(CONFIGS / "platform_paper_example.toml"), "-o", str(sheet), "--validation")
    assert run.returncode == 0, run.stderr
    text = sheet.read_text(encoding="utf-8")
    record = text[text.index("Validation record"):]
    assert out.summary(results) in record
    for r in results:
        assert out.value_text(r.value, out.scale(r)) in record, r.case.key
    for key in out.sources(results):
        assert REFERENCES[key].split(",")[0].replace("_", "\\_") in record, key
