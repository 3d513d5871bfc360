"""The code-zone check as a hand calculation: r.m.s. velocity from the harmonics, the zone table
with its clause, the zone found.

Each point's displacement is a series Σ_n A_n cos(nωt − φ_n) (the rigid-body motion of the point
from the sheet's own damped solve, :func:`~foundation_calc.solvers.crank.response.point_series`);
its velocity's r.m.s. over one revolution, the mean left out, is by Parseval's identity

    v_rms = √(Σ_{n≥1} v_n²),    v_n = nω A_n / √2

(ISO 10816-1, 3.3: the r.m.s. of the vibration). The larger of the horizontal and vertical
values is placed in the code's zone table (:mod:`~foundation_calc.checks.codes`; a boundary
value belongs to the lower zone). ``tests/test_report_code_zone.py`` compares v_rms and the zone
with the amplitudes check's.
"""

from __future__ import annotations

import numpy as np

from foundation_calc.output.report.model import Paragraph, table
from foundation_calc.output.report.numbers import column, figure

#: A harmonic gets its own column when its v_n reaches this fraction of the largest [-]; the
#: others are summed in quadrature into one column, so the printed sum is the whole of v_rms.
OWN_COLUMN = 1e-2

#: At most this many harmonics get their own column (the page's width).
MOST_COLUMNS = 4

DIRECTIONS = ("horizontal", "vertical")


def harmonic_amplitudes(motion, horizontal, height) -> np.ndarray:
    """A_n [m] of every point (rows) and direction (horizontal, vertical), shape (points, 2, K + 1)."""
    from foundation_calc.solvers.crank.response import point_series

    cos, sin = point_series(motion, np.asarray(horizontal, dtype=float), np.asarray(height, dtype=float))
    return np.hypot(cos, sin)


def velocity_terms(motion, horizontal, height) -> np.ndarray:
    """v_n = nω A_n / √2 [m/s] of every point (rows) and direction (horizontal, vertical), shape
    (points, 2, K + 1), n = 0 ... K (v_0 = 0: the mean is no vibration)."""
    A = harmonic_amplitudes(motion, horizontal, height)
    return np.arange(A.shape[-1]) * float(motion.omega) * A / np.sqrt(2.0)


def displacement_rms(motion, horizontal, height) -> np.ndarray:
    """d_rms = √(Σ_{n≥1} A_n²/2) [m] of every point and direction, shape (points, 2)."""
    A = harmonic_amplitudes(motion, horizontal, height)[..., 1:]
    return np.sqrt((A**2).sum(-1) / 2.0)


def zone_table(code: dict, kind: str):
    """The code's zone table of the support class ``kind`` (:data:`~foundation_calc.checks.codes.TABLES`)
    with its clause and each zone's verdict for the scene's acceptable zone; ``code``: the
    amplitudes document's part."""
    from foundation_calc.checks.codes import TABLES, zone_outcome

    zones = TABLES[code["code"], code["machine_group"], kind]

    def ranges(b):
        return (f"≤ {b[0]:g}", f"{b[0]:g} - {b[1]:g}", f"{b[1]:g} - {b[2]:g}", f"> {b[2]:g}") if b else ("-",) * 4

    accept = code["acceptable_zone"]
    return table(
        f"Zone table: {zones.title} support ({zones.clause}); the more restrictive quantity decides (5.2.3),"
        " a boundary value is in the lower zone",
        ("zone", "r.m.s. velocity [mm/s]", "r.m.s. displacement [µm]", f"verdict (acceptable zone: {accept or 'not given, B warns'})"),
        ((z, v, d, zone_outcome(z, accept).value) for z, v, d in
         zip("ABCD", ranges(zones.boundaries_mm_s), ranges(zones.displacement_boundaries_um))),
        (False, False, False, False))


def zone_tables(code: dict) -> tuple:
    """:func:`zone_table` of every support class the points are judged in."""
    used = dict.fromkeys(c["support"] for p in code["points"] for c in p["support"]) or {code["foundation"]: None}
    return tuple(zone_table(code, kind) for kind in used)


def judged_zone(code: dict, point: dict, velocity, displacement):
    """The zone of a point by its r.m.s. velocity [m/s] and displacement [m] in each direction,
    each in the table of its support class (the check's :func:`~foundation_calc.checks.codes.point_zone`;
    ``point``: the point's entry of the ``code`` part): (zone, table, governing direction's index)."""
    from foundation_calc.checks.codes import TABLES, point_zone

    kinds = [c["support"] for c in point["support"]] or [code["foundation"]] * len(velocity)
    tables = [TABLES[code["code"], code["machine_group"], kind] for kind in kinds]
    return point_zone(tables, [float(v) for v in velocity], [float(x) for x in displacement], code["acceptable_zone"])


