"""Exceptions raised by foundation_calc, and the exit code each one maps to.

Solvers and scene loaders raise; only :mod:`foundation_calc.cli` turns an exception into a
message and an exit code. Every exception also inherits a built-in (``ValueError`` or
``ArithmeticError``) so that library users can catch it without importing this module.
"""

from __future__ import annotations

from enum import IntEnum
from typing import NamedTuple


class ExitCode(IntEnum):
    """Exit codes of ``fcalc``, documented in docs/exit-codes.md and ``fcalc --help``."""

    OK = 0  #: every check passes
    CHECK_FAILED = 1  #: at least one check fails (resonance, amplitude, feasibility warning made strict)
    USAGE = 2  #: command-line usage error (typer/click)
    INVALID_SCENE = 3  #: unreadable file, bad TOML, failed validation, physically impossible design
    INTERNAL = 4  #: a bug in fcalc: please report it with the scene file


class Problem(NamedTuple):
    """One problem of a scene: ``field``, the dotted path of the key (``mechanism.rod_length``, or
    ``""`` for the file as a whole), and ``message``, naming the value, its unit and the allowed
    range.

    It is the pair ``(field, message)`` and also equals the ``{"field": ..., "message": ...}``
    object that the JSON documents carry for it:

    >>> problem = Problem("kind", "missing")
    >>> problem == ("kind", "missing"), problem == {"field": "kind", "message": "missing"}
    (True, True)
    """

    field: str
    message: str

    def __eq__(self, other) -> bool:
        if isinstance(other, dict):
            return other == self.to_dict()
        return tuple.__eq__(self, other)

    def __ne__(self, other) -> bool:
        return not self == other

    __hash__ = tuple.__hash__

    def to_dict(self) -> dict[str, str]:
        """The problem as the JSON documents write it: ``{"field": ..., "message": ...}``."""
        return {"field": self.field, "message": self.message}


class FcalcError(Exception):
    """Base class of every error that fcalc reports to its user."""

    exit_code: ExitCode = ExitCode.INTERNAL


class SceneError(FcalcError, ValueError):
    """A scene file cannot be used: unreadable, not TOML, or fails validation.

    ``problems`` holds one :class:`Problem` (a ``(field, message)`` pair) per problem, where
    ``field`` is the dotted path of the field (``mechanism.rod_length``) or ``""`` for the file as
    a whole: the ``problems`` of the JSON documents (``fcalc check --json``).
    """

    exit_code = ExitCode.INVALID_SCENE

    def __init__(self, source: str, problems: list[tuple[str, str]]):
        self.source = source
        self.problems = [Problem(*problem) for problem in problems]
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
    ``hint`` says what range would make the design possible; ``problems`` is the one
    :class:`Problem` a JSON document reports for it.
    """

    exit_code = ExitCode.INVALID_SCENE

    def __init__(self, message: str, *, field: str = "", hint: str = ""):
        self.message = message
        self.field = field
        self.hint = hint
        #: message and hint without the field: what a JSON document puts next to ``field``
        self.detail = f"{message} ({hint})" if hint else message
        self.problems = [Problem(field, self.detail)]
        super().__init__(f"{field}: {self.detail}" if field else self.detail)


class NotApplicable(PhysicsError):
    """A paper's closed form does not apply to the design, which has an answer by another method:
    a command that has one reports it and says why the closed form is left out (``message``); a
    command that has none refuses the scene, as any :class:`PhysicsError`."""


class ConvergenceError(FcalcError, ArithmeticError):
    """An iterative solver did not converge; the message says how far it got."""

    exit_code = ExitCode.INVALID_SCENE


class UsageError(FcalcError, ValueError):
    """An option has a value the command cannot take (a sweep range ``600:100``, ``--step`` and
    ``--points`` together): exit 2, as a command-line usage error. ``option`` names the option as
    the command line writes it (``'--speed'``); a keyword argument of the Python API has the
    option's name with ``_`` for ``-`` (``modulus_cov`` for ``--modulus-cov``)."""

    exit_code = ExitCode.USAGE

    def __init__(self, message: str, option: str = ""):
        self.option = option
        super().__init__(message)
