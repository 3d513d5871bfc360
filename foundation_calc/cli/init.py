"""``fcalc init KIND [PATH]``: write a starting scene with every key and its unit documented."""

from __future__ import annotations

from pathlib import Path
from typing import Annotated, Optional

import typer

from foundation_calc.cli.guard import reports_errors
from foundation_calc.cli.kinds import KindArg

PathArg = Annotated[
    Optional[Path],
    typer.Argument(
        metavar="PATH", help="File to write (default KIND.toml here; a folder gets KIND.toml; - prints it).", show_default=False
    ),
]
ForceOpt = Annotated[bool, typer.Option("--force", help="Overwrite PATH if it exists.")]


@reports_errors
def init(kind: KindArg, path: PathArg = None, force: ForceOpt = False) -> None:
    """Write a starting scene of KIND: the shipped example, every key with symbol, unit and range.

    Never overwrites an existing file without --force; a file is written atomically (a
    temporary file in the same folder, then renamed), so an interrupted run leaves no half file;
    a FIFO or a device (--force) is written in place, never replaced.
    """
    from foundation_calc.api.options import writable_path, writing
    from foundation_calc.output.files import write_atomically
    from foundation_calc.scenes.template import scene_template

    text = scene_template(kind)
    if path is not None and str(path) == "-":
        print(text, end="")
        return
    target = path if path is not None else Path(f"{kind}.toml")
    if target.is_dir():
        target = target / f"{kind}.toml"
    if target.exists() and not force:
        raise typer.BadParameter(f"{target} exists; use --force to overwrite it", param_hint="PATH")
    writable_path(target, "PATH")
    with writing(target, "PATH"):
        try:
            write_atomically(target, text, overwrite=force)
        except FileExistsError:
            raise typer.BadParameter(f"{target} exists; use --force to overwrite it", param_hint="PATH") from None
    from foundation_calc.output.console import stderr

    stderr().print(f"wrote {target} (kind {kind}); check it with: fcalc check {target}", soft_wrap=True, markup=False)
