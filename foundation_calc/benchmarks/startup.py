"""Start-up cost of ``fcalc`` measured side by side with the cost of its frameworks.

Three references are run interleaved with fcalc, many times each, and compared by the median:

- ``import typer, pydantic, rich`` — the import floor (typer and pydantic import lazily, so this
  line loads little of either);
- a minimal typer command that validates one pydantic model — the framework floor: what any
  typer + pydantic CLI pays before doing any work;
- ``python -c pass`` — the interpreter alone.
"""

from __future__ import annotations

import statistics
import subprocess
import sys
import time
from dataclasses import dataclass

FRAMEWORK_FLOOR = """
import typer
from pydantic import BaseModel

class Scene(BaseModel):
    mass: float

app = typer.Typer()

@app.command()
def main(path: str) -> None:
    Scene(mass=1.0)
    print(path)

app()
"""


@dataclass(frozen=True)
class StartupRow:
    """Median wall time [s] of one command line and its ratio to the import floor."""

    label: str
    command: tuple[str, ...]
    seconds: float
    ratio_to_import_floor: float
    ratio_to_framework_floor: float


def _commands(scene: str) -> dict[str, tuple[str, ...]]:
    py = sys.executable
    return {
        "python -c pass": (py, "-c", "pass"),
        "import typer, pydantic, rich": (py, "-c", "import typer, pydantic, rich"),
        "typer command + pydantic model": (py, "-c", FRAMEWORK_FLOOR, scene),
        "fcalc resonance SCENE": (py, "-m", "foundation_calc", "resonance", scene),
        "fcalc resonance SCENE --json": (py, "-m", "foundation_calc", "resonance", scene, "--json"),
    }


def startup_times(scene: str, runs: int = 20) -> list[StartupRow]:
    """Run every command ``runs`` times, interleaved, and return the medians and ratios."""
    commands = _commands(scene)
    samples: dict[str, list[float]] = {label: [] for label in commands}
    for _ in range(runs):
        for label, cmd in commands.items():
            t0 = time.perf_counter()
            subprocess.run(cmd, stdout=subprocess.DEVNULL, stderr=subprocess.DEVNULL, check=False)
            samples[label].append(time.perf_counter() - t0)
    medians = {label: statistics.median(ts) for label, ts in samples.items()}
    floor = medians["import typer, pydantic, rich"]
    framework = medians["typer command + pydantic model"]
    return [
        StartupRow(label, commands[label], t, t / floor, t / framework) for label, t in medians.items()
    ]