def support_blocks(code: dict) -> tuple:
    """The support class of every point and direction (ISO 10816-3:2009, 3.4) as a sheet table,
    from the ``code`` part: the lowest natural frequency in the direction against 1.25 × the main
    excitation frequency, or the scene's class."""
    from foundation_calc.checks.support import CLAUSE, RIGID_RATIO

    hz = 1.0 / (2.0 * np.pi)
    rows = []
    for p in code["points"]:
        for c in p["support"]:
            f = c["frequency"]
            rows.append((p["point"], c["direction"], c["mode"] or "-", "-" if f is None else figure(f * hz, 4),
                         figure(RIGID_RATIO * c["excitation"] * hz, 4), c["by_modes"],
                         c["support"] + (" (given in the scene)" if c["given"] else "")))
    if not rows:
        return ()
    note = Paragraph(
        f"Support class ({CLAUSE}): rigid in a measuring direction when the lowest natural frequency of machine and"
        f" foundation in that direction is at least {RIGID_RATIO:g} times the main excitation frequency (the speed;"
        " the highest machine speed on a block with several), flexible otherwise. A mode lies in a direction at a point"
        " when it carries at least 1 % of the point's static compliance along it, (φ_P,j/p_j)² over its sum over the"
        " modes. [limits] foundation, when given, overrides the modes' class.")
    found = table("Support class of each point and direction: lowest mode in the direction, its frequency f and"
                  f" {RIGID_RATIO:g} f_exc",
                  ("point", "direction", "lowest mode", "f [Hz]", f"{RIGID_RATIO:g} f_exc [Hz]", "modes say", "judged as"),
                  rows, (False, False, False, True, True, False, False))
    return (note, found)


def _verdict(code: dict, zone_name: str) -> str:
    from foundation_calc.checks.codes import zone_outcome

    return zone_outcome(zone_name, code["acceptable_zone"]).value.upper()


def code_zone_blocks(scene, code: dict | None, motion) -> tuple:
    """The code check of the scene's points from ``motion`` (the sheet's damped solve) and the
    ``code`` part of the amplitudes document (its table, clause, zones and verdicts)."""
    if code is None or not code.get("points"):
        return ()
    names = ["C", *(p.name for p in scene.points)]
    horizontal = [0.0, *(p.horizontal for p in scene.points)]
    height = [0.0, *(p.height for p in scene.points)]
    terms = velocity_terms(motion, horizontal, height)
    d_each = displacement_rms(motion, horizontal, height)
    d_rms = d_each.max(axis=1)
    v_rms = np.sqrt((terms**2).sum(-1))
    governing = [DIRECTIONS[int(np.argmax(v))] for v in v_rms]
    chosen = np.array([terms[i, DIRECTIONS.index(g)] for i, g in enumerate(governing)])  # (points, K + 1)
    strongest = chosen.max(axis=0)
    own = [int(n) for n in np.argsort(-strongest) if strongest[n] >= OWN_COLUMN * strongest.max() > 0.0][:MOST_COLUMNS]
    own.sort()
    rest = np.sqrt(np.maximum((chosen**2).sum(axis=1) - (chosen[:, own] ** 2).sum(axis=1), 0.0))
    total = np.sqrt((chosen**2).sum(axis=1))
    mm = 1e3
    cols = [column(list(chosen[:, n] * mm), 3, strongest.max() * mm) for n in own]
    rest_col = column(list(rest * mm), 2, strongest.max() * mm)
    total_col = column(list(total * mm), 3)
    zones_found = [judged_zone(code, code["points"][i], v_rms[i], d_each[i])[0] for i in range(len(names))]
    d_col = column(list(d_rms * 1e6), 3)
    rows = [(name, governing[i], *(c[i] for c in cols), rest_col[i], total_col[i], f"{z.velocity_zone}", d_col[i],
             z.displacement_zone, z.zone, _verdict(code, z.zone))
            for i, (name, z) in enumerate(zip(names, zones_found))]
    omega = float(motion.omega)
    velocity = table(
        f"R.m.s. velocity from the harmonics: v_n = nω A_n / √2, v_rms = √(Σ v_n²) (ω = {figure(omega, 4)} rad/s)",
        ("point", "direction", *(f"v_{n} [mm/s]" for n in own), "other n [mm/s]", "v_rms [mm/s]", "v zone",
         "d_rms [µm]", "d zone", "zone", "verdict"),
        rows, (False, False, *(True,) * (len(own) + 2), False, True, False, False, False))
    zones = zone_tables(code)
    note = Paragraph(
        "Each point's horizontal and vertical displacement, as a rigid-body point of the block, is the series"
        " Σ A_n cos(nωt − φ_n) of the damped solve above; its larger r.m.s. velocity √(Σ v_n²) and r.m.s."
        " displacement √(Σ A_n²/2) (the mean left out, ISO 10816-1, 3.3) are placed in the zone table; the worse zone"
        " decides.")
    from foundation_calc.output.report.handcalc import Definitions

    terms = Definitions({
        "A_n": ("amplitude of harmonic n of a point's displacement in one direction", "m"),
        "v_n": ("r.m.s. velocity of harmonic n, nω A_n/√2", "mm/s"),
        "v_rms": ("r.m.s. velocity of a point over one revolution, the mean left out", "mm/s"),
        "d_rms": ("r.m.s. displacement of a point, √(Σ A_n²/2), largest direction", "µm"),
        "ω": ("operating speed", "rad/s"),
    })
    return (note, velocity, *zones, *support_blocks(code), terms)


__all__ = ["code_zone_blocks", "judged_zone", "support_blocks", "velocity_terms", "zone_table", "zone_tables"]
