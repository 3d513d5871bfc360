"""The crank foundation's soil is a support (:mod:`foundation_calc.solvers.supports.plane_footing`):
the springs and dashpots the crank's checks use are its impedance read in the plane, and a support
registered by a test alone carries a crank scene through ``fcalc resonance``.

The reference springs are computed here from the scene file's data by the soil methods' solvers
called directly (Barkan's c S, c1 S, c_φ I1 written out), under the crank's body as the paper takes
it: M_tot = M + m + m1 and I_0 = I_c + M_tot h² about the base's axis; the dashpots are
2 ξ √(K m) of each uncoupled motion; the plane's 3 × 3 matrices in the crank's coordinates
(x, y, θ of C) are written out from u_x = x − h θ at the base. Tolerance 1e-9: the same
arithmetic in another order."""

from __future__ import annotations

import copy
import json

import numpy as np
import pytest
import tomli_w
from scipy.linalg import eigh

import foundation_calc as fc
from foundation_calc.cli.app import app
from foundation_calc.scenes import parse_scene, read_toml
from foundation_calc.solvers.constants import GRAVITY
from foundation_calc.solvers.crank.plane import in_plane
from foundation_calc.solvers.supports import register, unregister
from foundation_calc.solvers.supports.base import AtO, Validity

from tests.conftest import CONFIGS, closed_form_configs

#: The shipped crank scenes with a mechanism on a footing, each in every soil method its data allow, and on a stratum.
LYSMER = "compressor_medium_sand_lysmer.toml"
VARIANTS = [(p.name, {}) for p in closed_form_configs()] + [
    (LYSMER, {"method": "gazetas"}), (LYSMER, {"method": "pais_kausel"}),
    (LYSMER, {"stratum_depth": 7.0}), (LYSMER, {"method": "gazetas", "stratum_depth": 7.0}),
    (LYSMER, {"method": "pais_kausel", "embedment": 1.0}),
]


def _document(name: str, change: dict) -> dict:
    document = copy.deepcopy(read_toml(CONFIGS / name))
    soil = {k: v for k, v in change.items() if k != "embedment"}
    document["soil"].update(soil)
    if "embedment" in change:
        document["foundation"]["embedment"] = change["embedment"]
    return document


def _reference(scene, omega: float):
    """((K_x, K_z, K_φ), (ξ_x, ξ_z, ξ_φ), (M_tot, I_0)) of the scene's soil method at ``omega`` (module docstring)."""
    from foundation_calc.solvers.soil.stratum import on_stratum

    f, s, mech = scene.foundation, scene.soil, scene.mechanism
    M_tot = f.mass + mech.rod_mass + mech.slider_mass
    I_0 = f.moment_of_inertia + M_tot * f.cog_height**2
    L, B = f.dimensions
    S, I1, D = f.base_area, f.base_second_moment, f.embedment or 0.0
    method = s.method_used
    if method == "coefficients":
        xi_z, xi_x, xi_phi = s.damping or (0.0, 0.0, 0.0)
        c_phi = s.c_z if s.c_phi is None else s.c_phi
        return (s.c_x * S, s.c_z * S, c_phi * I1), (xi_x, xi_z, xi_phi), (M_tot, I_0)
    if method == "sp26":
        from foundation_calc.solvers.soil.sp26 import B0_BY_CLASS, sp26_springs

        k = sp26_springs(s.deformation_modulus, B0_BY_CLASS[s.soil_class], S, I1, M_tot * GRAVITY / S)
    elif method == "lysmer":
        from foundation_calc.solvers.soil.lysmer import lysmer_springs

        k = lysmer_springs(s.G, s.density, s.poisson, L, B, M_tot, I_0, s.material_damping or 0.0)
    else:
        from foundation_calc.solvers.soil.gazetas import gazetas_springs
        from foundation_calc.solvers.soil.pais_kausel import pais_kausel_springs

        springs = pais_kausel_springs if method == "pais_kausel" else gazetas_springs
        k = springs(s.G, s.density, s.poisson, L, B, D, M_tot, I_0, s.material_damping or 0.0, omega)
    if s.stratum_depth is not None:
        k = on_stratum(k, L, B, s.stratum_depth, s.V_s, s.poisson, s.material_damping or 0.0, omega)
    return (k.K_x, k.K_z, k.K_phi), (k.xi_x, k.xi_z, k.xi_phi), (M_tot, I_0)


def _plane(K_x, K_z, K_phi, h) -> np.ndarray:
    """The base's springs (or dashpots) in the crank's x, y, θ of C, h above the base: u_x = x − h θ."""
    return np.array([[K_x, 0.0, -h * K_x], [0.0, K_z, 0.0], [-h * K_x, 0.0, K_phi + h * h * K_x]])


