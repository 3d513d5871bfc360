"""The crank scene read as the one rigid-body model (solvers.crank.plane: the block's bodies on the
base's springs and dashpots, one crank throw of solvers.machines.crank_mechanism) against the crank
foundation's own exact equations (solvers.crank.dynamics, derived by Lagrange and checked with
sympy), linearised about rest by complex step and averaged over a revolution here:

* the averaged operator M̄, C̄, K̄ and the forcing's harmonics, to 1e-9 of each one's largest entry;
* the natural frequencies of the model's averaged inertia by scipy.linalg.eigh, and the harmonic
  response of the model to its machine's forcing harmonics by the rigid body's solver, against
  the solve of the linearised exact equations, to 1e-9 (both exact to round-off: the models
  coincide, one congruence apart).
"""

from __future__ import annotations

from dataclasses import replace
from pathlib import Path

import numpy as np
import pytest
import scipy.linalg

from foundation_calc.scenes.loading import load_scene
from foundation_calc.solvers.crank.averaged import FORCING_HARMONICS, averaged_operator, linearise
from foundation_calc.solvers.crank.plane import in_plane, plane_map
from foundation_calc.solvers.machines.crank_mechanism import forcing_harmonics
from foundation_calc.solvers.numerics.trig_series import analyse, phases
from foundation_calc.solvers.rigid_body.harmonic import harmonic_response

ROOT = Path(__file__).resolve().parents[1]
#: Undamped and damped scenes, a rod with a slider, and the motor off the foundation.
CONFIGS = ["frame_saw.toml", "crank_press.toml", "compressor_damped_near_resonance.toml", "vertical_compressor.toml"]


def _reference(design):
    """M̄, C̄, K̄ and the forcing's cosine and sine coefficients of the exact equations."""
    lin = linearise(design, phases(256))
    return (*(block.mean(axis=-1) for block in (lin.mass, lin.damping, lin.stiffness)),
            *analyse(lin.forcing, FORCING_HARMONICS))


def _assert_same_operator(mine, theirs):
    """M̄, C̄, K̄, fc, fs each to 1e-9 of its largest entry (C̄: of sqrt(max|M̄| max|K̄|), as an
    undamped scene's C̄ is round-off both ways)."""
    scale_C = np.sqrt(np.abs(theirs[0]).max() * np.abs(theirs[2]).max())
    for name, a, b, scale in zip(("M", "C", "K", "fc", "fs"), mine, theirs, (None, scale_C, None, None, None)):
        scale = np.abs(b).max() if scale is None else scale
        assert np.abs(a - b).max() <= 1e-9 * scale, name


def _scene(config):
    return load_scene(ROOT / "configs" / config)


@pytest.mark.parametrize("drive_on_foundation", [True, False])
@pytest.mark.parametrize("config", CONFIGS)
def test_averaged_operator_is_the_linearised_exact_equations(config, drive_on_foundation):
    d = replace(_scene(config).design(), drive_on_foundation=drive_on_foundation)
    _assert_same_operator(averaged_operator(d), _reference(d))


@pytest.mark.parametrize("config", CONFIGS)
def test_one_model_through_the_rigid_body_solvers(config):
    scene = _scene(config)
    d, found = scene.design(), scene.plane_model()
    M, C, K = (in_plane(A, d.h) for A in (found.model.M, found.model.C, found.model.K))
    M_ref, C_ref, K_ref, fc, fs = _reference(d)
    p = np.sqrt(scipy.linalg.eigh(K, M, eigvals_only=True))
    p_ref = np.sqrt(np.sort(np.linalg.eigvals(np.linalg.solve(M_ref, K_ref)).real))
    assert p == pytest.approx(p_ref, rel=1e-9)
    fh = forcing_harmonics([found.throw], d.omega, d.g)
    Q = (fh.inertial + fh.weight) @ plane_map(d.h)  # generalised forces in x, y, θ of C
    Z = harmonic_response(K, C, M, Q, fh.orders * d.omega)
    n = fh.orders[:, None, None]
    ref = np.linalg.solve(K_ref + 1j * n * d.omega * C_ref - (n * d.omega) ** 2 * M_ref,
                          (fc - 1j * fs)[:, fh.orders].T[..., None])[..., 0]
    assert (np.abs(Z - ref).max(axis=0) <= 1e-9 * np.abs(ref).max(axis=0)).all()


@pytest.mark.parametrize("config", CONFIGS)
def test_design_batch_split_is_the_same_operator(config):
    """The design batch's split, the mechanism's part (one per machine) plus the blocks' (the
    moving mass lumped at C), against the linearised exact equations."""
    from foundation_calc.solvers.crank.averaged import block_matrices, mechanism_operator

    d = _scene(config).design()
    mech, block = mechanism_operator(d), block_matrices(d)
    _assert_same_operator((mech[0] + block[0], mech[1] + block[1], mech[2] + block[2], mech[3], mech[4]),
                          _reference(d))
