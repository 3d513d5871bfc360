"""A design candidate on a pile group whose mode has no natural frequency (ω = p(K(ω)) has no root)
fails alone: the batch goes on and names the mode; ``fcalc check`` refuses that candidate's scene
naming the same mode.

The former reproduction: configs/crank_on_piles.toml's machine at 100 rpm on an 8 m × 3 m × 0.8 m
block over six 2 m × 1.5 m piles (their heads scaled with the plan, as a design moves them). The
group's springs at frequency there are negative in places (K_z = −5744 MN/m at 100 rad/s), and the
mode frequencies were read as sqrt|λ| of the eigenvalues λ of (K(ω), M̄): so read, p2's p(ω) - ω
keeps its sign on the whole scan and p2 was called rootless. A negative λ is no real frequency
(:func:`~foundation_calc.solvers.crank.averaged.natural_modes` with ``at_rest`` False: 0 there,
tests/test_signed_squared_frequency.py): every mode of the 8 m candidate has a root (p2 = 458.3
rad/s), and the candidate is judged, as ``fcalc check`` judges it.

Independent reference, written here: the plane's (K(ω), M̄) assembled by hand in
tests/test_crank_piles.py (the group's impedance at O carried to x, y, θ of C, the mechanism's mean
mass from its kinematics): read as sqrt|λ| its highest frequency p(ω) − ω keeps its sign on the
scan's samples (the former verdict), while each frequency fcalc reports is sqrt of a positive
eigenvalue of (K(p), M̄), p2 the highest.

A truly rootless crank candidate: the shipped supports give none among plausible sizes, so a
support registered here (the sway-rocking toy of tests/test_crank_support_design.py, its springs
times (1 + (ω/ω0)⁴), ω0 = 950 rad/s) makes one. A mode whose frequency on the constant springs is
p0 then has p(ω)² ≈ p0² (1 + (ω/ω0)⁴), which meets ω² only where p0 <= ω0/√2 = 672 rad/s: the 3 m
block's highest mode (p0 = 742 rad/s) has no root, the longer blocks' have. The batch fails that
candidate alone, naming p2, and fcalc check refuses its scene naming p2; the proof of "no root" is
independent: det(K(ω) − ω² M̄) of the hand assembly on a fine grid over the search's range
changes sign only at the two other modes' crossings, and the highest eigenvalue stays above ω².
A block's batch has no such case among the shipped scenes' plausible sizes either: its test makes
one, a block whose springs stiffen faster than its frequencies rise. A mode with several roots: the
shipped piled crank on a 4.5 m block (p2 = 392.8, 444.3 or 584.3 rad/s), against the same hand
assembly on a fine grid.
"""

from __future__ import annotations

import re
from dataclasses import replace

import numpy as np
import pytest
from scipy.linalg import eigvals

import foundation_calc as fc
from foundation_calc.checks.design.apply import applied_document
from foundation_calc.checks.design.candidates import FAIL
from foundation_calc.scenes import parse_scene, read_toml
from foundation_calc.solvers.soil.impedance import SCAN
from foundation_calc.solvers.supports import register, unregister
from foundation_calc.solvers.supports.base import AtO

from tests.conftest import CONFIGS
from tests.test_crank_piles import _mean_mass, _plane
from tests.test_crank_support_design import SWAY, COUPLINGS, Toy, _document
from tests.test_support_design import C_REF

#: The former rootless candidate's block length [m] and the range the batch varies [m].
ROOTLESS_LENGTH = 8.0
VARY = "foundation.block.length=8:9"


@pytest.fixture(scope="module")
def document():
    """The reproduction (module docstring): the shipped piled crank, its block 8 × 3 × 0.8 m on
    2 m × 1.5 m piles at 100 rpm, the base's given size left to the block."""
    doc = read_toml(CONFIGS / "crank_on_piles.toml")
    foundation = doc["foundation"]
    del foundation["base_length"], foundation["base_width"]
    foundation["block"].update(length=ROOTLESS_LENGTH, width=3.0, height=0.8)
    doc["piles"].update(length=2.0, diameter=1.5,
                        positions=[[x * ROOTLESS_LENGTH / 6.0, y * 3.0 / 4.0] for x, y in doc["piles"]["positions"]])
    doc["mechanism"]["speed_rpm"] = 100
    return doc


@pytest.fixture(scope="module")
def designed(document):
    return fc.design(document, vary=[VARY], points=2)