@pytest.mark.parametrize(("name", "change"), VARIANTS, ids=[f"{n}-{c}" for n, c in VARIANTS])
def test_the_support_in_the_plane_is_what_the_crank_checks_use(name, change):
    """At rest, at the speed and at twice it: the support's K and C at O read in the plane
    (:func:`~foundation_calc.solvers.crank.plane.in_plane`) are the reference springs and dashpots
    of the module docstring, and the crank's design (what its checks solve: c S, c1 S, c_φ I1 and
    C_x, C_z, C_φ) holds the same."""
    scene = parse_scene(_document(name, change))
    h, omega, f = scene.foundation.cog_height, scene.speed.omega_rad_s, scene.foundation
    support = scene.support()
    assert support.frequency_dependent == (scene.soil.method_used in ("gazetas", "pais_kausel")
                                           or scene.soil.stratum_depth is not None)
    for w in (0.0, omega, 2.0 * omega):
        springs, ratios, (M_tot, I_0) = _reference(scene, w)
        dashpots = [2.0 * xi * np.sqrt(k * m) for xi, k, m in zip(ratios, springs, (M_tot, M_tot, I_0))]
        at = support.impedance(w)
        assert in_plane(at.K, h) == pytest.approx(_plane(*springs, h), rel=1e-9, abs=1e-6)
        assert in_plane(at.C, h) == pytest.approx(_plane(*dashpots, h), rel=1e-9, abs=1e-6)
        d = scene.design(w)
        assert _plane(d.c1 * d.S, d.c * d.S, d.c_phi * d.I1, h) == pytest.approx(in_plane(at.K, h), rel=1e-9)
        assert _plane(d.C_x, d.C_z, d.C_phi, h) == pytest.approx(in_plane(at.C, h), rel=1e-9, abs=1e-6)
        assert (d.S, d.I1) == (f.base_area, f.base_second_moment)


#: The toy's springs at O [N/m, N m/rad], uncoupled, none like the scene's soil; its dashpots.
K_TOY = np.array([3.1e9, 2.0e9, 4.3e9, 2.5e10, 4.7e10, 1.0e10])
C_TOY = np.array([2.0e7, 1.0e7, 3.0e7, 4.0e7, 6.0e7, 3.0e7])


class Toy:
    """Constant springs and dashpots at O (coupled at ``coupled``, a pair of motions: x with ry, or z
    with ry): a support's whole interface."""

    label, method, unscaled, frequency_dependent = "toy", "toy", None, False

    def __init__(self, coupled: tuple[int, int] | None):
        self.coupled = coupled

    def impedance(self, omega) -> AtO:
        shape = np.shape(omega)
        off = np.zeros(shape + (6, 6))
        if self.coupled:
            i, j = self.coupled
            off[..., i, j] = off[..., j, i] = -1.0e9
        return AtO(np.broadcast_to(K_TOY, shape + (6,)), np.broadcast_to(C_TOY, shape + (6,)),
                   (off, np.zeros_like(off)) if self.coupled else None)

    def validity(self) -> Validity:
        return Validity("toy", None, "", "the toy's springs are constant: no range of a0 applies")

    def a0(self, omega):
        return None, "no a0"


def _toy_builder(scene, L, B, masses):
    return {"toy crank": Toy(None), "coupled toy crank": Toy((0, 4)), "vertically coupled toy crank": Toy((2, 4))}.get(scene.name)


@pytest.fixture(scope="module")
def toys():
    """Three crank scene documents a toy support takes (uncoupled, coupled in sway-rocking, coupled vertically),
    registered while the module's tests run."""
    documents = {name: {**read_toml(CONFIGS / "frame_saw.toml"), "name": name}
                 for name in ("toy crank", "coupled toy crank", "vertically coupled toy crank")}
    register(_toy_builder)
    yield documents
    unregister(_toy_builder)


