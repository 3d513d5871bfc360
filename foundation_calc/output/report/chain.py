"""The machine-readable chain of a calculation sheet: how each judged number follows from printed ones.

Every judged number of the Checks table is linked (:class:`~foundation_calc.output.report.model.Link`)
to the formula that gives it and to the cells of the same sheet that print the formula's inputs.
Each writer keeps the chain beside the sheet in its own format (a JSON comment at the end of the
Markdown, a ``<script type="application/json">`` of the HTML, typst ``metadata`` labelled
``<fcalc-chain>`` in the PDF's source, readable with ``typst query``), so a checker's tool, and the
test suite, can recompute each judged number from the sheet alone.
"""

from __future__ import annotations

import json
from dataclasses import asdict

from foundation_calc.output.report.model import Cell, Link

#: Formula name -> what a checker computes from the linked inputs (symbols as in the link).
FORMULAS = {
    "ratio": "value/limit; limit/value for a limit the value must reach (≥)",
    "detuning": "|ω − ω_c|/ω_c with ω_c = p/n, the nearer of the printed p (ω from n_rpm·π/30 when given in rpm)",
    "closest detuning": "the smallest |ω − p_i|/p_i over the printed p_i",
    "quotient": "a/b",
    "bearing pressure": "W/(L B) (1 + 6|e_x|/L + 6|e_y|/B)",
    "maximum": "the largest of the inputs",
    "integration": "the time integration stated under Start-up and run-down (its passages' peaks, the motor's torques)",
    "harmonic balance": "the 6-DOF verification's harmonic balance stated under its table (the printed value)",
    "block peak": "Σ over machines of max over one revolution of |Σ_n Re(u_P,n e^{i n ω t})|, u_P,n = Z_u,n + Z_θ,n × r_P",
    "block rms": "√(Σ over machines and orders of |Ω^{k} u_P,n|²/2), k = 1 for a velocity, 2 for an acceleration",
    "crank peak": "max over one revolution of |Σ_n Re((nω)^{k} Z_n e^{i nωt})| of the point's x + height·θ or y + horizontal·θ",
    "crank rms": "√(Σ_n |(nω)^{k} u_P,n|²/2) of the point's x + height·θ or y + horizontal·θ",
}

#: The cell of a check row of the Checks table.
CHECKS_TABLE = "Every check"

#: Formulas whose number is not a closed form of printed values but a numerical solution the sheet
#: states (its method, resolution and error), linked to the table that prints it.
NUMERICAL = ("integration", "harmonic balance")


def check_cell(check: str, item: str, column: str) -> Cell:
    """The cell of the Checks table's row ``check``, ``item`` under ``column``."""
    return Cell(CHECKS_TABLE, (check, item), column)


def _cell(cell: Cell) -> dict:
    """A cell as JSON: ``table``, ``row``, ``column`` and, where they are not empty, ``section``,
    ``after`` and ``index``."""
    return {k: v for k, v in asdict(cell).items() if k in ("table", "row", "column") or v}


def chain_document(links: tuple[Link, ...]) -> str:
    """The chain as JSON text: the formulas and a list of links, each ``formula``, ``result`` (a
    cell) and ``inputs`` (``[symbol, cell]``); a row ``["*"]`` is every row of the table, a column
    ``"*"`` every column. ``<``, ``>`` and ``&`` are written as JSON escapes, so the text, user
    text included, never reads as markup where a writer embeds it."""
    text = json.dumps(
        {"formulas": FORMULAS, "links": [{"formula": link.formula, "result": _cell(link.result),
                                          "inputs": [[name, _cell(cell)] for name, cell in link.inputs]} for link in links]},
        ensure_ascii=False, separators=(",", ":"),
    )
    return text.replace("&", "\\u0026").replace("<", "\\u003c").replace(">", "\\u003e")
