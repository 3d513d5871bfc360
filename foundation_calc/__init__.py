"""foundation_calc: dynamics of machine foundations and vibrating platforms.

As a library (``docs/python-api.md``)::

    import foundation_calc as fc
    scene = fc.load("configs/frame_saw.toml")   # a path, or a mapping with the same keys
    result = fc.check(scene)                    # fc.resonance, fc.amplitudes, fc.soil, fc.sweep,
    result.verdict, result.exit_code            # fc.runup, fc.platform, fc.design, fc.report
    result.to_dict()                            # what `fcalc check --json` says of this scene

The commands of ``fcalc`` call these very functions (:mod:`foundation_calc.api`). They are
imported on first use, so ``import foundation_calc`` stays as cheap as the command's start-up.

Layout, in the direction the dependencies point:

- :mod:`foundation_calc.scenes`  -- TOML scene files and their pydantic models;
- :mod:`foundation_calc.solvers` -- the physics, plain functions in SI units (no I/O):
  ``solvers.crank``, ``solvers.platform``, and ``solvers.numerics`` shared by both;
- :mod:`foundation_calc.checks`  -- limits compared with results, giving outcomes;
- :mod:`foundation_calc.output`  -- rich tables for people, JSON for scripts
  (:mod:`foundation_calc.benchmarks` sits beside it);
- :mod:`foundation_calc.api`     -- one function per command, returning its result;
- :mod:`foundation_calc.cli`     -- the ``fcalc`` command (typer), mapping errors to exit codes.
"""

#: The public names of the package -> the module that defines each (imported on first use).
API = {
    "load": "foundation_calc.api.scene",
    "Scene": "foundation_calc.api.scene",
    "Result": "foundation_calc.api.result",
    "SweepResult": "foundation_calc.api.sweep",
    "SheetResult": "foundation_calc.api.report",
    "check": "foundation_calc.api.check",
    "resonance": "foundation_calc.api.resonance",
    "amplitudes": "foundation_calc.api.amplitudes",
    "soil": "foundation_calc.api.soil",
    "sweep": "foundation_calc.api.sweep",
    "runup": "foundation_calc.api.runup",
    "platform": "foundation_calc.api.platform",
    "design": "foundation_calc.api.design",
    "report": "foundation_calc.api.report",
    "FcalcError": "foundation_calc.errors",
    "SceneError": "foundation_calc.errors",
    "PhysicsError": "foundation_calc.errors",
    "UsageError": "foundation_calc.errors",
    "Problem": "foundation_calc.errors",
}

__all__ = list(API)


def __getattr__(name: str):
    """The names of :data:`API` (PEP 562), imported on first use; ``__version__`` is found on
    first use too (:mod:`foundation_calc.version`: it may read git)."""
    if name == "__version__":
        from foundation_calc.version import version

        return version()
    if name in API:
        import importlib

        value = getattr(importlib.import_module(API[name]), name)
        globals()[name] = value
        return value
    raise AttributeError(f"module {__name__!r} has no attribute {name!r}")


def __dir__() -> list[str]:
    return sorted([*globals(), *API, "__version__"])
