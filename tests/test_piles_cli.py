"""A block on ``[piles]``: the scene's validation (exit 3 naming the key, its unit and range), the
support in the block's model (the group's coupled springs at O), the sheet's chain against the
solver, and the commands on the shipped scene."""

from __future__ import annotations

import json
import tomllib

import numpy as np
import pytest

from foundation_calc.cli.app import app
from foundation_calc.scenes import parse_scene
from tests.conftest import CONFIGS

PILED = CONFIGS / "block_on_piles.toml"


def _document(**piles):
    with open(PILED, "rb") as fh:
        document = tomllib.load(fh)
    document["piles"] |= piles
    return document


def _scene(**piles):
    return parse_scene(_document(**piles), "piles.toml")


@pytest.mark.parametrize("change,words", [
    ({"diameter": -0.6}, ["piles.diameter", "must be > 0", "d [m]"]),
    ({"positions": [[0.0, 0.0], [0.4, 0.0]]}, ["overlap", "0.4", "piles.diameter"]),
    ({"positions": [[3.5, 0.0]]}, ["piles.positions[0]", "outside the block's base", "L/2 = 3"]),
    ({"positions": [[1.0, 0.0], [1.0, 0.0]]}, ["repeats"]),
    ({"soil_profile": "exponential"}, ["soil_profile", "uniform", "linear", "parabolic"]),
    ({"tip": "socketed"}, ["tip", "floating", "end_bearing"]),
    ({"diametre": 0.6}, ["diametre"]),
])
def test_bad_piles_exit_3_naming_the_key(runner, tmp_path, change, words):
    import tomli_w

    path = tmp_path / "bad.toml"
    path.write_bytes(tomli_w.dumps(_document(**change)).encode())
    result = runner.invoke(app, ["resonance", str(path)])
    assert result.exit_code == 3, result.stdout + result.stderr
    for word in words:
        assert word in result.stderr, (word, result.stderr)


def test_piles_need_a_soil_with_a_modulus(runner, tmp_path):
    import tomli_w

    document = _document()
    document["soil"] = {"method": "springs", "stiffness": [1e9] * 6}
    path = tmp_path / "springs.toml"
    path.write_bytes(tomli_w.dumps(document).encode())
    result = runner.invoke(app, ["check", str(path)])
    assert result.exit_code == 3 and "soil.method = 'springs'" in result.stdout + result.stderr


def test_a_stratum_under_piles_is_refused_not_ignored(runner, tmp_path):
    """The piles' impedances are a deep soil's: a stratum_depth beside [piles] would be silently
    left out of them, so the scene is refused naming the key."""
    import tomli_w

    document = _document()
    document["soil"]["stratum_depth"] = 8.0
    path = tmp_path / "stratum.toml"
    path.write_bytes(tomli_w.dumps(document).encode())
    result = runner.invoke(app, ["check", str(path)])
    assert result.exit_code == 3 and "soil.stratum_depth = 8 m with [piles]" in result.stdout + result.stderr


def test_design_leaves_a_piled_block_over_a_modulus_range_to_the_check_path():
    """The design batch scales the soil's springs by one factor per modulus factor, which a pile
    group's are not (the batch's arrays did not even broadcast: an internal error): the vectorised
    evaluator declines the scene, so fcalc design judges each candidate by fcalc check's path."""
    import numpy as np

    from foundation_calc.checks.design.block import evaluate

    document = _document()
    document["soil"]["modulus_range"] = [0.5, 2.0]
    with pytest.raises(NotImplementedError, match=r"modulus_range.*\[piles\]"):
        evaluate(parse_scene(document, "piles.toml"), {"piles.length": np.array([12.0, 18.0])})


