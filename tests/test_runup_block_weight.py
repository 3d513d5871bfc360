"""A block's start-up keeps the moving weight's loads constant, as the crank foundation's does
(solvers.block.runup, solvers.crank.runup).

A block carrying one vertical throw is the crank scene it equals (tests/test_crank_machines.py's
plane twin: the crank model's x, y, θ about C are u_x, -u_z, θ_y of the block's coordinates about
C): its run-up load RotatingLoad.at(Ω, Ω', φ), carried to C, is the crank scene's at a low speed
where the weight's share is large, and the crank scene's run-up under that load passes its
resonances with the same peaks. At rest the load is the rods' weight alone, transcribed here from
the throw's masses and g: the rod's centre of mass swings sideways by r (1 - l'/l) sin φ, the slider
moves along the vertical and its weight has no moment.
"""

from __future__ import annotations

from dataclasses import replace

import numpy as np
import pytest

from foundation_calc.solvers.block.model import excitation
from foundation_calc.solvers.block.response import block_modes
from foundation_calc.solvers.block.runup import machine_structure
from foundation_calc.solvers.machines.crank_mechanism import CrankMechanism
from foundation_calc.solvers.numerics.sweep_response import RotatingLoad
from tests.test_crank_machines import _plane_block, _plane_design

#: A plane crank scene whose block passes k0 and p2 below the crank speed (order 1, the weight's order).
CONFIG = "configs/frame_saw_soft_soil_runup.toml"


@pytest.fixture(scope="module")
def twins():
    """(crank scene, its design, its run-up structure and speed, the block twin's run-up load in the
    crank's x, y, θ about C)."""
    from foundation_calc.checks.runup import machine_structures

    scene = _plane_design(CONFIG)
    d, throw, model, *_ = _plane_block(scene)
    rows = CrankMechanism((throw,), (0.0, 0.0, 0.0)).load_rows(d.omega, d.g)
    block = machine_structure(model, excitation("saw", d.omega, rows), np.zeros((0, 3)), block_modes(model))
    (_, crank, omega), *_ = machine_structures(scene)[0]
    # (x, y, θ) at C = (0, 0, h) from the block's (F, M) about O: x = F_x, y = -F_z, θ = M_y - h F_x
    to_plane = np.zeros((3, 6))
    to_plane[0, 0], to_plane[1, 2], to_plane[2, 4], to_plane[2, 0] = 1.0, -1.0, 1.0, -d.h
    load = RotatingLoad(block.load.ratio, block.load.inertial @ to_plane.T, block.load.constant @ to_plane.T)
    return scene, d, crank, omega, throw, load


def test_the_blocks_load_at_a_fifth_of_the_speed_is_the_crank_scenes(twins):
    """At Ω = 0.2 ω, Ω' = ω/10 s (a start-up in 10 s), on 64 angles of a revolution: x, y, θ of
    the block's load to 1e-9 of their largest (the crank scene splits its forcing from samples at
    ω and 2ω, the block takes the weight's harmonics apart: round-off, measured 2e-14). A load
    that grows all as (Ω/ω)² misses 17 % of θ there, the weight's moment it shrinks to 4 %."""
    _, d, crank, omega, _, load = twins
    phi = np.linspace(0.0, 2.0 * np.pi, 64, endpoint=False)
    speed, rate = np.full_like(phi, 0.2 * omega), np.full_like(phi, omega / 10.0)
    theirs, mine = crank.load.at(speed, rate, phi), load.at(speed, rate, phi)
    scale = np.abs(theirs).max(axis=1, keepdims=True)
    assert (np.abs(mine - theirs) <= 1e-9 * scale).all()


def test_at_rest_the_load_is_the_rods_weight_alone(twins):
    """Ω = Ω' = 0: the moment about the shaft's axis y of the rod's weight m g at its centre of
    mass, x = -r (1 - l'/l) sin φ (the pin at -r sin φ along x, the rod's centre l' from it along
    the rod, whose sideways lean is r sin φ/l), without its mean (zero): M_y = -m g r (1 - l'/l) sin φ,
    and nothing else, to 1e-9 of it (the harmonics are exact to round-off)."""
    _, d, _, _, throw, load = twins
    phi = np.linspace(0.0, 2.0 * np.pi, 64, endpoint=False)
    zero = np.zeros_like(phi)
    at_rest = load.at(zero, zero, phi)
    moment = -throw.m * d.g * throw.r * (1.0 - throw.l1 / throw.l) * np.sin(phi)
    expected = np.array([zero, zero, moment])
    assert np.abs(moment).max() > 100.0  # N m: the rod's weight is in the scene
    assert np.abs(at_rest - expected).max() <= 1e-9 * np.abs(moment).max()


def test_the_passages_under_the_blocks_load_are_the_crank_scenes(twins):
    """The crank scene's run-up (10 s up, 20 s down, its damping and soil) under the block's load
    in place of its own: every passage's integrated and closed-form peak to 1e-8 (the loads differ
    by round-off, the integrations then by 1e-11); a load growing all as (Ω/ω)² moves the peaks
    of the order-1 passages of k0 and p2 by 1.4 % to 8 %."""
    from foundation_calc.solvers.numerics.runup import runup

    scene, _, crank, omega, _, load = twins
    for duration, direction in ((scene.operation.run_up_time, 1), (scene.operation.run_down_time, -1)):
        theirs = runup(crank, omega, duration, direction).passages
        mine = runup(replace(crank, load=load), omega, duration, direction).passages
        assert [(p.mode, p.ratio) for p in mine] == [(p.mode, p.ratio) for p in theirs]
        assert any(p.ratio == 1.0 for p in theirs)
        for a, b in zip(mine, theirs):
            assert a.integrated == pytest.approx(b.integrated, rel=1e-8)
            assert a.closed_form == pytest.approx(b.closed_form, rel=1e-8)


def test_an_exciters_rotor_weight_is_a_weight_row_and_stays_at_rest():
    """An exciter on a vertical axis: its rotor's weight m g at the eccentricity l swings about the
    axis point, a moment of amplitude m g l about the horizontal axes (one row per axis) marked
    ``weight``; the force m l ω² is inertial. At rest the block's run-up load is that moment alone
    (transcribed: r × (0, 0, -m g) for the rotor at r = l (cos φ, sin φ, 0) from the axis point,
    (M_x, M_y) = m g l (-sin φ, cos φ); t1 = -y, t2 = x of Eq. (1.3), φ0 = π/2 puts it at +x at
    φ = 0), to 1e-9 of m g l."""
    from foundation_calc.solvers.block.model import block_model
    from foundation_calc.solvers.machines.exciter import UnbalancedExciter

    g, omega = 9.81, 100.0
    rotor = UnbalancedExciter(20.0, 0.05, (0.0, 0.0, 1.0), 0.0, 0.0, np.pi / 2.0)
    rows = rotor.load_rows(omega, g)
    assert {(r.inertial, r.weight) for r in rows} == {(True, False), (False, True)}
    model = block_model([1e4], [[0.0, 0.0, 0.5]], [[1e4, 1e4, 1e4]], np.full(6, 1e8), g, 3.0)
    load = machine_structure(model, excitation("table", omega, rows), np.zeros((0, 3)), block_modes(model)).load
    phi = np.linspace(0.0, 2.0 * np.pi, 16, endpoint=False)
    zero = np.zeros_like(phi)
    moment = rotor.m * g * rotor.l
    expected = np.array([zero, zero, zero, -moment * np.sin(phi), moment * np.cos(phi), zero])
    assert np.abs(load.at(zero, zero, phi) - expected).max() <= 1e-9 * moment
