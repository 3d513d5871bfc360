"""Conversions at the boundary between SI (used everywhere inside) and the units people type.

>>> round(rpm_from_omega(omega_from_rpm(1500.0)), 9)
1500.0
>>> round(hz_from_omega(50 * 3.141592653589793), 12)
25.0
"""

from __future__ import annotations

import math

TWO_PI = 2.0 * math.pi


def omega_from_rpm(speed_rpm):
    """Angular speed [rad/s] from a shaft speed [rpm]."""
    return speed_rpm * (TWO_PI / 60.0)


def omega_from_hz(frequency_hz):
    """Angular speed [rad/s] from a frequency [Hz]."""
    return frequency_hz * TWO_PI


def hz_from_omega(omega):
    """Frequency [Hz] from an angular speed [rad/s]."""
    return omega / TWO_PI


def rpm_from_omega(omega):
    """Shaft speed [rpm] from an angular speed [rad/s]."""
    return omega * (60.0 / TWO_PI)


def speed_triplet(omega) -> dict:
    """A speed [rad/s] in the three units people quote: rad/s, Hz and rpm."""
    return {"omega": omega, "frequency_hz": hz_from_omega(omega), "speed_rpm": rpm_from_omega(omega)}
