"""The physics: plain functions of the papers' symbols, SI units, no I/O.

Modules here never import pydantic, rich or typer. The closed forms are written with arithmetic
operators only, so they accept a Python float or a numpy array of designs alike and the
``fcalc resonance`` path does not pay for importing numpy.
"""
