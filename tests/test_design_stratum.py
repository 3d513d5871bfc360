"""``fcalc design`` on a block over a stratum (``[soil] stratum_depth``): the vectorised batch
against ``fcalc check``'s path, candidate by candidate.

The stratum's factors and cutoffs depend on the base L × B, and so does its plausibility remark
(a layer shallower than 2 R, R = sqrt(L B/π), takes extrapolated factors): the batch must judge
both on each candidate's base, not on the scene's own. It did not judge the remark per candidate,
and ``fcalc report`` of such a scene ended in an internal error (exit 4, the re-check disagreeing
on the ``inputs`` check).
"""

from __future__ import annotations

import tomllib

import numpy as np
import pytest

import foundation_calc as fc
from foundation_calc.checks.design import reference
from foundation_calc.checks.design.apply import apply
from foundation_calc.checks.design.block import _built, evaluate
from foundation_calc.checks.design.candidates import PASS, WARN
from foundation_calc.checks.design.recheck import OUTCOME_NAMES, disagreements
from foundation_calc.scenes import parse_scene

from tests.conftest import CONFIGS

#: A stratum 6 m deep under the fan's block (Gazetas' springs): 2 R = 6 m at L B = 9 π = 28.3 m².
STRATUM = 6.0

#: Candidates on both sides of H = 2 R (the scene's own 5 × 3 m base: 2 R = 4.37 m, no remark; the
#: last, 4.2 × 6.5 m, just short of it: 2 R = 5.90 m).
CANDIDATES = {"block.length": np.array([5.0, 5.28, 6.6, 8.0, 4.2]), "block.width": np.array([3.0, 5.54, 6.9, 7.0, 6.5]),
              "block.height": np.array([1.6, 3.94, 3.0, 3.4, 2.2])}


@pytest.fixture(scope="module")
def document():
    with open(CONFIGS / "block_fan_torsion_near_speed.toml", "rb") as f:
        found = tomllib.load(f)
    found["soil"] = {"method": "gazetas", "shear_wave_velocity": 150.0, "density": 1850.0, "poisson": 0.33,
                     "material_damping": 0.03, "stratum_depth": STRATUM}
    return found


def test_batch_springs_and_dashpots_on_a_stratum_are_the_check_paths(document):
    """Each candidate's springs and dashpots in the batch at frequencies below, between and above
    the stratum's cutoffs (ω_s = 2π V_s/4H = 39.3 rad/s, ω_c = 2π V_La/4H = 93.6 rad/s) equal those
    of its own scene (``fcalc check``'s path) to 1e-9: the same closed forms in another order,
    round-off only. The stratum moves them (factors 1 + c R/H, no radiation below a cutoff)."""
    scene = parse_scene(document, "stratum")
    L, B, H = (CANDIDATES[key] for key in ("block.length", "block.width", "block.height"))
    built = _built(scene, L, B, H)
    omega = np.broadcast_to(np.array([0.0, 20.0, 60.0, 103.7, 200.0]), (len(L), 5))
    springs, dashpots = built.impedance(omega)
    deep = parse_scene(document | {"soil": {k: v for k, v in document["soil"].items() if k != "stratum_depth"}}, "deep")
    for i in range(len(L)):
        one = apply(document, {key: float(values[i]) for key, values in CANDIDATES.items()})
        K, C = one.soil_impedance(omega[i])
        np.testing.assert_allclose(springs[i], K, rtol=1e-9, err_msg=f"springs of candidate {i}")
        np.testing.assert_allclose(dashpots[i], C, rtol=1e-9, atol=1e-9 * np.abs(C).max(), err_msg=f"dashpots of candidate {i}")
        np.testing.assert_allclose(built.model.K[i], one.model().K, rtol=1e-9, atol=1e-9 * np.abs(one.model().K).max())
        K_deep, C_deep = apply(deep.model_dump(exclude_unset=True), {k: float(v[i]) for k, v in CANDIDATES.items()}).soil_impedance(omega[i])
        assert (K[:, 2] > 1.1 * K_deep[:, 2]).all()  # the layer stiffens the vertical spring
        assert (C[1, :] < C_deep[1, :]).all()  # at 20 rad/s, below both cutoffs: material damping only


def test_batch_judges_the_stratums_remark_on_each_candidates_base(document):
    """The batch and the check path agree on every check of candidates on both sides of H = 2 R;
    those with 2 R > 6 m warn (the remark of the candidate's base), the scene's own base not."""
    scene = parse_scene(document, "stratum")
    searched = evaluate(scene, CANDIDATES)
    full = reference.evaluate(document, CANDIDATES)
    assert [d.text for d in disagreements(CANDIDATES, searched, full)] == []
    R = np.sqrt(CANDIDATES["block.length"] * CANDIDATES["block.width"] / np.pi)
    np.testing.assert_array_equal(searched.outcome["inputs"], np.where(STRATUM < 2.0 * R, WARN, PASS))
    assert searched.outcome["inputs"].tolist() == [PASS, WARN, WARN, WARN, PASS]  # 4.2 × 6.5 m: 2 R = 5.90 m


def test_design_of_a_block_on_a_stratum_is_what_fcalc_check_says_of_it(document, tmp_path):
    """fc.design over a small grid (its re-check agreeing: exit 0, not 4), and fc.check of the
    written design: the same verdict per check and the same utilisations (1e-9: the same path)."""
    import tomli_w

    scene = tmp_path / "stratum.toml"
    scene.write_text(tomli_w.dumps(document))
    best = tmp_path / "best.toml"
    result = fc.design(scene, vary=["block.length=5:8", "block.width=5:7", "block.height=3:4"], points=3, write=best)
    assert result.exit_code == 0, result.to_dict()["recheck"]
    found = result.to_dict()["best"]
    assert found["checks"]["inputs"]["outcome"] == "warn"  # 2 R > 6 m for the chosen base
    checked = fc.check(best)
    for run in checked.report.runs:
        outcome, utilisation, _ = reference.judged(run)
        said = found["checks"].get(run.check, {"outcome": "pass", "utilisation": None})
        assert OUTCOME_NAMES[outcome] == said["outcome"], run.check
        if said["utilisation"] is not None:
            np.testing.assert_allclose(utilisation, said["utilisation"], rtol=1e-9, err_msg=run.check)


def test_crank_batch_judges_the_stratums_remark_on_each_candidates_base():
    """The crank foundation's batch the same way: a 6 m stratum under Lysmer's compressor block,
    6 × 4 m (2 R = 5.53 m, no remark) and 7 × 5 m (2 R = 6.68 m, the remark), as fcalc check."""
    import importlib

    from foundation_calc.checks.design.candidates import EVALUATORS

    with open(CONFIGS / "compressor_medium_sand_lysmer.toml", "rb") as f:
        crank = tomllib.load(f)
    crank["soil"]["stratum_depth"] = STRATUM
    batch = {"foundation.block.length": np.array([6.0, 7.0]), "foundation.block.width": np.array([4.0, 5.0]),
             "foundation.block.height": np.array([1.6, 1.6])}
    searched = importlib.import_module(EVALUATORS["crank_foundation"]).evaluate(parse_scene(crank, "crank"), batch)
    assert [d.text for d in disagreements(batch, searched, reference.evaluate(crank, batch))] == []
    assert searched.outcome["inputs"].tolist() == [PASS, WARN]
