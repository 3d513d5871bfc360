"""The ``--units`` option shared by every command that prints tables (read by
:func:`foundation_calc.api.options.display_units`)."""

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