def test_model_carries_the_groups_coupled_springs():
    """K at O is the group's (diagonal and the heads' sway-rocking coupling) less the weight's
    tilt, and the static modes are eigh(K, M) of it."""
    from scipy.linalg import eigh

    from foundation_calc.solvers.constants import GRAVITY
    from foundation_calc.solvers.piles.cap import pile_group

    scene = _scene()
    model = scene.model()
    p, s = scene.piles, scene.soil
    xy = np.array(p.positions)
    K_group = pile_group(xy[:, 0], xy[:, 1], p.diameter, p.length, p.modulus, p.density, s.G, s.poisson, s.density,
                         s.material_damping, p.soil_profile, False, False, 0.0).real
    tilt = np.zeros((6, 6))
    tilt[3, 3] = tilt[4, 4] = model.mass * GRAVITY * model.cog[2]
    assert np.allclose(model.K, K_group - tilt, rtol=1e-6, atol=1e-6 * np.abs(K_group).max())
    assert K_group[0, 4] < 0 < K_group[1, 3]
    from foundation_calc.solvers.block.response import block_modes

    p2 = eigh(model.K, model.M, eigvals_only=True)
    assert np.allclose(np.sort(block_modes(model).frequencies) ** 2, np.sort(p2), rtol=1e-8)


@pytest.mark.parametrize("head,tip,profile", [("fixed", "floating", "linear"), ("pinned", "end_bearing", "uniform"),
                                              ("fixed", "end_bearing", "parabolic")])
def test_sheet_chain_is_the_solvers_pile(head, tip, profile):
    from foundation_calc.output.report.block_soil import rendered
    from foundation_calc.solvers.piles.single import pinned, single_pile
    from foundation_calc.solvers.supports.piles import single_pile_chain

    scene = _scene(head=head, tip=tip, soil_profile=profile)
    (chain,) = rendered(single_pile_chain(scene.soil, scene.piles), scene, None, ())
    p, s = scene.piles, scene.soil
    one = single_pile(p.diameter, p.length, p.modulus, p.density, s.G, s.poisson, s.density, profile,
                      tip == "end_bearing", 0.0)
    if head == "pinned":
        one = pinned(one)
    v = chain.values
    assert v["K_v"] == pytest.approx(float(one.K_v.real), rel=1e-9)
    assert v["K_HHp" if head == "pinned" else "K_HH"] == pytest.approx(float(one.K_HH.real), rel=1e-9)
    assert v["K_T"] == pytest.approx(float(one.K_T.real), rel=1e-9)


def test_soil_json_has_the_piles(runner):
    result = runner.invoke(app, ["soil", str(PILED), "--json"])
    assert result.exit_code == 0, result.stderr
    doc = json.loads(result.stdout)
    static = doc["piles"][0]
    assert static["at"] == "static" and 0.0 < static["efficiency"]["z"] < 1.0
    assert len(doc["at_frequencies"]) == 1 + 1 + 6  # at rest, the compressor's speed, six modes


def test_validity_remarks(runner):
    """A short pile in stiff soil is not flexible: the warning names the key and the active length."""
    scene = _scene(length=2.5)
    texts = scene.plausibility_warnings()
    assert any("piles.length = 2.5 m is shorter than the active length" in t for t in texts), texts
    assert any("outside 10-100" in t for t in texts), texts


def test_factored_soil_moves_the_groups_springs():
    """The soil's modulus range scales the soil under the piles (not a cached group): K_HH goes as
    E_s^(1 - 0.35) on the linear profile, the vertical spring between E_s^0 and E_s^1."""
    scene = _scene()
    scene.model()
    stiffer = scene.with_modulus_factor(2.0).model()
    ratio = np.diagonal(stiffer.K) / np.diagonal(scene.model().K)
    single = 2.0 ** (1.0 - 0.35)
    assert ratio[0] == pytest.approx(single, rel=1e-6)  # at rest = at 1e-3 rad/s (cap.OMEGA_REST): 1e-7 apart
    assert 1.0 < ratio[2] < 2.0


def test_sample_is_refused(runner):
    result = runner.invoke(app, ["soil", str(PILED), "--sample", "10"])
    assert result.exit_code == 2 and "not sampled" in result.stderr
