"""One resonance layer for every scene kind (checks/resonance/, output/resonance.py).

The crank scene and the block judge their conditions through one report: the same check in
``fcalc check``, the same report type from ``fc.resonance``, and a governing condition that is
the rule's over every machine at once. The governing condition is checked against an independent
transcription of docs/resonance-rule.md, rule 4 (the worst verdict among the conditions that can
decide — judged, or of order 1 — and among those the smallest margin over the margin it needs,
its band but at least 5 %), row by row in plain Python.
"""

from __future__ import annotations

import pytest

import foundation_calc as fc
from foundation_calc.checks.registry import CHECKS
from foundation_calc.checks.resonance.report import ResonanceReport
from tests.conftest import configs_of_kind

SEVERITY = {"pass": 0, "warn": 1, "fail": 2}


def _governing_by_hand(rows):
    """docs/resonance-rule.md, rule 4, over every row of every machine."""
    deciding = [r for r in rows if r.judged or r.order == 1]
    worst = max(SEVERITY[r.outcome.value] for r in deciding)
    return min((r for r in deciding if SEVERITY[r.outcome.value] == worst),
               key=lambda r: r.margin / max(r.required, 0.05))


def test_both_kinds_run_one_resonance_check():
    assert CHECKS["crank_foundation"]["resonance"] is CHECKS["block_foundation"]["resonance"]


@pytest.mark.parametrize("config", [*configs_of_kind("crank_foundation")[:2], *configs_of_kind("block_foundation")],
                         ids=lambda p: p.name)
def test_one_report_and_the_rules_governing_condition(config):
    result = fc.resonance(config)
    report = result.report
    assert isinstance(report, ResonanceReport)
    assert report.per_machine == (config.name.startswith("block"))
    if report.per_machine:  # every condition is shown: the rule's choice among all of them
        assert report.governing is _governing_by_hand(report.rows)
    doc = result.to_dict()
    governing = [r for r in doc["resonances"] if r["condition"] == report.governing.label]
    assert governing and governing[0]["margin"] == report.governing.margin
