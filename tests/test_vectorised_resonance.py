"""The batch path (numpy arrays of designs, one call) agrees with the scalar path design by design."""

from __future__ import annotations

from dataclasses import replace

import numpy as np
import pytest

from foundation_calc.benchmarks.throughput import perturbed_designs
from foundation_calc.checks.resonance.report import check_resonances
from foundation_calc.solvers.crank.natural import design_frequencies
from foundation_calc.solvers.crank.machine_conditions import paper_margin
from foundation_calc.scenes import load_scene
from tests.conftest import closed_form_configs


@pytest.mark.parametrize("config", closed_form_configs(), ids=lambda p: p.name)
def test_batch_matches_scalar(config):
    design = load_scene(config).design()
    batch = perturbed_designs(design, 200, seed=1)
    margins = paper_margin(batch)
    zero, avg = design_frequencies(batch)
    assert isinstance(margins, np.ndarray) and margins.shape == (200,)
    for i in range(0, 200, 7):
        one = replace(design, c=float(batch.c[i]), c_phi=float(batch.c_phi[i]), c1=float(batch.c1[i]), omega=float(batch.omega[i]))
        report = check_resonances(one, 0.2)
        expected = min(r.margin for r in report.rows if r.condition.source == "paper")
        assert margins[i] == pytest.approx(expected, rel=1e-14, abs=1e-15)
        assert zero.p1[i] == pytest.approx(report.zero_order.p1, rel=1e-14)
        assert avg.p2[i] == pytest.approx(report.averaged.p2, rel=1e-14)
