"""Stress tests of ``fcalc platform`` at its singular points: c0 → Mω² and u → 2ml/(M+2m).

c0 = (M + m)ω² + σ m l ω²/u (Eq. (3.14)): c0 → Mω² when u → l above resonance (the exciter
height (3.11) divides by c0 - Mω²), c0 → 0 when u → m l/(M + m) (one rotor; 2ml/(M + 2m) for a
pair). Near each, 1e-12 .. 1e-2 relative, the command must give finite JSON or a clear error
(exit 3), never NaN, inf or an internal error.
"""

from __future__ import annotations

import json

import pytest

from foundation_calc.cli.app import app
from foundation_calc.scenes import read_toml
from tests.conftest import CONFIGS
from tests.test_stress_resonance import _finite

SCENE = CONFIGS / "platform_paper_example.toml"
OFFSETS = [0.0, 1e-12, -1e-9, 1e-6, -1e-2]



def _singular_amplitudes():
    doc = read_toml(SCENE)
    M, m, l = doc["platform"]["mass"], doc["exciter"]["rotor_mass"], doc["exciter"]["eccentricity"]
    return {"u = l (c0 = Mω²)": l, "u = ml/(M+m) (c0 = 0)": m * l / (M + m), "u = 2ml/(M+2m)": 2 * m * l / (M + 2 * m)}


@pytest.mark.parametrize("label", list(_singular_amplitudes()))
def test_amplitude_near_singular_points(runner, tmp_path, label, regime="above"):
    """σ = -1 (above resonance) is where both singular points lie."""
    import tomli_w

    doc = read_toml(SCENE)
    doc["operation"]["regime"] = regime
    path = tmp_path / "p.toml"
    path.write_text(tomli_w.dumps(doc), encoding="utf-8")
    u0 = _singular_amplitudes()[label]
    for offset in OFFSETS:
        result = runner.invoke(app, ["platform", str(path), "--amp", repr(u0 * (1 + offset)), "--json"])
        assert result.exit_code in (0, 1, 3), (offset, result.output)
        if result.exit_code == 3:
            assert json.loads(result.stdout)["verdict"] == "invalid" and "error" in result.stderr
        else:
            assert _finite(json.loads(result.stdout)), offset
