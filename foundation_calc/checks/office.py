"""Office checks of a block foundation that DYNA6 and ACI 351.3R calculation sheets carry:
eccentricity of the combined centre of mass, static bearing pressure and settlement,
foundation-to-machine mass ratio; a crank foundation's bearing pressure and settlement.

Sources:

- Eccentricity: ACI 351.3R-18 (Foundations for Dynamic Equipment), ch. 3, rules of thumb for
  rigid block foundations, after Arya, O'Neill & Pincus (1979), *Design of Structures and
  Foundations for Vibrating Machines*: the horizontal eccentricity of the combined centre of mass
  from the centroid of the base contact area should not exceed 5 % of the base dimension in that
  direction. A recommendation ("should"): over it the check **warns**.
- Bearing pressure: statics. The base pressure of the total weight W with eccentricities
  e_x, e_y (contact over the whole base, e within the kern) is at most
  q_max = W / (L B) (1 + 6 |e_x| / L + 6 |e_y| / B); above the allowable of the scene
  (``[limits] bearing_pressure``, from the geotechnical report) the check **fails**. A base that
  does not bear on the soil (a pile cap without ``piles.cap_contact``: the piles carry W) has no
  such pressure: the row says so, with no number (:func:`~foundation_calc.solvers.supports.base.bears_on_soil`).
- Static settlement: s = W / K_z, the total weight W on the static vertical spring K_z at O of the
  scene's support (a soil method's, a pile group's; its ω = 0 value for a frequency-dependent one):
  the elastic settlement of the model the dynamic checks use, not a consolidation settlement. Above
  the allowable of the scene (``[limits] settlement``) the check **fails**; crank and block scenes
  alike. What the office checks leave out, each support says on the sheet
  (:func:`~foundation_calc.solvers.supports.base.not_checked`).
- Mass ratio: the same rules of thumb: a block at least 2-3 times the mass of a rotating
  machine and 3-5 times that of a reciprocating one. A rule of thumb, so below
  ``[limits] mass_ratio`` (default 3) the check **warns**.
"""

from __future__ import annotations

from dataclasses import dataclass

from foundation_calc.checks.outcomes import Outcome

SOURCE_RULES = "ACI 351.3R-18, ch. 3 (rules of thumb)"


@dataclass(frozen=True)
class OfficeRow:
    """One office check: the value, the limit, the verdict and where the rule comes from; ``value``
    None for a check that does not apply (its ``text`` says why)."""

    name: str
    value: float | None
    limit: float
    unit: str
    outcome: Outcome
    source: str
    text: str


#: An eccentricity below this fraction of the base's side is the round-off of the sum of the
#: bodies' moments m r (of order 1e-16 of the largest of them), not a position: it is shown as 0.
ROUND_OFF = 1e-12


def eccentricity_rows(cog_xy, L: float, B: float, allowed: float) -> list[OfficeRow]:
    """Eccentricity of the combined centre of mass from the base centroid along x and y, as a
    fraction of L and B [-]; warns above ``allowed``. A round-off eccentricity (:data:`ROUND_OFF`)
    of machines placed symmetrically is 0."""
    rows = []
    for axis, e, size in (("x", cog_xy[0], L), ("y", cog_xy[1], B)):
        e = 0.0 if abs(float(e)) <= ROUND_OFF * size else float(e)
        ratio = abs(e) / size
        outcome = Outcome.WARN if ratio > allowed else Outcome.PASS
        rows.append(OfficeRow(
            f"eccentricity {axis}", ratio, allowed, "-", outcome, SOURCE_RULES,
            f"e_{axis} = {e:.4g} m is {ratio:.2%} of the base's {'length' if axis == 'x' else 'width'} {size:g} m"
            f" ({'over' if ratio > allowed else 'within'} {allowed:.0%})",
        ))
    return rows


def bearing_row(W: float, e_x: float, e_y: float, L: float, B: float, allowable: float) -> OfficeRow:
    """Largest static base pressure q_max [Pa] (module docstring) against the allowable [Pa]."""
    return _bearing(float(bearing_pressure(W, e_x, e_y, L, B)), allowable, W)


def bearing_pressure(W, e_x, e_y, L, B):
    """q_max = W / (L B) (1 + 6 |e_x| / L + 6 |e_y| / B) [Pa] (module docstring); floats or arrays."""
    return W / (L * B) * (1.0 + 6.0 * abs(e_x) / L + 6.0 * abs(e_y) / B)


def crank_bearing_row(W: float, S: float, allowable: float) -> OfficeRow:
    """Static base pressure W / S [Pa] of a crank foundation (its machine stands over the base's
    centroid: no eccentricity) against the allowable [Pa]."""
    return _bearing(W / S, allowable, W, f"q = W/S, S = {S:.4g} m²")


def bearing_rows(support, allowable: float | None, computed) -> list[OfficeRow]:
    """The bearing pressure's row where ``[limits]`` gives its ``allowable`` [Pa]: ``computed()`` (the
    scene's q) under a base that bears on the soil, else a row saying that none applies."""
    from foundation_calc.solvers.supports.base import bears_on_soil

    if allowable is None:
        return []
    if bears_on_soil(support):
        return [computed()]
    return [OfficeRow(
        "bearing pressure", None, allowable, "Pa", Outcome.PASS, "scene [limits] bearing_pressure",
        f"not applicable: the base does not bear on the soil, its support ({support.label}) alone carries the"
        " weight; no pressure under it to judge",
    )]


