"""One rigid body on springs and dashpots in six degrees of freedom: the core shared by the
vibrating platform and the block foundation.

Coordinates q = (u, θ) of a reference point O: its displacement u = (u_x, u_y, u_z) [m] and the
small rotation θ = (θ_x, θ_y, θ_z) [rad] of the body (right-handed, about axes through O). A body
point at r_P from O moves by u_P = u + θ × r_P (:mod:`.kinematics`). :mod:`.inertia` assembles the
mass matrix of several bodies about O, :mod:`.kinematics` carries springs, dashpots and loads
from their point to O, :mod:`.modes` solves K v = p² M v and :mod:`.harmonic` the damped steady
state of harmonic loads, vectorised over frequencies.
"""
