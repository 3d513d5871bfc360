"""Options of the commands as keyword arguments: their allowed ranges (checked once for the
command line, typer's ``min``/``max`` shown in ``--help``, and for the Python API), and the
output files (``--junit``, ``--csv``, ``--plot``, ``--write``, ``-o``, ``init``'s PATH) as usage
errors: one rule, :func:`foundation_calc.output.files.output_target`."""

from __future__ import annotations

import contextlib


def option_name(keyword: str) -> str:
    """The command-line option of a keyword argument, quoted as usage errors quote it.

    >>> option_name("modulus_cov")
    "'--modulus-cov'"
    """
    return f"'--{keyword.replace('_', '-')}'"


def within(keyword: str, value, lo=None, hi=None) -> None:
    """Raise :class:`~foundation_calc.errors.UsageError` (exit 2) naming the option of ``keyword``
    unless ``lo <= value <= hi`` (None: no bound), in typer's words for the same range."""
    from foundation_calc.errors import UsageError

    if (lo is None or value >= lo) and (hi is None or value <= hi):
        return
    bounds = f"{lo}<=x<={hi}" if lo is not None and hi is not None else f"x>={lo}" if lo is not None else f"x<={hi}"
    raise UsageError(f"{value} is not in the range {bounds}.", option_name(keyword))


def writable_path(path, option: str) -> None:
    """A usage error (exit 2) naming ``option`` unless ``path`` can take an output file
    (:func:`foundation_calc.output.files.output_target`): checked before any work."""
    from foundation_calc.errors import UsageError
    from foundation_calc.output.files import OutputPathError, output_target

    try:
        output_target(path)
    except OutputPathError as exc:
        raise UsageError(str(exc), f"'{option}'") from None


@contextlib.contextmanager
def writing(path, option: str):
    """Inside, a failed write of ``path`` (:class:`OSError`: a full disk, a FIFO's reader gone, a
    path turned into a folder meanwhile) is a usage error (exit 2) naming ``option``."""
    from foundation_calc.errors import UsageError

    try:
        yield
    except OSError as exc:
        raise UsageError(f"cannot write {path}: {exc.strerror or exc}", f"'{option}'") from None


def plot_path(plot) -> None:
    """A usage error (exit 2) unless ``plot`` names a format ``--plot`` writes, can take an output
    file (:func:`writable_path`) and matplotlib is installed: checked before any work."""
    from foundation_calc.errors import UsageError
    from foundation_calc.output.plots import FORMATS, INSTALL_HINT, plotting_available

    if plot.suffix.lower() not in FORMATS:
        raise UsageError(f"{str(plot)!r}: unsupported plot format {plot.suffix or '(none)'!r}; use one of {', '.join(FORMATS)}",
                         "'--plot'")
    writable_path(plot, "--plot")
    if not plotting_available():
        raise UsageError(f"matplotlib is not installed: {INSTALL_HINT}", "'--plot'")


def display_units(tokens: list[str] | None, defaults: tuple[str, ...] = ()):
    """The :class:`~foundation_calc.output.display_units.DisplayUnits` of ``--units`` ``tokens``
    (``["mm,rpm"]``); ``defaults`` (unit names) hold for the quantities they do not name."""
    from foundation_calc.errors import UsageError
    from foundation_calc.output.display_units import parse_units

    try:
        return parse_units(tokens or [], defaults)
    except ValueError as exc:
        raise UsageError(str(exc), "'--units'") from None
