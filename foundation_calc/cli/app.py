"""The ``fcalc`` application: one module per command, heavy imports inside the commands."""

from __future__ import annotations

import typer

from foundation_calc import __version__
from foundation_calc.cli.amplitudes import amplitudes
from foundation_calc.cli.bench import bench
from foundation_calc.cli.check import check
from foundation_calc.cli.init import init
from foundation_calc.cli.platform import platform
from foundation_calc.cli.report import report
from foundation_calc.cli.resonance import resonance
from foundation_calc.cli.runup import runup
from foundation_calc.cli.schema import schema
from foundation_calc.cli.sweep import sweep

EXIT_CODES_HELP = (
    "Exit codes: 0 every check passes; 1 a check fails; 2 command-line usage error;"
    " 3 invalid scene (unreadable, bad TOML, failed validation, physically impossible);"
    " 4 internal error; 141 stdout closed by its reader (fcalc ... | head)."
)

app = typer.Typer(
    name="fcalc",
    help="Dynamics of machine foundations and vibrating platforms.\n\n" + EXIT_CODES_HELP,
    no_args_is_help=True,
    add_completion=False,
    pretty_exceptions_enable=False,
    epilog=EXIT_CODES_HELP,
    rich_markup_mode=None,  # help text is plain: units in brackets ([m], [[points]]) print as written
)
app.command(epilog=EXIT_CODES_HELP)(resonance)
app.command(epilog=EXIT_CODES_HELP)(amplitudes)
app.command(epilog=EXIT_CODES_HELP)(check)
app.command(epilog=EXIT_CODES_HELP)(init)
app.command(epilog=EXIT_CODES_HELP)(schema)
app.command(epilog=EXIT_CODES_HELP)(platform)
app.command(epilog=EXIT_CODES_HELP)(bench)
app.command(epilog=EXIT_CODES_HELP)(sweep)
app.command(epilog=EXIT_CODES_HELP)(report)
app.command(epilog=EXIT_CODES_HELP)(runup)


def _version(value: bool) -> None:
    if value:
        print(f"fcalc {__version__}")
        raise typer.Exit()


@app.callback()
def _root(
    version: bool = typer.Option(False, "--version", callback=_version, is_eager=True, help="Show the version."),
) -> None:
    """Dynamics of machine foundations and vibrating platforms."""


def main() -> None:
    """Console-script entry point."""
    app()