def _eigenvalues(scene, omega: float, M: np.ndarray, z_G: float) -> np.ndarray:
    """The eigenvalues λ [rad²/s²] of the plane's (K(ω), M̄), assembled by hand, ascending."""
    return np.sort(eigvals(_plane(scene, omega, z_G)[0], M).real)


def _highest(scene, omega: float, M: np.ndarray, z_G: float) -> float:
    """The highest natural frequency [rad/s] of the plane's (K(ω), M̄) read as sqrt|λ|, as fcalc
    read it before a negative λ counted as no frequency."""
    return float(np.max(np.sqrt(np.abs(_eigenvalues(scene, omega, M, z_G)))))


def test_read_as_sqrt_abs_the_highest_mode_had_no_root(document):
    """The former verdict, by the hand assembly: p(ω) - ω of the highest mode read as sqrt|λ|
    changes sign between none of fcalc's scan samples (:data:`SCAN` × p(p_s), p_s its static
    frequency, where consistent_frequency centres the scan of springs that stiffen with frequency),
    and the springs there make a λ negative."""
    scene = parse_scene(document)
    M, z_G = _mean_mass(scene)
    static = _highest(scene, 0.0, M, z_G)
    grid = _highest(scene, static, M, z_G) * SCAN
    g = np.array([_highest(scene, w, M, z_G) for w in grid]) - grid
    assert np.all(g > 0.0) or np.all(g < 0.0), grid[np.nonzero(np.diff(np.sign(g)))[0]]
    assert _eigenvalues(scene, 100.0, M, z_G)[0] < 0.0


def test_every_mode_of_the_former_rootless_candidate_is_a_root(document):
    """fcalc resonance finds every mode of the 8 m candidate: each p is sqrt of a positive
    eigenvalue of the hand-assembled (K(p), M̄) (1e-6: the fixed point's rtol and the mean of the
    kinematics' samples), p2 that of the highest (its rank at rest); p2 = 458.3 rad/s where main
    called it rootless."""
    found = fc.resonance(document).to_dict()["natural_frequencies"]
    scene = parse_scene(document)
    M, z_G = _mean_mass(scene)
    for mode in ("k0", "p1", "p2"):
        p = found[mode]
        lam = _eigenvalues(scene, p, M, z_G)
        assert np.min(np.abs(lam - p * p)) < 2e-6 * p * p, (mode, p, lam)
    assert abs(_eigenvalues(scene, found["p2"], M, z_G)[-1] - found["p2"] ** 2) < 2e-6 * found["p2"] ** 2
    assert found["p2"] == pytest.approx(458.32, abs=0.01)


def test_the_batch_judges_the_former_rootless_candidate(designed):
    """The 8 m candidate is no longer failed as rootless: the batch passes with it, the cheapest,
    and no candidate fails for a mode without a natural frequency; the re-check agrees."""
    found = designed.to_dict()
    assert designed.exit_code == 0
    assert found["best"]["values"]["foundation.block.length"] == pytest.approx(ROOTLESS_LENGTH)
    reasons = [f["reason"] for f in found["cheaper_failures"]]
    assert not [r for r in reasons if "has no natural frequency" in r], reasons
    assert found["recheck"]


def test_check_judges_the_former_rootless_candidate(document):
    """fcalc check on the candidate's scene: no invalid scene (exit 3) any more, no mode without a
    natural frequency named."""
    result = fc.check(applied_document(document, {"foundation.block.length": ROOTLESS_LENGTH}))
    assert result.exit_code in (0, 1)
    assert "has no natural frequency" not in str(result.to_dict())


@pytest.fixture(scope="module")
def several_roots_document():
    """configs/crank_on_piles.toml with a 4.5 m block (the pile heads scaled with it): its mode p2
    has several roots of ω = p(K(ω)) on the 16 m piles."""
    doc = read_toml(CONFIGS / "crank_on_piles.toml")
    foundation = doc["foundation"]
    del foundation["base_length"], foundation["base_width"]
    foundation["block"]["length"] = 4.5
    doc["piles"]["positions"] = [[x * 4.5 / 6.0, y] for x, y in doc["piles"]["positions"]]
    return doc


