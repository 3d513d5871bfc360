"""The Python API: every scene command of ``fcalc`` as a function that returns its result.

The commands themselves call these functions and print what they return (``--json`` prints
:meth:`Result.to_dict`), so a script and the command line cannot disagree. ``import
foundation_calc as fc`` reaches them lazily (``fc.load``, ``fc.check``, ``fc.resonance`` ...):
each module here is imported on first use. See ``docs/python-api.md``.
"""
