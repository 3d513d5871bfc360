"""``fcalc design`` on a crank foundation on piles (configs/crank_on_piles.toml): the crank batch
takes the pile group's sway-rocking coupling K_xφ, C_xφ as ``fcalc check`` does on the candidate's
own scene.

References, independent of the batch:

- ``fcalc resonance`` / ``fcalc amplitudes`` / ``fcalc check`` on each candidate's scene written out
  (the scene's document with the candidate's values, :func:`~foundation_calc.checks.design.apply.applied_document`):
  one design at a time through the scene model, where the batch is array operations over the
  candidates (the same physics by another path: 1e-9, round-off of the eigen-solve and of the
  frequency-consistent root's bracket, rtol 1e-10);
- a brute-force eigen-solve assembled here: the rigid body's mass matrix about O in (u_x, u_z, θ_y),
  block and machine at C plus the rod and the slider averaged over 720 crank angles from their
  kinematics, and the support's springs at O (its 6 × 6 K at ω, read at u_x, u_z, θ_y: the coupling
  K_xφ included) less the weight's tilt g Σ m z̄: each mode of rank j solves ω = p_j(K(ω)) of this
  eigen-solve, and where a scan finds that equation one root alone, is that root by Brent's method
  (1e-9: the brackets' widths, 1e-10 and 1e-13 of the root; a pile group's springs give some modes
  several roots, of which fcalc takes the one its bracket holds).

fcalc check's path takes seconds on this scene (every harmonic on the pile group's springs at its
own frequency): the runs here are few (one design of 2 × 2 points, one that fails everywhere) and
each candidate's scene is run once.
"""

from __future__ import annotations

import json
from pathlib import Path

import numpy as np
import pytest

ROOT = Path(__file__).resolve().parents[1]
CONFIG = ROOT / "configs" / "crank_on_piles.toml"

#: Candidates (block length [m], pile length [m]); the last two differ in the piles alone.
CANDIDATES = ((4.0, 12.0), (4.5, 10.0), (4.5, 16.0))

#: The plane's motions at O among the support's six: u_x, u_z, θ_y.
PLANE = [0, 2, 4]


def _document():
    from foundation_calc.scenes.files import parse_toml, read_text

    return parse_toml(read_text(CONFIG), str(CONFIG))


def _candidate_document(document, length, piles):
    from foundation_calc.checks.design.apply import applied_document

    found = applied_document(document, {"foundation.block.length": length, "piles.length": piles})
    assert found["foundation"]["block"]["length"] == length and found["piles"]["length"] == piles
    return found


@pytest.fixture(scope="module")
def batch():
    """The batch's frequencies (k0, p1, p2 by name, (N,) each) and verdicts of :data:`CANDIDATES`."""
    from foundation_calc.checks.design import crank
    from foundation_calc.checks.design.apply import sizing_of
    from foundation_calc.checks.design.crank_physics import Verdicts, judge_physics
    from foundation_calc.checks.design.supported import candidate_values
    from foundation_calc.scenes import parse_scene
    from foundation_calc.solvers.crank.batch import MechanismOperator

    scene = parse_scene(_document(), str(CONFIG))
    values = {"foundation.block.length": np.array([c[0] for c in CANDIDATES]),
              "piles.length": np.array([c[1] for c in CANDIDATES])}
    given = {f"foundation.block.{k}": getattr(scene.foundation.block, k) for k in ("length", "width", "height")}
    (L, B, H), sizes = candidate_values(values, given, sizing_of(scene).sizes, "crank_foundation")
    mech = MechanismOperator.of(scene.design())
    _, (zero, *_) = judge_physics(Verdicts(), scene, L, B, H, mech, mech.harmonics, sizes=sizes)
    return zero, crank.evaluate(scene, values)


@pytest.fixture(scope="module")
def candidate_scenes():
    from foundation_calc.scenes import parse_scene

    document = _document()
    found = [_candidate_document(document, *c) for c in CANDIDATES]
    return [(d, parse_scene(d, str(CONFIG))) for d in found]


def _mass_and_weight(scene, samples: int = 720):
    """(M (3, 3) about O in u_x, u_z, θ_y [kg, kg m, kg m²], g Σ m_i z̄_i [N m]) of the scene's
    rigid body: block and machine (M, I_c at C, h above O) and the rod and the slider at their
    positions averaged over a revolution. The crank centre A is a above C; the slider runs below A
    on the vertical through it; the crank pin at angle φ is r (-sin φ, -cos φ) from A; the rod's
    centre of mass l' from the pin towards the slider, its moment of inertia m ρ²."""
    f, mech = scene.foundation, scene.mechanism
    g = 9.81
    h = f.cog_height
    z_a = h + mech.crank_axis_to_cog
    r, l, l1, m, m1, rho = (mech.crank_radius, mech.rod_length, mech.rod_cog_to_crank_pin, mech.rod_mass,
                            mech.slider_mass, mech.rod_radius_of_gyration)
    phi = 2.0 * np.pi * np.arange(samples) / samples
    pin = np.stack([-r * np.sin(phi), z_a - r * np.cos(phi)])
    slider = np.stack([np.zeros(samples), z_a - r * np.cos(phi) - np.sqrt(l * l - (r * np.sin(phi)) ** 2)])
    rod = pin + l1 / l * (slider - pin)

    def body(mass, x, z, inertia=0.0):  # T = m/2 |(u_x' + z θ', u_z' - x θ')|² + J/2 θ'², averaged
        return mass * np.array([[1.0, 0.0, np.mean(z)], [0.0, 1.0, -np.mean(x)],
                                [np.mean(z), -np.mean(x), np.mean(x * x + z * z)]]) + np.diag([0.0, 0.0, inertia])

    M = body(f.mass, np.zeros(1), np.full(1, h), f.moment_of_inertia) + body(m, *rod, m * rho * rho) + body(m1, *slider)
    tilt = g * (f.mass * h + m * np.mean(rod[1]) + m1 * np.mean(slider[1]))
    return M, tilt