def test_a_registered_support_carries_the_crank_resonance(toys):
    """fc.resonance of a crank scene on the toy: k0, p1, p2 of the paper's zero-order operator
    (M_tot on x and y, I_c about C) are a generalized eigen-solve of the toy's springs written out in
    the plane here (the weight's −P h on θ), and the validity is the toy's (1e-9: round-off)."""
    scene = parse_scene(toys["toy crank"])
    f, mech = scene.foundation, scene.mechanism
    M_tot, h = f.mass + mech.rod_mass + mech.slider_mass, f.cog_height
    K = _plane(K_TOY[0], K_TOY[2], K_TOY[4], h) - np.diag([0.0, 0.0, M_tot * GRAVITY * h])
    M = np.diag([M_tot, M_tot, f.moment_of_inertia])
    p = np.sqrt(eigh(K, M, eigvals_only=True))
    k0 = np.sqrt(K_TOY[2] / M_tot)
    doc = fc.resonance(toys["toy crank"]).to_dict()
    found = doc["natural_frequencies"]
    assert found["k0"] == pytest.approx(k0, rel=1e-9)
    assert sorted([found["k0"], found["p1"], found["p2"]]) == pytest.approx(sorted(p), rel=1e-9)
    assert doc["soil_validity"]["method"] == "toy"
    assert fc.check(toys["toy crank"]).exit_code in (0, 1)  # amplitudes and office checks on the toy too


def test_a_support_coupling_the_plane_is_refused_by_name(toys, runner, tmp_path):
    """The paper's closed forms take three uncoupled springs: a support coupling sway with rocking is
    solved by the plane model (tests/test_crank_piles.py), never a silently dropped coupling: its
    resonance, its amplitudes and its speed sweep, whose row at the scene's speed is the amplitudes'
    averaged operator on the toy's constant springs (1e-9: the same operator, solved for all speeds at
    once); a coupling of the vertical motion is a PhysicsError that names it (exit code 3,
    docs/exit-codes.md), in the sweep too."""
    assert fc.resonance(toys["coupled toy crank"]).to_dict()["natural_frequencies"]["p1"] > 0.0
    amplitudes = fc.amplitudes(toys["coupled toy crank"]).to_dict()
    assert "first_approximation" in amplitudes["not_applicable"]
    with pytest.raises(fc.PhysicsError, match="support toy couples the motions of the plane at O other than"):
        fc.resonance(toys["vertically coupled toy crank"])
    runs = {}
    for name in ("coupled toy crank", "vertically coupled toy crank"):
        path = tmp_path / f"{name.replace(' ', '_')}.toml"
        path.write_text(tomli_w.dumps(toys[name]), encoding="utf-8")
        runs[name] = runner.invoke(app, ["sweep", str(path), "--speed", str(toys[name]["mechanism"]["speed_rpm"]), "--json"])
    vertical = runs["vertically coupled toy crank"]
    assert vertical.exit_code == 3 and "support toy couples the motions of the plane at O other than" in vertical.output
    assert runs["coupled toy crank"].exit_code == 0, runs["coupled toy crank"].output
    row = json.loads(runs["coupled toy crank"].stdout)["points"][0]
    peaks = amplitudes["approximations"]["averaged_operator"]["peaks"]
    for key, dof in (("x_peak", "x"), ("y_peak", "y"), ("theta_peak", "theta")):
        assert row[key] == pytest.approx(peaks[dof]["displacement"], rel=1e-9), key


def _stiff_builder(scene, L, B, masses):
    """The scene's own footing on its soil with G × 4 (V_s × 2), for the scene named "stiff crank"."""
    from foundation_calc.solvers.supports.plane_footing import build

    return build(scene.with_modulus_factor(4.0), L, B, masses) if scene.name == "stiff crank" else None


def test_the_soil_sample_reads_the_scenes_support():
    """fcalc soil --sample of a frequency-dependent crank scene takes each sample's springs from the
    scene's support, as resonance does: on a registered footing whose soil has G × 4, the sample
    without scatter gives fc.resonance's k0, p1, p2 (1e-9: the same fixed point ω = p(K(ω)) solved
    by both), and a vertical k0 = √(K_z/M_tot) twice the plain scene's (Gazetas' K(a0) ∝ G at
    a0 = ωB/V_s, so K_z × 4 at ω × 2 is again consistent; 1e-6, the fixed point's tolerance; p1, p2
    hold the weight's P h, which G does not scale)."""
    from foundation_calc.checks.soil_sample import sample_scene

    document = _document(LYSMER, {"method": "gazetas"})
    plain = sample_scene(parse_scene(document), 4, 0.0).percentiles
    document["name"] = "stiff crank"
    register(_stiff_builder)
    try:
        stiff = sample_scene(parse_scene(document), 4, 0.0).percentiles
        found = fc.resonance(document).to_dict()["natural_frequencies"]
    finally:
        unregister(_stiff_builder)
    for mode in ("k0", "p1", "p2"):
        assert stiff[mode] == pytest.approx([found[mode]] * len(stiff[mode]), rel=1e-9)
    assert stiff["k0"] == pytest.approx([2.0 * v for v in plain["k0"]], rel=1e-6)
