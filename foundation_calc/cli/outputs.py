"""The output-file options of every command (``--junit``, ``--csv``, ``--plot``, ``--write``, ``-o``,
``init``'s PATH) as usage errors: one rule, :func:`foundation_calc.output.files.output_target`."""

from __future__ import annotations

import contextlib
from pathlib import Path

import typer


def writable_path(path: Path, option: str) -> None:
    """A usage error (exit 2) naming ``option`` unless ``path`` can take an output file: checked
    before any work."""
    from foundation_calc.output.files import OutputPathError, output_target

    try:
        output_target(path)
    except OutputPathError as exc:
        raise typer.BadParameter(str(exc), param_hint=f"'{option}'") from None


@contextlib.contextmanager
def writing(path: Path, option: str):
    """Inside, a failed write of ``path`` (:class:`OSError`: a full disk, a FIFO's reader gone, a
    path turned into a folder meanwhile) is a usage error (exit 2) naming ``option``."""
    try:
        yield
    except OSError as exc:
        raise typer.BadParameter(f"cannot write {path}: {exc.strerror or exc}", param_hint=f"'{option}'") from None


def plot_path(plot: Path) -> None:
    """A usage error (exit 2) unless ``plot`` names a format ``--plot`` writes, can take an output
    file (:func:`writable_path`) and matplotlib is installed: checked before any work."""
    from foundation_calc.output.plots import FORMATS, INSTALL_HINT, plotting_available

    if plot.suffix.lower() not in FORMATS:
        raise typer.BadParameter(
            f"{str(plot)!r}: unsupported plot format {plot.suffix or '(none)'!r}; use one of {', '.join(FORMATS)}",
            param_hint="'--plot'",
        )
    writable_path(plot, "--plot")
    if not plotting_available():
        raise typer.BadParameter(f"matplotlib is not installed: {INSTALL_HINT}", param_hint="'--plot'")
