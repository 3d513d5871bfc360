"""Acceleration limits on a block foundation: ``[limits] acceleration`` (peak) and
``acceleration_rms``, judged at G and every point along x, y, z by the limit machinery every kind
shares (:mod:`foundation_calc.checks.limits`).

The golden values are an independent solve: each machine's order n by a direct complex solve of
(K - Ω² M + i Ω C) Z = Q_n at Ω = nω, the point's motion u_P = u + θ × r_P written out, its
acceleration a = -Ω² u at each harmonic; a machine's peak over its period by dense sampling of
Σ_n Re(a_n e^{inφ}), the machines' peaks added (the block's combination, solvers/block/response.py),
the RMS the root-sum-square of |a_n|/√2 over every harmonic of every machine.
"""

from __future__ import annotations

import json
import tomllib
from pathlib import Path

import numpy as np
import pytest

from foundation_calc.checks.amplitudes.machines import check_block
from foundation_calc.scenes import parse_scene

CONFIGS = "configs"
SAMPLES = 20000  # phases per period: the sampled peak is low by at most max|a''| Δφ²/8 ≈ 1.2e-8 relative (H ≤ 2)


def _document(**limits) -> dict:
    with open(f"{CONFIGS}/block_two_machines.toml", "rb") as fh:
        document = tomllib.load(fh)
    document["limits"] |= limits
    return document


def _independent(scene):
    """(peak, rms) acceleration (P, 3) [m/s²] of G and the points, by the module docstring's solve."""
    model = scene.model()
    points = np.array([model.cog, *(p.at for p in scene.points)], dtype=float)
    phase = np.linspace(0.0, 2.0 * np.pi, SAMPLES, endpoint=False)
    peak = np.zeros(points.shape)
    square = np.zeros(points.shape)
    for exc in scene.excitations():
        series = np.zeros(points.shape + (SAMPLES,))
        for n, q in zip(exc.orders, exc.Q):
            Omega = n * exc.omega
            Z = np.linalg.solve(model.K - Omega**2 * model.M + 1j * Omega * model.C, q)
            u = Z[:3] + np.cross(np.broadcast_to(Z[3:], points.shape), points)  # u_P = u_O + θ × r_P
            a = -(Omega**2) * u
            square += np.abs(a) ** 2 / 2.0
            series += (a[..., None] * np.exp(1j * n * phase)).real
        peak += np.abs(series).max(axis=-1)
    return peak, np.sqrt(square)


def test_acceleration_limits_judge_every_point_and_direction_against_an_independent_solve():
    scene = parse_scene(_document(acceleration=0.02, acceleration_rms=0.015), "two")
    peak, rms = _independent(scene)
    report = check_block(scene)
    rows = {(r.point, r.direction, r.quantity): r for r in report.limit_rows}
    names = ["G", *(p.name for p in scene.points)]
    for p, name in enumerate(names):
        for d, direction in enumerate("xyz"):
            for quantity, expected, limit in (("acceleration", peak, 0.02), ("acceleration_rms", rms, 0.015)):
                row = rows[name, direction, quantity]
                # the peak: the sampled one is low by at most ~1e-8; the RMS is the same sum, to round-off
                np.testing.assert_allclose(row.value, expected[p, d], rtol=1e-7, err_msg=f"{quantity} {name} {direction}")
                assert row.limit == limit
                assert (row.outcome.value == "fail") == (expected[p, d] > limit)
                assert row.source == f"scene [limits] {quantity}"
    assert report.amplitude_outcome.value == "fail"  # 0.0221 m/s² peak at a point > 0.02
    assert {r.outcome.value for r in report.limit_rows if r.quantity == "acceleration"} == {"pass", "fail"}


def test_without_acceleration_limits_the_block_adds_no_rows_and_a_loose_limit_passes():
    base = check_block(parse_scene(_document(), "two"))
    assert not [r for r in base.limit_rows if r.quantity.startswith("acceleration")]
    loose = check_block(parse_scene(_document(acceleration=1.0, acceleration_rms=1.0), "two"))
    assert loose.amplitude_outcome is base.amplitude_outcome
    assert len(loose.limit_rows) == len(base.limit_rows) + 2 * 3 * (1 + len(loose.motion.names) - 1)


def test_a_sweep_at_the_scene_speed_gives_the_scene_accelerations():
    """The batched sweep (solvers/block/sweep.py) against the per-scene steady state, to round-off."""
    from foundation_calc.checks.sweep.block import sweep_block

    scene = parse_scene(_document(acceleration=0.02), "two")
    report = check_block(scene)
    for swept in (0, 1):
        omega = scene.excitations()[swept].omega
        sweep = sweep_block(scene, swept, np.array([0.5 * omega, omega]))
        np.testing.assert_allclose(sweep.columns["acceleration_peak"][1], report.motion.acceleration_peak.max(axis=0), rtol=1e-12)
        np.testing.assert_allclose(sweep.columns["acceleration_rms"][1], report.motion.acceleration_rms.max(axis=0), rtol=1e-12)
        assert bool(sweep.rows.over_quantities["acceleration"][1])  # 0.0221 > 0.02 at the scene's speeds
    assert sweep.limits == {"displacement": 5.0e-5, "acceleration": 0.02, "velocity_rms": 2.8e-3}


@pytest.mark.parametrize("kind", ["crank", "block"])
def test_every_kind_judges_acceleration_with_the_same_keys_and_words(kind, tmp_path):
    """Conformance: the same [limits] keys on a crank and a block scene give rows of the same
    quantity and source, in the JSON of ``fcalc amplitudes`` and in ``fcalc check``'s exit code."""
    from typer.testing import CliRunner

    from foundation_calc.cli.app import app

    path = tmp_path / f"{kind}.toml"
    source = "block_two_machines" if kind == "block" else "compressor_damped_near_resonance"
    text = (Path(CONFIGS) / f"{source}.toml").read_text().replace("[limits]\n", "[limits]\nacceleration = 1.0e-6\nacceleration_rms = 1.0e-6\n")
    path.write_text(text)
    runner = CliRunner()
    result = runner.invoke(app, ["amplitudes", str(path), "--json"])
    assert result.exit_code == 1, result.output
    rows = json.loads(result.stdout)["limits"]
    for quantity in ("acceleration", "acceleration_rms"):
        found = [r for r in rows if r["quantity"] == quantity]
        assert found and all(r["verdict"] == "fail" and r["limit"] == 1.0e-6 for r in found)
        assert {r["source"] for r in found} == {f"scene [limits] {quantity}"}
    assert runner.invoke(app, ["check", str(path)]).exit_code == 1


def test_the_block_sheet_and_table_show_the_acceleration_rows(tmp_path):
    from typer.testing import CliRunner

    from foundation_calc.cli.app import app

    path = tmp_path / "two.toml"
    path.write_text((Path(CONFIGS) / "block_two_machines.toml").read_text().replace("[limits]\n", "[limits]\nacceleration = 0.02\n"))
    runner = CliRunner()
    table = runner.invoke(app, ["amplitudes", str(path)], env={"COLUMNS": "200"})
    assert table.exit_code == 1 and "acceleration" in table.stdout
    document = json.loads(runner.invoke(app, ["amplitudes", str(path), "--json"]).stdout)
    assert set(document["points"]["G"]) >= {"acceleration_peak", "acceleration_rms"}
    sheet = tmp_path / "two.md"
    result = runner.invoke(app, ["report", str(path), "-o", str(sheet)])
    assert result.exit_code in (0, 1), result.output
    assert "peak acceleration" in sheet.read_text()

