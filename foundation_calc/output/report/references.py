"""The sheet's References section: the full entry of every source the sheet cites.

A sheet cites a source by its key in brackets (``[KM]``, ``[RHW]`` …) in an equation's source, a
hand calculation's source column or a note; :func:`references_section` lists exactly the keys that
appear, in the order of the one list, :data:`foundation_calc.references.REFERENCES`.
"""

from __future__ import annotations

import re

from foundation_calc.output.report.model import Equation, Paragraph, Section, Table, table
from foundation_calc.references import REFERENCES

_KEY = re.compile(r"\[(" + "|".join(map(re.escape, REFERENCES)) + r")\]")


def _texts(block):
    if isinstance(block, Paragraph):
        yield block.text
    elif isinstance(block, Table):
        yield block.title
        yield from (cell for row in block.rows for cell in row)
    elif isinstance(block, Equation):
        yield block.source
        yield block.correction


def cited(sections) -> list[str]:
    """The keys of :data:`REFERENCES` cited anywhere in ``sections``, in the order of REFERENCES."""
    found = {m.group(1) for section in sections for block in section.blocks for text in _texts(block) for m in _KEY.finditer(text)}
    return [key for key in REFERENCES if key in found]


def references_section(sections) -> Section:
    """Every source ``sections`` cite, with its full entry."""
    rows = ((f"[{key}]", REFERENCES[key]) for key in cited(sections))
    return Section("References", (table("", ("key", "reference"), rows, (False, False)),))
