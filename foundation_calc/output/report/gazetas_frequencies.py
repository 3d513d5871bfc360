"""Gazetas' frequency-dependent springs where the checks took them: at each harmonic's n ω and
at each mode's own frequency.

On a frequency-dependent soil (``soil.method = "gazetas"``) the amplitudes solve harmonic n with
the springs and dashpots at n ω (:func:`~foundation_calc.solvers.crank.response.splice_harmonics`),
and the resonance check takes every mode at the root of ω = p(K(ω))
(:func:`~foundation_calc.solvers.soil.impedance.consistent_frequency`, bracketed between the
static value p_s and p(p_s)). The sheet shows both as columns of one chain
(:func:`~foundation_calc.output.report.soil_methods.gazetas_at`, then [KM] (4.5)-(4.7) for the
modes), so the number behind every judged harmonic and critical speed is on the page;
``tests/test_report_gazetas_frequencies.py`` compares them with the solvers'.
"""

from __future__ import annotations

from foundation_calc.output.report.handcalc import Chain, Columns
from foundation_calc.output.report.crank_frequencies import frequency_givens, frequency_steps
from foundation_calc.output.report.soil_methods import gazetas_at

#: At most this many harmonics are shown side by side (the page's width).
MOST_COLUMNS = 5

MODES = ("k0", "p1", "p2")

SPRING_FREQUENCY = "circular frequency at which the springs are taken (n ω, or a mode's own ω*)"


def shown_harmonics(amplitudes: dict | None) -> list[int]:
    """The harmonics n >= 2 that the sheet's damped solve lists
    (:func:`~foundation_calc.output.report.damped_response.solved_harmonics`; the first harmonic
    is the chain at the speed ω), at most :data:`MOST_COLUMNS`."""
    from foundation_calc.output.report.damped_response import solved_harmonics

    if amplitudes is None or amplitudes["approximations"][amplitudes["checked_with"]]["resonant"]:
        return []
    return [n for n in solved_harmonics(amplitudes) if n >= 2][:MOST_COLUMNS]


def harmonic_columns(scene, static: Chain, harmonics: list[int]) -> Columns:
    """Gazetas' springs, dashpots and damping ratios at each harmonic's frequency n ω."""
    omega = scene.speed.omega_rad_s
    chains = []
    for n in harmonics:
        chain = Chain("")
        chain.given("n", n, "-", "order of the harmonic")
        gazetas_at(chain, scene, static, n * omega, SPRING_FREQUENCY, name="omega_s")
        chains.append(chain)
    return Columns(f"Gazetas' springs and dashpots at each harmonic n ω (ω = {omega:.4g} rad/s; the formulas of the chain at ω)",
                   tuple(f"n = {n}" for n in harmonics), chains, (("omega_s", "n ω", "[PK]"),))


def mode_columns(scene, static: Chain, consistent: dict[str, float], footer=None) -> Columns:
    """Each mode's springs at its own frequency ω* (``consistent``: the resonance check's root of
    ω = p(K(ω)) per mode) and k0, p1, p2 on them: the mode's own row returns ω*."""
    chains = []
    for mode in MODES:
        chain = Chain("")
        frequency_givens(chain, scene)
        gazetas_at(chain, scene, static, consistent[mode], SPRING_FREQUENCY, dashpots=False, name="omega_s")
        frequency_steps(chain, "K_zw", "K_xw", "K_phiw")
        chains.append(chain)
    return Columns("Each mode at its own frequency: springs at ω*, then (4.5)-(4.7); the mode's own row equals ω* = p(K(ω*))",
                   tuple(f"at ω* of {m}" for m in MODES), chains,
                   (("omega_s", "ω* = p(K(ω*)), the root between p(p_s) and the static p_s", "[KM] (4.7) with [PK]"),),
                   footer)


def consistent_frequencies(scene) -> tuple[dict[str, float], dict[str, float]]:
    """(static, at its own frequency) k0, p1, p2 [rad/s] as the resonance check takes them."""
    from foundation_calc.checks.resonance.frequencies import scene_block_frequencies, scene_design_frequencies

    if scene.mechanism is None:
        own, static = scene_block_frequencies(scene)
    else:
        own, _, static = scene_design_frequencies(scene)
    return ({m: float(getattr(static, m)) for m in MODES}, {m: float(getattr(own, m)) for m in MODES})


def frequency_table_rows(static: dict[str, float], own: dict[str, float]) -> list[tuple[str, str, str, str]]:
    """Rows mode, static, own frequency, change for the sheet's summary under the mode columns."""
    from foundation_calc.output.report.numbers import figure, percent

    return [(m, figure(static[m], 4), figure(own[m], 4), percent(own[m] / static[m] - 1.0)) for m in MODES]


def gazetas_frequency_columns(scene, static: Chain, amplitudes: dict | None) -> list[Columns]:
    """The harmonic columns (when the response has harmonics above the first) and the mode
    columns with the static-versus-own-frequency table of a crank scene on Gazetas' soil."""
    from foundation_calc.output.report.model import table

    harmonics = shown_harmonics(amplitudes)
    static_f, own = consistent_frequencies(scene)
    summary = table("Natural frequencies: static springs and each mode at its own frequency (the resonance check's)",
                    ("mode", "static [rad/s]", "at ω* [rad/s]", "change"), frequency_table_rows(static_f, own))
    return [*([harmonic_columns(scene, static, harmonics)] if harmonics else []), mode_columns(scene, static, own, summary)]
