"""The one list of sources fcalc cites: a calculation sheet, the validation record and docs/theory.md.

Each source has one key, printed in brackets (``[KM]``, ``[RHW]`` …) wherever it is cited: in an
equation's source, a hand calculation's source column, a check's note or a validation case. The
entry is the full reference (authors, title, journal or publisher, year, pages or part used); where
the available copy of a paper does not show its journal, year or pages, the entry says so rather
than guess. Data only, so every layer may import it. docs/theory.md, References, lists the same
entries in the same words (a test compares them).
"""

from __future__ import annotations

#: key -> full entry, in the order docs/theory.md and a sheet's References section list them.
REFERENCES: dict[str, str] = {
    "KM": "M.F. Krichever, S.M. Makarov, \"Application of the small-parameter method to the problem of"
          " forced vibrations of the foundation of a crank-slider mechanism\" (in Russian: «Применение"
          " метода малого параметра к задаче о вынужденных колебаниях фундамента кривошипно-шатунного"
          " механизма»); journal, year and pages are not on the copy used (it cites works up to 1954).",
    "BC": "N.N. Bolotnik, B.V. Gusev, Nguyen Truong, I.E. Kholmin, F.L. Chernousko, \"Calculation of the"
          " parameters of a vibration mechanism with unbalanced vibration exciters\" (in Russian), Izvestiya"
          " AN SSSR, Mekhanika Tverdogo Tela (Mechanics of Solids), received 13 February 1986, sections 3-4;"
          " pages are not on the copy used.",
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
           " Institute, Farmington Hills, MI, 2018.",
    "SP26": "SP 26.13330.2012, Foundations of machines with dynamic loads (updated edition of SNiP 2.02.05-87),"
            " Ministry of Regional Development of the Russian Federation, Moscow, 2012.",
    "ISO": "ISO 10816-3:2009, Mechanical vibration — Evaluation of machine vibration by measurements on"
           " non-rotating parts — Part 3: Industrial machines with nominal power above 15 kW and nominal"
           " speeds between 120 r/min and 15 000 r/min when measured in situ, ISO, Geneva, 2009, Annex A,"
           " Tables A.1 and A.2.",
    "Le": "F.M. Lewis, \"Vibration during acceleration through a critical speed\", Transactions of the ASME 54"
          " (APM-54-24), 1932, pp. 253-261.",
    "FC": "fcalc's own independent solvers, as the validation record names them per case: scipy.linalg.eigh"
          " of a block's mass and stiffness matrices; the exact T-periodic solution of the full nonlinear"
          " equations by harmonic balance (converged below 1e-10); the 6-DOF linear platform model solved"
          " by harmonic balance.",
}

__all__ = ["REFERENCES"]
