"""Turn exceptions into messages on stderr and documented exit codes.

Every command body runs under :func:`reports_errors`: a :class:`FcalcError` prints its message
(one line per problem, naming the field) and exits with its code; anything else is a bug in
fcalc and exits 4 with a one-line summary, never a traceback (set ``FCALC_DEBUG=1`` to see it).
With ``--json`` the error is also the one JSON document on stdout (:func:`error_document`).
"""

from __future__ import annotations

import contextlib
import functools
import os
import sys
import threading
from collections.abc import Callable

import typer

from foundation_calc.errors import ExitCode, FcalcError, PhysicsError, SceneError, UsageError


#: Exit code when stdout is closed by its reader, as for a process ended by SIGPIPE (128 + 13).
BROKEN_PIPE = 141


class BadOption(typer.BadParameter):
    """typer's usage error (exit 2) for an option's value that fcalc refuses: its usage, hint and
    ``Error: ...`` as click writes them, through fcalc's message console, so that on a terminal
    the error wraps at words under its text (``Error: `` hangs) and in a file or a pipe each line
    stays whole (:class:`~foundation_calc.output.console.Hanging`)."""

    def show(self, file=None) -> None:
        import io

        from rich.text import Text

        from foundation_calc.output.console import Hanging, stderr

        if file is not None:
            super().show(file)
            return
        written = io.StringIO()
        super().show(written)
        stderr().print(Hanging(Text(written.getvalue().removesuffix("\n")), len("Error: ")))


class Interrupted(BaseException):
    """SIGTERM (a CI runner cancelling the job) or SIGINT (Ctrl-C) arrived inside
    :func:`interruptible`; the command ends with exit code 128 + ``signum``."""

    def __init__(self, signum: int):
        import signal

        self.signum = signum
        self.name = signal.Signals(signum).name
        super().__init__(self.name)


@contextlib.contextmanager
def interruptible():
    """Inside, SIGTERM and SIGINT raise :class:`Interrupted` in the main thread, so that the
    command can end its workers and its reports before it exits; the handlers are restored after.

    Yields a function that raises :class:`Interrupted` again when a signal came but its exception
    was swallowed (Python ignores exceptions raised in some callbacks, e.g. around a fork): call
    it between steps.
    """
    import signal

    received: list[int] = []

    def interrupt(signum, frame):
        received.append(signum)
        raise Interrupted(signum)

    def again() -> None:
        if received:
            raise Interrupted(received[0])

    if threading.current_thread() is not threading.main_thread():
        yield again  # only the main thread receives signals
        return
    previous = {signum: signal.signal(signum, interrupt) for signum in (signal.SIGTERM, signal.SIGINT)}
    try:
        yield again
    finally:
        for signum, handler in previous.items():
            signal.signal(signum, handler)


def report_error(exc: FcalcError) -> None:
    """Print a user-facing error on stderr: one line per problem in a file or a pipe (scripts grep
    them), wrapped with a hanging indent on a terminal (:class:`~foundation_calc.output.console.Hanging`)."""
    from rich.markup import escape

    from foundation_calc.output.console import Hanging, stderr

    err = stderr()
    if isinstance(exc, SceneError):
        err.print(Hanging(f"[bold red]error[/]: invalid scene {escape(exc.source)}", len("error: ")))
        for loc, msg in exc.problems:
            err.print(Hanging(f"  {escape(loc) + ': ' if loc else ''}{escape(msg)}"))
    else:
        err.print(Hanging(f"[bold red]error[/]: {escape(str(exc))}", len("error: ")))


def warn_implausible(scene, source: str = "") -> None:
    """Print the scene's plausibility warnings (probably a wrong unit) on stderr; they never
    change the exit code."""
    print_warnings(scene.plausibility_warnings(), source)


def print_warnings(texts, source: str = "") -> None:
    """Print plausibility warnings ``texts`` of the scene read from ``source`` on stderr."""
    if not texts:
        return  # nothing to import or set up: most scenes have no warning
    from foundation_calc.output.console import stderr, warning_line

    for text in texts:
        stderr().print(warning_line(f"{source}: {text}" if source else text))