def _independent_roots(scene, low: float, high: float) -> np.ndarray:
    """Every root [rad/s] of p(ω) - ω of the highest mode, assembled by hand, between ``low`` and
    ``high``: sign changes on 600 log-spaced samples (0.23 % apart), each refined by bisection to
    1e-10; p(ω) the sqrt of the highest eigenvalue λ, 0 where λ < 0 (no real frequency)."""
    M, z_G = _mean_mass(scene)
    g = lambda w: np.sqrt(max(_eigenvalues(scene, w, M, z_G)[-1], 0.0)) - w  # noqa: E731
    grid = np.geomspace(low, high, 600)
    values = np.array([g(w) for w in grid])
    roots = []
    for k in np.nonzero((values[:-1] > 0.0) != (values[1:] > 0.0))[0]:
        a, b, ga = grid[k], grid[k + 1], values[k]
        while b - a > 1e-10 * b:
            m = 0.5 * (a + b)
            a, b, ga = (m, b, g(m)) if (g(m) > 0.0) == (ga > 0.0) else (a, m, ga)
        roots.append(0.5 * (a + b))
    return np.array(roots)


def test_a_mode_with_several_roots_is_said_with_every_root(several_roots_document):
    """Main took p2 = 584.3 rad/s silently; now fcalc resonance warns, naming p2 and each root
    its scan found (rad/s and Hz), each a root of the hand-assembled operator's p(ω) = ω (1e-3: the
    message's 4 digits; the one taken, from the JSON, 1e-6: the bisection's 1e-10 and the fixed
    point's rtol), the one taken unchanged (tests/test_json_record.py pins it)."""
    resonance = fc.resonance(several_roots_document).to_dict()  # check's resonance finding: the same lines, its details
    warned = [d for d in resonance["several_roots"] if d.startswith("WARN mode p2 has")]
    assert len(warned) == 1, resonance["several_roots"]
    pairs = [(float(w), float(f)) for w, f in re.findall(r"([\d.]+) rad/s \(([\d.]+) Hz\)", warned[0])]
    listed = [w for w, _ in pairs]
    assert len(listed) >= 2 and all(w / (2.0 * np.pi) == pytest.approx(f, rel=1e-3) for w, f in pairs), warned
    scene = parse_scene(several_roots_document)
    independent = _independent_roots(scene, 0.5 * min(listed), 2.0 * max(listed))
    for w in listed:
        assert np.min(np.abs(independent - w)) / w < 1e-3, (w, independent)  # the message's 4 digits
    taken = resonance["natural_frequencies"]["p2"]
    assert np.min(np.abs(independent - taken)) / taken < 1e-6 and f"takes {taken:.4g} rad/s" in warned[0]
    assert min(listed) == pytest.approx(392.8, abs=0.05) and taken == pytest.approx(584.3, abs=0.05)  # the issue's


def test_consistent_frequency_leaves_a_rootless_element_nan_and_lists_every_root():
    """Closed forms: p = 50 + ω/2 has its root at 100 rad/s, p = 50 + 1.5 ω none (a batch of both
    with rootless="nan": 100 and NaN, where main raised for the batch); p = ω + 100 cos(2π ω/100)
    brackets no root from its static value (p rises past ω twice), and every root its scan lists
    is one of ω = 25 + 50 k (1e-9 of the spacing: Brent's method to round-off)."""
    from foundation_calc.solvers.soil.impedance import consistent_frequency

    batch = lambda w: np.where(np.arange(2) == 0, 50.0 + 0.5 * w, 50.0 + 1.5 * w)  # noqa: E731
    found = consistent_frequency(batch, np.array([50.0, 50.0]), rootless="nan")
    assert found[0] == pytest.approx(100.0, rel=1e-9) and np.isnan(found[1])

    wavy = lambda w: w + 100.0 * np.cos(2.0 * np.pi * np.asarray(w) / 100.0)  # noqa: E731 - p(0) = 100, p(100) = 200, p(200) = 300
    every = []
    root = consistent_frequency(wavy, wavy(0.0), every=every)
    assert len(every) > 1 and np.min(np.abs(np.array(every) - root)) < 1e-9 * root  # the root taken is one of them
    for w in every:  # ω = p(ω) where the cosine vanishes: ω = 25 + 50 k
        assert (w - 25.0) / 50.0 == pytest.approx(round((w - 25.0) / 50.0), abs=1e-9), every


