"""A new kind of machine part is one module plus its builder: a toy part defined only here, and
registered as a new module would register it (:data:`foundation_calc.scenes.block_parts.MACHINE_PARTS`),
runs through fc.check, fc.resonance, fc.amplitudes, fc.sweep and fc.report on a block scene with
no other edit. Its amplitudes are checked against a direct complex solve of the 6×6 equations
written out here (the mass matrix of point masses and a homogeneous block, the springs less the
weight's tilt, the loads carried to O).

Tolerance 1e-8 relative: both sides solve the same 6×6 system in double precision (condition
about 1e3); what differs is only the order of the sums.
"""

from __future__ import annotations

from dataclasses import dataclass

import numpy as np
import pytest

import foundation_calc as fc
from foundation_calc.scenes import block_parts
from foundation_calc.solvers.machines.part import LoadRow, MachinePart, Number

RPM = 2.0 * np.pi / 60.0
G_ACC = 9.81  # [m/s²] the project's gravity
L, B, H, RHO = 6.0, 4.0, 2.0, 2400.0
SPRINGS = np.array([6.0e9, 5.5e9, 8.0e9, 4.0e10, 7.0e10, 5.0e10])
DASHPOTS = np.array([1.5e7, 1.5e7, 2.5e7, 3.0e7, 5.0e7, 2.0e7])
MACHINE = dict(mass=5.0e3, cog=[0.5, 0.2, 2.5], inertia=[1.0e3, 2.0e3, 2.0e3], speed_rpm=900.0)
POINT = [0.8, -0.3, 2.6]
TOY_MASS, TOY_OFFSET = 300.0, np.array([0.4, 0.0, 0.3])  # [kg], [m] from the machine's cog
FORCE_ARM, COUPLE_ARM, COUPLE_PHASE = 0.02, 0.01, 0.3  # F = a ω², C = b ω² [kg m, kg m²], [rad]


@dataclass(frozen=True)
class ToyCouple(MachinePart):
    """A toy part: a point mass m at ``at``; loads of order 2, a force F = a ω² along x at ``at`` and
    a couple C = b ω² about z at phase 0.3, both growing as ω²; a periodic inertia, the point
    mass's mass matrix × (1 + 0.05 cos 2φ)."""

    m: float
    at: tuple

    periodic = True

    def mass_properties(self):
        return self.m, np.asarray(self.at, dtype=float), np.zeros((3, 3))

    def periodic_inertia(self, omega, g, N):
        phi = 2.0 * np.pi * np.arange(N) / N
        M = _point_mass_matrix(self.m, np.asarray(self.at, dtype=float))
        return (M * (1.0 + 0.05 * np.cos(2.0 * phi))[:, None, None], np.zeros((N, 6, 6)), np.zeros((N, 6, 6)))

    def load_rows(self, omega, g):
        return [LoadRow(2, [FORCE_ARM * omega ** 2, 0.0, 0.0], [0.0, 0.0, 0.0], 0.0, self.at, True),
                LoadRow(2, [0.0, 0.0, 0.0], [0.0, 0.0, COUPLE_ARM * omega ** 2], COUPLE_PHASE, self.at, True)]

    def sheet_text(self, omega):
        return ("toy couple C = b ω² = ", Number(COUPLE_ARM * omega ** 2), " N m")

    def assumption(self):
        return "the toy's couple about z, growing as ω²"


def _toy(machine) -> list:
    """The builder a new module would register: here every machine named "toy" carries one."""
    return [ToyCouple(TOY_MASS, tuple(np.asarray(machine.cog) + TOY_OFFSET))] if machine.name == "toy" else []


def _skew(r):
    return np.array([[0.0, -r[2], r[1]], [r[2], 0.0, -r[0]], [-r[1], r[0], 0.0]])


def _point_mass_matrix(m, r):
    """Kinetic energy ½ m |u' - [r]× θ'|²: the 6×6 mass matrix about O of a point mass m at r."""
    M = np.zeros((6, 6))
    M[:3, :3] = m * np.eye(3)
    M[:3, 3:] = -m * _skew(r)
    M[3:, :3] = m * _skew(r)
    M[3:, 3:] = m * (r @ r * np.eye(3) - np.outer(r, r))
    return M


def _body(m, cog, J):
    M = _point_mass_matrix(m, np.asarray(cog, dtype=float))
    M[3:, 3:] += np.diag(J)
    return M


