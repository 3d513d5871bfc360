"""A vibration code on a crank scene on a pile group (configs/crank_on_piles.toml with
``[limits] code = "ISO 10816-3"``, no ``foundation``): the code's support class is classified from
the modes of the one model in the plane the resonance check solves (the averaged operator with the
group's sway-rocking coupling K_xφ, each mode on the springs at its own frequency).

Independent reference, written here: a brute-force eigen-solve of the plane's 3 × 3 at each mode's
own frequency p (the group's 6 × 6 at O read from the support and carried to x, y, θ of C, the mean
mass of block and mechanism averaged over one revolution, both by the helpers of
tests/test_crank_piles.py), its eigenvector of eigenvalue p² mass-normalised; then the support
class of ISO 10816-3:2009, 3.4 by hand: the lowest mode carrying at least 1 % of a point's static
compliance along a direction, rigid when at least 1.25 times the speed.
"""

from __future__ import annotations

import numpy as np
import pytest
import tomli_w
from scipy.linalg import eig

import foundation_calc as fc
from foundation_calc.checks.amplitudes.approximations import scene_supports
from foundation_calc.checks.resonance.frequencies import scene_plane_modes
from foundation_calc.cli.app import app
from foundation_calc.scenes import parse_scene, read_toml

from tests.conftest import CONFIGS
from tests.test_crank_piles import _mean_mass, _plane

#: A bearing off the centre line, where rocking shows in both directions [m] from C.
BEARING = {"name": "bearing", "horizontal": 1.5, "height": 1.4}


@pytest.fixture(scope="module")
def document():
    document = read_toml(CONFIGS / "crank_on_piles.toml")
    document["limits"] |= {"code": "ISO 10816-3", "machine_group": 2, "machine_power": 250e3}
    document["points"] = [BEARING]
    return document


@pytest.fixture(scope="module")
def frequencies(document):
    return fc.resonance(document).to_dict()["natural_frequencies"]


@pytest.fixture(scope="module")
def brute_force(document, frequencies):
    """Mode name -> (p [rad/s], mass-normalised shape x, y, θ of C) of the plane's (K(p), M̄)."""
    scene = parse_scene(document)
    M, z_G = _mean_mass(scene)
    found = {}
    for mode in ("k0", "p1", "p2"):
        p = frequencies[mode]
        values, vectors = eig(_plane(scene, p, z_G)[0], M)
        j = int(np.argmin(np.abs(values.real - p * p)))
        v = vectors[:, j].real
        found[mode] = (p, v / np.sqrt(v @ M @ v))
    return found


def test_the_plane_modes_on_piles_are_a_brute_force_eigen_solve(document, brute_force):
    """The shapes the code's classification reads are the plane's eigenvectors at their own frequencies
    (1e-6 of the shape's size: the frequencies' fixed point to 1e-9 and the mean mass of 4096 samples)."""
    scene = parse_scene(document)
    modes = scene_plane_modes(scene, {mode: p for mode, (p, _) in brute_force.items()})
    assert modes.labels == ("k0", "p1", "p2")
    scale = np.array([1.0, 1.0, scene.foundation.cog_height])  # θ to a length, to compare with x, y
    for j, (p, shape) in enumerate(brute_force.values()):
        got = modes.shapes[:, j]
        sign = np.sign(got @ shape)
        assert np.max(np.abs((sign * got - shape) * scale)) < 1e-6 * np.max(np.abs(shape * scale)), (j, got, shape)


def _by_hand(brute_force, horizontal: float, height: float, excitation: float) -> dict[str, tuple[str, str]]:
    """Direction -> (class, lowest mode) at the point ``horizontal`` from C along +x, ``height`` above C:
    a body point p moves by (x − θ p_y, y + θ p_x) with y down (p_y = −height)."""
    names = list(brute_force)
    p = np.array([brute_force[n][0] for n in names])
    x, y, theta = np.array([brute_force[n][1] for n in names]).T
    motion = {"horizontal": x + theta * height, "vertical": y + theta * horizontal}
    found = {}
    for direction, phi in motion.items():
        compliance = (phi / p) ** 2
        inside = [j for j in np.argsort(p) if compliance[j] >= 0.01 * compliance.sum()]
        lowest = inside[0]
        found[direction] = ("rigid" if p[lowest] >= 1.25 * excitation else "flexible", names[lowest])
    return found


