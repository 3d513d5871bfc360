"""foundation_calc: dynamics of machine foundations and vibrating platforms.

Layout, in the direction the dependencies point:

- :mod:`foundation_calc.scenes`  -- TOML scene files and their pydantic models;
- :mod:`foundation_calc.solvers` -- the physics, plain functions in SI units (no I/O):
  ``solvers.crank``, ``solvers.platform``, and ``solvers.numerics`` shared by both;
- :mod:`foundation_calc.checks`  -- limits compared with results, giving outcomes;
- :mod:`foundation_calc.output`  -- rich tables for people, JSON for scripts
  (:mod:`foundation_calc.benchmarks` sits beside it);
- :mod:`foundation_calc.cli`     -- the ``fcalc`` command (typer), mapping errors to exit codes.
"""


def __getattr__(name: str):
    """``__version__`` is found on first use (:mod:`foundation_calc.version`): it may read git."""
    if name == "__version__":
        from foundation_calc.version import version

        return version()
    raise AttributeError(f"module {__name__!r} has no attribute {name!r}")
