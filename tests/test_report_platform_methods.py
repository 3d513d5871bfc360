"""The platform sheet's 6-DOF verification block: its modes, solved on the sheet from the printed
mean matrices M₀, K₀ (an eigen-solve of M₀⁻¹K₀), are the natural frequencies the check judged
(the solver's scaled symmetric eigen-solve of the same matrices). Agreement to 1e-9 relative: the
same eigenproblem by other routines in double precision.
"""

from __future__ import annotations

import pytest

from foundation_calc.scenes import load_scene
from tests.conftest import CONFIGS

TOLERANCE = 1e-9

PLATFORM = sorted(p for p in CONFIGS.glob("*.toml") if load_scene(p).kind == "platform")


@pytest.mark.parametrize("path", PLATFORM, ids=lambda p: p.stem)
def test_verification_modes_are_the_checks(path):
    import numpy as np

    from foundation_calc.checks.platform import check_platform
    from foundation_calc.output.platform import platform_document
    from foundation_calc.output.report.block_methods import modes_of
    from foundation_calc.output.report.platform_methods import verification_blocks, verification_system

    scene = load_scene(path)
    report = check_platform(scene.design(), scene.model(), scene.limits, scene.inertia_given)
    doc = platform_document(report, scene, "", scene.operation.speed_given_as)
    system = verification_system(scene)
    p, _, _ = modes_of(system.mass[0].real, system.stiff[0].real, np.zeros((6, 6)))
    judged = [f["omega"] for f in doc["natural_frequencies"]]
    assert np.all(np.abs(p - judged) <= TOLERANCE * np.asarray(judged))
    blocks = verification_blocks(scene, doc)
    modes = next(b for b in blocks if getattr(b, "title", "").startswith("Modes of the mean"))
    assert [row[1] for row in modes.rows] == [f["mode"] for f in doc["natural_frequencies"]]
