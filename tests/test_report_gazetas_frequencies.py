"""Gazetas' springs on the sheet where the checks took them: at each harmonic n ω and at each
mode's own frequency.

The columns evaluate the printed formulas (Pais & Kausel's modifiers, Gazetas' dashpots, [KM]
(4.5)-(4.7)); the solvers compute the same numbers vectorised (``footing_impedance``) and find
each mode's frequency by iterating ω = p(K(ω)) to 1e-10 relative. Agreement to 1e-9 relative:
the same formulas in double precision; the mode's own frequency on the springs at ω* returns ω*
to the iteration's tolerance, an independent check that the printed chain is the fixed point.
"""

from __future__ import annotations

import pytest

from tests.conftest import CONFIGS
from tests.test_report_methods import _gazetas_scene

TOLERANCE = 1e-9


def _close(a: float, b: float) -> bool:
    return abs(a - b) <= TOLERANCE * max(abs(a), abs(b), 1e-300)


def _amplitudes(scene) -> dict:
    from foundation_calc.checks.amplitudes.approximations import check_scene_amplitudes
    from foundation_calc.output.amplitudes import amplitudes_document

    return amplitudes_document(check_scene_amplitudes(scene), scene, "")


def _pais_kausel_scene(length: float, width: float, embedment: float):
    """The same scene with Pais & Kausel's static springs (Gazetas' dynamic modifiers and dashpots)."""
    from foundation_calc.scenes import parse_scene

    data = _gazetas_scene(length, width, embedment).model_dump(exclude_none=True)
    data["soil"]["method"] = "pais_kausel"
    return parse_scene(data)


@pytest.mark.parametrize("base", [(6.0, 4.0, 1.5, "gazetas"), (4.0, 6.0, 0.0, "gazetas"), (6.0, 4.0, 1.5, "pais_kausel")],
                         ids=["long-embedded", "short-surface", "pais-kausel"])
def test_each_harmonic_and_each_mode_at_its_own_frequency(base):
    from foundation_calc.checks.resonance.frequencies import scene_design_frequencies
    from foundation_calc.output.report.gazetas_frequencies import gazetas_frequency_columns, shown_harmonics
    from foundation_calc.output.report.soil_methods import gazetas_chains

    scene = (_gazetas_scene if base[3] == "gazetas" else _pais_kausel_scene)(*base[:3])
    amplitudes = _amplitudes(scene)
    harmonics = shown_harmonics(amplitudes)
    assert 2 in harmonics  # the crank's 2ω is on the sheet
    by_harmonic, by_mode = gazetas_frequency_columns(scene, gazetas_chains(scene)[0], amplitudes)
    omega = scene.speed.omega_rad_s
    for n, values in zip(harmonics, by_harmonic.values):
        springs = scene.soil_springs(omega=n * omega)  # what splice_harmonics solves harmonic n with
        for key in ("K_z", "K_x", "K_phi", "xi_z", "xi_x", "xi_phi"):
            assert _close(values[key + "w"], float(getattr(springs, key))), (n, key)
    own, _, static = scene_design_frequencies(scene)
    for mode, values in zip(("k0", "p1", "p2"), by_mode.values):
        assert _close(values["omega_s"], float(getattr(own, mode)))
        assert _close(values[mode], values["omega_s"]), mode  # p(K(ω*)) = ω*: the fixed point
        springs = scene.soil_springs(omega=values["omega_s"])
        for key in ("K_z", "K_x", "K_phi"):
            assert _close(values[key + "w"], float(getattr(springs, key))), (mode, key)
    summary = by_mode.blocks()[1]
    assert [row[0] for row in summary.rows] == ["k0", "p1", "p2"]
    assert float(summary.rows[2][1]) == pytest.approx(float(static.p2), rel=1e-3)


def test_every_symbol_of_the_columns_is_in_the_nomenclature():
    from foundation_calc.output.report.methods import methods_section
    from tests.test_report_methods import assert_every_symbol_defined

    scene = _gazetas_scene(6.0, 4.0, 1.5)
    section = methods_section(scene, {"amplitudes": _amplitudes(scene)})
    assert sum("own frequency" in getattr(b, "title", "") for b in section.blocks) == 2  # the columns and their summary
    assert_every_symbol_defined(section)


def test_a_frequency_independent_soil_has_no_columns():
    from foundation_calc.output.report.handcalc import Columns
    from foundation_calc.output.report.methods import crank_chains
    from foundation_calc.scenes import load_scene

    scene = load_scene(CONFIGS / "compressor_medium_sand_lysmer.toml")
    assert not any(isinstance(c, Columns) for c in crank_chains(scene, _amplitudes(scene)))
