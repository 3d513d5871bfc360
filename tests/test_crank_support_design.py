"""``fcalc design`` of a crank foundation asks its support, as ``fcalc check`` does: a toy support
defined only here (constant springs at O times a scale, constant dashpots), whose builder registers
the scene key of its scale (``soil.c_z``, the subgrade coefficient it reads) as a size a design may
vary and whose concrete grows with it, sizes a crank scene through ``fc.design``. Its cheapest
design, written into the scene, is judged by ``fc.check`` as the design said; the next cheaper
scale on the grid fails ``fc.check`` (the toy put in the scene's text here); the design's volume
is the block's and the toy's, summed here. A support that couples sway with rocking (x with θ_y,
a pile group's coupling) is sized by the plane's one model, as the crank's checks judge it; one
that couples the plane's motions otherwise (z with θ_y) is refused by the design as by the crank's
checks: a PhysicsError naming it, exit code 3 (docs/exit-codes.md), from the batch evaluator itself
too, never an answer on uncoupled springs."""

from __future__ import annotations

import tomllib

import numpy as np
import pytest
import tomli_w

import foundation_calc as fc
from foundation_calc.cli.app import app
from foundation_calc.scenes import parse_scene, read_toml
from foundation_calc.solvers.supports import register, unregister
from foundation_calc.solvers.supports.base import AtO, Variable
from tests.conftest import CONFIGS
from tests.test_crank_support import C_TOY, K_TOY
from tests.test_crank_support import Toy as PlaneToy
from tests.test_support_design import C_REF, CONCRETE, _verdicts
from tests.test_support_design import Toy as SizedToy

SCALE = Variable("soil.c_z", "toy's spring scale", "the toy crank scene", "N/m³", 1.0e5, 2.0e8)

#: The names of the scenes the toys take.
SIZED, COUPLED, UNSCALED = "toy crank sized", "coupled toy crank design", "unscaled toy crank"
SWAY = "sway-rocking toy crank design"

#: The pair of motions each coupled toy couples at O: z with θ_y (refused), x with θ_y (taken).
COUPLINGS = {COUPLED: (2, 4), SWAY: (0, 4)}


class Toy(SizedToy):
    """The plane toy's springs at O times ``scale`` (a float, or (N,) over a batch of candidates),
    its dashpots as they are (coupled at ``coupled``, a pair of motions, as the plane toy); the sizing hooks of the block's
    sized toy (its scale is soil.c_z / C_REF, its concrete CONCRETE per unit of scale)."""

    def __init__(self, scale, coupled=None):
        super().__init__(scale)
        self.coupled = coupled

    def impedance(self, omega) -> AtO:
        at = PlaneToy.impedance(self, omega)
        omega = np.asarray(omega, dtype=float)
        s = self.scale.reshape(self.scale.shape + (1,) * max(omega.ndim - self.scale.ndim, 0))
        shape = np.broadcast_shapes(omega.shape, s.shape)
        coupling = None if at.coupling is None else tuple(np.broadcast_to(c, shape + (6, 6)) for c in at.coupling)
        return AtO(np.broadcast_to(s, shape)[..., None] * K_TOY, np.broadcast_to(C_TOY, shape + (6,)), coupling)


def build(scene, L, B, masses):
    if scene.name not in (SIZED, COUPLED, SWAY, UNSCALED):
        return None
    toy = Toy(np.asarray(scene.soil.c_z, dtype=float) / C_REF, coupled=COUPLINGS.get(scene.name))
    if scene.name == UNSCALED:
        toy.unscaled = "[toy]: its springs do not scale with the soil's modulus"
    return toy


def _document(name: str) -> dict:
    """The compressor on its block (``[foundation.block]``), its soil the toy's scale."""
    document = read_toml(CONFIGS / "compressor_medium_sand_lysmer.toml")
    document["name"] = name
    document["soil"] = {"method": "coefficients", "c_z": C_REF, "c_x": 0.7 * C_REF}
    return document


@pytest.fixture(scope="module")
def toy(tmp_path_factory):
    """The toy scenes' files (sized, coupled vertically, coupled in sway-rocking), with the toy and its size registered while the module's tests run."""
    folder = tmp_path_factory.mktemp("crank_toy")
    paths = {}
    for name in (SIZED, COUPLED, SWAY):
        paths[name] = folder / f"{name.replace(' ', '_')}.toml"
        paths[name].write_text(tomli_w.dumps(_document(name)), encoding="utf-8")
    register(build, variables=(SCALE,))
    yield paths
    unregister(build)


