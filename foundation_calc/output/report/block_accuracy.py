"""The accuracy section of a block foundation's sheet: how exact the judged numbers are.

A block's response is the steady state of the linear rigid-block equations, solved exactly per
order and machine (``solvers/block/response.py``); what remains to state is how the machines'
motions are combined, how the peaks over time are found, which soil springs each order uses, and
how closely a checker reproduces the judged numbers from the printed tables (the chain kept beside
the sheet, ``output/report/chain.py``).
"""

from __future__ import annotations

from foundation_calc.output.report.model import Paragraph, Section
from foundation_calc.output.report.numbers import figure


def block_accuracy_section(scene, periodic=()) -> Section:
    """The statements of the accuracy of a block sheet's judged numbers (module docstring);
    ``periodic``: the amplitudes document's ``periodic_inertia`` entries, the first approximation's
    error for each machine whose parts have angle-dependent inertia."""
    dependent = scene.support().frequency_dependent
    several = len(scene.machines) > 1
    solve = ("Limits checked on the steady state of Eq. (1) under Methods: one complex solve"
             " (K − Ω² M + i Ω C) Z = Q_n per order of each machine, ")
    exact = [f"{c['machine']}: at most {figure(100.0 * c['first_approximation_error'], 2)} % of a peak"
             f" ({c['harmonics']} harmonics)" for c in periodic or ()]
    text = [
        solve + ("the first approximation of the machines whose parts have an angle-dependent inertia (their mean"
                 " mass matrix, the averaged operator); its error against the exact periodic solution with the"
                 " angle-dependent mass matrix M(ωt) (harmonic balance, its largest relative difference of the"
                 " peaks of G, the points and the rotations): " + "; ".join(exact) + "."
                 if exact else
                 "the exact steady state of the linear rigid-block model; there is no closed-form approximation"
                 " whose error would need estimating."),
        "Peaks over time: each machine's series Σ_n Re(u_P,n e^{i nωt}) is searched to round-off (sampled,"
        " then refined by Newton steps)"
        + ("; the machines' peaks are added, an upper bound of their combined motion that is reached when"
           " their phases align (machines at different speeds pass through every relative phase). RMS values:"
           " the root-sum-square of every order of every machine, exact for harmonics of distinct frequencies."
           if several else
           ". RMS values: the root-sum-square of the orders, exact for harmonics of distinct frequencies."),
        ("Soil: the springs and dashpots of each order at its own frequency nω and of each mode at its own"
         " ω* (Methods), so the response carries no error of a frequency-independent approximation."
         if dependent else
         "Soil: frequency-independent springs and dashpots, as the scene gives or derives them (Methods)."),
        "Reproduction: from the tables as printed (Z to 3 figures, phases to 0.1°) a checker recomputes each"
        " peak and RMS value of the Checks table within about 1 %, and each margin from the printed speed and"
        " natural frequency within its last printed digit; the machine-readable chain kept beside the sheet"
        " names, for every judged number, its formula and the cells that print its inputs.",
    ]
    return Section("Accuracy", tuple(Paragraph(t) for t in text))