def test_the_support_class_on_piles_is_classified_from_the_coupled_modes(document, brute_force):
    """Every point's support class (C and the bearing) in each direction, as ``fcalc amplitudes`` and
    ``fcalc check`` judge the code's zones with it: the class and the mode that sets it, as the
    brute-force modes give them, the mode's frequency the resonance check's."""
    scene = parse_scene(document)
    excitation = scene.speed.omega_rad_s
    points = scene_supports(scene)
    assert set(points) == {"C", "bearing"}
    for name, (u, H) in {"C": (0.0, 0.0), "bearing": (BEARING["horizontal"], BEARING["height"])}.items():
        for support in (c.document() for c in points[name]):
            expected, mode = _by_hand(brute_force, u, H, support["excitation"])[support["direction"]]
            assert (support["support"], support["mode"]) == (expected, mode), (name, support)
            assert support["frequency"] == pytest.approx(brute_force[mode][0], rel=1e-12)
            assert not support["given"]
            assert support["excitation"] == excitation


@pytest.fixture(scope="module")
def scene_file(document, tmp_path_factory):
    path = tmp_path_factory.mktemp("piles_code") / "crank_on_piles_code.toml"
    path.write_text(tomli_w.dumps(document), encoding="utf-8")
    return path


def test_check_and_report_judge_the_code_on_piles(scene_file, runner):
    """``fcalc check`` judges the code's zones (exit 0: zone A everywhere at 150 rpm, the support
    classified from the modes) and the calculation sheet exits as check does, with the code's rows
    (``fcalc report``'s sheet, made without its figures to keep the suite quick)."""
    import json

    from foundation_calc.api.options import display_units
    from foundation_calc.api.report import SHEET_UNITS
    from foundation_calc.output.report import write_sheet
    from foundation_calc.output.report.documents import scene_sheet

    check = runner.invoke(app, ["check", str(scene_file), "--json"])
    assert check.exit_code == 0, check.output
    verdicts = {c["check"]: c for c in json.loads(check.output)["scenes"][0]["checks"]}
    assert verdicts["amplitudes"]["verdict"] == "pass", verdicts
    assert "ISO 10816-3, group 2, rigid: zone A" in verdicts["amplitudes"]["reason"]
    assert "classified from the modes: p1 = " in verdicts["amplitudes"]["reason"]
    sheet, run = scene_sheet(scene_file, "fcalc report", display_units(None, SHEET_UNITS), figures=False, fit_units=True)
    assert run.exit_code(strict=False) == check.exit_code
    out = scene_file.with_suffix(".md")
    write_sheet(sheet, out)
    text = out.read_text(encoding="utf-8")
    assert "ISO 10816-3" in text and "classified from the modes" in text


def test_the_soil_validity_on_piles_judges_the_motions_each_mode_strains(document, brute_force):
    """The soil model's range is judged at each mode with the motions whose direct springs at O (the
    group's K_x, K_z, K_φ read from its 6 × 6 at the mode's frequency) hold at least 1 % of the
    mode's strain energy k_i q_i² in the brute-force shape (u_x = x − h θ, u_z = −y, θ_y = θ)."""
    scene = parse_scene(document)
    h = scene.foundation.cog_height
    values = fc.resonance(document).to_dict()["soil_validity"]["values"]
    for mode, (p, (x, y, theta)) in brute_force.items():
        springs = scene.support().impedance(p).springs[[0, 2, 4]]
        energy = springs * np.array([x - h * theta, -y, theta]) ** 2
        expected = [m for m, e in zip(("horizontal", "vertical", "rocking"), energy) if e >= 0.01 * energy.sum()]
        assert [v["motion"] for v in values if v["at"] == mode] == expected, (mode, energy / energy.sum())
