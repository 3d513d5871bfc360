"""Benchmarks behind ``fcalc bench``: they measure (time, peak memory, error); tests assert."""
