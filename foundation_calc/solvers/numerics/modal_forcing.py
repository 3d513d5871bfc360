"""How strongly each harmonic of a machine's forcing drives each mode of a linear structure.

For the undamped modes (K - p_j² M) φ_j = 0, mass-normalised (φ_jᵀ M φ_j = 1), harmonic n of
the generalised force, F_n (complex, ``F(t) = Re Σ F_n e^{inωt}``), moves mode j statically by
q = φ_jᵀ F_n / p_j²; the strain energy of that motion is ½ p_j² |q|², so

    w_nj = |φ_jᵀ F_n| / p_j                     [sqrt(J)]

is the square root of twice the static strain energy of mode j under harmonic n. Its weight does
not depend on how the coordinates are scaled (metres and radians alike), and at resonance the
mode's amplitude grows from it by the same factor 1/(2 ζ_j) whatever n is: w_nj compares the
harmonics and the modes of one machine on one footing. The resonance rule uses the share
w_nj / max w (``checks/resonance/rule.py``).
"""

from __future__ import annotations

import numpy as np

from foundation_calc.solvers.numerics.symmetric_modes import symmetric_modes


def modal_forcing_weights(M, K, forces) -> tuple[np.ndarray, np.ndarray, np.ndarray]:
    """Natural frequencies, mass-normalised mode shapes and the weights w_nj of each harmonic.

    Parameters
    ----------
    M, K : mass and stiffness matrices, shape (D, D) (symmetric, M positive definite), or stacks
        (..., D, D) of them
    forces : complex generalised force of each harmonic, shape (N, D)

    Returns
    -------
    natural : p_j [rad/s], ascending, shape (..., D)
    shapes : φ_j as columns, shape (..., D, D)
    weights : w_nj = |φ_jᵀ F_n|/p_j, shape (..., N, D) (0 for a mode of zero frequency)

    The modes are :func:`~foundation_calc.solvers.numerics.symmetric_modes.symmetric_modes`.

    >>> p, phi, w = modal_forcing_weights(np.diag([2.0, 1.0]), np.diag([8.0, 9.0]), np.array([[2.0, 0.0], [0.0, 3.0]]))
    >>> np.round(p, 12).tolist(), np.round(w, 12).tolist()
    ([2.0, 3.0], [[0.707106781187, 0.0], [0.0, 1.0]])
    """
    squared, shapes = symmetric_modes(np.asarray(K, dtype=float), np.asarray(M, dtype=float))
    natural = np.sqrt(np.clip(squared, 0.0, None))
    modal = np.abs(np.asarray(forces, dtype=complex) @ shapes)
    p = natural[..., None, :]  # stacks of structures: (..., D) frequencies against (..., N, D) weights
    weights = np.where(p > 0.0, modal / np.where(p > 0.0, p, 1.0), 0.0)
    return natural, shapes, weights


__all__ = ["modal_forcing_weights"]
