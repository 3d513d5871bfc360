"""``fcalc soil`` of a block on piles: the single pile's head springs and dashpots and the group's
efficiency at rest and at each machine's speed (:mod:`foundation_calc.checks.block_piles`), the
group's coupled springs at O."""

from __future__ import annotations

from foundation_calc.output.console import stdout

#: Rows of the single pile's table: (key, label, unit, scale from SI).
SINGLE_ROWS = (
    ("K_v", "K_v", "MN/m", 1e-6), ("K_HH", "K_HH", "MN/m", 1e-6), ("K_MM", "K_MM", "MN m/rad", 1e-6),
    ("K_HM", "K_HM", "MN/rad", 1e-6), ("K_T", "K_T", "MN m/rad", 1e-6),
)


def piles_document(rows) -> list[dict]:
    """JSON (SI) of the piles at each frequency."""
    return [{
        "at": r.label, "omega": r.omega, "a0": r.a0,
        "single": {k: {"K": K, "C": C} for k, (K, C) in r.single.items()},
        "group": {"K": r.group[0].tolist(), "C": r.group[1].tolist()},
        "efficiency": r.efficiency,
    } for r in rows]


def print_piles(scene, rows) -> None:
    """The single pile's springs and dashpots, the group's efficiency and its sway-rocking coupling."""
    from foundation_calc.output.soil import frequency_table
    from foundation_calc.units import hz_from_omega

    p = scene.piles
    heads = [r.label for r in rows]
    table = [("f", "Hz", [hz_from_omega(r.omega) for r in rows]), ("a0", "-", [r.a0 for r in rows])]
    table += [(label, unit, [r.single[key][0] * scale for r in rows]) for key, label, unit, scale in SINGLE_ROWS]
    table += [(f"C{label[1:]}", unit.replace("MN", "MN s"), [r.single[key][1] * scale for r in rows])
              for key, label, unit, scale in SINGLE_ROWS]
    table += [(f"η_{m}", "-", [r.efficiency[m] for r in rows]) for m in ("x", "y", "z")]
    table += [("K_x,ry", "MN/rad", [r.group[0][0, 4] * 1e-6 for r in rows]),
              ("K_y,rx", "MN/rad", [r.group[0][1, 3] * 1e-6 for r in rows])]
    title = (f"Piles: {len(p.positions)} × d = {p.diameter:g} m, L = {p.length:g} m, {p.head} heads, {p.tip.replace('_', '-')},"
             f" soil {p.soil_profile}: one pile's head springs and dashpots, the group's efficiency η"
             " (its spring over n single piles') and coupling at O")
    out = stdout()
    out.print(frequency_table(title, heads, table, 4))
    out.print("Single pile: EN 1998-5 Table C.1 [EC8] (K_HH, K_MM, K_HM), Randolph & Wroth 1978 (K_v), Randolph 1981 (K_T) [RW],"
              " frequency shape of a Winkler pile (Makris & Gazetas 1992 [MG]); group: Dobry & Gazetas 1988 [DG] interaction"
              " factors under a rigid cap. a0 = ω d/V_s.", soft_wrap=True)


__all__ = ["piles_document", "print_piles"]
