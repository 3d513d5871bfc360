"""Pile-to-pile dynamic interaction factors of Dobry & Gazetas (1988), in closed form.

Source
------
.. [1] R. Dobry, G. Gazetas, "Simple method for dynamic stiffness and damping of floating pile
   groups", Géotechnique 38(4), 1988, 557-574: cylindrical waves leave each pile shaft and
   reach a pile at the distance S attenuated by geometric spreading and material damping and
   delayed by their travel time::

       α_v(S, ω) = sqrt(r0/S) exp(-β ω S/V_s) exp(-i ω S/V_s)                     vertical
       α_h(S, θ, ω) = α(S, 0°, ω) cos²θ + α(S, 90°, ω) sin²θ                        horizontal
       α(S, 0°, ω)  = sqrt(r0/S) exp(-β ω S/V_La) exp(-i ω S/V_La)     along the loading
       α(S, 90°, ω) = α_v(S, ω)                                        across it

   r0 = d/2, β the soil's material damping ratio, V_La = 3.4 V_s/(π (1 - ν)) (Lysmer's analog
   velocity: along the loading the waves are compression-extension waves), θ the angle between
   the loading and the line joining the two piles. The group's impedances follow by
   superposition under a rigid cap (:mod:`.cap`).

Notes
-----
[1] derived them for floating piles in a homogeneous half-space and compared the group
impedances with Kaynia & Kausel's rigorous solution for S/d = 2-10; the static limit
sqrt(r0/S) (ω → 0) is the form's, not Randolph's static interaction factor.
"""

from __future__ import annotations

import numpy as np


def attenuation(S, d, V, beta, omega):
    """sqrt(r0/S) exp(-(β + i) ω S/V) [-] of [1] (module docstring), r0 = d/2.

    Parameters
    ----------
    S : distance between the piles' axes [m]
    d : pile diameter [m]
    V : the velocity of the waves [m/s] (V_s or V_La)
    beta : the soil's material damping ratio [-]
    omega : circular frequency [rad/s]

    >>> z = complex(attenuation(3.0, 1.0, 100.0, 0.0, 0.0)); round(z.real, 4), z.imag
    (0.4082, 0.0)
    """
    return np.sqrt(d / (2.0 * S)) * np.exp(-(beta + 1j) * omega * S / V)


def vertical_factor(S, d, V_s, beta, omega):
    """α_v(S, ω) [-] of [1] (module docstring).

    >>> z = complex(vertical_factor(3.0, 1.0, 100.0, 0.05, 100.0 * np.pi / 3.0))
    >>> round(z.real, 4), round(z.imag, 4)
    (-0.3489, -0.0)
    """
    return attenuation(S, d, V_s, beta, omega)


def horizontal_factor(S, cos2, d, V_s, nu, beta, omega):
    """α_h(S, θ, ω) [-] of [1] (module docstring); ``cos2`` = cos²θ, θ between the loading and the
    line joining the piles.

    >>> z = complex(horizontal_factor(3.0, 0.0, 1.0, 100.0, 0.3, 0.05, 10.0))
    >>> z == complex(vertical_factor(3.0, 1.0, 100.0, 0.05, 10.0))
    True
    """
    V_La = 3.4 * V_s / (np.pi * (1.0 - nu))
    return cos2 * attenuation(S, d, V_La, beta, omega) + (1.0 - cos2) * attenuation(S, d, V_s, beta, omega)


__all__ = ["attenuation", "horizontal_factor", "vertical_factor"]
