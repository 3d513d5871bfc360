"""``fcalc soil`` on a crank scene on a pile group (configs/crank_on_piles.toml): the group's springs
and dashpots in the plane at O (K_x, K_z, K_φ, K_xφ; C_x, C_z, C_φ, C_xφ) at rest, at the speed's
harmonics and at each mode's own frequency, the plane's natural frequencies k0, p1, p2, and the
piles' own table; no comparison of the footing's soil methods.

Independent references, written here:

- the support's 6 × 6 K and C at O read at each column's frequency
  (``scene.support().impedance(ω)``): the table is its u_x, u_z, θ_y rows and the u_x-θ_y coupling
  (1e-12 relative: one evaluation at an array of frequencies against one at a time, round-off);
- the group's static springs summed pile by pile: each unit motion of the cap (u_x, u_z, θ_y) sets
  every head's displacement, the heads' forces solve Dobry & Gazetas' superposition
  u_i = Σ_j α_ij P_j/K_1 with the static factor α = sqrt(r0/S) (their paper, ω → 0), each fixed head
  adds its own K_HM and K_MM, and the forces and moments about O are summed over the piles; the
  single pile's heads are :func:`~foundation_calc.solvers.piles.single.single_pile`'s (1e-9: a
  6 × 6 linear solve at ratios of 1e0..1e1, round-off);
- k0, p1, p2: each a natural frequency of the plane's 3 × 3 (K(p), M̄) assembled here from the
  table's own springs at that mode (carried to C, the weight's −W z_G on θ) and the mechanism's
  mean mass averaged over one revolution (:func:`tests.test_crank_piles._mean_mass`), by numpy's
  generalised eigen-solve (1e-6 relative: the fixed point p = p(K(p)) is solved to 1e-9);
- every line of the text at 80 columns fits them, with no number cut.
"""

from __future__ import annotations

import numpy as np
import pytest
from rich.cells import cell_len
from scipy.linalg import eigvals

import foundation_calc as fc
from foundation_calc.cli.app import app
from foundation_calc.output import console
from foundation_calc.scenes import parse_scene, read_toml
from foundation_calc.solvers.constants import GRAVITY
from foundation_calc.solvers.piles.single import single_pile
from tests.test_crank_piles import CONFIG, _mean_mass

PLANE = {"x": 0, "z": 2, "phi": 4}


@pytest.fixture(scope="module")
def scene():
    return parse_scene(read_toml(CONFIG))


@pytest.fixture(scope="module")
def soil():
    return fc.soil(read_toml(CONFIG)).to_dict()


def _columns(soil) -> list[dict]:
    return soil["in_plane"]["at_frequencies"] + soil["in_plane"]["at_modes"]


def test_the_table_is_the_supports_6x6_at_o(scene, soil):
    """Each column's K's and C's are the support's 6 × 6 at O at its frequency: rest, n ω for n = 1..4
    and the modes' own frequencies."""
    omega = scene.speed.omega_rad_s
    rows = soil["in_plane"]["at_frequencies"]
    assert [r["omega"] for r in rows] == pytest.approx([0.0, omega, 2 * omega, 3 * omega, 4 * omega], rel=1e-15)
    assert [r["omega"] for r in soil["in_plane"]["at_modes"]] == [soil["in_plane"]["natural_frequencies"][m]
                                                                    for m in ("k0", "p1", "p2")]
    for row in _columns(soil):
        at = scene.support().impedance(row["omega"])
        for name, M in (("K", at.K), ("C", at.C)):
            x, z, phi = (PLANE[k] for k in ("x", "z", "phi"))
            expected = {"x": M[x, x], "z": M[z, z], "phi": M[phi, phi], "xphi": M[x, phi]}
            assert M[x, phi] == pytest.approx(M[phi, x], rel=1e-12)
            for key, value in expected.items():
                assert row[f"{name}_{key}"] == pytest.approx(value, rel=1e-12), (row["at"], name, key)
    assert soil["in_plane"]["at_frequencies"][0]["K_xphi"] < 0.0  # the coupling is there, not dropped