def _brute_force(scene):
    """p(ω): the three natural frequencies [rad/s], ascending (..., 3), of the body of
    :func:`_mass_and_weight` on the scene's support's springs at ω (a scalar or an array), by the
    generalised symmetric eigenproblem K v = p² M v (scipy's eigh, one ω at a time)."""
    from scipy.linalg import eigh

    M, tilt = _mass_and_weight(scene)
    support = scene.support()

    def p(omega):
        K = support.impedance(np.asarray(omega, dtype=float)).K[..., PLANE, :][..., PLANE].copy()
        K[..., 2, 2] -= tilt
        found = [np.sqrt(np.abs(eigh(k, M, eigvals_only=True))) for k in K.reshape(-1, 3, 3)]
        return np.reshape(found, np.shape(omega) + (3,))

    return p


def _unique_root(p, j: int):
    """The root ω = p_j(ω) of rank j where a scan of 0.2 ... 5 × its static value crosses once, by
    Brent's method; None where it crosses more often (a pile group's springs give some modes
    several roots: fcalc takes the one its bracket holds)."""
    from scipy.optimize import brentq

    p_s = p(0.0)[j]
    grid = p_s * np.geomspace(0.2, 5.0, 201)
    values = p(grid)[:, j] - grid
    change = np.nonzero(np.sign(values[:-1]) != np.sign(values[1:]))[0]
    if len(change) != 1:
        return None
    k = change[0]
    return brentq(lambda w: p(w)[j] - w, grid[k], grid[k + 1], xtol=1e-13 * p_s, rtol=1e-14)


def test_batch_frequencies_match_resonance_and_a_brute_force_eigen_solve(batch, candidate_scenes):
    """k0, p1, p2 of each candidate by the batch's stacked eigen-solve equal ``fcalc resonance``'s on
    the candidate's own scene, by name (1e-9); by rank, each solves the brute-force eigen-solve's
    ω = p_j(K(ω)) (1e-9), and equals its root by Brent's method where it has one alone."""
    from foundation_calc.api.resonance import resonance

    zero, _ = batch
    alone = 0
    for i, (document, scene) in enumerate(candidate_scenes):
        found = np.array([getattr(zero, mode)[i] for mode in ("k0", "p1", "p2")])
        reported = resonance(document).to_dict()["natural_frequencies"]
        assert found == pytest.approx([reported[mode] for mode in ("k0", "p1", "p2")], rel=1e-9), CANDIDATES[i]
        p, ranked = _brute_force(scene), np.sort(found)
        assert [p(w)[j] for j, w in enumerate(ranked)] == pytest.approx(ranked, rel=1e-9), CANDIDATES[i]
        roots = [(w, _unique_root(p, j)) for j, w in enumerate(ranked)]
        roots = [(w, root) for w, root in roots if root is not None]
        assert [w for w, _ in roots] == pytest.approx([root for _, root in roots], rel=1e-9), CANDIDATES[i]
        alone += len(roots)
    assert alone >= 6  # most modes have one root: those compared with Brent's, every one with its equation


def test_brute_force_body_is_the_scenes_mass(candidate_scenes):
    """The brute-force body's mass and static rocking stiffness are the scene's own: M_tot and the
    scene's coupled stability margin's K_φ - K_xφ²/K_x over P h, as fcalc resonance derives it."""
    from foundation_calc.api.resonance import resonance

    document, scene = candidate_scenes[0]
    M, tilt = _mass_and_weight(scene)
    assert M[0, 0] == pytest.approx(scene.total_mass, rel=1e-12)
    K = scene.support().impedance(0.0).K[np.ix_(PLANE, PLANE)]
    margin = (K[2, 2] - K[0, 2] ** 2 / K[0, 0]) / (scene.total_mass * 9.81 * scene.foundation.cog_height) - 1.0
    derived = resonance(document).to_dict()["derived"]
    assert margin == pytest.approx(derived["rocking_stability_margin"], rel=1e-9)