def _direct(omega):
    """Complex amplitudes Z of q at 2ω and G from (K - Ω² M + iΩ C) Z = Q, written out here."""
    m_b = L * B * H * RHO
    J_b = m_b / 12.0 * np.array([B * B + H * H, L * L + H * H, L * L + B * B])
    cog_m = np.array(MACHINE["cog"])
    at = cog_m + TOY_OFFSET
    M = _body(m_b, [0.0, 0.0, H / 2.0], J_b) + _body(MACHINE["mass"], cog_m, MACHINE["inertia"]) + _point_mass_matrix(TOY_MASS, at)
    mass = M[0, 0]
    G = np.array([-M[4, 2], M[3, 2], -M[3, 1]]) / mass  # M_θu = Σ m [r]×
    K = np.diag(SPRINGS)
    K[3, 3] -= mass * G_ACC * G[2]
    K[4, 4] -= mass * G_ACC * G[2]
    F = np.array([FORCE_ARM * omega ** 2, 0.0, 0.0])
    Q = np.concatenate([F, np.cross(at, F)]) + np.array([0, 0, 0, 0, 0, COUPLE_ARM * omega ** 2]) * np.exp(1j * COUPLE_PHASE)
    W = 2.0 * omega
    return np.linalg.solve(K - W * W * M + 1j * W * np.diag(DASHPOTS), Q), G


def _peaks(Z, r):
    """Peak displacement of point r along x, y, z of one harmonic: |Z_u + Z_θ × r|."""
    return np.abs(Z[:3] + np.cross(Z[3:], r))


@pytest.fixture()
def toy_scene(monkeypatch, tmp_path):
    """The scene file (a sheet is made of a file): a block with one machine named "toy"."""
    monkeypatch.setattr(block_parts, "MACHINE_PARTS", [*block_parts.MACHINE_PARTS, _toy])
    path = tmp_path / "toy.toml"
    path.write_text(f"""kind = "block_foundation"
name = "toy part"
[block]
length = {L}
width = {B}
height = {H}
density = {RHO}
[[machines]]
name = "toy"
mass = {MACHINE['mass']}
cog = {MACHINE['cog']}
inertia = {MACHINE['inertia']}
speed_rpm = {MACHINE['speed_rpm']}
[soil]
method = "springs"
stiffness = {SPRINGS.tolist()}
dashpot = {DASHPOTS.tolist()}
[[points]]
name = "bearing"
at = {POINT}
""", encoding="utf-8")
    return path


def test_a_toy_part_runs_through_every_command(toy_scene, tmp_path):
    omega = MACHINE["speed_rpm"] * RPM
    Z, G = _direct(omega)

    amplitudes = fc.amplitudes(toy_scene).to_dict()
    for name, r in (("G", G), ("bearing", np.array(POINT))):
        found = amplitudes["points"][name]["displacement_peak"]
        assert [found[d] for d in "xyz"] == pytest.approx(_peaks(Z, r), rel=1e-8), name
    assert amplitudes["total_mass"] == pytest.approx(L * B * H * RHO + MACHINE["mass"] + TOY_MASS, rel=1e-12)
    (periodic,) = amplitudes["periodic_inertia"]  # the toy's angle-dependent inertia, solved as a crank's
    assert periodic["machine"] == "toy" and 0.0 < periodic["first_approximation_error"] < 0.5
    assert "crank" not in periodic["method"] and "machine's parts" in periodic["method"]  # the toy is no crank

    resonance = fc.resonance(toy_scene).to_dict()
    assert {(r["machine"], r["order"]) for r in resonance["resonances"]} == {("toy", 2)}

    checked = fc.check(toy_scene)
    assert checked.verdict in ("pass", "fail") and {c["check"] for c in checked.to_dict()["checks"]} >= {"resonance", "amplitudes"}

    rpm = 1200.0  # the loads grow as ω² along the sweep
    swept = fc.sweep(toy_scene, speed=f"{rpm:g}:{rpm:g}:1").to_dict()
    Z2, _ = _direct(rpm * RPM)
    largest = np.max([_peaks(Z2, G), _peaks(Z2, np.array(POINT))], axis=0)
    assert [swept["points"][0]["peak"][d] for d in "xyz"] == pytest.approx(largest, rel=1e-8)

    sheet = tmp_path / "toy.md"
    fc.report(toy_scene, output=sheet)
    text = sheet.read_text(encoding="utf-8")
    assert "toy: toy couple C = b ω² = " in text
    assert "The toy's couple about z, growing as ω²" in text  # the sheet's assumptions say what the part says of itself
