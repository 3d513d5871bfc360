"""Numerics shared by the problems: trigonometric series, their peaks and harmonic balance helpers."""