def test_batch_peaks_match_amplitudes_and_a_pile_length_moves_them(batch, candidate_scenes):
    """The batch's amplitude peaks (their largest ratio to the limits) and resonance utilisation
    (the governing condition's needed band over its margin) equal ``fcalc amplitudes``' on each
    candidate's scene (1e-9); the two candidates that differ in their piles alone differ in both."""
    from foundation_calc.api.amplitudes import amplitudes
    from foundation_calc.checks.design.candidates import PASS

    _, verdicts = batch
    for i in (1, 2):
        report = amplitudes(candidate_scenes[i][0]).to_dict()
        assert verdicts.utilisation["amplitudes"][i] == pytest.approx(max(r["ratio"] for r in report["limits"]), rel=1e-9)
        governing = report["resonance_rule"]["governing"]
        assert verdicts.utilisation["resonance"][i] == pytest.approx(governing["required"] / governing["margin"], rel=1e-9)
        assert report["verdict"] == "pass" and verdicts.outcome["amplitudes"][i] == verdicts.outcome["resonance"][i] == PASS
    for check in ("resonance", "amplitudes"):
        ten, sixteen = verdicts.utilisation[check][1:]
        assert abs(ten / sixteen - 1.0) > 0.01, check


#: A stricter displacement limit [m]: the cheapest block lies inside the range searched.
STRICT_AMPLITUDE = 3.0e-6


@pytest.fixture(scope="module")
def strict_scene(tmp_path_factory):
    import tomli_w

    document = _document()
    document["limits"]["amplitude"] = STRICT_AMPLITUDE
    path = tmp_path_factory.mktemp("piled") / "strict.toml"
    path.write_text(tomli_w.dumps(document), encoding="utf-8")
    return path


#: Columns of the terminal the design's tables must fit (tests/test_block_width.py).
WIDTH = 80


@pytest.fixture(scope="module")
def sized(strict_scene):
    """``fcalc design --write`` over block and pile lengths on the strict scene, on a terminal of
    :data:`WIDTH` columns: the run and the scene it wrote."""
    from typer.testing import CliRunner

    from foundation_calc.cli.app import app
    from foundation_calc.output import console

    written = strict_scene.with_name("best.toml")
    with pytest.MonkeyPatch.context() as patch:
        patch.setattr(console, "UNLIMITED_WIDTH", WIDTH)
        console.stdout.cache_clear()
        run = CliRunner().invoke(app, ["design", str(strict_scene), "--vary", "block.length=4:5", "--vary",
                                       "piles.length=12:16", "--points", "2", "--write", str(written)])
    console.stdout.cache_clear()
    return run, written


def test_best_passes_check_and_the_next_cheaper_fails(sized, strict_scene):
    """Exit 0: the cheapest design, inside the range, re-checked by fcalc check's path agrees, and its
    scene as written passes ``fcalc check``; the block one refined step (0.2 m: the grid's 1 m over
    its refinement) shorter fails it (exit 1) on amplitudes, as the search found."""
    from foundation_calc.api.check import check
    from foundation_calc.scenes.files import parse_toml, read_text

    run, written = sized
    assert run.exit_code == 0, run.output
    assert "every check agrees" in run.stdout and "refined to 0.2" in run.stdout
    best = parse_toml(read_text(written), str(written))
    length, piles = best["foundation"]["block"]["length"], best["piles"]["length"]
    assert 4.0 < length < 5.0
    assert check(written).exit_code == 0
    run = check(_candidate_document(parse_toml(read_text(strict_scene), str(strict_scene)), round(length - 0.2, 6), piles))
    assert run.exit_code == 1
    assert [c["verdict"] for c in run.to_dict()["checks"]] == ["pass", "fail"]


def test_design_tables_fit_80_columns(sized):
    """The verdicts, the Pareto set (the long key foundation.block.length beside piles.length) and
    why the cheaper candidates fail, within 80 columns, no number cut."""
    from rich.cells import cell_len

    run, _ = sized
    assert "Pareto set" in run.stdout and "cheaper candidates fail" in run.stdout
    wide = [line for line in run.stdout.splitlines() if cell_len(line) > WIDTH]
    assert not wide, f"{len(wide)} lines wider than {WIDTH}:\n" + "\n".join(wide[:8])
    assert "…" not in run.stdout


def test_design_exit_codes(runner, strict_scene, tmp_path):
    """Exit 1 and the design's JSON when no block passes (never the refusal of the coupled support,
    exit 3); 2 for a key the scene cannot vary."""
    from foundation_calc.cli.app import app

    impossible = tmp_path / "impossible.toml"
    impossible.write_text(strict_scene.read_text(encoding="utf-8").replace(f"amplitude = {STRICT_AMPLITUDE}",
                                                                           "amplitude = 1e-07"), encoding="utf-8")
    run = runner.invoke(app, ["design", str(impossible), "--vary", "block.length=4:5", "--vary", "piles.length=12:16",
                              "--points", "2", "--json"])
    assert run.exit_code == 1, run.output
    found = json.loads(run.stdout)
    assert not found["passed"] and found["recheck"]["disagreements"] == []
    assert found["closest"]["checks"]["amplitudes"]["outcome"] == "fail"
    run = runner.invoke(app, ["design", str(CONFIG), "--vary", "piles.spacing=1:2"])
    assert run.exit_code == 2 and "piles.spacing" in run.output and "Traceback" not in run.output
