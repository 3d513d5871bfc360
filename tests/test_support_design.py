"""A support with a size of its own is sized by ``fcalc design`` with no edit in checks/design: a
toy support defined only here (constant springs at O times a scale, coupled sway-rocking), whose
builder registers the scene key of its scale (``soil.c_z``, the subgrade coefficient it reads)
as a size a design may vary, and whose concrete grows with it. ``fc.design`` searches the scale;
its cheapest design, written into the scene, is judged by ``fc.check`` as the design said, the
next cheaper scale fails ``fc.check`` (the toy put in the scene's text here, not by fcalc
design's own write-back), and the design's volume is the block's and the toy's, summed here."""

from __future__ import annotations

import tomllib

import numpy as np
import pytest

import foundation_calc as fc
from foundation_calc.solvers.supports import register, unregister
from foundation_calc.solvers.supports.base import AtO, Variable
from tests import test_support_interface as toy_support
from tests.test_support_interface import C_TOY, K_TOY, OFF

#: soil.c_z [N/m³] of the scale 1; the toy's concrete per unit of scale [m³].
C_REF = 1.0e8
CONCRETE = 4.0

SCALE = Variable("soil.c_z", "toy's spring scale", "the toy scene", "N/m³", 1.0e7, 4.0e8)

#: The toy scene of tests/test_support_interface.py, its springs' scale the subgrade coefficient, and a limit.
SCENE = (toy_support.SCENE.replace('name = "toy"', 'name = "toy sized"')
         .replace('method = "springs"\nstiffness = [1.0e9, 1.0e9, 1.0e9, 1.0e10, 1.0e10, 1.0e10]',
                  'method = "coefficients"\nc_z = 1.0e8\nc_x = 7.0e7\n\n[limits]\nvelocity = 2.0e-3'))


class Toy(toy_support.Toy):
    """The toy's springs at O times ``scale`` (floats, or (N,) over a batch of candidates), its
    dashpots as they are: three of the sizing hooks (no warnings, nothing moves with the plan: the
    defaults)."""

    def __init__(self, scale):
        self.scale = np.asarray(scale, dtype=float)

    def impedance(self, omega) -> AtO:
        omega = np.asarray(omega, dtype=float)
        s = self.scale.reshape(self.scale.shape + (1,) * max(omega.ndim - self.scale.ndim, 0))
        shape = np.broadcast_shapes(omega.shape, s.shape)
        s = np.broadcast_to(s, shape)
        return AtO(s[..., None] * np.diagonal(K_TOY), np.broadcast_to(np.diagonal(C_TOY), shape + (6,)),
                   (s[..., None, None] * (K_TOY * OFF), np.broadcast_to(C_TOY * OFF, shape + (6, 6))))

    @property
    def sizes(self) -> dict:
        return {"soil.c_z": float(self.scale * C_REF)}

    def sized(self, scene, values):
        return scene.model_copy(update={"soil": scene.soil.model_copy(update={"c_z": values["soil.c_z"]})})

    def concrete(self, values=None):
        return CONCRETE * np.asarray((values or self.sizes).get("soil.c_z", self.sizes["soil.c_z"])) / C_REF


def build(scene, L, B, masses):
    return Toy(np.asarray(scene.soil.c_z, dtype=float) / C_REF) if scene.name == "toy sized" else None


@pytest.fixture(scope="module")
def toy(tmp_path_factory):
    """The toy scene's file, with the toy and its size registered while the module's tests run."""
    path = tmp_path_factory.mktemp("toy") / "toy.toml"
    path.write_text(SCENE, encoding="utf-8")
    register(build, variables=(SCALE,))
    yield path
    unregister(build)


def _verdicts(path) -> dict:
    return {c["check"]: c["verdict"] for c in fc.check(path).to_dict()["checks"]}


def test_design_sizes_the_toys_own_scale(toy, tmp_path):
    written = tmp_path / "written.toml"
    result = fc.design(toy, vary=["soil.c_z=2e7:2e8"], points=10, write=written)
    assert result.exit_code == 0, result.to_dict()
    document = result.to_dict()
    best = document["best"]
    c_z = best["values"]["soil.c_z"]
    assert 2e7 < c_z <= 2e8  # the scene's own 1e8 passes: the cheapest is no dearer
    with open(written, "rb") as fh:
        assert tomllib.load(fh)["soil"]["c_z"] == pytest.approx(c_z, rel=1e-9)
    said = {name: check["outcome"] for name, check in best["checks"].items()}
    assert _verdicts(written) == {name: said.get(name, "pass") for name in _verdicts(written)}
    assert best["volume"] == pytest.approx(5.0 * 3.0 * 1.6 + CONCRETE * c_z / C_REF, rel=1e-12)
    (axis,) = document["grid"]["axes"]
    step = axis["refined_step"] or axis["step"]
    cheaper = tmp_path / "cheaper.toml"
    cheaper.write_text(SCENE.replace("c_z = 1.0e8", f"c_z = {c_z - step!r}"), encoding="utf-8")
    assert "fail" in _verdicts(cheaper).values()  # the next cheaper scale on the grid fails fcalc check


def test_a_size_no_support_of_the_scene_has_is_refused(toy):
    from foundation_calc.checks.design.apply import VaryError, applied_document

    with open(fc.load(toy).path, "rb") as fh:
        document = tomllib.load(fh)
    document["name"] = "not the toy"
    with pytest.raises(VaryError, match="soil.c_z varies only in the toy scene"):
        applied_document(document, {"soil.c_z": 5e7})
