"""The sheet's code-zone chain ends in the amplitudes check's r.m.s. velocities and zones.

The sheet sums v_n = nω A_n/√2 in quadrature from its own damped solve (Parseval, term by term
over the point's series); the check takes ``trig_series.rms`` of the velocity series of the
solvers' motion. Agreement to 1e-9 relative: the same motion (the damped solve's harmonics agree
to 1e-9, ``test_report_damped_response``) and the same sum in another order.
"""

from __future__ import annotations

import numpy as np
import pytest

from foundation_calc.scenes import load_scene
from tests.conftest import CONFIGS

TOLERANCE = 1e-9


def test_rms_velocity_and_zone_of_every_point_are_the_checks():
    from foundation_calc.checks.amplitudes.approximations import check_scene_amplitudes
    from foundation_calc.output.amplitudes import amplitudes_document
    from foundation_calc.output.report.code_zone import DIRECTIONS, code_zone_blocks, velocity_terms
    from foundation_calc.output.report.damped_response import damped_solve

    scene = load_scene(CONFIGS / "compressor_vendor_loads.toml")
    doc = amplitudes_document(check_scene_amplitudes(scene), scene, "")
    motion = damped_solve(scene).motion()
    terms = velocity_terms(motion, [0.0, *(p.horizontal for p in scene.points)], [0.0, *(p.height for p in scene.points)])
    judged = doc["code"]["points"]
    assert len(judged) == 1 + len(scene.points)
    for i, row in enumerate(judged):
        for j, direction in enumerate(DIRECTIONS):
            ours = float(np.sqrt((terms[i, j] ** 2).sum()))
            assert abs(ours - row["velocity_rms"][direction]) <= TOLERANCE * row["velocity_rms"][direction], (row["point"], direction)
    _, velocity, zones, *_ = code_zone_blocks(scene, doc["code"], motion)
    assert [(r[-5], r[-4], r[-3], r[-2], r[-1].lower()) for r in velocity.rows] == [
        (row["velocity_zone"], f"{row['displacement_rms'][max(row['displacement_rms'], key=row['displacement_rms'].get)] * 1e6:.3g}",
         row["displacement_zone"], row["zone"], row["verdict"]) for row in judged]
    assert [r[0] for r in zones.rows] == ["A", "B", "C", "D"] and "Table A.2" in zones.title


def test_parseval_term_by_term_matches_a_sampled_rms():
    """v_rms from the harmonics equals the r.m.s. of the velocity sampled over one revolution
    (an independent quadrature: 4096 samples of a trigonometric polynomial of degree < 2048 are
    exact to round-off)."""
    from foundation_calc.output.report.code_zone import velocity_terms
    from foundation_calc.solvers.crank.response import PeriodicMotion, point_series

    rng = np.random.default_rng(7)
    cos, sin = rng.normal(size=(3, 6)) * 1e-4, rng.normal(size=(3, 6)) * 1e-4
    motion = PeriodicMotion(30.0, cos, sin)
    terms = velocity_terms(motion, [0.7], [1.2])
    c, s = point_series(motion, np.array([0.7]), np.array([1.2]))
    t = np.arange(4096) / 4096 * 2 * np.pi
    n = np.arange(c.shape[-1])
    w = (30.0 * n)[:, None]
    velocity = (w * (-c[..., None] * np.sin(np.outer(n, t)) + s[..., None] * np.cos(np.outer(n, t)))).sum(-2)
    sampled = np.sqrt((velocity**2).mean(-1))
    assert np.sqrt((terms**2).sum(-1)) == pytest.approx(sampled, rel=1e-12)
