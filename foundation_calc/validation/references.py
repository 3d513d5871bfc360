"""Full references of the sources the validation record compares fcalc with.

Keys are the short labels printed beside each case (``[DR]``); each entry gives authors, title,
journal or publisher, year and the pages or part used.
"""

from __future__ import annotations

from dataclasses import dataclass


@dataclass(frozen=True)
class Reference:
    """One source: ``key`` as printed beside a case, ``citation`` in full."""

    key: str
    citation: str


REFERENCES: dict[str, Reference] = {
    r.key: r
    for r in (
        Reference(
            "BGN",
            "N.N. Bolotnik, B.V. Gusev, Nguyen Truong, I.E. Kholmin, F.L. Chernousko, \"Calculation of the"
            " parameters of a vibration mechanism with unbalanced vibration exciters\", Izvestiya AN SSSR,"
            " Mekhanika Tverdogo Tela (received 13.II.1986), sections 3-4, Eqs. (3.15)-(3.21); worked example"
            " read with omega = 50 pi rad/s and c13 = 1.005e8 N/m (the print's 4.005e8 is c3).",
        ),
        Reference(
            "DR",
            "B.M. Das, G.V. Ramana, Principles of Soil Dynamics, 2nd ed., Cengage Learning, Stamford CT,"
            " 2011, ch. 5 (vibration of foundations: Lysmer's analog), worked example of a 4 m x 2 m x 1.5 m"
            " concrete block carrying a 6 t machine, V_s = 200 m/s, rho = 1800 kg/m3, nu = 0.33.",
        ),
        Reference(
            "GAZ",
            "G. Gazetas, \"Formulas and charts for impedances of surface and embedded foundations\","
            " Journal of Geotechnical Engineering (ASCE) 117(9), 1991, pp. 1363-1381, Table 1.",
        ),
        Reference(
            "ISO",
            "ISO 10816-3:2009, Mechanical vibration - Evaluation of machine vibration by measurements on"
            " non-rotating parts - Part 3: Industrial machines with nominal power above 15 kW and nominal"
            " speeds between 120 r/min and 15 000 r/min when measured in situ, ISO, Geneva, 2009,"
            " Annex A, Tables A.1 and A.2.",
        ),
        Reference(
            "KM",
            "M.F. Krichever, S.M. Makarov, \"Application of the small-parameter method to the problem of"
            " forced vibrations of the foundation of a crank-slider mechanism\", Eqs. (4.5)-(4.14), with"
            " the corrections listed in the README (Corrections to the sources).",
        ),
        Reference(
            "LEW",
            "F.M. Lewis, \"Vibration during acceleration through a critical speed\", Transactions of the"
            " ASME 54 (APM-54-24), 1932, pp. 253-261.",
        ),
        Reference(
            "RHW",
            "F.E. Richart Jr., J.R. Hall Jr., R.D. Woods, Vibrations of Soils and Foundations,"
            " Prentice-Hall, Englewood Cliffs NJ, 1970, ch. 7 (rigid circular footing on the elastic"
            " half-space, vertical stiffness 4 G r0/(1 - nu)).",
        ),
        Reference(
            "FC",
            "fcalc's own independent solvers: scipy.linalg.eigh of the block's mass and stiffness"
            " matrices; the exact T-periodic solution of the full nonlinear equations by harmonic balance"
            " (converged below 1e-10); the 6-DOF linear platform model solved by harmonic balance.",
        ),
    )
}

__all__ = ["REFERENCES", "Reference"]
