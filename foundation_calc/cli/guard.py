"""Turn exceptions into messages on stderr and documented exit codes.

Every command body runs under :func:`reports_errors`: a :class:`FcalcError` prints its message
(one line per problem, naming the field) and exits with its code; anything else is a bug in
fcalc and exits 4 with a one-line summary, never a traceback (set ``FCALC_DEBUG=1`` to see it).
"""

from __future__ import annotations

import functools
import os
import sys
from collections.abc import Callable

import typer

from foundation_calc.errors import ExitCode, FcalcError, SceneError


#: Exit code when stdout is closed by its reader, as for a process ended by SIGPIPE (128 + 13).
BROKEN_PIPE = 141


def report_error(exc: FcalcError) -> None:
    """Print a user-facing error on stderr."""
    from rich.markup import escape

    from foundation_calc.output.console import stderr

    err = stderr()
    if isinstance(exc, SceneError):
        err.print(f"[bold red]error[/]: invalid scene {escape(exc.source)}")
        for loc, msg in exc.problems:
            err.print(f"  {escape(loc) + ': ' if loc else ''}{escape(msg)}", soft_wrap=True)
    else:
        err.print(f"[bold red]error[/]: {escape(str(exc))}", soft_wrap=True)


def warn_implausible(scene, source: str = "") -> None:
    """Print the scene's plausibility warnings (probably a wrong unit) on stderr; they never
    change the exit code."""
    print_warnings(scene.plausibility_warnings(), source)


def print_warnings(texts, source: str = "") -> None:
    """Print plausibility warnings ``texts`` of the scene read from ``source`` on stderr."""
    if not texts:
        return  # nothing to import or set up: most scenes have no warning
    from rich.markup import escape

    from foundation_calc.output.console import stderr

    for text in texts:
        where = f"{escape(source)}: " if source else ""
        stderr().print(f"[bold yellow]warning[/]: {where}{escape(text)}", soft_wrap=True)


def report_internal(text: str) -> None:
    """Print an unexpected exception (a bug in fcalc) on stderr, without a traceback."""
    from rich.markup import escape

    from foundation_calc.output.console import stderr

    stderr().print(
        f"[bold red]internal error[/]: {escape(text)}\n"
        "  This is a bug in fcalc; please report it with the scene file"
        " (FCALC_DEBUG=1 shows the traceback).",
        soft_wrap=True,
    )


def reports_errors(command: Callable) -> Callable:
    """Decorate a typer command so that errors end in a message and an exit code."""

    @functools.wraps(command)
    def wrapper(*args, **kwargs):
        try:
            return command(*args, **kwargs)
        except (typer.Exit, typer.Abort, typer.BadParameter, KeyboardInterrupt):
            raise  # typer prints a bad parameter as a usage error itself (exit 2)
        except BrokenPipeError:  # `fcalc ... | head`: the reader left; stop quietly, as a shell would
            try:  # no "Exception ignored" message when Python flushes stdout at exit
                os.dup2(os.open(os.devnull, os.O_WRONLY), sys.stdout.fileno())
            except (OSError, ValueError):  # stdout is not a file (tests, embedding)
                pass
            raise typer.Exit(BROKEN_PIPE) from None
        except FcalcError as exc:
            report_error(exc)
            raise typer.Exit(int(exc.exit_code)) from None
        except Exception as exc:  # a bug: say so without a traceback
            if os.environ.get("FCALC_DEBUG"):
                raise
            report_internal(f"{type(exc).__name__}: {exc}")
            raise typer.Exit(int(ExitCode.INTERNAL)) from None

    return wrapper
