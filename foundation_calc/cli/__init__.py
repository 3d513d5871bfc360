"""The ``fcalc`` command line: a thin typer layer over scenes, solvers, checks and output."""
