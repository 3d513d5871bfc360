"""Full entries of every source a sheet cites, and the sheet's References section.

A sheet cites a source by its key in brackets (``[KM]``, ``[RHW]`` …) in an equation's source, a
hand calculation's source column or a note; :func:`references_section` lists exactly the keys that
appear, in the order of :data:`REFERENCES`. The README's References section lists the same.
Where the available copy of a paper does not show its journal, year or pages, the entry says so
rather than guess.
"""

from __future__ import annotations

import re

from foundation_calc.output.report.model import Equation, Paragraph, Section, Table, table

#: key -> full entry.
REFERENCES = {
    "KM": "M.F. Krichever, S.M. Makarov, \"Application of the small-parameter method to the problem of"
          " forced vibrations of the foundation of a crank-slider mechanism\" (in Russian: «Применение"
          " метода малого параметра к задаче о вынужденных колебаниях фундамента кривошипно-шатунного"
          " механизма»); journal, year and pages are not on the copy used (it cites works up to 1954).",
    "BC": "N.N. Bolotnik, B.V. Gusev, Nguyen Truong, I.E. Kholmin, F.L. Chernousko, \"Calculation of the"
          " parameters of a vibration mechanism with unbalanced vibration exciters\" (in Russian), Izvestiya"
          " AN SSSR, Mekhanika Tverdogo Tela (Mechanics of Solids), received 13 February 1986; pages are"
          " not on the copy used.",
    "Ba": "D.D. Barkan, Dynamics of Bases and Foundations (in Russian: «Динамика оснований и"
          " фундаментов»), Stroyvoenmorizdat, Moscow, 1948; English translation McGraw-Hill, New York, 1962.",
    "RHW": "F.E. Richart Jr., J.R. Hall Jr., R.D. Woods, Vibrations of Soils and Foundations, Prentice-Hall,"
           " Englewood Cliffs, NJ, 1970, chapters 7 and 10.",
    "DR": "B.M. Das, G.V. Ramana, Principles of Soil Dynamics, 2nd ed., Cengage Learning, Stamford, CT,"
          " 2011, chapter 5.",
    "Ga": "G. Gazetas, \"Formulas and charts for impedances of surface and embedded foundations\", Journal of"
          " Geotechnical Engineering (ASCE) 117(9), 1991, pp. 1363-1381.",
    "PK": "J. Pais, E. Kausel, \"Approximate formulas for dynamic stiffnesses of rigid foundations\", Soil Dynamics"
          " and Earthquake Engineering 7(4), 1988, pp. 213-227.",
    "NIST": "NEHRP Consultants Joint Venture, Soil-Structure Interaction for Building Structures, NIST GCR"
            " 12-917-21, National Institute of Standards and Technology, Gaithersburg, MD, 2012, Tables 2-2, 2-3.",
    "ACI": "ACI Committee 351, Report on Foundations for Dynamic Equipment, ACI 351.3R-18, American Concrete"
           " Institute, Farmington Hills, MI, 2018, section 4.5.",
    "SP26": "SP 26.13330.2012, Foundations of machines with dynamic loads (updated edition of SNiP 2.02.05-87),"
            " Ministry of Regional Development of the Russian Federation, Moscow, 2012.",
    "ISO": "ISO 10816-3:2009, Mechanical vibration — Evaluation of machine vibration by measurements on"
           " non-rotating parts — Part 3: Industrial machines with nominal power above 15 kW and nominal"
           " speeds between 120 r/min and 15 000 r/min when measured in situ, ISO, Geneva, 2009, Table A.1.",
    "Le": "F.M. Lewis, \"Vibration during acceleration through a critical speed\", Transactions of the ASME 54"
          " (APM-54-24), 1932, pp. 253-261.",
}

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