def test_a_speed_at_the_other_root_is_said_as_resonant(several_roots_document):
    """At 3750 rpm (ω = 392.7 rad/s) the speed sits on p2's other root 392.8 rad/s: the finding says
    ω = p2 is as resonant there (margin |ω - 392.8|/392.8 < 0.1 %, under the 20 % band), while the
    verdict stays the root taken's (584.3 rad/s, 33 % away): a warning, not a changed verdict
    (fcalc design's batch judges the one root taken, and its re-check must agree)."""
    doc = {**several_roots_document, "mechanism": {**several_roots_document["mechanism"], "speed_rpm": 3750.0}}
    found = fc.resonance(doc).to_dict()  # fcalc resonance --json: its note, said only when a mode has several roots
    said = [d for d in found["several_roots"] if d.startswith("WARN ω = p2 at the other root 392.8 rad/s")]
    assert len(said) == 1 and "margin 0.0% (needs 20%)" in said[0], found["several_roots"]
    assert found["verdict"] == "pass"


def test_a_block_candidate_whose_springs_stiffen_too_fast_fails_alone():
    """A block's batch (configs/block_fan_torsion_near_speed.toml on Gazetas' footing springs): two
    identical blocks, the second's springs times (1 + (ω/20)⁴), so its every p(ω) rises like ω² and
    outruns ω over the whole scan (asserted here on the scan's samples, by the eigenvalues of
    K(ω) − λ M written out with scipy). consistent_batch raised for the batch; with rootless="nan"
    the first block's modes are the plain batch's and the second fails resonance and amplitudes
    alone, the reason naming a mode without a natural frequency."""
    from scipy.linalg import eigh

    from foundation_calc.checks.design.block import _built, dynamics
    from foundation_calc.errors import PhysicsError
    from foundation_calc.solvers.block.response import consistent_batch

    doc = read_toml(CONFIGS / "block_fan_torsion_near_speed.toml")
    doc["soil"]["method"] = "gazetas"
    scene = parse_scene(doc)
    L, B, H = (np.full(2, getattr(scene.block, k)) for k in ("length", "width", "height"))
    built = _built(scene, L, B, H)

    def stiffening(omega):
        springs, dashpots, *rest = built.impedance(omega)
        factor = np.where(np.arange(2).reshape((2,) + (1,) * (np.ndim(omega) - 1)) == 1, 1.0 + (np.asarray(omega) / 20.0) ** 4, 1.0)
        return (springs * factor[..., None], dashpots, *rest)

    one = consistent_batch(built.model, built.impedance)
    found = consistent_batch(built.model, stiffening, "nan")
    assert list(found.rootless) == [False, True]
    assert np.allclose(found.frequencies[0], one.frequencies[0], rtol=1e-12)
    with pytest.raises(PhysicsError, match="has no natural frequency: ω = p\\(K\\(ω\\)\\) has no root found between"):
        consistent_batch(built.model, stiffening)

    for w in np.outer(found.static_frequencies[1], SCAN).ravel():  # the second block: every p_j(ω) > ω on every scan
        K, _ = built.model.soil_matrices(*stiffening(np.array([w, w])))
        assert np.all(np.sqrt(eigh(K[1], built.model.M[1], eigvals_only=True)) > w), w

    verdicts = dynamics(scene, replace(built, impedance=stiffening))
    for check in ("resonance", "amplitudes"):
        outcome, utilisation, governing, reasons = verdicts[check]
        assert outcome[1] == FAIL and utilisation[1] == np.inf
        assert reasons[governing[1]].startswith("a mode has no natural frequency"), reasons[governing[1]]
        assert not reasons[governing[0]].startswith("a mode has no natural frequency")


#: The stiffening support's ω0 [rad/s] (module docstring) and the name of the scene it takes.
CORNER = 950.0
STIFFENING = "stiffening toy crank"

#: The stiffening scene's block lengths the batch varies [m]: the shortest, 3 m, is rootless.
STIFFENING_VARY = "foundation.block.length=3:8"


class Stiffening(Toy):
    """The sway-rocking toy's springs at O (coupling included) times (1 + (ω/:data:`CORNER`)⁴), its
    dashpots as they are: springs that stiffen with frequency faster than a high mode's frequency rises."""

    frequency_dependent = True

    def impedance(self, omega) -> AtO:
        at = super().impedance(omega)
        factor = (1.0 + (np.asarray(omega, dtype=float) / CORNER) ** 4)[..., None]
        return AtO(at.springs * factor, at.dashpots, (at.coupling[0] * factor[..., None], at.coupling[1]))


def _stiffening_builder(scene, L, B, masses):
    if scene.name != STIFFENING:
        return None
    return Stiffening(np.asarray(scene.soil.c_z, dtype=float) / C_REF, coupled=COUPLINGS[SWAY])