def _static_group_by_piles(scene) -> np.ndarray:
    """K (3 × 3) at O in (u_x, u_z, θ_y) of the scene's piles at rest, summed pile by pile (module
    docstring): heads at (x_i, y_i) from O, w_i = u_z − x_i θ_y, u_i = u_x, the head turned by θ_y."""
    p, s = scene.piles, scene.soil
    head = single_pile(p.diameter, p.length, p.modulus, p.density, s.density * s.shear_wave_velocity**2, s.poisson,
                       s.density, p.soil_profile, p.tip == "end_bearing", 0.0)
    K_v, K_HH, K_MM, K_HM = (float(np.real(getattr(head, k))) for k in ("K_v", "K_HH", "K_MM", "K_HM"))
    xy = np.array(p.positions, dtype=float)
    n = len(xy)
    alpha = np.eye(n)
    for i in range(n):
        for j in range(n):
            if i != j:
                alpha[i, j] = np.sqrt(p.diameter / 2.0 / np.hypot(*(xy[i] - xy[j])))
    K = np.zeros((3, 3))
    for column, (u_x, u_z, theta) in enumerate(np.eye(3)):
        w = u_z - xy[:, 0] * theta
        P_z = K_v * np.linalg.solve(alpha, w)
        P_x = K_HH * np.linalg.solve(alpha, np.full(n, u_x))
        F_x = M_y = F_z = 0.0
        for i in range(n):
            F_x += P_x[i] + K_HM * theta
            F_z += P_z[i]
            M_y += -xy[i, 0] * P_z[i] + K_HM * u_x + K_MM * theta
        K[:, column] = F_x, F_z, M_y
    return K


def test_the_static_springs_are_the_piles_summed_one_by_one(scene, soil):
    """The static K_x, K_z, K_φ, K_xφ against the group summed pile by pile (module docstring); the
    cap does not bear (no ``cap_contact``, no embedment), so the piles are the whole support."""
    assert not scene.piles.cap_contact and not scene.foundation.embedment
    K = _static_group_by_piles(scene)
    rest = soil["in_plane"]["at_frequencies"][0]
    assert K[0, 2] == pytest.approx(K[2, 0], rel=1e-12)
    for key, value in (("K_x", K[0, 0]), ("K_z", K[1, 1]), ("K_phi", K[2, 2]), ("K_xphi", K[0, 2])):
        assert rest[key] == pytest.approx(value, rel=1e-9), key


def _plane_at_c(scene, row: dict, z_G: float) -> np.ndarray:
    """The table's springs at O in (u_x, u_z, θ_y) carried to x, y (down), θ of C (u_x = x − h θ,
    u_z = −y, θ_y = θ), the weight's −W z_G on θ."""
    K_O = np.array([[row["K_x"], 0.0, row["K_xphi"]], [0.0, row["K_z"], 0.0], [row["K_xphi"], 0.0, row["K_phi"]]])
    h = scene.foundation.cog_height
    P = np.array([[1.0, 0.0, -h], [0.0, -1.0, 0.0], [0.0, 0.0, 1.0]])
    return P.T @ K_O @ P - np.diag([0.0, 0.0, scene.total_mass * GRAVITY * z_G])


