"""A rigid block foundation in six degrees of freedom carrying several machines at their own
speeds (kind ``block_foundation``), built on :mod:`foundation_calc.solvers.rigid_body`."""
