"""Exceptions raised by foundation_calc, and the exit code each one maps to.

Solvers and scene loaders raise; only :mod:`foundation_calc.cli` turns an exception into a
message and an exit code. Every exception also inherits a built-in (``ValueError`` or
``ArithmeticError``) so that library users can catch it without importing this module.
"""

from __future__ import annotations

from enum import IntEnum


class ExitCode(IntEnum):
    """Exit codes of ``fcalc``, documented in docs/exit-codes.md and ``fcalc --help``."""

    OK = 0  #: every check passes
    CHECK_FAILED = 1  #: at least one check fails (resonance, amplitude, feasibility warning made strict)
    USAGE = 2  #: command-line usage error (typer/click)
    INVALID_SCENE = 3  #: unreadable file, bad TOML, failed validation, physically impossible design
    INTERNAL = 4  #: a bug in fcalc: please report it with the scene file


class FcalcError(Exception):
    """Base class of every error that fcalc reports to its user."""

    exit_code: ExitCode = ExitCode.INTERNAL


class SceneError(FcalcError, ValueError):
    """A scene file cannot be used: unreadable, not TOML, or fails validation.

    ``problems`` holds one ``(location, message)`` pair per problem, where ``location`` is the
    dotted path of the field (``mechanism.rod_length``) or ``""`` for the file as a whole.
    """

    exit_code = ExitCode.INVALID_SCENE

    def __init__(self, source: str, problems: list[tuple[str, str]]):
        self.source = source
        self.problems = problems
        lines = [f"{loc}: {msg}" if loc else msg for loc, msg in problems]
        super().__init__(f"{source}: " + "; ".join(lines))


class NonFiniteError(FcalcError, ArithmeticError):
    """A computed number is NaN or infinite: the scene cannot be computed (it lies outside the
    range the arithmetic carries). ``where`` is the dotted path of the number in the result
    (``result.passages[1].eta``), ``value`` the number itself."""

    exit_code = ExitCode.INVALID_SCENE

    def __init__(self, where: str, value: float):
        self.where = where
        self.value = value
        shown = "NaN" if value != value else f"{value}"
        super().__init__(
            f"{where or 'a result'} is {shown}: fcalc cannot compute this number for the scene"
            " (it is probably outside the trusted range of its inputs)"
        )

    @classmethod
    def find(cls, value, where: str = "") -> "NonFiniteError | None":
        """The error for the first NaN or inf in ``value`` (nested dicts, lists, tuples and
        numbers, e.g. a JSON document), None when every number in it is finite."""
        if isinstance(value, float):
            return None if value - value == 0.0 else cls(where, value)
        items = value.items() if isinstance(value, dict) else enumerate(value) if isinstance(value, (list, tuple)) else ()
        for key, item in items:
            inner = f"{where}[{key}]" if isinstance(key, int) else f"{where}.{key}" if where else str(key)
            found = cls.find(item, inner)
            if found is not None:
                return found
        return None


class PhysicsError(FcalcError, ValueError):
    """The inputs are valid numbers but describe a system that has no answer.

    Examples: a foundation that is unstable in rocking, an isolator stiffness that must be
    negative. ``field`` names the scene field (or derived quantity) that is responsible, and
    ``hint`` says what range would make the design possible.
    """

    exit_code = ExitCode.INVALID_SCENE

    def __init__(self, message: str, *, field: str = "", hint: str = ""):
        self.message = message
        self.field = field
        self.hint = hint
        #: message and hint without the field: what a JSON document puts next to ``field``
        self.detail = f"{message} ({hint})" if hint else message
        super().__init__(f"{field}: {self.detail}" if field else self.detail)


class ConvergenceError(FcalcError, ArithmeticError):
    """An iterative solver did not converge; the message says how far it got."""

    exit_code = ExitCode.INVALID_SCENE
