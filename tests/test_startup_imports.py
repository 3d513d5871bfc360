"""What `fcalc resonance` imports on its way to the answer (its start-up is measured by `fcalc
bench`, section startup, against a minimal typer + pydantic + rich command).

A fresh interpreter runs the command on an undamped crank scene and lists the modules loaded. The
path must not load scipy, the plotting or typesetting extras, another command's module, or the
solvers of another problem (numpy it does load: the resonance rule weighs each harmonic's forcing
on the averaged operator's modes); anything new on the path is measured by the bench, and a heavy
import shows up here first.
"""

from __future__ import annotations

import json
import subprocess
import sys

from tests.conftest import CONFIGS

PROBE = """
import json, runpy, sys
sys.argv = ["fcalc", *sys.argv[1:]]
code = 0
try:
    runpy.run_module("foundation_calc", run_name="__main__")
except SystemExit as exit:
    code = exit.code
sys.stderr.write(json.dumps([code, sorted(sys.modules)]))
"""


def _modules(*args: str) -> tuple[int, list[str]]:
    """Exit code of ``fcalc ARGS`` run in a fresh interpreter and the modules it loaded."""
    run = subprocess.run([sys.executable, "-c", PROBE, *args], capture_output=True, text=True, check=False)
    code, modules = json.loads(run.stderr.splitlines()[-1])
    return code, modules

#: Never on the path of `fcalc resonance` with an undamped crank scene.
HEAVY = ("scipy", "matplotlib", "typst", "multiprocessing")


def test_resonance_imports_only_its_own_path():
    scene = CONFIGS / "compressor_near_resonance.toml"
    _, modules = _modules("resonance", str(scene))
    assert not [m for m in modules if m.split(".")[0] in HEAVY]
    own = [m for m in modules if m.startswith("foundation_calc.")]
    from foundation_calc.cli.app import COMMANDS

    others = {module for name, module in COMMANDS.items() if name != "resonance"}
    assert not others & set(own)
    solvers = {m.split(".")[2] for m in own if m.startswith("foundation_calc.solvers.") and m.count(".") >= 3}
    # the crank scene is the one model (block, machines, rigid_body); supports: the footing's range of a0
    assert solvers <= {"crank", "soil", "numerics", "supports", "block", "machines", "rigid_body"}
    assert not [m for m in own if m.startswith(("foundation_calc.benchmarks", "foundation_calc.output.report"))]


def test_runup_without_a_run_time_fails_before_importing_scipy():
    """The missing run time is a scene error (exit 3) found before the time integration's
    scipy (a third of a second) is imported."""
    code, modules = _modules("runup", str(CONFIGS / "platform_paper_example.toml"))
    assert code == 3
    assert not [m for m in modules if m.split(".")[0] == "scipy"]


LIBRARY_PROBE = """
import json, sys
before = set(sys.modules)
import foundation_calc as fc
imported = set(sys.modules) - before
names = {name: callable(getattr(fc, name)) for name in fc.__all__}
sys.stdout.write(json.dumps([sorted(imported), sorted(set(sys.modules) - before), names]))
"""


def test_importing_the_library_is_as_cheap_as_it_was():
    """``import foundation_calc`` loads the package alone (its API is found on first use, PEP 562);
    resolving every public name then loads the API's modules, no solver, scipy, pydantic or rich."""
    run = subprocess.run([sys.executable, "-c", LIBRARY_PROBE], capture_output=True, text=True, check=True)
    imported, resolved, names = json.loads(run.stdout)
    assert [m for m in imported if m.startswith("foundation_calc")] == ["foundation_calc"]
    heavy = ("scipy", "numpy", "pydantic", "rich", "typer", "matplotlib", "pint")
    assert not [m for m in imported if m.split(".")[0] in heavy]
    assert all(names.values()) and {"load", "check", "resonance", "sweep", "design", "report", "SceneError"} <= set(names)
    assert not [m for m in resolved if m.split(".")[0] in heavy]
    assert not [m for m in resolved if m.startswith(("foundation_calc.solvers", "foundation_calc.checks", "foundation_calc.cli"))]