def test_the_frequencies_are_an_eigen_solve_of_the_tables_springs(scene, soil):
    """Each printed k0, p1, p2 is a natural frequency of the plane's 3 × 3 on the table's springs at
    that mode (module docstring); the static ones of the springs at rest. They are resonance's, and
    so is the warning that a0 leaves the piles' fitted range."""
    M, z_G = _mean_mass(scene)
    frequencies = soil["in_plane"]["natural_frequencies"]
    for row, mode in zip(soil["in_plane"]["at_modes"], ("k0", "p1", "p2")):
        roots = np.sqrt(np.sort(eigvals(_plane_at_c(scene, row, z_G), M).real))
        assert row["mode"] == mode
        assert np.min(np.abs(roots - frequencies[mode])) / frequencies[mode] < 1e-6, (mode, roots)
    static = np.sqrt(np.sort(eigvals(_plane_at_c(scene, soil["in_plane"]["at_frequencies"][0], z_G), M).real))
    found = soil["in_plane"]["static_frequencies"]
    assert sorted(found.values()) == pytest.approx(static, rel=1e-9)
    resonance = fc.resonance(read_toml(CONFIG)).to_dict()
    assert frequencies == pytest.approx(resonance["natural_frequencies"], rel=1e-12)
    assert soil["soil_validity"] == resonance["soil_validity"] and soil["soil_validity"]["beyond"]  # p2: a0 = 2.85


def test_the_json_keeps_the_crank_shape_and_says_why_no_methods(soil):
    """The crank's keys (methods empty), the piles' own table as the block's, and one line why."""
    assert {"scene", "method", "total_mass", "base", "methods", "warnings", "stratum", "piles", "sample",
            "comparison", "soil_validity", "in_plane"} <= set(soil)
    assert soil["methods"] == {} and soil["method"] == "piles" and soil["sample"] is None
    assert "for footings" in soil["comparison"]
    assert [r["at"] for r in soil["piles"]] == ["static", "ω, machine"]


@pytest.fixture(scope="module")
def terminal():
    """The results console at 80 columns, as on a terminal that wide (tests/test_block_width.py)."""
    with pytest.MonkeyPatch.context() as patch:
        patch.setattr(console, "UNLIMITED_WIDTH", 80)
        console.stdout.cache_clear()
        yield
    console.stdout.cache_clear()


def test_every_line_fits_80_columns(terminal, runner, soil):
    """At 80 columns no line is wider, no number cut, and every frequency of the modes is printed (Hz,
    4 significant figures) and the one line on the footing's comparison."""
    result = runner.invoke(app, ["soil", str(CONFIG)])
    assert result.exit_code == 0, result.output
    wide = [line for line in result.stdout.splitlines() if cell_len(line) > 80]
    assert not wide, "\n".join(wide[:8])
    assert "…" not in result.stdout
    text = " ".join(result.stdout.split())
    assert "comparison is for footings" in text
    for p in soil["in_plane"]["natural_frequencies"].values():
        assert f"{p / (2 * np.pi):.4g}" in result.stdout


def test_exit_codes(runner, tmp_path):
    """2 for a sample: the group's springs do not scale with one factor on the soil's modulus
    (docs/exit-codes.md), never a traceback (0 for the tables: :func:`test_every_line_fits_80_columns`)."""
    run = runner.invoke(app, ["soil", str(CONFIG), "--sample", "10"])
    assert run.exit_code == 2 and "not sampled" in run.stderr and "[piles]" in run.stderr
    assert "Traceback" not in run.output


@pytest.mark.parametrize("config", [CONFIG, CONFIG.parent / "block_on_piles.toml"], ids=["crank", "block"])
def test_a_sample_on_piles_is_refused_by_the_api_and_its_engine_as_by_the_command(runner, config):
    """One refusal, an FcalcError with the command's exit code 2, from ``fc.soil`` and from the
    sampling engine called on its own (:func:`~foundation_calc.checks.soil_sample.sample_scene`),
    where a bare numpy ValueError came; its message is the command's."""
    from foundation_calc.checks.soil_sample import sample_scene

    said = " ".join(runner.invoke(app, ["soil", str(config), "--sample", "10"]).stderr.split())
    with pytest.raises(fc.UsageError) as api:
        fc.soil(config, sample=10)
    with pytest.raises(fc.UsageError) as engine:
        sample_scene(fc.load(config).model, 10, 0.3)
    for raised in (api.value, engine.value):
        assert raised.exit_code == 2 and "sample" in raised.option
        assert "not sampled" in str(raised) and " ".join(str(raised).split()) in said
