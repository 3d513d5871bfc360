"""Soil models shared by both problems: springs and dashpots of a foundation's base from soil data.

One module per source, each ending in :class:`~foundation_calc.solvers.soil.springs.SoilSprings`
(K_z, K_x, K_φ and a damping ratio per mode): :mod:`.lysmer` (Richart, Hall & Woods analogs),
:mod:`.gazetas` (Gazetas 1991, surface and embedded), :mod:`.sp26` (SP 26.13330 from the static
modulus); :mod:`.dashpots` turns damping ratios into base dashpots. Barkan's coefficients, as the
crank-foundation paper uses them, need no solver: K = c S, c1 S, c_φ I1.
"""