def _bearing(q: float, allowable: float, W: float, formula: str = "q_max = W/(L B) (1 + 6|e_x|/L + 6|e_y|/B)") -> OfficeRow:
    """The bearing pressure's row; its text names the weight W, so q follows from the sheet's numbers."""
    outcome = Outcome.FAIL if q > allowable else Outcome.PASS
    return OfficeRow(
        "bearing pressure", q, allowable, "Pa", outcome, "scene [limits] bearing_pressure",
        f"{formula}, W = {W / 1e3:.4g} kN: q = {q / 1e3:.4g} kPa {'>' if q > allowable else '<='}"
        f" {allowable / 1e3:.4g} kPa",
    )


def settlement(W, K_z):
    """Static settlement s = W / K_z [m] of the weight W [N] on the vertical spring K_z [N/m]
    (module docstring); floats or arrays.

    >>> round(settlement(1.0e6, 2.0e9), 6)
    0.0005
    """
    return W / K_z


def static_rows(W: float, K_z: float, limits, bearing: list[OfficeRow]) -> list[OfficeRow]:
    """The static checks of every kind on the soil: the bearing pressure rows (given, as each kind
    computes its pressure: :func:`bearing_rows`) and the settlement s = W / K_z [m] against
    ``[limits] settlement``, where the scene gives its limit."""
    rows = list(bearing)
    if limits.settlement is not None:
        s, allowable = float(settlement(W, K_z)), limits.settlement
        over = s > allowable
        rows.append(OfficeRow(
            "settlement", s, allowable, "m", Outcome.FAIL if over else Outcome.PASS, "scene [limits] settlement",
            f"s = W/K_z = {W / 1e3:.4g} kN / {K_z:.4g} N/m = {s * 1e3:.4g} mm {'>' if over else '<='}"
            f" {allowable * 1e3:.4g} mm",
        ))
    return rows


def crank_office_rows(scene) -> tuple[OfficeRow, ...]:
    """The office checks of a ``crank_foundation`` scene: its bearing pressure W/S
    (:func:`crank_bearing_row`) and settlement W/K_z (K_z of its support at ω = 0), where
    ``[limits]`` gives their allowables; W = M_tot g."""
    from foundation_calc.solvers.constants import GRAVITY

    limits = scene.limits
    W = scene.total_mass * GRAVITY
    bearing = bearing_rows(scene.support(), limits.bearing_pressure,
                           lambda: crank_bearing_row(W, scene.foundation.base_area, limits.bearing_pressure))
    K_z = None if limits.settlement is None else float(scene.support().impedance(0.0).springs[2])
    return tuple(static_rows(W, K_z, limits, bearing))


def mass_ratio_row(foundation: float, machines: float, required: float) -> OfficeRow:
    """Foundation-to-machine mass ratio [-]; warns below ``required``."""
    ratio = foundation / machines
    outcome = Outcome.WARN if ratio < required else Outcome.PASS
    return OfficeRow(
        "mass ratio", ratio, required, "-", outcome, SOURCE_RULES,
        f"block {foundation / 1e3:.4g} t / machines {machines / 1e3:.4g} t = {ratio:.3g}"
        f" ({'below' if ratio < required else 'at least'} {required:g})",
    )


@dataclass(frozen=True)
class OfficeReport:
    """The office checks of a scene: its rows and their worst outcome."""

    office: tuple[OfficeRow, ...]

    @property
    def office_outcome(self) -> Outcome:
        from foundation_calc.checks.outcomes import worst

        return worst(r.outcome for r in self.office)


def office_rows(scene, model) -> tuple[OfficeRow, ...]:
    """The office checks of a ``block_foundation`` scene (module docstring); K_z the vertical spring
    at O of ``model`` (a frequency-dependent soil's at ω = 0)."""
    from foundation_calc.solvers.constants import GRAVITY

    L, B = scene.base
    limits = scene.limits
    W = model.mass * GRAVITY
    rows = eccentricity_rows(model.cog[:2], L, B, limits.eccentricity)
    bearing = bearing_rows(scene.support(), limits.bearing_pressure,
                           lambda: bearing_row(W, model.cog[0], model.cog[1], L, B, limits.bearing_pressure))
    rows += static_rows(W, float(model.springs[2]), limits, bearing)
    rows.append(mass_ratio_row(scene.block.mass_properties[0], sum(m.total_mass for m in scene.machines), limits.mass_ratio))
    return tuple(rows)


def scene_office(scene) -> OfficeReport:
    """The office checks of a scene of any kind with office rows, the one place they tell the kinds
    apart: a ``block_foundation``'s (:func:`office_rows` of the model the dynamic checks use, its
    ``stable_model``, the rows ``fcalc amplitudes`` lists too), a ``crank_foundation``'s
    (:func:`crank_office_rows`: its machine stands over the base's centroid, no eccentricity row,
    and no mass-ratio row). No rows: nothing for the office to judge."""
    if scene.kind == "block_foundation":
        return OfficeReport(office_rows(scene, scene.stable_model()))
    return OfficeReport(crank_office_rows(scene))


__all__ = ["OfficeReport", "OfficeRow", "bearing_pressure", "bearing_row", "bearing_rows", "crank_bearing_row", "crank_office_rows",
           "eccentricity_rows", "mass_ratio_row", "office_rows", "scene_office", "settlement", "static_rows"]
