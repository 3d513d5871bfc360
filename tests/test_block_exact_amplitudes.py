"""``fcalc amplitudes --exact`` on a block: the limits, the code's zones and the verdict are judged
with each periodic-inertia machine's exact periodic solution, as a crank scene's ``--exact`` does.

The golden values are the exact solution's harmonics (:func:`~foundation_calc.solvers.block.periodic_inertia.exact_response`)
summed in the test over a time grid of one revolution and carried to each point by the rigid
body's kinematics written out here (u_P = u_O + θ × r_P): the peak is the largest sample of 4096,
refined by a bounded scalar search about it (an independent route to the peak, not the solver's
trigonometric root search), the RMS velocity the mean of the samples' squares (exact to round-off
for a trigonometric polynomial of 16 harmonics on 4096 equal steps). Both to 1e-9 relative: the
search's tolerance (1e-13 rad on φ) leaves a relative error far below, the rest is round-off.
"""

from __future__ import annotations

import json
import tomllib
from pathlib import Path

import numpy as np
import pytest
import tomli_w
from typer.testing import CliRunner

import foundation_calc as fc
from foundation_calc.cli.app import app

ROOT = Path(__file__).resolve().parents[1]
COMPRESSOR = ROOT / "configs" / "block_two_throw_compressor.toml"

#: A block whose only machine is a fan's unbalance and its data sheet's loads: no periodic inertia.
LOADS_ONLY = ROOT / "configs" / "block_on_isolators.toml"

#: Samples per revolution of the time grid.
SAMPLES = 4096


def run(*args):
    return CliRunner().invoke(app, ["amplitudes", *map(str, args)])


@pytest.fixture(scope="module")
def documents():
    """The compressor's JSON document without and with ``exact``."""
    return fc.amplitudes(COMPRESSOR).to_dict(), fc.amplitudes(COMPRESSOR, exact=True).to_dict()


def _series(Z: np.ndarray, orders: np.ndarray, phi: np.ndarray) -> np.ndarray:
    """Re Σ_n Z_n e^{i n φ} at the phases φ, for the rows of Z (..., H): shape (..., len(φ))."""
    return np.real(Z @ np.exp(1j * np.outer(orders, phi)))


def _peak(Z: np.ndarray, orders: np.ndarray) -> float:
    """max over one revolution of |Re Σ Z_n e^{inφ}| (Z (H,)): the largest sample, then a bounded
    search within one step of it."""
    from scipy.optimize import minimize_scalar

    phi = np.linspace(0.0, 2.0 * np.pi, SAMPLES, endpoint=False)
    k = int(np.argmax(np.abs(_series(Z, orders, phi))))
    step = 2.0 * np.pi / SAMPLES
    found = minimize_scalar(lambda p: -abs(float(_series(Z, orders, np.array([p]))[0])),
                            bounds=(phi[k] - step, phi[k] + step), method="bounded", options={"xatol": 1e-13})
    return max(-float(found.fun), float(np.abs(_series(Z, orders, phi[k:k + 1]))[0]))


@pytest.fixture(scope="module")
def independent():
    """(point, direction) -> (peak displacement [m], RMS velocity [m/s]) of the compressor's exact
    periodic solution, by the time grid (module docstring)."""
    from foundation_calc.scenes import parse_scene
    from foundation_calc.solvers.block.periodic_inertia import exact_response
    from foundation_calc.solvers.constants import GRAVITY

    scene = parse_scene(tomllib.loads(COMPRESSOR.read_text("utf-8")), source=str(COMPRESSOR))
    model = scene.stable_model()
    (machine,), (exc,) = scene.machines, scene.excitations()
    sol = exact_response(model, exc, machine.periodic_parts, GRAVITY)
    assert sol.harmonic_change < 1e-9 and len(sol.orders) >= 8
    where = {"G": np.asarray(model.cog, dtype=float)} | {p.name: np.asarray(p.at, dtype=float) for p in scene.points}
    phi = np.linspace(0.0, 2.0 * np.pi, SAMPLES, endpoint=False)
    found = {}
    for name, r in where.items():
        U = sol.Z[:, :3] + np.cross(sol.Z[:, 3:], r)  # (H, 3): u_P = u_O + θ × r_P, harmonic by harmonic
        for k, direction in enumerate("xyz"):
            v = _series(1j * exc.omega * sol.orders * U[:, k], sol.orders, phi)
            found[name, direction] = (_peak(U[:, k], sol.orders), float(np.sqrt(np.mean(v * v))))
    return found


def test_exact_limit_rows_are_the_exact_solutions_peaks(documents, independent):
    first, exact = documents
    rows = {(r["point"], r["direction"], r["quantity"]): r for r in exact["limits"]}
    assert len(rows) == 2 * len(independent)
    moved = 0
    for (point, direction), (peak, rms) in independent.items():
        assert rows[point, direction, "displacement"]["value"] == pytest.approx(peak, rel=1e-9)
        assert rows[point, direction, "velocity_rms"]["value"] == pytest.approx(rms, rel=1e-9)
        assert exact["points"][point]["displacement_peak"][direction] == pytest.approx(peak, rel=1e-9)
        moved += abs(peak / next(r["value"] for r in first["limits"] if (r["point"], r["direction"], r["quantity"])
                                 == (point, direction, "displacement")) - 1.0) > 1e-6
    assert moved  # the first approximation differs from the exact solution by more than the tolerance


def test_exact_says_which_solution_judged(documents):
    first, exact = documents
    assert exact["checked_with"] == "exact" and "checked_with" not in first
    assert all(m["method"].endswith("; the limits judge the exact periodic solution") for m in exact["periodic_inertia"])
    assert all(m["method"].endswith("; the limits judge the first approximation (averaged operator)")
               for m in first["periodic_inertia"])
    result = run(COMPRESSOR, "--exact")
    assert result.exit_code == 0, result.output
    assert "the limits judge the exact periodic solution" in " ".join(result.stdout.split())
    assert "the limits judge the first approximation" not in " ".join(result.stdout.split())


def test_the_verdict_flips_with_the_exact_solution(documents, tmp_path):
    """A displacement limit between the first approximation's largest peak and the exact
    solution's: the first fails, the exact solution passes."""
    first, exact = documents
    largest = [max(r["value"] for r in doc["limits"] if r["quantity"] == "displacement") for doc in (first, exact)]
    assert largest[1] < largest[0]  # on the governing row the exact peak is the lower
    data = tomllib.loads(COMPRESSOR.read_text("utf-8"))
    data["limits"]["amplitude"] = (largest[0] + largest[1]) / 2.0
    scene = tmp_path / "between.toml"
    scene.write_text(tomli_w.dumps(data), "utf-8")
    assert fc.amplitudes(scene).to_dict()["verdict"] == "fail"
    result = run(scene, "--exact", "--json")
    assert result.exit_code == 0, result.output
    assert json.loads(result.stdout)["verdict"] == "pass"


def test_a_block_without_periodic_inertia_gets_the_note_and_the_same_document():
    plain, exact = run(LOADS_ONLY, "--json"), run(LOADS_ONLY, "--json", "--exact")
    assert exact.exit_code == plain.exit_code
    assert "note: --exact applies to a machine's periodic inertia ([[machines.cranks]], [[machines.exciters]])" in exact.stderr
    assert json.loads(exact.stdout) == json.loads(plain.stdout)
    assert "note:" not in plain.stderr