def _agrees(best: dict, written) -> None:
    """The design's verdicts of its ``best`` are fc.check's of its ``written`` scene."""
    said = {name: check["outcome"] for name, check in best["checks"].items()}
    assert _verdicts(written) == {name: said.get(name, "pass") for name in _verdicts(written)}


def test_design_sizes_a_crank_on_the_toys_own_scale(toy, tmp_path):
    written = tmp_path / "written.toml"
    result = fc.design(toy[SIZED], vary=["soil.c_z=1e6:1e8"], points=12, write=written)
    assert result.exit_code == 0, result.to_dict()
    document = result.to_dict()
    best = document["best"]
    c_z = best["values"]["soil.c_z"]
    assert 1e6 < c_z < 1e8  # the softest scales fail, the scene's own passes: a size in between
    with open(written, "rb") as fh:
        assert tomllib.load(fh)["soil"]["c_z"] == pytest.approx(c_z, rel=1e-9)
    _agrees(best, written)
    assert best["volume"] == pytest.approx(6.0 * 4.0 * 1.6 + CONCRETE * c_z / C_REF, rel=1e-12)
    (axis,) = document["grid"]["axes"]
    step = axis["refined_step"] or axis["step"]
    cheaper = tmp_path / "cheaper.toml"
    changed = _document(SIZED)
    changed["soil"]["c_z"] = c_z - step
    cheaper.write_text(tomli_w.dumps(changed), encoding="utf-8")
    assert "fail" in _verdicts(cheaper).values()  # the next cheaper scale on the grid fails fcalc check


def test_the_crank_batch_judges_blocks_on_the_toy_as_fcalc_check_does(toy, tmp_path):
    """Blocks varied on the toy: the batch's verdicts of the cheapest are fcalc check's of its
    written scene (on the scene's soil instead of its support the re-check disagrees: exit 4)."""
    written = tmp_path / "block.toml"
    result = fc.design(toy[SIZED], vary=["foundation.block.length=3:8", "foundation.block.height=0.8:2.5"], points=4,
                       write=written)
    assert result.exit_code == 0, result.to_dict()["recheck"]
    _agrees(result.to_dict()["best"], written)


def test_a_sway_rocking_support_is_sized_as_fcalc_check_judges_it(toy, tmp_path):
    """x coupled with θ_y (K_xφ, C_xφ): the batch's verdicts of the cheapest block are fc.check's of
    its written scene, and the re-check agrees (exit 0)."""
    written = tmp_path / "sway.toml"
    result = fc.design(toy[SWAY], vary=["foundation.block.length=3:8"], points=4, write=written)
    assert result.exit_code == 0, result.to_dict()["recheck"]
    _agrees(result.to_dict()["best"], written)


def test_a_coupled_support_is_refused_by_the_crank_design(toy, runner):
    from foundation_calc.checks.design.crank import evaluate

    scene = parse_scene(_document(COUPLED))
    with pytest.raises(fc.PhysicsError, match="support toy couples"):
        evaluate(scene, {"foundation.block.length": np.array([5.0, 6.0])})
    run = runner.invoke(app, ["design", str(toy[COUPLED]), "--vary", "foundation.block.length=5:7"])
    assert run.exit_code == 3 and "support toy couples" in run.output, run.output
    assert run.exception is None or isinstance(run.exception, SystemExit)


def test_a_support_that_does_not_scale_is_left_to_the_full_path_over_the_modulus_range(toy):
    """Over ``soil.modulus_range`` the batch scales the support's springs by one factor; a support
    that says they do not scale (:attr:`~foundation_calc.solvers.supports.base.Support.unscaled`)
    is left to fcalc check's path (NotImplementedError naming it), as the block's batch leaves it."""
    from foundation_calc.checks.design.crank import evaluate

    document = _document(UNSCALED)
    document["soil"]["modulus_range"] = [0.8, 1.2]
    with pytest.raises(NotImplementedError, match=r"does not hold for a block on \[toy\]"):
        evaluate(parse_scene(document), {"foundation.block.length": np.array([5.0, 6.0])})
