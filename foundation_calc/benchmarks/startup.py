"""Start-up cost of ``fcalc`` measured side by side with the cost of its frameworks.

Three references are run interleaved with fcalc, many times each, and compared by the median:

- ``import typer, pydantic, rich`` — the import floor (typer and pydantic import lazily, so this
  line loads little of either);
- a minimal typer command that reads a TOML scene, validates it with a small pydantic model and
  prints one rich table — the framework floor: what any typer + pydantic + rich CLI of this kind
  pays before doing its own work;
- ``python -c pass`` — the interpreter alone.
"""

from __future__ import annotations

import statistics
import subprocess
import sys
import time
from dataclasses import dataclass

FRAMEWORK_FLOOR = """
import sys
import tomllib

import typer
from pydantic import BaseModel, ConfigDict, Field
from rich.console import Console
from rich.table import Table


class Soil(BaseModel):
    model_config = ConfigDict(extra="forbid")
    c_z: float = Field(gt=0)
    c_x: float = Field(gt=0)


class Scene(BaseModel):
    model_config = ConfigDict(extra="ignore")
    kind: str
    soil: Soil


app = typer.Typer()


@app.command()
def main(path: str) -> None:
    with open(path, "rb") as handle:
        scene = Scene.model_validate(tomllib.load(handle))
    table = Table("key", "value")
    table.add_row("c_z", f"{scene.soil.c_z:.4g}")
    Console().print(table)


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
        "typer + TOML + pydantic model + rich table": (py, "-c", FRAMEWORK_FLOOR, scene),
        "fcalc resonance SCENE": (py, "-m", "foundation_calc", "resonance", scene),
        "fcalc resonance SCENE --json": (py, "-m", "foundation_calc", "resonance", scene, "--json"),
        "fcalc soil SCENE": (py, "-m", "foundation_calc", "soil", scene),
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
    framework = medians["typer + TOML + pydantic model + rich table"]
    return [
        StartupRow(label, commands[label], t, t / floor, t / framework) for label, t in medians.items()
    ]
