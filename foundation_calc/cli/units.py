"""The ``--units`` option shared by every command that prints tables."""

from __future__ import annotations

from typing import Annotated, Optional

import typer

UnitsOpt = Annotated[
    Optional[list[str]],
    typer.Option(
        "--units",
        metavar="UNIT[,UNIT]",
        help="Units of the tables (JSON stays SI): m, mm or µm (um) for amplitudes; rad/s, Hz or rpm"
        " for speeds; m/s or mm/s for velocities. Repeat the option or separate by commas, e.g."
        " --units mm,rpm. Default: SI.",
        show_default=False,
    ),
]


def display_units(tokens: list[str] | None, defaults: tuple[str, ...] = ()):
    """The :class:`~foundation_calc.output.display_units.DisplayUnits` chosen by ``--units``;
    ``defaults`` (unit names) hold for the quantities it does not name."""
    from foundation_calc.output.display_units import parse_units

    try:
        return parse_units(tokens or [], defaults)
    except ValueError as exc:
        raise typer.BadParameter(str(exc), param_hint="'--units'") from None
