"""Start-up cost of ``fcalc`` measured side by side with the cost of its frameworks.

Three references are run interleaved with fcalc, many times each (after one untimed round that
fills the bytecode cache, as an installed package has it), and compared by the median of the
wall time and of the CPU time (user + system, less disturbed by other work on the machine):

- ``import typer, pydantic, rich`` — the import floor (typer and pydantic import lazily, so this
  line loads little of either);
- a minimal typer command that reads a TOML scene, validates it with a small pydantic model and
  prints one rich table — the framework floor: what any typer + pydantic + rich CLI of this kind
  pays before doing its own work;
- ``python -c pass`` — the interpreter alone.
"""

from __future__ import annotations

import statistics
import sys
import tempfile
from dataclasses import dataclass

from foundation_calc.benchmarks.processes import bytecode_env, run_process

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
    """Median wall time [s] of one command line and its ratios to the import floor and to the
    framework floor; the same for the CPU time [s]."""

    label: str
    command: tuple[str, ...]
    seconds: float
    ratio_to_import_floor: float
    ratio_to_framework_floor: float
    cpu_seconds: float
    cpu_ratio_to_framework_floor: float


def _commands(scene: str) -> dict[str, tuple[str, ...]]:
    py = sys.executable
    return {
        "python -c pass": (py, "-c", "pass"),
        "import typer, pydantic, rich": (py, "-c", "import typer, pydantic, rich"),
        "typer + TOML + pydantic model + rich table": (py, "-c", FRAMEWORK_FLOOR, scene),
        "fcalc resonance SCENE": (py, "-m", "foundation_calc", "resonance", scene),
        "fcalc resonance SCENE --json": (py, "-m", "foundation_calc", "resonance", scene, "--json"),
    }


def startup_times(scene: str, runs: int = 20) -> list[StartupRow]:
    """Run every command ``runs`` times, interleaved, and return the medians and ratios."""
    commands = _commands(scene)
    samples: dict[str, list] = {label: [] for label in commands}
    with tempfile.TemporaryDirectory(prefix="fcalc-bytecode-") as cache:
        env = bytecode_env(cache)
        for round_ in range(runs + 1):
            for label, cmd in commands.items():
                run = run_process(cmd, env)
                if round_:
                    samples[label].append(run)
    wall = {label: statistics.median(r.seconds for r in rs) for label, rs in samples.items()}
    cpu = {label: statistics.median(r.cpu_seconds for r in rs) for label, rs in samples.items()}
    floor = wall["import typer, pydantic, rich"]
    framework = "typer + TOML + pydantic model + rich table"
    return [
        StartupRow(label, commands[label], t, t / floor, t / wall[framework], cpu[label], cpu[label] / cpu[framework])
        for label, t in wall.items()
    ]