def report_internal(text: str) -> None:
    """Print an unexpected exception (a bug in fcalc) on stderr, without a traceback."""
    from rich.markup import escape

    from foundation_calc.output.console import Hanging, stderr

    err = stderr()
    err.print(Hanging(f"[bold red]internal error[/]: {escape(text)}", len("internal error: ")))
    err.print(Hanging("  This is a bug in fcalc; please report it with the scene file"
                      " (FCALC_DEBUG=1 shows the traceback)."))


def error_document(command: str, scene: str, exc: BaseException) -> dict:
    """The JSON document of a command that ends in an error: ``verdict`` ``invalid`` (exit 3)
    or ``internal`` (exit 4, a bug), and one ``{field, message}`` per problem, as the entries of
    ``fcalc check --json`` carry them."""
    from foundation_calc.output.console import JSON_SCHEMA_VERSION

    if isinstance(exc, SceneError):
        scene, problems = exc.source, list(exc.problems)
    elif isinstance(exc, PhysicsError):
        problems = exc.problems
    elif isinstance(exc, FcalcError):
        problems = [("", str(exc))]
    else:
        problems = [("", f"internal error (a bug in fcalc): {type(exc).__name__}: {exc}")]
    code = exc.exit_code if isinstance(exc, FcalcError) else ExitCode.INTERNAL
    return {
        "schema_version": JSON_SCHEMA_VERSION,
        "command": command,
        "scene": scene,
        "verdict": "invalid" if code == ExitCode.INVALID_SCENE else "internal",
        "exit_code": int(code),
        "problems": [{"field": field, "message": message} for field, message in problems],
    }


def _print_error_document(command: Callable, args, kwargs, exc: BaseException) -> None:
    """With ``--json`` (the command's ``json`` argument), :func:`error_document` on stdout."""
    import inspect

    try:
        bound = inspect.signature(command).bind_partial(*args, **kwargs).arguments
    except TypeError:
        return
    if not bound.get("json"):
        return
    name = command.__module__.rpartition(".")[2]  # each command lives in the module of its name
    if name == "check":
        return  # its document, written scene by scene, carries every scene's problems itself
    scene = bound.get("scene")
    from foundation_calc.output.console import print_json

    print_json(error_document(name, "" if scene is None else str(scene), exc))


def reports_errors(command: Callable) -> Callable:
    """Decorate a typer command so that errors end in a message and an exit code."""

    @functools.wraps(command)
    def wrapper(*args, **kwargs):
        try:
            try:
                return command(*args, **kwargs)
            except (typer.Exit, typer.Abort, typer.BadParameter, KeyboardInterrupt, BrokenPipeError):
                raise  # typer prints a bad parameter as a usage error itself (exit 2)
            except UsageError as exc:  # an option's value (foundation_calc.api): typer's usage error
                raise BadOption(str(exc), param_hint=exc.option or None) from None
            except FcalcError as exc:
                report_error(exc)
                _print_error_document(command, args, kwargs, exc)
                raise typer.Exit(int(exc.exit_code)) from None
            except Exception as exc:  # a bug: say so without a traceback
                if os.environ.get("FCALC_DEBUG"):
                    raise
                report_internal(f"{type(exc).__name__}: {exc}")
                _print_error_document(command, args, kwargs, exc)
                raise typer.Exit(int(ExitCode.INTERNAL)) from None
        except BrokenPipeError:  # `fcalc ... | head`: the reader left; stop quietly, as a shell would
            try:  # no "Exception ignored" message when Python flushes stdout at exit
                os.dup2(os.open(os.devnull, os.O_WRONLY), sys.stdout.fileno())
            except (OSError, ValueError):  # stdout is not a file (tests, embedding), or closed
                pass
            raise typer.Exit(BROKEN_PIPE) from None

    return wrapper
