"""Embedment factors of the torsional spring of a rigid rectangular footing, K_t,emb = η_t K_t,sur.

Sources: G. Gazetas, "Formulas and charts for impedances of surface and embedded foundations",
J. Geotech. Eng. 117(9), 1991, Table 2 (torsion); J. Pais, E. Kausel, "Approximate formulas for
dynamic stiffnesses of rigid foundations", Soil Dyn. Earthq. Eng. 7(4), 1988, as tabulated in
NIST GCR 12-917-21 (2012), Table 2-2b (η_zz). Footing 2L' × 2B' with half-sides L' >= B',
embedment D, the sidewall in contact over its full height d = D (as the other springs of
:mod:`~foundation_calc.solvers.soil.gazetas` and :mod:`~foundation_calc.solvers.soil.pais_kausel`
take it)::

    Gazetas:        η_t = 1 + 1.4 (1 + B'/L') (d/B')^0.9
    Pais & Kausel:  η_t = 1 + (1.3 + 1.32 B'/L') (D/B')^0.9

Both are 1 for a surface footing (D = 0). Static factors: the torsional dashpot of the sidewalls
is not among them. Arithmetic and ``numpy`` ufuncs only: every argument may be an array.
"""

from __future__ import annotations

import numpy as np


def _halves(L, B):
    """(L', B') the long and short half-sides [m] of an L × B base in either order."""
    return np.maximum(L, B) / 2.0, np.minimum(L, B) / 2.0


def gazetas_torsion_embedment(L, B, D):
    """Gazetas' (1991, Table 2) η_t = 1 + 1.4 (1 + B'/L') (D/B')^0.9 [-] of an L × B base [m]
    embedded D [m] with full sidewall contact (module docstring).

    >>> round(float(gazetas_torsion_embedment(4.0, 4.0, 2.0)), 12)   # square, D/B' = 1: 1 + 1.4·2
    3.8
    """
    long_half, short_half = _halves(L, B)
    return 1.0 + 1.4 * (1.0 + short_half / long_half) * (D / short_half) ** 0.9


def pais_kausel_torsion_embedment(L, B, D):
    """Pais & Kausel's (NIST GCR 12-917-21, Table 2-2b) η_t = 1 + (1.3 + 1.32/r) (D/B')^0.9 [-],
    r = L'/B', of an L × B base [m] embedded D [m] (module docstring).

    >>> round(float(pais_kausel_torsion_embedment(4.0, 4.0, 2.0)), 12)   # square, D/B' = 1: 1 + 2.62
    3.62
    """
    long_half, short_half = _halves(L, B)
    return 1.0 + (1.3 + 1.32 * short_half / long_half) * (D / short_half) ** 0.9


__all__ = ["gazetas_torsion_embedment", "pais_kausel_torsion_embedment"]