@pytest.fixture(scope="module")
def stiffening():
    """The compressor's crank scene on the stiffening support (registered while the module's tests
    run), the base's size left to the block."""
    doc = _document(STIFFENING)
    del doc["foundation"]["base_length"], doc["foundation"]["base_width"]
    register(_stiffening_builder)
    yield doc
    unregister(_stiffening_builder)


@pytest.fixture(scope="module")
def stiffening_designed(stiffening):
    return fc.design(stiffening, vary=[STIFFENING_VARY], points=3)


def _length(document, length: float) -> dict:
    return applied_document(document, {"foundation.block.length": length})


def test_a_truly_rootless_crank_candidate_fails_alone(stiffening, stiffening_designed):
    """The batch goes on (exit 0): the 3 m block, the cheapest on the grid, fails resonance alone
    for p2 without a natural frequency, and the best is a longer block that the re-check (fcalc
    check's path on the best's written scene) judges as the batch did; fcalc check refuses the 3 m
    block's scene (exit 3) naming the same mode."""
    found = stiffening_designed.to_dict()
    assert stiffening_designed.exit_code == 0, found
    failures = found["cheaper_failures"]
    assert [(f["check"], f["count"]) for f in failures] == [("resonance", 1)], failures
    assert failures[0]["reason"].startswith("mode p2 has no natural frequency"), failures
    assert found["best"]["values"]["foundation.block.length"] > 3.0
    assert found["recheck"]["agree"] and found["recheck"]["designs"] >= 1, found["recheck"]
    refused = fc.check(_length(stiffening, 3.0))
    assert refused.exit_code == 3
    assert "mode p2 has no natural frequency" in str(refused.to_dict())


def _crossings(scene, grid: np.ndarray) -> tuple[np.ndarray, np.ndarray]:
    """Where det(K(ω) − ω² M̄) of the hand assembly (K(ω) the registered support's at ω carried to
    x, y, θ of C, M̄ the mechanism's mean mass) changes sign between neighbours of ``grid`` [rad/s],
    and the highest eigenvalue λ of (K(ω), M̄) minus ω² at each sample [rad²/s²]."""
    M, z_G = _mean_mass(scene)
    det, top = [], []
    for w in grid:
        K = _plane(scene, w, z_G)[0]
        det.append(np.linalg.det(K - w * w * M))
        top.append(np.max(eigvals(K, M).real) - w * w)
    det = np.array(det)
    return grid[1:][np.sign(det[1:]) != np.sign(det[:-1])], np.array(top)


def test_the_rootless_candidate_has_no_root_by_brute_force(stiffening, stiffening_designed):
    """Independent of fcalc's root search: on 1200 log-spaced ω from 20 to 2e4 rad/s (0.58 % apart;
    the search's range, 0.2 to 5 × p(p_s) = 174 to 4349 rad/s, inside), det(K(ω) − ω² M̄) of the
    3 m block changes sign four times, twice for each of the two lower modes (p0 < ω0/√2: a root
    near p0 and one near ω0²/p0), and the highest eigenvalue stays above ω² everywhere: its mode
    crosses nowhere. The best block's det changes sign six times: there the highest mode has its
    roots, one of them fcalc's p2."""
    grid = np.geomspace(20.0, 2.0e4, 1200)
    scene = parse_scene(_length(stiffening, 3.0))
    M, z_G = _mean_mass(scene)
    p_s = np.sqrt(np.max(eigvals(_plane(scene, 0.0, z_G)[0], M).real))
    p_ps = np.sqrt(np.max(eigvals(_plane(scene, p_s, z_G)[0], M).real))
    assert grid[0] < 0.2 * p_ps and 5.0 * p_ps < grid[-1], p_ps
    crossings, top = _crossings(scene, grid)
    assert len(crossings) == 4 and np.all(top > 0.0), (crossings, top.min())
    best = stiffening_designed.to_dict()["best"]["values"]["foundation.block.length"]
    best_scene = parse_scene(_length(stiffening, best))
    crossings, top = _crossings(best_scene, grid)
    assert len(crossings) == 6 and np.any(top < 0.0), crossings
    p2 = fc.resonance(_length(stiffening, best)).to_dict()["natural_frequencies"]["p2"]
    assert np.min(np.abs(crossings - p2)) / p2 < 0.006, (p2, crossings)  # the grid's spacing
