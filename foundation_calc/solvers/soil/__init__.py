"""Soil models shared by both problems: springs and dashpots of a foundation's base from soil data.

Barkan's coefficients of elastic uniform compression and shear, as the crank-foundation paper uses
them, are the model in force today (``solvers.crank``); models that start from a soil report go here.
"""
