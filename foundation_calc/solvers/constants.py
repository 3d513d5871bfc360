"""Physical constants used by the solvers."""

#: Acceleration of gravity [m/s²], the value both source papers use in their examples.
GRAVITY = 9.81
