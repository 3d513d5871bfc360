"""The ``fcalc`` application: one module per command, heavy imports inside the commands.

``fcalc NAME ...`` imports the module of command NAME alone (:func:`main`); ``app`` (every
command, for ``fcalc --help`` and the tests) is built on first use.
"""

from __future__ import annotations

import importlib
import os
import sys

import typer

#: The commands in the order of ``fcalc --help``: name -> module defining a function of that name.
COMMANDS = {
    name: f"foundation_calc.cli.{name}"
    for name in ("resonance", "amplitudes", "soil", "check", "init", "schema", "platform", "bench", "sweep", "report", "runup", "validate", "design")
}

EXIT_CODES_HELP = (
    "Exit codes: 0 every check passes; 1 a check fails; 2 command-line usage error;"
    " 3 invalid scene (unreadable, bad TOML, failed validation, physically impossible);"
    " 4 internal error; 141 stdout closed by its reader (fcalc ... | head);"
    " 143 / 130 stopped by SIGTERM / SIGINT."
)


#: Threads of the linear-algebra library, unless the environment sets them: fcalc's matrices have
#: at most a few hundred unknowns, where threads cost more than they give (several times the time
#: of a platform check on a busy machine); batches run in processes instead (``check --jobs``).
BLAS_THREAD_VARIABLES = ("OPENBLAS_NUM_THREADS", "OMP_NUM_THREADS", "MKL_NUM_THREADS")


def _version(value: bool) -> None:
    if value:
        from foundation_calc.version import version

        print(f"fcalc {version()}")
        raise typer.Exit()


def _root(
    version: bool = typer.Option(False, "--version", callback=_version, is_eager=True, help="Show the version."),
) -> None:
    """Dynamics of machine foundations and vibrating platforms."""


def build_app(names=tuple(COMMANDS)) -> typer.Typer:
    """The ``fcalc`` application with the commands ``names`` (all by default)."""
    from foundation_calc.cli.help_text import PlainCommand

    application = typer.Typer(
        name="fcalc",
        help="Dynamics of machine foundations and vibrating platforms.",
        no_args_is_help=True,
        add_completion=False,
        pretty_exceptions_enable=False,
        epilog=EXIT_CODES_HELP,
        rich_markup_mode=None,  # help text is plain: units in brackets ([m], [[points]]) print as written
    )
    for name in names:
        application.command(epilog=EXIT_CODES_HELP, cls=PlainCommand)(getattr(importlib.import_module(COMMANDS[name]), name))
    application.callback()(_root)
    return application


def __getattr__(name: str):
    if name == "app":
        globals()["app"] = build_app()
        return globals()["app"]
    raise AttributeError(f"module {__name__!r} has no attribute {name!r}")


class ClosedStream:
    """Stands for a standard stream that was closed before fcalc started (``fcalc ... >&-``):
    writing to it is a closed pipe (exit 141, as for ``fcalc ... | head``), never a crash."""

    encoding = "utf-8"
    errors = "backslashreplace"

    def write(self, text: str) -> int:
        raise BrokenPipeError(9, "the stream was closed before fcalc started")

    def flush(self) -> None:
        """Nothing is buffered, so nothing is lost."""

    def isatty(self) -> bool:
        return False

    def fileno(self) -> int:
        import io

        raise io.UnsupportedOperation("closed stream")


def prepare_streams() -> None:
    """Make stdout and stderr safe to write whatever a scene holds: a character the terminal's
    encoding lacks (a file name in another encoding, µ on an ASCII terminal) is written as a
    backslash escape, and a stream closed before the start is a :class:`ClosedStream`."""
    for name in ("stdout", "stderr"):
        stream = getattr(sys, name)
        if stream is None:
            setattr(sys, name, ClosedStream())
            continue
        try:
            stream.reconfigure(errors="backslashreplace")
        except (AttributeError, ValueError):  # not a text file of the io module (embedding)
            pass


def main() -> None:
    """Console-script entry point: only the module of the command asked for is imported, with one
    linear-algebra thread (:data:`BLAS_THREAD_VARIABLES`) unless the environment says otherwise,
    on streams that take any text (:func:`prepare_streams`)."""
    for variable in BLAS_THREAD_VARIABLES:
        os.environ.setdefault(variable, "1")
    prepare_streams()
    command = next((arg for arg in sys.argv[1:] if not arg.startswith("-")), None)
    build_app((command,) if command in COMMANDS else tuple(COMMANDS))()
